"""The CFD case's surfaces: buildings united into watertight bodies with roof/wall patches, and the ground.

Method, per building of the region (already validated, repaired and labelled):

1. its solids (Building and BuildingParts) are triangulated by the STL exporter's functions
   (:func:`lod2energy.energy.zones.shells.zone_shells`, ``stl._zone_mesh``), every triangle keeping
   its class (roof, wall, ground, floor);
2. every vertex of its ground (bottom) faces is moved down to ``ground level - SINK`` so that
   the body goes through the domain floor: a building standing a little above the region's
   lowest ground (3DBAG bases differ by decimetres) does not float, and the floor cuts it
   cleanly; a raised or cantilevered part is filled down to the ground (a CFD simplification);
3. gaps narrower than ``min_gap`` are closed by a morphological closing of the footprints (a
   mitred offset by ``+min_gap/2`` then ``-min_gap/2``, shapely): each piece the closing adds is
   extruded from below the ground to the lowest eave (lowest roof vertex) of the buildings
   next to it and joins the union as a block of wall with a roof on top;
4. all bodies are united by manifold3d (``stl.merge_meshes``): touching buildings merge, the
   result is a set of closed, outward, 2-manifold bodies, each triangle still with its class.

The STL has named solids ``roof``, ``wall`` (outer floor surfaces count as wall) and ``base``
(the sunk bottom, outside the fluid), which snappyHexMesh turns into the patches
``buildings_roof``, ``buildings_wall``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import manifold3d as m3
import numpy as np
from shapely import STRtree, polygons, union_all
from shapely.geometry import Polygon

from lod2energy.energy.zones.shells import zone_shells
from lod2energy.exporters.stl.writer import ZONE_WELD_TOL, _closed_by_position, _zone_mesh, ascii_solids, merge_meshes

#: Depth (m) below the ground level the building bottoms are sunk to.
SINK = 1.0
#: Output patch (solid) names; index = code in the united mesh.
SOLIDS = ("roof", "wall", "base")
#: Class of the STL exporter (stl.PATCHES order: roof, wall, ground, floor) -> SOLIDS index.
_FROM_STL = np.array([0, 1, 2, 1])


@dataclass(frozen=True)
class BuildingBody:
    """One building triangulated (local coordinates, before the union).

    Parameters
    ----------
    id : str
    meshes : tuple of (vertices (n, 3), triangles (t, 3), codes (t,))
        One closed mesh per solid; codes index :data:`SOLIDS`.
    footprint : shapely Polygon or MultiPolygon
        Plan projection of the building.
    base : float, m
        Lowest vertex z (before sinking).
    top : float, m
        Highest vertex z.
    eave : float, m
        Lowest roof vertex z (``top`` without roof faces).
    """
    id: str
    meshes: tuple
    footprint: object
    base: float
    top: float
    eave: float


@dataclass(frozen=True)
class UnitedSurface:
    """The united buildings.

    Parameters
    ----------
    vertices : (n, 3) float, m
    triangles : (t, 3) int
    codes : (t,) int
        Index into :data:`SOLIDS`.
    bodies : int
        Connected closed bodies after the union.
    volume_above_ground : float, m3
        Volume of the union above the ground level (what the mesh must carve out).
    gap_fills : int
        Blocks added to close gaps narrower than ``min_gap``.
    gap_fill_area : float, m2
    warnings : tuple of str
    """
    vertices: np.ndarray
    triangles: np.ndarray
    codes: np.ndarray
    bodies: int
    volume_above_ground: float
    gap_fills: int = 0
    gap_fill_area: float = 0.0
    warnings: tuple[str, ...] = field(default_factory=tuple)


def _to_manifold(v: np.ndarray, t: np.ndarray):
    return m3.Manifold(m3.Mesh64(vert_properties=np.ascontiguousarray(v, dtype=np.float64),
                                 tri_verts=np.ascontiguousarray(t, dtype=np.uint64)))


def _plan_shape(v: np.ndarray, t: np.ndarray):
    """Union of the triangles' plan projections (shapely)."""
    P = v[t][:, :, :2]
    a = 0.5 * np.abs((P[:, 1, 0] - P[:, 0, 0]) * (P[:, 2, 1] - P[:, 0, 1])
                     - (P[:, 2, 0] - P[:, 0, 0]) * (P[:, 1, 1] - P[:, 0, 1]))
    P = P[a > 1e-8]
    return union_all(polygons(P)).buffer(0) if len(P) else None


