"""Storey zones (lod2energy.energy.zones.cut and the IDF writer's zoning="storey")."""
import numpy as np
import pytest

from export_helpers import EPW, energy_ready, eppy_idf, parts_building, real_buildings, shifted, write_idf
from factories import box, box_polygons, gabled_house, stepped_tower
from lod2energy import energy
import lod2energy.energy.zones.storeys  # noqa: F401 - energy.zones.storeys
import lod2energy.energy.surfaces  # noqa: F401 - energy.surfaces
import lod2energy.energy.pieces  # noqa: F401 - energy.pieces
from lod2energy.energy.zones import cut as zoning
from lod2energy.exporters import energyplus
from lod2energy.validate.closed import check_closed_outward
from lod2energy.energy.zones.shells import local_origin, zone_shells
from lod2energy.energy.enclosure import enclosure_defects


def _pieces(b):
    b = energy_ready(b)
    z = zone_shells(b, local_origin([b]))[0]
    return z, energy.surfaces.zone_pieces(z, 0, {}, False)


def _idf(path):
    return eppy_idf(path)


def test_gabled_house_cut_into_two_storeys_and_an_attic():
    z, pcs = _pieces(gabled_house(eaves=5.6, ridge=9.0))
    out, note = energy.zones.storeys.storey_zones(z, 0, pcs, 2.8, "unconditioned")
    assert note is None and [a for _, _, a in out] == [False, False, True]
    vols = [energy.pieces._pieces_volume(zp) for _, zp, _ in out]
    assert vols == pytest.approx([224.0, 224.0, 136.0], rel=1e-6)
    for _, zp, _ in out:
        pts = [p.points for p in zp]
        assert not check_closed_outward(pts) and not enclosure_defects(pts)
    # ceilings of one storey are the floors of the next, reversed
    ceil = [p.points for p in out[0][1] if p.kind == "ceiling"]
    floor = [p.points for p in out[1][1] if p.kind == "floor"]
    assert len(ceil) == len(floor) and all(np.allclose(c[::-1], f) for c, f in zip(ceil, floor))


def test_low_roof_space_stays_in_the_top_storey():
    z, pcs = _pieces(gabled_house(eaves=5.6, ridge=6.6))
    out, _ = energy.zones.storeys.storey_zones(z, 0, pcs, 2.8, "unconditioned")
    assert len(out) == 2 and not any(a for _, _, a in out)


def test_no_cut_next_to_a_vertex_or_through_a_flat_roof():
    z = np.array([0.0, 0.0, 3.0, 3.03, 6.0])
    cuts, _ = zoning.storey_cuts(z, 0.0, 6.0, 6.0, 2, False)
    assert len(cuts) == 1 and np.all(np.abs(z - cuts[0]) >= zoning.CLEARANCE)  # no 3 cm sliver
    cuts, _ = zoning.storey_cuts(np.array([0.0, 2.98, 6.0]), 0.0, 6.0, 6.0, 2, False)
    assert cuts == [2.98]  # snapped onto the vertex line
    cuts, _ = zoning.storey_cuts(np.array([0.0, 3.0, 6.0]), 0.0, 6.0, 6.0, 2, False, horizontal_z=[3.0])
    assert all(abs(c - 3.0) >= zoning.CLEARANCE for c in cuts)


@pytest.mark.parametrize("make", [lambda: box(10, 8, 8.4), lambda: gabled_house(eaves=5.6, ridge=9.0)])
def test_storey_idf_passes_self_check_with_interzone_pairs(tmp_path, make):
    b = energy_ready(shifted(make()))
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")
    assert res[0].ok, res[0].problems
    I = _idf(res[0].path)
    zones = [z.Name for z in I.idfobjects["ZONE"]]
    assert len(zones) == 3
    surfs = {s.Name: s for s in I.idfobjects["BUILDINGSURFACE:DETAILED"]}
    inter = [s for s in surfs.values() if s.Outside_Boundary_Condition == "Surface"]
    assert inter and len(inter) % 2 == 0
    for s in inter:
        other = surfs[s.Outside_Boundary_Condition_Object]
        assert other.Outside_Boundary_Condition_Object == s.Name and other.Zone_Name != s.Zone_Name
        assert {s.Surface_Type, other.Surface_Type} == {"Floor", "Ceiling"}
    vol = sum(float(z.Volume) for z in I.idfobjects["ZONE"])
    assert vol == pytest.approx(energy.pieces._pieces_volume(_pieces(make())[1]), rel=0.005)
    # loads by use, setpoint schedules, the real site
    assert len(I.idfobjects["PEOPLE"]) == len(I.idfobjects["LIGHTS"]) == res[0].stats["storeys"] - res[0].stats["attic"]
    assert I.idfobjects["SCHEDULE:COMPACT"]
    loc = I.idfobjects["SITE:LOCATION"][0]
    assert 50 < float(loc.Latitude) < 54 and 3 < float(loc.Longitude) < 8


