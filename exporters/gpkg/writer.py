"""GeoPackage of building footprints (``--gpkg``): the GeoJSON's layer with declared field types.

One layer (named as the file's stem) of MultiPolygons in WGS84 (EPSG:4326, longitude as x),
one row per exported building, its fields those of the GeoJSON
(:data:`lod2energy.exporters.geojson.writer.FIELDS`, documented there) with their types
declared: ``str`` as String, ``int`` as Integer, ``float`` as Real, ``bool`` as Integer of
subtype Boolean; null where unknown. Rows, geometries and values are the GeoJSON's
(:func:`lod2energy.exporters.geojson.writer.features`).

Written with pyogrio (GDAL's GPKG driver) into a temporary folder beside the target, read back
by :func:`self_check` (one row per building, the declared fields and types, the values
written), and only then renamed to ``<stem>.footprints.gpkg``; a file that fails its check is
kept as ``<stem>.footprints.gpkg.invalid``.
"""
from __future__ import annotations

import math
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any, Iterable, Sequence

import numpy as np
import pyogrio
import pyogrio.raw
import shapely
from shapely.geometry import shape

from lod2energy.exporters.geojson.writer import FIELDS, features, layer_key
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.model import Building
from lod2energy.safe_write import INVALID_SUFFIX, check_target

SUFFIX = ".footprints.gpkg"
CRS = "EPSG:4326"
#: numpy dtype a field type is written from.
DTYPES = {str: object, int: np.int32, float: np.float64, bool: np.bool_}
#: GDAL's ``(type, subtype)`` of a field type.
OGR_TYPES = {str: ("OFTString", "OFSTNone"), int: ("OFTInteger", "OFSTNone"), float: ("OFTReal", "OFSTNone"),
             bool: ("OFTInteger", "OFSTBoolean")}


def columns(rows: Sequence[dict]) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """The field arrays (:data:`DTYPES`) and null masks (True: null) of properties ``rows``,
    in the order of :data:`FIELDS`."""
    values, masks = [], []
    for k, t in FIELDS.items():
        raw = [r[k] for r in rows]
        mask = np.array([v is None for v in raw], dtype=bool)
        fill = {str: None, int: 0, float: 0.0, bool: False}[t]
        values.append(np.array([fill if v is None else v for v in raw], dtype=DTYPES[t]))
        masks.append(mask)
    return values, masks


def _plain(v: Any, t: type) -> Any:
    """A value read back by pyogrio as the GeoJSON has it (NaN: null)."""
    if isinstance(v, np.generic):
        v = v.item()
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return None
    return {str: str, int: int, float: float, bool: bool}[t](v)


def self_check(path: str, ids: Sequence[str] | None = None, rows: Sequence[dict] | None = None) -> list[str]:
    """Problems of a written GeoPackage (empty: good), read back with pyogrio: one layer of
    MultiPolygons in EPSG:4326 with the fields of :data:`FIELDS` of their declared types
    (:data:`OGR_TYPES`), valid geometries, and, when given, the rows' ``ids`` and property
    values ``rows``."""
    try:
        layers = pyogrio.list_layers(path)
        meta, _, wkb, values = pyogrio.raw.read(path)
    except Exception as e:  # noqa: BLE001 - GDAL's errors: the file is not a readable layer
        return [f"{path}: not readable: {e}"]
    problems = []
    if len(layers) != 1:
        problems.append(f"{path}: {len(layers)} layers, not one")
    if meta.get("geometry_type") != "MultiPolygon" or meta.get("crs") != CRS:
        problems.append(f"{path}: geometry {meta.get('geometry_type')} in {meta.get('crs')}, not MultiPolygon in {CRS}")
    names = list(meta["fields"])
    if names != list(FIELDS):
        return problems + [f"{path}: fields {names} are not the layer's {list(FIELDS)}"]
    for k, ot, st in zip(names, meta["ogr_types"], meta["ogr_subtypes"]):
        if (ot, st) != OGR_TYPES[FIELDS[k]]:
            problems.append(f"{path}: field {k} is {ot}/{st}, not {'/'.join(OGR_TYPES[FIELDS[k]])}")
    geoms = shapely.from_wkb(wkb)
    if any(g is None or g.geom_type != "MultiPolygon" or not g.is_valid or g.area <= 0 for g in geoms):
        problems.append(f"{path}: a footprint is not a valid MultiPolygon")
    cols = dict(zip(names, values))
    if ids is not None and [str(v) for v in cols["id"]] != [str(i) for i in ids]:
        problems.append(f"{path}: {len(geoms)} rows, not the {len(ids)} buildings written")
    if rows is not None and len(rows) == len(geoms) and not problems:
        for k, t in FIELDS.items():
            bad = [i for i, r in enumerate(rows) if _plain(cols[k][i], t) != r[k]]
            if bad:
                problems.append(f"{path}: field {k} of row {bad[0]} reads {cols[k][bad[0]]!r}, {rows[bad[0]][k]!r} written")
                break
    return problems


