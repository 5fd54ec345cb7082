"""Stage 0 of the repair ladder: clean-up that moves nothing by more than the snap tolerance.

Snap and merge vertices within ``snap_tol``; drop repeated points, spikes, rings with fewer
than three points, duplicate and zero-area faces; split edges at T-junction vertices (a vertex
of one polygon lying on another polygon's edge); split rings pinched at a repeated vertex;
triangulate non-planar polygons (203/204); merge sliver faces into a coplanar neighbour.
"""
from __future__ import annotations

from collections import defaultdict

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import plane_basis, snap_map
from lod2energy.polymesh import (
    Face, PolyMesh, edge_faces, face_area, face_normal, planarity, ring_is_simple_2d, split_loop, triangulate_face,
)
from lod2energy.repair.holefill import triangulate_loop
from lod2energy.validate.closed import invalid_polygons

# scipy (0.4 s to import) is imported where it is used: validation never needs it


def snap_vertices(m: PolyMesh, snap_tol: float) -> PolyMesh:
    """Merge vertices closer than ``snap_tol`` (m); the lowest index of a cluster survives."""
    V = m.vertices
    if len(V) < 2:
        return m
    lut = snap_map(V, snap_tol * (1 + 1e-9) + 1e-12)
    if (lut == np.arange(len(V))).all():
        return m
    faces = [Face(tuple(tuple(int(lut[i]) for i in r) for r in f.rings), f.source, f.semantic)
             for f in m.faces]
    return m.with_faces(faces)


def clean_ring(r: tuple[int, ...]) -> tuple[int, ...]:
    """Drop repeated consecutive points and spikes (``a b a``) of an open ring."""
    r = list(r)
    changed = True
    while changed and len(r) >= 3:
        changed = False
        out = [v for i, v in enumerate(r) if v != r[i - 1]] if len(r) > 1 else r
        if len(out) != len(r):
            changed = True
        r = out
        if len(r) < 3:
            break
        n = len(r)
        for i in range(n):
            if r[i - 1] == r[(i + 1) % n]:
                # spike at i: remove it and its echo
                j = (i + 1) % n
                r = [v for k, v in enumerate(r) if k not in (i, j)]
                changed = True
                break
    return tuple(r)


def clean_rings(m: PolyMesh) -> PolyMesh:
    """Clean every ring; drop holes with < 3 points and faces whose outer ring has < 3."""
    faces = []
    for f in m.faces:
        rings = [clean_ring(r) for r in f.rings]
        if len(set(rings[0])) < 3:
            continue
        rings = [rings[0]] + [r for r in rings[1:] if len(set(r)) >= 3]
        faces.append(Face(tuple(rings), f.source, f.semantic))
    return m.with_faces(faces)


def split_pinched(m: PolyMesh) -> PolyMesh:
    """Split an outer ring passing twice through one vertex into simple rings (no holes)."""
    faces = []
    for f in m.faces:
        r = f.outer
        if len(f.rings) > 1 or len(set(r)) == len(r):
            faces.append(f)
            continue
        for sub in split_loop(list(r)):
            if len(set(sub)) >= 3:
                faces.append(Face((tuple(sub),), f.source, f.semantic))
    return m.with_faces(faces)


def split_t_junctions(m: PolyMesh, tol: float, min_gap: float = 0.001) -> PolyMesh:
    """Insert into each ring edge the shell's vertices lying on it.

    Parameters
    ----------
    tol : float, m
        Largest distance of a vertex to the edge.
    min_gap : float, m
        The vertex must be farther than this from both ends of the edge (the snap tolerance).

    Notes
    -----
    One batched ball query over every edge (balls :data:`_PREFILTER` wider than the edge's own)
    finds the few edges with a vertex near them besides their ends; only those are tested
    exactly (:func:`_on_edge`). An edge whose ball holds its two ends alone gets no vertex.
    """
    V = m.vertices
    used = np.array(sorted({i for f in m.faces for r in f.rings for i in r}), dtype=np.int64)
    if len(used) < 3:
        return m
    from scipy.spatial import cKDTree
    tree = cKDTree(V[used])
    A = [a for f in m.faces for r in f.rings for a in r]
    B = [b for f in m.faces for r in f.rings for b in r[1:] + r[:1]]
    if not A:
        return m
    A, B = np.asarray(A, dtype=np.int64), np.asarray(B, dtype=np.int64)
    E = V[B] - V[A]
    L = np.sqrt(np.einsum("ij,ij->i", E, E))
    inserted = {}
    for k in _near_edges(V, used, tree, A, B, E, L, tol, min_gap).tolist():
        ids = _on_edge(V, used, tree, int(A[k]), int(B[k]), tol, min_gap)
        if ids:
            inserted[k] = ids
    if not inserted:
        return m
    faces, k = [], 0
    for f in m.faces:
        rings = []
        for r in f.rings:
            new = []
            for a in r:
                new.append(a)
                if k in inserted:
                    new.extend(inserted[k])
                k += 1
            rings.append(clean_ring(tuple(new)))
        faces.append(Face(tuple(rings), f.source, f.semantic))
    return m.with_faces(faces)


