"""Compliant vs written: the energy CityJSON holds every building its writer's check (the one
final check, :func:`lod2energy.validate.closed.export_problem`) accepts, each with its compliance
block; a building whose val3dity-valid geometry keeps a sliver face (1003, which the repair
could not collapse) is written with ``compliant: false`` and gets no IDF/STL. So the number of
buildings the file calls compliant is the number the pipeline calls compliant."""
from __future__ import annotations

import dataclasses
import json
import logging

import pytest

from test_repair import building
from lod2energy.config import DEFAULT
from lod2energy.model import CityModel
from lod2energy.options import PrepareOptions
from lod2energy.prepare import final_check, prepare_building
from lod2energy.validate.checks import validate_building

#: The user's sliver tolerance: faces up to 0.3 m2 are slivers (val3dity does not mind them).
TOL = dataclasses.replace(DEFAULT, sliver_area=0.3)


def _chamfered_data(dx: float = 0.0):
    """Vertices (m), faces and semantic indices (0 ground, 1 roof, 2 wall) of a 10 x 8 x 6 m box
    whose top corner (10, 8, 6) is cut off by a 0.22 m2 triangle."""
    v = [(0, 0, 0), (10, 0, 0), (10, 8, 0), (0, 8, 0), (0, 0, 6), (10, 0, 6), (0, 8, 6),
         (9.5, 8, 6), (10, 7.5, 6), (10, 8, 5.5)]
    f = [[0, 3, 2, 1], [4, 5, 8, 7, 6], [0, 1, 5, 4], [1, 2, 9, 8, 5], [2, 3, 6, 7, 9], [3, 0, 4, 6], [7, 8, 9]]
    return [(x + dx, y, z) for x, y, z in v], f, [0, 1, 2, 2, 2, 2, 2]


def _box_data(dx: float = 30.0):
    v = [(0, 0, 0), (10, 0, 0), (10, 8, 0), (0, 8, 0), (0, 0, 6), (10, 0, 6), (10, 8, 6), (0, 8, 6)]
    f = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return [(x + dx, y, z) for x, y, z in v], f, [0, 1, 2, 2, 2, 2]


def chamfered(dx: float = 0.0, bid: str = "chamfered"):
    v, f, sem = _chamfered_data(dx)
    return building(v, f, semantics=sem, bid=bid)


def plain_box(dx: float = 30.0, bid: str = "box"):
    v, f, sem = _box_data(dx)
    return building(v, f, semantics=sem, bid=bid)


def test_a_valid_building_with_a_kept_sliver_is_written_as_not_compliant(tmp_path):
    from lod2energy.exporters.cityjson import writer as cityjson
    opts = dataclasses.replace(PrepareOptions(), tol=TOL)
    prepared = [prepare_building(b, opts) for b in (chamfered(), plain_box())]
    (sl, sl_rec), (ok, ok_rec) = prepared
    assert validate_building(chamfered(), TOL) == []
    # the pipeline: not compliant, not geometry-ready (no IDF/STL) because of the sliver ...
    assert not sl_rec.energy.compliant and not sl_rec.energy.geometry_ready
    assert any("sliver" in r for r in sl_rec.energy.reasons)
    assert 1003 in sl_rec.repair.detail["defects_after"]
    assert ok_rec.energy.compliant
    # ... while its geometry passes the writers' check: written, with its status
    assert final_check(sl, validate_building(sl, TOL), None, TOL) is None
    res = cityjson.write(str(tmp_path / "e.city.json"), CityModel(), [sl, ok], tol=TOL)
    assert res.ok and not res.skipped and set(res.building_ids) == {"chamfered", "box"}
    doc = json.loads((tmp_path / "e.city.json").read_text())
    flags = {k: o["attributes"]["+energyCompliance"]["compliant"] for k, o in doc["CityObjects"].items()
             if not o.get("parents")}
    assert flags == {"chamfered": False, "box": True}
    assert sum(flags.values()) == sum(r.energy.compliant for _, r in prepared)


