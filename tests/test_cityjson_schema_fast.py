"""The compiled schema check without detailed exceptions, and the extension check with one
validator per attribute, decide as the code they replace.

The compiled validator is built from the schema with ``const`` written as ``enum`` (its code
for ``const`` needs the detailed exceptions); it must accept and reject the same documents as
the validator compiled from the schema as it is, with details. The extension check builds
one ``jsonschema`` validator per declared attribute instead of one per value: the same
problems, in the same order.
"""
from __future__ import annotations

import json

import fastjsonschema
import jsonschema
import numpy as np
import pytest

from lod2energy.exporters.cityjson import writer as X
from lod2energy.exporters.cityjson import schema as CS

from test_export_cityjson import _random_mutation, model, two_buildings


def test_const_as_enum_rewrites_keywords_only():
    s = {"properties": {"const": {"const": 1}, "type": {"const": "Building"}},
         "enum": [{"const": 2}], "items": [{"const": None}], "default": {"const": 3},
         "allOf": [{"const": "a", "enum": ["a", "b"]}]}
    out = CS._const_as_enum(s)
    assert out["properties"] == {"const": {"enum": [1]}, "type": {"enum": ["Building"]}}
    assert out["enum"] == [{"const": 2}] and out["default"] == {"const": 3}  # values, untouched
    assert out["items"] == [{"enum": [None]}]
    both = out["allOf"][0]
    assert both["enum"] == ["a", "b"] and both["allOf"] == [{"enum": ["a"]}]
    assert s["properties"]["type"] == {"const": "Building"}  # the input is not changed


@pytest.mark.parametrize("const", ["Building", 1, 1.0, True, None, 0, "1"])
def test_const_and_its_enum_accept_the_same_values(const):
    schema = {"type": "object", "properties": {"t": {"const": const}}, "required": ["t"]}
    detailed = fastjsonschema.compile(schema, use_formats=False, use_default=False)
    lean = fastjsonschema.compile(CS._const_as_enum(schema), **CS._COMPILE)
    for value in ["Building", "building", 1, 1.0, 2, True, False, None, 0, 0.0, "1", [], {}, [1]]:
        verdicts = []
        for v in (detailed, lean):
            try:
                v({"t": value})
                verdicts.append(True)
            except fastjsonschema.JsonSchemaException:
                verdicts.append(False)
        assert verdicts[0] == verdicts[1], (const, value)
        assert verdicts[1] == jsonschema.Draft7Validator(schema).is_valid({"t": value}), (const, value)


def _detailed(version):
    """The compiled document validator as it was: from the schema as it is, with details."""
    main, _, files = CS._schema_files(version)

    def local(uri):
        return files[uri.split("#", 1)[0].rsplit("/", 1)[-1]]

    return fastjsonschema.compile(main, handlers={"https": local, "http": local}, use_formats=False,
                                  use_default=False)


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_lean_compiled_validator_decides_as_the_detailed_one(tmp_path, version):
    res = X.write(str(tmp_path / "g.city.json"), model(version), two_buildings(), version)
    assert res.ok
    good = json.loads(open(res.path, encoding="utf-8").read())
    ref = _detailed(version)
    rng = np.random.default_rng(11)
    rejected = 0
    for i in range(150):
        doc = json.loads(json.dumps(good))
        for _ in range(int(rng.integers(0 if i < 3 else 1, 3))):
            _random_mutation(doc, rng)
        try:
            ref(doc)
            want = True
        except fastjsonschema.JsonSchemaException:
            want = False
        assert CS._schema_valid_fast(version, doc) == want
        rejected += not want
    assert rejected > 40