#: Slack of :func:`_near_edges`, m: covers the rounding by which the batched lengths and
#: distances may differ from the ones :func:`_on_edge` computes edge by edge.
_PREFILTER = 1e-9


def _near_edges(V, used, tree, A, B, E, L, tol: float, min_gap: float) -> np.ndarray:
    """Indices of the edges ``A[k] B[k]`` (vectors ``E``, lengths ``L``) that may have a vertex
    of ``used`` on them: :func:`_on_edge`'s test for all edges at once, :data:`_PREFILTER`
    looser (a superset of the edges it finds a vertex on)."""
    long = np.flatnonzero(L > 2 * min_gap - _PREFILTER)
    if not len(long):
        return long
    C = (V[A[long]] + V[B[long]]) / 2
    hits = tree.query_ball_point(C, L[long] / 2 + tol + _PREFILTER, return_sorted=False)
    n = np.fromiter((len(h) for h in hits), dtype=np.int64, count=len(hits))
    busy = np.flatnonzero(n > 2)  # more than the edge's two ends
    if not len(busy):
        return busy
    k = np.repeat(long[busy], n[busy])
    ids = used[np.concatenate([np.asarray(hits[i], dtype=np.int64) for i in busy])]
    pa, e, Lk = V[A[k]], E[k], L[k]
    t = np.einsum("ij,ij->i", V[ids] - pa, e) / (Lk * Lk)
    d = np.linalg.norm(pa + t[:, None] * e - V[ids], axis=1)
    ok = (d <= tol + _PREFILTER) & (t * Lk > min_gap - _PREFILTER) & ((1 - t) * Lk > min_gap - _PREFILTER) \
        & (ids != A[k]) & (ids != B[k])
    return np.unique(k[ok])


def _on_edge(V: np.ndarray, used: np.ndarray, tree, a: int, b: int, tol: float, min_gap: float) -> list[int]:
    """The vertices of ``used`` on edge ``a b`` (within ``tol``, farther than ``min_gap`` from
    both ends), in order from ``a``."""
    pa, pb = V[a], V[b]
    e = pb - pa
    L = float(np.linalg.norm(e))
    if L <= 2 * min_gap:
        return []
    cand = tree.query_ball_point((pa + pb) / 2, L / 2 + tol)
    if len(cand) <= 2:
        return []
    ids = used[cand]
    Q = V[ids]
    t = (Q - pa) @ e / (L * L)
    d = np.linalg.norm(pa + t[:, None] * e - Q, axis=1)
    ok = (d <= tol) & (t * L > min_gap) & ((1 - t) * L > min_gap) & (ids != a) & (ids != b)
    if not ok.any():
        return []
    sel = np.flatnonzero(ok)
    sel = sel[np.argsort(t[sel], kind="stable")]
    return [int(ids[k]) for k in sel]


def _same_cycle(r1, r2) -> bool:
    if len(r1) != len(r2) or r2[0] not in r1:
        return False
    k = r1.index(r2[0])
    return tuple(r1[k:] + r1[:k]) == tuple(r2)


def drop_duplicate_faces(m: PolyMesh) -> PolyMesh:
    """Keep one of faces with the same vertex set and orientation; drop both faces of a pair
    walked in opposite directions (an internal wall between two solids, e.g. in a
    CompositeSolid, which must not stay inside the merged envelope)."""
    groups: dict[tuple, list[int]] = defaultdict(list)
    for i, f in enumerate(m.faces):
        groups[tuple(sorted(i for r in f.rings for i in r))].append(i)
    drop = set()
    for idx in groups.values():
        if len(idx) < 2:
            continue
        kept: list[int] = []
        for i in idx:
            r = list(m.faces[i].outer)
            twin = next((k for k in kept if _same_cycle(list(m.faces[k].outer), r)), None)
            if twin is not None:
                drop.add(i)
                continue
            anti = next((k for k in kept if _same_cycle(list(m.faces[k].outer), r[::-1])), None)
            if anti is not None:
                drop.update((i, anti))
                kept.remove(anti)
                continue
            kept.append(i)
    if not drop:
        return m
    return m.with_faces([f for i, f in enumerate(m.faces) if i not in drop])


