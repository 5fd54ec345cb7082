"""Energy-ADE-style CityJSON export of labelled buildings, with a self-check before a file counts.

What is written (through :mod:`lod2energy.io.cityjson`'s writer):

- the energy geometry of every building (the repaired, labelled LoD; other LoDs are left
  out unless ``keep_other_lods``), a semantic surface on every face carrying ``uValue``
  (W/(m2 K)), ``thermalBoundaryType``, ``area`` (m2), ``azimuth`` and ``inclination`` (deg);
- per building, ``+energy...`` attributes on the first-level Building (envelope area,
  volume, UA, typology, construction period, repair stage, energy compliance, ...), defined
  by the CityJSON Extension ``Energy`` shipped in ``lod2energy/data/extensions/<v>/`` and
  referenced under the document's ``"extensions"`` (relative URL ``energy.ext.json``; the
  extension file is copied next to the output);
- CityJSON version: the input's by default, else ``version`` ("1.0", "1.1", "2.0").

Self-check (:func:`self_check`): re-parse the file, validate it against the official
CityJSON schema of its version (bundled copy in ``lod2energy/data/schemas/cityjson``, with
a ``referencing`` registry for the ``$ref`` between schema files), validate the
``+energy`` attributes against the Extension schema, then re-read it with
:func:`lod2energy.io.cityjson.read` and check every energy building's geometry: val3dity
checks (:func:`lod2energy.validate.checks.validate_building`), closed and outward (every
edge used exactly twice in opposite directions, positive volume), every face labelled with
an envelope type and a positive ``uValue``.

Files are written to a temporary name next to the target and moved into place only when
the self-check passes; a file that fails is kept as ``<path>.invalid`` (for inspection) and
``ExportResult.ok`` is False with the problems. Buildings that cannot pass (no thermal
data, or an energy geometry that is not closed / labelled) are left out beforehand and
listed in ``ExportResult.skipped`` when ``exclude_unready`` is True (default).
"""
from __future__ import annotations

import itertools
import json
import os
from dataclasses import dataclass, replace
from functools import lru_cache
from importlib import resources
from typing import Any, Iterable, Mapping

import numpy as np

from lod2energy import safe_write
from lod2energy.errors import Lod2EnergyError
from lod2energy.io import cityjson as cjio
from lod2energy.model import Building, CityModel, frozen_mapping
from lod2energy.semantics import ENVELOPE_TYPES, envelope_objects

EXTENSION_NAME = "Energy"
EXTENSION_FILE = "energy.ext.json"
EXTENSION_VERSION = "1.0"
INVALID_SUFFIX = ".invalid"
_STAGED = itertools.count()
_VDIR = {"1.0": "10", "1.1": "11", "2.0": "20"}
_MAX_PROBLEMS = 50



#: Overlapping BuildingParts (601) are reported by the validator but do not stop an export:
#: each part is still a closed, outward shell (the repair ladder's own criterion); use
#: ``--merge-parts`` to union them.
TOLERATED_CODES = frozenset({601})

@dataclass(frozen=True)
class ExportResult:
    """Outcome of :func:`write`.

    Attributes
    ----------
    path : str
        Where the file is: the requested path when ``ok``, else ``path + ".invalid"``
        (or the requested path with nothing written, when writing itself failed).
    ok : bool
        The file passed the self-check.
    problems : tuple of str
        Self-check problems (empty when ok).
    version : str
        CityJSON version written.
    building_ids : tuple of str
        Buildings in the file.
    skipped : tuple of (str, str)
        ``(building id, reason)`` of buildings left out.
    extension_path : str or None
        The Energy extension file written next to the output.
    notes : tuple of str
        Changes made to the input's header to fit the target version.
    """

    path: str
    ok: bool
    problems: tuple[str, ...] = ()
    version: str = ""
    building_ids: tuple[str, ...] = ()
    skipped: tuple[tuple[str, str], ...] = ()
    extension_path: str | None = None
    notes: tuple[str, ...] = ()


# ----------------------------------------------------------------------------- resources

def _data():
    return resources.files("lod2energy") / "data"


