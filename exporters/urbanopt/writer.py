"""URBANopt FeatureFile: the buildings as URBANopt's GeoJSON reads them (``--urbanopt``).

One ``FeatureCollection`` with a ``project`` block (URBANopt's site properties: id, name, the
buildings' mean latitude / longitude, the weather file's name with ``--weather EPW``) and one
Feature per exported building:

- **geometry**: the footprint in WGS84 ``[lon, lat]`` as the GeoJSON writer writes it
  (:func:`lod2energy.exporters.geojson.writer.footprint_geometry`; Polygon or MultiPolygon);
- **properties**, named and typed as URBANopt's ``building_properties.json`` (urbanopt-geojson-gem)
  asks, in its units (feet, square feet): ``id``, ``name``, ``type: "Building"``,
  ``building_type`` (:data:`BUILDING_TYPE`), ``floor_area`` (gross floor area of the storeys),
  ``number_of_stories`` and ``number_of_stories_above_ground`` (LoD2 has no basements: equal),
  ``footprint_area``, ``footprint_perimeter``, ``maximum_roof_height`` (ridge over ground),
  ``year_built`` when known, ``source_name`` / ``source_id``; and ``user_data.lod2energy``
  with the same figures in metres and where each came from (:mod:`lod2energy.exporters.handoff`).

Our use types map to URBANopt's ``building_type`` enum by :data:`BUILDING_TYPE`:

=============  ===========================  ====================================================
ours           URBANopt ``building_type``   why
=============  ===========================  ====================================================
residential    Multifamily                  LoD2 does not say how many dwellings; URBANopt's
                                            residential workflow then needs
                                            ``number_of_residential_units`` and bedrooms added
office         Office
retail         Retail other than mall
education      Education
health         Outpatient health care       the common case; hospitals are "Inpatient ..."
hospitality    Lodging
industry       Nonrefrigerated warehouse    URBANopt has no industrial type
other          Service                      CBECS "service" buildings
=============  ===========================  ====================================================

The file is written through a staged temporary and given its name only when its self-check
(:func:`self_check`) passes.
"""
from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any, Iterable

from lod2energy.exporters.geojson.writer import _features, _feature_problems
from lod2energy.exporters.handoff import placed
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.model import Building
from lod2energy.safe_write import write_checked

SUFFIX = ".urbanopt.geojson"
#: Our use type -> URBANopt ``building_type`` (see the module docstring).
BUILDING_TYPE = {"residential": "Multifamily", "office": "Office", "retail": "Retail other than mall",
                 "education": "Education", "health": "Outpatient health care", "hospitality": "Lodging",
                 "industry": "Nonrefrigerated warehouse", "other": "Service"}
FT = 1.0 / 0.3048  # feet per metre
FT2 = FT * FT
#: Properties every Building feature must have, with their JSON types (URBANopt's ``required``).
REQUIRED = {"id": str, "type": str, "name": str, "floor_area": (int, float), "number_of_stories": int,
            "footprint_area": (int, float), "building_type": str}


def properties(h, source: str = "lod2energy") -> dict:
    """URBANopt Building properties of :class:`~lod2energy.exporters.handoff.HandoffFacts` ``h``."""
    props = {"id": h.id, "name": h.id, "type": "Building", "source_name": source, "source_id": h.id,
             "building_type": BUILDING_TYPE.get(h.use, BUILDING_TYPE["other"]),
             "floor_area": round(h.floor_area * FT2, 1),
             "number_of_stories": int(h.storeys), "number_of_stories_above_ground": int(h.storeys),
             "footprint_area": round(h.footprint_area * FT2, 1),
             "footprint_perimeter": round(h.footprint_perimeter * FT, 2),
             "maximum_roof_height": round(h.height * FT, 2)}
    if h.year is not None:
        props["year_built"] = int(h.year)
    props["user_data"] = {"lod2energy": {
        "use": h.use, "use_source": h.use_source, "storeys_source": h.storeys_source,
        "storey_height_m": round(h.storey_height, 3), "attic_storey": h.attic, "height_m": round(h.height, 3),
        "floor_area_m2": round(h.floor_area, 2), "footprint_area_m2": round(h.footprint_area, 2),
        "volume_m3": round(h.volume, 2) if h.volume else None, "year_source": h.year_source}}
    return props


def _centre(geom: dict) -> tuple[float, float]:
    """Mean ``(lon, lat)`` of a GeoJSON (Multi)Polygon's outer ring vertices."""
    polys = [geom["coordinates"]] if geom["type"] == "Polygon" else geom["coordinates"]
    pts = [p for poly in polys for p in poly[0][:-1]]
    return sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts)