def write(buildings: Iterable[Building], path: str | os.PathLike, *, crs: Any = None, frame=None,
          records: Sequence | None = None, use: str | None = None, lod: str | None = None,
          attic: str = "unconditioned", root: str | os.PathLike | None = None, keep: Any = None) -> ExportResult:
    """Write the footprint layer of ``buildings`` to GeoPackage ``path`` and self-check it.

    Parameters are those of :func:`lod2energy.exporters.geojson.writer.write`; ``keep``: the
    layer's key, to keep its geometry and facts for the GeoJSON writer of the same export.
    """
    path = Path(path)
    ids, geoms, rows, left_out, seen = [], [], [], {}, []
    for bid, geom, props in features(buildings, records, crs=crs, frame=frame, use=use, lod=lod, attic=attic,
                                     keep=keep):
        seen.append(bid)
        if geom is None:
            left_out[bid] = props
            continue
        ids.append(bid)
        geoms.append(shape(geom))
        rows.append(props)
    check_target(path, root)
    path.parent.mkdir(parents=True, exist_ok=True)
    layer = path.name[:-len(SUFFIX)] if path.name.endswith(SUFFIX) else path.stem
    tmp = Path(tempfile.mkdtemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent))
    try:
        staged = tmp / path.name
        values, masks = columns(rows)
        try:
            pyogrio.raw.write(str(staged), np.asarray(shapely.to_wkb(geoms), dtype=object) if geoms
                              else np.zeros(0, dtype=object), values, list(FIELDS), field_mask=masks, layer=layer,
                              driver="GPKG", geometry_type="MultiPolygon", crs=CRS, encoding="UTF-8")
        except Exception as e:  # noqa: BLE001 - GDAL's errors: nothing written under the good name
            problems = [f"{path}: not written: {e}"]
            return ExportResult(tuple(ids), str(path), False, tuple(problems), None, given=tuple(seen),
                                skipped=tuple(left_out.items()))
        problems = self_check(str(staged), ids, rows)
        target = path if not problems else path.with_name(path.name + INVALID_SUFFIX)
        check_target(target, root)
        os.replace(staged, target)
        if problems and path.exists() and not path.is_symlink():
            path.unlink()  # an older good-looking file of this name would now be a lie
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    problems = [p.replace(str(staged), str(path)) for p in problems]
    return ExportResult(tuple(ids), str(target), not problems, tuple(problems), None, given=tuple(seen),
                        skipped=tuple(left_out.items()))


def _write(buildings, outdir, options, *, crs=None, frame=None, records=None, stem="out", **_):
    """``OUTDIR/<stem>.footprints.gpkg``; ``options`` are the IDF options (as the GeoJSON's)."""
    path = os.path.join(str(outdir), f"{stem}{SUFFIX}")
    return [write(buildings, path, crs=crs, frame=frame, records=records, use=getattr(options, "use", None),
                  lod=getattr(options, "lod", None), attic=getattr(options, "attic", None) or "unconditioned",
                  root=outdir, keep=layer_key(outdir, stem, crs, frame, options))]


# before "geojson", which takes the geometry and facts it keeps; after "idf": the run figures included
register_writer("gpkg", _write, self_check, scope="dataset", records=True)
