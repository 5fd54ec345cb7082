"""The whole job per building: validate -> repair -> label -> U-values -> compliance, then export.

Each building goes through the stages on its own (pure functions, ``Building -> Building``);
a failure in one building is recorded for it and the batch goes on.
"""
from __future__ import annotations

import csv
import json
import os
import sys
import time
from dataclasses import dataclass, field, replace
from typing import Any, Iterable

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.model import Building, CityModel, FeatureError, frozen_mapping
from lod2energy.validate.checks import validate_building
from lod2energy.validate.compliance import energy_compliance
from lod2energy.validate.report import error_json

EXIT_OK, EXIT_INVALID, EXIT_UNUSABLE = 0, 1, 2


@dataclass
class Record:
    """What happened to one building (one row of the dataset report)."""

    id: str
    type: str
    input_errors: list[int] = field(default_factory=list)
    output_errors: list[int] = field(default_factory=list)
    repair: dict = field(default_factory=dict)
    energy: dict = field(default_factory=dict)
    thermal: dict = field(default_factory=dict)
    exports: dict = field(default_factory=dict)
    message: str = ""

    def row(self) -> dict:
        th = self.thermal or {}
        areas = th.get("areas", {}) or {}
        r = {"id": self.id, "type": self.type,
             "input_errors": " ".join(map(str, sorted(set(self.input_errors)))),
             "output_errors": " ".join(map(str, sorted(set(self.output_errors)))),
             "repair_stage": self.repair.get("stage", ""),
             "iou": self.repair.get("iou", ""), "mean_displacement_m": self.repair.get("mean_displacement", ""),
             "compliant": self.energy.get("compliant", ""), "status": self.energy.get("status", ""),
             "typology": th.get("typology", ""), "construction_period": th.get("construction_period", ""),
             "roof_m2": areas.get("roof", ""), "wall_m2": areas.get("wall", ""), "ground_m2": areas.get("ground", ""),
             "A_env_m2": th.get("A_env", ""), "volume_m3": th.get("volume", ""), "UA_W_per_K": th.get("UA", "")}
        for fmt, res in sorted(self.exports.items()):
            r[f"{fmt}_ok"] = res.get("ok", "")
            for k in ("heating_kwh", "cooling_kwh"):
                if k in res:
                    r[k] = res[k]
        r["message"] = self.message
        return r


def _codes(defects) -> list[int]:
    return sorted({d.code for d in defects})


def repair_one(b: Building, tol: Tolerances, timeout: float = 30.0, merge_parts: bool = False,
               lod: str | None = None) -> Building:
    """Repair a building by the ladder (identity for valid input and non-buildings)."""
    if not b.is_building:
        return b
    from lod2energy.repair.pipeline import repair_building
    return repair_building(b, tol=tol, timeout=timeout, merge_parts=merge_parts, lod=lod)


def _thermal_options(a, model: CityModel | None = None):
    from lod2energy.thermal import ThermalOptions
    kw = {"crs": model.crs if model is not None else None, "lod": getattr(a, "lod", None)}
    for name in ("country", "u_table", "u_wall", "u_roof", "u_ground", "u_window", "wwr"):
        v = getattr(a, name, None)
        if v is not None:
            kw[name] = v
    return ThermalOptions(**kw)


