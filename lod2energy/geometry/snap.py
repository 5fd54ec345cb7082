"""Vertex snapping: the clustering of points closer than a tolerance, in its two forms.

- :func:`snap_map`: transitive clusters (chains of close points merge), the lowest index
  represents a cluster; the face graph and the repair ladder's cleanup use it.
- :func:`weld`: transitive clusters merged into their mean, as the writers weld a zone's
  corners (each cluster's root picked in the order scipy's k-d tree gives the pairs);
- :func:`snap_points`: val3dity's first-come rule, which validation must reproduce exactly:
  val3dity adds the points of a shell one by one (face by face, ring by ring) and merges a
  new point into the *first* already-kept point whose squared distance is strictly below
  ``snap_tol**2`` (``Surface::add_point``); chains do not collapse transitively;
  :func:`snapped_ids` applies it to a shell's ring indices.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from lod2energy.geometry.pairs import close_pairs_grid, connected_components

# scipy (0.4 s to import) is imported where a k-d tree is needed: validation never needs one

__all__ = ["snap_map", "close_pairs", "weld", "drop_repeats", "snap_points", "snapped_ids", "first_occurrence"]


def close_pairs(points: np.ndarray, tol: float, groups: np.ndarray | None = None) -> np.ndarray:
    """Pairs ``(i, j)``, ``i < j``, of points at most ``tol`` apart.

    Parameters
    ----------
    points : (n, 3) float
    tol : float, m
    groups : (n,) int, optional
        Points of different groups never pair.

    Returns
    -------
    (p, 2) int
        Sorted lexicographically; the set ``cKDTree(points).query_pairs(tol)`` gives
        (:func:`~lod2energy.geometry.pairs.close_pairs_grid`).
    """
    pairs = close_pairs_grid(points, tol)
    if groups is not None and len(pairs):
        pairs = pairs[groups[pairs[:, 0]] == groups[pairs[:, 1]]]
    return pairs


def snap_map(points: np.ndarray, tol: float, groups: np.ndarray | None = None) -> np.ndarray:
    """Representative of each point after merging points closer than ``tol``.

    Chains of close points merge into one cluster (transitive closure); the representative
    is the cluster's lowest index, as val3dity keeps the first vertex it met.

    Parameters
    ----------
    points : (n, 3) float
    tol : float, m
        Points at most ``tol`` apart merge; ``<= 0`` merges only identical coordinates.
    groups : (n,) int, optional
        Points of different groups (buildings) never merge (only with ``tol > 0``).

    Returns
    -------
    (n,) int
        ``rep[i]`` is the index of the point that ``i`` merges into (``rep[rep] == rep``).
    """
    p = np.asarray(points, dtype=np.float64)
    n = len(p)
    if n == 0:
        return np.zeros(0, dtype=np.intp)
    if tol <= 0:
        _, first, inv = np.unique(p, axis=0, return_index=True, return_inverse=True)
        return first[inv.ravel()].astype(np.intp)
    pairs = close_pairs(p, tol, groups)
    if len(pairs) == 0:
        return np.arange(n, dtype=np.intp)
    lab, _ = connected_components(n, pairs[:, 0], pairs[:, 1])
    first = np.full(lab.max() + 1, n, dtype=np.intp)
    np.minimum.at(first, lab, np.arange(n))
    return first[lab]


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


def drop_repeats(ring: Sequence[int]) -> list[int]:
    """``ring`` without consecutive repeats, and without a closing copy of its first index."""
    out: list[int] = []
    for i in ring:
        if not out or out[-1] != i:
            out.append(int(i))
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return out


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
    # slightly larger radius for the grid, exact val3dity test below
    pairs = close_pairs_grid(pts, snap_tol * (1 + 1e-9) + 1e-300)
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
    """Vertex indices after val3dity's snapping (:func:`snap_points`), for vertex indices listed
    in insertion order (rings of a shell, concatenated).

    Parameters
    ----------
    vertices : (n, 3) float
        All vertices, m.
    ids : (k,) int
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


def split_at_points(v: np.ndarray, polys: list[list[int]], tol: float, only_unmatched: bool = False,
                    candidates=None) -> list[list[int]]:
    """Insert into polygon edges the vertices lying on them (T-junctions), in order along each edge.

    Parameters
    ----------
    v : (n, 3) float, m
    polys : list of list of int
        Rings as vertex indices into ``v``.
    tol : float, m
        Largest distance of a vertex from the edge it is inserted into (and from its ends).
    only_unmatched : bool
        Split only edges without a reversed twin (as EnergyPlus does when a zone is not
        enclosed), so that shared edges and diagonals stay untouched.
    candidates : iterable of int, optional
        Only these vertices may be inserted (and not into a ring that already has them);
        default every vertex.

    Returns
    -------
    list of list of int
        The rings with the vertices inserted.
    """
    from scipy.spatial import cKDTree
    tree = cKDTree(v)
    allowed = None if candidates is None else {int(c) for c in candidates}
    directed = {(poly[k], poly[(k + 1) % len(poly)]) for poly in polys for k in range(len(poly))}
    out = []
    for poly in polys:
        new = []
        inside = set(poly) if allowed is not None else ()
        for k in range(len(poly)):
            a, b = poly[k], poly[(k + 1) % len(poly)]
            new.append(a)
            if only_unmatched and (b, a) in directed:
                continue
            pa, pb = v[a], v[b]
            d = pb - pa
            L = float(np.linalg.norm(d))
            if L <= tol:
                continue
            cand = tree.query_ball_point((pa + pb) / 2, L / 2 + tol)
            on = []
            for c in cand:
                if c in (a, b) or (allowed is not None and (c not in allowed or c in inside)):
                    continue
                t = float(np.dot(v[c] - pa, d) / (L * L))
                if tol / L < t < 1 - tol / L and np.linalg.norm(pa + t * d - v[c]) <= tol:
                    on.append((t, c))
            new.extend(c for _, c in sorted(on))
        out.append(new)
    return out
