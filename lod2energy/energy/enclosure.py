"""EnergyPlus's zone enclosure test, emulated.

EnergyPlus (``CalculateZoneVolume`` in SurfaceGeometry.cc) calls a zone "not fully
enclosed" when an edge of its surfaces is not shared by exactly two surfaces. It compares
points with a per-axis tolerance of 0.0127 m (``isAlmostEqual3dPt``), so vertices a few
millimetres apart become one vertex and a short edge can collapse onto a point, and when the
first count fails it inserts into every surface edge each zone vertex it finds "on" that edge
(``|ac| + |cb| - |ab| < 0.0127 m``) and counts again. Both passes are reproduced here so the
exporter can check - and fix - a zone before EnergyPlus sees it, and tests can show it
without running EnergyPlus.

The steps follow EnergyPlus 9-25:

1. surface vertices as EnergyPlus keeps them: a vertex closer than :data:`COINCIDENT` to the
   one before it is dropped (``GetVertices``), so is a vertex on the line through its
   neighbours in the coordinate plane EnergyPlus projects the surface on (``CheckConvexity``,
   "collinear points that have been removed");
2. the zone's unique vertices: a vertex is new unless it is almost equal (per axis, under
   :data:`POINT_TOL`) to one met before; each surface point is the *first* almost-equal
   unique vertex;
3. undirected edges between unique vertices counted over all surfaces; enclosed when
   every count is 2;
4. otherwise every unique vertex "on" a surface edge is inserted into it (repeatedly), and
   the edges are counted again; the zone is enclosed when that second count passes.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
from scipy.spatial import cKDTree

from lod2energy import cache
from lod2energy.geometry.polygons import polygon_area3d
from lod2energy.geometry.snap import weld

#: Per-axis tolerance (m) of EnergyPlus's ``isAlmostEqual3dPt`` and the slack of its
#: ``isPointOnLineBetweenPoints`` (1/2 inch).
POINT_TOL = 0.0127
#: Consecutive surface vertices closer than this (m) are merged by EnergyPlus's GetVertices.
COINCIDENT = 0.01
#: EnergyPlus's ``CheckConvexity`` works in the first coordinate plane (XY, XZ, YZ) in which
#: the polygon's doubled signed area exceeds this (m2) ...
PLANE_DET = 1e-4
#: ... and drops a vertex where the sine of the outline's turn is below this in that plane
#: (straight on, or doubling back in a spike): collinear in the projection, which for a wall
#: a fraction of a degree off vertical (projected on XY) need not be collinear in 3D.
TURN_THRESHOLD = 1e-6
#: A projected edge shorter than this (m) has no direction.
PROJECTED_EPS = 1e-9


@dataclass(frozen=True)
class BadEdge:
    """An edge EnergyPlus would count other than twice.

    Attributes
    ----------
    start, end : (3,) float arrays
        The edge's unique vertices (m, the IDF's frame).
    count : int
        Surfaces that use it (1: open, 3+: more than two surfaces meet).
    surfaces : tuple of int
        Indices of the surfaces that use it.
    """
    start: np.ndarray
    end: np.ndarray
    count: int
    surfaces: tuple[int, ...]


def eplus_collinear(rings: Sequence[np.ndarray]) -> list[list[int]]:
    """The vertices EnergyPlus's ``CheckConvexity`` finds collinear with their neighbours, in
    each ring ``(k_i, 3)`` float64 (in its projection plane, see :data:`PLANE_DET`,
    :data:`TURN_THRESHOLD`).

    The element-wise arithmetic runs once over the concatenated rings; each ring's projected
    doubled area (which picks its coordinate plane) is summed on its own slice, so every
    decision is the one the ring alone gives. The sine of the turn decides: a spike (the
    outline doubling back, turn = pi) counts too; a vertex next to an edge that projects to a
    point (a vertical edge seen from above) has no turn and is kept.

    Returns
    -------
    list of list of int
        Per ring, the indices of its collinear vertices (empty for rings of < 3 vertices).
    """
    out: list[list[int]] = [[] for _ in rings]
    idx = [r for r, q in enumerate(rings) if len(q) >= 3]
    if not idx:
        return out
    qs = [rings[r] for r in idx]
    lens = [len(q) for q in qs]
    Q = np.concatenate(qs) if len(qs) > 1 else qs[0]
    # each ring's rows shifted once each way (np.roll per ring), as one gather
    starts = np.cumsum([0] + lens[:-1])
    pos = np.arange(len(Q)) - np.repeat(starts, lens)
    k = np.repeat(lens, lens)
    first = np.repeat(starts, lens)
    nxt = first + (pos + 1) % k
    prv = first + (pos - 1) % k
    Qn, Qp = Q[nxt], Q[prv]
    # doubled signed area in the XY, XZ and YZ planes, element-wise once; summed per ring on
    # its own contiguous slice (same summation as np.sum of the ring alone)
    terms = [Q[:, i] * Qn[:, j] - Qn[:, i] * Q[:, j] for i, j in ((0, 1), (0, 2), (1, 2))]
    ia = np.empty(len(Q), dtype=np.intp)
    ib = np.empty(len(Q), dtype=np.intp)
    a = 0
    for k_r in lens:
        b = a + k_r
        for (i, j), t in zip(((0, 1), (0, 2), (1, 2)), terms):
            if abs(float(np.sum(t[a:b]))) > PLANE_DET:
                break
        ia[a:b], ib[a:b] = i, j
        a = b
    rows = np.arange(len(Q))
    A, B = Q[rows, ia], Q[rows, ib]
    ua, ub = A - Qp[rows, ia], B - Qp[rows, ib]
    va, vb = Qn[rows, ia] - A, Qn[rows, ib] - B
    turn = np.arctan2(ua * vb - ub * va, ua * va + ub * vb)
    seen = (np.hypot(ua, ub) > PROJECTED_EPS) & (np.hypot(va, vb) > PROJECTED_EPS)
    hit = np.flatnonzero(seen & (np.abs(np.sin(turn)) < TURN_THRESHOLD))
    if len(hit):
        ring_of = np.repeat(np.arange(len(qs)), lens)
        for h, r in zip((hit - first[hit]).tolist(), ring_of[hit].tolist()):
            out[idx[r]].append(int(h))
    return out


def _drop_coincident_one(points: np.ndarray, floor: int) -> np.ndarray:
    """``GetVertices``' coincident test: a vertex closer than :data:`COINCIDENT` to the
    previous kept one is dropped, then the last ones while closer than that to the first and
    more than ``floor`` remain. (k, 3) -> (k', 3), a new array."""
    # distances as np.linalg.norm computes them (sqrt of the row sums of squares, sqrt of
    # the dot product for one vector), without its per-call overhead
    P = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    d = P[1:] - P[:-1]
    if len(P) > 1 and np.all(np.sqrt(np.add.reduce(d * d, axis=1)) >= COINCIDENT):
        keep = P.copy()      # no vertex dropped: each one's previous kept vertex is its predecessor
    else:                    # sequential: whether a vertex stays depends on the one kept before it
        rows = [P[0]] if len(P) else []
        for p in P[1:]:
            e = p - rows[-1]
            if math.sqrt(float(e.dot(e))) >= COINCIDENT:
                rows.append(p)
        keep = np.asarray(rows, dtype=np.float64).reshape(-1, 3)
    n = len(keep)
    while n > floor:
        e = keep[0] - keep[n - 1]
        if not math.sqrt(float(e.dot(e))) < COINCIDENT:
            break
        n -= 1
    return keep[:n]


def _drop_coincident(surfaces: Sequence[np.ndarray], floor: int) -> list[np.ndarray]:
    """``GetVertices``' coincident test of each surface (:func:`_drop_coincident_one`).

    The common case for all surfaces at once: no two consecutive vertices closer than
    :data:`COINCIDENT` (the same row sums as one surface at a time) and the last vertex
    clearly farther than that from the first (with a margin: the surface alone measures that
    distance with a dot product, whose rounding may differ); such a surface keeps every
    vertex. The others go through :func:`_drop_coincident_one`.
    """
    arrs = [np.asarray(s, dtype=np.float64).reshape(-1, 3) for s in surfaces]
    out: list[np.ndarray | None] = [None] * len(arrs)
    idx = [i for i, a in enumerate(arrs) if len(a) > max(floor, 1)]
    if idx:
        lens = np.array([len(arrs[i]) for i in idx])
        P = np.concatenate([arrs[i] for i in idx])
        starts = np.concatenate(([0], np.cumsum(lens)[:-1]))
        d = P[1:] - P[:-1]
        ok = np.empty(len(P), dtype=bool)
        ok[:-1] = np.sqrt(np.add.reduce(d * d, axis=1)) >= COINCIDENT
        ok[starts[1:] - 1] = True  # the pair across two surfaces
        ok[-1] = True
        e = P[starts] - P[starts + lens - 1]
        closed = np.sqrt(np.add.reduce(e * e, axis=1)) > COINCIDENT * (1 + 1e-9)
        for i, sure in zip(idx, (np.logical_and.reduceat(ok, starts) & closed).tolist()):
            if sure:
                out[i] = arrs[i].copy()
    return [q if q is not None else _drop_coincident_one(a, floor) for q, a in zip(out, arrs)]


def eplus_degenerate(surfaces: Sequence[np.ndarray]) -> list[bool]:
    """Would EnergyPlus call each surface degenerate (fewer than 3 sides once coincident and
    collinear vertices are removed: a severe error)?"""
    keeps = _drop_coincident(surfaces, 1)
    return [len(q) - len(c) < 3 for q, c in zip(keeps, eplus_collinear(keeps))]


def eplus_vertices_and_degenerate(surfaces: Sequence[np.ndarray]) -> tuple[list[np.ndarray], list[bool]]:
    """:func:`eplus_vertices` and :func:`eplus_degenerate` of the same surfaces,
    their shared work done once.

    The coincident test with a floor of 1 (degenerate) and of 3 (vertices) keeps the same
    vertices whenever the first keeps at least 3 (the trailing drop stops where it stops
    for both, or at 3 for the floor of 3), so the collinear test runs once on those.
    """
    keeps = _drop_coincident(surfaces, 1)
    cols = eplus_collinear(keeps)
    degenerate = [len(q) - len(c) < 3 for q, c in zip(keeps, cols)]
    short = [i for i, q in enumerate(keeps) if len(q) < 3]
    if short:
        redo = eplus_vertices([surfaces[i] for i in short])
    faces: list[np.ndarray] = []
    for q, drop in zip(keeps, cols):
        if drop and len(q) - len(drop) >= 3:
            q = np.delete(q, drop, axis=0)
        faces.append(q)
    for i, q in zip(short, redo if short else ()):
        faces[i] = q
    return faces, degenerate


def eplus_vertices(surfaces: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Each surface's vertices as EnergyPlus keeps them, (k, 3) -> (k', 3).

    Vertices closer than :data:`COINCIDENT` to the previous kept one are dropped
    (``GetVertices``), then the vertices :func:`eplus_collinear` finds, while at least three
    remain (``CheckConvexity``).
    """
    qs = _drop_coincident(surfaces, 3)
    out = []
    for q, drop in zip(qs, eplus_collinear(qs)):
        if drop and len(q) - len(drop) >= 3:
            q = np.delete(q, drop, axis=0)
        out.append(q)
    return out


def _near_pairs(points: np.ndarray, tol: float) -> np.ndarray:
    """Pairs of points almost equal per axis (``|p - q| < tol`` on every axis), ``(m, 2) int``
    with ``i < j``, sorted by ``j`` then ``i``.

    A k-d tree under the max-norm proposes the pairs within ``tol`` (``<=``); the test
    EnergyPlus makes (strictly less, per axis) then decides, with the same arithmetic as a
    point-by-point comparison.
    """
    P = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if len(P) < 2:
        return np.empty((0, 2), dtype=np.intp)
    pairs = cKDTree(P).query_pairs(tol, p=np.inf, output_type="ndarray").astype(np.intp).reshape(-1, 2)
    if len(pairs):
        pairs = np.sort(pairs, axis=1)
        pairs = pairs[np.all(np.abs(P[pairs[:, 0]] - P[pairs[:, 1]]) < tol, axis=1)]
        pairs = pairs[np.lexsort((pairs[:, 0], pairs[:, 1]))]
    return pairs


def _first_unique(n: int, pairs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """EnergyPlus's greedy merge over ``n`` points in order: a point is new unless almost
    equal to a unique point met before, and then becomes the first such point.

    Parameters
    ----------
    n : int
    pairs : (m, 2) int
        :func:`_near_pairs` (``i < j``, sorted by ``j`` then ``i``).

    Returns
    -------
    unique : (n,) bool
        The points that start a unique vertex.
    rep : (n,) int
        For each point, the index of the point whose unique vertex it becomes.
    """
    uniq = np.ones(n, dtype=bool)
    rep = np.arange(n, dtype=np.intp)
    if len(pairs):
        # sequential by nature (whether j is new depends on which earlier points are); only
        # the points with an earlier neighbour take part, in the order EnergyPlus meets them
        u = uniq.tolist()
        r = rep.tolist()
        for i, j in pairs.tolist():
            if u[j] and u[i]:
                u[j] = False
                r[j] = i
        uniq = np.asarray(u, dtype=bool)
        rep = np.asarray(r, dtype=np.intp)
    return uniq, rep


def unique_vertices(surfaces: Sequence[np.ndarray], tol: float = POINT_TOL) -> list[np.ndarray]:
    """The zone's unique vertices in EnergyPlus's order (a point is new unless almost equal
    to one met before)."""
    arrs = [np.asarray(s, dtype=np.float64).reshape(-1, 3) for s in surfaces]
    P = np.concatenate(arrs) if arrs else np.empty((0, 3))
    uniq, _ = _first_unique(len(P), _near_pairs(P, tol))
    return list(P[uniq])


def eplus_merge(points: np.ndarray, tol: float = POINT_TOL) -> tuple[np.ndarray, np.ndarray]:
    """Points merged as EnergyPlus merges them: each becomes the first point met before it
    that is almost equal to it (per axis under ``tol``).

    Returns
    -------
    unique : (m, 3) float
    index : (n,) int
        The unique point of each input point.
    """
    P = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    uniq, rep = _first_unique(len(P), _near_pairs(P, tol))
    number = np.cumsum(uniq) - 1
    return P[uniq].reshape(-1, 3), number[rep].astype(np.intp)


def _edges_not_two(surfaces: Sequence[np.ndarray], tol: float) -> list[tuple[np.ndarray, np.ndarray, list[int]]]:
    """EnergyPlus's edge count: an edge is the first stored one whose ends are almost equal to
    its ends (either direction). Returns (start, end, surfaces) of edges not used twice.

    Edge ``e`` of the concatenated surfaces runs from point ``e`` to point ``nxt[e]`` (the
    next vertex of its surface); an edge is stored when no stored edge matches it.
    """
    arrs = [np.asarray(s, dtype=np.float64).reshape(-1, 3) for s in surfaces]
    if not arrs:
        return []
    P = np.concatenate(arrs)
    n = len(P)
    nxt = np.arange(1, n + 1, dtype=np.intp)
    owner = np.empty(n, dtype=np.intp)
    k0 = 0
    for si, s in enumerate(arrs):
        k = len(s)
        if k:
            nxt[k0 + k - 1] = k0
            owner[k0:k0 + k] = si
        k0 += k
    near: list[set[int]] = [{i} for i in range(n)]
    for i, j in _near_pairs(P, tol).tolist():
        near[i].add(j)
        near[j].add(i)
    nx = nxt.tolist()
    own = owner.tolist()
    stored = [False] * n
    used: dict[int, list[int]] = {}
    for e in range(n):
        a_near, b_near = near[e], near[nx[e]]
        hit = None
        for f in a_near:        # stored edges starting near a and ending near b ...
            if f < e and stored[f] and nx[f] in b_near and (hit is None or f < hit):
                hit = f
        for f in b_near:        # ... or starting near b and ending near a
            if f < e and stored[f] and nx[f] in a_near and (hit is None or f < hit):
                hit = f
        if hit is None:
            stored[e] = True
            used[e] = [own[e]]
        else:
            used[hit].append(own[e])
    return [(P[f], P[nx[f]], u) for f, u in sorted(used.items()) if len(u) != 2]


def _on_line(a: np.ndarray, b: np.ndarray, t: np.ndarray, tol: float) -> bool:
    """EnergyPlus's ``isPointOnLineBetweenPoints``: ``t`` within ``tol`` of the line ``ab``
    and the path through it no more than ``tol`` longer than ``ab``."""
    ab = b - a
    L = float(np.linalg.norm(ab))
    if L <= 0.0 or float(np.linalg.norm(np.cross(ab, t - a))) / L >= tol:
        return False
    return abs(L - (float(np.linalg.norm(t - a)) + float(np.linalg.norm(b - t)))) < tol


def _first_on_edge(pts: np.ndarray, uniq: np.ndarray, tol: float) -> tuple[int, int] | None:
    """The first (edge, unique vertex) pair, in EnergyPlus's scan order, where the vertex
    lies on the edge (:func:`_on_line`) without being almost equal to either end."""
    a = pts
    b = np.roll(pts, -1, axis=0)
    lo = np.minimum(a, b) - tol
    hi = np.maximum(a, b) + tol
    inbox = np.all((uniq[None, :, :] >= lo[:, None, :]) & (uniq[None, :, :] <= hi[:, None, :]), axis=2)
    ii, tt = np.nonzero(inbox)      # row-major: by edge, then by unique vertex, as scanned
    if not len(ii):
        return None
    A, B, T = a[ii], b[ii], uniq[tt]
    at_end = np.all(np.abs(T - A) < tol, axis=1) | np.all(np.abs(T - B) < tol, axis=1)
    ab = B - A
    L = np.linalg.norm(ab, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        off = np.linalg.norm(np.cross(ab, T - A), axis=1) / L
        slack = np.abs(L - (np.linalg.norm(T - A, axis=1) + np.linalg.norm(B - T, axis=1)))
    ok = ~at_end & (L > 0.0) & (off < tol) & (slack < tol)
    if not ok.any():
        return None
    m = int(np.argmax(ok))
    return int(ii[m]), int(tt[m])


def _insert_collinear(face: np.ndarray, uniq: np.ndarray, tol: float) -> np.ndarray:
    """``face`` with every unique vertex EnergyPlus finds on one of its edges inserted
    (one at a time, rescanning after each insertion, as EnergyPlus does)."""
    pts = np.asarray(face, dtype=np.float64).reshape(-1, 3)
    uniq = np.asarray(uniq, dtype=np.float64).reshape(-1, 3)
    if not len(pts) or not len(uniq):
        return pts
    for _ in range(len(uniq) + 1):
        # only vertices inside the face's box (grown by tol) can be on one of its edges; the
        # box grows with each insertion
        box = np.all((uniq >= pts.min(axis=0) - tol) & (uniq <= pts.max(axis=0) + tol), axis=1)
        cand = uniq[box]
        hit = _first_on_edge(pts, cand, tol) if len(cand) else None
        if hit is None:
            break
        i, t = hit
        pts = np.insert(pts, i + 1, cand[t], axis=0)
    return pts


#: The :mod:`lod2energy.cache` table of :func:`enclosure_defects`' verdicts, by the exact content
#: of its input (a zone's pieces are tested in :func:`conform.eplus_enclose`, then the same values
#: again in :func:`model.enclosable`), and its size.
DEFECTS = "energy.enclosure_defects"
DEFECTS_KEPT = 64


def enclosure_defects(surfaces: Sequence[np.ndarray], tol: float = POINT_TOL) -> list[BadEdge]:
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
    arrs = [np.asarray(s, dtype=np.float64) for s in surfaces]
    key = (float(tol),) + tuple((a.shape, a.tobytes()) for a in arrs)
    return list(cache.remember(DEFECTS, key, lambda: face_defects(eplus_vertices(arrs), tol), DEFECTS_KEPT))


def face_defects(faces: Sequence[np.ndarray], tol: float = POINT_TOL) -> list[BadEdge]:
    """:func:`enclosure_defects` of surfaces given as EnergyPlus keeps them
    (:func:`eplus_vertices` of the zone's surfaces, float64 ``(k_i, 3)``)."""
    first = _edges_not_two(faces, tol)
    if not first:
        return []
    uniq = np.asarray(unique_vertices(faces, tol))
    second = _edges_not_two([_insert_collinear(f, uniq, tol) for f in faces], tol)
    if not second:
        return []

    def same(x, y):
        return ((np.all(np.abs(x[0] - y[0]) < tol) and np.all(np.abs(x[1] - y[1]) < tol))
                or (np.all(np.abs(x[0] - y[1]) < tol) and np.all(np.abs(x[1] - y[0]) < tol)))
    # EnergyPlus lists the edges that fail both counts (possibly none: the zone still fails)
    both = [e for e in first if any(same(e, f) for f in second)]
    return [BadEdge(e[0].copy(), e[1].copy(), len(e[2]), tuple(e[2])) for e in (both or second)]


def width(points: np.ndarray) -> float:
    """Width (m) of a polygon across its main direction: its extent along the second
    principal axis of its points."""
    q = np.asarray(points, dtype=np.float64)
    q = q - q.mean(axis=0)
    if len(q) < 3:
        return 0.0
    _, _, vt = np.linalg.svd(q, full_matrices=False)
    return float(np.ptp(q @ vt[1]))


#: Polygons narrower than this (m) are dropped by :func:`snap_polygons`: EnergyPlus removes
#: their vertices as collinear and then counts their edges wrongly; the neighbours' edges
#: meet across the gap in EnergyPlus's second count.
MIN_WIDTH = 0.005


def snap_polygons(polygons: Sequence[np.ndarray], tol: float | None = None, merge: bool = True,
                  min_width: float = MIN_WIDTH) -> list[tuple[int, np.ndarray]]:
    """Polygons with their vertices merged as EnergyPlus would merge them, cleaned.

    Parameters
    ----------
    polygons : sequence of (k, 3) float arrays, m
    merge : bool
        False: vertices are not merged (only slivers dropped).
    tol : float, optional, m
        None: each vertex becomes EnergyPlus's unique vertex for it (the first one met that
        is almost equal, per axis under :data:`POINT_TOL`), so what is written is what
        EnergyPlus counts. A number: vertices closer than ``tol`` (transitively) become
        their mean.

    Returns
    -------
    list of (index, (k', 3) array)
        The polygons that keep an area: repeated points and spikes (``a, b, a``) are removed,
        and pairs of polygons that became the same polygon with opposite orientation (a fold)
        are dropped together, so are polygons narrower than ``min_width`` (m).
    """
    allp = np.concatenate([np.asarray(p, dtype=np.float64) for p in polygons])
    if not merge:
        V, idx = weld(allp, 1e-9)  # shared corners only
    elif tol is None:
        V, idx = eplus_merge(allp)
    else:
        V, idx = weld(allp, tol)
    out: list[tuple[int, list[int]]] = []
    k = 0
    for pi, p in enumerate(polygons):
        ring = idx[k:k + len(p)].tolist()
        k += len(p)
        changed = True
        while changed and len(ring) >= 3:
            changed = False
            m = len(ring)
            for i in range(m):
                if ring[i] == ring[(i + 1) % m]:
                    del ring[i]
                    changed = True
                    break
                if m > 3 and ring[i - 1] == ring[(i + 1) % m]:  # spike a, b, a
                    del ring[i]
                    changed = True
                    break
        if len(set(ring)) >= 3 and polygon_area3d(V[ring]) > 1e-8 and width(V[ring]) >= min_width:
            out.append((pi, ring))
    # folds: the same cycle in both directions
    def canon(r):
        j = r.index(min(r))
        return tuple(r[j:] + r[:j])
    keys = {}
    for n, (_, r) in enumerate(out):
        keys.setdefault(canon(r), []).append(n)
    drop = set()
    for n, (_, r) in enumerate(out):
        rev = canon(r[::-1])
        if n in drop or rev not in keys:
            continue
        for m in keys[rev]:
            if m != n and m not in drop:
                drop.update((n, m))
                break
    return [(pi, V[r]) for n, (pi, r) in enumerate(out) if n not in drop]
