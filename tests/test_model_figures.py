"""Areas by thermal boundary, UA and party walls are the written IDF's (issue 39 item 4).

Tiny named geometries: two boxes side by side (a terraced pair sharing one wall) and a box
alone; the writer's figures are recomputed from the IDF it wrote (:mod:`idf_figures`, eppy).
Real tiles: for every IDF of three shared tiles (Den Haag terraced blocks, a 3DBAG subset of
Delft, a Berlin CityGML tile) report.json's figures equal the IDF's within 0.5%.
"""
from __future__ import annotations

import json

import pytest

from export_helpers import energy_ready, write_idf
from factories import box
from idf_figures import AREA_KEYS, idf_figures
from conftest import shared_path

from lod2energy.cli import main
from lod2energy.energy.figures import boundary_of, envelope_figures
from lod2energy.records import BuildingRecord, ExportRecord, ThermalRecord


def _close(a: float, b: float, rel: float = 0.005, abs_: float = 0.01) -> bool:
    return abs(a - b) <= max(rel * max(abs(a), abs(b)), abs_)


def _agree(figures: dict, recomputed: dict) -> list[str]:
    bad = [f"{k}: {figures['areas'][k]} != {recomputed['areas'][k]:.3f}" for k in AREA_KEYS
           if not _close(figures["areas"][k], recomputed["areas"][k])]
    if not _close(figures["UA"], recomputed["UA"]):
        bad.append(f"UA: {figures['UA']} != {recomputed['UA']:.3f}")
    return bad


def test_boundary_classes():
    assert boundary_of("Wall", "Outdoors") == "wall"
    assert boundary_of("Wall", "Adiabatic") == "adiabatic"
    assert boundary_of("Floor", "Ground") == "ground"
    assert boundary_of("Floor", "Outdoors") == "floor_exposed"
    assert boundary_of("Roof", "Outdoors") == "roof"
    assert boundary_of("Floor", "Surface") == "interzone"


def test_envelope_figures_leave_party_walls_and_windows_out_of_the_opaque_ua():
    f = envelope_figures([("wall", 10.0, 0.5, 2.0), ("adiabatic", 20.0, 0.5, 0.0), ("roof", 5.0, 0.2, 0.0)],
                         [(2.0, 1.5)])
    assert f["areas"]["wall"] == 10.0 and f["areas"]["adiabatic"] == 20.0 and f["areas"]["window"] == 2.0
    assert f["UA"] == pytest.approx(0.5 * 8 + 0.2 * 5 + 1.5 * 2)
    assert f["A_env"] == 15.0  # party walls are not envelope


def test_terraced_pair_figures_equal_the_written_idf(tmp_path):
    left = energy_ready(box(10, 8, 6, id="left"))
    right = energy_ready(box(10, 8, 6, origin=(10.0, 0.0, 0.0), id="right"))
    res = write_idf([left], tmp_path, context=[right])
    assert len(res) == 1 and res[0].ok, res[0].problems
    fig = res[0].stats["envelope"]["left"]
    assert fig["areas"]["adiabatic"] == pytest.approx(8 * 6, rel=1e-3)  # the shared wall
    assert fig["areas"]["wall"] == pytest.approx(2 * (10 * 6) + 8 * 6, rel=1e-3)  # three outdoor walls
    assert not _agree(fig, idf_figures(res[0].path))
    alone = write_idf([left], tmp_path / "alone")[0].stats["envelope"]["left"]
    assert alone["areas"]["adiabatic"] == 0.0 and alone["UA"] > fig["UA"]


def test_the_record_takes_the_written_models_figures():
    th = ThermalRecord.from_block({"areas": {"roof": 1.0, "wall": 2.0, "ground": 1.0}, "A_env": 4.0, "UA": 9.0})
    rec = BuildingRecord(0, "b", "Building", thermal=th)
    fig = envelope_figures([("wall", 1.5, 1.0, 0.0), ("adiabatic", 0.5, 1.0, 0.0)])
    rec = rec.with_export(ExportRecord("idf", True, "b.idf", (), {"envelope": {"b": fig, "other": {}}}))
    assert rec.thermal.UA == fig["UA"] == 1.5 and rec.thermal.detail["UA_geometry"] == 9.0
    assert rec.thermal.detail["figures_source"] == "idf" and rec.row()["adiabatic_m2"] == 0.5
    assert "envelope" not in rec.export("idf").to_json()  # the thermal block carries them
    again = BuildingRecord.from_json(json.loads(json.dumps(rec.to_json())))
    assert again.thermal.UA == 1.5


