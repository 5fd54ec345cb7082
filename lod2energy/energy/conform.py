"""Pieces conformed to EnergyPlus's enclosure test: kept corners, folded slivers, merged vertices.

The emulated test itself is :mod:`lod2energy.energy.enclosure`.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import replace

import numpy as np

from lod2energy.energy.enclosure import (
    _drop_coincident, _on_line, enclosure_defects, eplus_collinear, eplus_degenerate, snap_polygons,
)
from lod2energy.energy.pieces import Piece, WRITE_DECIMALS, _planar_dev, _surely_planar
from lod2energy.energy.zones.shells import MIN_PIECE_AREA
from lod2energy.geometry.polygons import polygon_area3d
from lod2energy.validate.closed import check_closed_outward
from lod2energy.geometry.snap import weld
from lod2energy.geometry import split_at_points


#: A vertex EnergyPlus finds collinear but which lies farther than this (m) from the line
#: through its neighbours in 3D is a real corner (:func:`keep_corners`).
CORNER_TOL = 1e-3


def keep_corners(pieces: list[Piece], tol: float = CORNER_TOL) -> list[Piece]:
    """Pieces in which EnergyPlus would drop no real corner.

    EnergyPlus tests collinearity in a coordinate plane (:func:`enclosure.eplus_collinear`):
    on a wall a fraction of a degree off vertical, projected on XY, a corner of a stepped
    bottom edge looks collinear and is removed, which opens the zone. Such a piece, one that
    EnergyPlus would call degenerate (fewer than 3 sides left) and one more than
    :data:`PIECE_PLANAR` out of plane are written as a fan of triangles around the centroid
    (a triangle keeps its three vertices and is planar); a fan triangle EnergyPlus would
    still call degenerate is left out (its short side is merged away by EnergyPlus too).
    """
    # EnergyPlus's collinear and degenerate tests batched over all pieces (the same verdicts
    # as eplus_collinear / eplus_degenerate of each one, bit for bit)
    rings = [np.asarray(p.points, dtype=np.float64) for p in pieces]
    collinear = eplus_collinear(rings)
    degenerate = _degenerate_given(rings, collinear)
    # the planarity test of the pieces with more than 3 vertices at once, where certain
    flat = iter(_surely_planar([q for q in rings if len(q) > 3], PIECE_PLANAR))
    out = []
    for p, q0, col, deg in zip(pieces, rings, collinear, degenerate):
        q = p.points
        sure = next(flat) if len(q0) > 3 else True
        lost = [i for i in col if not _on_line(q[i - 1], q[(i + 1) % len(q)], q[i], tol)]
        if not lost and not deg and (len(q) == 3 or sure or _planar_dev(q) <= PIECE_PLANAR):
            out.append(p)
            continue
        c = np.round(q.mean(axis=0), WRITE_DECIMALS)
        tris = [np.array([c, q[i], q[(i + 1) % len(q)]]) for i in range(len(q))]
        tris = [t for t in tris if polygon_area3d(t) > 1e-9]
        for tri, bad in zip(tris, eplus_degenerate(tris)):
            if not bad:
                out.append(replace(p, points=tri))
    return out


def _degenerate_given(rings: list[np.ndarray], collinear: list[list[int]]) -> list[bool]:
    """:func:`enclosure.eplus_degenerate` of ``rings`` whose :func:`eplus_collinear` is
    ``collinear``: the coincident test keeps every vertex of most rings, and then the
    collinear test it runs is that one (the same rows, the same verdicts)."""
    keeps = _drop_coincident(rings, 1)
    redo = [k for k, (q, kq) in enumerate(zip(rings, keeps)) if len(kq) != len(q)]
    cols = list(collinear)
    for k, c in zip(redo, eplus_collinear([keeps[k] for k in redo])):
        cols[k] = c
    return [len(kq) - len(c) < 3 for kq, c in zip(keeps, cols)]


#: A piece whose points lie farther than this (m) from their Newell plane is written as
#: triangles (EnergyPlus calls more than 1 cm "out of line" a severe error).
PIECE_PLANAR = 0.005


#: Vertex merges tried by :func:`eplus_enclose`: none (slivers dropped only), EnergyPlus's
#: own, then at 2 and 3 cm.
ENCLOSE_WELDS = (False, None, 0.02, 0.03)


def eplus_enclose(pieces: list[Piece]) -> list[Piece]:
    """Pieces that EnergyPlus's enclosure test accepts, when the written ones would fail it.

    EnergyPlus merges vertices closer than 1.27 cm per axis and then needs every edge on
    exactly two surfaces (:func:`enclosure.enclosure_defects`). A zone with features
    under that size (a 1.6 cm edge, two corners 8 mm apart, a sliver piece) can fail although
    it is a closed 2-manifold. Candidates, in order: the pieces with EnergyPlus's sliver
    triangles folded into their neighbours (:func:`eplus_conform`); then, from those and from
    the pieces as they are, slivers under 5 mm dropped, vertices merged as EnergyPlus merges
    them, then at 2 and 3 cm (:func:`enclosure.snap_polygons`). The first candidate that
    is closed, outward and passes the emulated test is returned; otherwise the pieces.
    """
    def passes(cand):
        cp = [c.points for c in cand]
        return bool(cand) and not check_closed_outward(cp) and not enclosure_defects(cp)

    if not pieces or not enclosure_defects([p.points for p in pieces]):
        return pieces
    conformed = eplus_conform(pieces)
    if passes(conformed):
        return conformed
    for tol in ENCLOSE_WELDS:
        for base in (conformed, pieces):
            snapped = snap_polygons([p.points for p in base], tol or None, merge=tol is not False)
            cand = [replace(base[i], points=q) for i, q in snapped]
            if passes(cand):
                return cand
    return pieces


#: EnergyPlus's point tolerance (m) in its enclosure test (``isAlmostEqual3dPt`` and
#: ``isPointOnLineBetweenPoints`` in SurfaceGeometry.cc, 0.0127 m = 1/2 inch).
EPLUS_POINT_TOL = 0.0127


def _on_segment(a: np.ndarray, b: np.ndarray, c: np.ndarray, tol: float = EPLUS_POINT_TOL) -> bool:
    """Would EnergyPlus see point ``c`` on segment ``ab``: not almost equal to either end (per
    axis), within ``tol`` of the line and ``|ac| + |cb| - |ab| < tol``."""
    if np.all(np.abs(c - a) < tol) or np.all(np.abs(c - b) < tol):
        return False
    return _on_line(a, b, c, tol)


class _PieceMemo:
    """Values per Piece object (a Piece holds arrays, so it is not hashable): keyed by identity,
    each piece held here so that its id is not reused while the memo lives. Pieces are
    immutable, so what was found for one stays true."""
    def __init__(self):
        self._d: dict[int, tuple[Piece, object]] = {}

    def get(self, p: Piece, default=None):
        m = self._d.get(id(p))
        return m[1] if m is not None and m[0] is p else default

    def put(self, p: Piece, value=True) -> None:
        self._d[id(p)] = (p, value)


def _split_on_own_edge(pieces: list[Piece], tol: float = EPLUS_POINT_TOL,
                       clean: _PieceMemo | None = None) -> list[Piece] | None:
    """Split the first piece with a vertex EnergyPlus sees on another of its edges.

    A thin piece ``(.., a, b, .., c, ..)`` whose vertex ``c`` lies within ``tol`` of its
    edge ``ab`` (EnergyPlus inserts ``c`` there and then counts ``a-c`` twice) becomes the
    triangle ``(a, b, c)`` (a sliver that :func:`eplus_conform` folds into the neighbour
    across ``ab``), the part ``(b, .., c)`` and the part ``(c, .., a)``; parts with fewer
    than 3 vertices are left out. Internal edges ``b-c`` and ``c-a`` are shared by two
    parts, so the shell stays closed. Returns None when no piece has such a vertex.
    ``clean`` holds the pieces already scanned without a hit: they are skipped, and the pieces
    scanned now without a hit are added.
    """
    for pi, p in enumerate(pieces):
        q = p.points
        k = len(q)
        if k < 4 or (clean is not None and clean.get(p)):
            continue
        for i in range(k):
            ib = (i + 1) % k
            for j in range(k):
                if j in (i, ib) or not _on_segment(q[i], q[ib], q[j], tol):
                    continue
                tri = q[[i, ib, j]]
                q1 = q[[(ib + m) % k for m in range((j - ib) % k + 1)]]
                q2 = q[[(j + m) % k for m in range((i - j) % k + 1)]]
                new = [replace(p, points=x) for x in (tri, q1, q2) if len(x) >= 3]
                return pieces[:pi] + new + pieces[pi + 1:]
        if clean is not None:
            clean.put(p)
    return None


def eplus_conform(pieces: list[Piece], tol: float = EPLUS_POINT_TOL) -> list[Piece]:
    """Drop sliver triangles EnergyPlus's enclosure test cannot match, keeping the zone closed.

    EnergyPlus inserts every zone vertex it finds on a surface edge (the two distances
    through the vertex exceed the edge length by less than ``tol``) before counting edges.
    A sliver triangle ``(a, b, c)`` with ``c`` "on" ``ab`` then folds onto itself and its
    edges no longer match. Such a triangle is dropped and ``c`` is inserted into the edge
    ``ba`` of the neighbouring piece, so the written shell stays closed (edges ``a-c`` and
    ``c-b`` are shared with the triangle's other neighbours) and equals what EnergyPlus sees.
    When ``c`` is off the neighbour's plane, the neighbour is written as a fan of triangles
    from ``c`` (each planar).

    Parameters
    ----------
    pieces : list of Piece
        Pieces of one closed zone (neighbours share exact vertex coordinates).
    tol : float, m

    Returns
    -------
    list of Piece
    """
    out = _eplus_conform(pieces, tol, split=True)
    if _edge_defects(out) > _edge_defects(pieces):
        # a split piece's vertex landed in a neighbour that already holds the edge through it
        out = _eplus_conform(pieces, tol, split=False)
    return out


def _edge_defects(pieces: list[Piece]) -> int:
    """Directed edges used more than once plus edges without their reverse."""
    cnt = Counter()
    for p in pieces:
        k = [tuple(np.round(x, 6).tolist()) for x in p.points]
        cnt.update((k[i], k[(i + 1) % len(k)]) for i in range(len(k)))
    return sum(1 for e, n in cnt.items() if n > 1 or (e[1], e[0]) not in cnt)


def _eplus_conform(pieces: list[Piece], tol: float, split: bool) -> list[Piece]:
    def key(x):
        return tuple(np.round(x, 6).tolist())

    out = list(pieces)
    # pieces already scanned without a hit (immutable, so they stay so): the scans below skip
    # them and find the same first hit as a scan of every piece
    tri_clean, own_clean, edge_memo = _PieceMemo(), _PieceMemo(), _PieceMemo()

    def edges_of(p):
        """``{(key of a vertex, key of the next): first index}`` of piece ``p`` (memoised)."""
        d = edge_memo.get(p)
        if d is None:
            k = [key(x) for x in p.points]
            d = {}
            for i in range(len(k)):
                d.setdefault((k[i], k[(i + 1) % len(k)]), i)
            edge_memo.put(p, d)
        return d
    for _ in range(4 * len(pieces) + 8):
        hit = None
        for pi, p in enumerate(out):
            q = p.points
            if len(q) != 3 or tri_clean.get(p):
                continue
            for i in range(3):
                a, b, c = q[i], q[(i + 1) % 3], q[(i + 2) % 3]
                if _on_segment(a, b, c, tol):
                    hit = (pi, a, b, c)
                    break
            if hit:
                break
            tri_clean.put(p)
        if hit is None:
            parts = _split_on_own_edge(out, tol, own_clean) if split else None
            if parts is None:
                break
            out = parts
            continue
        pi, a, b, c = hit
        ka, kb = key(a), key(b)
        nb = None
        for qi, p in enumerate(out):
            if qi == pi:
                continue
            edges = edges_of(p)
            i = edges.get((kb, ka))
            if i is not None:
                nb = (qi, i)
                break
        if nb is None:
            break  # no neighbour across ab: leave the zone as it is
        qi, i = nb
        q = np.insert(out[qi].points, i + 1, c, axis=0)
        if _planar_dev(q) > 1e-3:
            # c is off the neighbour's plane: a fan of triangles from c keeps every part planar
            k = len(q)
            j = i + 1
            fan = [q[[j, (j + m) % k, (j + m + 1) % k]] for m in range(1, k - 1)]
            new = [replace(out[qi], points=t) for t in fan if polygon_area3d(t) > MIN_PIECE_AREA]
        else:
            new = [replace(out[qi], points=q)]
        out = [p for ri, p in enumerate(out) if ri not in (pi, qi)] + new
    return out


def clean_piece(p: np.ndarray, min_area: float = 0.05, min_edge: float = 0.025,
                point_tol: float = 0.0127) -> bool:
    """No sliver: area, edge lengths and off-line vertices clear of EnergyPlus's tolerance.

    A vertex either lies on the line through its neighbours (EnergyPlus drops it) or at
    least ``point_tol`` (m) away from it.
    """
    if polygon_area3d(p) < min_area:
        return False
    k = len(p)
    for i in range(k):
        a, b, c = p[i - 1], p[i], p[(i + 1) % k]
        if np.linalg.norm(b - a) < min_edge:
            return False
        ac = c - a
        t = float((b - a) @ ac) / float(ac @ ac)
        d = float(np.linalg.norm(a + t * ac - b))
        if 1e-4 < d < point_tol:
            return False
    return True


def conform(pieces: list[Piece], tol: float = 1e-5) -> list[Piece]:
    """Insert into every piece the zone vertices that lie on its edges (no T-junctions).

    Splitting a face adds vertices on its boundary; the neighbouring faces get them too, so
    that every edge is shared by exactly two surfaces (EnergyPlus's enclosure test).
    """
    if not pieces:
        return pieces
    allp = np.concatenate([p.points for p in pieces])
    v, idx = weld(allp, tol / 2)
    polys, k = [], 0
    for p in pieces:
        polys.append(idx[k:k + len(p.points)].tolist())
        k += len(p.points)
    polys = split_at_points(v, polys, tol, only_unmatched=True)
    out = []
    for p, poly in zip(pieces, polys):
        poly = [i for j, i in enumerate(poly) if i != poly[j - 1]]
        if len(poly) >= 3:
            out.append(replace(p, points=v[poly]))
    return out
