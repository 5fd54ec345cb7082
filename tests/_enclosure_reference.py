"""The pure-Python enclosure emulation as it was before vectorisation (reference only).

Kept verbatim from ``exporters/eplus_enclosure.py`` (commit a7d11fd; now ``exporters/energyplus/enclosure.py``) so that
``tests/test_enclosure_equivalence.py`` can show the vectorised implementation gives the
same results. Not used by the package.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from lod2energy.energy.enclosure import COINCIDENT, BadEdge, POINT_TOL, eplus_collinear


def reference_eplus_degenerate(points: np.ndarray) -> bool:
    pts = [np.asarray(p, dtype=np.float64) for p in points]
    keep = [pts[0]] if pts else []
    for p in pts[1:]:
        if np.linalg.norm(p - keep[-1]) >= COINCIDENT:
            keep.append(p)
    while len(keep) > 1 and np.linalg.norm(keep[0] - keep[-1]) < COINCIDENT:
        keep.pop()
    return len(keep) - len(eplus_collinear([np.asarray(keep).reshape(-1, 3)])[0]) < 3


def reference_eplus_vertices(points: np.ndarray) -> np.ndarray:
    pts = [np.asarray(p, dtype=np.float64) for p in points]
    keep = [pts[0]] if pts else []
    for p in pts[1:]:
        if np.linalg.norm(p - keep[-1]) >= COINCIDENT:
            keep.append(p)
    while len(keep) > 3 and np.linalg.norm(keep[0] - keep[-1]) < COINCIDENT:
        keep.pop()
    q = np.asarray(keep, dtype=np.float64).reshape(-1, 3)
    drop = eplus_collinear([q])[0]
    if drop and len(q) - len(drop) >= 3:
        q = np.delete(q, drop, axis=0)
    return q


class _Grid:
    """Points on a hash grid of cell ``tol``: the first stored point almost equal to a query."""

    def __init__(self, tol: float = POINT_TOL):
        self.tol = tol
        self.points: list[np.ndarray] = []
        self._cells: dict[tuple[int, int, int], list[int]] = {}

    def _cell(self, p: np.ndarray) -> tuple[int, int, int]:
        return tuple(int(x) for x in np.floor(p / self.tol))

    def near(self, p: np.ndarray) -> list[int]:
        """Indices of the stored points almost equal to ``p`` (per axis under ``tol``), ascending."""
        cx, cy, cz = self._cell(p)
        out = []
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for i in self._cells.get((cx + dx, cy + dy, cz + dz), ()):
                        if np.all(np.abs(self.points[i] - p) < self.tol):
                            out.append(i)
        return sorted(out)

    def append(self, p: np.ndarray) -> int:
        self.points.append(p)
        self._cells.setdefault(self._cell(p), []).append(len(self.points) - 1)
        return len(self.points) - 1


def reference_unique_vertices(surfaces: Sequence[np.ndarray], tol: float = POINT_TOL) -> list[np.ndarray]:
    """The zone's unique vertices in EnergyPlus's order (a point is new unless almost equal
    to one met before)."""
    g = _Grid(tol)
    for s in surfaces:
        for p in s:
            if not g.near(p):
                g.append(p)
    return g.points


def reference_eplus_merge(points: np.ndarray, tol: float = POINT_TOL) -> tuple[np.ndarray, np.ndarray]:
    """Points merged as EnergyPlus merges them: each becomes the first point met before it
    that is almost equal to it (per axis under ``tol``).

    Returns
    -------
    unique : (m, 3) float
    index : (n,) int
        The unique point of each input point.
    """
    g = _Grid(tol)
    idx = np.empty(len(points), dtype=np.intp)
    for i, p in enumerate(np.asarray(points, dtype=np.float64)):
        near = g.near(p)
        idx[i] = near[0] if near else g.append(p)
    return np.asarray(g.points, dtype=np.float64).reshape(-1, 3), idx


def reference_edges_not_two(surfaces: Sequence[np.ndarray], tol: float) -> list[tuple[np.ndarray, np.ndarray, list[int]]]:
    """EnergyPlus's edge count: an edge is the first stored one whose ends are almost equal to
    its ends (either direction). Returns (start, end, surfaces) of edges not used twice."""
    starts, ends = _Grid(tol), _Grid(tol)
    used: list[list[int]] = []
    for si, s in enumerate(surfaces):
        k = len(s)
        for i in range(k):
            a, b = s[i], s[(i + 1) % k]
            hit = None
            sa, eb = set(starts.near(a)), set(ends.near(b))
            sb, ea = set(starts.near(b)), set(ends.near(a))
            both = (sa & eb) | (sb & ea)
            if both:
                hit = min(both)
            if hit is None:
                starts.append(a)
                ends.append(b)
                used.append([si])
            else:
                used[hit].append(si)
    return [(starts.points[i], ends.points[i], u) for i, u in enumerate(used) if len(u) != 2]


def reference_on_line(a: np.ndarray, b: np.ndarray, t: np.ndarray, tol: float) -> bool:
    """EnergyPlus's ``isPointOnLineBetweenPoints``: ``t`` within ``tol`` of the line ``ab``
    and the path through it no more than ``tol`` longer than ``ab``."""
    ab = b - a
    L = float(np.linalg.norm(ab))
    if L <= 0.0 or float(np.linalg.norm(np.cross(ab, t - a))) / L >= tol:
        return False
    return abs(L - (float(np.linalg.norm(t - a)) + float(np.linalg.norm(b - t)))) < tol


def reference_insert_collinear(face: np.ndarray, uniq: np.ndarray, tol: float) -> np.ndarray:
    """``face`` with every unique vertex EnergyPlus finds on one of its edges inserted."""
    pts = [p for p in face]
    for _ in range(len(uniq) + 1):
        inserted = False
        k = len(pts)
        for i in range(k):
            a, b = pts[i], pts[(i + 1) % k]
            lo = np.minimum(a, b) - tol
            hi = np.maximum(a, b) + tol
            for t in np.nonzero(np.all((uniq >= lo) & (uniq <= hi), axis=1))[0]:
                pt = uniq[t]
                if np.all(np.abs(pt - a) < tol) or np.all(np.abs(pt - b) < tol):
                    continue
                if reference_on_line(a, b, pt, tol):
                    pts.insert(i + 1, pt)
                    inserted = True
                    break
            if inserted:
                break
        if not inserted:
            break
    return np.asarray(pts)


def reference_enclosure_defects(surfaces: Sequence[np.ndarray], tol: float = POINT_TOL) -> list[BadEdge]:
    """Edges of a zone EnergyPlus would find not shared by exactly two surfaces.

    Parameters
    ----------
    surfaces : sequence of (k, 3) float arrays
        The zone's ``BuildingSurface:Detailed`` vertices (m), in the order of the IDF.
    tol : float, m

    Returns
    -------
    list of BadEdge
        Empty when EnergyPlus would call the zone fully enclosed; else the edges that fail
        both counts (what EnergyPlus lists in its warning) or, when none fails both, those
        that fail the second count.
    """
    faces = [reference_eplus_vertices(np.asarray(s, dtype=np.float64)) for s in surfaces]
    return reference_face_defects(faces, tol)


def reference_face_defects(faces: Sequence[np.ndarray], tol: float = POINT_TOL) -> list[BadEdge]:
    """:func:`reference_enclosure_defects` of surfaces given as EnergyPlus keeps them
    (:func:`reference_eplus_vertices` of each, float64 ``(k_i, 3)``)."""
    first = reference_edges_not_two(faces, tol)
    if not first:
        return []
    uniq = np.asarray(reference_unique_vertices(faces, tol))
    second = reference_edges_not_two([reference_insert_collinear(f, uniq, tol) for f in faces], tol)
    if not second:
        return []

    def same(x, y):
        return ((np.all(np.abs(x[0] - y[0]) < tol) and np.all(np.abs(x[1] - y[1]) < tol))
                or (np.all(np.abs(x[0] - y[1]) < tol) and np.all(np.abs(x[1] - y[0]) < tol)))
    # EnergyPlus lists the edges that fail both counts (possibly none: the zone still fails)
    both = [e for e in first if any(same(e, f) for f in second)]
    return [BadEdge(e[0].copy(), e[1].copy(), len(e[2]), tuple(e[2])) for e in (both or second)]