def test_party_walls_stay_adiabatic_per_storey(tmp_path):
    b = energy_ready(parts_building([box_polygons(5, 8, 6), box_polygons(5, 8, 6, origin=(5, 0, 0))]))
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(wwr=0.0))
    assert res[0].ok, res[0].problems
    I = _idf(res[0].path)
    assert len(I.idfobjects["ZONE"]) == 4
    adiabatic = [s for s in I.idfobjects["BUILDINGSURFACE:DETAILED"] if s.Outside_Boundary_Condition == "Adiabatic"]
    assert len({s.Zone_Name for s in adiabatic}) == 4  # every storey of each part keeps its party wall


def test_building_zoning_keeps_one_zone(tmp_path):
    res = write_idf([energy_ready(gabled_house())], tmp_path, energyplus.options.IdfOptions(zoning="building"))
    assert res[0].ok and res[0].stats["zones"] == 1 and res[0].stats["interzone_surfaces"] == 0


def test_bad_options_are_parameter_errors(tmp_path):
    from lod2energy.errors import ParameterError
    for kw in ({"zoning": "room"}, {"attic": "maybe"}, {"use": "spaceport"}):
        with pytest.raises(ParameterError):
            write_idf([energy_ready(box())], tmp_path, energyplus.options.IdfOptions(**kw))


def test_real_buildings_storey_zones_enclosed_and_volumes_add_up(tmp_path):
    bs = [energy_ready(b) for b in real_buildings("3dbag/delft_subset.city.jsonl")]
    split = 0
    for b in bs:
        whole = write_idf([b], tmp_path / "w", energyplus.options.IdfOptions(zoning="building", wwr=0.0))[0]
        res = write_idf([b], tmp_path / "s", energyplus.options.IdfOptions(wwr=0.0))[0]
        assert res.ok, res.problems
        v_whole = sum(whole.stats["zone_volume_m3"].values())
        v = sum(res.stats["zone_volume_m3"].values())
        assert v == pytest.approx(v_whole, rel=0.005)
        split += res.stats["zones"] > whole.stats["zones"]
    assert split >= len(bs) // 2


@pytest.mark.external
def test_energyplus_reads_heating_per_storey_zone(tmp_path):
    if energyplus.run.binary() is None:
        pytest.skip("EnergyPlus not installed")
    b = energy_ready(shifted(gabled_house(eaves=5.6, ridge=9.0), (212000.0, 490000.0, 0.0)))  # near Heino
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(run=True, weather=str(EPW)), crs="EPSG:28992")[0]
    assert res.ok, res.problems
    zr = res.stats["zone_results"]
    assert set(zr) == {"house_S1", "house_S2"}  # the unconditioned attic has no HVAC
    for z in zr.values():
        assert z["heating_kwh"] > 0 and z["heating_kwh_m2"] > 0 and z["heating_peak_w"] > 0
    bld = res.stats["building_results"]["house"]
    assert bld["heating_kwh"] == pytest.approx(sum(z["heating_kwh"] for z in zr.values()), rel=1e-6)
    assert bld["heating_kwh"] == pytest.approx(res.heating_kwh, rel=1e-6)
    assert res.stats["conditioned_floor_area_m2"] == pytest.approx(160.0)
    assert 20 < res.stats["heating_kwh_m2"] < 400
    assert res.stats["weather_distance_km"] < 50 and not any("km from the site" in w for w in res.warnings)


