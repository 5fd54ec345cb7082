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
    if not boundary and not dup and _surely_outward(v, polys):
        return problems  # the volume below is positive (see _surely_outward): nothing to add
    tris = []
    for poly in polys:
        pts = v[poly]
        t = triangulate(pts, [len(poly)])
        tris.extend([[poly[i] for i in tt] for tt in t])
    vol = signed_volume(v, np.asarray(tris, dtype=np.intp).reshape(-1, 3))
    if vol <= 0:
        problems.append(f"not outward: signed volume {vol:.3f} m3")
    return problems


_Z = np.array([[0.0, 0.0, 1.0]])
_X = np.array([[1.0, 0.0, 0.0]])


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise cross products of ``(m, 3)`` arrays (``np.cross`` without its overhead)."""
    a0, a1, a2 = a[:, 0], a[:, 1], a[:, 2]
    b0, b1, b2 = b[:, 0], b[:, 1], b[:, 2]
    return np.stack((a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0), axis=1)


#: Smallest sine of a turn of a ring projected on its plane for :func:`_surely_outward` to
#: take the ring as strictly convex.
_CONVEX_SIN = 1e-6


def _surely_outward(v: np.ndarray, polys: list[list[int]]) -> bool:
    """Is the signed volume :func:`check_closed_outward` computes from its earcut triangles
    certainly positive? Decided without triangulating; False when it cannot tell.

    Only for a shell whose rings (index lists into ``v``, ``(n, 3)`` m) use every directed
    edge once and its reverse once (zero boundary). Then the volume does not depend on the
    triangulation of a ring as long as that triangulation's boundary is the ring: two of them
    differ by the volume of a closed surface, which is at most ``delta x sum of its triangles'
    areas`` (``delta``: the largest distance of the ring's vertices from any plane; the
    volume is the integral of the height above that plane over the projected area). Earcut
    triangulates a strictly convex ring (every turn of its projection on the plane that
    :func:`polygons.triangulate` uses to the left by a sine of at least :data:`_CONVEX_SIN`,
    one turn in all) into ``k - 2`` triangles of its vertices that cover it, all oriented as
    the ring. So when every ring is strictly convex, the volume ``V`` of the fans
    ``(p0, p_i, p_i+1)`` minus the bound ``sum_r delta_r 2 k_r D_r^2`` (``D_r`` the diagonal
    of the ring's box, so no triangle of its vertices is larger than ``D_r^2 / 2``) and a
    margin for floating-point rounding is a lower bound of the earcut volume: when positive,
    the earcut volume is positive and the check adds nothing.
    """
    rings = [np.asarray(r, dtype=np.intp) for r in polys]
    if not rings or any(len(set(r)) != len(r) for r in polys):
        return False
    lens = np.array([len(r) for r in rings])
    starts = np.concatenate(([0], np.cumsum(lens)[:-1]))
    idx = np.concatenate(rings)
    P = v[idx]
    o = P.mean(axis=0)
    P = P - o
    ring_of = np.repeat(np.arange(len(rings)), lens)
    pos = np.arange(len(P)) - starts[ring_of]
    nxt = starts[ring_of] + (pos + 1) % lens[ring_of]
    # each ring's plane: the Newell normal (any plane serves the bound; this one for the
    # convexity test), through the ring's centroid
    cen = np.add.reduceat(P, starts, axis=0) / lens[:, None]
    rel = P - cen[ring_of]
    nrm = np.add.reduceat(_cross(rel, rel[nxt]), starts, axis=0)
    nlen = np.sqrt(np.sum(nrm * nrm, axis=1))
    if not np.all(nlen > 0):
        return False
    n = nrm / nlen[:, None]
    # in-plane basis u, v (u x v = n): the convexity test in the projection
    helper = np.where(np.abs(n[:, 2:3]) < 0.9, _Z, _X)
    bu = _cross(helper, n)
    bu /= np.sqrt(np.sum(bu * bu, axis=1))[:, None]
    bv = _cross(n, bu)
    x = np.sum(rel * bu[ring_of], axis=1)
    y = np.sum(rel * bv[ring_of], axis=1)
    dx, dy = x[nxt] - x, y[nxt] - y            # edge i: vertex i -> i + 1
    ex, ey = dx[nxt], dy[nxt]                  # the edge after it
    cross = dx * ey - dy * ex
    dot = dx * ex + dy * ey
    scale = np.hypot(dx, dy) * np.hypot(ex, ey)
    if not np.all(cross >= _CONVEX_SIN * scale) or not np.all(scale > 0):
        return False
    turning = np.add.reduceat(np.arctan2(cross, dot), starts)
    if not np.all(np.abs(turning - 2 * np.pi) < 1e-3):
        return False  # winds more than once
    # the fans' volume about o
    p0 = P[starts[ring_of]]
    fan = (pos >= 1) & (pos <= lens[ring_of] - 2)
    a, b, c = p0[fan], P[fan], P[nxt[fan]]
    dets = np.sum(a * _cross(b, c), axis=1)
    vol = float(dets.sum()) / 6.0
    # the bound, with room for rounding
    delta = np.maximum.reduceat(np.abs(np.sum(rel * n[ring_of], axis=1)), starts)
    diag2 = np.sum((np.maximum.reduceat(P, starts, axis=0) - np.minimum.reduceat(P, starts, axis=0)) ** 2, axis=1)
    bound = float(np.sum(delta * 2 * lens * diag2)) * (1 + 1e-9) + 1e-9
    r3 = float(np.max(np.sum(P * P, axis=1))) ** 1.5
    rounding = 1e-12 * (len(dets) + int(lens.sum())) * 8 * r3
    return vol - bound - rounding > 0
