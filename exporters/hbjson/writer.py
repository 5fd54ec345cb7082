"""Honeybee Model JSON (HBJSON) per building: the energy model's zones as Ladybug Tools reads them
(``--hbjson``).

Written as plain JSON by this module (honeybee is AGPL-3 and no part of it is imported here);
the tests load every file with honeybee-energy's ``Model.from_dict`` and run ``check_all()``.
One ``Model`` per building, in the IDF's local frame (metres; map coordinate = file coordinate
+ the record's offset), from the zones the IDF writer writes (the energy model,
:func:`lod2energy.energy.model.model_of`, cut into storeys by
:func:`lod2energy.energy.zones.storeys._written_zones`):

- one ``Room`` per thermal zone, its ``Face`` s the zone's written pieces (planar, convex),
  typed ``Wall``, ``RoofCeiling`` (roofs, ceilings) or ``Floor`` (ground, floors), a floor
  facing up or a roof facing down by its normal;
- the model's tolerance the geometry's own precision (:func:`model_tolerance`: 1 mm, or more
  where the input's faces are less flat);
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


def model_dict(b: Building, zones: list, options, name: str) -> tuple[dict, dict]:
    """The Model dict of building ``b`` and ``{room id: zone volume m3}``.

    Parameters
    ----------
    zones : list of (ZoneShell, pieces, ZoneInfo, source zone index)
        The building's written zones (local frame).
    options : IdfOptions
    name : str
        The model's identifier (a file-name stem).
    """
    rooms, materials, constructions, volumes = [], {}, {}, {}
    tol = model_tolerance(p.points for _, pieces, _, _ in zones for p in pieces)
    links: dict[str, tuple[str, str]] = {}  # interzone key + side -> (face id, room id)
    sides: dict[str, np.ndarray] = {}  # interzone key + side -> its vertices
    faces_of = []
    for k, (z, pieces, info, _) in enumerate(zones):
        rid = f"{name[:60]}_Z{k}"  # honeybee identifiers: at most 100 characters
        faces = []
        for j, p in enumerate(pieces):
            fid = f"{rid}_F{j}"
            if p.boundary == "Surface" and p.link:
                links[p.link] = (fid, rid)
                sides[p.link] = without_collinear(p.points, tol)
            faces.append((fid, p))
        faces_of.append((rid, z, info, faces))
    for rid, z, info, faces in faces_of:
        out, vol = [], 0.0
        walls = [polygon_area3d(p.points) if p.kind == "wall" and p.boundary == "Outdoors" else None for _, p in faces]
        eligible = sum(a for a in walls if a is not None and a >= options.min_window_wall_area)
        total = sum(a for a in walls if a is not None)
        ratio = min(z.wwr * total / eligible, 0.85) if eligible > 0 else 0.0
        for (fid, p), a in zip(faces, walls):
            pts = np.asarray(p.points, dtype=np.float64)
            if p.boundary == "Surface" and p.link in sides:
                # both sides of an interzone floor get the same vertices (honeybee compares them):
                # the side with more (a wall's vertex on the other's edge) for both
                key, side = p.link.rsplit(":", 1)
                pts, other = sides[p.link], sides.get(f"{key}:{'f' if side == 'c' else 'c'}")
                if other is not None and len(other) > len(pts):
                    pts = other[::-1]
            vol += float(np.dot(pts[0], np.cross(pts[1:-1] - pts[0], pts[2:] - pts[0]).sum(axis=0))) / 6.0 \
                if len(pts) >= 3 else 0.0
            face = {"type": "Face", "identifier": fid, "face_type": face_type(p.kind, pts), "geometry": _face3d(pts)}
            partner = None
            if p.boundary == "Surface":
                key, side = p.link.rsplit(":", 1)
                partner = links.get(f"{key}:{'f' if side == 'c' else 'c'}")
            face["boundary_condition"] = _bc(p.boundary if (p.boundary != "Surface" or partner) else "Adiabatic",
                                             partner)
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
            face["properties"] = {"type": "FacePropertiesAbridged", "energy": energy}
            if a is not None and ratio > 0 and a >= options.min_window_wall_area:
                w = window_for(pts, ratio)
                if w is not None and polygon_area3d(w) > 0.01:
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
    than 3, not finite, an area (collinear vertices dropped) of at most ``tol`` (its
    "degenerate", 000103), or a vertex farther than ``tol`` from the face's plane (000101)."""
    pts = np.asarray(points, dtype=np.float64)
    if pts.ndim != 2 or len(pts) < 3 or not np.all(np.isfinite(pts)):
        return "not a polygon"
    q = without_collinear(pts, tol)
    n = np.cross(q[1:-1] - q[0], q[2:] - q[0]).sum(axis=0) if len(q) >= 3 else np.zeros(3)
    area = 0.5 * float(np.linalg.norm(n))
    if area <= tol:
        return f"degenerate ({area:.2g} m2)"
    dev = float(np.abs((pts - pts.mean(axis=0)) @ (n / (2 * area))).max())
    if dev > 0.5 * tol:  # honeybee measures from its own plane: half the tolerance to spare
        return f"not planar ({dev * 1000:.1f} mm off its plane)"
    return None


def self_check(path: str, n_rooms: int | None = None) -> list[str]:
    """Problems of a written HBJSON (empty: good): a Model of ``n_rooms`` Rooms, each a closed,
    outward shell (:func:`lod2energy.validate.closed.check_closed_outward`, as the IDF's zones),
    no face honeybee would refuse (:func:`face_problem`), every ``Surface`` boundary naming a
    face of the file."""
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
    for r in rooms:
        vol, polys = 0.0, []
        for f in r.get("faces", []):
            pts = np.asarray(f["geometry"]["boundary"], dtype=np.float64)
            why = face_problem(pts, float(doc.get("tolerance") or TOLERANCE))
            if why:
                problems.append(f"{path}: face {f['identifier']}: {why}")
                if why == "not a polygon":
                    continue
            polys.append(pts)
            vol += float(np.dot(pts[0], np.cross(pts[1:-1] - pts[0], pts[2:] - pts[0]).sum(axis=0))) / 6.0
            bc = f.get("boundary_condition") or {}
            if bc.get("type") == "Surface" and bc["boundary_condition_objects"][0] not in ids:
                problems.append(f"{path}: face {f['identifier']}: its Surface partner is not in the file")
        shell = check_closed_outward(polys) if polys else ["no faces"]
        if shell or not vol > 0:
            problems.append(f"{path}: room {r['identifier']}: not a closed, outward shell"
                            + (f" ({shell[0]})" if shell else ""))
    return problems[:20]


def _scope(options) -> str:
    return "context"


def _halo(options) -> float:
    return 1.0  # party walls: faces within a few cm of each other


def _write(buildings, outdir, options, *, context=(), **_):
    return write(buildings, outdir, options, context=context, root=outdir)


register_writer("hbjson", _write, self_check, scope=_scope, halo=_halo, prepare=with_energy_model)
