"""Near contacts between two solids made exact: a corner a hair off a neighbour's surface put onto it.

Used by :func:`lod2energy.repair.parts.clip_overlapping_parts` before a difference of two
BuildingParts whose walls nearly meet.
"""
from __future__ import annotations

import numpy as np

from lod2energy.geometry import closest_on_triangle
from lod2energy.polymesh import PolyMesh, triangulate_mesh
from lod2energy.repair.metrics import _sqdist


def onto_surface(m: PolyMesh, other: PolyMesh, tol: float) -> PolyMesh | None:
    """``m`` with each vertex within ``tol`` (m) of ``other``'s surface (but not on it) put
    onto its nearest point there; None when no vertex moves.

    Where a part's corner stands a fraction of a millimetre off its neighbour's wall, the
    difference of the two (:func:`lod2energy.repair.parts.clip_overlapping_parts`) keeps a
    hairline strip along the part's edge, which folds into a line once written on a
    millimetre grid (a self-intersecting ring); with the corner on the wall the difference
    leaves no strip.
    """
    tris, _ = triangulate_mesh(other)
    if not len(tris):
        return None
    A, B, C = (other.vertices[tris[:, k]] for k in range(3))
    V = np.array(m.vertices, dtype=np.float64)
    moved = False
    for i in range(len(V)):
        d = _sqdist(V[i][None, :], A, B, C)
        k = int(np.argmin(d))
        if not 1e-16 < d[k] <= tol * tol:
            continue
        V[i] = closest_on_triangle(V[i], A[k], B[k], C[k])
        moved = True
    return m.with_faces(m.faces, V) if moved else None