def building_body(b, origin: np.ndarray, lod: str | None = None) -> BuildingBody:
    """Triangulate one building into closed meshes (local coordinates ``vertices - origin``).

    Raises
    ------
    ValueError
        The building has no solid, or one of its solids is not a closed 2-manifold.
    """
    zs = zone_shells(b, origin, lod, weld_tol=ZONE_WELD_TOL)
    ms = [_zone_mesh(z) for z in zs]
    if not all(_closed_by_position(v, t) for v, t, _ in ms):
        zs = zone_shells(b, origin, lod)
        ms = [_zone_mesh(z) for z in zs]
    ms = [(v, t, _FROM_STL[c]) for v, t, c in ms if len(t)]
    if not ms:
        raise ValueError("no solid geometry")
    for v, t, _ in ms:
        st = _to_manifold(v, t).status()
        if st != m3.Error.NoError:
            raise ValueError(f"a solid is not a closed 2-manifold ({st.name})")
    allv = np.concatenate([v[np.unique(t)] for v, t, _ in ms])
    roofz = [v[np.unique(t[c == 0])][:, 2] for v, t, c in ms if (c == 0).any()]
    top = float(allv[:, 2].max())
    eave = float(min(r.min() for r in roofz)) if roofz else top
    fp = union_all([s for s in (_plan_shape(v, t) for v, t, _ in ms) if s is not None])
    return BuildingBody(b.id, tuple(ms), fp, float(allv[:, 2].min()), top, eave)


def sink(mesh: tuple, floor: float) -> tuple:
    """``mesh`` with the vertices of its base (bottom) triangles moved down to ``floor`` (m)."""
    v, t, c = mesh
    bottom = np.unique(t[c == 2])
    if len(bottom) == 0:
        return mesh
    v = v.copy()
    v[bottom, 2] = np.minimum(v[bottom, 2], floor)
    return v, t, c


