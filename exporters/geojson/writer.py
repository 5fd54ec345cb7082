"""GeoJSON of building footprints in WGS84 (RFC 7946): one typed layer of the energy model's figures.

One Feature per exported building, for the GIS where a UBEM study reads its results. GDAL
(QGIS, pyogrio) reads the file as one layer: every geometry a MultiPolygon and every Feature
the same properties, each always of one JSON type (null where unknown). ``--gpkg`` writes the
same layer as a GeoPackage (:mod:`lod2energy.exporters.gpkg.writer`).

**geometry**: the footprint (:func:`lod2energy.exporters.footprint.footprint_geometry`: the
union of the envelope's projections, WGS84 ``[lon, lat]``, RFC 7946 winding, 8 decimals),
always a MultiPolygon (a one-part footprint is a one-part MultiPolygon).

**properties** (:data:`FIELDS`, in this order; types str, int, float, bool):

=========================  =====  ==============================================================
field                      type   meaning
=========================  =====  ==============================================================
id                         str    the building's id (also the Feature's ``id``)
type                       str    its CityObject type
use, use_source            str    use type the model takes (:func:`lod2energy.thermal.use.recorded_use`)
conditioned                bool   heated / cooled (false: no ideal loads, out of per-m2 figures)
conditioned_source         str    ``table``, ``map``, ``attribute``, ``geometry`` or ``default``
year, year_source          int    year of construction (null: unknown) and its source (str)
typology                   str    the building typology of the U-value tables
construction_period        str    the typology's period
storeys, storeys_source    int    storeys as the IDF zones them (:func:`lod2energy.thermal.storeys.storeys`)
height_m                   float  ridge over ground, m
floor_area_m2              float  gross floor area of the storeys, m2 (:mod:`lod2energy.exporters.handoff`)
footprint_area_m2          float  footprint area, m2
UA_W_per_K                 float  sum of U x A of the envelope, W/K
A_env_m2                   float  envelope area, m2
roof_m2 ... adiabatic_m2   float  areas by thermal boundary, m2 (:data:`lod2energy.energy.figures.AREA_KEYS`)
figures_source             str    ``idf``: UA and areas of the written IDF; else the geometry's estimate
u_wall, u_roof,            float  U-values of the constructions, W/(m2 K)
u_ground, u_window
wwr                        float  window-to-wall ratio
weather_station            str    the EPW's station (IDF with ``--weather``)
weather_file               str    the EPW's file name
weather_distance_km        float  site to station, km
heating_kwh, cooling_kwh   float  annual ideal-loads need after ``--run``, kWh (rounded to 1 kWh)
heating_kwh_m2,            float  the same per m2 of conditioned floor area, kWh/(m2 a) (0.1)
cooling_kwh_m2
heating_peak_w,            float  peak loads, W (rounded to 1 W)
cooling_peak_w
conditioned_floor_area_m2  float  conditioned floor area of the run, m2
status                     str    the final check's status (``watertight`` ...)
compliant                  bool   every requested writer wrote it and its file passed its check
geometry_ready             bool   the geometry passed the energy model's conditions
repair_stage               str    the repair stage (``valid``: untouched)
input_valid                bool   the input had no geometry error
output_errors              str    val3dity codes left after the repair, space-separated ("" none)
downgrades                 str    the energy model's downgrades, ``kind:zone`` items
downgrade_d_height_m,      float  height, volume and floor-area change they made (m, m3, m2)
downgrade_d_volume_m3,
downgrade_d_floor_area_m2
=========================  =====  ==============================================================

The run figures come from the building's IDF record (null without ``--run``); UA and areas
are those of the written IDF (:mod:`lod2energy.energy.figures`). GDAL infers a GeoJSON
field's type from its values, so a field null in every Feature reads as a string; the
GeoPackage declares every type.

The file is written through :mod:`lod2energy.safe_write` and self-checked by re-reading it
(:func:`self_check`: geometries, and every Feature's properties against :data:`FIELDS`).
"""
from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any, Iterable, Iterator, Mapping, Sequence

import numpy as np
from shapely.geometry import shape
from shapely.validation import explain_validity

from lod2energy import cache
from lod2energy.energy.downgrades import summed
from lod2energy.energy.figures import AREA_KEYS
from lod2energy.exporters import handoff
from lod2energy.exporters.footprint import _signed_area, footprint, footprint_geometry
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.io.json_stream import Scanner
from lod2energy.model import Building
from lod2energy.safe_write import atomic_write
from lod2energy.site import SiteError
from lod2energy.thermal.use import recorded_use

