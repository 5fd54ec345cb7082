"""Welding of close vertices into one, as the writers do it (each cluster becomes its mean)."""
from __future__ import annotations

from typing import Sequence

import numpy as np

# scipy is imported in the functions that use it: importing lod2energy stays cheap (issue 13)


def weld(points: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    """Merge points closer than ``tol`` (transitively) into their cluster's mean.

    The pairs are those of :func:`lod2energy.geometry.close_pairs`, but in the order scipy's
    k-d tree gives them: the merge order picks each cluster's root, and so the order of the
    welded points (the writers' output); unlike
    :func:`lod2energy.geometry.snap_map`, which keeps each cluster's first point (val3dity's
    rule, so that validation sees the input's coordinates), a writer puts a zone's corner
    between the welded inputs.

    Parameters
    ----------
    points : (n, 3) float, m
    tol : float, m

    Returns
    -------
    welded : (m, 3) float
        One point per cluster (the mean).
    index : (n,) int
        Cluster of each input point.
    """
    p = np.asarray(points, dtype=np.float64)
    if len(p) == 0:
        return p.reshape(0, 3), np.zeros(0, dtype=np.intp)
    from scipy.spatial import cKDTree
    pairs = cKDTree(p).query_pairs(tol, output_type="ndarray")
    if len(pairs) == 0:
        return p.copy(), np.arange(len(p))
    roots = np.array(_union_roots(len(p), pairs.tolist()))
    _, index = np.unique(roots, return_inverse=True)
    welded = np.zeros((index.max() + 1, 3))
    np.add.at(welded, index, p)
    welded /= np.bincount(index)[:, None]
    return welded, index


def _union_roots(n: int, pairs: list) -> list[int]:
    """The root of each of ``n`` elements after merging ``pairs`` in order, as
    ``scipy.cluster.hierarchy.DisjointSet(range(n))`` with ``merge(a, b)`` for each pair
    picks it: the root of the larger subset becomes the parent, the root inserted first
    (the smaller index) on equal sizes. Path halving as there (it does not change roots).
    On lists: a fraction of the cost of the dictionaries there."""
    parent = list(range(n))
    size = [1] * n

    def find(x):
        while x != parent[x]:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b in pairs:
        xr, yr = find(a), find(b)
        if xr == yr:
            continue
        if (size[xr], yr) < (size[yr], xr):
            xr, yr = yr, xr
        parent[yr] = xr
        size[xr] += size[yr]
    return [find(i) for i in range(n)]


def clean_ring(ring: Sequence[int]) -> list[int]:
    """``ring`` without consecutive repeats, and without a closing copy of its first index."""
    out: list[int] = []
    for i in ring:
        if not out or out[-1] != i:
            out.append(int(i))
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return out

