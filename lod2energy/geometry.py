"""Shared numeric geometry: normals, snapping, triangulation, volumes, intersections.

Everything here works on plain numpy arrays (a building's ``vertices`` and the integer
rings of :class:`~lod2energy.model.Surface`) and is vectorised over faces or triangles
where it matters. Coordinates are metres; callers working with large real-world
coordinates (national grids) should subtract a local origin before exact-ish tests,
the functions that need it do so themselves.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

try:  # mapbox_earcut is a declared dependency; keep import errors readable
    import mapbox_earcut as _earcut
except ImportError:  # pragma: no cover
    _earcut = None

__all__ = [
    "cross_rows", "newell_normal", "polygon_normal", "best_fit_plane", "project_2d", "snap_map",
    "triangulate_surface", "triangulate_surfaces", "triangulate_flat", "triangulate_shell", "triangle_normals", "triangle_areas",
    "signed_volume", "bbox_pairs", "segment_triangle_intersect", "triangle_pairs_intersect",
    "winding_number", "points_in_solid", "collapse_short_edges",
]


# ----------------------------------------------------------------------------- normals

def newell_normal(points: np.ndarray) -> np.ndarray:
    """Newell's (area-weighted, unnormalised) normal of a closed ring.

    Parameters
    ----------
    points : (k, 3) float
        Ring vertices, open (first not repeated), m.

    Returns
    -------
    (3,) float
        Normal whose length is twice the ring's vector area, m2; zero for a degenerate ring.
    """
    p = np.asarray(points, dtype=np.float64)
    if len(p) < 3:
        return np.zeros(3)
    p = p - p.mean(axis=0)
    return _cross(p, np.roll(p, -1, axis=0)).sum(axis=0)


def polygon_normal(points: np.ndarray) -> np.ndarray:
    """Unit normal of a ring (Newell), right-hand rule; zeros when degenerate.

    Parameters
    ----------
    points : (k, 3) float
        Ring vertices, m.

    Returns
    -------
    (3,) float
    """
    n = newell_normal(points)
    ln = np.linalg.norm(n)
    return n / ln if ln > 0 else n


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
    cr = _cross(p, p[nxt])
    out = np.add.reduceat(cr, starts, axis=0) if len(idx) else np.zeros((0, 3))
    out[lens == 0] = 0.0
    return out


def best_fit_plane(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Least-squares plane through points (as CGAL's ``linear_least_squares_fitting_3``).

    Parameters
    ----------
    points : (k, 3) float

    Returns
    -------
    centroid : (3,) float
    normal : (3,) float
        Unit normal, oriented like the Newell normal of ``points`` taken as a ring.
    """
    p = np.asarray(points, dtype=np.float64)
    c = p.mean(axis=0)
    _, _, vt = np.linalg.svd(p - c, full_matrices=False)
    n = vt[-1]
    if np.dot(n, newell_normal(p)) < 0:
        n = -n
    return c, n


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


# ----------------------------------------------------------------------------- snapping

def snap_map(points: np.ndarray, tol: float) -> np.ndarray:
    """Representative of each point after merging points closer than ``tol``.

    Chains of close points merge into one cluster (transitive closure); the representative
    is the cluster's lowest index, as val3dity keeps the first vertex it met.

    Parameters
    ----------
    points : (n, 3) float
    tol : float, m
        ``<= 0`` merges only identical coordinates.

    Returns
    -------
    (n,) int
        ``rep[i]`` is the index of the point that ``i`` merges into (``rep[rep] == rep``).
    """
    p = np.asarray(points, dtype=np.float64)
    n = len(p)
    if n == 0:
        return np.zeros(0, dtype=np.intp)
    if tol <= 0:
        _, first, inv = np.unique(p, axis=0, return_index=True, return_inverse=True)
        return first[inv.ravel()].astype(np.intp)
    from scipy.spatial import cKDTree
    pairs = cKDTree(p).query_pairs(tol, output_type="ndarray")
    if len(pairs) == 0:
        return np.arange(n, dtype=np.intp)
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    g = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, lab = connected_components(g, directed=False)
    first = np.full(lab.max() + 1, n, dtype=np.intp)
    np.minimum.at(first, lab, np.arange(n))
    return first[lab]


# ----------------------------------------------------------------------------- triangulation

def _fix_orientation(tris: np.ndarray, p2: np.ndarray, local: np.ndarray) -> np.ndarray:
    """Flip triangles (local indices into p2) whose 2D area is negative."""
    a, b, c = p2[local[:, 0]], p2[local[:, 1]], p2[local[:, 2]]
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    neg = area < 0
    if neg.any():
        tris = tris.copy()
        tris[neg] = tris[neg][:, [0, 2, 1]]
    return tris


def _earcut_rings(p2: np.ndarray, ring_ends: np.ndarray) -> np.ndarray:
    if _earcut is None:  # pragma: no cover
        raise ImportError("mapbox_earcut is required for triangulation (pip install mapbox-earcut)")
    t = _earcut.triangulate_float64(np.ascontiguousarray(p2, dtype=np.float64),
                                    np.asarray(ring_ends, dtype=np.uint32))
    return np.asarray(t, dtype=np.intp).reshape(-1, 3)