SUFFIX = ".footprints.geojson"
#: The layer's fields, in order, and their types (see the module docstring).
FIELDS: dict[str, type] = {
    "id": str, "type": str, "use": str, "use_source": str, "conditioned": bool, "conditioned_source": str,
    "year": int, "year_source": str, "typology": str, "construction_period": str,
    "storeys": int, "storeys_source": str, "height_m": float, "floor_area_m2": float, "footprint_area_m2": float,
    "UA_W_per_K": float, "A_env_m2": float, **{f"{k}_m2": float for k in AREA_KEYS}, "figures_source": str,
    "u_wall": float, "u_roof": float, "u_ground": float, "u_window": float, "wwr": float,
    "weather_station": str, "weather_file": str, "weather_distance_km": float,
    "heating_kwh": float, "cooling_kwh": float, "heating_kwh_m2": float, "cooling_kwh_m2": float,
    "heating_peak_w": float, "cooling_peak_w": float, "conditioned_floor_area_m2": float,
    "status": str, "compliant": bool, "geometry_ready": bool, "repair_stage": str, "input_valid": bool,
    "output_errors": str, "downgrades": str, "downgrade_d_height_m": float, "downgrade_d_volume_m3": float,
    "downgrade_d_floor_area_m2": float}
#: Decimals a float field is rounded to (the others: as computed).
ROUND = {"heating_kwh": 0, "cooling_kwh": 0, "heating_kwh_m2": 1, "cooling_kwh_m2": 1, "heating_peak_w": 0,
         "cooling_peak_w": 0, "conditioned_floor_area_m2": 2, "height_m": 2, "floor_area_m2": 2,
         "footprint_area_m2": 2, "weather_distance_km": 1}
#: Run figures copied from the building's IDF record (``ExportRecord.values()``).
_UNSET = object()
#: The :mod:`lod2energy.cache` table of the layer's geometry and facts, kept by the GeoPackage
#: writer for the GeoJSON writer of the same export (:func:`features`): one layer,
#: ``{building key: (geometry or None, facts or why)}``.
LAYER_TABLE = "footprint_layer"
RUN_KEYS = ("heating_kwh", "cooling_kwh", "heating_kwh_m2", "cooling_kwh_m2", "heating_peak_w",
            "cooling_peak_w", "conditioned_floor_area_m2")


# ----------------------------------------------------------------------------- properties

def typed(name: str, x: Any) -> Any:
    """``x`` as field ``name``'s type (:data:`FIELDS`), rounded as :data:`ROUND` says; None
    for None, "" in a number field, and a non-finite number."""
    t = FIELDS[name]
    if isinstance(x, np.generic):
        x = x.item()
    if x is None or (t is not str and x == ""):
        return None
    if t is str:
        return str(x)
    if t is bool:
        return bool(x)
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if t is int:
        return int(x)
    x = float(x)
    return float(round(x, ROUND[name])) if name in ROUND else x


def _facts(b: Building, use, lod, attic, fp) -> handoff.HandoffFacts | None:
    """:func:`lod2energy.exporters.handoff.facts`, None when the building has no storey figure."""
    try:
        return handoff.facts(b, use, lod, attic, fp)
    except Exception:  # noqa: BLE001 - no storey figure is not a reason to drop the footprint
        return None


def _source(facts: Mapping, key: str) -> str | None:
    return (facts.get(key) or {}).get("source")


