"""Run figures per building and per zone in the records (registry) and report.json/csv (records)."""
from lod2energy.exporters.result import ExportResult
from lod2energy.exporters.registry import records_of as _records
from lod2energy.records import CSV_FIELDS, RESULT_FIGURES, BuildingRecord


def _zone(h, c, a):
    return {"heating_kwh": h, "cooling_kwh": c, "heating_kwh_m2": h / a, "cooling_kwh_m2": c / a,
            "heating_peak_w": 100.0 * h, "cooling_peak_w": 50.0 * c, "floor_area_m2": a}


def _result(ids):
    zones = {"a_S1": _zone(100.0, 10.0, 50.0), "a_S2": _zone(80.0, 12.0, 50.0), "b_S1": _zone(300.0, 0.0, 60.0)}
    stats = {"zone_results": zones, "zone_building": {"a_S1": "a", "a_S2": "a", "b_S1": "b"},
             "building_results": {"a": _zone(180.0, 22.0, 100.0), "b": _zone(300.0, 0.0, 60.0)}}
    if len(ids) == 1:
        stats = {k: ({z: v for z, v in d.items() if z.startswith(ids[0])} if k != "zone_building" else d)
                 for k, d in stats.items()}
    return ExportResult(tuple(ids), "x.idf", True, stats=stats, heating_kwh=480.0, cooling_kwh=22.0)


def test_dataset_file_gives_each_building_its_own_figures_and_zones():
    pairs = _records("idf", [_result(["a", "b"])])
    got = {ids[0]: er for ids, er in pairs}
    assert set(got) == {"a", "b"}
    a, b = got["a"].values(), got["b"].values()
    assert a["heating_kwh"] == 180.0 and b["heating_kwh"] == 300.0  # not the file's 480
    assert a["heating_kwh_m2"] == 1.8 and a["conditioned_floor_area_m2"] == 100.0
    assert [z["zone"] for z in a["zones"]] == ["a_S1", "a_S2"] and len(b["zones"]) == 1
    # stored once: the flat figures and the zone list are derived from the results
    assert not set(RESULT_FIGURES) & set(got["a"].extra)
    assert got["a"].extra["results"]["building"]["heating_kwh_m2"] == a["heating_kwh_m2"]


def test_report_json_has_zones_and_csv_the_building_columns():
    ((ids, er),) = _records("idf", [_result(["a"])])
    rec = BuildingRecord(0, "a", "Building").with_export(er)
    entry = rec.report_entry()
    assert [z["zone"] for z in entry["zones"]] == ["a_S1", "a_S2"]
    assert "zones" not in entry["exports"]["idf"]
    row = rec.row()
    for k in ("heating_kwh_m2", "cooling_kwh_m2", "heating_peak_w", "cooling_peak_w", "conditioned_floor_area_m2"):
        assert k in CSV_FIELDS and row[k] == er.values()[k] == er.extra["results"]["building"][
            "floor_area_m2" if k == "conditioned_floor_area_m2" else k]
    assert row["heating_kwh"] == 480.0  # a one-building file keeps the run's own total
    assert "zones" not in CSV_FIELDS
    back = BuildingRecord.from_json(rec.to_json())  # the journal keeps the zones
    assert back.report_entry()["zones"] == entry["zones"]
    assert back.to_json() == rec.to_json() and list(back.report_entry()) == list(entry)
    assert not set(RESULT_FIGURES) & set(back.export("idf").extra)  # once again after the round trip


import json  # noqa: E402
import csv  # noqa: E402

import pytest  # noqa: E402


@pytest.mark.external
def test_cli_run_puts_zone_figures_in_report_and_geojson(tmp_path):
    from export_helpers import EPW, REPO
    from lod2energy.exporters import energyplus
    from lod2energy.cli import main
    if energyplus.run.binary() is None:
        pytest.skip("EnergyPlus not installed")
    lines = (REPO / "examples" / "delft_subset.city.jsonl").read_text().splitlines()
    one = [ln for ln in lines[1:] if "0503100000005156" in ln][:1]  # b3_bouwlagen 3: three storey zones
    src = tmp_path / "one.city.jsonl"
    src.write_text("\n".join([lines[0]] + one) + "\n")
    out = tmp_path / "out"
    rc = main(["export", str(src), "-o", str(out), "--idf", "--run", "--weather", str(EPW), "--geojson",
               "--no-html", "-q", "-j", "1"])
    assert rc in (0, 1)
    b = json.loads((out / "report.json").read_text())["buildings"][0]
    assert len(b["zones"]) >= 2
    assert sum(z["heating_kwh"] for z in b["zones"]) == pytest.approx(b["exports"]["idf"]["heating_kwh"], rel=1e-3)
    assert b["heating_kwh_m2"] > 0 and b["heating_peak_w"] > 0 and b["conditioned_floor_area_m2"] > 0
    row = next(csv.DictReader((out / "report.csv").open()))
    assert float(row["heating_kwh_m2"]) == pytest.approx(b["heating_kwh_m2"])
    props = json.loads(next(out.glob("*.footprints.geojson")).read_text())["features"][0]["properties"]
    assert props["heating_kwh_m2"] == pytest.approx(b["heating_kwh_m2"], abs=0.05) and props["heating_peak_w"] > 0
    w = b["exports"]["idf"]["weather"]
    assert (props["weather_file"], props["weather_station"]) == (w["file"], w["station"])
    assert props["weather_distance_km"] == pytest.approx(w["distance_km"], abs=0.05)
    assert props["heating_kwh"] == round(props["heating_kwh"]) and isinstance(props["heating_kwh"], float)
