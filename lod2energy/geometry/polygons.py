"""Planar polygons as the writers cut them: areas, a wall-aligned plane basis, triangles, convex pieces.

Exporter coordinates are local (a few hundred metres at most, see
:func:`~lod2energy.energy.zones.shells.local_origin`). The normal is
:func:`lod2energy.geometry.newell_normal` in Newell's textbook form (``centred=False``): the
writers' thresholds (piece area, planarity, collinearity) and their written IDF/STL bytes were
made with that operation order.

What is the writers' own: a plane basis whose ``u`` is horizontal (:func:`wall_basis`: walls are
written with "up" = ``v``), putting back the collinear ring vertices earcut skips (neighbouring
faces must keep sharing every vertex), and Hertel-Mehlhorn merging of triangles into the convex
pieces EnergyPlus wants.
"""
from __future__ import annotations

import math
from functools import partial
from typing import Sequence

import numpy as np

from lod2energy import cache
from lod2energy.geometry.cdt import earcut_rings
from lod2energy.geometry.vectors import newell_normal as _newell, unit, vector_length

#: Largest distance of a vertex to its face plane (m) for the face to be written as one piece.
PLANAR_TOL = 0.01


#: Newell's normal on the raw coordinates (length = 2 x area, m2), the writers' operation order.
newell_normal = partial(_newell, centred=False)


