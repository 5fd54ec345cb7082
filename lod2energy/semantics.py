"""Semantic labels of envelope surfaces: keep, transfer after repair, or infer by rules.

Every surface of a building's energy geometries gets its own entry in
``Geometry.semantic_surfaces`` (one entry per surface, so per-surface values such as a
U-value fit), typed RoofSurface, WallSurface, GroundSurface or ClosureSurface.

Rules (the method's; thresholds in :class:`LabelRules`), per energy geometry with
``z_min``/``z_max`` its lowest/highest vertex, ``z_c`` a face's area centroid height,
``n_z`` the vertical component of its unit outward normal and
``h_rel = (z_c - z_min) / (z_max - z_min)``:

1. GroundSurface if ``z_c - z_min <= 0.05 m``;
2. RoofSurface if ``n_z >= 0.70``, or ``n_z >= 0.30`` and ``h_rel >= 0.65``;
3. OuterFloorSurface if ``n_z <= -0.70`` (an overhang's underside, a soffit, a floor over a
   passage: an exterior floor);
4. WallSurface otherwise.

A surface facing down (``n_z < -0.17``, :attr:`LabelRules.check_facing_nz`) is never a roof:
an input RoofSurface / OuterCeilingSurface facing down is labelled OuterFloorSurface (source
``"facing"``, the input's type kept as ``"inputType"``).

Where labels come from (recorded per surface as ``"labelSource"``):

- ``"input"``: the surface carries a label from the input (kept as is; for repaired
  buildings this is a face the repair derived from an input face);
- ``"transfer"``: a face the repair created takes the label of the nearest face of the
  input building whose normal is compatible;
- ``"closure"``: an unlabelled face lying on a face of another part of the same building,
  with opposite normal (a virtual boundary between parts): ClosureSurface;
- ``"rule"``: the rules above;
- ``"facing"``: an input roof facing down, relabelled OuterFloorSurface.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Iterable, Mapping

import numpy as np
from shapely.geometry import Point, Polygon
from shapely.validation import make_valid

from lod2energy import cache
from lod2energy.geometry import cross_rows, newell_normal, plane_basis
from lod2energy.model import BUILDING_TYPES, Building, Geometry, Shell, Solid, Surface, frozen_mapping
from lod2energy.validate.codes import Defect

ROOF, WALL, GROUND, CLOSURE = "RoofSurface", "WallSurface", "GroundSurface", "ClosureSurface"
OUTER_CEILING, OUTER_FLOOR = "OuterCeilingSurface", "OuterFloorSurface"
#: LoD3 openings: input labels kept as such; they close the envelope through their wall's hole
#: and become real windows / doors in the IDF (``exporters.energyplus.openings.split_openings``).
WINDOW, DOOR = "Window", "Door"
OPENING_TYPES = (WINDOW, DOOR)
ENVELOPE_TYPES = (ROOF, WALL, GROUND, CLOSURE, OUTER_CEILING, OUTER_FLOOR) + OPENING_TYPES


@dataclass(frozen=True)
class LabelRules:
    """Thresholds of the labelling rules and of the plausibility checks.

    Parameters
    ----------
    ground_dz : float, m
        A face whose centroid is at most this far above the geometry's lowest point is
        GroundSurface.
    roof_nz : float
        A face whose unit normal has ``n_z`` at or above this is RoofSurface.
    roof_nz_high : float
        ... or ``n_z`` at or above this and ``h_rel`` at or above ``roof_hrel``.
    roof_hrel : float
        Relative height (0 at the lowest point, 1 at the highest) for ``roof_nz_high``.
    floor_nz : float
        A face above the ground whose unit normal has ``n_z`` at or below this is
        OuterFloorSurface.
    transfer_normal_cos : float
        After repair, a new face takes the label of an input face only if the cosine of
        the angle between their normals is at least this (0.866 = 30 degrees).
    transfer_max_dist : float, m
        ... and only if the input face is at most this far away (default: no limit, as the
        method states it; a finite value sends far-away new faces to the rules).
    closure_between_parts : bool
        Label unlabelled faces lying on another part's face (opposite normals) as
        ClosureSurface.
    closure_plane_tol : float, m
        Largest plane offset of two faces that close each other.
    closure_overlap : float
        Smallest fraction of a face's area covered by the other part's face.
    check_facing_nz : float
        Plausibility: a RoofSurface with ``n_z`` below ``-check_facing_nz`` faces down
        (1101, and :func:`label_building` labels it OuterFloorSurface); a GroundSurface /
        OuterFloorSurface with ``n_z`` above it faces up (1104).
    check_ground_hrel : float
        Plausibility: a GroundSurface whose centroid has ``h_rel`` above this, and more
        than ``check_min_height`` above the lowest point, is not at the bottom (1102).
    check_min_height : float, m
        See ``check_ground_hrel``; also the margin by which a wall must rise above the
        highest roof point to be reported (1103).
    """

    ground_dz: float = 0.05
    roof_nz: float = 0.70
    roof_nz_high: float = 0.30
    roof_hrel: float = 0.65
    floor_nz: float = -0.70
    transfer_normal_cos: float = 0.866
    transfer_max_dist: float = math.inf
    closure_between_parts: bool = True
    closure_plane_tol: float = 0.01
    closure_overlap: float = 0.5
    check_facing_nz: float = 0.17
    check_ground_hrel: float = 0.5
    check_min_height: float = 0.5


DEFAULT_RULES = LabelRules()


def envelope_objects(b: Building, lod: str | None = None) -> list:
    """The geometries that make the thermal envelope: ``(object, geom_index, geometry)``.

    :meth:`Building.envelope` restricted to Building / BuildingPart objects (installations
    such as balconies or chimneys are neither labelled nor given U-values).
    """
    return [e for e in b.envelope(lod) if e[0].type in BUILDING_TYPES]


# ----------------------------------------------------------------------------- face geometry

def _ring_centroid(p: np.ndarray, n_hat: np.ndarray) -> tuple[float, np.ndarray]:
    """Signed area (along ``n_hat``) and area centroid of a planar ring (fan triangulation)."""
    if len(p) < 3:
        return 0.0, p.mean(axis=0) if len(p) else np.zeros(3)
    a, b, c = p[0], p[1:-1], p[2:]
    w = 0.5 * cross_rows(b - a, c - a) @ n_hat
    tot = w.sum()
    cent = (a + b + c) / 3.0
    if abs(tot) < 1e-15:
        return 0.0, p.mean(axis=0)
    return float(tot), (w[:, None] * cent).sum(axis=0) / tot


def face_metrics(vertices: np.ndarray, surface: Surface) -> tuple[float, np.ndarray, np.ndarray]:
    """Area, unit normal and area centroid of one (planar) polygon with holes.

    A pure function of the polygon's ring coordinates: the same polygon is measured by the
    labelling, the U-value volume and the acceptance check, so the answers are kept in a
    bounded cache keyed by the coordinates themselves (their bytes, dtype, shape and strides,
    ring by ring), never by the identity of ``vertices`` (:mod:`lod2energy.cache`).

    Parameters
    ----------
    vertices : (n, 3) float
        Building vertices, m.
    surface : Surface
        Outer ring counter-clockwise seen from outside; holes in any orientation.

    Returns
    -------
    area : float, m2
    normal : (3,) float
        Unit normal from the outer ring (zeros for a degenerate face); a new array each call.
    centroid : (3,) float, m
        Area centroid (holes subtracted); a new array each call.
    """
    rings = [vertices[r] for r in surface.rings]
    key = tuple((p.dtype.str, p.shape, p.strides, p.tobytes()) for p in rings)
    area, n_hat, centroid = cache.remember(FACE_METRICS, key, lambda: _face_metrics(rings), KEPT_FACES)
    return area, n_hat.copy(), centroid.copy()


#: Polygons whose metrics :func:`face_metrics` keeps (:mod:`lod2energy.cache`, table ``FACE_METRICS``).
KEPT_FACES = 8192
FACE_METRICS = "semantics.face-metrics"


def _face_metrics(rings: list[np.ndarray]) -> tuple[float, np.ndarray, np.ndarray]:
    """:func:`face_metrics` of a polygon given as its rings' coordinates ``[(k, 3) float, ...]``."""
    outer = rings[0]
    origin = outer.mean(axis=0) if len(outer) else np.zeros(3)
    vec = 0.5 * newell_normal(outer) if len(outer) >= 3 else np.zeros(3)
    outer = outer - origin
    norm = math.sqrt(float(vec.dot(vec)))  # np.linalg.norm of a (3,) float64 vector, the same bits
    if norm < 1e-15:
        return 0.0, np.zeros(3), origin
    n_hat = vec / norm
    a0, c0 = _ring_centroid(outer, n_hat)
    area, moment = abs(a0), abs(a0) * c0
    for r in rings[1:]:
        p = r - origin
        ai, ci = _ring_centroid(p, n_hat)
        area -= abs(ai)
        moment = moment - abs(ai) * ci
    if area <= 1e-15:
        return 0.0, n_hat, origin + c0
    return float(area), n_hat, origin + moment / area


