"""Stage 2 of the repair ladder ("Output A"): fill the holes bounded by open edges.

Open (boundary) edges are walked into closed loops, oriented so that the filling face agrees
with its neighbours. A planar loop becomes one new polygon; a non-planar one is split into
triangles by a constrained Delaunay triangulation in its projected plane
(:func:`lod2energy.geometry.constrained_delaunay`). Nothing outside the holes moves.
"""
from __future__ import annotations

from collections import defaultdict

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import constrained_delaunay, lawson_cdt, newell_normal, plane_basis, ring_area_2d
from lod2energy.polymesh import Face, PolyMesh, edge_faces, ring_is_simple_2d, split_loop


def boundary_loops(m: PolyMesh) -> list[list[int]]:
    """Closed loops of open edges, each walked in the direction a filling face needs.

    Returns
    -------
    list of list of int
        Vertex loops without repeated vertices (pinched loops are split).
    """
    inc = edge_faces(m.faces)
    out_edges: dict[int, list[int]] = defaultdict(list)
    for (a, b), lst in inc.items():
        if len(lst) != 1:
            continue
        _, d = lst[0]
        # the face walks a->b when d == 1; the filling face must walk b->a
        s, t = (b, a) if d == 1 else (a, b)
        out_edges[s].append(t)
    for v in out_edges:
        out_edges[v].sort()
    loops = []
    for s in sorted(out_edges):
        while out_edges[s]:
            loop = [s]
            cur = out_edges[s].pop(0)
            guard = 0
            while cur != s and guard < 100000:
                guard += 1
                loop.append(cur)
                if not out_edges.get(cur):
                    loop = None
                    break
                cur = out_edges[cur].pop(0)
            if loop is None:
                continue
            loops.extend(sub for sub in split_loop(loop) if len(sub) >= 3)
    return loops


def _loop_plane(P: np.ndarray) -> tuple[np.ndarray, float]:
    n = newell_normal(P, centred=False)
    ln = np.linalg.norm(n)
    if ln < 1e-12:
        c = P.mean(axis=0)
        _, _, vt = np.linalg.svd(P - c, full_matrices=False)
        n = vt[2]
    else:
        n = n / ln
    c = P.mean(axis=0)
    return n, float(np.abs((P - c) @ n).max())


def triangulate_loop(V: np.ndarray, loop: list[int]) -> list[tuple[int, ...]] | None:
    """Constrained Delaunay triangles of a (possibly non-planar) loop, or None.

    The loop is projected on its Newell plane, then on the coordinate planes, until a
    projection keeps it simple; triangles are oriented like the loop.
    """
    P = V[loop]
    n, _ = _loop_plane(P)
    cands = [n] + [np.eye(3)[k] * (1 if n[k] >= 0 else -1) for k in np.argsort(-np.abs(n))]
    for nn in cands:
        B = plane_basis(nn)
        P2 = (P - P.mean(axis=0)) @ B.T
        if not ring_is_simple_2d(P2):
            continue
        # the triangulation is counter-clockwise in 2D; keep the loop's orientation
        area = ring_area_2d(P2)
        if abs(area) < 1e-14:
            continue
        try:
            t = np.asarray(constrained_delaunay(P2, np.array([len(loop)])), dtype=np.int64).reshape(-1, 3)
        except Exception:  # noqa: BLE001 - fall back on ear clipping + flips
            t = None
        if t is None or len(t) != len(loop) - 2:
            t = lawson_cdt(P2, np.array([len(loop)]))
            if len(t) != len(loop) - 2:
                continue
        tl = [list(map(int, x)) for x in t]
        if area < 0:
            tl = [[a, c, b] for a, b, c in tl]
        return [tuple(loop[i] for i in tri) for tri in tl]
    return None


def _planar_polygon(V: np.ndarray, loop: list[int], tol: Tolerances) -> bool:
    P = V[loop]
    n, d2p = _loop_plane(P)
    if d2p > tol.planarity_d2p_tol * 0.5:
        return False
    B = plane_basis(n)
    P2 = (P - P.mean(axis=0)) @ B.T
    area = abs(ring_area_2d(P2))
    return area > tol.sliver_area and ring_is_simple_2d(P2)


def best_chord(V: np.ndarray, loop: list[int], tol: Tolerances) -> tuple[int, int] | None:
    """Chord ``(i, j)`` splitting a non-planar loop into the most planar pair of loops.

    Both halves planar beats one, which beats none; then fewer vertices left in non-planar
    halves; ties go to the smallest summed distance to plane. None when no chord makes a
    half planar. Every chord is scored at once (prefix sums of the points' moments).
    """
    n = len(loop)
    P = V[loop] - V[loop].mean(axis=0)
    ii, jj = np.triu_indices(n, 2)
    keep = ~((ii == 0) & (jj == n - 1))
    ii, jj = ii[keep], jj[keep]
    la = np.asarray(loop)
    keep = la[ii] != la[jj]
    ii, jj = ii[keep], jj[keep]
    if len(ii) == 0:
        return None
    S1 = np.vstack([np.zeros(3), np.cumsum(P, axis=0)])
    O = P[:, :, None] * P[:, None, :]
    S2 = np.concatenate([np.zeros((1, 3, 3)), np.cumsum(O, axis=0)])
    k = np.arange(n)
    ma = (k[None, :] >= ii[:, None]) & (k[None, :] <= jj[:, None])   # chord x point: in half a
    mb = ~ma
    mb[np.arange(len(ii)), ii] = True
    mb[np.arange(len(ii)), jj] = True
    out = []
    for mask, s1, s2, cnt in (
            (ma, S1[jj + 1] - S1[ii], S2[jj + 1] - S2[ii], (jj - ii + 1).astype(float)),
            (mb, S1[n] - (S1[jj + 1] - S1[ii]) + P[ii] + P[jj],
             S2[n] - (S2[jj + 1] - S2[ii]) + O[ii] + O[jj], (n - (jj - ii + 1) + 2).astype(float))):
        mean = s1 / cnt[:, None]
        C = s2 / cnt[:, None, None] - mean[:, :, None] * mean[:, None, :]
        _, vec = np.linalg.eigh(C)
        nrm = vec[:, :, 0]
        d = np.abs(P @ nrm.T - (mean * nrm).sum(axis=1)[None, :]).T  # chord x point
        d = np.where(mask, d, 0.0).max(axis=1)
        d = np.where(cnt <= 3, 0.0, d)
        out.append((d, cnt))
    (da, na), (db, nb) = out
    lim = tol.planarity_d2p_tol * 0.5
    oka, okb = da <= lim, db <= lim
    n_ok = oka.astype(int) + okb.astype(int)
    if not n_ok.any():
        return None
    left = np.where(oka, 0, na) + np.where(okb, 0, nb)
    order = np.lexsort((da + db, left, -n_ok))
    b = order[0]
    return int(ii[b]), int(jj[b])