def gap_fills(bodies: list[BuildingBody], min_gap: float, floor: float
              ) -> tuple[list[tuple], float]:
    """Blocks closing the gaps narrower than ``min_gap`` (m) between / within footprints.

    Returns
    -------
    (list of (vertices, triangles, codes) meshes, total plan area m2)
    """
    if min_gap <= 0 or not bodies:
        return [], 0.0

    fps = [bd.footprint for bd in bodies]
    union = union_all(fps)
    closed = union.buffer(min_gap / 2, join_style="mitre", mitre_limit=4.0).buffer(
        -min_gap / 2, join_style="mitre", mitre_limit=4.0)
    extra = closed.difference(union)
    pieces = list(extra.geoms) if hasattr(extra, "geoms") else [extra]
    tree = STRtree(fps)
    out, area = [], 0.0
    for p in pieces:
        if not isinstance(p, Polygon) or p.area < max(0.05 * min_gap ** 2, 0.01):
            continue
        # ignore slivers the offsets leave along straight edges
        if p.buffer(-0.02).is_empty:
            continue
        near = tree.query(p, predicate="dwithin", distance=0.05 + 1e-6)
        if len(near) == 0:
            continue
        height = min(bodies[i].eave for i in near)
        grown = p.buffer(0.05, join_style="mitre")
        grown = grown.intersection(closed.buffer(0.05, join_style="mitre"))
        polys = [grown] if isinstance(grown, Polygon) else [g for g in getattr(grown, "geoms", []) if isinstance(g, Polygon)]
        for g in polys:
            if g.area <= 0 or height - floor <= 0.05:
                continue
            rings = [np.asarray(g.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in g.interiors]
            cs = m3.CrossSection([np.ascontiguousarray(r, dtype=np.float64) for r in rings], m3.FillRule.EvenOdd)
            solid = m3.Manifold.extrude(cs, float(height - floor)).translate((0.0, 0.0, float(floor)))
            mesh = solid.to_mesh64()
            v = np.asarray(mesh.vert_properties)[:, :3].astype(np.float64)
            t = np.asarray(mesh.tri_verts).astype(np.intp)
            if len(t) == 0:
                continue
            n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
            nz = n[:, 2] / np.maximum(np.linalg.norm(n, axis=1), 1e-30)
            c = np.where(nz > 0.5, 0, np.where(nz < -0.5, 2, 1))
            out.append((v, t, c))
            area += g.area
    return out, float(area)


def unite(bodies: list[BuildingBody], ground: float, min_gap: float = 0.0,
          sink_to: float | None = None) -> UnitedSurface:
    """Sink, close gaps and unite building bodies into watertight surfaces.

    Parameters
    ----------
    bodies : list of BuildingBody
        Local coordinates.
    ground : float, m
        Ground level (domain floor), local z.
    min_gap : float, m
        Gaps narrower than this are closed (0: none).
    sink_to : float, optional, m
        Level the bottoms are moved down to (default ``ground - SINK``).

    Raises
    ------
    ValueError
        The union is not a closed 2-manifold.
    """
    floor = ground - SINK if sink_to is None else float(sink_to)
    meshes = [sink(m, floor) for bd in bodies for m in bd.meshes]
    fills, fill_area = gap_fills(bodies, min_gap, floor)
    v, t, c, warnings = merge_meshes(meshes + fills, union=True)
    if any("not merged" in w for w in warnings):
        raise ValueError("; ".join(warnings))
    mf = _to_manifold(v, t)
    if mf.status() != m3.Error.NoError:
        raise ValueError(f"the united surface is not a closed 2-manifold ({mf.status().name})")
    above = mf.trim_by_plane((0.0, 0.0, 1.0), float(ground))
    nbodies = len(mf.decompose())
    return UnitedSurface(v, t.astype(np.intp), np.asarray(c, dtype=np.intp), nbodies, float(above.volume()),
                         len(fills), fill_area, tuple(warnings))


def stl_text(v: np.ndarray, t: np.ndarray, codes: np.ndarray, names: tuple[str, ...]) -> str:
    """ASCII STL with one ``solid <name>`` per code present (the STL exporter's format)."""
    return "".join(ascii_solids(v, t, codes, names))


def flat_ground(corners: np.ndarray, margin: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Two triangles covering the domain floor (corners ``(8, 3)`` in blockMesh order), upward."""
    v = np.asarray(corners, dtype=np.float64)[:4].copy()
    if margin:
        c = v[:, :2].mean(axis=0)
        d = v[:, :2] - c
        v[:, :2] = c + d * (1 + margin / np.linalg.norm(d, axis=1))[:, None]
    return v, np.array([[0, 1, 2], [0, 2, 3]])


def smallest_feature(bodies: list[BuildingBody], ground: float) -> float:
    """Smallest building dimension (m): the least of every building's height above ``ground``
    and the short side of its footprint's minimum rotated rectangle."""
    best = np.inf
    for bd in bodies:
        best = min(best, bd.top - max(ground, bd.base) if bd.top > ground else np.inf)
        fp = bd.footprint
        if fp is None or fp.is_empty:
            continue
        r = np.asarray(fp.minimum_rotated_rectangle.exterior.coords)
        if len(r) >= 4:
            e = np.linalg.norm(np.diff(r[:3], axis=0), axis=1)
            best = min(best, float(e.min()))
    return float(best)