def drop_degenerate(m: PolyMesh, area_eps: float = 1e-10) -> PolyMesh:
    """Drop faces of (near) zero area."""
    faces = [f for f in m.faces if face_area(m.vertices, f) > area_eps]
    return m.with_faces(faces) if len(faces) != len(m.faces) else m


def fix_nonplanar(m: PolyMesh, tol: Tolerances, rounds: int = 3) -> PolyMesh:
    """Triangulate polygons that are non-planar (203/204) or whose rings cross (104, 2xx).

    The project's polygon validator decides (204 is only checked once every polygon is
    otherwise valid, hence the rounds).
    """
    for _ in range(rounds):
        bad = {f: c for f, c in invalid_polygons(m, tol).items() if c & {104, 201, 203, 204, 205, 206, 207, 208}}
        if not bad:
            return m
        V = m.vertices
        faces = []
        for fi, f in enumerate(m.faces):
            if fi not in bad or (len(f.outer) == 3 and len(f.rings) == 1):
                faces.append(f)
                continue
            tris = triangulate_loop(V, list(f.outer)) if len(f.rings) == 1 else None
            if tris is None:
                tris = [tuple(int(i) for i in t) for t in triangulate_face(V, f)]
            faces.extend(Face((t,), f.source, f.semantic) for t in tris)
        m = m.with_faces(faces)
    return m


def merge_ring_pair(r1: tuple[int, ...], r2: tuple[int, ...]) -> tuple[int, ...] | None:
    """Union of two rings sharing an edge in opposite directions (None if they share none)."""
    e1 = {(r1[i], r1[(i + 1) % len(r1)]): i for i in range(len(r1))}
    for j in range(len(r2)):
        a, b = r2[(j + 1) % len(r2)], r2[j]  # r2 walks b->a, r1 walks a->b
        if (a, b) in e1:
            i = e1[(a, b)]
            # r2 rotated to start at a (= r2[j+1]) and end at b (= r2[j])
            k = (j + 1) % len(r2)
            path = [r2[(k + s) % len(r2)] for s in range(len(r2))]  # a ... b
            rot1 = [r1[(i + 1 + s) % len(r1)] for s in range(len(r1))]  # b ... a
            merged = rot1[:-1] + path[:-1]
            # rot1 = b..a ; path = a..b -> b..(before a), a..(before b)
            return clean_ring(tuple(merged))
    return None


def merge_slivers(m: PolyMesh, tol: Tolerances, only_new: bool = False) -> PolyMesh:
    """Merge each face with area <= ``tol.sliver_area`` into an edge-adjacent face.

    The merged polygon must stay simple and planar within ``tol``; the neighbour keeps its
    source and semantic. A sliver no neighbour can absorb is kept.
    """
    V = m.vertices
    faces = list(m.faces)
    areas = [face_area(V, f) for f in faces]
    slivers = [i for i, a in enumerate(areas) if a <= tol.sliver_area and (not only_new or faces[i].source < 0)]
    if not slivers:
        return m
    alive = [True] * len(faces)
    for s in slivers:
        if not alive[s] or len(faces[s].rings) > 1:
            continue
        inc = edge_faces([f if alive[k] else Face(((),)) for k, f in enumerate(faces)])
        nbrs = []
        for a, b in faces[s].edges():
            for g, _ in inc.get((min(a, b), max(a, b)), ()):
                if g != s and alive[g] and g not in nbrs:
                    nbrs.append(g)
        # biggest neighbour first: it absorbs the sliver with the smallest relative change
        nbrs.sort(key=lambda g: -areas[g])
        for g in nbrs:
            fg = faces[g]
            merged = merge_ring_pair(fg.outer, faces[s].outer)
            if merged is None or len(set(merged)) < 3 or len(set(merged)) != len(merged):
                continue
            nf = Face((merged,) + fg.rings[1:], fg.source, fg.semantic)
            d2p, dev = planarity(V, nf)
            if d2p > tol.planarity_d2p_tol * 0.5:
                continue
            B = plane_basis(face_normal(V, nf))
            if not all(ring_is_simple_2d(V[list(r)] @ B.T) for r in nf.rings):
                continue
            if face_area(V, nf) <= tol.sliver_area:
                continue
            if invalid_polygons(m.with_faces([nf]), tol):
                continue  # folded (204) or otherwise rejected: fix_nonplanar would split it again
            faces[g] = nf
            areas[g] = face_area(V, nf)
            alive[s] = False
            break
    return m.with_faces([f for k, f in enumerate(faces) if alive[k]])


