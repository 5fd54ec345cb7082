"""GeoJSON of building footprints in WGS84 (RFC 7946) with the energy model's figures.

One Feature per exported building, for the GIS where a UBEM study reads its results:

- **geometry**: the footprint, the union of the 2D projections of the envelope's faces (so
  an overhanging storey or roof counts; a Building with its BuildingParts is one footprint),
  snapped to a 1 cm grid (:func:`shapely.union_all` with ``grid_size``) so that faces that
  share an edge leave no sliver; a Polygon, or a MultiPolygon for detached parts. Taken to
  WGS84 through the file's CRS with pyproj (:func:`lod2energy.site.to_wgs84`, which also
  knows the local frame of a geographic file) and written ``[longitude, latitude]``, exterior
  rings counter-clockwise, holes clockwise, 8 decimals (about 1 mm), as RFC 7946 asks;
- **properties**: ``id``, ``type``, the repair (``repair_stage``, ``input_valid``,
  ``output_errors``), the compliance (``compliant``, ``status``, ``geometry_ready``), the
  storeys and use the energy model takes (:func:`lod2energy.thermal.storeys.storeys`,
  :func:`lod2energy.thermal.use.building_use`, with their sources), typology and period, the
  energy model's downgrades (``downgrades``: ``kind:zone`` items, and the height, volume and
  floor-area change they made, :mod:`lod2energy.energy.downgrades`); the envelope's areas by
  thermal boundary and UA (``figures_source`` "idf": those of the written IDF,
  :mod:`lod2energy.energy.figures`; else the geometry's estimate); with ``--run`` also the annual ideal-loads heating and cooling need (kWh, kWh/m2a of conditioned
  floor area) and peak loads (W) from the building's IDF record.

The file is written through :mod:`lod2energy.safe_write` and self-checked by re-reading it
(:func:`self_check`).
"""
from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, shape
from shapely.validation import explain_validity

from lod2energy.energy.downgrades import summed
from lod2energy.energy.figures import AREA_KEYS
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.io.json_stream import Scanner
from lod2energy.model import Building
from lod2energy.safe_write import atomic_write
from lod2energy.site import SiteError, to_wgs84
from lod2energy.thermal.storeys import storeys
from lod2energy.thermal.use import building_use

#: Decimal places of the coordinates (1e-8 degree is about 1 mm).
DECIMALS = 8
#: Snapping grid of the footprint union, m (ten times the coordinates' precision, so that no
#: two vertices of the snapped footprint fall on one rounded position).
GRID = 0.01
#: Footprint pieces and holes smaller than this are dropped, m2.
MIN_AREA = 0.01
#: Run figures copied from the building's IDF record (``ExportRecord.extra``).
RUN_KEYS = ("heating_kwh", "cooling_kwh", "heating_kwh_m2", "cooling_kwh_m2", "heating_peak_w",
            "cooling_peak_w", "conditioned_floor_area_m2")
SUFFIX = ".footprints.geojson"


# ----------------------------------------------------------------------------- footprint

def footprint(b: Building, lod: str | None = None):
    """The building's footprint: union of its envelope faces' projections on the xy plane.

    Parameters
    ----------
    b : Building
        Coordinates in metres (a projected CRS, or the local frame of a geographic file).
    lod : str, optional
        The envelope's LoD (default: the building's highest).

    Returns
    -------
    shapely Polygon or MultiPolygon, or None
        In the building's xy coordinates (m); None when no face has a projected area.
    """
    v = np.asarray(b.vertices, dtype=np.float64)
    polys = []
    for _, _, g in b.envelope(lod):
        for _, hi, _, s in g.iter_surfaces():
            if hi > 0:
                continue
            rings = [v[np.asarray(r, dtype=np.intp)][:, :2] for r in s.rings]
            if len(rings[0]) < 3 or not np.all(np.isfinite(rings[0])):
                continue
            p = Polygon(rings[0], [r for r in rings[1:] if len(r) >= 3])
            if not p.is_valid:
                p = shapely.make_valid(p)
            if p.area > 1e-9:
                polys.append(p)
    if not polys:
        return None
    u = shapely.union_all(polys, grid_size=GRID)
    parts = [g for g in getattr(u, "geoms", [u]) if g.geom_type == "Polygon" and g.area >= MIN_AREA]
    if not parts:
        return None
    clean = [Polygon(p.exterior.coords, [h.coords for h in p.interiors if Polygon(h).area >= MIN_AREA])
             for p in parts]
    return clean[0] if len(clean) == 1 else MultiPolygon(clean)


