"""temporary alias during the merge; import lod2energy.geometry.triangulate"""
from lod2energy.geometry.triangulate import constrained_delaunay, ear_triangles, lawson_cdt  # noqa: F401
