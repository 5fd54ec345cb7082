"""Energy-ADE CityJSON export: round trip per version, the shipped extension and schemas,
and the self-check catching broken files."""
from __future__ import annotations

import json
from dataclasses import replace
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from factories import box, gabled_house, open_box
from lod2energy import semantics as S
from lod2energy import thermal as T
from lod2energy.exporters.cityjson import writer as X
from lod2energy.exporters.cityjson import schema as CS
from lod2energy.io.cityjson_grid import on_grid
from lod2energy.io import cityjson as cjio
from lod2energy.model import Building, CityModel, frozen_mapping
from conftest import shared_path

VERSIONS = ("1.0", "1.1", "2.0")
KNOWN = dict(u_roof=0.2, u_wall=0.3, u_ground=0.4, u_window=1.5)


def energy_ready(b: Building, **attrs) -> Building:
    if attrs:
        b = replace(b, objects=(replace(b.root, attributes=frozen_mapping(attrs)),) + b.objects[1:])
    return T.assign_u_values(S.label_building(b), T.ThermalOptions(**KNOWN))


def model(version="2.0") -> CityModel:
    return CityModel(version=version, metadata=frozen_mapping({"referenceSystem": "urn:ogc:def:crs:EPSG::7415"}))


def two_buildings():
    return [energy_ready(box(id="box"), yearOfConstruction=1970),
            energy_ready(gabled_house(id="house"), yearOfConstruction=2001)]


# ----------------------------------------------------------------------------- round trip

@pytest.mark.parametrize("version", VERSIONS)
def test_round_trip(tmp_path, version):
    bs = two_buildings()
    path = tmp_path / "out.city.json"
    res = X.write(str(path), model(version), bs)
    assert res.ok, res.problems
    assert res.path == str(path) and path.exists() and not Path(str(path) + ".invalid").exists()
    assert res.version == version and res.building_ids == ("box", "house")
    assert (tmp_path / "energy.ext.json").exists()
    doc = json.loads(path.read_text())
    assert doc["version"] == version
    assert doc["extensions"]["Energy"]["url"] == "energy.ext.json"
    m, feats = cjio.read(str(path))
    back = {f.id: f for f in feats}
    for b in bs:
        f = back[b.id]
        th = b.provenance["thermal"]
        a = f.root.attributes
        assert a["+energyUA"] == pytest.approx(th["UA"])
        assert a["+energyEnvelopeArea"] == pytest.approx(th["A_env"])
        assert a["+energyVolume"] == pytest.approx(th["volume"])
        assert a["+energyTypology"] == th["typology"]
        assert a["+energyConstructionPeriod"] == th["construction_period"]
        assert a["+energyRepairStage"] == "none"
        assert a["+energyUValues"] == th["u_values"]
        (o, gi, g), = S.envelope_objects(f)
        (o0, gi0, g0), = S.envelope_objects(b)
        assert g.n_surfaces == g0.n_surfaces
        assert np.allclose(np.sort(f.vertices, axis=0), np.sort(b.vertices, axis=0), atol=1e-3)
        for (*_, s), (*_, s0) in zip(g.iter_surfaces(), g0.iter_surfaces()):
            e, e0 = g.semantic_surfaces[s.semantic], g0.semantic_surfaces[s0.semantic]
            for k in ("type", "uValue", "thermalBoundaryType", "area", "azimuth", "inclination"):
                assert e[k] == e0[k]
    assert X.self_check(str(path)) == []


def test_version_defaults_to_the_input_version(tmp_path):
    res = X.write(str(tmp_path / "a.city.json"), model("1.1"), two_buildings())
    assert res.ok and json.loads(Path(res.path).read_text())["version"] == "1.1"


def test_lod_is_a_number_in_1_0_and_a_string_later(tmp_path):
    for v in VERSIONS:
        res = X.write(str(tmp_path / f"{v}.city.json"), model("2.0"), two_buildings(), v)
        doc = json.loads(Path(res.path).read_text())
        lods = [g["lod"] for co in doc["CityObjects"].values() for g in co["geometry"]]
        assert lods and all(isinstance(x, (int, float)) if v == "1.0" else isinstance(x, str) for x in lods)