def test_section_area_is_the_floor_of_a_storey_at_that_height():
    pts = [p.points for p in _pieces(gabled_house(eaves=6.0, ridge=9.0))[1]]
    ground = min(float(p[:, 2].min()) for p in pts)
    assert zoning.section_area(pts, ground) == pytest.approx(80.0, rel=1e-6)  # the ground face is below the plane
    assert zoning.section_area(pts, ground + 3.0) == pytest.approx(80.0, rel=1e-6)
    assert zoning.section_area(pts, ground + 7.5) == pytest.approx(40.0, rel=1e-3)  # half way up the roof
    assert zoning.section_area(pts, ground + 9.0) == 0.0  # the ridge: nothing above
    top = [p.points for p in _pieces(box(10, 8, 6))[1]]
    assert zoning.section_area(top, max(float(p[:, 2].max()) for p in top)) == 0.0  # a flat roof on the plane


def _zone_floor_areas(path):
    return {z.Name: float(z.Floor_Area) for z in _idf(path).idfobjects["ZONE"]}


@pytest.mark.parametrize("make, storeys", [(lambda: box(10, 8, 8.4), 3), (lambda: box(10, 8, 2.8), 1),
                                           (lambda: gabled_house(eaves=5.6, ridge=9.0), 2)])
def test_whole_zone_floor_area_is_the_storeys_gross_floor_area(tmp_path, make, storeys):
    """A zone kept whole gets the floor area of all its storeys (80 m2 footprint each), as its
    storey zones would have: per-m2 loads and kWh/m2a do not change with the zoning."""
    b = energy_ready(shifted(make()))
    whole = write_idf([b], tmp_path / "w", energyplus.options.IdfOptions(zoning="building"),
                                    crs="EPSG:28992")[0]
    split = write_idf([b], tmp_path / "s", energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    assert whole.ok and split.ok
    (area,) = _zone_floor_areas(whole.path).values()
    assert area == pytest.approx(80.0 * storeys, rel=1e-6)
    assert whole.stats["zone_floor_area_m2"] == {whole.stats["conditioned_zones"][0]: area}
    conditioned = sum(a for z, a in _zone_floor_areas(split.path).items()
                      if z.upper() in {c.upper() for c in split.stats["conditioned_zones"]})
    assert conditioned == pytest.approx(area, rel=0.005)
    if storeys > 1:  # the storey zones themselves keep their floor surfaces' area
        assert list(_zone_floor_areas(split.path).values()) == [pytest.approx(80.0)] * len(split.stats["zone_floor_area_m2"])


def test_whole_zone_counts_the_attic_floor_only_when_the_attic_is_conditioned(tmp_path):
    b = energy_ready(shifted(gabled_house(eaves=5.6, ridge=9.0)))
    got = {}
    for attic in ("unconditioned", "conditioned"):
        res = write_idf([b], tmp_path / attic, energyplus.options.IdfOptions(zoning="building", attic=attic),
                                      crs="EPSG:28992")[0]
        (got[attic],) = _zone_floor_areas(res.path).values()
    # the attic floor is the section just above the eave: 80 m2 less a sliver of the roof pitch
    assert got["unconditioned"] == pytest.approx(160.0) and got["conditioned"] == pytest.approx(240.0, rel=1e-3)


def test_storey_zoning_that_stays_whole_gets_the_storeys_area(tmp_path, monkeypatch):
    """The fallback of storey zoning (a cut that would not close) is a whole zone too."""
    b = energy_ready(shifted(box(10, 8, 8.4)))
    monkeypatch.setattr(zoning, "split_storeys", lambda *a, **k: None)
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    assert res.ok and res.stats["zones"] == 1
    assert list(_zone_floor_areas(res.path).values()) == [pytest.approx(240.0)]
    assert any("kept as one zone" in w for w in res.warnings)


@pytest.mark.external
def test_energyplus_uses_the_whole_zone_gross_floor_area(tmp_path):
    """EnergyPlus takes the written Floor Area (its people and the reported kWh/m2a follow it)."""
    import sqlite3
    if energyplus.run.binary() is None:
        pytest.skip("EnergyPlus not installed")
    b = energy_ready(shifted(box(10, 8, 8.4), (212000.0, 490000.0, 0.0)))  # near Heino
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(zoning="building", run=True,
                                                                               weather=str(EPW)), crs="EPSG:28992")[0]
    assert res.ok, res.problems
    assert res.stats["conditioned_floor_area_m2"] == pytest.approx(240.0)
    assert res.stats["heating_kwh_m2"] == pytest.approx(res.heating_kwh / 240.0, abs=0.01)
    sql = next(tmp_path.rglob("eplusout.sql"))
    with sqlite3.connect(sql) as con:
        (floor,), = con.execute("SELECT FloorArea FROM Zones").fetchall()
        people = con.execute("SELECT SUM(NumberOfPeople) FROM NominalPeople").fetchone()[0]
    assert floor == pytest.approx(240.0)
    from lod2energy.thermal.use import use_conditions
    assert people == pytest.approx(use_conditions("residential").people_per_m2 * 240.0, rel=1e-3)


