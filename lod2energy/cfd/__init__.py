"""``python -m lod2energy.cfd``: the CFD case's command (the case itself is :mod:`lod2energy.exporters.cfd`)."""
from lod2energy.exporters.cfd.options import CfdOptions, add_cli_arguments, options_from_args  # noqa: F401