def test_crs_written_in_the_target_versions_form(tmp_path):
    r10 = X.write(str(tmp_path / "a.json"), model("2.0"), two_buildings(), "1.0")
    m = CityModel(version="1.0", metadata=frozen_mapping({"referenceSystem": "urn:ogc:def:crs:EPSG::7415"}))
    r20 = X.write(str(tmp_path / "b.json"), m, two_buildings(), "2.0")
    assert json.loads(Path(r10.path).read_text())["metadata"]["referenceSystem"] == "urn:ogc:def:crs:EPSG::7415"
    assert (json.loads(Path(r20.path).read_text())["metadata"]["referenceSystem"]
            == "https://www.opengis.net/def/crs/EPSG/0/7415")
    assert r10.ok and r20.ok


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_cityjsonseq_round_trip(tmp_path, version):
    m = replace(model(version), transform=frozen_mapping({"scale": [0.001] * 3, "translate": [0, 0, 0]}))
    res = X.write(str(tmp_path / "out.city.jsonl"), m, two_buildings(), version)
    assert res.ok, res.problems
    lines = Path(res.path).read_text().splitlines()
    assert len(lines) == 3 and json.loads(lines[1])["type"] == "CityJSONFeature"


def test_cityjsonseq_needs_1_1(tmp_path):
    res = X.write(str(tmp_path / "out.city.jsonl"), model("2.0"), two_buildings(), "1.0")
    assert not res.ok and "1.1" in res.problems[0]


@pytest.mark.parametrize("version", VERSIONS)
def test_addresses_follow_the_target_version(tmp_path, version):
    b = energy_ready(box())
    addr = {"CountryName": "Nederland", "location": {"type": "MultiPoint", "lod": "0", "boundaries": [0]}}
    b = replace(b, objects=(replace(b.root, extra=frozen_mapping({"address": addr})),))
    res = X.write(str(tmp_path / "a.city.json"), model("1.0"), [b], version)
    assert res.ok, res.problems
    out = json.loads(Path(res.path).read_text())["CityObjects"]["box"]["address"]
    assert out == ({"CountryName": "Nederland"} if version == "1.0" else [{"CountryName": "Nederland"}])


@pytest.mark.parametrize("version", VERSIONS)
def test_null_standard_attributes(tmp_path, version):
    b = energy_ready(box(), **{"class": None, "function": "residential", "note": None})
    res = X.write(str(tmp_path / "a.city.json"), model("2.0"), [b], version)
    assert res.ok, res.problems
    attrs = json.loads(Path(res.path).read_text())["CityObjects"]["box"]["attributes"]
    assert attrs["function"] == "residential"
    assert ("class" in attrs) == (version != "1.0")


def test_other_lods_and_installations_are_left_out(tmp_path):
    b = box()
    g = b.objects[0].geometries[0]
    lod1 = replace(g, lod="1")
    b = replace(b, objects=(replace(b.root, geometries=(lod1, g)),))
    res = X.write(str(tmp_path / "o.city.json"), model(), [energy_ready(b)])
    assert res.ok
    doc = json.loads(Path(res.path).read_text())
    assert [x["lod"] for x in doc["CityObjects"]["box"]["geometry"]] == ["2"]


# ----------------------------------------------------------------------------- skipping and failing

def test_unready_buildings_are_skipped_and_listed(tmp_path):
    good = two_buildings()
    no_thermal = S.label_building(box(id="plain"))
    broken = energy_ready(open_box(id="open"))
    res = X.write(str(tmp_path / "o.city.json"), model(), good + [no_thermal, broken])
    assert res.ok and res.building_ids == ("box", "house")
    reasons = dict(res.skipped)
    assert set(reasons) == {"plain", "open"}
    assert "thermal" in reasons["plain"] and "closed" in reasons["open"]


def test_a_failing_file_is_not_written_under_its_name(tmp_path):
    path = tmp_path / "o.city.json"
    path.write_text("old")
    broken = energy_ready(open_box(id="open"))
    res = X.write(str(path), model(), two_buildings() + [broken], exclude_unready=False)
    assert not res.ok and res.problems
    assert not path.exists() and res.path == str(path) + ".invalid" and Path(res.path).exists()
    assert any("coid=open" in p for p in res.problems)
    again = X.write(str(path), model(), two_buildings())
    assert again.ok and path.exists() and not Path(str(path) + ".invalid").exists()


def test_buildings_are_checked_on_the_files_grid(tmp_path):
    """A building that only breaks once its coordinates are rounded to the file's grid is
    left out, instead of failing the whole file."""
    coarse = replace(model(), transform=frozen_mapping({"scale": [1.0, 1.0, 1.0], "translate": [0, 0, 0]}))
    flat = energy_ready(box(10, 8, 0.4, id="flat"))        # 0.4 m high: rounds to nothing
    tall = energy_ready(box(10, 8, 6, id="tall"))
    res = X.write(str(tmp_path / "g.city.json"), coarse, [flat, tall])
    assert res.ok, res.problems
    assert res.building_ids == ("tall",) and [i for i, _ in res.skipped] == ["flat"]
    off = replace(tall, vertices=tall.vertices + 0.3)
    assert np.array_equal(on_grid(off, coarse.transform).vertices, np.rint(off.vertices))