def prepare(b: Building, tol: Tolerances, a, source_model: CityModel | None = None) -> tuple[Building, Record]:
    """validate -> repair -> label -> U-values -> compliance for one building."""
    from lod2energy.semantics import label_building
    from lod2energy.thermal import assign_u_values

    from lod2energy.io.interior import without_interior
    b = without_interior(b)  # LoD3/4 interior detail is not envelope (counted in the repair record)
    rec = Record(b.id, b.type)
    before = validate_building(b, tol)
    rec.input_errors = _codes(before)
    lod = getattr(a, "lod", None)
    rb = repair_one(b, tol, getattr(a, "timeout", 30.0), getattr(a, "merge_parts", False), lod)
    from lod2energy.repair import repair_info
    rec.repair = {k: v for k, v in repair_info(rb).items() if k != "geometries"}
    if b.provenance.get("interior_left_out"):
        rec.repair["interior_left_out"] = dict(b.provenance["interior_left_out"])
    if not getattr(a, "merge_parts", False):  # the energy model counts no volume twice
        from lod2energy.repair.parts import clip_overlapping_parts
        rb, parts_energy = clip_overlapping_parts(rb, tol, lod)
        if parts_energy:
            rec.repair["parts_energy"] = parts_energy
    lb = label_building(rb, lod=lod, source=b)
    tb = assign_u_values(lb, _thermal_options(a, source_model))
    after = validate_building(tb, tol)
    rec.output_errors = _codes(after)
    rec.energy = energy_compliance(tb, after, lod=lod, tol=tol, assess_labels=True, assess_u_values=True)
    if rec.repair.get("error"):  # e.g. implausible coordinates: kept in the output, not simulated
        rec.energy.update(compliant=False, geometry_ready=False,
                          reasons=[f"repair: {rec.repair['error']}"] + list(rec.energy.get("reasons", [])))
    # areas, volume and UA of implausible geometry (e.g. a vertex 2,000 km away) would only
    # pollute sums over the report's columns
    rec.thermal = {} if rec.repair.get("error") else dict(tb.provenance.get("thermal", {}) or {})
    tb = tb.with_provenance(energy=frozen_mapping(rec.energy))
    return tb, rec


def frame_entry(model: CityModel | None) -> dict:
    """Report entry for a geographic input: the local metric frame its buildings were
    validated, repaired and exported in (IDF / STL offsets are in this frame)."""
    frame = getattr(model, "frame", None)
    return {"local_frame": frame.as_dict()} if frame is not None else {}


def _progress(quiet: bool, desc: str):
    if quiet:
        return lambda: None, lambda: None
    from tqdm import tqdm
    bar = tqdm(desc=desc, unit=" buildings", file=sys.stderr, disable=None, leave=False)
    return (lambda: bar.update(1)), bar.close


def _open_input(path: str):
    """Open ``path``; None (after one error line per problem) when the file is unusable."""
    from lod2energy.io import read
    model, feats = read(path)
    if model is None:
        for fe in feats:
            _err(fe.message)
        return None
    note_frame(path, model)
    return model, feats


def note_frame(path: str, model: CityModel | None) -> None:
    """One line on stderr when a geographic input is processed in a local metric frame."""
    f = getattr(model, "frame", None)
    if f is not None:
        print(f"lod2energy: note: {path}: CRS {model.crs} is geographic (degrees); buildings are checked and "
              f"exported in a local east-north-up frame in metres at lat {f.lat0:.7f}, lon {f.lon0:.7f} "
              "(report.json: local_frame); CityJSON is written back in degrees", file=sys.stderr)


def _err(msg: str) -> None:
    print(f"lod2energy: error: {msg}", file=sys.stderr)


def _write_json(path: str, obj: Any) -> None:
    tmp = path + ".part"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(obj, f, indent=1, ensure_ascii=False, default=_json_default)
    os.replace(tmp, path)


def _json_default(o):
    try:
        import numpy as np
        if isinstance(o, np.generic):
            return o.item()
        if isinstance(o, np.ndarray):
            return o.tolist()
    except ImportError:  # pragma: no cover
        pass
    if hasattr(o, "items"):
        return dict(o.items())
    if isinstance(o, (set, tuple)):
        return list(o)
    return str(o)


def _repair_attributes(b: Building) -> Building:
    """``b`` with its repair record as flat attributes of the root CityObject."""
    from lod2energy.repair import repair_attributes
    if not b.is_building:
        return b
    attrs = dict(b.root.attributes)
    attrs.update({k: v for k, v in repair_attributes(b).items() if v is not None})
    root = replace(b.root, attributes=frozen_mapping(attrs))
    return replace(b, objects=(root,) + b.objects[1:])


