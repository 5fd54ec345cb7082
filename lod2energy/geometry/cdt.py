"""Ear clipping and the constrained Delaunay triangulation (CDT) of planar polygons with holes.

:func:`constrained_delaunay` is the CDT val3dity's check 204 works on (CGAL): the plain
Delaunay triangulation when it already holds every ring edge, else ear clipping followed by
constrained Lawson flips (:func:`lawson_cdt`, the one implementation of edge flips).
:func:`constrained_delaunay_many` gives the same triangulations for many polygons at once from
GEOS's compiled CDT (``shapely.constrained_delaunay_triangles``), falling back to
:func:`constrained_delaunay` polygon by polygon where GEOS does not apply.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np
import shapely

from lod2energy.geometry.vectors import cross2

try:  # mapbox_earcut is a declared dependency; keep import errors readable
    import mapbox_earcut as _earcut
except ImportError:  # pragma: no cover
    _earcut = None

# scipy (0.4 s to import) is imported where Qhull is needed: most validations never need it
__all__ = ["earcut_rings", "ear_triangles", "constrained_delaunay", "constrained_delaunay_many", "lawson_cdt"]


def _counter_clockwise(tri: np.ndarray, corners: np.ndarray) -> np.ndarray:
    """``tri`` (t, 3) with each clockwise triangle turned (in place), its corners (t, 3, 2) given."""
    cw = cross2(corners[:, 0], corners[:, 1], corners[:, 2]) < 0
    tri[cw] = tri[cw][:, [0, 2, 1]]
    return tri


def earcut_rings(p2: np.ndarray, ring_ends: np.ndarray) -> np.ndarray:
    """mapbox-earcut triangles (t, 3) of 2D rings ``p2`` (n, 2) ending at ``ring_ends`` (r,), as it orients them."""
    if _earcut is None:  # pragma: no cover
        raise ImportError("mapbox_earcut is required for triangulation (pip install mapbox-earcut)")
    t = _earcut.triangulate_float64(np.ascontiguousarray(p2, dtype=np.float64),
                                    np.asarray(ring_ends, dtype=np.uint32))
    return np.asarray(t, dtype=np.intp).reshape(-1, 3)


def _incircle_d(adx: float, ady: float, bdx: float, bdy: float, cdx: float, cdy: float) -> float:
    """The incircle determinant from the corners' offsets to ``pd`` (``a - d``, ``b - d``,
    ``c - d``): > 0 when ``d`` is inside the circle through the counter-clockwise triangle
    ``a, b, c``; 0 where its sign is rounding noise."""
    ad = adx * adx + ady * ady
    bd = bdx * bdx + bdy * bdy
    cd = cdx * cdx + cdy * cdy
    det = adx * (bdy * cd - bd * cdy) - ady * (bdx * cd - bd * cdx) + ad * (bdx * cdy - bdy * cdx)
    # Shewchuk's permanent: below ~1e-14 of it the sign is rounding noise (cocircular)
    perm = ((abs(bdx * cdy) + abs(bdy * cdx)) * ad + (abs(cdx * ady) + abs(cdy * adx)) * bd
            + (abs(adx * bdy) + abs(ady * bdx)) * cd)
    return det if abs(det) > 1e-14 * perm else 0.0


def ear_triangles(points2d: np.ndarray, ring_ends: np.ndarray) -> np.ndarray:
    """Ear-clipping triangulation.

    Parameters
    ----------
    points2d : (n, 2) float
        Ring vertices (outer ring first, then holes), open rings, concatenated.
    ring_ends : (r,) int
        Cumulative ring sizes (``ring_ends[-1] == n``).

    Returns
    -------
    (t, 3) int
        Triangles as indices into ``points2d``, each counter-clockwise.
    """
    pts = np.ascontiguousarray(points2d, dtype=np.float64)
    tri = earcut_rings(pts, ring_ends)
    if len(tri) == 0:
        return tri
    return _counter_clockwise(tri, pts[tri])


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
    """Inside triangles of the Delaunay triangulation when it contains all ring edges, else None.

    Duplicate points (``==``) and ring edges are looked up in Python sets (issue 13: microseconds
    for most polygons' 4-30 points); odd ring ends take the vectorised :func:`_has_ring_edges_np`."""
    n = len(pts)
    if len(set(map(tuple, pts.tolist()))) < n:
        return None  # a ring touching another at a vertex: leave it to the general path
    from scipy.spatial import Delaunay
    try:
        tri = Delaunay(pts).simplices
    except Exception:  # Qhull refuses degenerate input
        return None
    ends = np.asarray(ring_ends, dtype=np.intp)
    el = ends.tolist()
    well_formed = not (len(ends) == 0 or el[-1] != n or el[0] < 1 or any(a >= b for a, b in zip(el, el[1:])))
    if not well_formed:
        if not _has_ring_edges_np(tri, ends, n):
            return None
    else:
        have = set()
        for a, b, c in tri.tolist():
            have.add(a * n + b if a < b else b * n + a)
            have.add(b * n + c if b < c else c * n + b)
            have.add(a * n + c if a < c else c * n + a)
        start = 0
        for end in el:
            for i in range(start, end):
                j = i + 1 if i + 1 < end else start
                if (i * n + j if i < j else j * n + i) not in have:
                    return None
            start = end
    P = pts[tri]  # (t, 3, 2) corners: centroids (their mean) and orientations from one gather
    c = P.mean(axis=1)
    bounds = [0] + el
    poly = shapely.Polygon(pts[:bounds[1]], [pts[bounds[k]:bounds[k + 1]] for k in range(1, len(bounds) - 1)])
    inside = shapely.contains_xy(poly, c[:, 0], c[:, 1])
    if well_formed and int(inside.sum()) != n - 2 + 2 * (len(el) - 1):
        return None  # a flat triangle of collinear boundary points counted inside: not a triangulation
    return _counter_clockwise(tri[inside].astype(np.intp), P[inside])


def _has_ring_edges_np(tri: np.ndarray, ends: np.ndarray, n: int) -> bool:
    """Does ``tri`` hold every ring edge (vectorised: an (n, n) table for small n, else ``np.isin``)?"""
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
        return bool(tab[i, j].all())
    simp = np.sort(tri, axis=1)
    have = np.concatenate([simp[:, 0] * n + simp[:, 1], simp[:, 1] * n + simp[:, 2], simp[:, 0] * n + simp[:, 2]])
    return bool(np.isin(np.minimum(i, j) * n + np.maximum(i, j), have).all())


_EDGE_TABLE_MAX = 2048
"""Up to this many points the Delaunay edges go in a dense (n, n) table."""


def lawson_cdt(pts: np.ndarray, ring_ends, max_flips: int | None = None) -> np.ndarray:
    """CDT by ear clipping then constrained Lawson flips (general, slower path).

    The flip test is :func:`_incircle_d` and the orientation of the new diagonal's triangles,
    written out inline.
    """
    tri = ear_triangles(pts, ring_ends)
    n = len(pts)
    if len(tri) < 2:
        return tri
    constrained = _ring_edges(ring_ends)
    tris = tri.tolist()
    edge_tris = {}
    for ti, (a, b, c) in enumerate(tris):
        for u, v in ((a, b), (b, c), (c, a)):
            k = (u, v) if u < v else (v, u)
            lst = edge_tris.get(k)
            if lst is None:
                edge_tris[k] = [ti]
            else:
                lst.append(ti)
    stack = [e for e, ts in edge_tris.items() if len(ts) == 2 and e not in constrained]
    X = pts[:, 0].tolist()
    Y = pts[:, 1].tolist()
    budget = max_flips if max_flips is not None else 10 * n * n + 10
    get = edge_tris.get
    incircle = _incircle_d
    while stack and budget > 0:
        e = stack.pop()
        ts = get(e)
        if ts is None or len(ts) != 2:
            continue
        t1, t2 = ts
        a, b = e
        A, B, C = tris[t1]
        if (a == A and b == B) or (b == A and a == B):
            a, b, c = A, B, C
        elif (a == B and b == C) or (b == B and a == C):
            a, b, c = B, C, A
        else:
            a, b, c = C, A, B
        T2 = tris[t2]
        D = [v for v in T2 if v != a and v != b]
        if len(D) != 1:
            continue
        d = D[0]
        xd, yd = X[d], Y[d]
        if incircle(X[a] - xd, Y[a] - yd, X[b] - xd, Y[b] - yd, X[c] - xd, Y[c] - yd) <= 0.0:
            continue
        xa, ya, xc, yc = X[a], Y[a], X[c], Y[c]
        if (xd - xa) * (yc - ya) - (yd - ya) * (xc - xa) <= 0:
            continue
        xb, yb = X[b], Y[b]
        if (xb - xd) * (yc - yd) - (yb - yd) * (xc - xd) <= 0:
            continue
        budget -= 1
        tris[t1] = [a, d, c]
        tris[t2] = [d, b, c]
        del edge_tris[(a, b) if a < b else (b, a)]
        edge_tris[(c, d) if c < d else (d, c)] = [t1, t2]
        lst = edge_tris[(b, c) if b < c else (c, b)]
        lst[lst.index(t1)] = t2
        lst = edge_tris[(a, d) if a < d else (d, a)]
        lst[lst.index(t2)] = t1
        for u, v in ((a, c), (c, b), (b, d), (d, a)):
            k = (u, v) if u < v else (v, u)
            if k not in constrained:
                lk = get(k)
                if lk is not None and len(lk) == 2:
                    stack.append(k)
    return np.asarray(tris, dtype=np.intp).reshape(-1, 3)


def constrained_delaunay_many(polygons: Sequence[tuple[np.ndarray, np.ndarray]]) -> list[np.ndarray | None]:
    """:func:`constrained_delaunay` of many polygons, by GEOS in one call where it applies.

    GEOS (``shapely.constrained_delaunay_triangles``, shapely >= 2.1) triangulates every valid
    polygon without repeated points in compiled code; each corner carries its ring position as
    its z, so the triangles come back as indices without a coordinate lookup. A polygon goes to
    :func:`constrained_delaunay` instead when GEOS is missing or refuses it, when it is invalid
    or repeats a point (a ring touching another at a vertex), or when GEOS's answer is not a
    full triangulation of its points (``n - 2 + 2 holes`` triangles of distinct corners, as when
    it drops a vertex between collinear neighbours). Both are the CDT of the polygon; they can
    differ only where the choice is free (four or more co-circular points).

    Parameters
    ----------
    polygons : sequence of (points2d (n, 2) float, ring_ends (r,) int)
        Each polygon's ring vertices (outer ring first, then holes; open rings, concatenated)
        and cumulative ring sizes, as :func:`constrained_delaunay` takes them.

    Returns
    -------
    list of (t, 3) int or None
        Counter-clockwise triangles, indices into each polygon's points; None where
        :func:`constrained_delaunay` raised for that polygon.
    """
    out: list[np.ndarray | None] = [None] * len(polygons)
    todo = _geos_cdt(polygons, out)
    for k in todo:
        pts, ends = polygons[k]
        try:
            out[k] = np.asarray(constrained_delaunay(pts, ends), dtype=np.intp).reshape(-1, 3)
        except Exception:  # the caller keeps its own fallback
            out[k] = None
    return out


def _geos_cdt(polygons: Sequence[tuple[np.ndarray, np.ndarray]], out: list) -> list[int]:
    """Fill ``out`` with GEOS's CDT where it applies; return the polygons left to do."""
    P = len(polygons)
    if not hasattr(shapely, "constrained_delaunay_triangles"):
        return list(range(P))
    pts = [np.asarray(p, dtype=np.float64).reshape(-1, 2) for p, _ in polygons]
    ends = [np.asarray(e, dtype=np.intp).reshape(-1) for _, e in polygons]
    npts = np.fromiter(map(len, pts), dtype=np.intp, count=P)
    nring = np.fromiter(map(len, ends), dtype=np.intp, count=P)
    first_ring = np.cumsum(nring) - nring
    E = np.concatenate(ends) if P else np.zeros(0, np.intp)
    ring_poly = np.repeat(np.arange(P), nring)
    prev = np.concatenate(([0], E[:-1])) if len(E) else E
    prev[first_ring[nring > 0]] = 0
    size = E - prev                                                   # (R,) ring sizes
    last = np.where(nring > 0, E[np.maximum(first_ring + nring - 1, 0)] if len(E) else 0, -1)
    ok = (nring > 0) & (npts >= 3) & (last == npts) & (np.bincount(ring_poly[size < 3], minlength=P) == 0)
    X = np.concatenate(pts) if P else np.zeros((0, 2))
    poly_of = np.repeat(np.arange(P), npts)
    ok &= np.bincount(poly_of[~np.isfinite(X).all(axis=1)], minlength=P) == 0
    # a repeated point (same polygon, same x and y) makes the corner's index ambiguous
    order = np.lexsort((X[:, 1], X[:, 0], poly_of))
    same = (poly_of[order][1:] == poly_of[order][:-1]) & (X[order][1:] == X[order][:-1]).all(axis=1)
    ok[poly_of[order][1:][same]] = False
    use = np.flatnonzero(ok)
    if len(use) == 0:
        return list(range(P))
    # closed rings, each corner with its position in its polygon as z
    keep = ok[poly_of]
    pstart = np.cumsum(npts) - npts
    Y = np.column_stack([X, np.arange(len(X)) - np.repeat(pstart, npts)])[keep]
    rs = size[ok[ring_poly]]                                          # rings of the polygons used
    rstart = np.cumsum(rs) - rs                                       # into Y
    pos = np.arange(int(rs.sum()) + len(rs)) - np.repeat(np.arange(len(rs)), rs + 1)
    closing = np.cumsum(rs + 1) - 1
    pos[closing] = rstart
    ring_off = np.concatenate(([0], np.cumsum(rs + 1)))
    poly_off = np.concatenate(([0], np.cumsum(nring[use])))
    geoms = shapely.from_ragged_array(shapely.GeometryType.POLYGON, Y[pos], (ring_off, poly_off))
    valid = shapely.is_valid(geoms)
    try:
        tri = shapely.constrained_delaunay_triangles(np.where(valid, geoms, None))
    except Exception:  # one refusal fails the batch: ask polygon by polygon
        tri = np.array([_geos_one(g) if v else None for g, v in zip(geoms, valid)], dtype=object)
    parts, owner = shapely.get_parts(tri, return_index=True)
    C = shapely.get_coordinates(parts, include_z=True).reshape(-1, 4, 3)[:, :3]
    T = C[..., 2].astype(np.intp)
    # every corner one of its polygon's points, three distinct ones, in n - 2 + 2 holes triangles
    bad = ((T != C[..., 2]).any(axis=1) | (T < 0).any(axis=1) | (T >= npts[use][owner][:, None]).any(axis=1)
           | (T[:, 0] == T[:, 1]) | (T[:, 1] == T[:, 2]) | (T[:, 0] == T[:, 2]))
    counts = np.bincount(owner, minlength=len(use))
    took = valid & (counts == npts[use] - 2 + 2 * (nring[use] - 1)) & (np.bincount(owner[bad], minlength=len(use)) == 0)
    _counter_clockwise(T, C[..., :2])
    for k, t, took_k in zip(use.tolist(), np.split(T, np.cumsum(counts)[:-1]), took.tolist()):
        if took_k:
            out[k] = t
    done = np.zeros(P, dtype=bool)
    done[use[took]] = True
    return np.flatnonzero(~done).tolist()


def _geos_one(geom):
    try:
        return shapely.constrained_delaunay_triangles(geom)
    except Exception:
        return None