def _ring_lonlat(xy: np.ndarray, z: float, crs: Any, frame) -> list[list[float]]:
    p = np.column_stack([xy, np.full(len(xy), z)])
    ll = to_wgs84(p, crs, frame)
    return [[round(float(lon), DECIMALS), round(float(lat), DECIMALS)] for lat, lon in ll]


def _signed_area(ring: Sequence[Sequence[float]]) -> float:
    a = np.asarray(ring, dtype=np.float64)
    return 0.5 * float(np.sum(a[:-1, 0] * a[1:, 1] - a[1:, 0] * a[:-1, 1]))


def _oriented(ring: list, ccw: bool) -> list:
    return ring if (_signed_area(ring) > 0) == ccw else ring[::-1]


def footprint_geometry(b: Building, crs: Any = None, frame=None, lod: str | None = None) -> dict | None:
    """The GeoJSON geometry (WGS84, ``[lon, lat]``, RFC 7946 winding) of ``b``'s footprint.

    Raises
    ------
    lod2energy.site.SiteError
        The coordinates cannot be placed on the Earth (no CRS, unknown CRS).
    """
    fp = footprint(b, lod)
    if fp is None:
        return None
    v = np.asarray(b.vertices, dtype=np.float64)
    fin = v[np.all(np.isfinite(v), axis=1)]
    z = float(fin[:, 2].min()) if len(fin) else 0.0
    # one transform of all the rings together: to_wgs84 chooses the axis order once per call
    rings = []
    for p in getattr(fp, "geoms", [fp]):
        rings.append([np.asarray(p.exterior.coords)[:, :2]] + [np.asarray(h.coords)[:, :2] for h in p.interiors])
    flat = np.concatenate([r for poly in rings for r in poly])
    ll = _ring_lonlat(flat, z, crs, frame)
    polys, k = [], 0
    for poly in rings:
        out = []
        for i, r in enumerate(poly):
            ring = ll[k:k + len(r)]
            k += len(r)
            ring[-1] = list(ring[0])
            out.append(_oriented(ring, ccw=(i == 0)))
        polys.append(out)
    if len(polys) == 1:
        return {"type": "Polygon", "coordinates": polys[0]}
    return {"type": "MultiPolygon", "coordinates": polys}


# ----------------------------------------------------------------------------- properties

def _plain(x):
    if isinstance(x, (np.generic,)):
        x = x.item()
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def properties(b: Building, record=None, use: str | None = None, lod: str | None = None,
               run: bool = False) -> dict:
    """The Feature properties of ``b`` (see the module docstring).

    Parameters
    ----------
    b : Building
        The prepared building (``provenance["energy"]``, ``["thermal"]``, ``["repair"]``).
    record : lod2energy.records.BuildingRecord, optional
        Its record: repair, compliance and the IDF export's run figures.
    use : str, optional
        The ``--use`` override.
    run : bool
        Add the run figures (None where the record has none).
    """
    energy = dict(b.provenance.get("energy") or {})
    thermal = dict(b.provenance.get("thermal") or {})
    u = building_use(b, use)
    try:
        st = storeys(b, u.type, lod)
        n_st, st_src = int(st.count), st.source
    except Exception:  # noqa: BLE001 - no storey figure is not a reason to drop the footprint
        n_st, st_src = None, None
    stage = ""
    out_errors: list[int] = []
    if record is not None:
        stage = record.repair.stage or str(record.repair.detail.get("stage", ""))
        out_errors = sorted(set(int(c) for c in record.output_errors))
        energy = dict(record.energy.detail) or energy
    else:
        stage = str((b.provenance.get("repair") or {}).get("stage", ""))
    props = {"id": str(b.id), "type": b.type, "repair_stage": stage or None,
             "input_valid": (stage == "valid") if stage else None,
             "output_errors": " ".join(map(str, out_errors)),
             "compliant": energy.get("compliant"), "geometry_ready": energy.get("geometry_ready"),
             "status": energy.get("status") or None,
             "storeys": n_st, "storeys_source": st_src, "use": u.type, "use_source": u.source,
             "typology": thermal.get("typology") or None,
             "construction_period": thermal.get("construction_period") or None}
    th = dict(record.thermal.detail) if record is not None and record.thermal.detail else thermal
    areas = th.get("areas") or {}
    props.update(UA_W_per_K=th.get("UA"), A_env_m2=th.get("A_env"),
                 **{f"{k}_m2": areas.get(k) for k in AREA_KEYS}, figures_source=th.get("figures_source"))
    down = tuple(record.downgrades) if record is not None else ()
    dh, dv, da = summed(down)
    props.update(downgrades=" ".join(f"{d.kind}:{d.zone}" for d in down) or None,
                 downgrade_d_height_m=dh if down else None, downgrade_d_volume_m3=dv if down else None,
                 downgrade_d_floor_area_m2=da if down else None)
    if run:
        idf = record.export("idf") if record is not None else None
        extra = idf.values() if idf is not None else {}
        for k in RUN_KEYS:
            props[k] = _plain(extra.get(k))
    return {k: _plain(v) for k, v in props.items()}