@dataclass(frozen=True)
class FaceTable:
    """Per-face metrics of one geometry, in ``Geometry.iter_surfaces`` order.

    Attributes
    ----------
    keys : list of (solid, shell, face) int tuples, length N
    area : (N,) float, m2
    normal : (N, 3) float, unit
    centroid : (N, 3) float, m
    z_min, z_max : float, m
        Lowest / highest vertex of the geometry.
    """

    keys: list
    surfaces: list
    area: np.ndarray
    normal: np.ndarray
    centroid: np.ndarray
    z_min: float
    z_max: float

    @property
    def h_rel(self) -> np.ndarray:
        h = self.z_max - self.z_min
        if h <= 1e-9:
            return np.zeros(len(self.area))
        return (self.centroid[:, 2] - self.z_min) / h


def face_table(vertices: np.ndarray, g: Geometry) -> FaceTable:
    """Metrics of every surface of ``g`` (see :class:`FaceTable`)."""
    keys, surfs, areas, normals, cents, used = [], [], [], [], [], []
    for si, hi, fi, s in g.iter_surfaces():
        a, n, c = face_metrics(vertices, s)
        keys.append((si, hi, fi))
        surfs.append(s)
        areas.append(a)
        normals.append(n)
        cents.append(c)
        used.extend(int(i) for r in s.rings for i in r)
    if used:
        z = vertices[np.unique(np.asarray(used, dtype=np.intp)), 2]
        zmin, zmax = float(z.min()), float(z.max())
    else:
        zmin = zmax = 0.0
    return FaceTable(keys, surfs, np.asarray(areas, dtype=float).reshape(-1),
                     np.asarray(normals, dtype=float).reshape(-1, 3),
                     np.asarray(cents, dtype=float).reshape(-1, 3), zmin, zmax)


