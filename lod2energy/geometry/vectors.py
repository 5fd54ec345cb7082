"""Vector maths on rings and points: cross products, Newell normals, unit vectors, plane bases, 2D projection.

The one home of these operations: every module that needs a polygon's normal, a plane
basis or a projection calls them (floating-point order matters for bit-identical results,
so keep one implementation). Coordinates are metres.
"""
from __future__ import annotations

import math
from functools import reduce
from itertools import repeat
from operator import add, mul, sub
from typing import Sequence

import numpy as np

from lod2energy import cache

__all__ = ["roll_next", "cross_rows", "unit_rows", "newell_normal", "newell_normals",
           "rings_normal", "plane_basis", "plane_bases", "project_2d", "cross2", "vector_length", "unit"]


def newell_normal(points: np.ndarray, centred: bool = True) -> np.ndarray:
    """Newell's (area-weighted, unnormalised) normal of a closed ring.

    Parameters
    ----------
    points : (k, 3) float
        Ring vertices, open (first not repeated), m.
    centred : bool
        True: sum of the cross products of consecutive points taken about their mean (exact
        to the last bits for national-grid coordinates). False: Newell's textbook sums
        ``sum (y_i - y_i+1)(z_i + z_i+1)`` on the raw coordinates, the operation order the
        repair ladder's results were tuned on (both agree to rounding; keep each caller's
        order so that results stay bit-identical).

    Returns
    -------
    (3,) float
        Normal whose length is twice the ring's vector area, m2; zero for a degenerate ring.
    """
    p = np.asarray(points, dtype=np.float64)
    if len(p) < 3:
        return np.zeros(3)
    if len(p) < _SMALL_RING and p.ndim == 2 and p.shape[1] == 3:
        # the same ring is measured by several stages: remember its normal by its coordinates
        # (bytes and shape; strides and order change neither path's bits for k < 8)
        key = (centred, p.shape, p.tobytes())
        return cache.remember("geometry.ring-normals", key, lambda: _newell_small(p, centred), KEPT_RINGS).copy()
    return _newell_numpy(p, centred)


#: Small rings whose normal :func:`newell_normal` keeps (:mod:`lod2energy.cache`).
KEPT_RINGS = 8192


#: Rings with fewer vertices than this go through :func:`_newell_small` (Python floats): below
#: 8 terms numpy's pairwise summation is a plain left-to-right loop, which Python reproduces.
_SMALL_RING = 8


def _newell_small(p: np.ndarray, centred: bool) -> np.ndarray:
    """:func:`newell_normal` of a (k, 3) float64 ring with 3 <= k < 8, on Python floats.

    The same operations in the same order as :func:`_newell_numpy`, hence the same bits:
    numpy's ``add.reduce`` starts from 0.0 and, for fewer than 8 terms (contiguous rows) or
    along axis 0, adds the terms one after the other; the element-wise products, sums and
    differences are IEEE operations either way. A fifth of the cost on 4-point rings.
    """
    xs, ys, zs = zip(*p.tolist())
    k = len(xs)
    if centred:
        xs = tuple(map(sub, xs, repeat(reduce(add, xs, 0.0) / k)))
        ys = tuple(map(sub, ys, repeat(reduce(add, ys, 0.0) / k)))
        zs = tuple(map(sub, zs, repeat(reduce(add, zs, 0.0) / k)))
        xq, yq, zq = xs[1:] + xs[:1], ys[1:] + ys[:1], zs[1:] + zs[:1]
        # cross_rows(p, q) row by row, summed along axis 0
        return np.array([reduce(add, map(sub, map(mul, ys, zq), map(mul, zs, yq)), 0.0),
                         reduce(add, map(sub, map(mul, zs, xq), map(mul, xs, zq)), 0.0),
                         reduce(add, map(sub, map(mul, xs, yq), map(mul, ys, xq)), 0.0)])
    xq, yq, zq = xs[1:] + xs[:1], ys[1:] + ys[:1], zs[1:] + zs[:1]
    return np.array([reduce(add, map(mul, map(sub, ys, yq), map(add, zs, zq)), 0.0),
                     reduce(add, map(mul, map(sub, zs, zq), map(add, xs, xq)), 0.0),
                     reduce(add, map(mul, map(sub, xs, xq), map(add, ys, yq)), 0.0)])


