"""Triangulation of surfaces and shells: one polygon, or many at once on bulk paths.

:func:`triangulate_flat` handles many polygons at once (triangles, quads, convex fans in bulk;
ear clipping by mapbox-earcut for the rest, replaced by the constrained Delaunay triangulation
where ear clipping leaves slivers). The ear clipping and the CDT of one polygon live in
:mod:`lod2energy.geometry.cdt`.
"""
from __future__ import annotations

import numpy as np

from lod2energy.geometry.cdt import constrained_delaunay, constrained_delaunay_many, earcut_rings
from lod2energy.geometry.vectors import cross_rows, cross2, newell_normal, project_2d

__all__ = ["triangulate_surface", "triangulate_flat", "SLIVER_RATIO"]


def _fix_orientation(tris: np.ndarray, p2: np.ndarray, local: np.ndarray) -> np.ndarray:
    """Flip triangles (local indices into p2) whose 2D area is negative."""
    a, b, c = p2[local[:, 0]], p2[local[:, 1]], p2[local[:, 2]]
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    neg = area < 0
    if neg.any():
        tris = tris.copy()
        tris[neg] = tris[neg][:, [0, 2, 1]]
    return tris


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
    local = earcut_rings(p2, ends)
    if len(local) > 1 and _sliver_mask_2d(p2[local]).any():
        # ear clipping leaves slivers along near-collinear vertices, which can cross a
        # neighbouring face; val3dity's constrained Delaunay triangulation avoids them
        try:
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


SLIVER_RATIO = 0.01
"""Triangles whose height is under this share of their longest edge are slivers."""


def _sliver_mask(P: np.ndarray) -> np.ndarray:
    """(..., 3, 3) triangle corners -> (...) bool: sliver (2 area / longest edge^2 < SLIVER_RATIO)."""
    e = np.stack([P[..., 1, :] - P[..., 0, :], P[..., 2, :] - P[..., 1, :], P[..., 0, :] - P[..., 2, :]], -2)
    longest = (e * e).sum(-1).max(-1)
    cr = cross_rows(e[..., 0, :], -e[..., 2, :])
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
    n = cross_rows(P, np.roll(P, -1, axis=1)).sum(axis=1)
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
    cr = cross_rows(Q, Q[nxt])
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
        loc = earcut_rings(p2[a:b], rend_local[rcut[k]:rcut[k + 1]])
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
        redo = redo.tolist()
        cdts = constrained_delaunay_many([(p2[pstart[k]:pstart[k + 1]], rend_local[rcut[k]:rcut[k + 1]])
                                          for k in redo])
        for k, loc in zip(redo, cdts):
            a, b = pstart[k], pstart[k + 1]
            ends = rend_local[rcut[k]:rcut[k + 1]]
            if loc is None:  # keep ear clipping when the CDT fails
                loc = earcut_rings(p2[a:b], ends)
                ar = cross2(p2[a:b][loc[:, 0]], p2[a:b][loc[:, 1]], p2[a:b][loc[:, 2]]) if len(loc) else loc
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
        normals[quad_c] = cross_rows(P, np.roll(P, -1, axis=1)).sum(axis=1)
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