# ----------------------------------------------------------------------------- rules

def rule_label(nz: float, dz: float, h_rel: float, rules: LabelRules = DEFAULT_RULES) -> str:
    """Label of one face by the rules alone.

    Parameters
    ----------
    nz : float
        Vertical component of the unit outward normal.
    dz : float, m
        Height of the face's centroid above the geometry's lowest point.
    h_rel : float
        Relative height of the centroid (0 bottom, 1 top).
    """
    if dz <= rules.ground_dz:
        return GROUND
    if nz >= rules.roof_nz or (nz >= rules.roof_nz_high and h_rel >= rules.roof_hrel):
        return ROOF
    if nz <= rules.floor_nz:
        return OUTER_FLOOR
    return WALL


def rule_labels(t: FaceTable, rules: LabelRules = DEFAULT_RULES) -> list[str]:
    """Rule labels of every face of a :class:`FaceTable`."""
    hr = t.h_rel
    return [rule_label(float(t.normal[i, 2]), float(t.centroid[i, 2] - t.z_min), float(hr[i]), rules)
            for i in range(len(t.area))]


# ----------------------------------------------------------------------------- helpers

def _polygon2d(vertices: np.ndarray, s: Surface, origin: np.ndarray, u: np.ndarray, v: np.ndarray):

    rings = [np.c_[(vertices[r] - origin) @ u, (vertices[r] - origin) @ v] for r in s.rings if len(r) >= 3]
    if not rings:
        return None
    try:
        p = Polygon(rings[0], rings[1:])
        if not p.is_valid:
            p = make_valid(p)
        return p
    except Exception:  # degenerate rings: shapely refuses them
        return None


def _entry(base: Mapping[str, Any] | None, stype: str, source: str) -> Mapping[str, Any]:
    d = {k: v for k, v in (base or {}).items() if k not in ("parent", "children")}
    d["type"] = stype
    d["labelSource"] = source
    return frozen_mapping(d)


def _rebuild(g: Geometry, sem_by_key: dict) -> Geometry:
    """Copy of ``g`` whose surfaces point at ``sem_by_key[(solid, shell, face)]``."""
    solids = tuple(
        Solid(tuple(Shell(tuple(Surface(s.rings, sem_by_key[(si, hi, fi)])
                                for fi, s in enumerate(sh.surfaces)))
                    for hi, sh in enumerate(so.shells)))
        for si, so in enumerate(g.solids))
    return replace(g, solids=solids)


def _known_type(g: Geometry, s: Surface) -> str | None:
    t = g.semantic_type(s)
    return t if isinstance(t, str) and t else None