def _doc_of(**buildings) -> dict:
    """A CityJSON 2.0 document (1 mm grid) of ``id=(vertices, faces, semantics)`` (one Solid each)."""
    types = [{"type": "GroundSurface"}, {"type": "RoofSurface"}, {"type": "WallSurface"}]
    verts, objs = [], {}
    for bid, (v, f, sem) in buildings.items():
        base = len(verts)
        verts += [[round(c * 1000) for c in p] for p in v]
        objs[bid] = {"type": "Building", "attributes": {"yearOfConstruction": 1975},
                     "geometry": [{"type": "Solid", "lod": "2.2",
                                   "boundaries": [[[[base + i for i in face]] for face in f]],
                                   "semantics": {"surfaces": types, "values": [sem]}}]}
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [0.001, 0.001, 0.001], "translate": [85000.0, 447000.0, 0.0]},
            "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
            "CityObjects": objs, "vertices": verts}


def test_every_writer_accepts_exactly_the_buildings_called_compliant(tmp_path, capsys, caplog):
    """Issue 19: the energy CityJSON carries the not-compliant building (nothing lost), but does not
    accept it as an energy model: compliant, cityjson_ok and stl_ok count the same buildings, and
    the user reads a note, not a self-check failure."""
    from lod2energy.options import ExportOptions, RunOptions
    from lod2energy.pipeline import export
    src = tmp_path / "two.city.json"
    src.write_text(json.dumps(_doc_of(chamfered=_chamfered_data(), box=_box_data())), encoding="utf-8")
    out = tmp_path / "o"
    opts = ExportOptions(("cityjson", "stl"), dataclasses.replace(PrepareOptions(), tol=TOL), html=False)
    with caplog.at_level(logging.INFO, logger="lod2energy"):  # the notes, whatever ran before
        res = export(str(src), str(out), opts, RunOptions(jobs=1))
    err = capsys.readouterr().err + caplog.text
    rows = {r["id"]: r for r in json.loads((out / "report.json").read_text())["buildings"]}
    assert set(rows) == {"chamfered", "box"}
    compliant = {i for i, r in rows.items() if r["compliant"]}
    assert compliant == {"box"}
    for fmt in ("cityjson", "stl"):
        assert {i for i, r in rows.items() if r["exports"].get(fmt, {}).get("ok")} == compliant, fmt
    # the not-compliant building is still in the file, with its status, and says why it is not accepted
    doc = json.loads((out / "two.energy.city.json").read_text())
    assert doc["CityObjects"]["chamfered"]["attributes"]["+energyCompliance"]["compliant"] is False
    why = rows["chamfered"]["exports"]["cityjson"]["problems"][0]
    assert why.startswith("in the file, not energy-compliant: ") and "sliver" in why
    assert "failed its self-check" not in err and "not accepted as energy models" in err
    assert res.exit_code == 1  # a building is not compliant


def test_an_export_record_says_whether_a_file_failed_or_none_was_written():
    from lod2energy.records import ExportRecord
    failed = ExportRecord("idf", False, "/o/b.idf", ("zone z1 not enclosed",))
    assert failed.message("b") == "IDF export /o/b.idf failed its self-check: zone z1 not enclosed"
    unwritten = ExportRecord("idf", False, "", ("IDF not written: timeout: not finished within 5 s (--timeout)",))
    assert unwritten.message("b") == "IDF export b not written: timeout: not finished within 5 s (--timeout)"
    assert ExportRecord("stl", False).message("b") == "STL export b not written: no file"


def test_a_file_that_fails_its_self_check_makes_the_building_not_compliant(tmp_path, monkeypatch):
    """Issue 38 item 3: compliant means written and self-checked by every requested writer; the
    record, report.json and report.csv say which writer's check failed."""
    import csv
    from lod2energy.exporters.stl import writer as stl
    from lod2energy.options import ExportOptions, RunOptions
    from lod2energy.pipeline import export
    src = tmp_path / "two.city.json"
    src.write_text(json.dumps(_doc_of(a=_box_data(0.0), b=_box_data(30.0))), encoding="utf-8")
    real = stl.self_check
    monkeypatch.setattr(stl, "self_check", lambda p: ["degenerate facet 3"] if "b" in str(p).rsplit("/", 1)[-1]
                        else real(p))
    out = tmp_path / "o"
    opts = ExportOptions(("cityjson", "stl"), PrepareOptions(), html=False)
    res = export(str(src), str(out), opts, RunOptions(jobs=1))
    rows = {r["id"]: r for r in json.loads((out / "report.json").read_text())["buildings"]}
    assert rows["a"]["compliant"] is True and rows["a"]["exports"]["stl"]["ok"]
    assert rows["b"]["compliant"] is False and not rows["b"]["exports"]["stl"]["ok"]
    assert "STL" in rows["b"]["energy"]["reasons"][0] and "degenerate facet 3" in rows["b"]["message"]
    # every writer accepts exactly the buildings called compliant: the CityJSON does not accept b
    assert not rows["b"]["exports"]["cityjson"]["ok"]
    with open(out / "report.csv", newline="") as f:
        csv_rows = {r["id"]: r for r in csv.DictReader(f)}
    assert csv_rows["b"]["compliant"] == "False" and csv_rows["b"]["stl_ok"] == "False"
    assert "STL" in csv_rows["b"]["message"]
    assert res.exit_code == 1