# ----------------------------------------------------------------------------- file

def write(buildings: Iterable[Building], path: str | os.PathLike, *, crs: Any = None, frame=None,
          records: Sequence | None = None, use: str | None = None, lod: str | None = None, run: bool = False,
          root: str | os.PathLike | None = None) -> ExportResult:
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
    use, lod, run :
        See :func:`properties`.
    root : path, optional
        The folder the file must stay in (:func:`lod2energy.safe_write.check_target`).
    """
    records = records or ()
    by_id = {r.id: i for i, r in enumerate(records)}  # the index: a record may be rebuilt when read
    ids, left_out, seen = [], {}, []
    name = Path(path).name[:-len(SUFFIX)] if str(path).endswith(SUFFIX) else Path(path).stem
    head = _dumps({"type": "FeatureCollection", "name": name, "features": []})
    # one Feature at a time: the bytes of json.dumps of the whole collection
    with atomic_write(path, "w", root=root) as f:
        f.write(head[:-2])
        for b in buildings:
            if not b.is_building:
                continue
            seen.append(str(b.id))
            try:
                geom = footprint_geometry(b, crs, frame, lod)
            except SiteError as e:
                left_out[str(b.id)] = str(e)
                continue
            if geom is None:
                left_out[str(b.id)] = "no face with a projected area"
                continue
            f.write(("," if ids else "") + _dumps({"type": "Feature", "id": str(b.id),
                                                  "properties": properties(b, records[by_id[str(b.id)]] if str(b.id) in by_id else None,
                                                                         use, lod, run),
                                                  "geometry": geom}))
            ids.append(str(b.id))
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

    Re-reads the JSON and checks: a FeatureCollection of ``n_features`` Features, each with a
    Polygon / MultiPolygon of closed rings of ``[lon, lat]`` in range, exterior rings
    counter-clockwise and holes clockwise (RFC 7946 3.1.6), a valid polygon (shapely) and an id.
    The file is read one Feature at a time (:class:`lod2energy.io.json_stream.Scanner`).
    """
    try:
        problems, head, n = [], {}, 0
        for i, ft in _features(path, head):
            n += 1
            if len(problems) <= 20:
                problems += _feature_problems(path, i, ft)
    except (OSError, ValueError) as e:
        return [f"{path}: not readable as JSON: {e}"]
    if head.get("type") != "FeatureCollection" or not isinstance(head.get("features"), list):
        return [f"{path}: not a FeatureCollection"]
    if n_features is not None and n != n_features:
        problems.insert(0, f"{path}: {n} features, {n_features} written")
    return problems


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
    ``options`` are the IDF options (``use``, ``lod``, ``run``: the figures of the energy model)."""
    path = os.path.join(str(outdir), f"{stem}{SUFFIX}")
    return [write(buildings, path, crs=crs, frame=frame, records=records, use=getattr(options, "use", None),
                  lod=getattr(options, "lod", None), run=bool(getattr(options, "run", False)), root=outdir)]


# after "idf": the footprints carry the run figures of the IDF pass
register_writer("geojson", _write, self_check, scope="dataset", records=True)