class _SourceFaces:
    """Labelled faces of the input building, for label transfer after repair."""

    def __init__(self, source: Building, lod: str | None):
        self.vertices = source.vertices
        self.items = []  # (type, entry, normal, centroid, polygon-data)
        for o, gi, g in envelope_objects(source, lod):
            t = face_table(source.vertices, g)
            # a solid oriented inwards (a defect the repair fixes) has its normals flipped:
            # compare orientations with the repaired faces as if it were outward (surface sets
            # have no inside: their orientation is taken as given)
            origin = t.centroid.mean(axis=0) if len(t.area) else np.zeros(3)
            signed_volume = float(np.einsum("ij,ij->", t.centroid - origin, t.normal * t.area[:, None])) / 3
            if g.is_volumetric and signed_volume < 0:
                t = replace(t, normal=-t.normal)
            for i, s in enumerate(t.surfaces):
                st = _known_type(g, s)
                if st is None or t.area[i] <= 0:
                    continue
                self.items.append((st, g.semantic_surfaces[s.semantic], t.normal[i], t.centroid[i], s))
        self.normals = np.array([it[2] for it in self.items]).reshape(-1, 3)
        self.centroids = np.array([it[3] for it in self.items]).reshape(-1, 3)
        # radius of each face around its centroid: |p - c| - radius bounds the distance below
        self.radii = np.array([float(np.linalg.norm(self.vertices[it[4].outer] - it[3], axis=1).max())
                               if len(it[4].outer) else 0.0 for it in self.items])
        self._poly: dict[int, Any] = {}

    def _distance(self, j: int, point: np.ndarray) -> float:
        st, entry, n, c, s = self.items[j]
        if j not in self._poly:
            u, v = plane_basis(n)
            self._poly[j] = (u, v, _polygon2d(self.vertices, s, c, u, v))
        u, v, poly = self._poly[j]
        d = point - c
        off = float(d @ n)
        if poly is None or poly.is_empty:
            return float(np.linalg.norm(d))
        din = poly.distance(Point(float(d @ u), float(d @ v)))
        return math.hypot(din, off)

    def nearest(self, normal: np.ndarray, point: np.ndarray, rules: LabelRules):
        if not self.items:
            return None
        ok = np.nonzero(self.normals @ normal >= rules.transfer_normal_cos)[0]
        if not len(ok):
            return None
        lower = np.maximum(np.linalg.norm(self.centroids[ok] - point, axis=1) - self.radii[ok], 0.0)
        order = np.argsort(lower, kind="stable")
        best, best_d = None, rules.transfer_max_dist
        for k in order:
            if lower[k] > best_d:
                break
            j = int(ok[k])
            d = self._distance(j, point)
            if d <= best_d:
                best, best_d = j, d
        return None if best is None else self.items[best]


def _closure_faces(vertices: np.ndarray, tables: list[FaceTable], gi: int, candidates: Iterable[int],
                   rules: LabelRules) -> set[int]:
    """Faces (indices into ``tables[gi]``) lying on a face of another geometry, opposite normals."""
    out = set()
    t = tables[gi]
    for i in candidates:
        if t.area[i] <= 0:
            continue
        n, c = t.normal[i], t.centroid[i]
        u, v = plane_basis(n)
        mine = None
        for gj, o in enumerate(tables):
            if gj == gi or len(o.area) == 0:
                continue
            cand = np.nonzero((o.normal @ n <= -0.99)
                              & (np.abs((o.centroid - c) @ n) <= rules.closure_plane_tol))[0]
            for j in cand:
                if mine is None:
                    mine = _polygon2d(vertices, t.surfaces[i], c, u, v)
                    if mine is None or mine.is_empty:
                        break
                other = _polygon2d(vertices, o.surfaces[j], c, u, v)
                if other is None or other.is_empty:
                    continue
                try:
                    ov = mine.intersection(other).area
                except Exception:  # shapely topology errors on degenerate input
                    continue
                if ov >= rules.closure_overlap * t.area[i]:
                    out.add(i)
                    break
            if i in out:
                break
    return out


# ----------------------------------------------------------------------------- public API

