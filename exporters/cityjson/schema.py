"""The official CityJSON schemas and the Energy extension: loading, validating, and the extension's attributes.

The bundled copies live in ``lod2energy/data/schemas/cityjson/<v>/`` (official files, with a
``referencing`` registry for the ``$ref`` between them) and
``lod2energy/data/extensions/<v>/energy.ext.json`` (the Extension lod2energy ships). A
document is validated by ``jsonschema-rs``; one it rejects goes to the interpreted
``jsonschema`` validators for the messages; every ``+energy...``
attribute must be declared by the extension and its value valid under its schema
(:func:`extension_problems`), as CityJSON's extension mechanism wants.
"""
from __future__ import annotations

import json
import os
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from typing import Any

import jsonschema
import jsonschema_rs
from referencing import Registry, Resource
from referencing.jsonschema import DRAFT7

from lod2energy import cache
from lod2energy.errors import Lod2EnergyError

EXTENSION_NAME = "Energy"
EXTENSION_FILE = "energy.ext.json"
EXTENSION_VERSION = "1.0"
_VDIR = {"1.0": "10", "1.1": "11", "2.0": "20"}
#: At most this many problems are listed for one file.
MAX_PROBLEMS = 50


def _data():
    return resources.files("lod2energy") / "data"


@cache.memoize("cityjson.extension-schemas", 8)
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


@cache.memoize("cityjson.validators", 8)
def _validators(version: str) -> _SchemaSet:
    """Validators for the official schema of ``version`` (bundled copy)."""
    main, feat, files = _schema_files(version)
    if version == "1.0":
        main.setdefault("$id", "https://www.cityjson.org/schemas/1.0.3/cityjson.schema.json")
    registry = Registry().with_resources(
        (f["$id"], Resource.from_contents(f, default_specification=DRAFT7)) for f in files.values())
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


@cache.memoize("cityjson.fast-validators", 8)
def _fast_validator(version: str, feature: bool) -> Any:
    """The ``jsonschema-rs`` validator of the document (``feature=False``) or of a
    CityJSONFeature for ``version`` (formats not asserted, as :mod:`jsonschema` validates), its
    ``$ref`` s to the official files resolved to the bundled copies, never to the network; None
    when the version has no feature schema."""
    main, feat, files = _schema_files(version)
    if feature and feat is None:
        return None
    registry = jsonschema_rs.Registry([(f["$id"], f) for f in files.values()], draft=jsonschema_rs.Draft7)
    return jsonschema_rs.Draft7Validator(feat if feature else main, validate_formats=False, registry=registry,
                                         retriever=_no_retrieval)


def _no_retrieval(uri: str) -> Any:
    raise Lod2EnergyError(f"schema reference {uri} is not a bundled CityJSON file")


def _schema_valid_fast(version: str, doc: Any, feature: bool = False) -> bool:
    """True when ``doc`` is valid under the official schema of ``version`` (``jsonschema-rs``).
    False sends the document to the interpreted validators of :func:`_schema_errors`, which
    give the messages and the final verdict."""
    v = _fast_validator(version, bool(feature))
    return v is not None and v.is_valid(doc)


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
        for e in sorted(v.iter_errors(inst), key=lambda e: list(e.absolute_path))[:MAX_PROBLEMS]:
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
        if len(out) > MAX_PROBLEMS:
            break
    return out


def extension_problems(doc: Mapping, extension: Mapping | None, what: str) -> list[str]:

    out = []
    if extension is None:
        return out
    exts = doc.get("extensions") or {}
    if EXTENSION_NAME not in exts:
        return [f"{what}: extension {EXTENSION_NAME!r} is not referenced under 'extensions'"]
    declared = extension.get("extraAttributes", {})
    validators: dict[tuple, Any] = {}  # one per declared attribute: building one costs more than using it
    for oid, co in (doc.get("CityObjects") or {}).items():
        attrs = (co or {}).get("attributes") or {}
        for k, v in attrs.items():
            if not k.startswith("+energy"):
                continue
            sch = declared.get(co.get("type"), {}).get(k)
            if sch is None:
                out.append(f"{what}: {oid}: attribute {k} is not defined by the {EXTENSION_NAME} extension")
                continue
            key = (co.get("type"), k)
            if key not in validators:
                validators[key] = jsonschema.Draft7Validator(sch)
            if validators[key].is_valid(v):
                continue
            try:
                validators[key].validate(v)
            except jsonschema.ValidationError as e:
                out.append(f"{what}: {oid}: {k}: {e.message}")
    return out


def load_extension_beside(path: str, doc: Mapping) -> Mapping | None:
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