def test_bad_version_is_reported(tmp_path):
    res = X.write(str(tmp_path / "o.city.json"), model(), two_buildings(), "3.0")
    assert not res.ok and "not supported" in res.problems[0]


# ----------------------------------------------------------------------------- self-check catches broken files

@pytest.fixture
def good_file(tmp_path):
    res = X.write(str(tmp_path / "g.city.json"), model("2.0"), two_buildings())
    assert res.ok
    return Path(res.path)


def _mutate(path: Path, fn) -> Path:
    doc = json.loads(path.read_text())
    fn(doc)
    out = path.with_name("bad.city.json")
    out.write_text(json.dumps(doc))
    return out


def _box_geom(doc):
    return doc["CityObjects"]["box"]["geometry"][0]


def _drop_face(doc):
    g = _box_geom(doc)
    g["boundaries"][0].pop(1)
    g["semantics"]["values"][0].pop(1)


def _flip_face(doc):
    g = _box_geom(doc)
    g["boundaries"][0][2] = [r[::-1] for r in g["boundaries"][0][2]]


def _no_u(doc):
    g = _box_geom(doc)
    g["semantics"]["surfaces"][0].pop("uValue")


def _unlabelled(doc):
    g = _box_geom(doc)
    g["semantics"]["values"][0][3] = None


def _bad_semantic_type(doc):
    _box_geom(doc)["semantics"]["surfaces"][0]["type"] = "Roof"


def _bad_object_type(doc):
    doc["CityObjects"]["box"]["type"] = "BuildingZ"


def _bad_extension_value(doc):
    doc["CityObjects"]["box"]["attributes"]["+energyUA"] = "high"


def _undeclared_extension_attribute(doc):
    doc["CityObjects"]["box"]["attributes"]["+energyColour"] = "red"


def _bad_vertex_index(doc):
    _box_geom(doc)["boundaries"][0][0][0][0] = len(doc["vertices"]) + 5


def _address_as_object(doc):
    doc["CityObjects"]["box"]["address"] = {"CountryName": "Nederland"}    # 1.0 style in a 2.0 file


def _whole_box_inverted(doc):
    g = _box_geom(doc)
    g["boundaries"][0] = [[r[::-1] for r in s] for s in g["boundaries"][0]]


@pytest.mark.parametrize("mutation, fragment", [
    (_drop_face, "not closed"),
    (_flip_face, "not closed or not consistently oriented"),
    (_whole_box_inverted, "oriented inwards"),
    (_no_u, "no positive uValue"),
    (_unlabelled, "no semantic surface"),
    (_bad_semantic_type, "schema"),
    (_bad_object_type, "schema"),
    (_bad_extension_value, "+energyUA"),
    (_undeclared_extension_attribute, "not defined by the Energy extension"),
    (_bad_vertex_index, "out of range"),
    (_address_as_object, "CityObjects/box/address"),
])
def test_self_check_catches(good_file, mutation, fragment):
    bad = _mutate(good_file, mutation)
    problems = X.self_check(str(bad))
    assert problems, mutation.__name__
    assert any(fragment in p for p in problems), problems


def test_self_check_on_non_json(tmp_path):
    p = tmp_path / "x.city.json"
    p.write_text("{not json")
    assert "not valid JSON" in X.self_check(str(p))[0]


def test_self_check_needs_no_shared_folder():
    d = resources.files("lod2energy") / "data"
    for v in ("10", "11", "20"):
        assert (d / "extensions" / v / "energy.ext.json").is_file()
        assert any(f.name.startswith("cityjson") for f in (d / "schemas" / "cityjson" / v).iterdir())
    assert "shared" not in str(Path(str(d)).resolve().relative_to(Path(X.__file__).resolve().parents[2]))


@pytest.mark.parametrize("v", ("11", "20"))
def test_shipped_extension_is_valid_against_the_extension_schema(v):
    import jsonschema

    d = resources.files("lod2energy") / "data"
    meta = json.loads((d / "schemas" / "cityjson" / "extensions" / v / "extension.schema.json").read_text())
    ext = json.loads((d / "extensions" / v / "energy.ext.json").read_text())
    jsonschema.Draft7Validator(meta).validate(ext)
    assert all(k.startswith("+energy") for k in ext["extraAttributes"]["Building"])


