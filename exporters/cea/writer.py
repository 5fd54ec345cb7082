"""City Energy Analyst zone table: the buildings as CEA 4 reads a scenario's ``zone.shp`` (``--cea``).

CEA 4 reads one table of footprints and their typology, ``inputs/building-geometry/zone.shp``
(``cea/datamanagement/databases_verification.py``: ``COLUMNS_ZONE``; types and bounds in
``cea/schemas.yml``, ``get_zone_geometry``); earlier versions split the typology into
``typology.dbf`` with the same columns. It is written with pyogrio into
``OUTDIR/<input>.cea/inputs/building-geometry/``, a scenario folder to copy into a CEA project,
in the UTM zone of the buildings (CEA's own choice, ``get_projected_coordinate_system``), one
row per exported building (:data:`FIELDS`):

- ``name``: the id as a file-name stem (:func:`lod2energy.exporters.paths.safe_stem`: CEA
  names its result files after it), ``B`` in front when it does not start with a letter, as
  CEA asks; ``reference``: the id itself;
- ``floors_ag``: our storeys, ``floors_bg`` / ``height_bg`` / ``void_deck`` 0 (LoD2 shows no
  basement);
- ``height_ag``: the height of the prism on the footprint with the building's volume (CEA
  extrudes the footprint: its heated volume stays ours; :attr:`HandoffFacts.prism_height`);
- ``year``: the year of construction, else the year the thermal stage looked the U-values up
  for (:data:`lod2energy.thermal.typology.DEFAULT_YEAR`); ``const_type`` from it by CEA's rule
  (the first of its construction types whose years hold it) over its default database's years
  (:data:`CONST_TYPES`);
- ``use_type1`` from our use (:data:`USE_TYPE`; "other" takes the commonest use type of the
  file, else ``MULTI_RES``, as CEA's zone helper does), ``use_type1r`` 1, the second and third
  use ``NONE`` with 0.

CEA needs Polygons: a footprint of detached pieces gives its largest piece (a note says how
many); a building lower than CEA's 2 m, or lower than 1 m a storey, is left out with the reason.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from collections import Counter
from pathlib import Path
from typing import Any, Iterable

import numpy as np
import pyogrio
import pyogrio.raw
import shapely
from pyproj import CRS, Transformer
from shapely.geometry import shape

from lod2energy.exporters.handoff import placed
from lod2energy.exporters.paths import safe_stem
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.model import Building
from lod2energy.safe_write import check_target
from lod2energy.thermal.typology import DEFAULT_YEAR

#: Where CEA reads the zone table, under the scenario folder.
ZONE = os.path.join("inputs", "building-geometry", "zone.shp")
SCENARIO_SUFFIX = ".cea"
#: The columns written, in order, with their numpy types (CEA 4's ``COLUMNS_ZONE`` but the
#: address columns, which CEA fills with nothing either).
FIELDS = {"name": object, "floors_bg": np.int32, "floors_ag": np.int32, "void_deck": np.int32,
          "height_bg": np.float64, "height_ag": np.float64, "reference": object, "year": np.int32,
          "const_type": object, "use_type1": object, "use_type1r": np.float64, "use_type2": object,
          "use_type2r": np.float64, "use_type3": object, "use_type3r": np.float64}
#: Our use type -> CEA use type (its ``ARCHETYPES/USE/USE_TYPES.csv``); "other": see the module docstring.
USE_TYPE = {"residential": "MULTI_RES", "office": "OFFICE", "retail": "RETAIL", "education": "SCHOOL",
            "health": "HOSPITAL", "hospitality": "HOTEL", "industry": "INDUSTRIAL", "other": None}
#: CEA's default construction types and their years (``cea/databases/CH/ARCHETYPES/CONSTRUCTION/
#: CONSTRUCTION_TYPES.csv``: ``const_type, year_start, year_end``); STANDARD6 (Minergie) is
#: never the first match and is left out.
CONST_TYPES = (("STANDARD1", 1000, 1920), ("STANDARD2", 1921, 1970), ("STANDARD3", 1971, 1980),
               ("STANDARD4", 1981, 2000), ("STANDARD5", 2000, 2040))
#: The longest text a shapefile (dBASE) field holds, bytes.
MAX_TEXT = 254
#: CEA refuses lower buildings (``schemas.yml``: ``height_ag`` min 2.0 m; at least 1 m a floor).
MIN_HEIGHT = 2.0


def const_type(year: int) -> str:
    """CEA's construction type of ``year``: the first of :data:`CONST_TYPES` whose years hold it,
    else the first (CEA's ``calc_category``)."""
    for name, start, end in CONST_TYPES:
        if start <= year <= end:
            return name
    return CONST_TYPES[0][0]


def utm_crs(lon: float, lat: float) -> CRS:
    """The WGS84 UTM zone of a point (degrees)."""
    zone = int((lon + 180.0) // 6.0) % 60 + 1
    return CRS.from_epsg((32600 if lat >= 0 else 32700) + zone)


def scenario_path(outdir: str | os.PathLike, stem: str) -> Path:
    """``OUTDIR/<stem>.cea/inputs/building-geometry/zone.shp``."""
    return Path(outdir) / f"{stem}{SCENARIO_SUFFIX}" / ZONE


def write(buildings: Iterable[Building], path: str | os.PathLike, *, crs: Any = None, frame=None,
          use: str | None = None, lod: str | None = None, attic: str = "unconditioned",
          root: str | os.PathLike | None = None) -> ExportResult:
    """Write CEA's zone table of ``buildings`` to ``path`` (``zone.shp`` and its sidecars) and
    self-check it.

    Parameters
    ----------
    buildings : iterable of Building
        Prepared buildings, coordinates in metres.
    path : path
        The ``.shp`` file; its folder is created.
    crs, frame :
        As :func:`lod2energy.exporters.geojson.writer.write`.
    use, lod, attic :
        See :func:`lod2energy.exporters.handoff.facts`.
    root : path, optional
        The folder every file must stay in.
    """
    path = Path(path)
    rows, polys, left_out, seen, used = [], [], {}, [], set()
    split = 0
    for b in buildings:
        if not b.is_building:
            continue
        seen.append(str(b.id))
        if len(str(b.id).encode("utf-8")) > MAX_TEXT:
            left_out[str(b.id)] = f"CEA: the id is longer than a shapefile field holds ({MAX_TEXT} bytes)"
            continue
        geom, h, why = placed(b, crs, frame, lod, use, attic)
        if why:
            left_out[str(b.id)] = why
            continue
        height = h.prism_height
        if height < max(MIN_HEIGHT, float(h.storeys)):
            left_out[str(b.id)] = (f"CEA: {height:.2f} m high for {h.storeys} storeys, below CEA's minimum "
                                   f"({MIN_HEIGHT:g} m, 1 m a storey)")
            continue
        poly = shape(geom)
        if poly.geom_type == "MultiPolygon":
            poly = max(poly.geoms, key=lambda p: p.area)
            split += 1
        name = safe_stem(h.id, used)
        if not name[:1].isalpha():
            name = "B" + name
        year = h.year if h.year is not None else DEFAULT_YEAR
        rows.append({"name": name, "floors_bg": 0, "floors_ag": h.storeys, "void_deck": 0, "height_bg": 0.0,
                     "height_ag": round(height, 3), "reference": h.id, "year": year,
                     "const_type": const_type(year), "use_type1": USE_TYPE.get(h.use), "use_type1r": 1.0,
                     "use_type2": "NONE", "use_type2r": 0.0, "use_type3": "NONE", "use_type3r": 0.0})
        polys.append(poly)
    ids = tuple(r["reference"] for r in rows)
    notes = ()
    if split:
        notes = (f"CEA: {split} footprints of detached pieces written as their largest piece (CEA takes Polygons)",)
    if not rows:
        return ExportResult((), str(path), True, (), None, given=tuple(seen), skipped=tuple(left_out.items()),
                            notes=notes)
    known = Counter(r["use_type1"] for r in rows if r["use_type1"] is not None)
    fallback = known.most_common(1)[0][0] if known else "MULTI_RES"
    for r in rows:
        r["use_type1"] = r["use_type1"] or fallback
    centre = shapely.centroid(shapely.MultiPoint([p.centroid for p in polys]))
    utm = utm_crs(centre.x, centre.y)
    to_utm = Transformer.from_crs("EPSG:4326", utm, always_xy=True)
    projected = shapely.transform(polys, lambda xy: np.column_stack(to_utm.transform(xy[:, 0], xy[:, 1])))
    wkb = np.asarray(shapely.to_wkb(projected), dtype=object)
    fields = {k: np.array([r[k] for r in rows], dtype=t) for k, t in FIELDS.items()}
    problems = _write_shapefile(path, wkb, fields, utm, root)
    if not problems:
        problems = self_check(str(path), n_rows=len(rows), ids=ids)
    if problems and path.exists():
        _set_aside(path)
        problems.append(f"failed its self-check: kept as {path.name}.invalid")
    sidecars = tuple(str(p) for p in _companions(path)[1:] if p.exists()) if not problems else ()
    return ExportResult(ids, str(path) if not problems else f"{path}.invalid", not problems, tuple(problems), None,
                        sidecars=sidecars, given=tuple(seen), skipped=tuple(left_out.items()), notes=notes)


def _companions(path: Path) -> list[Path]:
    stem = path.with_suffix("")
    return [stem.with_suffix(s) for s in (".shp", ".shx", ".dbf", ".prj", ".cpg")]


def _write_shapefile(path: Path, wkb: np.ndarray, fields: dict, crs: CRS, root) -> list[str]:
    """Write through a temporary folder beside ``path``; its files take their names only once
    the whole table is written (a half table never sits under ``zone.shp``)."""
    for p in _companions(path):
        check_target(p, root)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{path.stem}.", suffix=".part", dir=path.parent))
    try:
        staged = tmp / path.name
        pyogrio.raw.write(str(staged), wkb, list(fields.values()), list(fields), crs=crs.to_wkt(),
                          geometry_type="Polygon", driver="ESRI Shapefile", encoding="UTF-8")
        for p in _companions(staged):
            if p.exists():
                os.replace(p, path.parent / p.name)
    except OSError as e:
        return [f"{path}: not written: {e.strerror or e}"]
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return []


def _set_aside(path: Path) -> None:
    for p in _companions(path):
        if p.exists():
            os.replace(p, p.with_name(p.name + ".invalid"))


def self_check(path: str, n_rows: int | None = None, ids: tuple[str, ...] | None = None) -> list[str]:
    """Problems of a written zone table (empty: good), read back through pyogrio: the columns of
    :data:`FIELDS`, ``n_rows`` Polygons in a projected CRS, unique names starting with a
    letter, no empty value, at least one floor and :data:`MIN_HEIGHT` (and 1 m a floor) above
    ground, and the ``reference`` column ``ids`` when given."""
    try:
        meta, _, wkb, values = pyogrio.raw.read(path)
    except Exception as e:  # noqa: BLE001 - GDAL's errors: the file is not a readable table
        return [f"{path}: not readable: {e}"]
    cols = dict(zip(meta["fields"], values))
    missing = [k for k in FIELDS if k not in cols]
    if missing:
        return [f"{path}: columns missing: {', '.join(missing)}"]
    problems = []
    if n_rows is not None and len(wkb) != n_rows:
        problems.append(f"{path}: {len(wkb)} rows, {n_rows} written")
    if not meta.get("crs") or not CRS.from_user_input(meta["crs"]).is_projected:
        problems.append(f"{path}: not in a projected CRS")
    if ids is not None and [str(r) for r in cols["reference"]] != list(ids):
        problems.append(f"{path}: the reference column is not the ids written")
    geoms = shapely.from_wkb(wkb)
    if any(g is None or g.geom_type != "Polygon" or not g.is_valid or g.area <= 0 for g in geoms):
        problems.append(f"{path}: a footprint is not a valid Polygon")
    names = [str(n) for n in cols["name"]]
    if len(set(names)) != len(names) or not all(n[:1].isalpha() for n in names):
        problems.append(f"{path}: names not unique or not starting with a letter")
    for k in FIELDS:
        if any(v is None or (isinstance(v, float) and not np.isfinite(v)) for v in cols[k]):
            problems.append(f"{path}: empty values in {k}")
    fl, h = np.asarray(cols["floors_ag"], dtype=float), np.asarray(cols["height_ag"], dtype=float)
    if np.any(fl < 1) or np.any(h < MIN_HEIGHT) or np.any(h < fl):
        problems.append(f"{path}: a building with no floor or too low for its floors")
    return problems


def _write(buildings, outdir, options, *, crs=None, frame=None, stem="out", **_):
    """``OUTDIR/<stem>.cea/inputs/building-geometry/zone.shp``; ``options`` are the IDF options."""
    return [write(buildings, scenario_path(outdir, stem), crs=crs, frame=frame, use=getattr(options, "use", None),
                  lod=getattr(options, "lod", None), attic=getattr(options, "attic", None) or "unconditioned",
                  root=outdir)]


register_writer("cea", _write, self_check, scope="dataset")
