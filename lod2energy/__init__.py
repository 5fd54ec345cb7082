"""lod2energy: LoD2 city models to simulation-ready geometry.

Pipeline: read (``lod2energy.io``) -> validate (``lod2energy.validate``) ->
repair (``lod2energy.repair``) -> label and assign U-values (``lod2energy.semantics``,
``lod2energy.thermal``) -> export (``lod2energy.exporters``).
"""
__version__ = "0.1.0"

from lod2energy.errors import Lod2EnergyError, InputError  # noqa: F401