def properties(b: Building, record=None, use: str | None = None, lod: str | None = None,
               attic: str = "unconditioned", fp=None, facts=_UNSET) -> dict:
    """The Feature properties of ``b``: every field of :data:`FIELDS`, typed (see the module docstring).

    Parameters
    ----------
    b : Building
        The prepared building (``provenance["energy"]``, ``["thermal"]``, ``["repair"]``),
        coordinates in metres.
    record : lod2energy.records.BuildingRecord, optional
        Its record: repair, compliance, the written model's figures and the IDF export's
        weather and run figures.
    use : str, optional
        The ``--use`` override.
    lod : str, optional
    attic : {"unconditioned", "conditioned"}
        ``--attic``: whether the attic floor counts in the floor area.
    fp : shapely Polygon or MultiPolygon, optional
        Its :func:`footprint`, when the caller has it.
    facts : HandoffFacts or None, optional
        Its :func:`_facts`, when the caller has them.
    """
    energy = dict(b.provenance.get("energy") or {})
    thermal = dict(b.provenance.get("thermal") or {})
    h = _facts(b, use, lod, attic, fp) if facts is _UNSET else facts
    u = recorded_use(b, use) if h is None else None
    stage = ""
    out_errors: list[int] = []
    if record is not None:
        stage = record.repair.stage or str(record.repair.detail.get("stage", ""))
        out_errors = sorted(set(int(c) for c in record.output_errors))
        energy = dict(record.energy.detail) or energy
    else:
        stage = str((b.provenance.get("repair") or {}).get("stage", ""))
    th = dict(record.thermal.detail) if record is not None and record.thermal.detail else thermal
    facts = th.get("facts") or {}
    areas = th.get("areas") or {}
    uv = th.get("u_values") or {}
    idf = record.export("idf") if record is not None else None
    extra = idf.values() if idf is not None else {}
    weather = extra.get("weather") or {}
    down = tuple(record.downgrades) if record is not None else ()
    dh, dv, da = summed(down)
    props = {
        "id": str(b.id), "type": b.type,
        "use": h.use if h else u.type, "use_source": h.use_source if h else u.source,
        "conditioned": (facts.get("conditioned") or {}).get("value"), "conditioned_source": _source(facts, "conditioned"),
        "year": th.get("year_of_construction"), "year_source": _source(facts, "year"),
        "typology": th.get("typology") or None, "construction_period": th.get("construction_period") or None,
        "storeys": h.storeys if h else None, "storeys_source": h.storeys_source if h else None,
        "height_m": h.height if h else None, "floor_area_m2": h.floor_area if h else None,
        "footprint_area_m2": h.footprint_area if h else None,
        "UA_W_per_K": th.get("UA"), "A_env_m2": th.get("A_env"), **{f"{k}_m2": areas.get(k) for k in AREA_KEYS},
        "figures_source": th.get("figures_source"),
        **{f"u_{k}": uv.get(k) for k in ("wall", "roof", "ground", "window")}, "wwr": th.get("wwr"),
        "weather_station": weather.get("station"), "weather_file": weather.get("file"),
        "weather_distance_km": weather.get("distance_km"),
        **{k: extra.get(k) for k in RUN_KEYS},
        "status": energy.get("status") or None, "compliant": energy.get("compliant"),
        "geometry_ready": energy.get("geometry_ready"),
        "repair_stage": stage or None, "input_valid": (stage == "valid") if stage else None,
        "output_errors": " ".join(map(str, out_errors)),
        "downgrades": " ".join(f"{d.kind}:{d.zone}" for d in down) or None,
        "downgrade_d_height_m": dh if down else None, "downgrade_d_volume_m3": dv if down else None,
        "downgrade_d_floor_area_m2": da if down else None}
    return {k: typed(k, props[k]) for k in FIELDS}


def multi(geom: dict) -> dict:
    """A GeoJSON Polygon as a one-part MultiPolygon (a MultiPolygon as it is)."""
    return {"type": "MultiPolygon", "coordinates": [geom["coordinates"]]} if geom["type"] == "Polygon" else geom


def features(buildings: Iterable[Building], records: Sequence | None = None, *, crs: Any = None, frame=None,
             use: str | None = None, lod: str | None = None, attic: str = "unconditioned",
             keep: Any = None, take: Any = None) -> Iterator[tuple[str, dict | None, dict | str]]:
    """The layer's rows, one building at a time: ``(id, MultiPolygon geometry, properties)``, or
    ``(id, None, why)`` for a building left out (it cannot be placed, or has no footprint).

    Parameters are those of :func:`write`, and
    keep, take : hashable, optional
        The layer's key in one export that writes it twice (GeoPackage, then GeoJSON): ``keep``
        keeps each building's footprint geometry and facts (the costly part) under it in
        :data:`LAYER_TABLE`, ``take`` uses those kept for the same building (id, geometry and
        thermal facts) instead of computing them again, once. The properties from the records
        are made afresh for each.
    """
    records = records or ()
    by_id = {r.id: i for i, r in enumerate(records)}  # the index: a record may be rebuilt when read
    kept = cache.recall(LAYER_TABLE, take) if take is not None else None
    if take is not None:
        cache.clear(LAYER_TABLE)  # taken once
    mine = cache.keep(LAYER_TABLE, keep, {}, size=1) if keep is not None else None
    for b in buildings:
        if not b.is_building:
            continue
        bid = str(b.id)
        fp = None
        # the building as read: its geometry and the thermal stage's facts (storeys, use)
        bkey = (bid, cache.digest(b.vertices, repr(b.provenance.get("thermal")))) \
            if kept is not None or mine is not None else None
        if kept is not None and bkey in kept:
            geom, h = kept.pop(bkey)
        else:
            fp = footprint(b, lod)
            try:
                geom = footprint_geometry(b, crs, frame, lod, fp)
                h = _facts(b, use, lod, attic, fp) if geom is not None else handoff.NO_FOOTPRINT
                geom = multi(geom) if geom is not None else None
            except SiteError as e:
                geom, h = None, str(e)
            if mine is not None:
                mine[bkey] = (geom, h)
        if geom is None:
            yield bid, None, h
            continue
        rec = records[by_id[bid]] if bid in by_id else None
        yield bid, geom, properties(b, rec, use, lod, attic, fp, facts=h)


