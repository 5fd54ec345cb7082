"""Honeybee Model JSON (HBJSON) per building: the energy model's zones as Ladybug Tools reads them
(``--hbjson``).

Written as plain JSON by this module (honeybee is AGPL-3 and no part of it is imported here);
the tests load every file with honeybee-energy's ``Model.from_dict`` and run ``check_all()``.
One ``Model`` per building, in the IDF's local frame (metres; map coordinate = file coordinate
+ the record's offset), from the zones the IDF writer writes (the energy model,
:func:`lod2energy.energy.model.model_of`, cut into storeys by
:func:`lod2energy.energy.zones.storeys._written_zones`):

- one ``Room`` per thermal zone, its ``Face`` s the zone's written pieces (convex), typed
  ``Wall``, ``RoofCeiling`` (roofs, ceilings) or ``Floor`` (ground, floors), a floor facing up
  or a roof facing down by its normal; a warped piece without a window as exact triangles
  (:func:`fan`), a sliver honeybee calls degenerate merged into its neighbour
  (:func:`mend_slivers`);
- the model's tolerance the geometry's own precision (:func:`model_tolerance`: 1 mm, or more
  where a face is less flat or the input's parts interpenetrate, :func:`overlap_tolerance`);
- boundary conditions as in the IDF: ``Outdoors``, ``Ground``, ``Adiabatic`` for party walls,
  ``Surface`` for the floors and ceilings between storeys (each naming its partner);
- ``Aperture`` s on the outdoor walls from the window-to-wall ratio, placed as the IDF places
  its windows (:func:`lod2energy.energy.openings.window_for`);
- constructions from our U-values: one no-mass layer giving the U-value with films
  (:func:`lod2energy.exporters.energyplus.constructions.construction_layers` without the mass
  layer), windows a simple glazing system (U, the IDF's SHGC). Programs and HVAC are left to
  honeybee's defaults; the room's use is in its ``user_data``.
"""
from __future__ import annotations

import json
import os
from typing import Iterable

import numpy as np
from shapely.geometry import Polygon

from lod2energy.energy.model import model_of, with_energy_model
from lod2energy.energy.openings import window_for
from lod2energy.energy.zones.storeys import _written_zones
from lod2energy.exporters.energyplus.constructions import construction_layers
from lod2energy.exporters.paths import output_path, safe_stem, set_aside_failed
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.geometry.polygons import polygon_area3d
from lod2energy.model import Building
from lod2energy.safe_write import write_text
from lod2energy.validate.closed import check_closed_outward

SUFFIX = ".hbjson"
#: Our piece kinds -> honeybee face types.
FACE_TYPE = {"wall": "Wall", "roof": "RoofCeiling", "ceiling": "RoofCeiling", "ground": "Floor", "floor": "Floor"}
#: Honeybee's tolerances of the written models (m, degrees).
TOLERANCE, ANGLE_TOLERANCE = 0.001, 1.0
#: The tolerances a model may declare (m): the first that its faces' flatness allows
#: (:func:`model_tolerance`).
TOLERANCES = (0.001, 0.002, 0.005, 0.01)
#: Faces farther from flat than this (m, a few times the 6-decimal rounding) are written as triangles.
WARP = 1e-5
#: Normals closer to vertical than this (|nz|, about 1 degree) make a face "up" or "down".
_VERTICAL = 0.0175


def _bc(boundary: str, partner: tuple[str, str] | None = None) -> dict:
    if boundary == "Outdoors":
        return {"type": "Outdoors", "sun_exposure": True, "wind_exposure": True,
                "view_factor": {"type": "Autocalculate"}}
    if boundary == "Surface":
        return {"type": "Surface", "boundary_condition_objects": list(partner)}
    return {"type": boundary}


