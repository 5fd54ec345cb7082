"""The ``roofs`` stage of the repair ladder: the input rebuilt as a 2.5D model of its roof faces.

Tried after ``refill`` and before the alpha shapes (:data:`lod2energy.repair.pipeline.STAGES`).
Every upward-facing face (roof, dormer, outer ceiling) is projected to XY and extruded from
the ground level up to its own plane (:func:`extrude_roofs`); the union of those prisms
(manifold3d) is the building as a 2.5D model: the input's roof shapes and heights are kept
exactly, only overhangs and anything below the ground level are lost. Reconstructed outlines
rarely meet exactly: with ``snap`` the prisms stand instead on the cells of a partition of the
outlines (:func:`roof_partition`: vertices and edges within ``snap`` shared, hairline gaps and
tiny holes closed), and a thin column fills each vertical line where two blocks touch only at
a corner (:func:`pinches`), so that the union is a valid shell once its vertices are snapped.
:func:`roof_model` makes the union valid and keeps it only when the input's vertices lie
close to it.
"""
from __future__ import annotations

import manifold3d as m3
import mapbox_earcut as earcut
import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient as orient2d

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import collapse_short_edges, snap_map
from lod2energy.polymesh import PolyMesh, face_area, face_normal, merge_coplanar, triangles_to_mesh, triangulate_mesh
from lod2energy.repair.accept import is_repaired
from lod2energy.repair.cleanup import cleanup, desliver
from lod2energy.repair.metrics import point_triangle_distance
from lod2energy.repair.orientation import orient
from lod2energy.repair.refill import close
from lod2energy.repair.unpinch import unpinch


#: Faces whose unit normal has a z component above this are roofs for :func:`extrude_roofs`.
UP_NZ = 0.05
#: Vertices of the union closer than this (m) are merged (sliver removal, manifold3d simplify).
UNION_SIMPLIFY = 1e-3
#: manifold3d simplify tolerance (m) for the union over a partition (its prisms meet exactly,
#: so only coplanar triangles need merging: a larger value folds thin walls into the roofs).
SNAP_SIMPLIFY = 1e-6
#: Edges of the union over a partition shorter than this (m) are collapsed: walls a few
#: millimetres high where two roof planes nearly meet over a shared edge, which the clean-up
#: (T-junctions within 5 mm) would otherwise zip into folds. Vertices move at most this far,
#: val3dity's planarity tolerance.
SNAP_COLLAPSE = 1e-2
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


#: Snap distance (m) of :func:`roof_partition`: roof outlines closer than this in plan are
#: made to share their vertices and edges (5 x val3dity's snap tolerance).
ROOF_SNAP = DEFAULT.roof_snap


#: Holes in the plan of the roofs up to this area (m2) are closed by :func:`roof_partition`
#: (gaps where walls cross, whose corners pinch the footprint); larger ones are courtyards.
MAX_HOLE = 0.1


def _roof_faces(m: PolyMesh, L: np.ndarray) -> list[tuple[object, np.ndarray, np.ndarray]]:
    """(shapely Polygon in plan, point on the plane (3,), unit normal (3,)) per upward face.

    ``L`` (n, 3) are the mesh's vertices in local coordinates (m).
    """

    out = []
    for f in m.faces:
        n = face_normal(L, f)
        if n[2] <= UP_NZ or face_area(L, f) <= 1e-4:
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
            if p.geom_type == "Polygon" and p.area > 1e-4:
                out.append((orient2d(p, 1.0), p0, n))
    return out