def collapse_slivers(m: PolyMesh, tol: Tolerances, edge: float = 0.02, height: float = 0.01,
                     rank: int = 0, keep_high: bool = False) -> PolyMesh:
    """Remove the slivers :func:`merge_slivers` could not absorb.

    A sliver with an edge shorter than ``edge`` (m) has that edge collapsed (its second
    vertex snapped onto the first everywhere); a needle whose height over its longest edge
    is under ``height`` (m) is dropped, leaving a slit that hole filling zips into the face
    across it. Other slivers are kept. ``rank`` picks the edge (0: the shortest, 1: the next
    one...) and ``keep_high`` which end survives, for :func:`desliver`'s alternatives.
    """
    V = m.vertices
    faces = list(m.faces)
    lut: dict[int, int] = {}
    drop = set()
    for i, f in enumerate(faces):
        if len(f.rings) > 1 or face_area(V, f) > tol.sliver_area:
            continue
        r = [lut.get(v, v) for v in f.outer]
        P = V[r]
        L = np.linalg.norm(P - np.roll(P, -1, axis=0), axis=1)
        k = int(np.argsort(L, kind="stable")[min(rank, len(L) - 1)])
        a, b = r[k], r[(k + 1) % len(r)]
        if L[k] <= edge and a != b and a not in lut and b not in lut:
            if keep_high:
                lut[min(a, b)] = max(a, b)
            else:
                lut[max(a, b)] = min(a, b)
            continue
        long_ = float(L.max())
        if long_ > 0 and 2 * face_area(V, f) / long_ <= height:
            drop.add(i)
    if not lut and not drop:
        return m
    out = []
    for i, f in enumerate(faces):
        if i in drop:
            continue
        out.append(Face(tuple(tuple(lut.get(v, v) for v in r) for r in f.rings), f.source, f.semantic))
    return clean_rings(m.with_faces(out))


def desliver(m: PolyMesh, tol: Tolerances, accept) -> PolyMesh | None:
    """A version of ``m`` without slivers that ``accept`` takes, or None.

    Tries each way of collapsing the slivers (which short edge, which end survives; every
    vertex moves at most 2 cm) followed by the usual tidy-up; the first result ``accept``
    passes wins. Used when the ladder would otherwise keep a valid shell with a sliver.
    """
    if all(face_area(m.vertices, f) > tol.sliver_area for f in m.faces):
        return None
    for rank in (0, 1, 2):
        for keep_high in (False, True):
            x = m
            for _ in range(2):
                x = collapse_slivers(merge_slivers(x, tol), tol, rank=rank, keep_high=keep_high)
                x = fix_nonplanar(drop_degenerate(drop_duplicate_faces(x)), tol)
                if all(face_area(x.vertices, f) > tol.sliver_area for f in x.faces):
                    break
            if accept(x):
                return x
    return None


def cleanup(m: PolyMesh, tol: Tolerances = DEFAULT, tjunction_tol: float | None = None) -> PolyMesh:
    """Stage 0: every clean-up step in order (see the module docstring).

    Parameters
    ----------
    tjunction_tol : float, m
        Distance under which a vertex is inserted into a polygon edge; default
        ``max(tol.snap_tol, tol.tjunction_tol)`` (half the planarity tolerance: the polygon stays
        planar within it).
    """
    tj = max(tol.snap_tol, tol.tjunction_tol) if tjunction_tol is None else tjunction_tol
    m = snap_vertices(m, tol.snap_tol)
    m = clean_rings(m)
    m = split_pinched(m)
    m = split_t_junctions(m, tj, tol.snap_tol)
    m = drop_duplicate_faces(m)
    m = drop_degenerate(m)
    m = fix_nonplanar(m, tol)
    m = drop_degenerate(m)
    for _ in range(3):  # triangulating a polygon bent by a collapse can leave a new sliver
        m = merge_slivers(m, tol)
        m = collapse_slivers(m, tol)
        m = drop_degenerate(drop_duplicate_faces(m))
        m = fix_nonplanar(m, tol)
        if all(face_area(m.vertices, f) > tol.sliver_area for f in m.faces):
            break
    return m