def write(buildings: Iterable[Building], path: str | os.PathLike, *, crs: Any = None, frame=None,
          use: str | None = None, lod: str | None = None, attic: str = "unconditioned",
          weather: str | None = None, root: str | os.PathLike | None = None) -> ExportResult:
    """Write the URBANopt FeatureFile of ``buildings`` to ``path`` and self-check it.

    Parameters
    ----------
    buildings : iterable of Building
        Prepared buildings, coordinates in metres.
    path : path
    crs, frame :
        As :func:`lod2energy.exporters.geojson.writer.write`.
    use, lod, attic :
        See :func:`lod2energy.exporters.handoff.facts`.
    weather : str, optional
        The EPW file: its name becomes the project's ``weather_filename``.
    root : path, optional
        The folder the file must stay in.
    """
    ids, left_out, seen = [], {}, []
    lon_lat = [0.0, 0.0]
    name = Path(path).name[:-len(SUFFIX)] if str(path).endswith(SUFFIX) else Path(path).stem

    def body(f) -> None:
        f.write('{"type":"FeatureCollection","name":' + _dumps(name) + ',"features":[')
        for b in buildings:
            if not b.is_building:
                continue
            seen.append(str(b.id))
            geom, h, why = placed(b, crs, frame, lod, use, attic)
            if why:
                left_out[str(b.id)] = why
                continue
            f.write(("," if ids else "") + _dumps({"type": "Feature", "id": h.id, "properties": properties(h),
                                                  "geometry": geom}))
            ids.append(h.id)
            lon, lat = _centre(geom)
            lon_lat[0] += lon
            lon_lat[1] += lat
        project = {"id": name, "name": name}
        if ids:
            project.update(longitude=round(lon_lat[0] / len(ids), 6), latitude=round(lon_lat[1] / len(ids), 6))
        if weather and os.path.isfile(weather):
            project["weather_filename"] = os.path.basename(weather)
        f.write('],"project":' + _dumps(project) + "}\n")

    # the check runs after ``body``: ``ids`` then holds the features written
    final, problems = write_checked(path, body, lambda p: self_check(str(p), n_features=len(ids)), root=root)
    return ExportResult(tuple(ids), final or str(path), not problems, tuple(problems), None, given=tuple(seen),
                        skipped=tuple(left_out.items()))


def _dumps(x) -> str:
    return json.dumps(x, ensure_ascii=False, separators=(",", ":"), allow_nan=False)


def _property_problems(where: str, props: Any) -> list[str]:
    if not isinstance(props, dict):
        return [f"{where}: no properties"]
    for k, t in REQUIRED.items():
        v = props.get(k)
        if not isinstance(v, t) or isinstance(v, bool) or (isinstance(v, float) and not math.isfinite(v)):
            return [f"{where}: property {k!r} missing or not {getattr(t, '__name__', 'a number')}"]
    if props["type"] != "Building" or props["building_type"] not in BUILDING_TYPE.values():
        return [f"{where}: not a Building of a known building_type"]
    if props["number_of_stories"] < 1 or not props["floor_area"] > 0 or not props["footprint_area"] > 0:
        return [f"{where}: no storey, floor area or footprint area"]
    return []


def self_check(path: str, n_features: int | None = None) -> list[str]:
    """Problems of a written FeatureFile (empty: good): a FeatureCollection with a ``project``
    object and ``n_features`` Features, each a valid footprint (as the GeoJSON writer's check)
    with URBANopt's required Building properties, typed."""
    try:
        problems, head, n = [], {}, 0
        for i, ft in _features(path, head):
            n += 1
            if len(problems) <= 20:
                bad = _feature_problems(path, i, ft)
                problems += bad or _property_problems(f"{path}: feature {i}", ft.get("properties"))
    except (OSError, ValueError) as e:
        return [f"{path}: not readable as JSON: {e}"]
    if head.get("type") != "FeatureCollection" or not isinstance(head.get("features"), list):
        return [f"{path}: not a FeatureCollection"]
    if not isinstance(head.get("project"), dict):
        problems.append(f"{path}: no project object")
    if n_features is not None and n != n_features:
        problems.insert(0, f"{path}: {n} features, {n_features} written")
    return problems


def _write(buildings, outdir, options, *, crs=None, frame=None, stem="out", **_):
    """``OUTDIR/<stem>.urbanopt.geojson``; ``options`` are the IDF options (``use``, ``lod``,
    ``attic``, ``weather``: the energy model's)."""
    path = os.path.join(str(outdir), f"{stem}{SUFFIX}")
    weather = getattr(options, "weather", None)
    return [write(buildings, path, crs=crs, frame=frame, use=getattr(options, "use", None),
                  lod=getattr(options, "lod", None), attic=getattr(options, "attic", None) or "unconditioned",
                  weather=weather if isinstance(weather, str) else None, root=outdir)]


register_writer("urbanopt", _write, self_check, scope="dataset")
