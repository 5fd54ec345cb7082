"""temporary alias during the merge; import lod2energy.polymesh"""
from lod2energy.polymesh import *  # noqa: F401,F403
from lod2energy.polymesh import __all__  # noqa: F401
