"""Validation reports in val3dity's JSON shape, plus an energy block and a graph summary.

One feature per first-level CityObject (a Building with its BuildingParts), as val3dity
does; ``dataset_errors`` for problems of the whole file; ``features_overview`` and
``primitives_overview`` as val3dity writes them.
"""
from __future__ import annotations

import time
from collections import Counter
from datetime import datetime, timezone
from typing import Callable, Iterable

import lod2energy
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.graph import building_graphs
from lod2energy.model import Building, FeatureError
from lod2energy.validate.checks import validate_building, validate_buildings
from lod2energy.validate.codes import Defect, name
from lod2energy.validate.compliance import energy_compliance


def parameters_json(tol: Tolerances) -> dict:
    return {"overlap_tol": tol.overlap_tol, "planarity_d2p_tol": tol.planarity_d2p_tol,
            "planarity_n_tol": tol.planarity_n_tol, "snap_tol": tol.snap_tol,
            "ignore204": tol.ignore204}


def error_json(code: int, location: str, info: str) -> dict:
    return {"code": int(code), "description": name(code), "id": location, "info": info}


def _owner_of(b: Building) -> dict[str, str]:
    """Feature id per object id: a Building and its BuildingParts form one feature; other
    descendants (BuildingInstallation, ...) are features of their own, as val3dity reports."""
    env = {o.id for o in b.envelope_objects}
    return {o.id: (b.id if o.id in env or o.id == b.id else o.id) for o in b.objects}


def _coid(location: str) -> str:
    head = location.split("|", 1)[0]
    return head[5:] if head.startswith("coid=") else ""


def feature_reports(b: Building, tol: Tolerances = DEFAULT, lod: str | None = None,
                    defects: list[Defect] | None = None, assess_labels: bool = False,
                    assess_u_values: bool = False, graph=None) -> list[dict]:
    """Feature entries of one building: its own (with energy and graph) first, then one per
    descendant that is not a BuildingPart (installations), as val3dity reports them."""
    defects = validate_building(b, tol) if defects is None else defects
    owner = _owner_of(b)
    own = [d for d in defects if owner.get(_coid(d.location), b.id) == b.id]
    out = [feature_report(b, tol, lod, own, assess_labels, assess_u_values, graph)]
    for o in b.objects:
        if owner[o.id] != o.id or o.id == b.id:
            continue
        mine = [d for d in defects if _coid(d.location) == o.id]
        out.append({"id": o.id, "type": o.type, "validity": not mine, "errors": [d.to_json() for d in mine],
                    "_primitives": [p for p in _primitives(b, mine) if p[2] == o.id]})
    out[0]["_primitives"] = [p for p in out[0]["_primitives"] if owner.get(p[2], b.id) == b.id]
    return out


def feature_report(b: Building, tol: Tolerances = DEFAULT, lod: str | None = None,
                   defects: list[Defect] | None = None, assess_labels: bool = False,
                   assess_u_values: bool = False, graph=None) -> dict:
    """The feature entry of a building (val3dity shape + energy + graph) for ``defects``."""
    defects = validate_building(b, tol) if defects is None else defects
    entry = {"id": b.id, "type": b.type, "validity": not defects,
             "errors": [d.to_json() for d in defects]}
    if b.is_building:
        lod = lod if lod is not None else b.default_lod()
        g = graph if graph is not None else building_graphs([b], lod, tol)[0]
        entry["energy"] = energy_compliance(b, defects, g, lod, tol, assess_labels, assess_u_values)
        entry["graph"] = g.summary()
    entry["_primitives"] = _primitives(b, defects)
    return entry


def _primitives(b: Building, defects: list[Defect]) -> list[tuple[str, bool, str]]:
    """``(geometry type, valid, object id)`` per polygonal geometry (primitives_overview)."""
    bad = set()
    for d in defects:
        for loc in d.location.split("&&"):
            bad.add("|".join(loc.split("|")[:2]))
    out = []
    for o in b.objects:
        for gi, g in enumerate(o.geometries):
            if g.is_polygonal or g.type == "GeometryInstance":
                out.append((g.type, f"coid={o.id}|geom={gi}" not in bad, o.id))
    return out