def roof_partition(polys: list, snap: float = ROOF_SNAP) -> list[tuple[object, list[int]]]:
    """The plan of the roof faces as cells that share their edges exactly.

    Vertices of the outlines closer than ``snap`` are merged (to their mean), every outline is
    snapped to the vertices and edges of the others within ``snap``, and the noded linework is
    polygonized. Each cell lists the faces over it (those containing a point inside it); a
    cell under no face that is thinner than ``snap`` on average (a gap where two outlines
    nearly met) lists the faces within ``snap`` of it; other uncovered cells (courtyards) are
    dropped, except holes of the plan up to :data:`MAX_HOLE` (they list the faces within
    ``snap``: the walls that crossed around them).

    Parameters
    ----------
    polys : list of shapely Polygon
        Outlines of the roof faces in plan (m).
    snap : float
        Snap distance, m.

    Returns
    -------
    list of (shapely Polygon, list of int)
        Cells (counter-clockwise exteriors) and the indices into ``polys`` of the faces over them.
    """

    rings = [[np.asarray(p.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in p.interiors]
             for p in polys]
    pts = np.vstack([r for rs in rings for r in rs])
    # merge vertices within snap (transitive clusters), each group to its mean
    root = snap_map(pts, snap)
    sums = np.zeros((len(pts), 2))
    np.add.at(sums, root, pts)
    cnt = np.bincount(root, minlength=len(pts)).astype(float)
    merged = sums[root] / cnt[root, None]
    snapped, k = [], 0
    for rs in rings:
        new = []
        for r in rs:
            new.append(merged[k:k + len(r)])
            k += len(r)
        try:
            p = Polygon(new[0], new[1:])
            if not p.is_valid:
                p = p.buffer(0)
        except Exception:  # noqa: BLE001
            p = Polygon()
        snapped.append(p)
    # vertices of one outline that lie near an edge of another are put on it
    allb = shapely.union_all([p.boundary for p in snapped if not p.is_empty])
    out = []
    for p in snapped:
        if p.is_empty:
            out.append(p)
            continue
        q = shapely.snap(p, allb, snap)
        if not q.is_valid:
            q = q.buffer(0)
        out.append(q)
    lines = shapely.union_all([p.boundary for p in out if not p.is_empty and p.area > 0])
    cells = list(shapely.polygonize([lines]).geoms)
    tree = shapely.STRtree(out)
    # the outline of the roofs with every hole filled: uncovered cells inside it are holes
    U = shapely.union_all([p for p in out if not p.is_empty])
    filled = shapely.union_all([Polygon(q.exterior) for q in getattr(U, "geoms", [U])
                                if q.geom_type == "Polygon"])
    res = []
    for c in cells:
        if c.area <= 1e-9:
            continue
        rp = c.representative_point()
        over = [int(i) for i in tree.query(rp, predicate="intersects")]
        if not over and (c.area < 0.5 * snap * c.length
                         or (c.area <= MAX_HOLE and filled.intersects(rp))):
            over = [int(i) for i in tree.query(c, predicate="dwithin", distance=snap)]
        if over:
            res.append((orient2d(c, 1.0), over))
    return res


def _manifold(pr):
    mf = m3.Manifold(m3.Mesh64(vert_properties=np.ascontiguousarray(pr[0], dtype=np.float64),
                               tri_verts=np.ascontiguousarray(pr[1], dtype=np.uint64)))
    return mf if mf.status() == m3.Error.NoError and not mf.is_empty() else None


def _prism_manifolds(p, z0: float, plane: tuple[np.ndarray, np.ndarray], split: bool = False) -> list:
    """manifold3d prisms over the shapely Polygon ``p`` from ``z0`` up to ``plane``.

    One prism, or none when it is not a closed 2-manifold (a ring that touches itself, a hole
    touching the outline). With ``split``, such a polygon is cut into its triangles and one
    prism stands on each (they share their edges exactly, so their union is the prism).
    """

    ext = np.asarray(p.exterior.coords)[:-1]
    holes = [np.asarray(r.coords)[:-1] for r in p.interiors]
    pr = _prism(ext, holes, z0, plane)
    if pr is None:
        return []
    mf = _manifold(pr)
    if mf is not None or not split:
        return [mf] if mf is not None else []
    rings = [ext] + holes
    pts = np.vstack(rings)
    ends = np.cumsum([len(r) for r in rings]).astype(np.uint32)
    tri = np.asarray(earcut.triangulate_float64(pts, ends), dtype=np.int64).reshape(-1, 3)
    out = []
    for t in tri:
        a = pts[t]
        if abs((a[1, 0] - a[0, 0]) * (a[2, 1] - a[0, 1]) - (a[1, 1] - a[0, 1]) * (a[2, 0] - a[0, 0])) < 1e-8:
            continue
        pr = _prism(a if _ccw(a) else a[::-1], [], z0, plane)
        mf = _manifold(pr) if pr is not None else None
        if mf is not None:
            out.append(mf)
    return out


def _ccw(a: np.ndarray) -> bool:
    x, y = a[:, 0], a[:, 1]
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y)) > 0


