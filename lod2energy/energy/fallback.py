"""Simpler envelopes for a zone EnergyPlus would not accept as written (the energy model's fallbacks).

Part of the energy model stage (:mod:`lod2energy.energy.model`), which tries them in
the order of :data:`FALLBACKS` before the IDF writer runs; the writer only writes the result.

A repaired LoD2 shell is a closed 2-manifold, but EnergyPlus's enclosure test merges points
within 1.27 cm per axis and inserts points within 1.27 cm of an edge
(:mod:`lod2energy.energy.enclosure`); a shell with many centimetre-scale features (alpha wraps
of buildings with crossing walls) can fail it however its pieces are cut. Such a zone is
written as a simpler envelope of the same building, least change first:

0. :func:`cleared_zone` - the same faces, with points that lie within EnergyPlus's
   tolerance of an edge or point they do not share moved 1.6 cm clear of it;
   :func:`separated_zone` - the same faces, with sheets that touch within EnergyPlus's
   tolerance pulled 4 cm apart (instead of the repair's 8 mm);
1. :func:`roof_zone` - the building as a 2.5D model (every roof plane kept, walls vertical,
   :func:`lod2energy.repair.roofs.roof_model`);
2. :func:`block_zone` - an LoD1 block: the footprint, simplified at 5 cm, extruded from the
   lowest point to the height that keeps the shell's volume (the area-weighted mean roof
   height when the shell has no positive volume); then the same with spikes narrower
   than 20 cm and 1 m cut off (morphological opening), then the footprint's convex hull.

U-values carry over per surface class (area-weighted mean of the zone's faces of that class).
"""
from __future__ import annotations

from dataclasses import replace
from functools import partial

import numpy as np
from shapely.geometry.polygon import orient

from lod2energy.config import DEFAULT
from lod2energy.energy.enclosure import eplus_merge
from lod2energy.energy.zones.shells import ZoneFace, ZoneShell, classify
from lod2energy.geometry.polygons import newell_normal, polygon_area3d
from lod2energy.geometry.snap import drop_repeats
from lod2energy.polymesh import Face, PolyMesh, signed_volume
from lod2energy.repair.footprint import footprint_polygon, roof_height
from lod2energy.repair.roofs import roof_model
from lod2energy.repair.unpinch import unpinch

#: Footprint simplification (m) of :func:`block_zone`: above EnergyPlus's 1.27 cm tolerance.
BLOCK_SIMPLIFY = 0.05
_SEMANTIC = {"roof": "RoofSurface", "wall": "WallSurface", "ground": "GroundSurface"}
# shapely is imported in the functions that use it: importing lod2energy stays cheap (issue 13)


def _mesh(zone: ZoneShell) -> PolyMesh:
    return PolyMesh(np.asarray(zone.vertices, dtype=np.float64),
                    tuple(Face(tuple(tuple(int(i) for i in r) for r in f.rings)) for f in zone.faces))


def _u_by_kind(zone: ZoneShell) -> dict[str, float]:
    num: dict[str, float] = {}
    den: dict[str, float] = {}
    for f in zone.faces:
        k = "ground" if f.kind == "floor" else f.kind
        a = polygon_area3d(zone.vertices[list(f.rings[0])])
        num[k] = num.get(k, 0.0) + a * f.u_value
        den[k] = den.get(k, 0.0) + a
    return {k: num[k] / den[k] for k in num if den[k] > 0}


def zone_from_mesh(zone: ZoneShell, m: PolyMesh, note: str) -> ZoneShell | None:
    """A zone with ``m``'s faces (local coordinates), classified by orientation and given
    the zone's U-value of their class; ``note`` is added to its warnings."""
    u = _u_by_kind(zone)
    fallback_u = float(np.mean(list(u.values()))) if u else 0.5
    faces = []
    for fi, f in enumerate(m.faces):
        pts = m.vertices[list(f.rings[0])]
        if len(pts) < 3 or polygon_area3d(pts) <= 1e-4:
            continue
        kind = classify(None, newell_normal(pts))
        faces.append(ZoneFace(tuple(tuple(int(i) for i in r) for r in f.rings), kind, _SEMANTIC[kind],
                              u.get(kind, fallback_u), fi))
    if len(faces) < 4:
        return None
    return ZoneShell(zone.building_id, zone.object_id, np.asarray(m.vertices, dtype=np.float64), tuple(faces),
                     zone.u_window, zone.wwr, tuple(zone.warnings) + (note,))


#: Points closer than this (m) to an edge they are not on, or (per axis) to another point,
#: are moved by :func:`cleared_zone` to :data:`CLEARANCE` from it.
NEAR_MISS = 0.0127
#: Distance (m) :func:`cleared_zone` leaves between a point and the edge or point it was
#: too close to.
CLEARANCE = 0.016