def wall_basis(normal: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Orthonormal (u, v) in the plane of unit ``normal`` with u x v = normal.

    u is horizontal (so for walls v points up), except on horizontal planes where u = +x.
    The cross products ``up x n`` and ``n x u`` are written out on Python floats in
    ``np.cross``'s operation order (same bits, a tenth of its cost).

    Parameters
    ----------
    normal : (3,) float
        Any length (it is normalised first).

    Returns
    -------
    u, v : (3,) float
    """
    n = unit(np.asarray(normal, dtype=np.float64))
    n0, n1, n2 = n.tolist()
    u = np.array([0.0 * n2 - 1.0 * n1, 1.0 * n0 - 0.0 * n2, 0.0 * n1 - 0.0 * n0])
    lu = vector_length(u)
    if lu < 1e-6:
        u = np.array([1.0, 0.0, 0.0]) - n[0] * n
        lu = vector_length(u)
    if lu > 0:  # unit(u), its length known
        u = u / lu
    u0, u1, u2 = u.tolist()
    v = np.array([n1 * u2 - n2 * u1, n2 * u0 - n0 * u2, n0 * u1 - n1 * u0])
    return u, v


def polygon_area3d(points: np.ndarray, normal: np.ndarray | None = None) -> float:
    """Area (m2) of a planar polygon, (k, 3) points: half the length of :func:`newell_normal`.

    ``normal``, when given, is that normal (the caller has it already: not computed again).
    """
    if normal is None:
        normal = newell_normal(points)
    return 0.5 * vector_length(normal)


def triangulate(points: np.ndarray, ring_ends: Sequence[int], normal: np.ndarray | None = None) -> np.ndarray:
    """Triangulate a 3D polygon with holes (earcut in its plane).

    Parameters
    ----------
    points : (k, 3) float
        Outer ring then holes, concatenated, rings open.
    ring_ends : sequence of int
        End index (exclusive) of each ring in ``points``.
    normal : (3,) float, optional
        Orientation of the result; defaults to the outer ring's Newell normal.

    Returns
    -------
    (t, 3) int
        Indices into ``points``, each triangle counter-clockwise seen from ``normal``; a new
        array each call.

    Notes
    -----
    Without ``normal`` the triangles are a pure function of the coordinates and ring ends:
    the zone shells triangulate each face for their volume and the STL writer again for its
    mesh, so the answers are kept in a bounded cache keyed by the coordinates' bytes.
    """
    p = np.asarray(points, dtype=np.float64)
    if normal is not None:
        return _triangulate(p, ring_ends, normal)
    key = (p.shape, p.tobytes(), tuple(map(int, ring_ends)))
    return cache.remember("geometry.polygon-triangles", key,
                          lambda: _triangulate(p, ring_ends, newell_normal(p[: ring_ends[0]])), KEPT_POLYGONS).copy()


#: Polygons whose triangles :func:`triangulate` keeps (:mod:`lod2energy.cache`).
KEPT_POLYGONS = 4096


def _triangulate(p: np.ndarray, ring_ends: Sequence[int], normal: np.ndarray) -> np.ndarray:
    """:func:`triangulate` of float64 points ``p`` (k, 3) seen from ``normal``."""
    n = unit(normal)
    if not n.any():
        return np.zeros((0, 3), dtype=np.intp)
    u, v = wall_basis(n)
    d = p - np.add.reduce(p, axis=0) / len(p)  # p - p.mean(axis=0), the same bits
    xy = np.empty((len(p), 2))
    xy[:, 0] = d @ u
    xy[:, 1] = d @ v
    tri = earcut_rings(xy, ring_ends)
    if len(tri) == 0:
        return tri
    # orient each triangle counter-clockwise; the 2D cross products on Python floats are the
    # same IEEE operations in the same order as on numpy rows (a tenth of the cost for the
    # few triangles of a building face)
    pts = xy.tolist()
    tris = tri.tolist()
    used = set()
    for t in tris:
        (ax, ay), (bx, by), (cx, cy) = pts[t[0]], pts[t[1]], pts[t[2]]
        if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0:
            t.reverse()
        used.update(t)
    tri = np.array(tris, dtype=np.intp)
    if len(used) < len(p):
        missing = np.array(sorted(set(range(len(p))) - used), dtype=np.intp)
        tri = _insert_dropped(tri, xy, missing)
    return tri


def _insert_dropped(tri: np.ndarray, xy: np.ndarray, missing: np.ndarray) -> np.ndarray:
    """Put back ring vertices earcut skipped (collinear ones) by splitting the triangle edge
    they lie on, so that neighbouring faces still share every vertex (no T-junction)."""
    tris = [list(t) for t in tri]
    for m in missing:
        q = xy[m]
        best, bd = None, np.inf
        for ti, t in enumerate(tris):
            for k in range(3):
                a, b = t[k], t[(k + 1) % 3]
                ab = xy[b] - xy[a]
                L2 = float(ab @ ab)
                if L2 == 0:
                    continue
                u = float((q - xy[a]) @ ab) / L2
                if not 0 < u < 1:
                    continue
                d = float(np.linalg.norm(xy[a] + u * ab - q))
                if d < bd:
                    best, bd = (ti, k), d
        if best is None:
            continue
        ti, k = best
        t = tris[ti]
        a, b, c = t[k], t[(k + 1) % 3], t[(k + 2) % 3]
        tris[ti] = [a, int(m), c]
        tris.append([int(m), b, c])
    return np.asarray(tris, dtype=np.intp).reshape(-1, 3)


#: Smallest sine of the turn at a vertex of a written convex piece: EnergyPlus removes
#: (near-)collinear vertices, which would leave T-junctions with the neighbouring surfaces.
STRICT_SIN = 2e-3


def is_convex_2d(xy: np.ndarray, eps: float = 1e-9, strict: bool = False) -> bool:
    """Counter-clockwise polygon ``(k, 2)`` convex?

    Collinear corners are allowed unless ``strict`` (then every turn must have a sine of
    at least :data:`STRICT_SIN`).
    """
    # on Python floats, row by row: the same IEEE operations as the numpy rows (a row norm
    # of two squares is their sum's square root either way), stopping at the first reflex turn
    pts = xy.tolist()
    d1 = [(bx - ax, by - ay) for (ax, ay), (bx, by) in zip(pts, pts[1:] + pts[:1])]
    bound = STRICT_SIN if strict else -eps
    for (ax, ay), (bx, by) in zip(d1, d1[1:] + d1[:1]):
        scale = math.sqrt(ax * ax + ay * ay) * math.sqrt(bx * bx + by * by)
        if not ax * by - ay * bx >= bound * (scale if scale >= 1e-12 or scale != scale else 1e-12):
            return False
    return True


def merge_convex(tris: np.ndarray, xy: np.ndarray, strict: bool = False) -> list[list[int]]:
    """Hertel-Mehlhorn: merge counter-clockwise triangles into convex polygons.

    Parameters
    ----------
    tris : (t, 3) int
        Triangles (indices into ``xy``) of one planar polygon.
    xy : (k, 2) float
        Vertex coordinates in the polygon's plane.

    Returns
    -------
    list of list of int
        Convex counter-clockwise polygons covering the same area, using only the
        triangles' vertices (so shared edges with other faces are kept).
    """
    polys: list[list[int] | None] = [list(map(int, t)) for t in tris]
    changed = True
    while changed:
        changed = False
        edge_owner: dict[tuple[int, int], int] = {}
        for pi, poly in enumerate(polys):
            if poly is None:
                continue
            for k in range(len(poly)):
                edge_owner[(poly[k], poly[(k + 1) % len(poly)])] = pi
        for (a, b), pi in list(edge_owner.items()):
            qi = edge_owner.get((b, a))
            if qi is None or qi == pi or polys[pi] is None or polys[qi] is None:
                continue
            p, q = polys[pi], polys[qi]
            if (a, b) not in {(p[k], p[(k + 1) % len(p)]) for k in range(len(p))}:
                continue
            i = p.index(b)
            p_rot = p[i:] + p[:i]          # b ... a
            j = q.index(a)
            q_rot = q[j:] + q[:j]          # a ... b
            merged = p_rot + q_rot[1:-1]   # b ... a ... (before b)
            if len(set(merged)) != len(merged):
                continue
            if is_convex_2d(xy[merged], strict=strict):
                polys[pi] = merged
                polys[qi] = None
                changed = True
                break
    return [p for p in polys if p is not None]

