"""Near contacts between two solids made exact: a corner a hair off a neighbour's surface put onto it.

Used by :func:`lod2energy.repair.parts.clip_overlapping_parts` before a difference of two
BuildingParts whose walls nearly meet.
"""
from __future__ import annotations

import numpy as np

from lod2energy.polymesh import PolyMesh, triangulate_mesh


def onto_surface(m: PolyMesh, other: PolyMesh, tol: float) -> PolyMesh | None:
    """``m`` with each vertex within ``tol`` (m) of ``other``'s surface (but not on it) put
    onto its nearest point there; None when no vertex moves.

    Where a part's corner stands a fraction of a millimetre off its neighbour's wall, the
    difference of the two (:func:`lod2energy.repair.parts.clip_overlapping_parts`) keeps a
    hairline strip along the part's edge, which folds into a line once written on a
    millimetre grid (a self-intersecting ring); with the corner on the wall the difference
    leaves no strip.
    """
    from lod2energy.repair.metrics import _sqdist
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


def closest_on_triangle(p, a, b, c):
    """The point of triangle ``abc`` nearest to ``p`` ((3,) arrays, m; Ericson's method)."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = ab @ ap, ac @ ap
    if d1 <= 0 and d2 <= 0:
        return a
    bp = p - b
    d3, d4 = ab @ bp, ac @ bp
    if d3 >= 0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return a + d1 / (d1 - d3) * ab
    cp = p - c
    d5, d6 = ab @ cp, ac @ cp
    if d6 >= 0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return a + d2 / (d2 - d6) * ac
    va = d3 * d6 - d5 * d4
    if va <= 0 and d4 - d3 >= 0 and d5 - d6 >= 0:
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)
    den = 1.0 / (va + vb + vc)
    return a + ab * (vb * den) + ac * (vc * den)
