"""Close point pairs and connected components in numpy alone (no scipy import: start-up stays cheap).

- :func:`close_pairs_grid`: every pair of points at most ``r`` apart, the set
  ``scipy.spatial.cKDTree(points).query_pairs(r)`` returns, from a uniform grid of cells at
  least ``r`` wide (points sorted by cell, each cell paired with itself and half of its
  neighbours, candidates expanded in bounded chunks, then tested as the k-d tree tests them);
- :func:`connected_components`: the components of an undirected graph given by its edges,
  numbered as ``scipy.sparse.csgraph.connected_components`` numbers them (by their smallest
  node), by hooking roots onto smaller roots and pointer jumping.

Importing numpy and these costs nothing extra; scipy's k-d tree and sparse graphs cost about
0.2 CPU s to import, more than ``validate`` spends on a small file.
"""
from __future__ import annotations

import itertools

import numpy as np

__all__ = ["close_pairs_grid", "connected_components"]

#: Candidate pairs tested at once: bounds the memory of a cell crowded with (near-)duplicates.
CHUNK = 1 << 21
#: At most this many cells along one axis: floor((p - min) / h) stays exact to ~2**-19 of a cell.
_MAX_CELLS_AXIS = float(1 << 32)
#: The cell keys of all axes together stay below this (int64, with room for the neighbours).
_MAX_KEY = float(1 << 62)
#: Below this radius squares may underflow: candidates are searched at least this far.
_TINY = 1e-149