#: Output suffixes of ``lod2energy repair`` (the writer picks CityJSON or CityJSONSeq by them).
REPAIR_SUFFIXES = (".json", ".jsonl", ".cjseq")


def repair_file(a, tol: Tolerances) -> int:
    """``lod2energy repair IN -o OUT``: every CityObject kept, defective buildings replaced by solids."""
    from lod2energy.io import cityjson
    from lod2energy.repair import dataset_table, repair_features, repair_info

    if not a.output.lower().endswith(REPAIR_SUFFIXES):
        _err(f"repair writes CityJSON (.json, .city.json) or CityJSONSeq (.jsonl, .city.jsonl): "
             f"cannot write {a.output!r}")
        return EXIT_UNUSABLE
    opened = _open_input(a.input)
    if opened is None:
        return EXIT_UNUSABLE
    model, feats = opened
    out_b: list[Building] = []
    records: list[dict] = []
    lost: list[dict] = []
    tick, close = _progress(a.quiet, os.path.basename(a.input))
    worst = EXIT_OK
    try:
        for item in repair_features(feats, tol, a.timeout, a.merge_parts, a.lod):
            tick()
            if isinstance(item, FeatureError):
                _err(f"{a.input}: {item.message}")
                lost.append({"id": item.id, "type": item.type, "errors": [error_json(item.code, "", item.message)]})
                worst = max(worst, EXIT_INVALID)
                continue
            if item.is_building:
                rep = {"id": item.id, **{k: v for k, v in repair_info(item).items() if k != "geometries"}}
                records.append(rep)
                if rep.get("error"):
                    _err(f"{a.input}: {item.type} {item.id}: {rep['error']}")
                after = rep.get("defects_after") or []
                if rep.get("stage") == "irreparable" or any(c != 601 for c in after):
                    worst = max(worst, EXIT_INVALID)
            out_b.append(_repair_attributes(item))
    finally:
        close()
    out_dir = os.path.dirname(os.path.abspath(a.output))
    os.makedirs(out_dir, exist_ok=True)
    cityjson.write(a.output, model, out_b)
    table = dataset_table(out_b)
    if a.report:
        _write_json(a.report, {"input_file": a.input, "output_file": a.output, **frame_entry(model),
                               "summary": table, "buildings": records, "unreadable": lost})
    if not a.quiet:
        _print_repair_summary(table)
    return worst


def _print_repair_summary(table: dict) -> None:
    keys = ("total", "valid_before", "valid_after", "compliant_before", "compliant_after", "local_repairs",
            "global_repairs", "left", "miou", "map_v")
    print("  ".join(f"{k}={table[k]:.3g}" if isinstance(table.get(k), float) else f"{k}={table.get(k)}"
                    for k in keys if k in table))
    print("stages: " + ", ".join(f"{k}: {v}" for k, v in (table.get("stages") or {}).items()))


CSV_FIELDS = ["id", "type", "input_errors", "output_errors", "repair_stage", "iou", "mean_displacement_m",
              "compliant", "status", "typology", "construction_period", "roof_m2", "wall_m2", "ground_m2",
              "A_env_m2", "volume_m3", "UA_W_per_K", "cityjson_ok", "idf_ok", "stl_ok", "heating_kwh",
              "cooling_kwh", "message"]