@lru_cache(maxsize=None)
def extension_schema(version: str) -> dict:
    """The shipped Energy extension for CityJSON ``version``."""
    return json.loads((_data() / "extensions" / _VDIR[version] / EXTENSION_FILE).read_text(encoding="utf-8"))


@dataclass(frozen=True)
class _SchemaSet:
    """Validators of one CityJSON version (whole document, feature, one per CityObject type)."""

    document: Any
    feature: Any
    branches: tuple  # one validator per alternative of CityObjects' "oneOf"


def _wrap(branch: Mapping, base: str, i: int) -> dict:
    # a root "$id" next to the official files so that their relative "$ref"s resolve
    return {"$schema": "http://json-schema.org/draft-07/schema#",
            "$id": base.rsplit("/", 1)[0] + f"/lod2energy-cityobject-{i}.json", "allOf": [dict(branch)]}


@lru_cache(maxsize=None)
def _validators(version: str) -> _SchemaSet:
    """Validators for the official schema of ``version`` (bundled copy)."""
    import jsonschema
    from referencing import Registry, Resource
    from referencing.jsonschema import DRAFT7

    d = _data() / "schemas" / "cityjson" / _VDIR[version]
    registry = Registry()
    feat = None
    if version == "1.0":
        main = json.loads((d / "cityjson.min.schema.json").read_text(encoding="utf-8"))
        main.setdefault("$id", "https://www.cityjson.org/schemas/1.0.3/cityjson.schema.json")
    else:
        resources_ = []
        for f in sorted(d.iterdir(), key=lambda p: p.name):
            if not f.name.endswith(".schema.json") or ".min." in f.name:
                continue
            contents = json.loads(f.read_text(encoding="utf-8"))
            resources_.append((contents["$id"], Resource.from_contents(contents, default_specification=DRAFT7)))
            if f.name == "cityjson.schema.json":
                main = contents
            elif f.name == "cityjsonfeature.schema.json":
                feat = contents
        registry = registry.with_resources(resources_)
    branches = main["properties"]["CityObjects"]["additionalProperties"]["oneOf"]
    return _SchemaSet(
        jsonschema.Draft7Validator(main, registry=registry),
        jsonschema.Draft7Validator(feat, registry=registry) if feat else None,
        tuple(jsonschema.Draft7Validator(_wrap(b, main["$id"], i), registry=registry)
              for i, b in enumerate(branches)))


def _schema_files(version: str) -> tuple[dict, dict | None, dict]:
    """The bundled official schema of ``version``: (main, feature or None, ``{file name: schema}``)."""
    d = _data() / "schemas" / "cityjson" / _VDIR[version]
    if version == "1.0":
        main = json.loads((d / "cityjson.min.schema.json").read_text(encoding="utf-8"))
        return main, None, {}
    files = {f.name: json.loads(f.read_text(encoding="utf-8")) for f in d.iterdir()
             if f.name.endswith(".schema.json") and ".min." not in f.name}
    return files["cityjson.schema.json"], files.get("cityjsonfeature.schema.json"), files


#: As jsonschema validates: formats not asserted, and the document never filled with defaults.
_COMPILE = {"use_formats": False, "use_default": False}


@lru_cache(maxsize=None)
def _compiled(version: str) -> tuple[Any, Any]:
    """Compiled (``fastjsonschema``) validators of the document and of a CityJSONFeature for
    ``version``, built once per process; ``$ref`` s to the official files resolve to the
    bundled copies, never to the network. (None, None) when fastjsonschema is missing."""
    try:
        import fastjsonschema
    except ImportError:  # the interpreted validators still decide, only slower
        return None, None
    main, feat, files = _schema_files(version)

    def local(uri: str) -> dict:
        name = uri.split("#", 1)[0].rsplit("/", 1)[-1]
        if name not in files:
            raise Lod2EnergyError(f"schema reference {uri} is not a bundled CityJSON {version} file")
        return files[name]

    handlers = {"https": local, "http": local}
    return (fastjsonschema.compile(main, handlers=handlers, **_COMPILE),
            fastjsonschema.compile(feat, handlers=handlers, **_COMPILE) if feat else None)