def layer_key(outdir, stem: str, crs: Any, frame, options) -> tuple:
    """The key of one export's footprint layer (:func:`features`' ``keep`` / ``take``)."""
    return (os.path.abspath(str(outdir)), stem, str(crs), repr(frame), getattr(options, "use", None),
            getattr(options, "lod", None), getattr(options, "attic", None) or "unconditioned")


# ----------------------------------------------------------------------------- file

def write(buildings: Iterable[Building], path: str | os.PathLike, *, crs: Any = None, frame=None,
          records: Sequence | None = None, use: str | None = None, lod: str | None = None,
          attic: str = "unconditioned", root: str | os.PathLike | None = None, take: Any = None) -> ExportResult:
    """Write the footprints of ``buildings`` to ``path`` and self-check the file.

    Parameters
    ----------
    buildings : iterable of Building
    path : path
    crs : CRS of the coordinates (any CRS pyproj reads, :func:`lod2energy.crs.crs_info`)
    frame : LocalFrame or ScaledFrame, optional
        The metric frame of a geographic file or of one in feet.
    records : sequence of BuildingRecord, optional
        The buildings' records (matched by id).
    use, lod, attic :
        See :func:`properties`.
    root : path, optional
        The folder the file must stay in (:func:`lod2energy.safe_write.check_target`).
    take : hashable, optional
        The layer's key, when the GeoPackage writer kept its geometry and facts (:func:`features`).
    """
    ids, left_out, seen = [], {}, []
    name = Path(path).name[:-len(SUFFIX)] if str(path).endswith(SUFFIX) else Path(path).stem
    head = _dumps({"type": "FeatureCollection", "name": name, "features": []})
    # one Feature at a time: the bytes of json.dumps of the whole collection
    with atomic_write(path, "w", root=root) as f:
        f.write(head[:-2])
        for bid, geom, props in features(buildings, records, crs=crs, frame=frame, use=use, lod=lod, attic=attic,
                                         take=take):
            seen.append(bid)
            if geom is None:
                left_out[bid] = props
                continue
            f.write(("," if ids else "") + _dumps({"type": "Feature", "id": bid, "properties": props,
                                                  "geometry": geom}))
            ids.append(bid)
        f.write("]}\n")
    problems = self_check(str(path), n_features=len(ids))
    return ExportResult(tuple(ids), str(path), not problems, tuple(problems), None, given=tuple(seen),
                        skipped=tuple(left_out.items()))


def _dumps(x) -> str:
    return json.dumps(x, ensure_ascii=False, separators=(",", ":"), allow_nan=False)


def _check_ring(ring, where: str) -> list[str]:
    if not isinstance(ring, list) or len(ring) < 4:
        return [f"{where}: a ring needs at least 4 positions"]
    for p in ring:
        if not (isinstance(p, list) and len(p) == 2 and all(isinstance(c, (int, float)) and math.isfinite(c)
                                                            for c in p)):
            return [f"{where}: position {p!r} is not [lon, lat]"]
        if not (-180 <= p[0] <= 180 and -90 <= p[1] <= 90):
            return [f"{where}: position {p!r} outside longitude/latitude range"]
    if ring[0] != ring[-1]:
        return [f"{where}: ring not closed"]
    return []