def _zone_heights(path) -> dict[str, float]:
    """Height (m) of each zone of an IDF: the z-range of its surfaces' vertices."""
    lo: dict[str, float] = {}
    hi: dict[str, float] = {}
    for s in _idf(path).idfobjects["BUILDINGSURFACE:DETAILED"]:
        z = [float(s[f"Vertex_{i}_Zcoordinate"]) for i in range(1, int(s.Number_of_Vertices) + 1)]
        lo[s.Zone_Name] = min(lo.get(s.Zone_Name, np.inf), *z)
        hi[s.Zone_Name] = max(hi.get(s.Zone_Name, -np.inf), *z)
    return {k: hi[k] - lo[k] for k in lo}


#: Storeys of 3 m: a podium of 10, a shaft of 15 and a top of 15 storeys (two set-backs).
TOWER = dict(sizes=(40.0, 28.0, 16.0), tops=(30.0, 75.0, 120.0))
TOWER_VOLUME = 40.0 ** 2 * 30 + 28.0 ** 2 * 45 + 16.0 ** 2 * 45


@pytest.mark.parametrize("attrs", [{}, {"storeysAboveGround": 40}])
def test_set_back_tower_is_zoned_to_the_top(tmp_path, attrs):
    """A 40-storey tower on a podium: its eave (the median roof level by area) is the podium's
    roof, yet every storey up to the top is a zone of at most two storeys."""
    from dataclasses import replace
    t = stepped_tower(**TOWER)
    t = replace(t, objects=(replace(t.root, attributes={**t.root.attributes, **attrs}),) + t.objects[1:])
    b = energy_ready(shifted(t))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    assert res.ok, res.problems
    h = res.stats["storey_height_m"]
    heights = _zone_heights(res.path)
    assert len(heights) == res.stats["zones"] >= 38
    assert max(heights.values()) <= 2 * h + 1e-6
    assert sum(res.stats["zone_volume_m3"].values()) == pytest.approx(TOWER_VOLUME, rel=1e-5)
    assert not any("kept as one zone" in w for w in res.warnings)
    z, pcs = _pieces(stepped_tower(**TOWER))
    out, note = energy.zones.storeys.storey_zones(z, 0, pcs, h, "unconditioned")
    assert note is None and len(out) == len(heights)
    vols = [energy.pieces._pieces_volume(zp) for _, zp, _ in out]
    assert sum(vols) == pytest.approx(TOWER_VOLUME, rel=1e-9)


def test_tall_part_beside_a_low_wide_part_gets_its_storeys(tmp_path):
    """The building's eave is the wide part's roof: the tall part is still zoned per storey."""
    b = energy_ready(shifted(parts_building([box_polygons(60, 60, 9), box_polygons(20, 20, 65, (60, 0, 0))])))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(wwr=0.0), crs="EPSG:28992")[0]
    assert res.ok, res.problems
    heights = _zone_heights(res.path)
    assert max(heights.values()) <= 2 * res.stats["storey_height_m"] + 1e-6
    assert sum(res.stats["zone_volume_m3"].values()) == pytest.approx(60 * 60 * 9 + 20 * 20 * 65, rel=1e-5)


def test_whole_tower_zone_counts_the_storeys_above_the_podium(tmp_path):
    """Kept whole, the tower's floor area is that of every storey its storey zones would have."""
    b = energy_ready(shifted(stepped_tower(**TOWER)))
    whole = energyplus.writer.write([b], tmp_path / "w", energyplus.options.IdfOptions(zoning="building"),
                                    crs="EPSG:28992")[0]
    split = energyplus.writer.write([b], tmp_path / "s", energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    (area,) = _zone_floor_areas(whole.path).values()
    # a storey cut that would run through a set-back's roof is moved 0.2 m below it, so that
    # storey's floor is the larger section: a few % more for the storey zones
    assert area == pytest.approx(sum(_zone_floor_areas(split.path).values()), rel=0.05)
    assert area > 40.0 ** 2 * 10 + 28.0 ** 2 * 15