def export_file(a, tol: Tolerances) -> int:
    """``lod2energy export IN -o OUTDIR [--idf] [--stl] [--cityjson]``."""
    opened = _open_input(a.input)
    if opened is None:
        return EXIT_UNUSABLE
    model, feats = opened
    idf_opts = _idf_options(a, model) if a.idf else None  # option errors before any work
    os.makedirs(a.output, exist_ok=True)
    prepared: list[Building] = []
    others: list[Building] = []
    records: list[Record] = []
    worst = EXIT_OK
    tick, close = _progress(a.quiet, os.path.basename(a.input))
    t0 = time.perf_counter()
    try:
        for item in feats:
            tick()
            if isinstance(item, FeatureError):
                _err(f"{a.input}: {item.message}")
                records.append(Record(str(item.id), item.type or "unknown", [item.code], message=item.message))
                worst = max(worst, EXIT_INVALID)
                continue
            if not item.is_building:
                others.append(item)
                continue
            try:
                pb, rec = prepare(item, tol, a, model)
            except Exception as e:
                rec = Record(item.id, item.type, message=f"pipeline failed: {type(e).__name__}: {e}")
                records.append(rec)
                worst = max(worst, EXIT_INVALID)
                continue
            if rec.repair.get("error"):
                _err(f"{a.input}: {item.type} {item.id}: {rec.repair['error']}")
            prepared.append(pb)
            records.append(rec)
    finally:
        close()
    by_id = {r.id: r for r in records}
    ready = [b for b in prepared if by_id[b.id].energy.get("geometry_ready")]
    for b in prepared:
        if not by_id[b.id].energy.get("geometry_ready"):
            by_id[b.id].message = (by_id[b.id].message + " not exported: " +
                                   "; ".join(by_id[b.id].energy.get("reasons", []))).strip()
            worst = max(worst, EXIT_INVALID)
    stem = _stem(a.input)
    if a.cityjson:
        from lod2energy.exporters import cityjson as cj_export
        path = os.path.join(a.output, f"{stem}.energy.city.json")
        res = cj_export.write(path, model, [_repair_attributes(b) for b in prepared] + others,
                              version=a.cityjson_version)
        ok = bool(getattr(res, "ok", False))
        skipped = dict(getattr(res, "skipped", ()) or ())
        for r in records:
            if r.energy:
                r.exports["cityjson"] = ({"ok": False, "path": path, "problems": [f"left out: {skipped[r.id]}"]}
                                         if r.id in skipped else {"ok": ok, "path": str(res.path)})
        for note in getattr(res, "notes", ()) or ():
            if not a.quiet:
                print(f"lod2energy: note: {note}", file=sys.stderr)
        if skipped:
            worst = max(worst, EXIT_INVALID)
        if not ok:
            worst = max(worst, EXIT_INVALID)
            _err(f"CityJSON export failed its self-check: {'; '.join(getattr(res, 'problems', [])[:3])}")
    if a.idf:
        worst = max(worst, _export_with("idf", ready, a, by_id, model, idf_opts))
    if a.stl:
        worst = max(worst, _export_with("stl", ready, a, by_id, model))
    rows = [r.row() for r in records]
    _write_json(os.path.join(a.output, "report.json"),
                {"input_file": a.input, "output_dir": a.output, "seconds": round(time.perf_counter() - t0, 2),
                 **frame_entry(model),
                 "buildings": [{**r.row(), "repair": r.repair, "energy": r.energy, "thermal": r.thermal,
                                "exports": r.exports} for r in records]})
    with open(os.path.join(a.output, "report.csv"), "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=CSV_FIELDS, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    if not a.quiet:
        _print_export_summary(records, a)
    return worst


def default_weather(country: str | None) -> str | None:
    """The bundled EPW for ``country`` (only NL ships one), else None."""
    if (country or "").upper() != "NL":
        return None
    from importlib.resources import files
    p = files("lod2energy") / "data" / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"
    return str(p) if p.is_file() else None


def _idf_options(a, model: CityModel):
    from lod2energy.errors import ParameterError
    from lod2energy.exporters.idf import IdfOptions
    from lod2energy.thermal import country_from_crs
    weather = a.weather
    if a.run and weather is None:
        weather = default_weather(a.country or country_from_crs(model.crs))
        if weather is None:
            raise ParameterError("--run needs --weather EPW (a weather file ships only for the Netherlands)")
    if weather is not None and not os.path.isfile(weather):
        raise ParameterError(f"--weather {weather}: no such file")
    kw = dict(mode=a.idf_mode, version=a.energyplus_version, shading=a.shading, run=a.run, weather=weather,
              lod=a.lod)
    if a.wwr is not None:
        kw["wwr"] = a.wwr
    return IdfOptions(**kw)


def _export_with(fmt: str, buildings: list[Building], a, by_id: dict, model: CityModel, opts=None) -> int:
    worst = EXIT_OK
    if fmt == "idf":
        from lod2energy.exporters import idf as mod
    else:
        from lod2energy.exporters import stl as mod
        opts = mod.StlOptions(mode=a.stl_mode, ascii=a.stl_ascii, lod=a.lod)
    try:
        results = mod.write(buildings, a.output, opts, crs=model.crs)
    except Exception as err:  # noqa: BLE001 - a geometry the writer cannot take: isolate it
        results = []
        one_file = getattr(opts, "mode", "building") != "building"
        for b in buildings if not one_file else []:
            try:
                results.extend(mod.write([b], a.output, opts, crs=model.crs))
            except Exception as e:  # noqa: BLE001 - reported for this building, the rest goes on
                if b.id in by_id:
                    by_id[b.id].exports[fmt] = {"ok": False, "path": "",
                                                "problems": [f"{fmt.upper()} not written: {type(e).__name__}: {e}"]}
                worst = EXIT_INVALID
                _err(f"{fmt.upper()} export of {b.type} {b.id} failed: {type(e).__name__}: {e}")
        if one_file:
            for b in buildings:
                if b.id in by_id:
                    by_id[b.id].exports[fmt] = {"ok": False, "path": "",
                                                "problems": [f"{fmt.upper()} not written: {type(err).__name__}: {err}"]}
            worst = EXIT_INVALID
            _err(f"{fmt.upper()} export failed: {type(err).__name__}: {err}")
    for res in results:
        ids = list(getattr(res, "building_ids", None) or [])
        d = {"ok": bool(res.ok), "path": str(res.path), "problems": list(getattr(res, "problems", []) or [])}
        for k in ("offset", "heating_kwh", "cooling_kwh", "severe_errors", "not_enclosed", "warnings"):
            v = getattr(res, k, None)
            if v is not None and v != ():
                d[k] = list(v) if isinstance(v, tuple) else v
        for bid in ids:
            if bid in by_id:
                by_id[bid].exports[fmt] = d
        if not res.ok:
            worst = EXIT_INVALID
            _err(f"{fmt.upper()} export {res.path} failed its self-check: {'; '.join(d['problems'][:3])}")
    return worst


def _stem(path: str) -> str:
    base = os.path.basename(path)
    for suf in (".city.jsonl", ".city.json", ".jsonl", ".json", ".obj", ".off", ".poly"):
        if base.lower().endswith(suf):
            return base[: -len(suf)]
    return os.path.splitext(base)[0]


def _print_export_summary(records: list[Record], a) -> None:
    b = [r for r in records if r.type == "Building" or r.energy]
    n = len(b)
    comp = sum(bool(r.energy.get("compliant")) for r in b)
    hdr = f"{'buildings':>9} {'compliant':>9} {'repaired':>8}  " + "  ".join(
        f"{f} ok" for f, on in (("cityjson", a.cityjson), ("idf", a.idf), ("stl", a.stl)) if on)
    print(hdr)
    rep = sum(1 for r in b if r.repair.get("stage") not in (None, "", "valid", "none", "irreparable"))
    cells = []
    for f, on in (("cityjson", a.cityjson), ("idf", a.idf), ("stl", a.stl)):
        if on:
            cells.append(f"{sum(bool(r.exports.get(f, {}).get('ok')) for r in b)}/{n}")
    print(f"{n:>9} {comp:>9} {rep:>8}  " + "  ".join(f"{c:>8}" for c in cells))
    print(f"report: {os.path.join(a.output, 'report.json')} and report.csv")