def _sq_dist(p: np.ndarray, i: np.ndarray, j: np.ndarray) -> np.ndarray:
    """Squared distances summed in the k-d tree's order (four running sums, then the rest).

    Parameters
    ----------
    p : (n, d) float
    i, j : (k,) int

    Returns
    -------
    (k,) float
        Bit for bit what ``cKDTree`` compares with ``r * r``.
    """
    d = p.shape[1]
    acc = []
    for k in range(4 * (d // 4)):
        t = p[i, k] - p[j, k]
        t = t * t
        if k < 4:
            acc.append(t)
        else:
            acc[k % 4] = acc[k % 4] + t
    s = np.zeros(len(i)) if not acc else acc[0]
    for t in acc[1:]:
        s = s + t
    for k in range(4 * (d // 4), d):
        t = p[i, k] - p[j, k]
        s = s + t * t
    return s


def _cells(p: np.ndarray, reach: float) -> np.ndarray:
    """Per-axis cell of each point, cells at least ``reach`` wide, within the key budget.

    Parameters
    ----------
    p : (n, d) float, finite
    reach : float > 0
        Points at most this far apart along every axis land in equal or adjacent cells.

    Returns
    -------
    (n, d) int64
        Cell coordinates, each in ``[0, 2**32]``, their product of extents (+3 each) below 2**62.
    """
    lo, hi = p.min(axis=0), p.max(axis=0)
    with np.errstate(over="ignore", invalid="ignore"):
        span = hi - lo
    # coordinates near the float limit: halve everything (exact) so that p - lo cannot overflow
    scale = 1.0 if np.isfinite(span).all() else 0.5
    if scale != 1.0:
        span = hi * scale - lo * scale
    # 2**-10 wider than the reach: rounding of (p - lo) / h moves a point by < 2**-19 of a cell
    h = np.maximum(np.full(len(span), reach * scale * (1 + 2.0 ** -10)), span / _MAX_CELLS_AXIS)
    h = np.where(h > 0, h, 1.0)
    while np.prod(np.floor(span / h) + 4.0) >= _MAX_KEY:  # too many cells: widen the finest-cut axis
        k = int(np.argmax(span / h))
        h[k] *= 2.0
    q = (p * scale - lo * scale) / h if scale != 1.0 else (p - lo) / h
    return np.floor(q).astype(np.int64)


def _expand(i: np.ndarray, j_lo: np.ndarray, j_hi: np.ndarray):
    """Yield the pairs ``(i[s], j)`` for ``j_lo[s] <= j < j_hi[s]``, as two position arrays, at
    most :data:`CHUNK` pairs at a time (or one row's worth when a single row has more).

    Parameters
    ----------
    i, j_lo, j_hi : (s,) int
        Rows with ``j_hi > j_lo``.
    """
    c = j_hi - j_lo
    total = np.cumsum(c)
    lo, s = 0, len(i)
    while lo < s:
        base = int(total[lo - 1]) if lo else 0
        hi = max(int(np.searchsorted(total, base + CHUNK, side="right")), lo + 1)
        cc = c[lo:hi]
        m = int(total[hi - 1]) - base
        first = np.repeat(np.cumsum(cc) - cc, cc)
        yield np.repeat(i[lo:hi], cc), np.repeat(j_lo[lo:hi], cc) + (np.arange(m) - first)
        lo = hi


def close_pairs_grid(points: np.ndarray, r: float) -> np.ndarray:
    """All pairs ``(i, j)``, ``i < j``, of points at most ``r`` apart (Euclidean), sorted.

    The same set as ``scipy.spatial.cKDTree(points).query_pairs(r, output_type="ndarray")``:
    a pair is in when its squared distance, summed as the k-d tree sums it, is ``<= r * r``
    (so ``r = 0`` gives coinciding points, and points whose squared distance underflows).

    Points are sorted by grid cell (cells at least ``r`` wide, numbered with the last axis
    fastest); a point is paired with the points after it in its own cell and the next cell
    along the last axis, and with the three consecutive cells along the last axis of each
    neighbouring column whose offset is positive: each pair of cells once.

    Parameters
    ----------
    points : (n, d) float
        Coordinates, any unit (m for city models); finite (huge values are fine).
    r : float
        Largest distance, the unit of ``points``. ``nan`` or ``< 0`` gives no pair (the
        k-d tree gives none for ``nan``; for ``r < 0`` it would use ``r * r``, this does
        not); ``r * r = inf`` (``r`` above ~1.3e154) gives every pair.

    Returns
    -------
    (p, 2) intp
        Sorted lexicographically (rows ``(i, j)``, ``i < j``), not in the k-d tree's order.

    Raises
    ------
    ValueError
        If a coordinate is ``nan`` or infinite (as ``cKDTree`` does).
    """
    p = np.asarray(points, dtype=np.float64)
    n = len(p)
    if p.ndim != 2:
        p = p.reshape(n, -1) if n else p.reshape(0, 0)
    empty = np.zeros((0, 2), dtype=np.intp)
    if n and not np.isfinite(p).all():
        raise ValueError("data must be finite, check for nan or inf values")
    r = float(r)
    if n < 2 or not r >= 0:  # also nan
        return empty
    r2 = r * r
    if np.isinf(r2) or p.shape[1] == 0:  # r * r overflows: every squared distance is <= inf
        return np.stack(np.triu_indices(n, 1), axis=1).astype(np.intp)
    d = p.shape[1]
    # fl(d2) <= fl(r*r) implies a true distance below r * (1 + 4 eps), or below ~1.2e-150 when
    # the squares underflow: every axis of a pair differs by at most ``reach``
    cell = _cells(p, max(r * (1 + 1e-9), _TINY))
    ext = cell.max(axis=0) + 3                 # cell + 1 in [1, max + 1], neighbours in [0, max + 2]
    stride = np.ones(d, dtype=np.int64)
    for k in range(d - 2, -1, -1):
        stride[k] = stride[k + 1] * ext[k + 1]
    key = (cell + 1) @ stride
    del cell
    order = np.argsort(key, kind="stable")
    skey = key[order]
    ps = p[order]
    cut = np.flatnonzero(np.r_[True, skey[1:] != skey[:-1]])
    ukey = skey[cut]
    del skey, key
    bound = np.r_[cut, n]                      # cell c holds sorted positions bound[c]:bound[c + 1]
    cell_of = np.repeat(np.arange(len(ukey)), np.diff(bound))
    pos = np.arange(n)

    def ranges():
        """Per sorted position, its partners' positions ``[lo, hi)``: its own cell after it and
        the next cell along the last axis, then each neighbouring column of positive offset."""
        yield pos + 1, bound[np.searchsorted(ukey, ukey + 1, side="right")][cell_of]
        for off in itertools.product((-1, 0, 1), repeat=d - 1):
            o = int(np.dot(off, stride[:-1]))
            if o > 0:
                lo_c = bound[np.searchsorted(ukey, ukey + (o - 1), side="left")]
                hi_c = bound[np.searchsorted(ukey, ukey + (o + 1), side="right")]
                yield lo_c[cell_of], hi_c[cell_of]

    out = []
    for j_lo, j_hi in ranges():
        live = np.flatnonzero(j_hi > j_lo)
        for a, b in _expand(live, j_lo[live], j_hi[live]):
            ok = _sq_dist(ps, a, b) <= r2
            if ok.any():
                a, b = order[a[ok]], order[b[ok]]
                out.append(np.stack([np.minimum(a, b), np.maximum(a, b)], axis=1))
    if not out:
        return empty
    pairs = np.concatenate(out).astype(np.intp, copy=False)
    return pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]


def connected_components(n: int, i: np.ndarray, j: np.ndarray) -> tuple[np.ndarray, int]:
    """Connected components of the undirected graph on ``n`` nodes with edges ``(i[k], j[k])``.

    Numbered as ``scipy.sparse.csgraph.connected_components(..., directed=False)`` numbers
    them: component 0 holds node 0, component ``c + 1`` the smallest node outside components
    ``0..c``. Repeated edges and self-loops are allowed.

    Parameters
    ----------
    n : int
        Number of nodes.
    i, j : (e,) int
        Edge ends, node indices in ``[0, n)``.

    Returns
    -------
    labels : (n,) intp
        Component of each node.
    count : int
        Number of components.
    """
    parent = np.arange(n, dtype=np.intp)
    a = np.asarray(i, dtype=np.intp).ravel()
    b = np.asarray(j, dtype=np.intp).ravel()
    if len(a) != len(b):
        raise ValueError("i and j differ in length")
    if len(a) and (min(a.min(), b.min()) < 0 or max(a.max(), b.max()) >= n):
        raise ValueError("edge end out of range")
    while len(a):
        ra, rb = parent[a], parent[b]
        live = ra != rb
        if not live.any():
            break
        a, b, ra, rb = a[live], b[live], ra[live], rb[live]
        # every root hooks onto the smallest root it touches (roots only ever decrease)
        np.minimum.at(parent, np.maximum(ra, rb), np.minimum(ra, rb))
        while True:  # pointer jumping until every node points at its root
            pp = parent[parent]
            if np.array_equal(pp, parent):
                break
            parent = pp
    root = parent == np.arange(n)
    first = np.cumsum(root) - 1
    return first[parent].astype(np.intp, copy=False), int(root.sum())