#: Compiling a schema version costs about 2 s once per process, as much as interpreting the
#: schema on some 25 CityObjects: smaller files are left to the interpreted validators unless
#: the compiled ones are already built.
COMPILE_MIN_OBJECTS = 25
_COMPILED_VERSIONS: set[str] = set()


def _worth_compiling(version: str, n_objects: int) -> bool:
    """Use the compiled validator: a large file, or one already built for ``version``."""
    return n_objects >= COMPILE_MIN_OBJECTS or version in _COMPILED_VERSIONS


def _schema_valid_fast(version: str, doc: Any, feature: bool = False) -> bool:
    """True when the compiled validator accepts ``doc``. Only a shortcut for valid files:
    False (or no compiled validator) sends the document to the interpreted validators of
    :func:`_schema_errors`, which give the messages and the final verdict."""
    import fastjsonschema

    _COMPILED_VERSIONS.add(version)
    v = _compiled(version)[1 if feature else 0]
    if v is None:
        return False
    try:
        v(doc)
    except fastjsonschema.JsonSchemaException:
        return False
    return True


def _light(co: Any) -> Any:
    if not isinstance(co, Mapping):
        return co
    return {k: ([] if k == "geometry" else v) for k, v in co.items()}


def _schema_errors(schemas: _SchemaSet, doc: Any, what: str, feature: bool = False) -> list[str]:
    """Schema errors of a CityJSON document or CityJSONFeature.

    Equivalent to validating the whole document, but fast: the document is validated
    without its CityObjects, and each CityObject only against the alternative(s) of the
    schema's CityObject ``oneOf`` that accept it once its geometry is set aside (its type);
    validating every object against all ~30 alternatives takes minutes on a tile.
    """
    out: list[str] = []
    validator = schemas.feature if feature else schemas.document

    def collect(v, inst, prefix):
        for e in sorted(v.iter_errors(inst), key=lambda e: list(e.absolute_path))[:_MAX_PROBLEMS]:
            where = "/".join(str(p) for p in list(prefix) + list(e.absolute_path)) or "(root)"
            msg = e.message
            if e.validator in ("oneOf", "anyOf"):
                t = e.instance.get("type") if isinstance(e.instance, Mapping) else None
                msg = (f"{t!r} is not valid under any of the given schemas" if t else
                       "not valid under any of the given schemas")
            msg = msg if len(msg) < 300 else msg[:300] + "..."
            out.append(f"{what}: schema: {where}: {msg}")

    cos = doc.get("CityObjects") if isinstance(doc, Mapping) else None
    if not isinstance(cos, Mapping):
        collect(validator, doc, ())
        return out
    skeleton = {**doc, "CityObjects": {}}
    collect(validator, skeleton, ())
    for oid, co in cos.items():
        light = _light(co)
        cands = [v for v in schemas.branches if v.is_valid(light)]
        if len(cands) == 1:
            collect(cands[0], co, ("CityObjects", oid))
        elif not cands:
            # no alternative accepts it even without geometry: report the errors of the
            # alternative of its own type (the one not complaining about "type"), else the oneOf
            own = None
            for v in schemas.branches:
                errs = list(v.iter_errors(light))
                if not any(list(e.absolute_path)[:1] == ["type"] for e in errs):
                    own = v
                    break
            if own is not None:
                collect(own, light, ("CityObjects", oid))
            else:
                collect(validator, {**skeleton, "CityObjects": {oid: light}}, ())
        else:  # several alternatives accept it: the full oneOf decides
            collect(validator, {**skeleton, "CityObjects": {oid: co}}, ())
        if len(out) > _MAX_PROBLEMS:
            break
    return out


# ----------------------------------------------------------------------------- preparing