def without_collinear(points: np.ndarray, tol: float = TOLERANCE) -> np.ndarray:
    """``points`` ``(k, 3)`` without the vertices closer than ``tol`` (m) to the segment of their
    neighbours: the two sides of an interzone floor keep the same vertices, as honeybee asks of
    adjacent faces (each side may carry a vertex the other's walls put there)."""
    pts = np.asarray(points, dtype=np.float64)
    changed = True
    while changed and len(pts) > 3:
        changed = False
        for i in range(len(pts)):
            a, b, c = pts[i - 1], pts[i], pts[(i + 1) % len(pts)]
            ac = c - a
            t = float(np.clip(np.dot(b - a, ac) / max(float(np.dot(ac, ac)), 1e-18), 0.0, 1.0))
            if np.linalg.norm(a + t * ac - b) < tol:
                pts = np.delete(pts, i, axis=0)
                changed = True
                break
    return pts


def collapsed(points: np.ndarray, tol: float) -> bool:
    """Whether honeybee calls a face of these vertices ``(k, 3)`` degenerate (000103): with the
    vertices it deems collinear removed (the triangle a vertex makes with its neighbours lower
    than ``tol / 2`` over the longer of its two edges, as honeybee's geometry library removes them),
    fewer than 3 are left or an area of at most ``tol`` m2."""
    pts = [np.asarray(p, dtype=np.float64) for p in points]
    if len(pts) < 3:
        return True
    q = np.asarray(pts)
    normal = np.cross(q[1:-1] - q[0], q[2:] - q[0]).sum(axis=0)
    if not np.linalg.norm(normal) > 0:
        return True
    normal = normal / np.linalg.norm(normal)
    changed = True
    while changed and len(pts) >= 3:
        changed = False
        for i in range(len(pts)):
            a, v, c = pts[i - 1], pts[i], pts[(i + 1) % len(pts)]
            area2 = abs(float(np.dot(np.cross(v - a, c - a), normal)))
            if area2 < max(float(np.linalg.norm(v - a)), float(np.linalg.norm(v - c)), tol) * tol / 2:
                del pts[i]
                changed = True
                break
    if len(pts) < 3:
        return True
    q = np.asarray(pts)
    return 0.5 * float(np.linalg.norm(np.cross(q[1:-1] - q[0], q[2:] - q[0]).sum(axis=0))) <= tol


def mend_slivers(faces: list[dict], tol: float) -> list[dict]:
    """``faces`` (a Room's Face dicts) with each degenerate face (:func:`collapsed`) merged into
    a neighbour across its longest edge the neighbour shares: the neighbour's edge ``b -> a``
    becomes the sliver's path ``b -> ... -> a``, so the room stays closed. A sliver with a
    ``Surface`` boundary, or without such a neighbour, is kept (the self-check refuses it)."""
    def ring(f):
        return [tuple(v) for v in f["geometry"]["boundary"]]
    out = list(faces)
    i = 0
    while i < len(out):
        f = out[i]
        sl = ring(f)
        if f["boundary_condition"]["type"] == "Surface" or not collapsed(np.array(sl), tol):
            i += 1
            continue
        edges = sorted(range(len(sl)), key=lambda k: -float(np.linalg.norm(np.subtract(sl[k], sl[(k + 1) % len(sl)]))))
        merged = False
        for k in edges:
            a, b = sl[k], sl[(k + 1) % len(sl)]
            for j, g in enumerate(out):
                if j == i or g["boundary_condition"]["type"] == "Surface":
                    continue
                gr = ring(g)
                m = next((m for m in range(len(gr)) if gr[m] == b and gr[(m + 1) % len(gr)] == a), None)
                if m is None:
                    continue
                path = [sl[(k + 1 + t) % len(sl)] for t in range(1, len(sl) - 1)]  # after b, before a
                new = gr[:m + 1] + path + gr[m + 1:]
                out[j] = {**g, "geometry": {"type": "Face3D", "boundary": [list(v) for v in new]}}
                merged = True
                break
            if merged:
                break
        if merged:
            del out[i]
        else:
            i += 1
    return out


def _deviation(points: np.ndarray) -> float:
    """Largest distance (m) of ``points`` from their Newell plane through their mean."""
    n = np.cross(points[1:-1] - points[0], points[2:] - points[0]).sum(axis=0)
    norm = float(np.linalg.norm(n))
    return float(np.abs((points - points.mean(axis=0)) @ (n / norm)).max()) if norm > 0 else 0.0