def label_building(b: Building, lod: str | None = None, rules: LabelRules = DEFAULT_RULES,
                   source: Building | None = None) -> Building:
    """Give every surface of the energy geometries its own, typed semantic surface.

    Parameters
    ----------
    b : Building
        Input (or repaired) building; not modified.
    lod : str, optional
        LoD of the energy geometries (default: ``b.default_lod()``).
    rules : LabelRules
        Thresholds.
    source : Building, optional
        The input building before repair. Used only when ``b.provenance["repair"]`` is
        present: faces without a label (created by the repair) take the label of the
        nearest input face with a compatible normal.

    Returns
    -------
    Building
        New building; ``provenance["labels"]`` counts surfaces per ``labelSource``.
    """
    lod = lod if lod is not None else b.default_lod()
    energy = envelope_objects(b, lod)
    tables = [face_table(b.vertices, g) for _, _, g in energy]
    repaired = "repair" in b.provenance
    src = _SourceFaces(source, lod) if (repaired and source is not None) else None
    counts = {"input": 0, "transfer": 0, "closure": 0, "rule": 0, "facing": 0}
    out = b
    for k, (o, gi, g) in enumerate(energy):
        t = tables[k]
        rl = rule_labels(t, rules)
        unlabelled = [i for i, s in enumerate(t.surfaces) if _known_type(g, s) is None]
        closure = (_closure_faces(b.vertices, tables, k, unlabelled, rules)
                   if rules.closure_between_parts and len(tables) > 1 else set())
        entries, sem_by_key = [], {}
        for i, (key, s) in enumerate(zip(t.keys, t.surfaces)):
            st = _known_type(g, s)
            if st in (ROOF, OUTER_CEILING) and t.area[i] > 0 and t.normal[i, 2] < -rules.check_facing_nz:
                e = _entry({**g.semantic_surfaces[s.semantic], "inputType": st}, OUTER_FLOOR, "facing")
            elif st is not None:
                e = _entry(g.semantic_surfaces[s.semantic], st, "input")
            elif i in closure:
                e = _entry(None, CLOSURE, "closure")
            else:
                hit = src.nearest(t.normal[i], t.centroid[i], rules) if src is not None else None
                if hit is not None:
                    e = _entry(hit[1], hit[0], "transfer")
                else:
                    e = _entry(None, rl[i], "rule")
            counts[e["labelSource"]] += 1
            sem_by_key[key] = len(entries)
            entries.append(e)
        ng = replace(_rebuild(g, sem_by_key), semantic_surfaces=tuple(entries))
        out = out.replace_geometry(o.id, gi, ng)
    return out.with_provenance(labels=frozen_mapping({"lod": lod, **counts}))


def check_labels(b: Building, lod: str | None = None, rules: LabelRules = DEFAULT_RULES) -> list[Defect]:
    """Implausible semantic labels of the energy geometries.

    Codes: 1101 roof facing down, 1102 ground surface not at the bottom, 1103 wall
    entirely above the highest roof point, 1104 ground/outer floor facing up.

    Returns
    -------
    list of Defect
        Located as ``coid=..|geom=..|shell=..|face=..``.
    """
    out: list[Defect] = []
    for o, gi, g in envelope_objects(b, lod):
        t = face_table(b.vertices, g)
        hr = t.h_rel
        types = [_known_type(g, s) for s in t.surfaces]
        roof_top = max((float(b.vertices[np.concatenate(s.rings), 2].max())
                        for s, ty in zip(t.surfaces, types) if ty == ROOF and len(s.outer)),
                       default=None)
        for i, ((si, hi, fi), s, ty) in enumerate(zip(t.keys, t.surfaces, types)):
            if ty is None or t.area[i] <= 0:
                continue
            loc = f"coid={o.id}|" + g.location(gi, si, hi, fi)
            nz = float(t.normal[i, 2])
            dz = float(t.centroid[i, 2] - t.z_min)
            if ty in (ROOF, OUTER_CEILING) and nz < -rules.check_facing_nz:
                out.append(Defect(1101, loc, f"{ty} normal n_z={nz:.2f} points down"))
            if ty == GROUND and hr[i] > rules.check_ground_hrel and dz > rules.check_min_height:
                out.append(Defect(1102, loc, f"GroundSurface centroid {dz:.2f} m above the lowest point "
                                             f"(h_rel={hr[i]:.2f})"))
            if ty == WALL and roof_top is not None:
                zlow = float(b.vertices[np.concatenate(s.rings), 2].min())
                if zlow > roof_top + rules.check_min_height:
                    out.append(Defect(1103, loc, f"WallSurface starts {zlow - roof_top:.2f} m above "
                                                 f"the highest roof point"))
            if ty in (GROUND, OUTER_FLOOR) and nz > rules.check_facing_nz:
                out.append(Defect(1104, loc, f"{ty} normal n_z={nz:.2f} points up"))
    return out


def strip_to_energy(b: Building, lod: str | None, keep_other_lods: bool = False) -> Building:
    """``b`` with only its envelope geometries at ``lod`` (all of them when ``keep_other_lods``)."""
    if keep_other_lods:
        return b
    keep = {(o.id, gi) for o, gi, _ in envelope_objects(b, lod)}
    objs = []
    for o in b.objects:
        geoms = tuple(g for gi, g in enumerate(o.geometries) if (o.id, gi) in keep)
        objs.append(replace(o, geometries=geoms))
    return replace(b, objects=tuple(objs))
