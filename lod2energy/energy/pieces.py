"""Pieces: the planar convex parts of a zone face as they are written, and their decomposition.

Every input face becomes one or more ``BuildingSurface:Detailed`` (planar convex pieces,
counter-clockwise seen from outside, in a local frame whose offset is written in the IDF header).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np

from lod2energy.geometry.polygons import is_convex_2d, merge_convex, newell_normal, PLANAR_TOL, wall_basis, triangulate, unit
from lod2energy.energy.zones.shells import ZoneFace, ZoneShell

#: Decimals of the vertex coordinates written to the IDF (m): 0.1 mm.
WRITE_DECIMALS = 4


@dataclass(frozen=True)
class Piece:
    """A planar convex part of a zone face as it will be written.

    Parameters
    ----------
    points : (k, 3) float, m
        Counter-clockwise seen from outside, in the dataset-local frame.
    kind : str
        "roof" / "wall" / "ground" / "floor".
    boundary : str
        "Outdoors", "Ground" or "Adiabatic".
    u_value : float, W/(m2 K)
    face_index : int
    link : str, optional
        Interzone pieces (``boundary == "Surface"``): ``"<key>:c"`` for a ceiling, ``"<key>:f"``
        for the floor on its other side (the same key).
    glazed : bool
        False for an outdoor wall that gets no windows (a wall shared with an unconditioned
        building, written as an outdoor wall).
    """

    points: np.ndarray
    kind: str
    boundary: str
    u_value: float
    face_index: int
    link: str | None = None
    glazed: bool = True


def _face_frame(zone: ZoneShell, face: ZoneFace):
    pts, ends = zone.face_points(face)
    n = unit(newell_normal(pts[: ends[0]]))
    c = pts[: ends[0]].mean(axis=0)
    return pts, ends, n, c


def _planar(pts: np.ndarray, n: np.ndarray, c: np.ndarray, tol: float = PLANAR_TOL) -> bool:
    return bool(np.all(np.abs((pts - c) @ n) <= tol))


#: Ring vertices this close (m) to the segment joining the kept vertices around them are
#: left out of the convex decomposition and put back on the piece edge they lie on.
NEAR_COLLINEAR = 0.01


def _near_collinear_chains(xy: np.ndarray, ends: Sequence[int], tol: float = NEAR_COLLINEAR
                           ) -> dict[int, tuple[int, list[int]]]:
    """Vertices to leave out of a decomposition: ``{a: (b, [m1, m2, ..])}`` where ``a`` and
    ``b`` are consecutive kept vertices of a ring and ``m1, m2, ..`` the left-out ones
    between them, all within ``tol`` (m) of the segment ``ab``."""
    chains: dict[int, tuple[int, list[int]]] = {}
    start = 0
    for end in ends:
        ring = list(range(start, end))
        start = end
        after: dict[int, list[int]] = {i: [] for i in ring}
        changed = True
        while changed and len(ring) > 3:
            changed = False
            for k in range(len(ring)):
                p, i, q = ring[k - 1], ring[k], ring[(k + 1) % len(ring)]
                a, b = xy[p], xy[q]
                ab = b - a
                L2 = float(ab @ ab)
                if L2 <= 0:
                    continue
                cand = after[p] + [i] + after[i]
                t = (xy[cand] - a) @ ab / L2
                d = np.abs((xy[cand, 0] - a[0]) * ab[1] - (xy[cand, 1] - a[1]) * ab[0]) / np.sqrt(L2)
                if np.all((t > 0) & (t < 1)) and np.all(d < tol):
                    after[p] = cand
                    del after[i]
                    del ring[k]
                    changed = True
                    break
        for k, i in enumerate(ring):
            if after[i]:
                chains[i] = (ring[(k + 1) % len(ring)], after[i])
    return chains


def _pieces_from_points(pts: np.ndarray, ends: Sequence[int], n: np.ndarray, c: np.ndarray) -> list[np.ndarray]:
    """Planar convex pieces (or triangles for non-planar faces) of one polygon with holes.

    Vertices within :data:`NEAR_COLLINEAR` of the line through their neighbours are left out
    of the decomposition and then put back on the edge of the piece they lie on: a
    decomposition through them would cut slivers narrower than EnergyPlus's 1.27 cm point
    tolerance, which its enclosure test cannot match.
    """
    planar = _planar(pts, n, c)
    u, v = wall_basis(n)
    xy = np.column_stack([(pts - c) @ u, (pts - c) @ v])
    if len(ends) == 1 and planar and is_convex_2d(xy):
        return [pts]
    chains = _near_collinear_chains(xy, ends)
    if chains:
        dropped = {m for _, ms in chains.values() for m in ms}
        sub = np.array([i for i in range(len(pts)) if i not in dropped])
        sub_ends = [int(np.searchsorted(sub, e)) for e in ends]
        polys = _decompose(pts[sub], sub_ends, n, xy[sub], planar)
        polys = [[int(sub[i]) for i in p] for p in polys]
        out = _put_back(polys, chains)
        if out is not None:
            return [pts[p] for p in out]
    return [pts[p] for p in _decompose(pts, ends, n, xy, planar)]


def _decompose(pts, ends, n, xy, planar) -> list[list[int]]:
    if len(ends) == 1 and planar and is_convex_2d(xy):
        return [list(range(len(pts)))]
    tris = triangulate(pts, ends, n)
    if len(tris) == 0:
        return []
    if planar:
        return merge_convex(tris, xy)
    return [list(map(int, t)) for t in tris]


def _put_back(polys: list[list[int]], chains: dict[int, tuple[int, list[int]]]) -> list[list[int]] | None:
    """Insert each chain between its kept vertices ``a`` and ``b`` on the piece that has the
    edge ``a -> b``; None when no piece has it."""
    out = [list(p) for p in polys]
    for a, (b, ms) in chains.items():
        for pi, p in enumerate(out):
            k = next((k for k in range(len(p)) if p[k] == a and p[(k + 1) % len(p)] == b), None)
            if k is not None:
                out[pi] = p[:k + 1] + ms + p[k + 1:]
                break
        else:
            return None
    return out


def _outer_boundary(kind: str) -> str:
    return "Ground" if kind == "ground" else "Outdoors"


def _as_written(pieces: list[Piece]) -> list[Piece]:
    """Pieces with their points rounded as the IDF writes them, so that every emulated
    EnergyPlus test sees what EnergyPlus will read (rounding can make a near-collinear vertex
    collinear in EnergyPlus's projection plane)."""
    return [replace(p, points=np.round(p.points, WRITE_DECIMALS)) for p in pieces]


def _planar_dev(q: np.ndarray) -> float:
    """Largest distance (m) of the points ``(k, 3)`` to their Newell plane."""
    return _planar_dev_of(q, newell_normal(q))


def _planar_dev_of(q: np.ndarray, normal: np.ndarray) -> float:
    """:func:`_planar_dev` of ``q`` whose :func:`newell_normal` is ``normal`` (given when the
    caller has it)."""
    n = unit(normal)
    return float(np.max(np.abs((q - q.mean(axis=0)) @ n))) if np.any(n) else 0.0


#: Machine epsilon of float64.
_EPS = float(np.finfo(np.float64).eps)


def _surely_planar(rings: Sequence[np.ndarray], max_dev: float, min_area: float = -np.inf) -> list[bool]:
    """Per ring (``(k, 3)`` float64, k >= 3, m): is it certainly within ``max_dev`` (m) of its
    plane (:func:`_planar_dev` at most ``max_dev``) and larger than ``min_area`` (m2, half
    the length of :func:`polygons.newell_normal`)? False when it cannot tell: the caller
    then runs the tests themselves.

    The same formulas on all rings at once; sums run in another order than one ring at a
    time (``np.add.reduceat`` against numpy's pairwise sums), so each result carries a
    bound of that difference: a sum of ``k`` terms is off by at most ``k eps sum|t|`` either
    way; the unit normal by that over the normal's length; the centroid by ``k eps max|p|``.
    A ring is passed only when its normal is many times longer than its error and its
    values clear the thresholds by more than the bounds (several times over).
    """
    if not len(rings):
        return []
    lens = np.fromiter((len(r) for r in rings), dtype=np.intp, count=len(rings))
    P = np.concatenate(rings)
    starts = np.concatenate(([0], np.cumsum(lens)[:-1]))
    ring_of = np.repeat(np.arange(len(rings)), lens)
    nxt = np.arange(1, len(P) + 1)
    nxt[starts + lens - 1] = starts
    Q = P[nxt]
    # Newell's textbook sums (polygons.newell_normal): component c sums
    # (p - q)[A[c]] * (p + q)[B[c]]
    t = (P - Q)[:, [1, 2, 0]] * (P + Q)[:, [2, 0, 1]]
    nn = np.add.reduceat(t, starts, axis=0)
    err_nn = 4.0 * lens * _EPS * np.add.reduceat(np.abs(t), starts, axis=0).max(axis=1) + 1e-300
    nlen = np.sqrt(np.sum(nn * nn, axis=1))
    area = 0.5 * nlen
    ok = (nlen > 16.0 * err_nn) & (area - (2.0 * err_nn + 8 * _EPS * area) > min_area)
    safe = np.where(ok, nlen, 1.0)
    n = nn / safe[:, None]
    cen = np.add.reduceat(P, starts, axis=0) / lens[:, None]
    rel = P - cen[ring_of]
    dev = np.maximum.reduceat(np.abs(np.sum(rel * n[ring_of], axis=1)), starts)
    reach = np.maximum.reduceat(np.sqrt(np.sum(rel * rel, axis=1)), starts)
    scale = np.maximum.reduceat(np.abs(P).max(axis=1), starts)
    err_dev = reach * (8.0 * err_nn / safe + 16 * _EPS) + 8.0 * lens * _EPS * scale + 1e-12
    return (ok & (dev + err_dev <= max_dev)).tolist()


def _pieces_volume(pieces: Sequence[Piece]) -> float:
    """Enclosed volume (m3) of a zone's convex pieces (fan triangulation, divergence theorem)."""
    vol = 0.0
    for p in pieces:
        q = p.points
        if q.dtype != np.float64 or q.ndim != 2 or q.shape[1] != 3:
            for k in range(1, len(q) - 1):
                vol += float(np.dot(q[0], np.cross(q[k], q[k + 1]))) / 6.0
            continue
        # np.cross of two 3-vectors written out on floats in its operation order (same bits);
        # the dot stays np.dot (BLAS sums in its own order)
        q0, rows = q[0], q.tolist()
        for k in range(1, len(rows) - 1):
            x0, x1, x2 = rows[k]
            y0, y1, y2 = rows[k + 1]
            vol += float(np.dot(q0, np.array([x1 * y2 - x2 * y1, x2 * y0 - x0 * y2, x0 * y1 - x1 * y0]))) / 6.0
    return vol
