"""Stages 5 and 6 of the repair ladder: the building's 2D footprint extruded to its heights, its convex hull.

The 2.5D model with every roof plane kept is the earlier ``roofs`` stage
(:mod:`lod2energy.repair.roofs`). Here (:func:`extrude_footprint`): the footprint is the union of the faces' XY projections
(walls vanish); when that is not one polygon, the 2D alpha shape (``shapely.concave_hull``) of
all the points is used instead. The prism goes from the lowest point to the area-weighted
mean height of the upward-facing faces (the roof), so that its volume approximates the input's.
:func:`convex_hull` is the last resort; its coplanar triangles are merged back into convex
polygons so the face count stays low.
"""
from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry import MultiPoint, Polygon

from lod2energy.polymesh import Face, PolyMesh, face_area, face_normal, merge_coplanar, triangles_to_mesh

# scipy (0.4 s to import) is imported where it is used: validation never needs it


def footprint_polygon(m: PolyMesh, simplify: float = 0.01):
    """The shapely Polygon of the footprint, or None."""
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


def convex_hull(m: PolyMesh) -> PolyMesh | None:
    """Outward convex hull of the vertices used by ``m`` (None if they span no volume)."""
    used = np.unique([i for f in m.faces for r in f.rings for i in r])
    if len(used) < 4:
        return None
    from scipy.spatial import ConvexHull, QhullError
    P = m.vertices[used]
    try:
        h = ConvexHull(P)
    except (QhullError, ValueError):
        return None
    tris = h.simplices.copy()
    # Qhull does not orient simplices: make each one face away from the centroid
    c = P[h.vertices].mean(axis=0)
    T = P[tris]
    n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    flip = np.einsum("ij,ij->i", n, T[:, 0] - c) < 0
    tris[flip] = tris[flip][:, ::-1]
    keep = np.unique(tris)
    lut = np.full(len(P), -1)
    lut[keep] = np.arange(len(keep))
    hm = triangles_to_mesh(P[keep], lut[tris])
    return merge_coplanar(hm, angle_tol=1e-9, dist_tol=1e-6)