def model_tolerance(polygons: Iterable[np.ndarray]) -> float:
    """The model's tolerance (m): the first of :data:`TOLERANCES` at least twice the largest
    deviation of a face from its plane (the geometry's own precision: honeybee calls a face
    farther from flat than the tolerance not planar), the last when none is."""
    dev = max((_deviation(np.asarray(p, dtype=np.float64)) for p in polygons if len(p) >= 3), default=0.0)
    return next((t for t in TOLERANCES if t >= 2 * dev), TOLERANCES[-1])


def collisions(floors: list[tuple[int, np.ndarray]], tol: float) -> list[tuple[int, int]]:
    """Pairs of rooms whose floors at one height (within ``tol``) overlap in plan by more than
    ``tol / 2`` (m; honeybee's room collision check, 000108, measures a vertex's depth past an
    edge against ``tol``). ``floors``: ``(room index, vertices (k, 3))`` of horizontal floors."""
    polys = [(r, float(p[0, 2]), Polygon(p[:, :2])) for r, p in floors]
    out = set()
    for i, (ra, za, a) in enumerate(polys):
        for rb, zb, b in polys[i + 1:]:
            if ra == rb or (ra, rb) in out or abs(za - zb) > tol or not (a.is_valid and b.is_valid):
                continue
            if a.intersects(b) and not a.intersection(b).buffer(-tol / 4).is_empty:
                out.add((ra, rb))
    return sorted(out)


def overlap_tolerance(floors: list[tuple[int, np.ndarray]]) -> float:
    """The least of :data:`TOLERANCES` under which no rooms collide (:func:`collisions`):
    BuildingParts of the input may interpenetrate by a millimetre or two. The least of all
    when none is (rooms that truly overlap: the self-check refuses the file)."""
    return next((t for t in TOLERANCES if not collisions(floors, t)), TOLERANCES[0])


def face_type(kind: str, points: np.ndarray) -> str:
    """Honeybee face type of a piece: by its kind (:data:`FACE_TYPE`), but a floor never faces
    up nor a roof or ceiling down (honeybee's upside-down check): those go by their normal."""
    t = FACE_TYPE[kind]
    n = np.cross(points[1:-1] - points[0], points[2:] - points[0]).sum(axis=0)
    nz = float(n[2] / (np.linalg.norm(n) or 1.0))
    if t == "Floor" and nz > _VERTICAL:
        return "RoofCeiling"
    if t == "RoofCeiling" and nz < -_VERTICAL:
        return "Floor"
    return t


def _face3d(points: np.ndarray) -> dict:
    return {"type": "Face3D", "boundary": [[round(float(c), 6) for c in p] for p in points]}


def fan(points: np.ndarray, tol: float = TOLERANCE) -> list[np.ndarray] | None:
    """A warped convex face ``(k, 3)`` as ``k - 2`` triangles sharing one apex (the vertex whose
    fan has the largest smallest triangle), or None when every fan has a triangle of at most
    ``tol`` m2. Triangles are exactly planar: honeybee's ray test that turns a closed room's
    faces outward misreads a face beside a warped neighbour (a floor flipped upward)."""
    pts = np.asarray(points, dtype=np.float64)
    best, best_min = None, tol
    for i in range(len(pts)):
        q = np.roll(pts, -i, axis=0)
        areas = 0.5 * np.linalg.norm(np.cross(q[1:-1] - q[0], q[2:] - q[0]), axis=1)
        if areas.min() > best_min:
            best, best_min = q, float(areas.min())
    if best is None:
        return None
    return [np.array([best[0], best[j], best[j + 1]]) for j in range(1, len(best) - 1)]


def _volume(pts: np.ndarray) -> float:
    """Signed volume contribution (m3) of one outward face ``(k, 3)``."""
    return float(np.dot(pts[0], np.cross(pts[1:-1] - pts[0], pts[2:] - pts[0]).sum(axis=0))) / 6.0 \
        if len(pts) >= 3 else 0.0