def test_fast_schema_check_agrees_with_full_validation(good_file):
    """The per-CityObject dispatch gives the same verdict as validating the whole document."""
    schemas = CS._validators("2.0")
    for fn in (lambda d: None, _bad_semantic_type, _bad_object_type):
        doc = json.loads(good_file.read_text())
        fn(doc)
        full = list(schemas.document.iter_errors(doc))
        fast = CS._schema_errors(schemas, doc, "doc")
        assert bool(full) == bool(fast)


# ----------------------------------------------------------------------------- real tiles

@pytest.mark.parametrize("version", VERSIONS)
def test_real_tile_export_is_schema_valid_labelled_with_u_values(tmp_path, version):
    src = shared_path("3dbag", "small.city.jsonl")
    m, feats = cjio.read(str(src))
    bs = [T.assign_u_values(S.label_building(f), T.ThermalOptions(crs=m.crs)) for f in feats]
    res = X.write(str(tmp_path / "small.city.json"), m, bs, version)
    assert res.ok, res.problems
    assert not res.skipped
    _, back = cjio.read(res.path)
    n = 0
    for f in back:
        for o, gi, g in S.envelope_objects(f):
            for *_, s in g.iter_surfaces():
                e = g.semantic_surfaces[s.semantic]
                assert e["type"] in S.ENVELOPE_TYPES and e["uValue"] > 0
                n += 1
    assert n > 0


@pytest.mark.slow
def test_rotterdam_tile_with_installations(tmp_path):
    src = shared_path("rotterdam", "Example_CityGML_Converted_Rotterdam.json")
    m, feats = cjio.read(str(src))
    bs = [T.assign_u_values(S.label_building(f), T.ThermalOptions(crs=m.crs)) for f in feats
          if isinstance(f, Building) and f.is_building]
    res = X.write(str(tmp_path / "r.city.json"), m, bs)
    assert res.ok, res.problems
    assert res.version == "1.0"
    assert len(res.building_ids) + len(res.skipped) == len(bs)
    assert len(res.building_ids) >= len(bs) // 2


# ----------------------------------------------------------------------------- compiled schema check

def _random_mutation(doc, rng):
    """Change one value somewhere in ``doc``: a key dropped, a type changed, a string or
    number replaced, a list emptied, an unknown key added."""
    path, node = [], doc
    while isinstance(node, (dict, list)) and node and rng.random() < 0.8:
        keys = list(node.keys()) if isinstance(node, dict) else list(range(len(node)))
        k = keys[rng.integers(len(keys))]
        path.append((node, k))
        node = node[k]
    if not path:
        doc["bogus"] = 1
        return
    parent, k = path[-1]
    r = rng.integers(6)
    if r == 0 and isinstance(parent, dict):
        del parent[k]
    elif r == 1:
        parent[k] = "x"
    elif r == 2:
        parent[k] = -1.5
    elif r == 3:
        parent[k] = []
    elif r == 4:
        parent[k] = {"unknown": True}
    else:
        parent[k] = None


@pytest.mark.parametrize("version", ("1.1", "2.0"))
def test_fast_schema_check_never_accepts_what_jsonschema_rejects(tmp_path, version):
    """The jsonschema-rs validator is a shortcut for valid documents: whatever it accepts the
    official schema (jsonschema) accepts too, and it does not change the document."""
    res = X.write(str(tmp_path / "g.city.json"), model(version), two_buildings(), version)
    assert res.ok
    good = json.loads(Path(res.path).read_text())
    schemas = CS._validators(version)
    assert CS._schema_valid_fast(version, good)
    rng = np.random.default_rng(3)
    rejected = 0
    for _ in range(200):
        doc = json.loads(json.dumps(good))
        for _ in range(int(rng.integers(1, 3))):
            _random_mutation(doc, rng)
        before = json.dumps(doc, sort_keys=True)
        fast = CS._schema_valid_fast(version, doc)
        assert json.dumps(doc, sort_keys=True) == before
        full = not CS._schema_errors(schemas, doc, "doc")   # agrees with iter_errors (test above)
        assert full or not fast
        rejected += not fast
    assert rejected > 60
    for fn in (_bad_semantic_type, _bad_object_type, _address_as_object):
        doc = json.loads(json.dumps(good))
        fn(doc)
        assert not CS._schema_valid_fast(version, doc)
