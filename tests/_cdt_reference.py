"""The constrained Delaunay triangulation as it was before its speed-up (reference for
``tests/test_cdt_equivalence.py``): ``np.unique`` / ``np.isin`` in the conforming-Delaunay
test and the flip loop calling ``_incircle`` / ``_orient``. Do not import from the package
code; only the tests use it."""
from __future__ import annotations

import numpy as np
import shapely
from scipy.spatial import Delaunay

from lod2energy.geometry.cdt import ear_triangles

def _incircle(pa, pb, pc, pd) -> float:
    """> 0 when ``pd`` is inside the circle through the CCW triangle ``pa, pb, pc``."""
    adx, ady = pa[0] - pd[0], pa[1] - pd[1]
    bdx, bdy = pb[0] - pd[0], pb[1] - pd[1]
    cdx, cdy = pc[0] - pd[0], pc[1] - pd[1]
    ad = adx * adx + ady * ady
    bd = bdx * bdx + bdy * bdy
    cd = cdx * cdx + cdy * cdy
    det = adx * (bdy * cd - bd * cdy) - ady * (bdx * cd - bd * cdx) + ad * (bdx * cdy - bdy * cdx)
    # Shewchuk's permanent: below ~1e-14 of it the sign is rounding noise (cocircular)
    perm = ((abs(bdx * cdy) + abs(bdy * cdx)) * ad + (abs(cdx * ady) + abs(cdy * adx)) * bd
            + (abs(adx * bdy) + abs(ady * bdx)) * cd)
    return det if abs(det) > 1e-14 * perm else 0.0


def _orient(pa, pb, pc) -> float:
    return (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0])


def constrained_delaunay(points2d: np.ndarray, ring_ends: np.ndarray, max_flips: int | None = None) -> np.ndarray:
    """CDT of a polygon with holes whose constraints are its ring edges.

    When the plain Delaunay triangulation (Qhull) already holds every ring edge, the CDT is
    its triangles inside the polygon; otherwise ear clipping + constrained Lawson flips.

    Parameters
    ----------
    points2d : (n, 2) float
        Ring vertices (outer ring first, then holes), open rings, concatenated.
    ring_ends : (r,) int
        Cumulative ring sizes.
    max_flips : int, optional
        Safety bound on edge flips (default ``10 n^2``).

    Returns
    -------
    (t, 3) int
        Counter-clockwise triangles, indices into ``points2d``.
    """
    pts = np.asarray(points2d, dtype=np.float64)
    fast = _delaunay_if_conforming(pts, ring_ends)
    if fast is not None:
        return fast
    return lawson_cdt(pts, ring_ends, max_flips)


def _ring_edges(ring_ends) -> set[tuple[int, int]]:
    edges = set()
    start = 0
    for end in np.asarray(ring_ends).tolist():
        for i in range(start, end):
            j = i + 1 if i + 1 < end else start
            edges.add((min(i, j), max(i, j)))
        start = end
    return edges