def model_dict(b: Building, zones: list, options, name: str) -> tuple[dict, dict]:
    """The Model dict of building ``b`` and ``{room id: zone volume m3}``.

    Faces warped by more than :data:`WARP` (m) that carry no window are written as triangles
    (:func:`fan`); the model's tolerance follows the faces as written (:func:`model_tolerance`).

    Parameters
    ----------
    zones : list of (ZoneShell, pieces, ZoneInfo, source zone index)
        The building's written zones (local frame).
    options : IdfOptions
    name : str
        The model's identifier (a file-name stem).
    """
    rooms, materials, constructions, volumes = [], {}, {}, {}
    links: dict[str, tuple[str, str]] = {}  # interzone key + side -> (face id, room id)
    faces_of = []
    for k, (z, pieces, info, _) in enumerate(zones):
        rid = f"{name[:60]}_Z{k}"  # honeybee identifiers: at most 100 characters
        walls = [polygon_area3d(p.points) if p.kind == "wall" and p.boundary == "Outdoors" else None for p in pieces]
        eligible = sum(a for a in walls if a is not None and a >= options.min_window_wall_area)
        total = sum(a for a in walls if a is not None)
        ratio = min(z.wwr * total / eligible, 0.85) if eligible > 0 else 0.0
        faces = []
        for j, (p, a) in enumerate(zip(pieces, walls)):
            fid = f"{rid}_F{j}"
            pts = np.asarray(p.points, dtype=np.float64)
            w = None
            if a is not None and ratio > 0 and a >= options.min_window_wall_area:
                w = window_for(pts, ratio)
                w = w if w is not None and polygon_area3d(w) > 0.01 else None
            if p.boundary == "Surface" and p.link:
                links[p.link] = (fid, rid)
            parts = fan(pts) if (w is None and p.boundary != "Surface" and _deviation(pts) > WARP) else None
            faces.append((fid, p, [pts] if parts is None else parts, w))
        faces_of.append((rid, z, info, faces))
    tol = model_tolerance(q for _, _, _, faces in faces_of for _, _, parts, _ in faces for q in parts)
    tol = max(tol, overlap_tolerance([(k, q) for k, (_, _, _, faces) in enumerate(faces_of) for _, p, parts, _ in faces
                                      for q in parts if p.kind in ("ground", "floor") and np.ptp(q[:, 2]) <= 1e-6]))
    # both sides of an interzone floor get the same vertices (honeybee compares them): the side
    # with more (a wall's vertex on the other's edge) for both
    sides = {p.link: without_collinear(p.points, tol) for _, _, _, faces in faces_of for _, p, _, _ in faces
             if p.boundary == "Surface" and p.link}
    for rid, z, info, faces in faces_of:
        out, vol = [], 0.0
        for fid, p, parts, w in faces:
            partner = None
            if p.boundary == "Surface" and p.link in sides:
                key, side = p.link.rsplit(":", 1)
                pts, other = sides[p.link], sides.get(f"{key}:{'f' if side == 'c' else 'c'}")
                parts = [other[::-1] if other is not None and len(other) > len(pts) else pts]
                partner = links.get(f"{key}:{'f' if side == 'c' else 'c'}")
            bc = _bc(p.boundary if (p.boundary != "Surface" or partner) else "Adiabatic", partner)
            energy = {"type": "FaceEnergyPropertiesAbridged"}
            if p.boundary != "Surface" and p.u_value > 0:
                cid = f"{FACE_TYPE[p.kind]}_{p.boundary}_U{p.u_value:.4f}".replace(".", "p")
                if cid not in constructions:
                    r, _, _ = construction_layers(p.kind, p.boundary, p.u_value, False)
                    materials[cid + "_layer"] = {"type": "EnergyMaterialNoMass", "identifier": cid + "_layer",
                                                 "r_value": round(float(r), 5), "roughness": "MediumRough",
                                                 "thermal_absorptance": 0.9, "solar_absorptance": 0.7,
                                                 "visible_absorptance": 0.7}
                    constructions[cid] = {"type": "OpaqueConstructionAbridged", "identifier": cid,
                                          "materials": [cid + "_layer"]}
                energy["construction"] = cid
            for t, pts in enumerate(parts):
                vol += _volume(pts)
                face = {"type": "Face", "identifier": fid if len(parts) == 1 else f"{fid}_{t}",
                        "face_type": face_type(p.kind, pts), "geometry": _face3d(pts), "boundary_condition": bc,
                        "properties": {"type": "FacePropertiesAbridged", "energy": energy}}
                if w is not None:
                    wid = f"Window_U{z.u_window:.3f}_G{options.shgc:.2f}".replace(".", "p")
                    if wid not in constructions:
                        materials[wid + "_glazing"] = {"type": "EnergyWindowMaterialSimpleGlazSys",
                                                       "identifier": wid + "_glazing",
                                                       "u_factor": round(min(float(z.u_window), 7.0), 4),
                                                       "shgc": float(options.shgc), "vt": float(options.shgc)}
                        constructions[wid] = {"type": "WindowConstructionAbridged", "identifier": wid,
                                              "materials": [wid + "_glazing"]}
                    face["apertures"] = [{"type": "Aperture", "identifier": f"{fid}_Win", "geometry": _face3d(w),
                                          "is_operable": False, "boundary_condition": _bc("Outdoors"),
                                          "properties": {"type": "AperturePropertiesAbridged",
                                                         "energy": {"type": "ApertureEnergyPropertiesAbridged",
                                                                    "construction": wid}}}]
                out.append(face)
        volumes[rid] = vol
        out = mend_slivers(out, tol)
        rooms.append({"type": "Room", "identifier": rid, "display_name": str(z.object_id), "faces": out,
                      "properties": {"type": "RoomPropertiesAbridged",
                                     "energy": {"type": "RoomEnergyPropertiesAbridged"}},
                      "user_data": {"building": str(b.id), "use": info.use, "conditioned": bool(info.conditioned),
                                    "storey": info.storey, "attic": bool(info.attic)}})
    model = {"type": "Model", "identifier": name, "display_name": str(b.id), "units": "Meters",
             "tolerance": tol, "angle_tolerance": ANGLE_TOLERANCE, "rooms": rooms,
             "properties": {"type": "ModelProperties", "energy": {
                 "type": "ModelEnergyProperties", "materials": list(materials.values()),
                 "constructions": list(constructions.values())}}}
    return model, volumes


