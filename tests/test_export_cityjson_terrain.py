"""The input's terrain (TINRelief) in the energy CityJSON: carried as read, on the file's grid,
schema-valid against the official schemas (``../shared/schemas``), and counted in the report."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from conftest import SHARED, shared_path
from factories import box
from lod2energy.exporters.cityjson import writer as X
from lod2energy.exporters.cityjson.terrain import prepare_terrain, terrain_problem
from lod2energy.io import cityjson as cjio
from lod2energy.model import Building, CityModel, CityObject, Geometry, Shell, Solid, Surface, frozen_mapping
from test_export_cityjson import energy_ready

VERSIONS = ("1.0", "1.1", "2.0")
_VDIR = {"1.0": "10", "1.1": "11", "2.0": "20"}
#: The 2-triangle TIN under the box (m): a square 20 x 18 m, off the millimetre grid by 0.4 mm.
TIN_VERTICES = np.array([[-5.0004, -5.0004, -0.1], [15.0004, -5.0, -0.05], [15.0, 13.0004, 0.0],
                         [-5.0, 13.0, -0.0204]])
TIN_TRIANGLES = ((0, 1, 2), (0, 2, 3))


def official_errors(doc: dict, version: str) -> list[str]:
    """Errors of ``doc`` against the official schema of ``version`` (the shared copy, not the
    one the writer bundles)."""
    import jsonschema
    p = SHARED / "schemas" / "cityjson" / _VDIR[version] / "cityjson.min.schema.json"
    if not p.exists():
        pytest.skip(f"official schema not available: {p}")
    v = jsonschema.Draft7Validator(json.loads(p.read_text(encoding="utf-8")))
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message[:200]}" for e in v.iter_errors(doc)]


def tin(gtype: str = "CompositeSurface", id: str = "dtm", lod: str = "1", **attrs) -> Building:
    """The 2-triangle TINRelief feature, as the CityJSON reader yields one."""
    surfaces = tuple(Surface.from_lists([list(t)]) for t in TIN_TRIANGLES)
    g = Geometry(gtype, lod, (Solid((Shell(surfaces),)),))
    return Building(id, "TINRelief", TIN_VERTICES.copy(),
                    (CityObject(id, "TINRelief", (g,), frozen_mapping(attrs)),))


def model(version: str = "2.0") -> CityModel:
    return CityModel(version=version, metadata=frozen_mapping({"referenceSystem": "urn:ogc:def:crs:EPSG::7415"}))


def terrain_objects(doc: dict) -> dict:
    return {k: co for k, co in doc["CityObjects"].items() if co["type"] == "TINRelief"}


def file_vertices(doc: dict) -> np.ndarray:
    t = doc["transform"]
    return np.asarray(doc["vertices"], dtype=np.float64) * t["scale"] + t["translate"]


def assert_tin_on_grid(doc: dict, geom: dict, expected: np.ndarray) -> None:
    """The TIN's triangles in the file are ``expected`` (k, 3, 3) rounded to the file's grid."""
    v = file_vertices(doc)
    got = np.array([[v[i] for i in face[0]] for face in geom["boundaries"]])
    assert got.shape == expected.shape
    scale = np.asarray(doc["transform"]["scale"])
    assert (np.abs(got - expected) <= scale / 2 + 1e-9).all()
    # exactly the grid nodes: an integer number of steps from the translation
    k = (got - doc["transform"]["translate"]) / scale
    assert np.allclose(k, np.rint(k), atol=1e-6)


# ----------------------------------------------------------------------------- the writer

@pytest.mark.parametrize("version", VERSIONS)
def test_tin_is_carried_on_the_grid_with_its_attributes(tmp_path, version):
    path = tmp_path / "out.city.json"
    res = X.write(str(path), model(version), [energy_ready(box(id="b")), tin(source="tiny DTM", year=2020)])
    assert res.ok, res.problems
    assert res.building_ids == ("b",) and res.terrain == (("dtm", 2),) and not res.skipped
    doc = json.loads(path.read_text())
    assert official_errors(doc, version) == []
    (co,) = terrain_objects(doc).values()
    assert co["attributes"] == {"source": "tiny DTM", "year": 2020}
    assert not any(k.startswith("+energy") for k in co["attributes"])
    (g,) = co["geometry"]
    assert g["type"] == "CompositeSurface"
    assert g["lod"] == (1 if version == "1.0" else "1")
    assert len(g["boundaries"]) == 2 and all(len(f) == 1 and len(f[0]) == 3 for f in g["boundaries"])
    assert_tin_on_grid(doc, g, TIN_VERTICES[np.array(TIN_TRIANGLES)])
    # the building is still the energy building, and the file reads back with both
    _, feats = cjio.read(str(path))
    types = {f.id: f.type for f in feats}
    assert types == {"b": "Building", "dtm": "TINRelief"}
    assert X.self_check(str(path)) == []


def test_without_terrain_the_result_has_no_terrain_member(tmp_path):
    res = X.write(str(tmp_path / "o.city.json"), model(), [energy_ready(box(id="b"))])
    assert res.ok and res.terrain == ()
    assert not terrain_objects(json.loads(Path(res.path).read_text()))


def test_a_multisurface_tin_is_written_as_the_compositesurface_the_schema_wants(tmp_path):
    t = tin("MultiSurface")
    assert prepare_terrain(t).objects[0].geometries[0].type == "CompositeSurface"
    res = X.write(str(tmp_path / "o.city.json"), model("1.1"), [energy_ready(box(id="b")), t])
    assert res.ok, res.problems
    assert res.terrain == (("dtm", 2),)
    doc = json.loads(Path(res.path).read_text())
    (co,) = terrain_objects(doc).values()
    assert [g["type"] for g in co["geometry"]] == ["CompositeSurface"]
    assert official_errors(doc, "1.1") == []


def test_a_terrain_the_schema_cannot_hold_is_left_out_with_its_reason(tmp_path):
    bad = tin("Solid", id="dtm_solid")
    assert "Solid" in terrain_problem(bad) and "coid=dtm_solid|geom=0" in terrain_problem(bad)
    assert terrain_problem(tin(lod=None)) is not None
    res = X.write(str(tmp_path / "o.city.json"), model(), [energy_ready(box(id="b")), bad, tin()])
    assert res.ok, res.problems
    assert res.terrain == (("dtm", 2),)
    assert [s[0] for s in res.skipped] == ["dtm_solid"]
    assert set(terrain_objects(json.loads(Path(res.path).read_text()))) == {"dtm"}


def test_cityjsonseq_carries_the_terrain_as_a_feature(tmp_path):
    res = X.write(str(tmp_path / "o.city.jsonl"), model("2.0"), [energy_ready(box(id="b")), tin()])
    assert res.ok, res.problems
    assert res.terrain == (("dtm", 2),)
    lines = [json.loads(ln) for ln in Path(res.path).read_text().splitlines()]
    assert [ln["id"] for ln in lines[1:]] == ["b", "dtm"]
    assert lines[2]["CityObjects"]["dtm"]["type"] == "TINRelief"


# ----------------------------------------------------------------------------- the command

def cityjson_input(tmp_path) -> str:
    """A CityJSON box building on a 2-triangle TIN (integer vertices on a 1 mm grid)."""
    from cityjson_docs import box_doc
    doc = box_doc()
    n = len(doc["vertices"])
    doc["vertices"] += [[-5000, -5000, -100], [15000, -5000, -50], [15000, 13000, 0], [-5000, 13000, -20]]
    doc["CityObjects"]["dtm"] = {"type": "TINRelief", "attributes": {"source": "tiny DTM"}, "geometry": [
        {"type": "CompositeSurface", "lod": "1", "boundaries": [[[n, n + 1, n + 2]], [[n, n + 2, n + 3]]]}]}
    p = tmp_path / "in.city.json"
    p.write_text(json.dumps(doc), encoding="utf-8")
    return str(p)


def run(args, capsys):
    from lod2energy.cli import main
    rc = main(args)
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return rc, out, err


@pytest.mark.parametrize("version", VERSIONS)
def test_export_carries_the_cityjson_terrain_and_reports_it(tmp_path, capsys, version):
    src = cityjson_input(tmp_path)
    out = tmp_path / "out"
    rc, text, err = run(["export", src, "-o", str(out), "--cityjson", "--cityjson-version", version], capsys)
    assert rc == 0, err
    path = out / "in.energy.city.json"
    doc = json.loads(path.read_text())
    assert official_errors(doc, version) == []
    (co,) = terrain_objects(doc).values()
    assert co["attributes"] == {"source": "tiny DTM"}
    src_doc = json.loads(Path(src).read_text())
    sv = np.asarray(src_doc["vertices"], float) * 0.001 + src_doc["transform"]["translate"]
    expected = np.array([[sv[i] for i in f[0]] for f in src_doc["CityObjects"]["dtm"]["geometry"][0]["boundaries"]])
    assert_tin_on_grid(doc, co["geometry"][0], expected)
    rep = json.loads((out / "report.json").read_text())
    assert rep["terrain"] == [{"format": "cityjson", "path": str(path), "ok": True, "objects": 1, "faces": 2,
                               "ids": ["dtm"]}]
    assert [b["id"] for b in rep["buildings"]] == ["b1"] and rep["buildings"][0]["exports"]["cityjson"]["ok"]
    assert f"terrain: 1 TINRelief object(s), 2 faces, carried into {path}" in text


def test_export_without_terrain_reports_none(tmp_path, capsys):
    from cityjson_docs import box_doc, write
    src = write(tmp_path, box_doc(), name="in.city.json")
    out = tmp_path / "out"
    rc, text, err = run(["export", src, "-o", str(out), "--cityjson"], capsys)
    assert rc == 0, err
    assert "terrain" not in json.loads((out / "report.json").read_text())
    assert "terrain:" not in text


@pytest.mark.parametrize("version", (None, "1.0"))
def test_export_carries_a_citygml_tin_relief(tmp_path, capsys, version):
    from test_citygml import box_body, building, city_model, read_all, write
    from test_citygml_relief import relief, triangulated
    src = write(tmp_path, city_model(building("B", box_body()), relief(triangulated())))
    _, feats = read_all(src)
    (t,) = [f for f in feats if f.type == "TINRelief"]
    (g0,) = t.objects[0].geometries
    expected = np.array([[t.vertices[i] for i in s.rings[0]] for _, _, sh in g0.iter_shells() for s in sh.surfaces])
    out = tmp_path / "out"
    args = ["export", src, "-o", str(out), "--cityjson", "-q"] + (["--cityjson-version", version] if version else [])
    rc, _, err = run(args, capsys)
    assert rc == 0, err
    doc = json.loads((out / "tile.energy.city.json").read_text())
    assert official_errors(doc, doc["version"]) == []
    (co,) = terrain_objects(doc).values()
    (g,) = co["geometry"]
    assert (g["type"], str(g["lod"])) == ("CompositeSurface", "2")
    assert len(g["boundaries"]) == 32 == len(expected)
    assert_tin_on_grid(doc, g, expected)
    rep = json.loads((out / "report.json").read_text())
    assert (rep["terrain"][0]["objects"], rep["terrain"][0]["faces"], rep["terrain"][0]["ids"]) == (1, 32, ["tin1"])


# ----------------------------------------------------------------------------- a real tile

def test_real_tile_terrain_is_carried_schema_valid(tmp_path):
    """Den Haag tile 01's TINRelief (CityJSON 1.1) with three of its buildings."""
    from lod2energy import semantics as S
    from lod2energy import thermal as T
    src = shared_path("denhaag", "DenHaag_01.city.json")
    m, feats = cjio.read(str(src))
    terrain, bs = [], []
    for f in feats:
        if isinstance(f, Building) and f.type == "TINRelief":
            terrain.append(f)
        elif isinstance(f, Building) and f.is_building and len(bs) < 3:
            bs.append(T.assign_u_values(S.label_building(f), T.ThermalOptions(crs=m.crs)))
    assert len(terrain) == 1
    n_in = sum(len(sh.surfaces) for o in terrain[0].objects for g in o.geometries for *_, sh in g.iter_shells())
    res = X.write(str(tmp_path / "dh.city.json"), m, bs + terrain)
    assert res.ok, res.problems
    assert res.terrain == ((terrain[0].id, n_in),)
    doc = json.loads(Path(res.path).read_text())
    assert official_errors(doc, "1.1") == []
    (co,) = terrain_objects(doc).values()
    assert len(co["geometry"][0]["boundaries"]) == n_in
    assert doc["transform"] == json.loads(Path(src).read_text())["transform"]
