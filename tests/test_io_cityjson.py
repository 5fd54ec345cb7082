"""CityJSON / CityJSONSeq reading, writing and bad input handling."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from lod2energy.io import cityjson_write, read
from lod2energy.model import Building, FeatureError

from cityjson_docs import BOX_VERTICES, box_doc, parts_doc, to_seq, write


def _all(path, **kw):
    model, it = read(path, **kw)
    return model, list(it)


@pytest.mark.parametrize("version", ["1.0", "1.1", "2.0"])
def test_reads_every_supported_version(tmp_path, version):
    model, feats = _all(write(tmp_path, box_doc(version)))
    assert model.version == version
    (b,) = feats
    assert isinstance(b, Building) and b.id == "b1" and b.type == "Building"
    np.testing.assert_allclose(b.vertices.min(axis=0), [85000, 447000, 0])
    g = b.root.geometries[0]
    assert g.type == "Solid" and g.lod == "2.2" and g.n_surfaces == 6
    assert [g.semantic_type(s) for _, _, _, s in g.iter_surfaces()][:2] == ["GroundSurface", "RoofSurface"]


def test_utf8_bom_is_accepted(tmp_path):
    p = tmp_path / "bom.city.json"
    p.write_bytes(b"\xef\xbb\xbf" + json.dumps(box_doc()).encode())
    _, feats = _all(str(p))
    assert isinstance(feats[0], Building)


def test_cityjsonseq_streams_features_and_survives_a_broken_line(tmp_path):
    doc = box_doc(extra_objects={"b2": box_doc()["CityObjects"]["b1"]})
    text = to_seq(doc).splitlines()
    text.insert(2, '{"type": "CityJSONFeature", "CityObjects": {')  # truncated line
    p = write(tmp_path, None, "s.city.jsonl", "\n".join(text) + "\n")
    model, feats = _all(p)
    assert model.format == "CityJSONSeq"
    ok = [f for f in feats if isinstance(f, Building)]
    bad = [f for f in feats if isinstance(f, FeatureError)]
    assert [b.id for b in ok] == ["b1", "b2"]
    assert len(bad) == 1 and bad[0].code == 901 and "line 3" in bad[0].message


@pytest.mark.parametrize("text, code, words", [
    ("", 901, "not valid JSON"),
    ('{"type": "CityJSON", "version": "2.0", "CityObjects": {', 901, "not valid JSON"),
    ('[1, 2]', 901, "not an object"),
    ('{"type": "CityJSON", "version": "3.7", "CityObjects": {}, "vertices": []}', 904, "not supported"),
    ('{"type": "FeatureCollection"}', 904, "not 'CityJSON'"),
])
def test_unusable_files_give_one_file_level_error(tmp_path, text, code, words):
    model, feats = _all(write(tmp_path, None, "x.city.json", text))
    assert model is None
    (fe,) = feats
    assert isinstance(fe, FeatureError) and fe.id is None and fe.code == code and words in fe.message


def test_missing_vertices_is_a_file_error(tmp_path):
    doc = box_doc()
    del doc["vertices"]
    _, feats = _all(write(tmp_path, doc))
    assert isinstance(feats[0], FeatureError) and "vertices" in feats[0].message


def test_out_of_range_index_spoils_only_its_building(tmp_path):
    good = box_doc()["CityObjects"]["b1"]
    bad = json.loads(json.dumps(good))
    bad["geometry"][0]["boundaries"][0][0][0][0] = 999
    doc = box_doc(extra_objects={"bad": bad, "good2": good})
    _, feats = _all(write(tmp_path, doc))
    kinds = {f.id: type(f).__name__ for f in feats}
    assert kinds == {"b1": "Building", "bad": "FeatureError", "good2": "Building"}
    (fe,) = [f for f in feats if isinstance(f, FeatureError)]
    assert fe.code == 901 and "out of range" in fe.message and "coid=bad" in fe.message


def test_nan_coordinates_spoil_only_the_buildings_using_them(tmp_path):
    doc = box_doc()
    doc["transform"] = None
    doc["vertices"] = [list(map(float, v)) for v in BOX_VERTICES]
    text = json.dumps(doc).replace("[0.0, 0.0, 6.0]", "[NaN, 0.0, 6.0]")
    _, feats = _all(write(tmp_path, None, "n.city.json", text))
    assert isinstance(feats[0], FeatureError) and "non-finite" in feats[0].message


@pytest.mark.parametrize("lod, present", [(None, True), ("", True), (None, False)])
def test_missing_or_null_lod_is_reported_and_geometry_kept(tmp_path, lod, present):
    doc = box_doc()
    g = doc["CityObjects"]["b1"]["geometry"][0]
    if present:
        g["lod"] = lod
    else:
        del g["lod"]
    _, (b,) = _all(write(tmp_path, doc))
    (code, loc, msg), = b.provenance["input_errors"]
    assert code == 901 and loc == "coid=b1|geom=0" and "lod" in msg
    assert b.root.geometries[0].n_surfaces == 6


def test_unknown_geometry_type_and_empty_boundaries(tmp_path):
    doc = box_doc()
    doc["CityObjects"]["b1"]["geometry"][0]["type"] = "Polyhedron"
    _, (fe,) = _all(write(tmp_path, doc))
    assert isinstance(fe, FeatureError) and "unknown geometry type" in fe.message
    doc = box_doc()
    doc["CityObjects"]["b1"]["geometry"][0]["boundaries"] = []
    _, (b,) = _all(write(tmp_path, doc, "e.city.json"))
    assert isinstance(b, Building) and b.root.geometries[0].n_surfaces == 0


def test_huge_coordinates_keep_precision(tmp_path):
    doc = box_doc()
    doc["transform"]["translate"] = [4.0e6, 5.0e6, 100.0]
    _, (b,) = _all(write(tmp_path, doc))
    assert math.isclose(b.vertices[:, 0].max() - b.vertices[:, 0].min(), 10.0, abs_tol=1e-6)


def test_parts_are_grouped_with_their_parent(tmp_path):
    doc = parts_doc()
    _, feats = _all(write(tmp_path, doc))
    (b,) = feats
    assert [o.id for o in b.objects] == ["b1", "p1", "p2"]
    assert len(b.shells()) == 2 and b.default_lod() == "2.2"


@pytest.mark.parametrize("suffix", ["out.city.json", "out.city.jsonl"])
def test_round_trip_keeps_what_it_does_not_touch(tmp_path, suffix):
    doc = box_doc()
    doc["CityObjects"]["t1"] = {"type": "PlantCover", "attributes": {"k": [1, 2]},
                                "geometry": [{"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}]}
    doc["metadata"]["title"] = "round trip"
    model, feats = _all(write(tmp_path, doc))
    out = str(tmp_path / suffix)
    before = [b.vertices.copy() for b in feats]
    cityjson_write.write(out, model, feats)
    assert all(np.array_equal(a, b.vertices) for a, b in zip(before, feats))  # input untouched
    model2, feats2 = _all(out)
    assert model2.metadata["title"] == "round trip"
    assert {b.id for b in feats2} == {"b1", "t1"}
    b1 = next(b for b in feats2 if b.id == "b1")
    assert dict(b1.root.attributes) == {"yearOfConstruction": 1975, "note": "x"}
    np.testing.assert_allclose(np.sort(b1.vertices, axis=0), np.sort(feats[0].vertices, axis=0), atol=1e-9)
    g = b1.root.geometries[0]
    assert [g.semantic_type(s) for _, _, _, s in g.iter_surfaces()] == \
        ["GroundSurface", "RoofSurface"] + ["WallSurface"] * 4


def test_building_is_immutable(tmp_path):
    _, (b,) = _all(write(tmp_path, box_doc()))
    with pytest.raises((AttributeError, TypeError)):
        b.id = "x"
    with pytest.raises(ValueError):
        b.vertices[0, 0] = 1.0


def test_absurd_coordinates_spoil_only_their_building(tmp_path):
    doc = box_doc()
    doc["transform"]["translate"] = [1e15, 0.0, 0.0]
    _, (fe,) = _all(write(tmp_path, doc))
    assert isinstance(fe, FeatureError) and "coordinates beyond" in fe.message


def test_textures_and_version_1_0_lods_round_trip(tmp_path):
    doc = box_doc("1.0", lod=2)
    doc["CityObjects"]["b1"]["geometry"][0]["material"] = {"visual": {"value": 0}}
    model, feats = _all(write(tmp_path, doc))
    assert feats[0].root.geometries[0].lod == "2"
    out = tmp_path / "o.city.json"
    cityjson_write.write(str(out), model, feats)
    g = json.loads(out.read_text())["CityObjects"]["b1"]["geometry"][0]
    assert g["lod"] == 2 and g["material"] == {"visual": {"value": 0}}
