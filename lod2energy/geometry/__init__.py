"""Shared numeric geometry on plain numpy arrays, one module per operation.

- :mod:`~lod2energy.geometry.vectors`: cross products, Newell normals (the one face normal), plane
  bases, 2D projection;
- :mod:`~lod2energy.geometry.pairs`: close point pairs (a grid of cells) and connected components, numpy alone;
- :mod:`~lod2energy.geometry.snap`: vertex clustering, the one home of it: transitive snapping, the writers'
  welding, val3dity's first-come snapping; vertices put into the ring edges they lie on (T-junctions);
- :mod:`~lod2energy.geometry.cdt`: ear clipping and the constrained Delaunay triangulation of one polygon,
  or of many at once (GEOS);
- :mod:`~lod2energy.geometry.triangulate`: triangulation of surfaces, bulk paths;
- :mod:`~lod2energy.geometry.polygons`: planar polygons as the writers cut them (wall basis, triangles
  with every ring vertex kept, convex pieces);
- :mod:`~lod2energy.geometry.intersect`: box pairs, segment/triangle tests, winding number, closest point on a triangle;
- :mod:`~lod2energy.geometry.measure`: areas, signed volume (the one formula), planarity;
- :mod:`~lod2energy.geometry.simplify`: short-edge collapse.

Everything works on a building's ``vertices`` (n, 3) float, metres, and integer rings of
:class:`~lod2energy.model.Surface`. Nothing here imports from the rest of the project but
:mod:`lod2energy.cache`. The names are re-exported here (``from lod2energy.geometry import X``).
"""
from __future__ import annotations

from lod2energy.geometry.cdt import constrained_delaunay, constrained_delaunay_many, ear_triangles, earcut_rings, lawson_cdt
from lod2energy.geometry.intersect import (
    bbox_pairs, closest_on_triangle, segment_triangle_intersect, triangle_pairs_intersect, winding_number,
)
from lod2energy.geometry.measure import (
    plane_distance, ring_area_2d, signed_volume, triangle_areas, triangle_normals,
)
from lod2energy.geometry.pairs import close_pairs_grid, connected_components
from lod2energy.geometry.simplify import collapse_short_edges
from lod2energy.geometry.snap import close_pairs, snap_map, snapped_ids, split_at_points, weld
from lod2energy.geometry.triangulate import SLIVER_RATIO, triangulate_flat, triangulate_surface
from lod2energy.geometry.vectors import (
    cross2, cross_rows, newell_normal, newell_normals, plane_basis, plane_bases, project_2d, rings_normal, unit,
    unit_rows,
)

__all__ = [
    "constrained_delaunay", "constrained_delaunay_many", "ear_triangles", "earcut_rings", "lawson_cdt",
    "bbox_pairs", "closest_on_triangle", "segment_triangle_intersect", "triangle_pairs_intersect", "winding_number",
    "plane_distance", "ring_area_2d", "signed_volume", "triangle_areas", "triangle_normals",
    "close_pairs_grid", "connected_components", "collapse_short_edges",
    "close_pairs", "snap_map", "snapped_ids", "split_at_points", "weld",
    "SLIVER_RATIO", "triangulate_flat", "triangulate_surface",
    "cross2", "cross_rows", "newell_normal", "newell_normals", "plane_basis", "plane_bases", "project_2d",
    "rings_normal", "unit", "unit_rows",
]