def _delaunay_if_conforming(pts: np.ndarray, ring_ends) -> np.ndarray | None:
    """Inside triangles of the Delaunay triangulation when it contains all ring edges, else None."""
    if len(np.unique(pts, axis=0)) != len(pts):
        return None  # a ring touching another at a vertex: leave it to the general path
    try:
        dt = Delaunay(pts)
    except Exception:  # Qhull refuses degenerate input
        return None
    n = len(pts)
    simp = np.sort(dt.simplices, axis=1)
    have = np.concatenate([simp[:, 0] * n + simp[:, 1], simp[:, 1] * n + simp[:, 2], simp[:, 0] * n + simp[:, 2]])
    ends = np.asarray(ring_ends, dtype=np.intp)
    sizes = np.diff(np.concatenate([[0], ends]))
    i = np.arange(n)
    j = i + 1
    j[ends - 1] = ends - sizes
    need = np.minimum(i, j) * n + np.maximum(i, j)
    if not np.isin(need, have).all():
        return None
    tri = dt.simplices
    c = pts[tri].mean(axis=1)
    start = 0
    rings = []
    for end in np.asarray(ring_ends).tolist():
        rings.append(pts[start:end])
        start = end
    poly = shapely.Polygon(rings[0], rings[1:])
    inside = shapely.contains_xy(poly, c[:, 0], c[:, 1])
    tri = tri[inside].astype(np.intp)
    a, b, cc = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    cw = (b[:, 0] - a[:, 0]) * (cc[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (cc[:, 0] - a[:, 0]) < 0
    tri[cw] = tri[cw][:, [0, 2, 1]]
    return tri


def lawson_cdt(pts: np.ndarray, ring_ends, max_flips: int | None = None) -> np.ndarray:
    """CDT by ear clipping then constrained Lawson flips (general, slower path)."""
    tri = ear_triangles(pts, ring_ends)
    n = len(pts)
    if len(tri) < 2:
        return tri
    constrained = _ring_edges(ring_ends)
    tris = [list(t) for t in tri.tolist()]
    edge_tris: dict[tuple[int, int], list[int]] = {}
    for ti, (a, b, c) in enumerate(tris):
        for u, v in ((a, b), (b, c), (c, a)):
            edge_tris.setdefault((min(u, v), max(u, v)), []).append(ti)
    stack = [e for e, ts in edge_tris.items() if len(ts) == 2 and e not in constrained]
    P = pts.tolist()
    budget = max_flips if max_flips is not None else 10 * n * n + 10
    while stack and budget > 0:
        e = stack.pop()
        ts = edge_tris.get(e)
        if ts is None or len(ts) != 2:
            continue
        t1, t2 = ts
        a, b = e
        # orient t1 so that it holds a -> b
        A, B, C = tris[t1]
        rot = {(A, B): (A, B, C), (B, C): (B, C, A), (C, A): (C, A, B)}
        if (a, b) in rot:
            a, b, c = rot[(a, b)]
        else:
            a, b, c = rot[(b, a)]
        D = [v for v in tris[t2] if v != a and v != b]
        if len(D) != 1:
            continue
        d = D[0]
        if _incircle(P[a], P[b], P[c], P[d]) <= 0.0:
            continue
        if _orient(P[a], P[d], P[c]) <= 0 or _orient(P[d], P[b], P[c]) <= 0:
            continue
        budget -= 1
        tris[t1] = [a, d, c]
        tris[t2] = [d, b, c]
        del edge_tris[(min(a, b), max(a, b))]
        edge_tris[(min(c, d), max(c, d))] = [t1, t2]
        # edge (b, d) moved from t2 to t2 (unchanged); (a, c) stays in t1; (b, c) moved t1 -> t2;
        # (a, d) moved t2 -> t1
        for (u, v), old, new in (((b, c), t1, t2), ((a, d), t2, t1)):
            lst = edge_tris[(min(u, v), max(u, v))]
            lst[lst.index(old)] = new
        for u, v in ((a, c), (c, b), (b, d), (d, a)):
            k = (min(u, v), max(u, v))
            if k not in constrained and len(edge_tris.get(k, ())) == 2:
                stack.append(k)
    return np.asarray(tris, dtype=np.intp).reshape(-1, 3)


_EDGE_TABLE_MAX = 2048


def _delaunay_if_conforming_table(pts: np.ndarray, ring_ends) -> np.ndarray | None:
    """(cd06ee6) Inside triangles of the Delaunay triangulation when it contains all ring edges, else None.

    Duplicate points are found by a lexicographic sort, the ring edges looked up in an
    (n, n) incidence table (small n), the same answers as ``np.unique`` / ``np.isin``.
    """
    n = len(pts)
    if n > 1:
        o = np.lexsort((pts[:, 1], pts[:, 0]))
        s = pts[o]
        if ((s[1:, 0] == s[:-1, 0]) & (s[1:, 1] == s[:-1, 1])).any():
            return None  # a ring touching another at a vertex: leave it to the general path
    import shapely
    from scipy.spatial import Delaunay
    try:
        dt = Delaunay(pts)
    except Exception:  # Qhull refuses degenerate input
        return None
    tri = dt.simplices
    ends = np.asarray(ring_ends, dtype=np.intp)
    sizes = np.diff(ends, prepend=0)
    i = np.arange(n)
    j = i + 1
    j[ends - 1] = ends - sizes
    if n <= _EDGE_TABLE_MAX:
        tab = np.zeros((n, n), dtype=bool)
        a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
        for u, v in ((a, b), (b, c), (a, c)):
            tab[u, v] = True
            tab[v, u] = True
        if not tab[i, j].all():
            return None
    else:
        simp = np.sort(tri, axis=1)
        have = np.concatenate([simp[:, 0] * n + simp[:, 1], simp[:, 1] * n + simp[:, 2], simp[:, 0] * n + simp[:, 2]])
        if not np.isin(np.minimum(i, j) * n + np.maximum(i, j), have).all():
            return None
    c = pts[tri].mean(axis=1)
    bounds = [0] + ends.tolist()
    poly = shapely.Polygon(pts[:bounds[1]], [pts[bounds[k]:bounds[k + 1]] for k in range(1, len(bounds) - 1)])
    inside = shapely.contains_xy(poly, c[:, 0], c[:, 1])
    tri = tri[inside].astype(np.intp)
    a, b, cc = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    cw = (b[:, 0] - a[:, 0]) * (cc[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (cc[:, 0] - a[:, 0]) < 0
    tri[cw] = tri[cw][:, [0, 2, 1]]
    return tri