def error_feature(fe: FeatureError) -> dict:
    """Feature entry for a CityObject that could not be read."""
    loc = fe.message.split(":")[0] if fe.message.startswith("coid=") else (f"coid={fe.id}" if fe.id else "")
    return {"id": fe.id, "type": fe.type or "unknown", "validity": False,
            "errors": [error_json(fe.code, loc, fe.message)], "_primitives": []}


def new_report(input_file: str, input_type: str, tol: Tolerances) -> dict:
    return {"type": "val3dity_report", "val3dity_version": "2.6.0 (lod2energy " + lod2energy.__version__ + ")",
            "lod2energy_version": lod2energy.__version__,
            "input_file": input_file, "input_file_type": input_type,
            "parameters": parameters_json(tol), "time": datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%S (UTC)"),
            "dataset_errors": [], "features": []}


def finish_report(rep: dict) -> dict:
    """Fill overviews, ``all_errors`` and ``validity`` from the features (in place, returned)."""
    fo: dict[str, Counter] = {}
    po: dict[str, Counter] = {}
    codes = set()
    for f in rep["features"]:
        c = fo.setdefault(f["type"], Counter())
        c["total"] += 1
        c["valid"] += bool(f["validity"])
        for t, ok, *_ in f.pop("_primitives", []):
            p = po.setdefault(t, Counter())
            p["total"] += 1
            p["valid"] += ok
        codes.update(e["code"] for e in f["errors"])
    codes.update(e["code"] for e in rep["dataset_errors"])
    rep["features_overview"] = [{"type": t, "total": c["total"], "valid": c["valid"]} for t, c in sorted(fo.items())]
    rep["primitives_overview"] = [{"type": t, "total": c["total"], "valid": c["valid"]} for t, c in sorted(po.items())]
    rep["all_errors"] = sorted(codes)
    rep["validity"] = not codes
    buildings = [f for f in rep["features"] if "energy" in f]
    rep["energy_overview"] = {
        "buildings": len(buildings),
        "geometry_ready": sum(bool(f["energy"]["geometry_ready"]) for f in buildings),
        "compliant": sum(bool(f["energy"]["compliant"]) for f in buildings),
        "status": dict(Counter(f["energy"]["status"] for f in buildings)),
    }
    return rep


def validate_features(model, features: Iterable, input_file: str, tol: Tolerances = DEFAULT,
                      lod: str | None = None, progress: Callable[[dict], None] | None = None,
                      chunk: int = 256) -> dict:
    """Validate every feature of an opened file; never raises on bad geometry or input.

    Features are streamed in chunks of ``chunk`` buildings whose shell checks run in one
    vectorised batch (:func:`~lod2energy.validate.checks.validate_buildings`).
    """
    rep = new_report(input_file, model.format if model is not None else "unknown", tol)
    t0 = time.perf_counter()
    pending: list[Building] = []

    def flush():
        try:
            all_defects = validate_buildings(pending, tol)
        except Exception:  # isolate the failing building instead of losing the chunk
            all_defects = [None] * len(pending)
        try:
            graphs = building_graphs(pending, lod, tol)
        except Exception:
            graphs = [None] * len(pending)
        for b, defects, g in zip(pending, all_defects, graphs):
            for entry in _safe_feature_reports(b, tol, lod, defects, g):
                _emit(rep, entry, progress)
        pending.clear()

    for item in features:
        if isinstance(item, FeatureError):
            if item.id is None:
                rep["dataset_errors"].append(error_json(item.code, "", item.message))
                continue
            flush()
            _emit(rep, error_feature(item), progress)
            continue
        pending.append(item)
        if len(pending) >= chunk:
            flush()
    flush()
    rep["seconds"] = round(time.perf_counter() - t0, 3)
    return finish_report(rep)


def _emit(rep: dict, entry: dict, progress) -> None:
    rep["features"].append(entry)
    if progress:
        progress(entry)


def _safe_feature_reports(b: Building, tol: Tolerances, lod, defects, graph=None) -> list[dict]:
    try:
        return feature_reports(b, tol, lod, defects, graph=graph if b.is_building else None)
    except Exception as e:  # a bug must not lose the rest of the batch: report it for this building
        return [{"id": b.id, "type": b.type, "validity": False,
                 "errors": [error_json(999, f"coid={b.id}", f"internal error: {type(e).__name__}: {e}")],
                 "_primitives": []}]