def _first_building_ids(path, n: int, start: int = 0) -> list[str]:
    d = json.loads(path.read_text())
    return [k for k, v in d["CityObjects"].items() if v["type"] == "Building"][start:start + n]


@pytest.mark.parametrize("tile", ["denhaag", "delft", "berlin"])
def test_report_figures_equal_each_written_idf(tile, tmp_path):
    extra = []
    if tile == "denhaag":  # terraced blocks: party walls with neighbours outside the selection
        src = shared_path("denhaag", "DenHaag_01.city.json")
        extra = ["--ids", ",".join(_first_building_ids(src, 12, 100))]
    elif tile == "delft":
        src = shared_path("3dbag", "delft_subset.city.jsonl")
    else:
        src = shared_path("citygml-real", "berlin", "3900_5819.gml")
    out = tmp_path / "out"
    assert main(["export", str(src), "-o", str(out), "--idf", "--geojson", "--cityjson", "-q", "-j", "1", "--no-html",
                 *extra]) in (0, 1)
    rep = json.loads((out / "report.json").read_text())
    checked = adiabatic = 0
    for b in rep["buildings"]:
        e = b["exports"].get("idf") or {}
        if not e.get("ok"):
            continue
        th = b["thermal"]
        assert th["figures_source"] == "idf"
        bad = _agree(th, idf_figures(e["path"]))
        assert not bad, (b["id"], bad)
        checked += 1
        adiabatic += th["areas"]["adiabatic"] > 0
    assert checked >= 3
    if tile == "denhaag":
        assert adiabatic >= checked // 2
        cj = json.loads(next(out.glob("*.city.json")).read_text())
        types = {sf.get("thermalBoundaryType") for o in cj["CityObjects"].values() for g in o.get("geometry", [])
                 for sf in (g.get("semantics") or {}).get("surfaces", [])}
        assert "sharedWallOrFloor" in types and "exterior" in types
    feats = json.loads(next(out.glob("*.geojson")).read_text())["features"]
    by_id = {b["id"]: b["thermal"] for b in rep["buildings"] if b["thermal"].get("figures_source")}
    for f in feats:
        if f["id"] in by_id:
            assert f["properties"]["UA_W_per_K"] == by_id[f["id"]]["UA"]


def test_the_shared_wall_is_shared_wall_or_floor_in_the_cityjson_semantics(tmp_path):
    from lod2energy.energy.figures import with_shared_boundaries
    from lod2energy.semantics import face_table

    left = energy_ready(box(10, 8, 6, id="left"))
    right = energy_ready(box(10, 8, 6, origin=(10.0, 0.0, 0.0), id="right"))
    fig = write_idf([left], tmp_path, context=[right])[0].stats["envelope"]["left"]
    assert list(fig["shared_faces"].values()) == [[fig["shared_faces"]["left"][0]]]
    out = with_shared_boundaries(left, fig["shared_faces"])
    (o, gi, g), = out.envelope()
    t = face_table(out.vertices, g)
    shared = [float(t.area[i]) for i, s in enumerate(t.surfaces)
              if g.semantic_surfaces[s.semantic].get("thermalBoundaryType") == "sharedWallOrFloor"]
    assert shared == [pytest.approx(48.0)]
    # the other walls keep theirs, and the input building is unchanged
    assert sum(e.get("thermalBoundaryType") == "exterior" for e in g.semantic_surfaces) >= 1
    (_, _, g0), = left.envelope()
    assert all(e.get("thermalBoundaryType") != "sharedWallOrFloor" for e in g0.semantic_surfaces)
