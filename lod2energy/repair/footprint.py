"""Stage 5 of the repair ladder: extrude the building's 2D footprint to its heights.

First choice (:func:`extrude_roofs`): every upward-facing face (roof, dormer, outer ceiling)
is projected to XY and extruded from the ground level up to its own plane; the union of those
prisms (manifold3d) is the building as a 2.5D model: the input's roof shapes and heights are
kept exactly, only overhangs and anything below the ground level are lost.

Fallback (:func:`extrude_footprint`): the footprint is the union of the faces' XY projections
(walls vanish); when that is not one polygon, the 2D alpha shape (``shapely.concave_hull``) of
all the points is used instead. The prism goes from the lowest point to the area-weighted
mean height of the upward-facing faces (the roof), so that its volume approximates the input's.
"""
from __future__ import annotations

import numpy as np

from lod2energy.geometry import collapse_short_edges
from lod2energy.repair._mesh import Face, PolyMesh, face_area, face_normal


def footprint_polygon(m: PolyMesh, simplify: float = 0.01):
    """The shapely Polygon of the footprint, or None."""
    import shapely
    from shapely.geometry import MultiPoint, Polygon
    V = m.vertices
    polys = []
    for f in m.faces:
        P = V[list(f.outer)][:, :2]
        if len(P) < 3:
            continue
        try:
            p = Polygon(P, [V[list(r)][:, :2] for r in f.rings[1:]])
            if not p.is_valid:
                p = p.buffer(0)
        except Exception:  # noqa: BLE001
            continue
        if p.area > 1e-6:
            polys.append(p)
    fp = shapely.union_all(polys).buffer(0.005, join_style="mitre").buffer(-0.005, join_style="mitre") if polys else None
    if fp is None or fp.is_empty or fp.geom_type != "Polygon":
        used = sorted({i for f in m.faces for r in f.rings for i in r})
        pts = MultiPoint(V[used][:, :2])
        fp = shapely.concave_hull(pts, ratio=0.3)
        if fp.geom_type != "Polygon":
            fp = pts.convex_hull
    if fp.geom_type != "Polygon" or fp.area <= 1e-4:
        return None
    fp = fp.simplify(simplify, preserve_topology=True)
    return shapely.geometry.polygon.orient(fp, 1.0)


def roof_height(m: PolyMesh) -> tuple[float, float]:
    """(lowest z, area-weighted mean z of upward faces), m."""
    V = m.vertices
    used = sorted({i for f in m.faces for r in f.rings for i in r})
    z0 = float(V[used, 2].min())
    num = den = 0.0
    for f in m.faces:
        n = face_normal(V, f)
        if n[2] > 0.1:
            a = face_area(V, f) * n[2]
            num += a * V[list(f.outer), 2].mean()
            den += a
    top = num / den if den > 0 else float(V[used, 2].max())
    if top - z0 < 0.1:
        top = float(V[used, 2].max())
    return z0, top


def extrude_footprint(m: PolyMesh) -> PolyMesh | None:
    """A prism over the footprint (None if there is none)."""
    fp = footprint_polygon(m)
    if fp is None:
        return None
    z0, z1 = roof_height(m)
    if z1 - z0 <= 1e-3:
        return None
    rings2 = [np.asarray(fp.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in fp.interiors]
    verts, bottom, top, walls = [], [], [], []
    for k, R in enumerate(rings2):
        if k > 0:  # holes run clockwise after orient(); that is what the bottom/top need
            pass
        n = len(R)
        base = len(verts)
        for x, y in R:
            verts.append((x, y, z0))
        for x, y in R:
            verts.append((x, y, z1))
        b = [base + i for i in range(n)]
        t = [base + n + i for i in range(n)]
        bottom.append(tuple(reversed(b)))
        top.append(tuple(t))
        for i in range(n):
            j = (i + 1) % n
            walls.append(Face(((b[i], b[j], t[j], t[i]),)))
    faces = [Face(tuple(bottom)), Face(tuple(top))] + walls
    return PolyMesh(np.asarray(verts, dtype=np.float64), tuple(faces))


#: Faces whose unit normal has a z component above this are roofs for :func:`extrude_roofs`.
UP_NZ = 0.05
#: Vertices of the union closer than this (m) are merged (sliver removal, manifold3d simplify).
UNION_SIMPLIFY = 1e-3
#: Pieces of the union under this share of its volume are dropped (crumbs of tiny roof faces).
MIN_PIECE = 0.01
#: Edges of the union shorter than this (m) are collapsed: 1.5 x val3dity's snap tolerance.
COLLAPSE = 1.5e-3


def ground_level(m: PolyMesh) -> float:
    """Ground height, m: the area-weighted mean z of the downward-facing faces (lowest point
    when there are none)."""
    V = m.vertices
    num = den = 0.0
    for f in m.faces:
        n = face_normal(V, f)
        if n[2] < -0.9:
            a = face_area(V, f)
            num += a * V[list(f.outer), 2].mean()
            den += a
    if den > 0:
        return num / den
    used = sorted({i for f in m.faces for r in f.rings for i in r})
    return float(V[used, 2].min())


def _prism(P2: np.ndarray, holes: list[np.ndarray], z0: float, plane: tuple[np.ndarray, np.ndarray]
           ) -> tuple[np.ndarray, np.ndarray] | None:
    """Closed triangle mesh of the prism over a 2D polygon from ``z0`` up to a plane.

    Returns
    -------
    vertices (n, 3), triangles (t, 3), or None when the plane is not above ``z0``
    """
    import mapbox_earcut as earcut

    p0, n = plane
    rings = [P2] + holes
    pts = np.vstack(rings)
    ztop = p0[2] - (n[0] * (pts[:, 0] - p0[0]) + n[1] * (pts[:, 1] - p0[1])) / n[2]
    if np.any(ztop <= z0 + 1e-3):
        return None
    ends = np.cumsum([len(r) for r in rings]).astype(np.uint32)
    tri = np.asarray(earcut.triangulate_float64(pts, ends), dtype=np.int64).reshape(-1, 3)
    if len(tri) == 0:
        return None
    k = len(pts)
    V = np.vstack([np.column_stack([pts, np.full(k, z0)]), np.column_stack([pts, ztop])])
    # earcut keeps the input winding: make the top counter-clockwise seen from above
    a = pts[tri]
    cross = (a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1]) - (a[:, 1, 1] - a[:, 0, 1]) * (a[:, 2, 0] - a[:, 0, 0])
    tri[cross < 0] = tri[cross < 0][:, ::-1]
    T = [tri + k, tri[:, ::-1]]
    s = 0
    for r in rings:
        m = len(r)
        idx = np.arange(s, s + m)
        nxt = np.roll(idx, -1)
        T.append(np.column_stack([idx, nxt, nxt + k]))
        T.append(np.column_stack([idx, nxt + k, idx + k]))
        s += m
    T = np.vstack(T)
    # walls follow the ring direction: outward for a CCW exterior and CW holes (shapely orient)
    return V, T


