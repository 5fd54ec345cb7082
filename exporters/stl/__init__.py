"""STL for CFD: closed, outward triangle surfaces with one patch per semantic class (``writer``),
its seams (``seams``) and the row keys it welds by (``rows``)."""
from lod2energy.exporters.stl.writer import StlOptions, read_stl, self_check, write  # noqa: F401
