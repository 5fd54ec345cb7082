"""Unique rows of index arrays (edges, triangles) as ``np.unique(a, axis=0)`` gives them, faster.

``np.unique`` along an axis sorts the rows as structured records; the writers' self-checks and
seam repairs call it on every zone's edges and triangles. Rows of non-negative integers below
``n`` are packed into one int64 each (``((a0 n) + a1) n + a2``), which keeps their
lexicographic order, and made unique in 1-D: the same unique rows in the same order, the same
inverse and counts.
"""
from __future__ import annotations

import numpy as np

#: Largest packed key (the int64 range).
_KEY_MAX = np.iinfo(np.int64).max


def row_keys(a: np.ndarray) -> np.ndarray | None:
    """One int64 per row of ``a`` ``(k, m)`` int, ordered as the rows are (lexicographically);
    None when ``a`` has a negative entry or its keys would not fit in an int64."""
    a = np.asarray(a)
    if a.ndim != 2 or a.dtype.kind not in "iu":
        return None
    k, m = a.shape
    if k == 0 or m == 0:
        return None
    if a.min() < 0:
        return None
    n = int(a.max()) + 1
    if n ** m > _KEY_MAX:
        return None
    keys = a[:, 0].astype(np.int64)
    for j in range(1, m):
        keys = keys * n + a[:, j]
    return keys


def unique_rows(a: np.ndarray, return_inverse: bool = False, return_counts: bool = False):
    """``np.unique(a, axis=0, return_inverse=..., return_counts=...)`` for an int array
    ``(k, m)``: the same unique rows (same order), inverse ``(k,)`` and counts.

    Returns
    -------
    unique rows (u, m), then the inverse and / or the counts when asked for (a tuple when
    either is; the unique rows alone otherwise), as :func:`numpy.unique` returns them.
    """
    a = np.asarray(a)
    keys = row_keys(a)
    if keys is None:
        out = np.unique(a, axis=0, return_inverse=return_inverse, return_counts=return_counts)
        if return_inverse:  # numpy 2.0 returned it as (k, 1) along an axis
            out = (out[0], out[1].ravel()) + tuple(out[2:])
        return out
    _, first, inv, cnt = np.unique(keys, return_index=True, return_inverse=True, return_counts=True)
    out = (a[first],)
    if return_inverse:
        out += (inv.ravel(),)
    if return_counts:
        out += (cnt,)
    return out if len(out) > 1 else out[0]


def same_position(points: np.ndarray) -> np.ndarray:
    """Which rows of ``points`` ``(n, m)`` float are equal, as ``np.unique(points, axis=0,
    return_inverse=True)`` groups them (its inverse, ``(n,)``: the same number for equal rows,
    ``-0.0 == 0.0``, a NaN equal to nothing), from a lexicographic sort of the columns instead
    of a sort of structured records."""
    p = np.asarray(points)
    if len(p) == 0:
        return np.zeros(0, dtype=np.intp)
    order = np.lexsort(p.T[::-1])
    s = p[order]
    new = np.any(s[1:] != s[:-1], axis=1)
    inv = np.empty(len(p), dtype=np.intp)
    inv[order] = np.concatenate(([0], np.cumsum(new)))
    return inv
