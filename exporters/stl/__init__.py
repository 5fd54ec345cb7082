"""STL for CFD: closed, outward triangle surfaces with one patch per semantic class."""
from lod2energy.exporters.stl.writer import StlOptions, read_stl, self_check, write  # noqa: F401