def _newell_numpy(p: np.ndarray, centred: bool) -> np.ndarray:
    """:func:`newell_normal` of a float64 ring of at least 3 points, on numpy arrays."""
    if not centred:
        q = roll_next(p)
        # the three products as the rows of one C-contiguous (3, k) array: each row is summed
        # on its own, as np.sum of that product alone sums it (same bits, one call)
        t = np.ascontiguousarray(((p - q)[:, _NEWELL_A] * (p + q)[:, _NEWELL_B]).T)
        return np.add.reduce(t, axis=1)
    p = p - np.add.reduce(p, axis=0) / len(p)
    return np.add.reduce(cross_rows(p, roll_next(p)), axis=0)


#: Newell's sums: component c is sum((p - q)[:, _NEWELL_A[c]] * (p + q)[:, _NEWELL_B[c]]).
_NEWELL_A = np.array([1, 2, 0])
_NEWELL_B = np.array([2, 0, 1])


def roll_next(a: np.ndarray) -> np.ndarray:
    """The rows of ``a`` shifted by one: row ``i`` holds ``a[i + 1]``, the last row ``a[0]``.

    The same values as ``np.roll(a, -1, axis=0)`` at a fraction of its call overhead (the
    ring walks call it hundreds of thousands of times per file).

    Parameters
    ----------
    a : (k, ...) array

    Returns
    -------
    (k, ...) array
        A new array (``a`` is not modified).
    """
    return np.concatenate((a[1:], a[:1]))


def newell_normals(vertices: np.ndarray, rings: Sequence[np.ndarray]) -> np.ndarray:
    """Newell normals of many rings at once.

    Parameters
    ----------
    vertices : (n, 3) float
    rings : sequence of (k_i,) int

    Returns
    -------
    (len(rings), 3) float
        Unnormalised normals (length = 2 x area), m2.
    """
    if len(rings) == 0:
        return np.zeros((0, 3))
    lens = np.fromiter((len(r) for r in rings), dtype=np.intp, count=len(rings))
    idx = np.concatenate([np.asarray(r, dtype=np.intp) for r in rings])
    starts = np.concatenate(([0], np.cumsum(lens)[:-1]))
    nxt = np.arange(len(idx)) + 1
    ends = starts + lens - 1
    nxt[ends] = starts
    p = vertices[idx]
    p = p - p.mean(axis=0)
    cr = cross_rows(p, p[nxt])
    out = np.add.reduceat(cr, starts, axis=0) if len(idx) else np.zeros((0, 3))
    out[lens == 0] = 0.0
    return out