def extrude_roofs(m: PolyMesh) -> PolyMesh | None:
    """The union of prisms from the ground level up to each upward-facing face (2.5D model).

    Returns
    -------
    PolyMesh or None
        Polygons (coplanar triangles of the union merged), or None when there is no roof or
        the union fails.
    """
    import manifold3d as m3
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient as orient2d

    from lod2energy.repair._mesh import merge_coplanar, triangles_to_mesh

    V = m.vertices
    used = sorted({i for f in m.faces for r in f.rings for i in r})
    if len(used) < 4:
        return None
    origin = V[used].mean(axis=0)
    L = V - origin
    z0 = ground_level(m) - origin[2]
    parts = []
    for f in m.faces:
        n = face_normal(V, f)
        if n[2] <= UP_NZ or face_area(V, f) <= 1e-4:
            continue
        try:
            poly = Polygon(L[list(f.outer)][:, :2], [L[list(r)][:, :2] for r in f.rings[1:]])
            if not poly.is_valid:
                poly = poly.buffer(0)
        except Exception:  # noqa: BLE001 - shapely rejects degenerate rings
            continue
        polys = [poly] if poly.geom_type == "Polygon" else list(getattr(poly, "geoms", []))
        p0 = L[list(f.outer)].mean(axis=0)
        for p in polys:
            if p.geom_type != "Polygon" or p.area <= 1e-4:
                continue
            p = orient2d(p, 1.0)
            ext = np.asarray(p.exterior.coords)[:-1]
            holes = [np.asarray(r.coords)[:-1] for r in p.interiors]
            pr = _prism(ext, holes, z0, (p0, n))
            if pr is None:
                continue
            mf = m3.Manifold(m3.Mesh64(vert_properties=np.ascontiguousarray(pr[0], dtype=np.float64),
                                       tri_verts=np.ascontiguousarray(pr[1], dtype=np.uint64)))
            if mf.status() == m3.Error.NoError and not mf.is_empty():
                parts.append(mf)
    if not parts:
        return None
    u = m3.Manifold.batch_boolean(parts, m3.OpType.Add).simplify(UNION_SIMPLIFY)
    if u.is_empty() or u.status() != m3.Error.NoError:
        return None
    pieces = u.decompose()
    if len(pieces) > 1:
        # separate pieces cannot be one Solid's shell: keep the main one when the others are
        # crumbs (under MIN_PIECE of the volume), else give up
        vols = np.array([p.volume() for p in pieces])
        if np.sort(vols)[-2] > MIN_PIECE * vols.sum():
            return None
        u = pieces[int(np.argmax(vols))]
    out = u.to_mesh64()
    P = np.asarray(out.vert_properties)[:, :3].astype(np.float64)
    T = np.asarray(out.tri_verts).astype(np.int64)
    # micro-edges where prisms met a hair apart: collapse them (2-manifold kept) so that no
    # two vertices are closer than the snap tolerance
    P, T, _ = collapse_short_edges(P, T, np.zeros(len(T), dtype=np.intp), COLLAPSE)
    P = P + origin
    if len(T) < 4:
        return None
    return merge_coplanar(triangles_to_mesh(P, T), angle_tol=1e-5, dist_tol=1e-3)