#: Half the side (m) of the square column :func:`extrude_roofs` stands at a pinch.
PINCH_COLUMN = 0.015


def pinches(P: np.ndarray, T: np.ndarray, grid: float = 1e-3) -> list[tuple[np.ndarray, tuple]]:
    """Vertical lines along which a 2.5D union touches itself (two blocks meeting at a corner).

    The union's triangles are manifold (manifold3d keeps touching blocks apart by
    duplicating their vertices), but once vertices are snapped, the stretch of a vertical
    line where more than two walls meet is a non-manifold edge (val3dity 303). On each
    vertical line (vertices on a ``grid`` in plan), the z intervals between the ends of the
    vertical edges are counted; where more than two wall triangles cover one, the line is a
    pinch.

    Parameters
    ----------
    P : (n, 3) float
        Vertices of the union (m).
    T : (t, 3) int
        Its triangles.
    grid : float
        Plan distance (m) under which vertices are on one vertical line.

    Returns
    -------
    list of (xy (2,) float, plane)
        Per pinch, its plan position and the plane (point (3,), unit normal (3,)) of the
        roof at the top of the pinched stretch: a column up to it fills the notch between
        the blocks.
    """
    T = np.asarray(T, dtype=np.int64)
    if len(T) == 0:
        return []
    key = np.round(P[:, :2] / grid).astype(np.int64)
    E = np.vstack([T[:, [0, 1]], T[:, [1, 2]], T[:, [2, 0]]])
    vert = np.all(key[E[:, 0]] == key[E[:, 1]], axis=1) & (np.abs(P[E[:, 0], 2] - P[E[:, 1], 2]) > grid)
    groups: dict[tuple, list[int]] = {}
    for k in np.flatnonzero(vert):
        groups.setdefault(tuple(key[E[k, 0]]), []).append(k)
    A = P[T[:, 1]] - P[T[:, 0]]
    B = P[T[:, 2]] - P[T[:, 0]]
    N = np.cross(A, B)
    N /= np.maximum(np.linalg.norm(N, axis=1), 1e-300)[:, None]
    out = []
    for g, ks in groups.items():
        if len(ks) < 3:
            continue
        lo = np.minimum(P[E[ks, 0], 2], P[E[ks, 1], 2])
        hi = np.maximum(P[E[ks, 0], 2], P[E[ks, 1], 2])
        zs = np.unique(np.concatenate([lo, hi]))
        mids = 0.5 * (zs[:-1] + zs[1:])
        cover = ((lo[None, :] < mids[:, None]) & (hi[None, :] > mids[:, None])).sum(axis=1)
        bad = np.flatnonzero(cover > 2)
        if len(bad) == 0:
            continue
        ztop = zs[bad.max() + 1]
        # the roof triangles at the top of the pinched stretch: the lowest plane there
        at = np.flatnonzero(np.all(key == np.array(g), axis=1) & (np.abs(P[:, 2] - ztop) <= grid))
        cand = [t for t in np.flatnonzero(np.isin(T, at).any(axis=1)) if N[t, 2] > UP_NZ]
        xy = P[at[0], :2] if len(at) else np.array(g, dtype=np.float64) * grid
        if cand:
            t = cand[0]
            plane = (P[T[t, 0]], N[t])
        else:
            plane = (np.array([xy[0], xy[1], ztop]), np.array([0.0, 0.0, 1.0]))
        out.append((xy, plane))
    return out


