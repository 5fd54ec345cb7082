"""Downgrades of the energy model are fields of the building's record, columns of report.csv,
properties of the GeoJSON and counts in the console summary (lod2energy.energy.downgrades).

A building is forced into each simpler envelope by an enclosure test that rejects its zone as
written (the fallbacks then tried one kind at a time), into a whole zone by a storey section
that never closes.
"""
from __future__ import annotations

import csv
import json

import pytest

import cityjson_docs as docs
from export_helpers import energy_ready, shifted, two_part_building
from factories import box, gabled_house
from lod2energy.cli import main
from lod2energy.energy import downgrades as dg, fallback, model as energy_model
from lod2energy.energy.zones import cut as zoning
from lod2energy.exporters import energyplus
from lod2energy.records import BuildingRecord, ExportRecord

FORCED = {"lod1_block": fallback.block_zone, "2.5d": fallback.roof_zone, "cleared_zone": fallback.cleared_zone}


def _reject_written(monkeypatch, kind):
    """The zone as written fails the enclosure test once per zone; the fallbacks are ``kind``'s."""
    real = energy_model.enclosure_defects
    seen: set = set()

    def fake(pts):
        key = len(seen)
        if not seen or getattr(fake, "next_is_zone", False):
            seen.add(key)
            fake.next_is_zone = False
            return ["not fully enclosed (forced)"]
        return real(pts)

    real_enclosable = energy_model.enclosable

    def enclosable(zone, zi, pieces):
        fake.next_is_zone = True
        return real_enclosable(zone, zi, pieces)

    monkeypatch.setattr(energy_model, "enclosure_defects", fake)
    monkeypatch.setattr(energy_model, "enclosable", enclosable)
    monkeypatch.setattr(energy_model, "FALLBACKS", (FORCED[kind],))


def _downgrades(res, bid):
    return [dg.Downgrade.from_json(d) for d in res.stats.get("downgrades", {}).get(bid, [])]


def test_lod1_block_records_its_height_and_keeps_the_volume(tmp_path, monkeypatch):
    _reject_written(monkeypatch, "lod1_block")
    b = energy_ready(shifted(gabled_house(eaves=6.0, ridge=9.0)))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    assert res.ok, res.problems
    (d,) = _downgrades(res, b.id)
    assert d.kind == "lod1_block" and d.zone == b.id and "enclosure" in d.reason
    assert d.d_height_m == pytest.approx(7.5 - 9.0, abs=0.01)  # 600 m3 over 80 m2
    assert d.d_volume_m3 == pytest.approx(0.0, abs=0.5) and d.d_floor_area_m2 == pytest.approx(0.0, abs=0.1)


def test_2_5d_model_is_recorded(tmp_path, monkeypatch):
    _reject_written(monkeypatch, "2.5d")
    b = energy_ready(shifted(gabled_house(eaves=6.0, ridge=9.0)))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    assert [d.kind for d in _downgrades(res, b.id)] == ["2.5d"]


def test_party_walls_dropped_with_a_simpler_envelope(tmp_path, monkeypatch):
    _reject_written(monkeypatch, "lod1_block")
    b = energy_ready(shifted(two_part_building()))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    kinds = [(d.kind, d.zone) for d in _downgrades(res, b.id)]
    assert ("lod1_block", "two_parts-part0") in kinds and ("party_walls_dropped", "two_parts-part0") in kinds
    walls = next(d for d in _downgrades(res, b.id) if d.kind == "party_walls_dropped")
    assert walls.reason.startswith("36.0 m2")  # the shared rectangle


def test_whole_zone_instead_of_storeys(tmp_path, monkeypatch):
    monkeypatch.setattr(zoning, "split_storeys", lambda *a, **k: None)
    b = energy_ready(shifted(box(10, 8, 8.4)))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    (d,) = _downgrades(res, b.id)
    assert d.kind == "whole_zone" and d.d_volume_m3 == 0.0
    assert d.d_height_m == pytest.approx(8.4 - 2.8) and d.d_floor_area_m2 == pytest.approx(-160.0)
    # asked for: not a downgrade
    whole = energyplus.writer.write([b], tmp_path / "b", energyplus.options.IdfOptions(zoning="building"),
                                    crs="EPSG:28992")[0]
    assert not whole.stats.get("downgrades")


def test_no_downgrade_no_field(tmp_path):
    b = energy_ready(shifted(gabled_house()))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    assert res.ok and not res.stats.get("downgrades")