def fill_loop(V: np.ndarray, loop: list[int], tol: Tolerances, depth: int = 0) -> tuple[list[Face], np.ndarray]:
    """Faces closing one loop (and extra vertices when a centroid fan was needed).

    A planar, simple loop becomes one polygon; a non-planar loop is split along the chord
    giving the most planar halves (recursively), and what stays non-planar is triangulated.
    """
    if len(loop) == 3:
        return [Face((tuple(loop),))], np.zeros((0, 3))
    if _planar_polygon(V, loop, tol):
        return [Face((tuple(loop),))], np.zeros((0, 3))
    if depth < 12 and len(loop) <= 64:
        ch = best_chord(V, loop, tol)
        if ch is not None:
            i, j = ch
            a = loop[i:j + 1]
            b = loop[j:] + loop[:i + 1]
            fa, ea = fill_loop(V, a, tol, depth + 1)
            if len(ea) == 0:
                fb, eb = fill_loop(V, b, tol, depth + 1)
                if len(eb) == 0:
                    return fa + fb, np.zeros((0, 3))
    tris = triangulate_loop(V, loop)
    if tris is not None:
        return [Face((t,)) for t in tris], np.zeros((0, 3))
    # last resort: a fan around the loop's centroid (one new vertex)
    c = len(V)
    faces = [Face(((loop[i], loop[(i + 1) % len(loop)], c),)) for i in range(len(loop))]
    return faces, V[loop].mean(axis=0)[None, :]


def zip_slits(m: PolyMesh, tol: Tolerances, width: float = 0.01) -> tuple[PolyMesh, list[list[int]]]:
    """Close thin loops (slits) by inserting their vertices into the face across them.

    A loop whose vertices all lie within ``width`` (m) of its longest edge is a slit left by
    a T-junction: the face owning that edge gets the loop's other vertices inserted, which
    pairs every open edge of the slit. Returns the mesh and the loops that were not slits.
    """
    loops = boundary_loops(m)
    if not loops:
        return m, []
    V = m.vertices
    faces = list(m.faces)
    inc = edge_faces(faces)
    rest = []
    for loop in loops:
        P = V[loop]
        k = len(loop)
        L = np.linalg.norm(P - np.roll(P, -1, axis=0), axis=1)
        e = int(np.argmax(L))  # fill edge loop[e] -> loop[e+1]; a face walks it backwards
        loop_r = loop[e + 1:] + loop[:e + 1]  # starts at loop[e+1], ends at loop[e]
        a, c = loop_r[0], loop_r[-1]  # the face across the slit walks a -> c
        pa, pc = V[a], V[c]
        d = pc - pa
        ln = float(np.linalg.norm(d))
        if ln == 0:
            rest.append(loop)
            continue
        mid = V[loop_r[1:-1]]
        t = (mid - pa) @ d / ln ** 2
        dist = np.linalg.norm(pa + t[:, None] * d - mid, axis=1)
        lst = inc.get((min(a, c), max(a, c)), [])
        if k < 3 or len(lst) != 1 or (dist > width).any() or (t <= 0).any() or (t >= 1).any() \
                or (np.diff(t) <= 0).any():
            rest.append(loop)
            continue
        fi = lst[0][0]
        f = faces[fi]
        new_rings, done = [], False
        for r in f.rings:
            r = list(r)
            for i in range(len(r)):
                if not done and r[i] == a and r[(i + 1) % len(r)] == c:
                    r = r[:i + 1] + loop_r[1:-1] + r[i + 1:]
                    done = True
                    break
            new_rings.append(tuple(r))
        if not done:
            rest.append(loop)
            continue
        faces[fi] = Face(tuple(new_rings), f.source, f.semantic)
        inc = edge_faces(faces)
    return m.with_faces(faces), rest


def fill_holes(m: PolyMesh, tol: Tolerances = DEFAULT) -> PolyMesh:
    """Stage 2: zip slits, then close every other boundary loop with new faces."""
    m, loops = zip_slits(m, tol)
    if not loops:
        return m
    V = m.vertices
    faces = list(m.faces)
    for loop in loops:
        new, extra = fill_loop(V, loop, tol)
        if len(extra):
            V = np.vstack([V, extra])
        faces.extend(new)
    return PolyMesh(V, tuple(faces))