def _edges(zone: ZoneShell) -> np.ndarray:
    e = set()
    for f in zone.faces:
        for r in f.rings:
            for i in range(len(r)):
                a, b = int(r[i]), int(r[(i + 1) % len(r)])
                if a != b:
                    e.add((min(a, b), max(a, b)))
    return np.array(sorted(e), dtype=np.intp).reshape(-1, 2)


def cleared_zone(zone: ZoneShell, rounds: int = 3) -> ZoneShell | None:
    """The zone with its near misses pulled apart, or None when it has none.

    EnergyPlus inserts a point into any edge within 1.27 cm of it and merges points within
    1.27 cm per axis. A corner 7 mm from a wall's vertical edge it does not belong to (two
    LoD2 walls drawn a few millimetres apart) is then put on that edge, which ends up on
    four surfaces. Each such point moves straight away from the edge (or point) it is too
    close to, to :data:`CLEARANCE`; faces keep their vertices, so the shell stays closed.
    A point exactly on an edge (a true T-junction, which EnergyPlus handles) stays.
    """
    V = np.array(zone.vertices, dtype=np.float64)
    E = _edges(zone)
    if len(E) == 0:
        return None
    adj: dict[int, set[int]] = {}
    for a, b in E:
        adj.setdefault(int(a), set()).add(int(b))
        adj.setdefault(int(b), set()).add(int(a))
    used = sorted(adj)
    moved_any = False
    for _ in range(rounds):
        moved = False
        A, B = V[E[:, 0]], V[E[:, 1]]
        AB = B - A
        L2 = np.einsum("ij,ij->i", AB, AB)
        for i in used:
            p = V[i]
            t = np.einsum("ij,ij->i", p - A, AB) / np.where(L2 > 0, L2, 1.0)
            C = A + t[:, None] * AB
            d = np.linalg.norm(p - C, axis=1)
            near_a = np.all(np.abs(p - A) < NEAR_MISS, axis=1)
            near_b = np.all(np.abs(p - B) < NEAR_MISS, axis=1)
            hit = (L2 > 0) & (t > 0) & (t < 1) & (d < NEAR_MISS) & (d > 1e-6) & ~near_a & ~near_b
            hit &= (E[:, 0] != i) & (E[:, 1] != i)
            # points EnergyPlus would merge with this one although no edge joins them
            others = np.array([j for j in used if j != i and j not in adj[i]], dtype=np.intp)
            close = others[np.all(np.abs(V[others] - p) < NEAR_MISS, axis=1)] if len(others) else others
            if np.any(hit):
                k = int(np.argmin(np.where(hit, d, np.inf)))
                away, dist = p - C[k], d[k]
            elif len(close):
                q = V[close[np.argmin(np.linalg.norm(V[close] - p, axis=1))]]
                away, dist = p - q, float(np.linalg.norm(p - q))
                if dist <= 1e-9:
                    continue
            else:
                continue
            V[i] = p + away / dist * (CLEARANCE - dist)
            moved = moved_any = True
        if not moved:
            break
    if not moved_any:
        return None
    note = (f"{zone.object_id}: points closer than 1.27 cm to an edge or point they do not share moved "
            f"{CLEARANCE * 100:.1f} cm clear of it for EnergyPlus's enclosure test")
    return replace(zone, vertices=V, warnings=tuple(zone.warnings) + (note,))


#: How far (m) :func:`separated_zone` moves each copy of a pinch vertex into its own
#: material: copies end up about twice this apart, clear of EnergyPlus's 1.27 cm per-axis merge.
EPLUS_UNPINCH = 0.02


def separated_zone(zone: ZoneShell) -> ZoneShell | None:
    """The zone with sheets that EnergyPlus would join pulled apart, or None.

    The repair separates sheets that touch along an edge or at a point by 8 mm
    (:mod:`lod2energy.repair.unpinch`); EnergyPlus merges points within 1.27 cm per axis and
    joins them again (an edge on four surfaces). Here the zone's points are merged as
    EnergyPlus merges them and the sheets separated by :data:`EPLUS_UNPINCH` instead; faces
    and their classes stay, only the pinch points move.
    """
    V, idx = eplus_merge(zone.vertices)
    if len(V) == len(zone.vertices):
        return None
    kept, faces = [], []
    for f in zone.faces:
        rings = [tuple(drop_repeats([int(idx[i]) for i in r])) for r in f.rings]
        if len(set(rings[0])) < 3 or any(len(set(r)) < 3 for r in rings[1:]):
            return None
        kept.append(f)
        faces.append(Face(tuple(rings)))
    u = unpinch(PolyMesh(V, tuple(faces)), DEFAULT, offset=EPLUS_UNPINCH)
    if u is None:
        return None
    new = tuple(replace(f, rings=g.rings) for f, g in zip(kept, u.faces))
    note = (f"{zone.object_id}: sheets that touch within EnergyPlus's 1.27 cm tolerance separated by "
            f"{2 * EPLUS_UNPINCH * 100:.0f} cm")
    return replace(zone, vertices=np.asarray(u.vertices, dtype=np.float64), faces=new,
                   warnings=tuple(zone.warnings) + (note,))


