"""Vertex snapping as val3dity does it: per primitive, first-come representative within ``snap_tol``.

val3dity adds the points of a shell one by one (face by face, ring by ring) and merges a
new point into the *first* already-kept point whose squared distance is strictly below
``snap_tol**2`` (``Surface::add_point``). The result depends on the order of insertion
(chains of close points do not collapse transitively), so it is reproduced here exactly,
with a k-d tree to find the few candidate pairs and a short sequential pass over them.
"""
from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree


def first_occurrence(ids: np.ndarray) -> np.ndarray:
    """Distinct values of ``ids`` in the order they first occur.

    Parameters
    ----------
    ids : (k,) int

    Returns
    -------
    (u,) int
    """
    ids = np.asarray(ids, dtype=np.intp)
    if ids.size == 0:
        return ids
    u, first = np.unique(ids, return_index=True)
    return u[np.argsort(first, kind="stable")]


def snap_points(points: np.ndarray, snap_tol: float) -> np.ndarray:
    """Representative of each point, val3dity's way.

    Parameters
    ----------
    points : (k, 3) float
        Points in insertion order, m.
    snap_tol : float, m
        Points closer than this (strictly) merge; ``<= 0`` disables snapping.

    Returns
    -------
    rep : (k,) int
        ``rep[i]`` is the index (into ``points``) of the kept point that ``points[i]``
        merges into; ``rep[i] == i`` for kept points, and always ``rep[i] <= i``.
    """
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    n = len(pts)
    rep = np.arange(n, dtype=np.intp)
    if n < 2 or not snap_tol or snap_tol <= 0 or not np.isfinite(pts).all():
        return rep
    tol2 = snap_tol * snap_tol
    # slightly larger radius for the tree, exact val3dity test below
    pairs = cKDTree(pts).query_pairs(snap_tol * (1 + 1e-9) + 1e-300, output_type="ndarray")
    if len(pairs) == 0:
        return rep
    d = pts[pairs[:, 0]] - pts[pairs[:, 1]]
    d2 = d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1] + d[:, 2] * d[:, 2]
    pairs = pairs[d2 < tol2]
    if len(pairs) == 0:
        return rep
    near: dict[int, list[int]] = {}
    for a, b in pairs.tolist():
        lo, hi = (a, b) if a < b else (b, a)
        near.setdefault(hi, []).append(lo)
    kept = np.ones(n, dtype=bool)
    for i in sorted(near):
        # the first kept point (lowest insertion index) within tolerance wins
        cands = sorted(j for j in near[i] if kept[j])
        if cands:
            rep[i] = cands[0]
            kept[i] = False
    return rep


def snapped_ids(vertices: np.ndarray, ids: np.ndarray, snap_tol: float) -> np.ndarray:
    """Vertex indices after snapping, for vertex indices listed in insertion order.

    Parameters
    ----------
    vertices : (n, 3) float
        All vertices, m.
    ids : (k,) int
        Vertex indices in the order val3dity would add them (rings of a shell, concatenated).
    snap_tol : float, m

    Returns
    -------
    (k,) int
        For each entry of ``ids``, the vertex index of its representative.
    """
    ids = np.asarray(ids, dtype=np.intp)
    order = first_occurrence(ids)
    if len(order) < 2:
        return ids.copy()
    rep = snap_points(vertices[order], snap_tol)
    if (rep == np.arange(len(order))).all():
        return ids.copy()
    lut = {int(v): int(order[r]) for v, r in zip(order.tolist(), rep.tolist())}
    return np.fromiter((lut[i] for i in ids.tolist()), dtype=np.intp, count=len(ids))