def test_a_compliant_building_left_out_of_a_one_file_writer_is_not_compliant():
    """A one-file writer (the CityJSON) that leaves a compliant building out without a record:
    not written, so not compliant."""
    from lod2energy.dataset import DatasetResult, dataset_apply
    from lod2energy.run.record_store import RecordStore
    from lod2energy.records import BuildingRecord, ComplianceRecord
    ok = ComplianceRecord.from_block({"compliant": True, "geometry_ready": True, "reasons": []})
    store = RecordStore()
    store[0] = BuildingRecord(0, "a", "Building", energy=ok)
    store[1] = BuildingRecord(1, "b", "Building", energy=ok)
    store[2] = BuildingRecord(2, "c", "Building", energy=ok)
    from lod2energy.records import LEFT_OUT, ExportRecord
    left = ExportRecord("cityjson", False, "/o/x.city.json", (f"{LEFT_OUT}invalid on the output grid (102)",))
    res = DatasetResult("cityjson", (0, 1, 2), ((("a",), ExportRecord("cityjson", True, "/o/x.city.json")),
                                                (("c",), left)))
    dataset_apply(res, store, quiet=True)
    assert store[0].energy.compliant and store[0].export("cityjson").ok
    assert store[1].energy.compliant is False and not store[1].export("cityjson").ok
    assert "CITYJSON" in store[1].energy.reasons[0]
    assert store[2].energy.compliant is False and "(102)" in store[2].energy.reasons[0]
    assert "left out" in store[2].message


@pytest.mark.parametrize("jobs", [1, 2])
def test_an_idf_that_fails_its_self_check_is_not_compliant_in_every_output(tmp_path, monkeypatch, jobs):
    """The IDF is written in the neighbour pass, the CityJSON beside it (``-j 2``): a building
    whose IDF fails its self-check is not compliant in the record, report.csv and the CityJSON."""
    import csv
    from lod2energy.exporters.energyplus import writer as idf
    from lod2energy.options import ExportOptions, RunOptions
    from lod2energy.pipeline import export
    src = tmp_path / "two.city.json"
    src.write_text(json.dumps(_doc_of(a=_box_data(0.0), b=_box_data(30.0))), encoding="utf-8")
    real = idf.self_check
    monkeypatch.setattr(idf, "self_check", lambda p: ["surface s3 is degenerate"]
                        if str(p).endswith("/b.idf") else real(p))
    out = tmp_path / "o"
    res = export(str(src), str(out), ExportOptions(("idf", "cityjson"), PrepareOptions(), html=False),
                 RunOptions(jobs=jobs, quiet=True))
    rows = {r["id"]: r for r in json.loads((out / "report.json").read_text())["buildings"]}
    assert rows["a"]["compliant"] is True and rows["a"]["exports"]["idf"]["ok"]
    assert rows["b"]["compliant"] is False and not rows["b"]["exports"]["idf"]["ok"]
    assert "IDF" in rows["b"]["energy"]["reasons"][0] and "degenerate" in rows["b"]["message"]
    assert not rows["b"]["exports"]["cityjson"]["ok"]
    doc = json.loads((out / "two.energy.city.json").read_text())
    flags = {k: o["attributes"]["+energyCompliance"]["compliant"] for k, o in doc["CityObjects"].items()
             if not o.get("parents")}
    assert flags == {"a": True, "b": False}
    with open(out / "report.csv", newline="") as f:
        assert {r["id"]: r["compliant"] for r in csv.DictReader(f)} == {"a": "True", "b": "False"}
    assert res.exit_code == 1