def _energy_attributes(b: Building) -> dict[str, Any]:
    th = dict(b.provenance.get("thermal") or {})
    rep = dict(b.provenance.get("repair") or {})
    energy = b.provenance.get("energy")
    a: dict[str, Any] = {
        "+energyEnvelopeArea": float(th.get("A_env", 0.0)),
        "+energyVolume": float(th.get("volume", 0.0)),
        "+energyUA": float(th.get("UA", 0.0)),
        "+energyTypology": str(th.get("typology")),
        "+energyConstructionPeriod": str(th.get("construction_period")),
        "+energyYearOfConstruction": th.get("year_of_construction"),
        "+energyCountry": str(th.get("country")),
        "+energyUValues": dict(th.get("u_values") or {}),
        "+energyWindowToWallRatio": float(th.get("wwr", 0.0)),
        "+energyAreas": dict(th.get("areas") or {}),
        "+energyRepairStage": str(rep.get("stage", "none")),
    }
    if rep:  # without its timings: the file is byte-reproducible (they stay in report.json)
        a["+energyRepair"] = _untimed(cjio._plain(rep))
    if energy is not None:
        a["+energyCompliance"] = cjio._plain(energy)
    return a


def _untimed(x: Any) -> Any:
    """``x`` without the members that measure time (``seconds``...), which differ run to run."""
    if isinstance(x, dict):
        return {k: _untimed(v) for k, v in x.items() if "seconds" not in str(k)}
    if isinstance(x, list):
        return [_untimed(v) for v in x]
    return x


def _strip_to_energy(b: Building, lod: str | None, keep_other_lods: bool) -> Building:
    if keep_other_lods:
        return b
    keep = {(o.id, gi) for o, gi, _ in envelope_objects(b, lod)}
    objs = []
    for o in b.objects:
        geoms = tuple(g for gi, g in enumerate(o.geometries) if (o.id, gi) in keep)
        objs.append(replace(o, geometries=geoms))
    return replace(b, objects=tuple(objs))


def acceptance_problem(b: Building, lod: str | None) -> str | None:
    """The checks of an energy building besides its val3dity validity: a Building with thermal
    data and an envelope at ``lod`` that is closed, outward, labelled and has U-values; the first
    problem, or None. The pipeline's final check and this writer's both start with it."""
    if b.type != "Building":
        return f"not a Building (type {b.type!r})"
    if "thermal" not in b.provenance:
        return "no thermal data (labels / U-values not assigned)"
    energy = envelope_objects(b, lod)
    if not energy:
        return "no polygonal geometry at the energy LoD"
    probs = _envelope_problems(b, energy)
    return probs[0] if probs else None


def _ready_problem(b: Building, lod: str | None, keep_other_lods: bool = False, tol=None) -> str | None:
    """Why ``b`` cannot be exported as an energy building (None when it can).

    The same checks as :func:`self_check` runs on the file, on the building as it will be
    written: thermal data present, val3dity-valid, closed, outward, labelled, U-values.
    """
    from lod2energy.config import DEFAULT
    from lod2energy.validate.checks import validate_building

    why = acceptance_problem(b, lod)
    if why is not None:
        return why
    defects = [d for d in validate_building(_strip_to_energy(b, lod, keep_other_lods), tol or DEFAULT)
               if d.code not in TOLERATED_CODES]
    if defects:
        codes = sorted({d.code for d in defects})
        return f"invalid geometry (val3dity codes {codes}), e.g. {defects[0].location}"
    return None


def prepare_building(b: Building, lod: str | None = None, keep_other_lods: bool = False) -> Building:
    """The building as exported: energy LoD only, ``+energy`` attributes on the root."""
    lod = lod if lod is not None else (b.provenance.get("thermal") or {}).get("lod") or b.default_lod()
    b = _strip_to_energy(b, lod, keep_other_lods)
    root = b.root
    attrs = dict(root.attributes)
    attrs.update(_energy_attributes(b))
    objs = (replace(root, attributes=frozen_mapping(attrs)),) + tuple(b.objects[1:])
    return replace(b, objects=objs)


def on_grid(b: Building, transform: Mapping, frame=None) -> Building:
    """``b`` with its vertices rounded to the grid of ``transform`` (scale, translate), as a
    CityJSON file stores them (for a geographic input, on the file's grid in degrees:
    ``frame`` moves them there and back)."""
    scale = np.asarray(transform["scale"], dtype=np.float64)
    translate = np.asarray(transform["translate"], dtype=np.float64)
    fv = cjio.file_coordinates(b.vertices, frame)
    v = np.rint((fv - translate) / scale) * scale + translate
    if frame is not None and len(v):
        v = frame.to_local(v)
    if np.array_equal(v, b.vertices):
        return b
    return replace(b, vertices=v)