def write(buildings: Iterable[Building], outdir: str | os.PathLike, options, *, context: Iterable[Building] = (),
          root: str | os.PathLike | None = None) -> list[ExportResult]:
    """One ``<id>.hbjson`` per building of ``buildings`` (energy-ready, with their neighbours
    ``context`` for the party walls), each self-checked (:func:`self_check`)."""
    model = model_of(buildings, options, context)
    if model is None:
        return []
    n_own = model.n_own
    written_of, _, _, _ = _written_zones(list(model.buildings[:n_own]), model.zones, model.zones_of, model.pieces,
                                         options, model.openings)
    out, used = [], set()
    for bi in range(n_own):
        b = model.buildings[bi]
        stem = safe_stem(str(b.id), used)
        path = output_path(outdir, stem, SUFFIX)
        doc, volumes = model_dict(b, written_of[bi], options, stem)
        doc["user_data"] = {"building": str(b.id), "offset_m": [float(x) for x in model.origin]}
        write_text(path, json.dumps(doc, separators=(",", ":"), allow_nan=False), root=root or outdir)
        problems = self_check(str(path), len(written_of[bi]))
        res = ExportResult((str(b.id),), str(path), not problems, tuple(problems),
                           tuple(float(x) for x in model.origin),
                           stats={"zones": len(volumes), "zone_volumes_m3": volumes})
        out.append(set_aside_failed(res))
    return out


