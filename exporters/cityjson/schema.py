"""The official CityJSON schemas and the Energy extension: loading, validating, and the extension's attributes.

The bundled copies live in ``lod2energy/data/schemas/cityjson/<v>/`` (official files, with a
``referencing`` registry for the ``$ref`` between them) and
``lod2energy/data/extensions/<v>/energy.ext.json`` (the Extension lod2energy ships). A
document is validated by the compiled (``fastjsonschema``) validator when that is worth it,
and by the interpreted ``jsonschema`` validators for the messages; every ``+energy...``
attribute must be declared by the extension and its value valid under its schema
(:func:`extension_problems`), as CityJSON's extension mechanism wants.
"""
from __future__ import annotations

import json
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from typing import Any, Callable

import fastjsonschema
import jsonschema
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


#: As jsonschema validates: formats not asserted, and the document never filled with defaults;
#: the exceptions without their details (the compiled validator only says yes or no: a no goes
#: to the interpreted validators for the messages), which makes the generated code a tenth
#: the size and its compilation and its rejections (every alternative of a ``oneOf`` that does
#: not apply) several times cheaper.
_COMPILE = {"use_formats": False, "use_default": False, "detailed_exceptions": False}
#: Members whose value maps names to schemas (the names are not keywords).
_SCHEMA_MAPS = ("properties", "patternProperties", "definitions", "$defs", "dependencies")


def _rewrite(schema: Any, node: Callable[[dict, dict], dict]) -> Any:
    """``schema`` with ``node(new, old)`` applied to every subschema, innermost first:
    ``new`` is ``old`` with its subschemas already rewritten (keyword values such as ``enum``
    and the names of ``properties`` and the like are values, never walked into)."""
    if isinstance(schema, list):
        return [_rewrite(x, node) for x in schema]
    if not isinstance(schema, dict):
        return schema
    out = {}
    for k, v in schema.items():
        if k in ("enum", "const", "examples", "default"):
            out[k] = v  # values, not schemas
        elif k in _SCHEMA_MAPS and isinstance(v, dict):
            out[k] = {name: _rewrite(sub, node) for name, sub in v.items()}
        else:
            out[k] = _rewrite(v, node)
    return node(out, schema)


def _const_as_enum(schema: Any) -> Any:
    """``schema`` with every ``{"const": x}`` written ``{"enum": [x]}`` (the same constraint:
    fastjsonschema generates the same test for both), for ``fastjsonschema`` without detailed
    exceptions, whose code for ``const`` does not compile (it formats a message with the
    detail it leaves out)."""
    def node(out: dict, old: dict) -> dict:
        if "const" not in old:
            return out
        if "enum" in old:  # both: the value must satisfy both
            c = out.pop("const")
            out["allOf"] = list(out.get("allOf", [])) + [{"enum": [c]}]
            return out
        return {("enum" if k == "const" else k): ([v] if k == "const" else v) for k, v in out.items()}
    return _rewrite(schema, node)


def _disjoint_oneof_as_anyof(schema: Any) -> Any:
    """``schema`` with every ``oneOf`` of single-value-set string enums (and at most one
    ``{"type": "string", "pattern": P}`` branch matching none of their strings) written as an
    ``anyOf`` of one merged enum and that branch: the same constraint, the branches being
    mutually exclusive (exactly one matches iff at least one does), and the compiled test of
    a valid value stops at the branch it matches instead of raising and catching an exception
    in each other one (a semantic surface's ``type``: 19 branches in CityJSON 1.1 and 2.0).
    Anything else is left as it is."""
    def node(out: dict, old: dict) -> dict:
        merged = _merged_enum_branches(out.get("oneOf"))
        if merged is not None and "anyOf" not in out:
            del out["oneOf"]
            out["anyOf"] = merged
        return out
    return _rewrite(schema, node)


def _merged_enum_branches(branches: Any) -> list | None:
    """:func:`_disjoint_oneof_as_anyof`'s ``anyOf`` for the ``oneOf`` ``branches``, or None."""
    if not isinstance(branches, list) or not branches or not all(isinstance(b, dict) for b in branches):
        return None
    words: list[str] = []
    others = []
    for b in branches:
        if set(b) == {"enum"} and isinstance(b["enum"], list) and b["enum"] \
                and all(type(x) is str for x in b["enum"]):
            words.extend(b["enum"])
        elif set(b) == {"type", "pattern"} and b["type"] == "string" and isinstance(b["pattern"], str):
            others.append(b)
        else:
            return None
    if not words or len(others) > 1 or len(set(words)) != len(words):
        return None  # a value in two enum branches would fail the oneOf
    if others and any(re.search(others[0]["pattern"], w) for w in words):
        return None  # a string of the enums the pattern branch takes too
    return [{"enum": words}] + others


@cache.memoize("cityjson.compiled", 16)
def _compiled_one(version: str, feature: bool) -> Any:
    """The compiled (``fastjsonschema``) validator of the document (``feature=False``) or of a
    CityJSONFeature for ``version``, built once per process and only when first asked for (a
    file or a CityJSONSeq needs one of the two: compiling costs about 1 s CPU each); ``$ref``
    s to the official files resolve to the bundled copies, never to the network. None when
    fastjsonschema is missing or the version has no feature schema."""
    try:
        import fastjsonschema
    except ImportError:  # the interpreted validators still decide, only slower
        return None
    main, feat, files = _schema_files(version)
    if feature and feat is None:
        return None

    files = {name: _disjoint_oneof_as_anyof(_const_as_enum(f)) for name, f in files.items()}

    def local(uri: str) -> dict:
        name = uri.split("#", 1)[0].rsplit("/", 1)[-1]
        if name not in files:
            raise Lod2EnergyError(f"schema reference {uri} is not a bundled CityJSON {version} file")
        return files[name]

    handlers = {"https": local, "http": local}
    return fastjsonschema.compile(_disjoint_oneof_as_anyof(_const_as_enum(feat if feature else main)),
                                  handlers=handlers, **_COMPILE)


#: Compiling a schema version costs about 2 s once per process, as much as interpreting the
#: schema on some 25 CityObjects: smaller files are left to the interpreted validators unless
#: the compiled ones are already built.
COMPILE_MIN_OBJECTS = 25
#: The table of the versions whose compiled validators were asked for in this process.
_COMPILED_VERSIONS = "cityjson.compiled-versions"


def _worth_compiling(version: str, n_objects: int) -> bool:
    """Use the compiled validator: a large file, or one already built for ``version``."""
    return n_objects >= COMPILE_MIN_OBJECTS or cache.recall(_COMPILED_VERSIONS, version, False)


def _schema_valid_fast(version: str, doc: Any, feature: bool = False) -> bool:
    """True when the compiled validator accepts ``doc``. Only a shortcut for valid files:
    False (or no compiled validator) sends the document to the interpreted validators of
    :func:`_schema_errors`, which give the messages and the final verdict."""
    cache.keep(_COMPILED_VERSIONS, version, True, 8)
    v = _compiled_one(version, bool(feature))
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
