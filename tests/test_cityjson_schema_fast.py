"""The schema shortcut (jsonschema-rs) decides as the interpreted validators (jsonschema), and
the extension check with one validator per attribute finds what one validator per value finds.

A document jsonschema-rs accepts is never shown to :mod:`jsonschema`, so the two must agree on
what the official schemas accept: on random mutations of a written file, on the semantic
surface types (a ``oneOf`` of enums and a pattern) and on ``const`` (``1``, ``1.0``, ``True``).
"""
from __future__ import annotations

import json

import jsonschema
import jsonschema_rs
import numpy as np
import pytest

from lod2energy.exporters.cityjson import writer as X
from lod2energy.exporters.cityjson import schema as CS

from test_export_cityjson import _random_mutation, model, two_buildings


@pytest.mark.parametrize("const", ["Building", 1, 1.0, True, None, 0, "1"])
def test_const_decided_as_by_jsonschema(const):
    schema = {"type": "object", "properties": {"t": {"const": const}}, "required": ["t"]}
    fast = jsonschema_rs.Draft7Validator(schema, validate_formats=False)
    ref = jsonschema.Draft7Validator(schema)
    verdicts = set()
    for value in ["Building", "building", 1, 1.0, 2, True, False, None, 0, 0.0, "1", [], {}, [1]]:
        assert fast.is_valid({"t": value}) == ref.is_valid({"t": value}), (const, value)
        verdicts.add(ref.is_valid({"t": value}))
    assert verdicts == {True, False}


def _written(tmp_path, version) -> dict:
    res = X.write(str(tmp_path / "g.city.json"), model(version), two_buildings(), version)
    assert res.ok
    return json.loads(open(res.path, encoding="utf-8").read())


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_fast_validator_decides_as_jsonschema(tmp_path, version):
    good = _written(tmp_path, version)
    ref = CS._validators(version).document
    rng = np.random.default_rng(11)
    rejected = 0
    for i in range(150):
        doc = json.loads(json.dumps(good))
        for _ in range(int(rng.integers(0 if i < 3 else 1, 3))):
            _random_mutation(doc, rng)
        before = json.dumps(doc, sort_keys=True)
        want = ref.is_valid(doc)
        assert CS._schema_valid_fast(version, doc) == want
        assert json.dumps(doc, sort_keys=True) == before  # the document is not changed
        rejected += not want
    assert rejected > 40


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_feature_schema_decided_as_jsonschema(tmp_path, version):
    good = _written(tmp_path, version)
    ref = CS._validators(version).feature
    oid = sorted(good["CityObjects"])[0]
    feature = {"type": "CityJSONFeature", "id": oid, "CityObjects": {oid: good["CityObjects"][oid]},
               "vertices": good["vertices"]}
    rng = np.random.default_rng(7)
    verdicts = set()
    for i in range(60):
        doc = json.loads(json.dumps(feature))
        for _ in range(int(rng.integers(0 if i < 3 else 1, 3))):
            _random_mutation(doc, rng)
        want = ref.is_valid(doc)
        assert CS._schema_valid_fast(version, doc, feature=True) == want
        verdicts.add(want)
    assert verdicts == {True, False}


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_semantic_types_decided_as_by_the_oneof(tmp_path, version):
    good = _written(tmp_path, version)
    ref = CS._validators(version).document
    key, gi = next((k, i) for k, c in good["CityObjects"].items()
                   for i, g in enumerate(c.get("geometry", [])) if g.get("semantics", {}).get("surfaces"))
    verdicts = set()
    for value in ["RoofSurface", "WallSurface", "GroundSurface", "Window", "TransportationMarking", "+Custom",
                  "+", "Roof+Surface", "+ x", "roofsurface", "", "Roof", 5, None, ["RoofSurface"], True]:
        doc = json.loads(json.dumps(good))
        doc["CityObjects"][key]["geometry"][gi]["semantics"]["surfaces"][0]["type"] = value
        want = ref.is_valid(doc)
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
