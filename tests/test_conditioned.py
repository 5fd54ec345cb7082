"""Heated or not (issue 39 item 3): an unconditioned building has no HVAC in its IDF, still
makes party walls, and a wall a heated building shares with it is an outdoor wall without
windows, not adiabatic.

Tiny named geometries: a 10 x 8 x 6 m house with a 3 x 6 x 2.5 m garage against its east
wall (18 m2: an annex under :data:`~lod2energy.thermal.facts.ANNEX_FLOOR_AREA`), and a
Hamburg-like ALKIS parking garage code on a large box.
"""
from __future__ import annotations

import pytest

from export_helpers import eppy_idf, energy_ready, write_idf
from factories import box
from idf_figures import idf_figures

from lod2energy.model import frozen_mapping
from lod2energy.thermal.facts import ANNEX_FLOOR_AREA, conditioned_fact, is_conditioned


def _with_attribute(b, key, value):
    root = b.objects[0]
    objs = (root.__class__(**{**vars(root), "attributes": frozen_mapping({**root.attributes, key: value})}),)
    return b.__class__(**{**vars(b), "objects": objs + tuple(b.objects[1:])})


def _house_and_garage():
    house = energy_ready(box(10, 8, 6, id="house"))
    garage = energy_ready(box(3, 6, 2.5, origin=(10.0, 1.0, 0.0), id="garage"))
    return house, garage


def test_an_annex_under_the_threshold_is_unconditioned_by_its_geometry():
    house, garage = _house_and_garage()
    assert is_conditioned(house) and not is_conditioned(garage)
    fact = garage.provenance["thermal"]["facts"]["conditioned"]
    assert fact["source"] == "geometry" and fact["raw"] < ANNEX_FLOOR_AREA
    # the table wins over the threshold
    b = box(3, 6, 2.5, id="g")
    assert conditioned_fact(b, floor_area=18.0).value is False
    assert conditioned_fact(b, floor_area=25.0).value is True


def test_alkis_parking_garage_and_osm_shed_are_unconditioned():
    for key, value in (("function", "31001_2461"), ("function", "31001_2723"), ("building", "shed"),
                       ("usage", "452")):
        b = energy_ready(_with_attribute(box(30, 20, 9, id="big"), key, value))
        assert not is_conditioned(b), (key, value)
        assert b.provenance["thermal"]["facts"]["conditioned"]["source"] == "attribute"
    assert is_conditioned(energy_ready(_with_attribute(box(30, 20, 9), "function", "31001_1010")))


def test_unconditioned_garage_idf_has_no_ideal_loads(tmp_path):
    house, garage = _house_and_garage()
    res = write_idf([garage], tmp_path, context=[house])
    assert res[0].ok, res[0].problems
    idf = eppy_idf(res[0].path)
    assert not idf.idfobjects["ZONEHVAC:IDEALLOADSAIRSYSTEM"] and not idf.idfobjects["ZONECONTROL:THERMOSTAT"]
    assert all(str(z.Part_of_Total_Floor_Area).lower() == "no" for z in idf.idfobjects["ZONE"])
    # its own wall against the heated house is not adiabatic either
    assert res[0].stats["envelope"]["garage"]["areas"]["adiabatic"] == 0.0


def test_a_wall_shared_with_an_unconditioned_garage_is_outdoor_without_windows(tmp_path):
    house, garage = _house_and_garage()
    res = write_idf([house], tmp_path, context=[garage])
    assert res[0].ok, res[0].problems
    fig = res[0].stats["envelope"]["house"]
    assert fig["areas"]["adiabatic"] == 0.0
    assert fig["areas"]["wall"] == pytest.approx(2 * (10 * 6 + 8 * 6), rel=1e-3)  # every wall outdoors
    assert any("unconditioned" in w for w in res[0].warnings)
    idf = eppy_idf(res[0].path)
    assert idf.idfobjects["ZONEHVAC:IDEALLOADSAIRSYSTEM"]
    bases = {w.Building_Surface_Name for w in idf.idfobjects["FENESTRATIONSURFACE:DETAILED"]}
    # the east wall (x = 10 in the file frame, the largest x) carries no window
    xs = {s.Name: [float(c[0]) for c in s.coords] for s in idf.idfobjects["BUILDINGSURFACE:DETAILED"]
          if s.Surface_Type.lower() == "wall"}
    xmax = max(max(v) for v in xs.values())
    east = [n for n, v in xs.items() if min(v) > xmax - 1e-6]
    assert east and not set(east) & bases
    assert bases  # the other walls keep theirs
    recomputed = idf_figures(res[0].path)
    assert abs(recomputed["UA"] - fig["UA"]) <= 0.005 * fig["UA"]


def test_between_two_conditioned_buildings_the_wall_stays_adiabatic(tmp_path):
    house = energy_ready(box(10, 8, 6, id="house"))
    other = energy_ready(box(10, 8, 6, origin=(10.0, 0.0, 0.0), id="other"))
    res = write_idf([house], tmp_path, context=[other])
    assert res[0].stats["envelope"]["house"]["areas"]["adiabatic"] == pytest.approx(48.0, rel=1e-3)


def test_nrw_tile_alkis_unheated_buildings_have_no_ideal_loads(tmp_path):
    """A German state LoD2 tile: its barns, sheds, stables and garages (ALKIS codes) and its
    annexes under the threshold are unconditioned, and their IDFs have no ideal loads; the
    heated buildings' do."""
    import json

    from conftest import shared_path
    from lod2energy.cli import main

    src = shared_path("citygml-real", "nrw", "LoD2_32_280_5657_1_NW.gml")
    out = tmp_path / "out"
    assert main(["export", str(src), "-o", str(out), "--idf", "-q", "-j", "1", "--no-html"]) in (0, 1)
    rep = json.loads((out / "report.json").read_text())
    by_source: dict[str, int] = {}
    for b in rep["buildings"]:
        fact = ((b.get("thermal") or {}).get("facts") or {}).get("conditioned")
        e = b["exports"].get("idf") or {}
        if not fact or not e.get("ok"):
            continue
        text = open(e["path"]).read()
        if fact["value"] is False:
            by_source[fact["source"]] = by_source.get(fact["source"], 0) + 1
            assert "ZoneHVAC:IdealLoadsAirSystem" not in text, b["id"]
            assert b.get("heating_kwh_m2") in (None, "")
        else:
            assert "ZoneHVAC:IdealLoadsAirSystem" in text, b["id"]
    assert by_source.get("attribute", 0) >= 10 and by_source.get("geometry", 0) >= 1
