"""Closed-shell check of what a writer wrote: welded, T-junctions split, every edge twice, positive volume.

:func:`check_closed_outward` is the check each writer runs on a zone's written polygons
(the IDF and STL self-checks); :func:`signed_volume` is
:func:`lod2energy.geometry.signed_volume` about the mesh's centroid.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from lod2energy.geometry import signed_volume as _signed_volume, split_at_points

from .polygons import triangulate
from .weld import clean_ring, weld


def signed_volume(vertices: np.ndarray, tris: np.ndarray) -> float:
    """Signed volume (m3) of a triangle mesh ``(t, 3)`` over ``vertices`` ``(n, 3)``; positive
    when outward oriented (taken about the vertices' centroid: local and map coordinates alike)."""
    return _signed_volume(np.asarray(vertices, dtype=np.float64), tris, origin="centroid")


def check_closed_outward(polygons: Sequence[np.ndarray], tol: float = 1e-3,
                         t_tol: float = 0.0127) -> list[str]:
    """Is a set of 3D polygons (one zone's written surfaces) a closed, outward shell?

    Vertices are welded at ``tol``, T-junctions within ``t_tol`` (EnergyPlus's point
    tolerance, 1.27 cm) are split, then every undirected edge must
    be used exactly twice, once in each direction (closed, 2-manifold, consistent winding),
    and the enclosed signed volume must be positive (outward).

    Parameters
    ----------
    polygons : sequence of (k, 3) float
        Polygons as written, counter-clockwise seen from outside.

    Returns
    -------
    list of str
        Problems found (empty when the shell is fine).
    """
    if not polygons:
        return ["no surfaces"]
    allp = np.concatenate([np.asarray(p, dtype=np.float64) for p in polygons])
    v, idx = weld(allp, tol)
    polys, k = [], 0
    for p in polygons:
        ring = clean_ring(idx[k:k + len(p)].tolist())
        k += len(p)
        if len(set(ring)) >= 3:
            polys.append(ring)
    polys = split_at_points(v, polys, t_tol, only_unmatched=True)
    directed: dict[tuple[int, int], int] = {}
    for poly in polys:
        for i in range(len(poly)):
            e = (poly[i], poly[(i + 1) % len(poly)])
            directed[e] = directed.get(e, 0) + 1
    problems = []
    boundary = sum(1 for (a, b), n in directed.items() if (b, a) not in directed)
    dup = sum(1 for n in directed.values() if n > 1)
    if boundary:
        problems.append(f"not closed: {boundary} edge(s) used by one surface only")
    if dup:
        problems.append(f"inconsistent winding or non-manifold: {dup} edge(s) used twice in one direction")
    tris = []
    for poly in polys:
        pts = v[poly]
        t = triangulate(pts, [len(poly)])
        tris.extend([[poly[i] for i in tt] for tt in t])
    vol = signed_volume(v, np.asarray(tris, dtype=np.intp).reshape(-1, 3))
    if vol <= 0:
        problems.append(f"not outward: signed volume {vol:.3f} m3")
    return problems