def extrude_roofs(m: PolyMesh, snap: float = 0.0) -> PolyMesh | None:
    """The union of prisms from the ground level up to each upward-facing face (2.5D model).

    Parameters
    ----------
    m : PolyMesh
    snap : float
        When > 0 (m), the roof outlines are first cut into cells that share their edges
        exactly (:func:`roof_partition`) and the prisms stand on those cells: prisms that met
        a hair apart then meet exactly, a column fills each pinch (:func:`pinches`) and
        edges under :data:`SNAP_COLLAPSE` are collapsed. 0 extrudes the outlines as they are.

    Returns
    -------
    PolyMesh or None
        Polygons (coplanar triangles of the union merged), or None when there is no roof or
        the union fails.
    """


    V = m.vertices
    used = sorted({i for f in m.faces for r in f.rings for i in r})
    if len(used) < 4:
        return None
    origin = V[used].mean(axis=0)
    L = V - origin
    z0 = ground_level(m) - origin[2]
    faces = _roof_faces(m, L)
    if not faces:
        return None
    if snap > 0:
        try:
            cells = roof_partition([p for p, _, _ in faces], snap)
        except Exception:  # noqa: BLE001 - GEOS topology errors on degenerate outlines
            return None
        items = [(c, faces[i][1], faces[i][2]) for c, over in cells for i in over]
    else:
        items = faces
    parts = []
    for p, p0, n in items:
        parts.extend(_prism_manifolds(p, z0, (p0, n), split=snap > 0))
    if not parts:
        return None
    u = m3.Manifold.batch_boolean(parts, m3.OpType.Add)
    u = u.simplify(SNAP_SIMPLIFY if snap > 0 else UNION_SIMPLIFY)
    if u.is_empty() or u.status() != m3.Error.NoError:
        return None
    if snap > 0:
        out = u.to_mesh64()
        cols = []
        for xy, plane in pinches(np.asarray(out.vert_properties)[:, :3], np.asarray(out.tri_verts)):
            sq = xy + PINCH_COLUMN * np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
            pr = _prism(sq, [], z0, plane)
            mf = _manifold(pr) if pr is not None else None
            if mf is not None:
                cols.append(mf)
        if cols:
            u = m3.Manifold.batch_boolean([u] + cols, m3.OpType.Add)
            u = u.simplify(SNAP_SIMPLIFY)
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
    # (over a partition: up to SNAP_COLLAPSE)
    P, T, _ = collapse_short_edges(P, T, np.zeros(len(T), dtype=np.intp), max(COLLAPSE, SNAP_COLLAPSE if snap > 0 else 0.0))
    P = P + origin
    if len(T) < 4:
        return None
    return merge_coplanar(triangles_to_mesh(P, T), angle_tol=1e-5, dist_tol=1e-3)


#: A 2.5D roof model is kept only when the input's vertices lie this close to it on average
#: (m): beyond that the building is not 2.5D (overhangs, parts below ground) and the alpha
#: shapes decide.
ROOF_MODEL_MAX_DISPLACEMENT = DEFAULT.roof_max_displacement


def roof_model(m: PolyMesh, lod, tol: Tolerances) -> PolyMesh | None:
    """The input rebuilt as a 2.5D model (:func:`extrude_roofs`), made valid.

    The union of roof prisms is cleaned, oriented, separated where prisms only touch along an
    edge (:func:`unpinch`) and rid of union slivers (:func:`desliver`). When the prisms over
    the outlines as drawn give no valid result (outlines a hair apart leave micro-edges and
    separate pieces, a ring touching itself gives no prism), the same is tried with prisms
    over the snapped partition of the outlines (``extrude_roofs(m, ROOF_SNAP)``: exact shared
    edges, pinched corners filled). Returns None when no valid result is found or the input's
    vertices are on average more than :data:`ROOF_MODEL_MAX_DISPLACEMENT` from it.
    """
    def good(x):
        return x is not None and is_repaired(x, lod, tol)

    def made_valid(snap):
        r = extrude_roofs(m, snap)
        if r is None:
            return None
        r = orient(cleanup(r, tol))
        if not good(r):
            u = unpinch(r, tol)
            if u is not None:
                u = close(cleanup(u, tol), tol)
                r = u if good(u) else r
        if not good(r):
            r = desliver(r, tol, good)
        return r
    # the outlines as they are first; when that union cannot be made valid, the outlines
    # snapped into a partition (prisms meeting exactly, polygons that pinch split)
    r = made_valid(0.0)
    if r is None:
        r = made_valid(tol.roof_snap)
    if r is None:
        return None
    tris, _ = triangulate_mesh(m)
    rt, _ = triangulate_mesh(r)
    pts = m.vertices[np.unique(tris)]
    if len(rt) == 0 or point_triangle_distance(pts, r.vertices, rt).mean() > tol.roof_max_displacement:
        return None
    return r