def roof_zone(zone: ZoneShell) -> ZoneShell | None:
    """The zone as a 2.5D model (roof planes kept), or None when there is no valid one."""
    try:
        m = roof_model(_mesh(zone), "2.2", DEFAULT)
    except Exception:  # noqa: BLE001 - a failed reconstruction only means no candidate
        return None
    if m is None:
        return None
    return zone_from_mesh(zone, m, f"{zone.object_id}: written as a 2.5D model (roof planes kept, walls "
                                  "vertical): the repaired shell fails EnergyPlus's enclosure test")


def block_zone(zone: ZoneShell, simplify: float = BLOCK_SIMPLIFY, opening: float = 0.0,
               hull: bool = False) -> ZoneShell | None:
    """The zone as an LoD1 block, or None.

    The footprint is extruded from the lowest point to the height at which the block keeps
    the zone shell's volume (:func:`block_top`), so the zone volume EnergyPlus uses (air
    changes, the heat capacity of the air) is the building's.

    Parameters
    ----------
    simplify : float, m
        Douglas-Peucker tolerance of the footprint.
    opening : float, m
        Morphological opening of the footprint (parts narrower than twice this go).
    hull : bool
        Use the footprint's convex hull.
    """
    m = _mesh(zone)
    fp = footprint_polygon(m, simplify=simplify)
    if fp is None:
        return None
    z0, z1 = roof_height(m)
    if z1 - z0 <= 0.1:
        return None
    if opening > 0:
        # spikes and slits narrower than 2 x opening go (the footprint of an alpha wrap has some)
        fp = fp.buffer(-opening, join_style="mitre").buffer(opening, join_style="mitre")
        if fp.geom_type == "MultiPolygon":
            fp = max(fp.geoms, key=lambda g: g.area)
        if fp.geom_type != "Polygon" or fp.is_empty:
            return None
        fp = orient(fp.simplify(simplify, preserve_topology=True), 1.0)
    if hull:
        fp = orient(fp.convex_hull.simplify(simplify), 1.0)
    if fp.geom_type != "Polygon" or not fp.is_valid or fp.area <= 1e-2:
        return None
    z1 = block_top(m, z0, z1, float(fp.area))
    rings = [np.asarray(fp.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in fp.interiors]
    verts: list[tuple[float, float, float]] = []
    bottom, top, walls = [], [], []
    for R in rings:
        n = len(R)
        base = len(verts)
        verts.extend((float(x), float(y), z0) for x, y in R)
        verts.extend((float(x), float(y), z1) for x, y in R)
        b = [base + i for i in range(n)]
        t = [base + n + i for i in range(n)]
        bottom.append(tuple(reversed(b)))
        top.append(tuple(t))
        walls.extend(Face(((b[i], b[(i + 1) % n], t[(i + 1) % n], t[i]),)) for i in range(n))
    mesh = PolyMesh(np.asarray(verts), (Face(tuple(bottom)), Face(tuple(top))) + tuple(walls))
    what = "convex hull of the footprint" if hull else "footprint"
    return zone_from_mesh(zone, mesh, f"{zone.object_id}: written as an LoD1 block ({what} extruded to "
                                      f"{z1 - z0:.2f} m): the repaired shell fails EnergyPlus's enclosure test")


def block_top(m: PolyMesh, z0: float, mean_top: float, area: float) -> float:
    """Top (m) of an LoD1 block of footprint ``area`` (m2) from ``z0`` (m) that holds the
    volume of the closed shell ``m``: ``z0 + V / area``; ``mean_top`` (the area-weighted
    mean roof height) when the shell's volume is not positive or gives a block lower than
    10 cm.

    The mean roof height is not the height of the volume under the roof: each roof face
    counts with the mean of its vertex heights (not its centroid's), faces steeper than
    84 degrees and undersides not at all (on a 3DBAG house with
    31 roof faces, 6.335 m against 6.303 m: a block 0.51 % larger than the shell; the 5 cm
    footprint simplification adds 0.01 %).
    """
    vol = signed_volume(m)
    if not np.isfinite(vol) or vol <= 0 or vol / area <= 0.1:
        return mean_top
    return z0 + vol / area


#: Tried in this order by the energy model stage: least change first.
FALLBACKS = (cleared_zone, separated_zone, roof_zone, block_zone, partial(block_zone, opening=0.1),
             partial(block_zone, opening=0.5), partial(block_zone, hull=True))