def project_2d(points: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """Project points on the coordinate plane most orthogonal to ``normal``, keeping orientation.

    A ring counter-clockwise around ``normal`` in 3D is counter-clockwise in 2D.

    Parameters
    ----------
    points : (k, 3) float
    normal : (3,) float

    Returns
    -------
    (k, 2) float
    """
    ax = int(np.argmax(np.abs(normal)))
    i, j = [(1, 2), (2, 0), (0, 1)][ax]
    if normal[ax] < 0:
        i, j = j, i
    return np.asarray(points)[:, [i, j]]

def cross_rows(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise cross product of (..., 3) arrays (cheaper than np.cross on small batches).

    Parameters
    ----------
    a, b : (..., 3) float

    Returns
    -------
    (..., 3) float
    """
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    c = (a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0)
    out = np.empty(c[0].shape + (3,), dtype=np.result_type(*c))  # np.stack(c, axis=-1), less overhead
    out[..., 0], out[..., 1], out[..., 2] = c
    return out


def unit_rows(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit vectors of the rows of ``v`` (..., 3) (zero stays zero) and their lengths (...,)."""
    if type(v) is np.ndarray and v.dtype == np.float64:
        # np.linalg.norm's own computation for real rows, without its argument handling
        ln = np.sqrt(np.add.reduce(v * v, axis=-1, keepdims=True))
    else:
        ln = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, ln, out=np.zeros_like(v), where=ln > 0), ln[..., 0]

def vector_length(v: np.ndarray) -> float:
    """Euclidean length of a 1-D float64 vector, computed as ``np.linalg.norm`` does it
    (``sqrt(v.dot(v))``, the same bits) without its argument handling."""
    return math.sqrt(float(v.dot(v)))


def unit(v: np.ndarray) -> np.ndarray:
    """``v`` (3,) scaled to length 1 (unchanged when it is zero)."""
    if type(v) is np.ndarray and v.ndim == 1 and v.dtype == np.float64:
        n = vector_length(v)
    else:
        n = float(np.linalg.norm(v))
    return v / n if n > 0 else v


def cross2(o, a, b):
    """z of the 2D cross product (a - o) x (b - o), over the last axis of (..., 2) arrays."""
    return (a[..., 0] - o[..., 0]) * (b[..., 1] - o[..., 1]) - (a[..., 1] - o[..., 1]) * (b[..., 0] - o[..., 0])


def rings_normal(vertices: np.ndarray, rings: Sequence[Sequence[int]], centred: bool = True) -> np.ndarray:
    """Unit normal of a polygon with holes: Newell vectors of all its rings summed.

    Holes wound against the outer ring subtract their area; a degenerate polygon gives zeros.

    Parameters
    ----------
    vertices : (n, 3) float
        m.
    rings : sequence of sequence of int
        Outer ring first, then holes (indices into ``vertices``).
    centred : bool
        See :func:`newell_normal`.

    Returns
    -------
    (3,) float
    """
    n = newell_normal(vertices[list(rings[0])], centred)
    for r in rings[1:]:
        n = n + newell_normal(vertices[list(r)], centred)
    ln = np.linalg.norm(n)
    return n / ln if ln > 0 else np.zeros(3)


def _cross3(a, b) -> np.ndarray:
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def plane_basis(n: np.ndarray) -> np.ndarray:
    """Orthonormal basis ``(u, v)`` of the plane with normal ``n``, right-handed with ``n``.

    ``u = n x a`` with ``a`` the x axis (the y axis when ``n`` is within 26 degrees of x).

    Parameters
    ----------
    n : (3,) float
        Normal (any length; zero gives the xy plane's basis).

    Returns
    -------
    (2, 3) float
    """
    n = np.asarray(n, dtype=np.float64)
    ln = float(np.sqrt(n @ n))
    if not ln > 0:  # degenerate face: any basis will do (callers reject the face anyway)
        return np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    n = n / ln
    a = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = _cross3(n, a)
    u /= np.sqrt(u @ u)
    v = _cross3(n, u)
    return np.vstack([u, v])


def plane_bases(normals: np.ndarray, helper: str = "x_or_y") -> tuple[np.ndarray, np.ndarray]:
    """Orthonormal bases ``u, v`` of many planes, each right-handed with its normal.

    Parameters
    ----------
    normals : (m, 3) float
        Unit normals.
    helper : {"x_or_y", "least"}
        The axis ``a`` in ``u = n x a``: ``"x_or_y"`` as :func:`plane_basis`; ``"least"`` the
        coordinate axis along which the normal is smallest (the validator's projection).

    Returns
    -------
    u, v : (m, 3) float
    """
    m = len(normals)
    if helper == "least":
        a = np.zeros((m, 3))
        a[np.arange(m), np.argmin(np.abs(normals), axis=1)] = 1.0
        u = cross_rows(normals, a)
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        return u, cross_rows(normals, u)
    a = np.where(np.abs(normals[:, :1]) < 0.9, np.array([[1.0, 0, 0]]), np.array([[0, 1.0, 0]]))
    u, _ = unit_rows(cross_rows(normals, a))
    return u, cross_rows(normals, u)