def test_disjoint_oneof_as_anyof_only_when_exclusive():
    sem = {"type": "string", "oneOf": [{"enum": ["A"]}, {"enum": ["B"]}, {"type": "string", "pattern": "(\\+)\\w+"}]}
    out = CS._disjoint_oneof_as_anyof({"properties": {"oneOf": sem}, "enum": [sem]})
    assert out["properties"]["oneOf"] == {"type": "string", "anyOf": [{"enum": ["A", "B"]},
                                                                     {"type": "string", "pattern": "(\\+)\\w+"}]}
    assert out["enum"] == [sem]  # values, untouched
    for kept in ([{"enum": ["A"]}, {"enum": ["A"]}],                                    # a value in two branches
                 [{"enum": ["+A"]}, {"type": "string", "pattern": "(\\+)\\w+"}],       # the pattern takes a word
                 [{"enum": ["A"]}, {"enum": [1]}],                                       # not strings
                 [{"enum": ["A"]}, {"type": "string", "pattern": "x"}, {"type": "string", "pattern": "y"}],
                 [{"enum": ["A"]}, {"$ref": "#/x"}]):
        assert CS._disjoint_oneof_as_anyof({"oneOf": kept}) == {"oneOf": kept}


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_semantic_types_decided_as_by_the_oneof(tmp_path, version):
    res = X.write(str(tmp_path / "g.city.json"), model(version), two_buildings(), version)
    good = json.loads(open(res.path, encoding="utf-8").read())
    ref = _detailed(version)
    key, gi = next((k, i) for k, c in good["CityObjects"].items()
                   for i, g in enumerate(c.get("geometry", [])) if g.get("semantics", {}).get("surfaces"))
    verdicts = set()
    for value in ["RoofSurface", "WallSurface", "GroundSurface", "Window", "TransportationMarking", "+Custom",
                  "+", "Roof+Surface", "+ x", "roofsurface", "", "Roof", 5, None, ["RoofSurface"], True]:
        doc = json.loads(json.dumps(good))
        doc["CityObjects"][key]["geometry"][gi]["semantics"]["surfaces"][0]["type"] = value
        try:
            ref(doc)
            want = True
        except fastjsonschema.JsonSchemaException:
            want = False
        assert CS._schema_valid_fast(version, doc) == want, value
        verdicts.add(want)
    assert verdicts == {True, False}


def _old_extension_problems(doc, extension, what):
    """:func:`cityjson_schema.extension_problems` as it was: a validator per value."""
    out = []
    declared = extension.get("extraAttributes", {})
    for oid, co in (doc.get("CityObjects") or {}).items():
        for k, v in ((co or {}).get("attributes") or {}).items():
            if not k.startswith("+energy"):
                continue
            sch = declared.get(co.get("type"), {}).get(k)
            if sch is None:
                out.append(f"{what}: {oid}: attribute {k} is not defined by the {CS.EXTENSION_NAME} extension")
                continue
            try:
                jsonschema.Draft7Validator(sch).validate(v)
            except jsonschema.ValidationError as e:
                out.append(f"{what}: {oid}: {k}: {e.message}")
    return out


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_extension_problems_as_before(tmp_path, version):
    res = X.write(str(tmp_path / "g.city.json"), model(version), two_buildings(), version)
    good = json.loads(open(res.path, encoding="utf-8").read())
    ext = CS.extension_schema(version)
    rng = np.random.default_rng(5)
    found = 0
    for _ in range(200):
        doc = json.loads(json.dumps(good))
        co = doc["CityObjects"][sorted(doc["CityObjects"])[int(rng.integers(len(doc["CityObjects"])))]]
        attrs = co.setdefault("attributes", {})
        keys = [k for k in attrs if k.startswith("+energy")] or ["+energyVolume"]
        attrs[keys[int(rng.integers(len(keys)))]] = [None, "x", -1.5, [], {"a": 1}, 3, True][int(rng.integers(7))]
        if rng.random() < 0.2:
            attrs["+energyBogus"] = 1
        new = CS.extension_problems(doc, ext, "document")
        assert new == _old_extension_problems(doc, ext, "document")
        found += bool(new)
    assert found > 50