def _crs_for_version(crs: str, version: str) -> str:
    from lod2energy.crs import cityjson_reference_system
    return cityjson_reference_system(crs, version) or crs


def _header_fixes(md: dict, ext: dict, version: str) -> list[str]:
    """Make the input's metadata / extension declarations valid for ``version`` (in place).

    Metadata keys the target schema rejects are dropped; an extension version "1.1.0" is
    written "1.1" where the schema wants major.minor. Returns notes on what changed.
    """
    import re

    notes: list[str] = []
    if "referenceSystem" in md:
        new = _crs_for_version(str(md["referenceSystem"]), version)
        if new != md["referenceSystem"]:
            notes.append(f"metadata.referenceSystem written as {new}")
            md["referenceSystem"] = new
    schemas = _validators(version)
    for _ in range(5):
        probe = {"type": "CityJSON", "version": version, "CityObjects": {}, "vertices": [],
                 "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]}, "metadata": md, "extensions": ext}
        errs = list(schemas.document.iter_errors(probe))
        if not errs:
            break
        changed = False
        for e in errs:
            path = list(e.absolute_path)
            if path[:1] == ["metadata"]:
                if len(path) >= 2 and path[1] in md:
                    notes.append(f"metadata.{path[1]} dropped (not valid in CityJSON {version})")
                    md.pop(path[1])
                    changed = True
                elif e.validator == "additionalProperties" and isinstance(e.instance, Mapping):
                    allowed = set((e.schema.get("properties") or {}))
                    for k in [k for k in md if k not in allowed]:
                        notes.append(f"metadata.{k} dropped (not defined in CityJSON {version})")
                        md.pop(k)
                        changed = True
            elif path[:1] == ["extensions"] and len(path) >= 2 and path[1] in ext:
                name_ = path[1]
                v = str((ext[name_] or {}).get("version", ""))
                m = re.match(r"^(\d+)\.(\d+)", v)
                if path[-1] == "version" and m and m.group(0) != v:
                    ext[name_] = {**ext[name_], "version": m.group(0)}
                    notes.append(f"extensions.{name_}.version {v!r} written as {m.group(0)!r}")
                else:
                    ext.pop(name_)
                    notes.append(f"extensions.{name_} dropped (not valid in CityJSON {version})")
                changed = True
        if not changed:
            break
    return notes


def _model_for(model: CityModel, version: str) -> tuple[CityModel, list[str]]:
    ext = dict(cjio._plain(model.extensions) or {})
    ext[EXTENSION_NAME] = {"url": EXTENSION_FILE, "version": EXTENSION_VERSION}
    md = dict(cjio._plain(model.metadata) or {})
    notes = _header_fixes(md, ext, version)
    extra = dict(model.extra)
    if model.version != version:
        extra = {k: v for k, v in extra.items() if k.startswith("+")}
    # textures / materials refer to surfaces by index: after relabelling they are not kept
    return replace(model, extensions=frozen_mapping(ext), metadata=frozen_mapping(md),
                   extra=frozen_mapping(extra), appearance=None, version=version), notes


def _fix_address(co: dict, version: str) -> None:
    """Addresses: an object in CityJSON 1.0, an array of objects later. Their ``location``
    (a MultiPoint with vertex indices) is dropped: the energy export does not carry it."""
    addr = co.get("address")
    if addr is None:
        return
    items = addr if isinstance(addr, list) else [addr]
    items = [{k: v for k, v in a.items() if k != "location"} for a in items if isinstance(a, dict)]
    if not items:
        co.pop("address")
    elif version == "1.0":
        co["address"] = items[0]
    else:
        co["address"] = items


def _fix_document(doc: dict, version: str) -> dict:
    """Version-specific details the shared writer leaves generic."""
    for co in doc.get("CityObjects", {}).values():
        _fix_address(co, version)
        if version == "1.0" and isinstance(co.get("attributes"), dict):
            # CityJSON 1.0 types its standard attributes (class, function, ...) as strings
            # without a null: an attribute without a value is left out
            co["attributes"] = {k: v for k, v in co["attributes"].items() if v is not None}
        for g in co.get("geometry", []) or []:
            if version == "1.0" and isinstance(g.get("lod"), str):
                lod = float(g["lod"])
                g["lod"] = int(lod) if lod.is_integer() else lod
            g.pop("material", None)
            g.pop("texture", None)
    if version == "1.0":
        doc.get("metadata", {}).pop("title", None)
    return doc


# ----------------------------------------------------------------------------- writing

def write(path: str, model: CityModel, buildings: Iterable[Building], version: str | None = None, *,
          lod: str | None = None, keep_other_lods: bool = False, exclude_unready: bool = True,
          tol=None) -> ExportResult:
    """Write an Energy-ADE-style CityJSON (``.json``) or CityJSONSeq (``.jsonl``) file.

    Parameters
    ----------
    path : str
        Target file.
    model : CityModel
        File-level data of the input (metadata, transform, extensions, version).
    buildings : iterable of Building
        Output of label + U-value stages (``provenance["thermal"]`` present).
    version : str, optional
        "1.0", "1.1" or "2.0"; default: the input's version.
    lod : str, optional
        Energy LoD (default: each building's own).
    keep_other_lods : bool
        Keep the geometries at other LoDs too (they are then also self-checked).
    exclude_unready : bool
        Leave out (and list in ``skipped``) buildings without thermal data or whose energy
        geometry is not closed / labelled; otherwise they are written and fail the check.
    tol : Tolerances, optional
        The user's tolerances, for the acceptance check and the self-check (default: val3dity's).

    Returns
    -------
    ExportResult
    """
    try:
        version = cjio.normalise_version(version or model.version)
    except Lod2EnergyError as e:
        return ExportResult(path, False, (str(e),), str(version))
    if cjio.is_cityjsonseq(path) and version == "1.0":
        return ExportResult(path, False, ("CityJSONSeq needs CityJSON 1.1 or 2.0",), version)
    out, skipped = [], []
    buildings = list(buildings)
    m, notes = _model_for(model, version)
    transform = cjio._transform_for(m, buildings)
    if not m.transform:
        m = replace(m, transform=frozen_mapping(transform))
    for b in buildings:
        blod = lod if lod is not None else (b.provenance.get("thermal") or {}).get("lod")
        # checked as it will be read back: coordinates on the file's grid (a repaired vertex
        # off the grid moves by up to scale/2, which can tip a face over a tolerance)
        b = on_grid(b, transform, m.frame)
        why = _ready_problem(b, blod, keep_other_lods, tol) if exclude_unready else None
        if why is not None:
            skipped.append((b.id, why))
            continue
        out.append(prepare_building(b, blod, keep_other_lods))
    ids = tuple(b.id for b in out)
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    base = os.path.basename(path)
    # staged under a name unique per process and call, with the suffix the self-check reads
    tmp = os.path.join(folder, f".{base}.{os.getpid()}.{next(_STAGED)}.tmp"
                       + (".jsonl" if cjio.is_cityjsonseq(path) else ".json"))
    ext_path = os.path.join(folder, EXTENSION_FILE)
    inputs = [model.source] if model.source and os.path.exists(str(model.source)) else []
    try:
        safe_write.write_json(ext_path, extension_schema(version), root=folder, inputs=inputs)
        if cjio.is_cityjsonseq(path):
            cjio.write(tmp, m, out, version, root=folder, inputs=inputs)
        else:
            doc = _fix_document(cjio.to_document(m, out, version), version)
            with safe_write.atomic_write(tmp, "w", root=folder, inputs=inputs) as f:
                json.dump(doc, f, separators=(",", ":"), ensure_ascii=False)
    except (OSError, ValueError, TypeError, Lod2EnergyError) as e:
        _remove(tmp)
        why = e.strerror if isinstance(e, OSError) and e.strerror else e
        return ExportResult(path, False, (f"cannot write {path}: {why}",), version, ids, tuple(skipped))
    try:
        problems = self_check(tmp, extension=extension_schema(version), tol=tol)
        target = path + INVALID_SUFFIX if problems else path
        safe_write.check_target(target, folder, inputs)
        os.replace(tmp, target)
        _remove(path if problems else path + INVALID_SUFFIX)  # never leave an older file that looks like this run's
    except OSError as e:
        _remove(tmp)
        return ExportResult(path, False, (f"cannot write {path}: {e.strerror or e}",), version, ids, tuple(skipped))
    if problems:
        return ExportResult(target, False, tuple(problems) + (f"failed its self-check: kept as {base}{INVALID_SUFFIX}",),
                            version, ids, tuple(skipped), ext_path, tuple(notes))
    return ExportResult(path, True, (), version, ids, tuple(skipped), ext_path, tuple(notes))


def _remove(p: str) -> None:
    try:
        os.remove(p)
    except FileNotFoundError:
        pass


# ----------------------------------------------------------------------------- self-check

def _envelope_problems(b: Building, energy=None) -> list[str]:
    """Closed, outward, labelled, with U-values: problems of the energy geometries of ``b``."""
    out = []
    energy = energy if energy is not None else envelope_objects(b)
    from lod2energy.semantics import face_metrics

    # identical coordinates = same vertex, whatever the index
    _, inv = np.unique(b.vertices, axis=0, return_inverse=True)
    inv = inv.reshape(-1)
    origin = b.vertices.mean(axis=0) if len(b.vertices) else np.zeros(3)
    for o, gi, g in energy:
        where = f"coid={o.id}|geom={gi}"
        if not g.is_volumetric:
            out.append(f"{where}: {g.type} is not a solid")
            continue
        for si, so in enumerate(g.solids):
            for hi, sh in enumerate(so.shells):
                edges: dict[tuple[int, int], int] = {}
                vol = 0.0
                for s in sh.surfaces:
                    for r in s.rings:
                        ids = inv[r]
                        for a, c in zip(ids, np.roll(ids, -1)):
                            if a != c:
                                edges[(int(a), int(c))] = edges.get((int(a), int(c)), 0) + 1
                    ar, n, cen = face_metrics(b.vertices, s)
                    vol += float((cen - origin) @ (n * ar)) / 3.0
                bad = [e for e, k in edges.items() if k != 1 or edges.get((e[1], e[0]), 0) != 1]
                if bad:
                    out.append(f"{where}|solid={si}|shell={hi}: not closed or not consistently oriented "
                               f"({len(bad)} bad edges)")
                elif hi == 0 and vol <= 0:
                    out.append(f"{where}|solid={si}|shell={hi}: exterior shell oriented inwards (volume {vol:.3f} m3)")
        for si, hi, fi, s in g.iter_surfaces():
            loc = f"{where}|shell={hi}|face={fi}"
            if s.semantic is None or s.semantic >= len(g.semantic_surfaces):
                out.append(f"{loc}: no semantic surface")
                continue
            e = g.semantic_surfaces[s.semantic]
            if e.get("type") not in ENVELOPE_TYPES:
                out.append(f"{loc}: semantic type {e.get('type')!r} is not an envelope type")
            u = e.get("uValue")
            if not isinstance(u, (int, float)) or isinstance(u, bool) or not u > 0:
                out.append(f"{loc}: no positive uValue")
        if len(out) > _MAX_PROBLEMS:
            break
    return out


def _extension_problems(doc: Mapping, extension: Mapping | None, what: str) -> list[str]:
    import jsonschema

    out = []
    if extension is None:
        return out
    exts = doc.get("extensions") or {}
    if EXTENSION_NAME not in exts:
        return [f"{what}: extension {EXTENSION_NAME!r} is not referenced under 'extensions'"]
    declared = extension.get("extraAttributes", {})
    for oid, co in (doc.get("CityObjects") or {}).items():
        attrs = (co or {}).get("attributes") or {}
        for k, v in attrs.items():
            if not k.startswith("+energy"):
                continue
            sch = declared.get(co.get("type"), {}).get(k)
            if sch is None:
                out.append(f"{what}: {oid}: attribute {k} is not defined by the {EXTENSION_NAME} extension")
                continue
            try:
                jsonschema.Draft7Validator(sch).validate(v)
            except jsonschema.ValidationError as e:
                out.append(f"{what}: {oid}: {k}: {e.message}")
    return out


def _load_extension_beside(path: str, doc: Mapping) -> Mapping | None:
    url = ((doc.get("extensions") or {}).get(EXTENSION_NAME) or {}).get("url")
    if not url:
        return None
    p = os.path.join(os.path.dirname(os.path.abspath(path)), url)
    if os.path.exists(p):
        try:
            with open(p, encoding="utf-8") as f:
                return json.load(f)
        except (OSError, ValueError):
            return None
    return None


def self_check(path: str, extension: Mapping | None = None, tol=None) -> list[str]:
    """Problems of an exported file (empty list: the file is OK).

    Parameters
    ----------
    path : str
        CityJSON (``.json``) or CityJSONSeq (``.jsonl``) file.
    extension : mapping, optional
        Energy extension schema to check ``+energy`` attributes against (default: the
        file referenced under ``extensions``, looked up next to ``path``, else the shipped one).
    tol : Tolerances, optional
        For the val3dity checks.

    Returns
    -------
    list of str
        One line per problem (schema errors with their JSON path, then geometry problems
        with val3dity-style locations).
    """
    from lod2energy.config import DEFAULT
    from lod2energy.validate.checks import validate_building
    from lod2energy.validate.codes import name

    tol = tol or DEFAULT
    problems: list[str] = []
    try:
        with open(path, "rb") as f:
            raw = f.read().decode("utf-8")
    except (OSError, UnicodeDecodeError) as e:
        return [f"cannot read {path}: {e}"]
    docs: list[tuple[str, Any]] = []
    try:
        if cjio.is_cityjsonseq(path):
            lines = [ln for ln in raw.splitlines() if ln.strip()]
            docs = [(f"line {i + 1}", json.loads(ln)) for i, ln in enumerate(lines)]
        else:
            docs = [("document", json.loads(raw))]
    except json.JSONDecodeError as e:
        return [f"{path} is not valid JSON: {e.msg} at line {e.lineno}"]
    if not docs or not isinstance(docs[0][1], dict):
        return [f"{path}: no CityJSON object"]
    head = docs[0][1]
    try:
        version = cjio.normalise_version(head.get("version"))
    except Lod2EnergyError as e:
        return [f"{path}: {e}"]
    schemas = _validators(version)
    # a document the compiled validator accepts has no schema error: the interpreted
    # validators (slow, with the messages) only see the documents it rejects
    n_objects = sum(len(d.get("CityObjects") or {}) for _, d in docs if isinstance(d, Mapping))
    fast = _worth_compiling(version, n_objects)
    if not (fast and _schema_valid_fast(version, head)):
        problems += _schema_errors(schemas, head, docs[0][0])
    for what, d in docs[1:]:
        if schemas.feature is None:
            problems.append(f"{what}: CityJSONFeature needs CityJSON 1.1 or later")
            break
        if not (fast and _schema_valid_fast(version, d, feature=True)):
            problems += _schema_errors(schemas, d, what, feature=True)
        if len(problems) > _MAX_PROBLEMS:
            break
    if extension is None:
        extension = _load_extension_beside(path, head)
        if extension is None and EXTENSION_NAME in (head.get("extensions") or {}):
            extension = extension_schema(version)
    for what, d in docs[1:] if len(docs) > 1 else docs:
        if len(docs) > 1:
            d = {**d, "extensions": head.get("extensions")}
        problems += _extension_problems(d, extension, what)
    if problems:
        return problems[:_MAX_PROBLEMS]
    from lod2energy.io import to_local_frame
    model, feats = to_local_frame(*cjio.read(path))  # a geographic file is checked in metres
    n_energy = 0
    for f in feats:
        if not isinstance(f, Building):
            problems.append(f"re-read: {f.message}")
            continue
        if not any(k.startswith("+energy") for k in f.root.attributes):
            continue
        n_energy += 1
        for d in validate_building(f, tol):
            if d.code in TOLERATED_CODES:
                continue
            problems.append(f"{d.location}: {d.code} {name(d.code)} {d.info}".rstrip())
        problems += _envelope_problems(f)
        if len(problems) > _MAX_PROBLEMS:
            break
    return problems[:_MAX_PROBLEMS]