def test_record_takes_its_own_downgrades_from_a_shared_file():
    own = dg.Downgrade("lod1_block", "a", "r", -1.5, 0.0, 0.0)
    other = dg.Downgrade("whole_zone", "b", "r", 5.6, 0.0, -160.0)
    er = ExportRecord("idf", True, "dataset.idf", (), {"downgrades": {"a": [own.to_json()], "b": [other.to_json()]}})
    rec = BuildingRecord(0, "a", "Building").with_export(er)
    assert rec.downgrades == (own,) and rec.export("idf").extra["downgrades"] == {"a": [own.to_json()]}
    assert "downgrades" not in rec.export("idf").to_json()  # the record's own field in the report
    assert BuildingRecord(0, "a", "Building").with_export(ExportRecord.from_journal(
        json.loads(json.dumps(rec.export("idf").journal())))) == rec
    assert BuildingRecord.from_json(json.loads(json.dumps(rec.to_json()))) == rec
    row = rec.row()
    assert row["downgrades"] == "lod1_block:a" and row["downgrade_d_height_m"] == -1.5
    assert BuildingRecord(1, "c", "Building").row()["downgrades"] == ""


@pytest.mark.parametrize("kind", ["lod1_block", "2.5d", "whole_zone"])
def test_csv_geojson_and_console_show_the_downgrade(tmp_path, monkeypatch, capsys, kind):
    if kind == "whole_zone":
        monkeypatch.setattr(zoning, "split_storeys", lambda *a, **k: None)
    else:
        _reject_written(monkeypatch, kind)
    vertices = [[x, y, z * 8.4 / 6] for x, y, z in docs.BOX_VERTICES]  # three storeys
    src = docs.write(tmp_path, docs.box_doc(vertices=vertices))
    out = tmp_path / "out"
    with_html = kind == "whole_zone"  # report.html once: it takes a few seconds
    assert main(["export", src, "-o", str(out), "--idf", "--geojson", *([] if with_html else ["--no-html"]),
                 "-j", "1"]) == 0
    printed = capsys.readouterr().out
    assert f"energy model downgraded: {kind} 1 building(s)" in printed
    (row,) = list(csv.DictReader((out / "report.csv").open()))
    assert row["downgrades"] == f"{kind}:b1" and row["downgrade_d_height_m"] != ""
    (entry,) = json.loads((out / "report.json").read_text())["buildings"]
    assert [d["kind"] for d in entry["energy_downgrades"]] == [kind]
    (gj,) = out.glob("*.footprints.geojson")
    (feat,) = json.loads(gj.read_text())["features"]
    assert feat["properties"]["downgrades"] == f"{kind}:b1"
    assert feat["properties"]["downgrade_d_height_m"] == pytest.approx(float(row["downgrade_d_height_m"]))
    if with_html:
        assert 'data-key="energy_downgraded">1<' in (out / "report.html").read_text()


def _prism(xy, h, id="slit"):
    """A closed, outward prism of the counter-clockwise footprint ``xy`` (k, 2), ``h`` m high."""
    import numpy as np
    from factories import building_from_polygons
    xy = np.asarray(xy, float)
    n = len(xy)
    bot = np.column_stack([xy, np.zeros(n)])
    top = np.column_stack([xy, np.full(n, h)])
    polys, sem = [[bot[::-1]], [top]], ["GroundSurface", "RoofSurface"]
    for i in range(n):
        j = (i + 1) % n
        polys.append([np.array([bot[i], bot[j], top[j], top[i]])])
        sem.append("WallSurface")
    return building_from_polygons(polys, "Solid", sem, id=id)


def test_cleared_zone_is_recorded(tmp_path, monkeypatch):
    """A slit from the back wall to 7 mm from the front wall: its corners lie within
    EnergyPlus's 1.27 cm of the front wall's edges, and are moved clear of them."""
    _reject_written(monkeypatch, "cleared_zone")
    xy = [(0, 0), (10, 0), (10, 8), (5.01, 8), (5.01, 0.007), (4.99, 0.007), (4.99, 8), (0, 8)]
    b = energy_ready(shifted(_prism(xy, 3.0)))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(wwr=0.0), crs="EPSG:28992")[0]
    (d,) = _downgrades(res, b.id)
    assert d.kind == "cleared_zone" and d.d_height_m == 0.0
    assert abs(d.d_volume_m3) < 0.01  # points moved by millimetres