def triangulate_surface(vertices: np.ndarray, surface, normal: np.ndarray | None = None) -> np.ndarray:
    """Triangulate one polygon (holes included) in its own plane.

    Parameters
    ----------
    vertices : (n, 3) float
        The building's vertices, m.
    surface : Surface or sequence of (k,) int
        The polygon (outer ring first, then holes), or its rings.
    normal : (3,) float, optional
        Plane normal; default: Newell normal of the outer ring.

    Returns
    -------
    (t, 3) int
        Triangles as indices into ``vertices``, oriented like the outer ring (their
        normals agree with ``normal``). Empty for a degenerate polygon.
    """
    rings = surface.rings if hasattr(surface, "rings") else surface
    outer = np.asarray(rings[0], dtype=np.intp)
    if len(rings) == 1 and len(outer) == 3:
        return outer.reshape(1, 3).copy()
    if len(outer) < 3:
        return np.zeros((0, 3), dtype=np.intp)
    if normal is None:
        normal = newell_normal(vertices[outer])
    if not np.any(normal):
        return np.zeros((0, 3), dtype=np.intp)
    ids = np.concatenate([np.asarray(r, dtype=np.intp) for r in rings])
    p2 = project_2d(vertices[ids], normal)
    p2 = p2 - p2.mean(axis=0)
    ends = np.cumsum([len(r) for r in rings])
    local = _earcut_rings(p2, ends)
    if len(local) > 1 and _sliver_mask_2d(p2[local]).any():
        # ear clipping leaves slivers along near-collinear vertices, which can cross a
        # neighbouring face; val3dity's constrained Delaunay triangulation avoids them
        try:
            from lod2energy.validate.triangulate import constrained_delaunay
            local = np.asarray(constrained_delaunay(p2, ends), dtype=np.intp).reshape(-1, 3)
        except Exception:  # pragma: no cover - keep the ear-clipping result
            pass
    if len(local) == 0:
        return np.zeros((0, 3), dtype=np.intp)
    return _fix_orientation(ids[local], p2, local)