def face_problem(points: np.ndarray, tol: float = TOLERANCE) -> str | None:
    """Why honeybee's ``check_all`` would refuse a face of these vertices (m), or None: fewer
    than 3, not finite, an area (collinear vertices dropped) of at most ``tol`` or
    :func:`collapsed` (its "degenerate", 000103), or a vertex farther than ``tol`` from the face's plane (000101)."""
    pts = np.asarray(points, dtype=np.float64)
    if pts.ndim != 2 or len(pts) < 3 or not np.all(np.isfinite(pts)):
        return "not a polygon"
    q = without_collinear(pts, tol)
    n = np.cross(q[1:-1] - q[0], q[2:] - q[0]).sum(axis=0) if len(q) >= 3 else np.zeros(3)
    area = 0.5 * float(np.linalg.norm(n))
    if area <= tol or collapsed(pts, tol):
        return f"degenerate ({area:.2g} m2)"
    dev = float(np.abs((pts - pts.mean(axis=0)) @ (n / (2 * area))).max())
    if dev > 0.5 * tol:  # honeybee measures from its own plane: half the tolerance to spare
        return f"not planar ({dev * 1000:.1f} mm off its plane)"
    return None


def self_check(path: str, n_rooms: int | None = None) -> list[str]:
    """Problems of a written HBJSON (empty: good): a Model of ``n_rooms`` Rooms, each a closed,
    outward shell (:func:`lod2energy.validate.closed.check_closed_outward`, T-junctions joined
    within EnergyPlus's 1.27 cm or within the model's tolerance),
    no face honeybee would refuse (:func:`face_problem`), every ``Surface`` boundary naming a
    face of the file, no two rooms overlapping (:func:`collisions`)."""
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        return [f"{path}: not readable as JSON: {e}"]
    if not isinstance(doc, dict) or doc.get("type") != "Model":
        return [f"{path}: not a honeybee Model"]
    rooms = doc.get("rooms") or []
    problems = []
    if n_rooms is not None and len(rooms) != n_rooms:
        problems.append(f"{path}: {len(rooms)} rooms, {n_rooms} written")
    ids = {f["identifier"] for r in rooms for f in r.get("faces", [])}
    tol = float(doc.get("tolerance") or TOLERANCE)
    floors = []
    for k, r in enumerate(rooms):
        vol, polys = 0.0, []
        for f in r.get("faces", []):
            pts = np.asarray(f["geometry"]["boundary"], dtype=np.float64)
            why = face_problem(pts, tol)
            if why:
                problems.append(f"{path}: face {f['identifier']}: {why}")
                if why == "not a polygon":
                    continue
            polys.append(pts)
            if f.get("face_type") == "Floor" and np.ptp(pts[:, 2]) <= tol:
                floors.append((k, pts))
            vol += float(np.dot(pts[0], np.cross(pts[1:-1] - pts[0], pts[2:] - pts[0]).sum(axis=0))) / 6.0
            bc = f.get("boundary_condition") or {}
            if bc.get("type") == "Surface" and bc["boundary_condition_objects"][0] not in ids:
                problems.append(f"{path}: face {f['identifier']}: its Surface partner is not in the file")
        # T-junctions joined within EnergyPlus's 1.27 cm, or within the model's tolerance (a
        # vertex nearer than 1.27 cm to another face's edge, and not on it, is a corner of its own)
        shell = check_closed_outward(polys) if polys else ["no faces"]
        if shell and polys and not check_closed_outward(polys, t_tol=tol):
            shell = []
        if shell or not vol > 0:
            problems.append(f"{path}: room {r['identifier']}: not a closed, outward shell"
                            + (f" ({shell[0]})" if shell else ""))
    for a, b in collisions(floors, tol):
        problems.append(f"{path}: rooms {rooms[a]['identifier']} and {rooms[b]['identifier']} overlap "
                        "(the input's parts overlap)")
    return problems[:20]


def _scope(options) -> str:
    return "context"


def _halo(options) -> float:
    return 1.0  # party walls: faces within a few cm of each other


def _write(buildings, outdir, options, *, context=(), **_):
    return write(buildings, outdir, options, context=context, root=outdir)


register_writer("hbjson", _write, self_check, scope=_scope, halo=_halo, prepare=with_energy_model)