def self_check(path: str, n_features: int | None = None) -> list[str]:
    """Problems of a written footprint file (empty: good).

    Re-reads the JSON and checks: a FeatureCollection of ``n_features`` Features, each with an
    id and a MultiPolygon of closed rings of ``[lon, lat]`` in range, exterior rings
    counter-clockwise and holes clockwise (RFC 7946 3.1.6), a valid polygon (shapely), and the
    properties of :data:`FIELDS`, each null or of its type (:func:`property_problems`).
    The file is read one Feature at a time (:class:`lod2energy.io.json_stream.Scanner`).
    """
    try:
        problems, head, n = [], {}, 0
        for i, ft in _features(path, head):
            n += 1
            if len(problems) <= 20:
                problems += (_feature_problems(path, i, ft) or _multi_problems(path, i, ft)
                             or property_problems(f"{path}: feature {i}", ft.get("properties")))
    except (OSError, ValueError) as e:
        return [f"{path}: not readable as JSON: {e}"]
    if head.get("type") != "FeatureCollection" or not isinstance(head.get("features"), list):
        return [f"{path}: not a FeatureCollection"]
    if n_features is not None and n != n_features:
        problems.insert(0, f"{path}: {n} features, {n_features} written")
    return problems


def _multi_problems(path: str, i: int, ft: dict) -> list[str]:
    t = (ft.get("geometry") or {}).get("type")
    return [] if t == "MultiPolygon" else [f"{path}: feature {i} ({ft.get('id')}): geometry is {t}, not a MultiPolygon"]


def _json_type(t: type, v: Any) -> bool:
    if t is float:
        return isinstance(v, float) and math.isfinite(v)
    if t is int:
        return isinstance(v, int) and not isinstance(v, bool)
    return isinstance(v, t)


def property_problems(where: str, props: Any) -> list[str]:
    """The first problem of a Feature's properties against :data:`FIELDS` (empty: good): the
    same keys, each value null or of its field's JSON type (a float field's number written
    with a decimal point)."""
    if not isinstance(props, dict):
        return [f"{where}: no properties"]
    if list(props) != list(FIELDS):
        extra, missing = sorted(set(props) - set(FIELDS)), [k for k in FIELDS if k not in props]
        return [f"{where}: properties not the layer's fields (missing {missing}, extra {extra})"]
    for k, t in FIELDS.items():
        if props[k] is not None and not _json_type(t, props[k]):
            return [f"{where}: property {k!r} is {props[k]!r}, not {t.__name__}"]
    return []


def _features(path: str, head: dict):
    """``(index, Feature)`` of the file's ``features`` array, one at a time; ``head`` gets
    the other members (and ``features: []`` when it is an array). ValueError: not JSON."""
    with open(path, encoding="utf-8") as f:
        sc = Scanner(f)
        if sc.peek() != "{":  # valid JSON, not an object: not a FeatureCollection
            head["type"] = None
            sc.value()
            sc.end()
            return
        for key in sc.members():
            if key == "features" and sc.peek() == "[":
                head[key] = []
                for i in sc.items():
                    yield i, sc.value()
            else:
                head[key] = sc.value()
        sc.end()


def _feature_problems(path: str, i: int, ft) -> list[str]:
    """The first problem of Feature ``i`` (empty: good)."""
    where = f"{path}: feature {i} ({ft.get('id') if isinstance(ft, dict) else '?'})"
    if not isinstance(ft, dict) or ft.get("type") != "Feature" or "id" not in ft:
        return [f"{where}: not a Feature with an id"]
    g = ft.get("geometry") or {}
    if g.get("type") not in ("Polygon", "MultiPolygon"):
        return [f"{where}: geometry is {g.get('type')!r}, not a (Multi)Polygon"]
    polys = [g.get("coordinates")] if g["type"] == "Polygon" else g.get("coordinates") or []
    bad = []
    for poly in polys:
        for k, ring in enumerate(poly or []):
            bad += _check_ring(ring, where)
            if not bad and (_signed_area(ring) > 0) != (k == 0):
                bad.append(f"{where}: ring {k} wound {'clockwise' if k == 0 else 'counter-clockwise'}")
    if not bad and not shape(g).is_valid:
        bad.append(f"{where}: invalid polygon: {explain_validity(shape(g))}")
    return bad[:1]


def _write(buildings, outdir, options, *, crs=None, frame=None, records=None, stem="out", **_):
    """``OUTDIR/<stem>.footprints.geojson``: the footprints (WGS84) with the buildings' records;
    ``options`` are the IDF options (``use``, ``lod``, ``attic``: the energy model's)."""
    path = os.path.join(str(outdir), f"{stem}{SUFFIX}")
    return [write(buildings, path, crs=crs, frame=frame, records=records, use=getattr(options, "use", None),
                  lod=getattr(options, "lod", None), attic=getattr(options, "attic", None) or "unconditioned",
                  root=outdir, take=layer_key(outdir, stem, crs, frame, options))]


# after "idf": the footprints carry the run figures of the IDF pass
register_writer("geojson", _write, self_check, scope="dataset", records=True)