def _triangulate_quads(vertices: np.ndarray, quads: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """Split simple quads (m, 4) along the diagonal through their sharpest corner."""
    m = len(quads)
    ax = np.argmax(np.abs(normals), axis=1)
    ij = np.array([(1, 2), (2, 0), (0, 1)])[ax]
    flip = normals[np.arange(m), ax] < 0
    ij[flip] = ij[flip][:, ::-1]
    pts = vertices[quads]                                        # (m, 4, 3)
    p2 = np.stack([np.take_along_axis(pts, np.broadcast_to(ij[:, None, k:k + 1], (m, 4, 1)), 2)[..., 0]
                   for k in range(2)], axis=-1)                  # (m, 4, 2)
    prv = np.roll(p2, 1, axis=1)
    nxt = np.roll(p2, -1, axis=1)
    turn = ((p2[..., 0] - prv[..., 0]) * (nxt[..., 1] - p2[..., 1])
            - (p2[..., 1] - prv[..., 1]) * (nxt[..., 0] - p2[..., 0]))   # (m, 4) > 0 convex corner
    # the diagonal leaves the sharpest corner (reflex or collinear): no zero-area triangle
    use_bd = np.minimum(turn[:, 1], turn[:, 3]) < np.minimum(turn[:, 0], turn[:, 2])
    a, b, c, d = quads.T
    t1 = np.where(use_bd[:, None], np.stack([a, b, d], 1), np.stack([a, b, c], 1))
    t2 = np.where(use_bd[:, None], np.stack([b, c, d], 1), np.stack([a, c, d], 1))
    return np.stack([t1, t2], axis=1).reshape(-1, 3)


def triangulate_surfaces(vertices: np.ndarray, ringsets: Sequence[Sequence[np.ndarray]]
                         ) -> tuple[np.ndarray, np.ndarray]:
    """Triangulate many polygons at once (see :func:`triangulate_flat`).

    Parameters
    ----------
    vertices : (n, 3) float
        The building's vertices, m.
    ringsets : sequence of sequence of (k,) int
        For each polygon its rings (outer first).

    Returns
    -------
    tris : (T, 3) int
        Indices into ``vertices``, each oriented like its polygon's outer ring, grouped
        by polygon in input order.
    poly_of_tri : (T,) int
        Index (into ``ringsets``) of the polygon of each triangle.
    """
    rings = [np.asarray(r, dtype=np.intp) for rs in ringsets for r in rs]
    if not rings:
        return np.zeros((0, 3), dtype=np.intp), np.zeros(0, dtype=np.intp)
    return triangulate_flat(vertices, np.concatenate(rings), np.array([len(r) for r in rings]),
                            np.array([len(rs) for rs in ringsets]))


SLIVER_RATIO = 0.01
"""Triangles whose height is under this share of their longest edge are slivers."""


def _sliver_mask(P: np.ndarray) -> np.ndarray:
    """(..., 3, 3) triangle corners -> (...) bool: sliver (2 area / longest edge^2 < SLIVER_RATIO)."""
    e = np.stack([P[..., 1, :] - P[..., 0, :], P[..., 2, :] - P[..., 1, :], P[..., 0, :] - P[..., 2, :]], -2)
    longest = (e * e).sum(-1).max(-1)
    cr = _cross(e[..., 0, :], -e[..., 2, :])
    return np.sqrt((cr * cr).sum(-1)) < SLIVER_RATIO * longest


def _sliver_mask_2d(P: np.ndarray) -> np.ndarray:
    """(t, 3, 2) triangles -> (t,) bool: sliver (see :func:`_sliver_mask`)."""
    e0, e1, e2 = P[:, 1] - P[:, 0], P[:, 2] - P[:, 1], P[:, 0] - P[:, 2]
    longest = np.maximum(np.maximum((e0 * e0).sum(1), (e1 * e1).sum(1)), (e2 * e2).sum(1))
    return np.abs(e0[:, 0] * e1[:, 1] - e0[:, 1] * e1[:, 0]) < SLIVER_RATIO * longest


def _has_sliver(vertices: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """(m, t, 3) triangles of m polygons -> (m,) bool: the polygon's triangulation has a sliver."""
    return _sliver_mask(vertices[tris]).any(axis=-1)


def _fan_convex(vertices: np.ndarray, polys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Fan triangulation of convex polygons (m, k), from a corner whose neighbours are corners too.

    Returns ``(tris (m, k-2, 3), ok (m,))``; ``ok`` is False for polygons that are not
    convex (or have no such corner), which need a general triangulation.
    """
    m, k = polys.shape
    P = vertices[polys]
    P = P - P.mean(axis=1, keepdims=True)
    n = _cross(P, np.roll(P, -1, axis=1)).sum(axis=1)
    ax = np.argmax(np.abs(n), axis=1)
    ij = np.array([(1, 2), (2, 0), (0, 1)])[ax]
    flip = n[np.arange(m), ax] < 0
    ij[flip] = ij[flip][:, ::-1]
    rows = np.arange(m)[:, None]
    p2 = np.stack([P[rows, np.arange(k)[None, :], ij[:, :1]], P[rows, np.arange(k)[None, :], ij[:, 1:]]], -1)
    e_in = p2 - np.roll(p2, 1, axis=1)
    e_out = np.roll(p2, -1, axis=1) - p2
    turn = e_in[..., 0] * e_out[..., 1] - e_in[..., 1] * e_out[..., 0]
    scale = np.linalg.norm(e_in, axis=2) * np.linalg.norm(e_out, axis=2)
    strict = turn > 1e-9 * scale
    convex = (turn >= -1e-12 * scale).all(axis=1)
    apex_ok = strict & np.roll(strict, 1, axis=1) & np.roll(strict, -1, axis=1)
    ok = convex & apex_ok.any(axis=1) & np.any(n != 0, axis=1)
    a = np.argmax(apex_ok, axis=1)
    i = np.arange(1, k - 1)
    loc = np.stack([np.broadcast_to(a[:, None], (m, k - 2)), (a[:, None] + i) % k, (a[:, None] + i + 1) % k], -1)
    return np.take_along_axis(polys[:, None, :], loc.reshape(m, 1, -1), axis=2).reshape(m, k - 2, 3), ok


def _triangulate_general(vertices, ids, ring_start, ring_len, first_ring, rpp, polys):
    """Ear clipping (constrained Delaunay where it leaves slivers) of polygons ``polys``,
    with normals, projections, orientation fixes and sliver tests vectorised."""
    # vertex slots of the chosen polygons (all their rings)
    r0 = first_ring[polys]
    nr = rpp[polys]
    rings = np.repeat(r0, nr) + (np.arange(nr.sum()) - np.repeat(np.cumsum(nr) - nr, nr))
    rl = ring_len[rings]
    slot = np.repeat(ring_start[rings], rl) + (np.arange(rl.sum()) - np.repeat(np.cumsum(rl) - rl, rl))
    ring_of = np.repeat(np.arange(len(rings)), rl)
    poly_of_ring = np.repeat(np.arange(len(polys)), nr)
    poly_of = poly_of_ring[ring_of]
    P = vertices[ids[slot]]
    # Newell normals of the outer rings
    rstart = np.concatenate(([0], np.cumsum(rl)[:-1]))
    nxt = np.arange(len(slot)) + 1
    nxt[rstart + rl - 1] = rstart
    o = P[np.concatenate(([0], np.cumsum(np.bincount(poly_of, minlength=len(polys)))[:-1]))][poly_of]
    Q = P - o
    cr = _cross(Q, Q[nxt])
    is_outer = np.zeros(len(rings), dtype=bool)
    is_outer[np.concatenate(([0], np.cumsum(nr)[:-1]))] = True
    cr[~is_outer[ring_of]] = 0.0
    n = np.zeros((len(polys), 3))
    np.add.at(n, poly_of, cr)
    ax = np.argmax(np.abs(n), axis=1)
    ij = np.array([(1, 2), (2, 0), (0, 1)])[ax]
    flip = n[np.arange(len(polys)), ax] < 0
    ij[flip] = ij[flip][:, ::-1]
    ijv = ij[poly_of]
    p2 = np.ascontiguousarray(np.stack([Q[np.arange(len(Q)), ijv[:, 0]], Q[np.arange(len(Q)), ijv[:, 1]]], -1))
    pstart = np.concatenate(([0], np.cumsum(np.bincount(poly_of, minlength=len(polys)))))
    rend_local = (rstart + rl) - pstart[poly_of_ring]
    good = np.any(n != 0, axis=1)
    tl, towner = [], []
    rcut = np.concatenate(([0], np.cumsum(nr)))
    for k in np.flatnonzero(good).tolist():
        a, b = pstart[k], pstart[k + 1]
        loc = _earcut_rings(p2[a:b], rend_local[rcut[k]:rcut[k + 1]])
        if len(loc):
            tl.append(loc + a)
            towner.append(np.full(len(loc), k, dtype=np.intp))
    if not tl:
        return np.zeros((0, 3), dtype=np.intp), np.zeros(0, dtype=np.intp)
    T = np.concatenate(tl)
    own = np.concatenate(towner)
    A2 = p2[T]
    area = ((A2[:, 1, 0] - A2[:, 0, 0]) * (A2[:, 2, 1] - A2[:, 0, 1])
            - (A2[:, 1, 1] - A2[:, 0, 1]) * (A2[:, 2, 0] - A2[:, 0, 0]))
    neg = area < 0
    T[neg] = T[neg][:, [0, 2, 1]]
    sl = _sliver_mask_2d(A2)
    redo = np.unique(own[sl & (np.bincount(own, minlength=len(polys))[own] > 1)])
    if len(redo):
        keep = ~np.isin(own, redo)
        T, own = T[keep], own[keep]
        extra_t, extra_o = [T], [own]
        try:
            from lod2energy.validate.triangulate import constrained_delaunay
        except ImportError:  # pragma: no cover
            constrained_delaunay = None
        for k in redo.tolist():
            a, b = pstart[k], pstart[k + 1]
            ends = rend_local[rcut[k]:rcut[k + 1]]
            try:
                loc = np.asarray(constrained_delaunay(p2[a:b], ends), dtype=np.intp).reshape(-1, 3)
            except Exception:  # keep ear clipping when the CDT fails
                loc = _earcut_rings(p2[a:b], ends)
                ar = _cross2(p2[a:b][loc[:, 0]], p2[a:b][loc[:, 1]], p2[a:b][loc[:, 2]]) if len(loc) else loc
                if len(loc):
                    loc[ar < 0] = loc[ar < 0][:, [0, 2, 1]]
            extra_t.append(loc + a)
            extra_o.append(np.full(len(loc), k, dtype=np.intp))
        T, own = np.concatenate(extra_t), np.concatenate(extra_o)
    return ids[slot[T]], polys[own]


def triangulate_flat(vertices: np.ndarray, ids: np.ndarray, ring_len: np.ndarray,
                     rings_per_poly: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Triangulate many polygons given in a flat encoding, in their own planes.

    Triangles, quadrilaterals (split through their sharpest corner) and convex
    polygons (fans from a strict corner) are handled in bulk; other polygons get ear
    clipping, replaced by a constrained Delaunay triangulation (as val3dity's) where it
    leaves slivers. No triangle has zero area unless its polygon has.

    Parameters
    ----------
    vertices : (n, 3) float
    ids : (m,) int
        All ring vertex indices, rings and polygons concatenated.
    ring_len : (r,) int
        Length of each ring.
    rings_per_poly : (f,) int
        Number of rings of each polygon (outer first).

    Returns
    -------
    tris : (T, 3) int
    poly_of_tri : (T,) int
    """
    ids = np.asarray(ids, dtype=np.intp)
    ring_len = np.asarray(ring_len, dtype=np.intp)
    rpp = np.asarray(rings_per_poly, dtype=np.intp)
    nf = len(rpp)
    if nf == 0:
        return np.zeros((0, 3), dtype=np.intp), np.zeros(0, dtype=np.intp)
    ring_start = np.concatenate(([0], np.cumsum(ring_len)[:-1]))
    first_ring = np.concatenate(([0], np.cumsum(rpp)[:-1]))
    ostart = ring_start[first_ring]
    nout = ring_len[first_ring]
    simple = rpp == 1
    out_t, out_f = [], []
    tri_f = np.flatnonzero(simple & (nout == 3))
    if len(tri_f):
        out_t.append(ids[ostart[tri_f, None] + np.arange(3)])
        out_f.append(tri_f)
    quad_c = np.flatnonzero(simple & (nout == 4))
    normals = np.zeros((nf, 3))
    if len(quad_c):
        q = ids[ostart[quad_c, None] + np.arange(4)]
        P = vertices[q]
        P = P - P.mean(axis=1, keepdims=True)
        normals[quad_c] = _cross(P, np.roll(P, -1, axis=1)).sum(axis=1)
        good = np.any(normals[quad_c] != 0, axis=1)
        quad_f = quad_c[good]
        if len(quad_f):
            out_t.append(_triangulate_quads(vertices, q[good], normals[quad_f]))
            out_f.append(np.repeat(quad_f, 2))
    else:
        quad_f = quad_c
    done = np.zeros(nf, dtype=bool)
    done[tri_f] = True
    done[quad_f] = True
    big = np.flatnonzero(simple & (nout >= 5))
    for k in np.unique(nout[big]).tolist():
        fk = big[nout[big] == k]
        t, ok = _fan_convex(vertices, ids[ostart[fk, None] + np.arange(k)])
        ok &= ~_has_sliver(vertices, t)
        if ok.any():
            out_t.append(t[ok].reshape(-1, 3))
            out_f.append(np.repeat(fk[ok], k - 2))
            done[fk[ok]] = True
    rest = np.flatnonzero(~done & (nout >= 3))
    if len(rest):
        t, owner = _triangulate_general(vertices, ids, ring_start, ring_len, first_ring, rpp, rest)
        if len(t):
            out_t.append(t)
            out_f.append(owner)
    if not out_t:
        return np.zeros((0, 3), dtype=np.intp), np.zeros(0, dtype=np.intp)
    tris = np.concatenate(out_t).astype(np.intp)
    fot = np.concatenate(out_f).astype(np.intp)
    order = np.argsort(fot, kind="stable")
    return tris[order], fot[order]


def triangulate_shell(vertices: np.ndarray, shell, rings_map: np.ndarray | None = None
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Triangulate every surface of a shell.

    Parameters
    ----------
    vertices : (n, 3) float
        The building's vertices, m.
    shell : Shell or sequence of Surface
    rings_map : (n,) int, optional
        Index map applied to ring indices first (e.g. snapped representatives).

    Returns
    -------
    tris : (T, 3) int
        Indices into ``vertices``, each oriented like its surface's outer ring.
    face_of_tri : (T,) int
        Index of the surface (in ``shell.surfaces``) each triangle comes from.
    """
    surfaces = shell.surfaces if hasattr(shell, "surfaces") else shell
    if rings_map is not None:
        mp = np.asarray(rings_map)
        ringsets = [[mp[r] for r in s.rings] for s in surfaces]
    else:
        ringsets = [s.rings for s in surfaces]
    return triangulate_surfaces(vertices, ringsets)


# ----------------------------------------------------------------------------- measures

def triangle_normals(vertices: np.ndarray, tris: np.ndarray, unit: bool = True) -> np.ndarray:
    """Normals of triangles.

    Parameters
    ----------
    vertices : (n, 3) float
    tris : (T, 3) int
    unit : bool
        Normalise (zero stays zero); else length = 2 x area.

    Returns
    -------
    (T, 3) float
    """
    v = vertices[tris]
    n = _cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    if unit:
        ln = np.linalg.norm(n, axis=1, keepdims=True)
        n = np.divide(n, ln, out=np.zeros_like(n), where=ln > 0)
    return n


def triangle_areas(vertices: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Areas of triangles, m2, shape (T,)."""
    return 0.5 * np.linalg.norm(triangle_normals(vertices, tris, unit=False), axis=1)


def signed_volume(vertices: np.ndarray, tris: np.ndarray) -> float:
    """Signed volume enclosed by triangles (divergence theorem), m3.

    Positive when a closed surface's normals point outwards. Computed about one of
    its vertices, so large real-world coordinates do not cost precision.

    Parameters
    ----------
    vertices : (n, 3) float
    tris : (T, 3) int

    Returns
    -------
    float
    """
    tris = np.asarray(tris, dtype=np.intp)
    if len(tris) == 0:
        return 0.0
    v = vertices[tris]
    v = v - v[0, 0]
    return float(np.einsum("ij,ij->i", v[:, 0], _cross(v[:, 1], v[:, 2])).sum() / 6.0)


# ----------------------------------------------------------------------------- pairs & intersections

def bbox_pairs(lo: np.ndarray, hi: np.ndarray, pad: float = 0.0,
               lo2: np.ndarray | None = None, hi2: np.ndarray | None = None, block: int = 2_000_000) -> np.ndarray:
    """Pairs of overlapping axis-aligned boxes (sort and sweep on x).

    Parameters
    ----------
    lo, hi : (m, 3) float
        Box corners.
    pad : float, m
        Boxes are grown by ``pad`` on each side.
    lo2, hi2 : (k, 3) float, optional
        A second set: pairs ``(i, j)`` with ``i`` in the first, ``j`` in the second.
        Without it, pairs ``i < j`` within the first set.
    block : int
        Candidate pairs examined at once (bounds memory on long strips of boxes).

    Returns
    -------
    (p, 2) int
    """
    lo = np.asarray(lo, dtype=np.float64) - pad
    hi = np.asarray(hi, dtype=np.float64) + pad
    if lo2 is None:
        m = len(lo)
        if m < 2:
            return np.zeros((0, 2), dtype=np.intp)
        order = np.argsort(lo[:, 0], kind="stable")
        slo = lo[order, 0]
        end = np.searchsorted(slo, hi[order, 0], side="right")
        start = np.arange(m) + 1
        cnt = np.maximum(end - start, 0)
        if int(cnt.sum()) == 0:
            return np.zeros((0, 2), dtype=np.intp)
        # expand the x-overlaps in blocks of about `block` candidates (bounded memory)
        csum = np.cumsum(cnt)
        cuts = np.searchsorted(csum, np.arange(block, int(csum[-1]), block), side="left")
        out = []
        for r0, r1 in zip(np.r_[0, cuts], np.r_[cuts, m]):
            c = cnt[r0:r1]
            tot = int(c.sum())
            if tot == 0:
                continue
            ii = np.repeat(np.arange(r0, r1), c)
            jj = start[ii] + (np.arange(tot) - np.repeat(np.cumsum(c) - c, c))
            a, b = order[ii], order[jj]
            ok = np.all((lo[a, 1:] <= hi[b, 1:]) & (lo[b, 1:] <= hi[a, 1:]), axis=1)
            a, b = a[ok], b[ok]
            out.append(np.stack([np.minimum(a, b), np.maximum(a, b)], axis=1))
        return np.concatenate(out) if out else np.zeros((0, 2), dtype=np.intp)
    lo2 = np.asarray(lo2, dtype=np.float64) - pad
    hi2 = np.asarray(hi2, dtype=np.float64) + pad
    ok = np.all((lo[:, None, :] <= hi2[None, :, :]) & (lo2[None, :, :] <= hi[:, None, :]), axis=2)
    return np.argwhere(ok)


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
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


_cross = cross_rows


def _unit(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    ln = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, ln, out=np.zeros_like(v), where=ln > 0), ln[..., 0]


def segment_triangle_intersect(s0: np.ndarray, s1: np.ndarray, t0: np.ndarray, t1: np.ndarray,
                               t2: np.ndarray, eps: float = 1e-6) -> np.ndarray:
    """Whether segments properly pierce triangles (by more than ``eps``).

    A segment pierces a triangle when its endpoints lie on both sides of the
    triangle's plane, each farther than ``eps``, and the crossing point lies inside
    the triangle, farther than ``eps`` from its edges. Touching (within ``eps``) does
    not count; segments lying in the plane do not count (test those in 2D).

    Parameters
    ----------
    s0, s1 : (m, 3) float
        Segment endpoints, m (local coordinates).
    t0, t1, t2 : (m, 3) float
        Triangle corners.
    eps : float, m

    Returns
    -------
    (m,) bool
    """
    un, ln = _unit(_cross(t1 - t0, t2 - t0))
    d0 = np.einsum("ij,ij->i", s0 - t0, un)
    d1 = np.einsum("ij,ij->i", s1 - t0, un)
    ok = (ln > 0) & (((d0 > eps) & (d1 < -eps)) | ((d0 < -eps) & (d1 > eps)))
    if not ok.any():
        return ok
    den = np.where(ok, d0 - d1, 1.0)
    x = s0 + (d0 / den)[:, None] * (s1 - s0)
    for a, b in ((t0, t1), (t1, t2), (t2, t0)):
        inward, _ = _unit(_cross(un, b - a))           # points into the (CCW) triangle
        ok &= np.einsum("ij,ij->i", x - a, inward) > eps
    return ok


def _coplanar_overlap(A: np.ndarray, B: np.ndarray, normal: np.ndarray, eps: float = 1e-6) -> np.ndarray:
    """Whether coplanar triangles A, B (m, 3, 3) share interior area (beyond ``eps``)."""
    m = len(A)
    if m == 0:
        return np.zeros(0, dtype=bool)
    un, _ = _unit(normal)
    ref = np.where(np.abs(un[:, :1]) < 0.9, np.array([[1.0, 0, 0]]), np.array([[0, 1.0, 0]]))
    e1, _ = _unit(_cross(un, ref))
    e2 = _cross(un, e1)
    o = A[:, :1]
    a2 = np.stack([np.einsum("ijk,ik->ij", A - o, e1), np.einsum("ijk,ik->ij", A - o, e2)], -1)
    b2 = np.stack([np.einsum("ijk,ik->ij", B - o, e1), np.einsum("ijk,ik->ij", B - o, e2)], -1)
    for t in (a2, b2):                                   # both counter-clockwise
        neg = _cross2(t[:, 0], t[:, 1], t[:, 2]) < 0
        t[neg] = t[neg][:, ::-1]

    def side(p, q, r):                                   # signed distance of r from line pq
        ln = np.linalg.norm(q - p, axis=-1)
        return np.divide(_cross2(p, q, r), ln, out=np.zeros_like(ln), where=ln > 0)

    hit = np.zeros(m, dtype=bool)
    for i in range(3):
        p, q = a2[:, i], a2[:, (i + 1) % 3]
        for j in range(3):
            r, s_ = b2[:, j], b2[:, (j + 1) % 3]
            o1, o2 = side(p, q, r), side(p, q, s_)
            o3, o4 = side(r, s_, p), side(r, s_, q)
            hit |= (((o1 > eps) & (o2 < -eps)) | ((o1 < -eps) & (o2 > eps))) & \
                   (((o3 > eps) & (o4 < -eps)) | ((o3 < -eps) & (o4 > eps)))

    def inside(t, x):
        return (side(t[:, 0], t[:, 1], x) > eps) & (side(t[:, 1], t[:, 2], x) > eps) & \
            (side(t[:, 2], t[:, 0], x) > eps)
    hit |= inside(a2, b2.mean(axis=1)) | inside(b2, a2.mean(axis=1))
    for k in range(3):
        hit |= inside(a2, b2[:, k]) | inside(b2, a2[:, k])
    return hit


def _cross2(o, a, b):
    return (a[..., 0] - o[..., 0]) * (b[..., 1] - o[..., 1]) - (a[..., 1] - o[..., 1]) * (b[..., 0] - o[..., 0])


def triangle_pairs_intersect(vertices: np.ndarray, tris: np.ndarray, pairs: np.ndarray,
                             eps: float = 1e-6) -> np.ndarray:
    """Whether pairs of triangles of one surface intersect other than along shared elements.

    Triangles sharing an edge intersect only when folded onto each other; triangles
    sharing a vertex when they meet elsewhere too; others when they meet at all.
    Contacts within ``eps`` (round-off of touching faces) do not count.

    Parameters
    ----------
    vertices : (n, 3) float
        Use local coordinates (subtract an origin) for real-world data, m.
    tris : (T, 3) int
        Triangles; vertex identity is by index (snap first).
    pairs : (p, 2) int
        Candidate pairs (e.g. from :func:`bbox_pairs`).
    eps : float, m
        Distance under which points count as touching / in the same plane.

    Returns
    -------
    (p,) bool
    """
    pairs = np.asarray(pairs, dtype=np.intp).reshape(-1, 2)
    res = np.zeros(len(pairs), dtype=bool)
    if len(pairs) == 0:
        return res
    used = np.unique(pairs)
    P = vertices[tris[used]]
    un_all = np.zeros((len(tris), 3))
    un_all[used], _ = _unit(_cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]))
    ta, tb = tris[pairs[:, 0]], tris[pairs[:, 1]]
    eq = ta[:, :, None] == tb[:, None, :]                        # (p, 3, 3)
    in_b = eq.any(axis=2)                                        # vertex k of a is in b
    in_a = eq.any(axis=1)
    nshared = in_b.sum(axis=1)
    res[nshared == 3] = True

    # shared edge: only a fold (coplanar, third vertices on the same side) intersects
    s2 = np.flatnonzero(nshared == 2)
    if len(s2):
        ua, ub = un_all[pairs[s2, 0]], un_all[pairs[s2, 1]]
        folded = np.einsum("ij,ij->i", ua, ub) < 0
        s2 = s2[folded]
        if len(s2):
            kb = np.argmin(in_a[s2], axis=1)
            d = vertices[tb[s2, kb]]
            a0 = vertices[ta[s2, 0]]
            dn = np.abs(np.einsum("ij,ij->i", d - a0, un_all[pairs[s2, 0]]))
            res[s2] = dn <= eps

    rest = np.flatnonzero(nshared < 2)
    if len(rest) == 0:
        return res
    ia, ib = in_a[rest], in_b[rest]
    A, B = vertices[ta[rest]], vertices[tb[rest]]
    ua, ub = un_all[pairs[rest, 0]], un_all[pairs[rest, 1]]
    sd_b = np.einsum("ijk,ik->ij", B - A[:, :1], ua)            # (r, 3) signed distances of B to plane A
    sd_a = np.einsum("ijk,ik->ij", A - B[:, :1], ub)
    # a triangle whose own (non-shared) vertices are all strictly on one side of the other's
    # plane meets that plane at most in the shared vertex: no intersection
    sep = (np.where(ia, np.inf, sd_b).min(axis=1) > eps) | \
        (np.where(ia, -np.inf, sd_b).max(axis=1) < -eps) | \
        (np.where(ib, np.inf, sd_a).min(axis=1) > eps) | \
        (np.where(ib, -np.inf, sd_a).max(axis=1) < -eps)
    keep = np.flatnonzero(~sep)
    if len(keep) == 0:
        return res
    rest, ia, ib, A, B, ua = rest[keep], ia[keep], ib[keep], A[keep], B[keep], ua[keep]
    coplanar = np.all(np.abs(sd_b[keep]) <= eps, axis=1)
    ns = nshared[rest]
    hit = np.zeros(len(rest), dtype=bool)
    # shared vertex: the opposite edges must not pierce the other triangle
    s1 = np.flatnonzero((ns == 1) & ~coplanar)
    if len(s1):
        ka = np.argmax(ib[s1], axis=1)
        kb = np.argmax(ia[s1], axis=1)
        r = np.arange(len(s1))
        A1, B1 = A[s1], B[s1]
        hit[s1] = (segment_triangle_intersect(A1[r, (ka + 1) % 3], A1[r, (ka + 2) % 3], B1[:, 0], B1[:, 1], B1[:, 2], eps)
                   | segment_triangle_intersect(B1[r, (kb + 1) % 3], B1[r, (kb + 2) % 3], A1[:, 0], A1[:, 1], A1[:, 2], eps))
    # disjoint vertex sets
    s0 = np.flatnonzero((ns == 0) & ~coplanar)
    if len(s0):
        a, b = A[s0], B[s0]
        h = np.zeros(len(s0), dtype=bool)
        for i in range(3):
            h |= segment_triangle_intersect(a[:, i], a[:, (i + 1) % 3], b[:, 0], b[:, 1], b[:, 2], eps)
            h |= segment_triangle_intersect(b[:, i], b[:, (i + 1) % 3], a[:, 0], a[:, 1], a[:, 2], eps)
        hit[s0] = h
    cop = np.flatnonzero(coplanar)
    if len(cop):
        hit[cop] = _coplanar_overlap(A[cop], B[cop], ua[cop], eps)
    # a vertex of one lying on the other (not one of its vertices): they touch there
    hit |= _vertex_on_triangle(B, ~ia, A, ua, eps) | _vertex_on_triangle(A, ~ib, B, un_all[pairs[rest, 1]], eps)
    res[rest] = hit
    return res


def _vertex_on_triangle(P: np.ndarray, own: np.ndarray, T: np.ndarray, un: np.ndarray, eps: float) -> np.ndarray:
    """(m, 3, 3) points P (mask ``own`` (m, 3): not shared) lying on triangles T (m, 3, 3)
    of unit normals ``un`` (m, 3), within ``eps`` of its plane and inside or on its edges."""
    d = np.einsum("ijk,ik->ij", P - T[:, :1], un)               # (m, 3)
    on = own & (np.abs(d) <= eps) & (np.linalg.norm(un, axis=1) > 0)[:, None]
    if not on.any():
        return on.any(axis=1)
    inside = on.copy()
    for a, b in ((0, 1), (1, 2), (2, 0)):
        inward, _ = _unit(_cross(un, T[:, b] - T[:, a]))
        inside &= np.einsum("ijk,ik->ij", P - T[:, a][:, None, :], inward) >= -eps
    return inside.any(axis=1)


# ----------------------------------------------------------------------------- inside / outside

def winding_number(points: np.ndarray, vertices: np.ndarray, tris: np.ndarray,
                   chunk: int = 2_000_000) -> np.ndarray:
    """Generalised winding number of points w.r.t. a triangle surface.

    About 1 inside a closed outward-oriented surface, 0 outside, -1 inside an inward one.

    Parameters
    ----------
    points : (P, 3) float
    vertices : (n, 3) float
    tris : (T, 3) int
    chunk : int
        Largest P x T block evaluated at once.

    Returns
    -------
    (P,) float
    """
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    tris = np.asarray(tris, dtype=np.intp)
    if len(tris) == 0 or len(pts) == 0:
        return np.zeros(len(pts))
    o = vertices[np.unique(tris)].mean(axis=0)
    V = vertices[tris] - o                                        # (T, 3, 3)
    pts = pts - o
    out = np.empty(len(pts))
    step = max(1, chunk // max(len(tris), 1))
    for s in range(0, len(pts), step):
        p = pts[s:s + step]
        a = V[None, :, 0] - p[:, None]
        b = V[None, :, 1] - p[:, None]
        c = V[None, :, 2] - p[:, None]
        la, lb, lc = (np.linalg.norm(x, axis=2) for x in (a, b, c))
        det = np.einsum("ptk,ptk->pt", a, np.cross(b, c))
        den = (la * lb * lc + np.einsum("ptk,ptk->pt", a, b) * lc
               + np.einsum("ptk,ptk->pt", b, c) * la + np.einsum("ptk,ptk->pt", c, a) * lb)
        out[s:s + step] = np.arctan2(det, den).sum(axis=1) / (2 * np.pi)
    return out


def points_in_solid(points: np.ndarray, vertices: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Whether points lie inside a closed triangle surface (either orientation).

    Parameters
    ----------
    points : (P, 3) float
    vertices : (n, 3) float
    tris : (T, 3) int

    Returns
    -------
    (P,) bool
    """
    return np.abs(winding_number(points, vertices, tris)) > 0.5


def collapse_short_edges(v: np.ndarray, t: np.ndarray, c: np.ndarray, tol: float
                         ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Collapse edges shorter than ``tol`` (m) one at a time, keeping the mesh 2-manifold.

    Unions leave micro-edges where a vertex of one part lies a few micrometres off a face of
    another; the triangles around them are slivers that STL readers see as degenerate (a
    binary STL stores float32, so endpoints closer than about 1e-6 m become one point).
    Shortest edges first, an edge a-b is collapsed only when it is used by exactly two
    triangles and the link condition holds (the vertices adjacent to both a and b are the
    two opposite vertices of those triangles): collapsing all short edges at once can pinch
    the surface into an edge used by four triangles. The surviving endpoint keeps its
    position; the collapse is tried the other way round, and skipped, when it would turn the
    normal of a remaining triangle by more than 60 degrees or flatten it.

    Parameters
    ----------
    v : (n, 3) float
        Vertices (m).
    t : (t, 3) int
        Triangles, closed and consistently wound.
    c : (t,) int
        A value per triangle (kept for the triangles that stay).
    tol : float
        Edge length (m) below which edges are collapsed.

    Returns
    -------
    vertices (n', 3) float, triangles (t', 3) int, values (t',) int
    """
    v = np.asarray(v, dtype=np.float64)
    t = np.array(t, dtype=np.intp).reshape(-1, 3)
    c = np.asarray(c)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    L = np.linalg.norm(v[e[:, 0]] - v[e[:, 1]], axis=1)
    sel = np.nonzero(L < tol)[0]
    if len(sel) == 0:
        return v, t, c
    sel = sel[np.argsort(L[sel], kind="stable")]
    alive = np.ones(len(t), dtype=bool)
    vt: list[set[int]] = [set() for _ in range(len(v))]
    for i, tri in enumerate(t.tolist()):
        for x in tri:
            vt[x].add(i)

    def ring(x: int) -> set[int]:
        return {int(y) for ti in vt[x] for y in t[ti]} - {x}

    def normal(p: np.ndarray) -> np.ndarray:
        return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])

    def keeps_shape(keep: int, gone: int, shared: set[int]) -> bool:
        moved = sorted(vt[gone] - shared)
        if not moved:
            return True
        tri = t[moved]
        before = normal(v[tri])
        after_idx = np.where(tri == gone, keep, tri)
        after = normal(v[after_idx])
        nb, na = np.linalg.norm(before, axis=1), np.linalg.norm(after, axis=1)
        ok = (na > 1e-12) & (np.einsum("ij,ij->i", before, after) > 0.5 * nb * na)
        return bool(ok.all())

    for a, b in e[sel].tolist():
        if not vt[a] or not vt[b] or np.linalg.norm(v[a] - v[b]) >= tol:
            continue
        shared = vt[a] & vt[b]
        if len(shared) != 2:
            continue
        opposite = {int(y) for ti in shared for y in t[ti]} - {a, b}
        if (ring(a) & ring(b)) != opposite:
            continue
        if keeps_shape(a, b, shared):
            keep, gone = a, b
        elif keeps_shape(b, a, shared):
            keep, gone = b, a
        else:
            continue
        for ti in shared:
            alive[ti] = False
            for x in t[ti]:
                vt[int(x)].discard(ti)
        for ti in vt[gone]:
            t[ti][t[ti] == gone] = keep
            vt[keep].add(ti)
        vt[gone] = set()
    t, c = t[alive], c[alive]
    used, inv = np.unique(t, return_inverse=True)
    return v[used], inv.reshape(-1, 3), c
