"""``python -m lod2energy`` runs the command line."""
import sys

from lod2energy.cli import main

sys.exit(main())
