"""CFD case geometry: guideline domain sizing, wind rotation, blockage, region selection, options."""
from __future__ import annotations

import argparse
import math

import numpy as np
import pytest

from factories import box, gabled_house

from lod2energy.exporters.cfd import CfdOptions, add_cli_arguments, options_from_args
from lod2energy.exporters.cfd.case import build_case, plan_mesh
from lod2energy.exporters.cfd.domain import (DOWNSTREAM_H, HEIGHT_H, LATERAL_H, MAX_BLOCKAGE, UPSTREAM_H, flow_direction,
                                   frontal_area, size_domain, to_wind_frame)
from lod2energy.exporters.cfd.region import make_region, select
from lod2energy.exporters.cfd.surfaces import SOLIDS
from lod2energy.errors import ParameterError


def _translated(b, dx, dy, dz=0.0, id=None):
    from dataclasses import replace
    return replace(b, vertices=b.vertices + np.array([dx, dy, dz]), id=id or b.id)


# --------------------------------------------------------------------------- wind frame

@pytest.mark.parametrize("deg, expected", [(0, (0, -1)), (90, (-1, 0)), (180, (0, 1)), (270, (1, 0)),
                                           (225, (math.sqrt(0.5), math.sqrt(0.5)))])
def test_flow_direction_is_meteorological(deg, expected):
    """Wind FROM the north blows south; from the west (270) blows east."""
    assert np.allclose(flow_direction(deg), expected, atol=1e-12)


def test_wind_frame_x_runs_downwind():
    pts = np.array([[0.0, 10.0], [0.0, -10.0]])  # north and south of the centre
    uv = to_wind_frame(pts, np.zeros(2), 0.0)  # wind from the north: south is downwind
    assert uv[1, 0] > uv[0, 0]
    assert np.allclose(uv[:, 1], 0.0, atol=1e-12)


# --------------------------------------------------------------------------- sizing

def test_domain_extents_follow_the_guidelines_for_the_tallest_building():
    """Upstream/lateral 5 H, downstream 15 H, height 6 H, H = tallest building above the ground."""
    low = box(10, 8, 6, id="low")
    tall = box(6, 6, 21, origin=(30, 0, 0), id="tall")
    case = build_case([low, tall], make_region(), 270.0, cell_size=2.0, min_gap=0.0)
    d = case.domain
    H = 21.0
    assert d.h_max == pytest.approx(H, abs=1e-3)
    bx0, bx1, by0, by1 = d.built_extent
    assert bx1 - bx0 == pytest.approx(36.0, abs=0.01)  # wind from the west: x is east
    assert by1 - by0 == pytest.approx(8.0, abs=0.01)
    assert bx0 - d.x_min == pytest.approx(UPSTREAM_H * H, abs=0.01)
    assert d.x_max - bx1 == pytest.approx(DOWNSTREAM_H * H, abs=0.01)
    assert by0 - d.y_min == pytest.approx(LATERAL_H * H, abs=0.01)
    assert d.y_max - by1 == pytest.approx(LATERAL_H * H, abs=0.01)
    assert d.z_max - d.z_min == pytest.approx(HEIGHT_H * H, abs=0.01)
    assert d.blockage_ratio < MAX_BLOCKAGE and d.enlarged == 1.0
    # the sidecar reports the same figures
    dd = d.as_dict()
    assert dd["upstream_m"] == pytest.approx(5 * H, abs=0.01) and dd["downstream_m"] == pytest.approx(15 * H, abs=0.01)


def test_domain_turns_with_the_wind():
    """A long row across the wind gives a wide domain; along the wind a long one."""
    row = [box(10, 10, 10, origin=(20 * i, 0, 0), id=f"b{i}") for i in range(5)]  # a row along x (east)
    from_west = build_case(row, make_region(), 270.0, 2.0, 0.0).domain
    from_north = build_case(row, make_region(), 0.0, 2.0, 0.0).domain
    assert from_west.built_extent[1] - from_west.built_extent[0] == pytest.approx(90, abs=0.01)
    assert from_north.built_extent[3] - from_north.built_extent[2] == pytest.approx(90, abs=0.01)
    # inlet side: with wind from the north the inlet corners are north of the buildings
    c = from_north.corners()
    inlet = c[[0, 3, 4, 7]]
    assert inlet[:, 1].min() == pytest.approx(10 + 5 * 10 + from_north.centre[1] - 5, abs=0.01)
    assert from_north.flow_dir[1] == pytest.approx(-1.0)
    # corners stay a rectangle of the guideline size
    lx, ly, lz = from_north.size
    assert np.linalg.norm(c[1] - c[0]) == pytest.approx(lx) and np.linalg.norm(c[3] - c[0]) == pytest.approx(ly)


def test_oblique_wind_rotates_the_box():
    d = build_case([box(10, 10, 10)], make_region(), 225.0, 2.0, 0.0).domain  # from the south-west
    c = d.corners()
    along = (c[1] - c[0])[:2] / np.linalg.norm((c[1] - c[0])[:2])
    assert np.allclose(along, [math.sqrt(0.5), math.sqrt(0.5)], atol=1e-9)


def test_blockage_ratio_enlarges_the_domain():
    """A frontal area that would block more than 3% widens and heightens the box until it does not."""
    xy = np.array([[0.0, 0.0], [10.0, 2.0]])
    plain = size_domain(xy, 10.0, 0.0, 270.0, frontal_area=10.0)
    assert plain.enlarged == 1.0
    wide = size_domain(xy, 10.0, 0.0, 270.0, frontal_area=0.2 * plain.size[1] * plain.size[2])
    assert wide.enlarged > 1.0
    assert wide.blockage_ratio <= MAX_BLOCKAGE + 1e-9
    assert wide.size[1] > plain.size[1] and wide.size[2] > plain.size[2]
    assert wide.x_min == plain.x_min and wide.x_max == plain.x_max  # up/downstream unchanged


def test_frontal_area_of_a_box_depends_on_the_wind():
    b = box(10, 4, 6)
    from lod2energy.exporters.cfd.surfaces import building_body
    (v, t, _), = building_body(b, np.zeros(3)).meshes
    assert frontal_area(v, t, 270.0, 0.0) == pytest.approx(4 * 6, rel=1e-6)   # wind along x sees the 4 m side
    assert frontal_area(v, t, 0.0, 0.0) == pytest.approx(10 * 6, rel=1e-6)    # along y sees the 10 m side
    assert frontal_area(v, t, 270.0, 2.0) == pytest.approx(4 * 4, rel=1e-6)   # above the ground only


def test_mesh_plan_levels_follow_cell_size_and_small_features():
    d = size_domain(np.array([[0.0, 0.0], [20.0, 20.0]]), 16.0, 0.0, 270.0, 50.0)
    p = plan_mesh(d, 2.0, smallest=20.0)
    assert p.surface_cell == pytest.approx(2.0) and p.surface_level == 3 and p.feature_level == 3
    assert p.background_cell == pytest.approx(16.0)
    small = plan_mesh(d, 2.0, smallest=2.5)
    assert small.feature_level == 4  # two cells across 2.5 m need 1 m cells... within two levels
    with pytest.raises(ParameterError):
        plan_mesh(d, 0.0, 5.0)


# --------------------------------------------------------------------------- region

def test_region_keeps_cut_buildings_whole_and_leaves_out_the_rest():
    inside = box(10, 10, 6, origin=(0, 0, 0), id="inside")
    cut = box(10, 10, 6, origin=(45, 0, 0), id="cut")          # crosses x = 50
    outside = box(10, 10, 6, origin=(80, 0, 0), id="outside")
    r = make_region(region=(-5, -5, 50, 20))
    got, left = select([inside, cut, outside], r)
    assert [b.id for b in got] == ["inside", "cut"] and left == ["outside"]
    case = build_case([inside, cut, outside], r, 270.0, 2.0, 0.0)
    assert case.included == ("inside", "cut") and case.excluded == ("outside",)
    # the cut building is whole: the built extent reaches its far side (x = 55), past the region
    off = np.asarray(case.offset)
    assert case.domain.built_extent[1] + case.domain.centre[0] + off[0] == pytest.approx(55.0, abs=0.01)
    assert case.united.volume_above_ground == pytest.approx(2 * 600.0, rel=1e-6)


def test_circle_region():
    a = box(10, 10, 6, origin=(0, 0, 0), id="a")
    b = box(10, 10, 6, origin=(100, 0, 0), id="b")
    got, left = select([a, b], make_region(centre=(0, 0), radius=5))
    assert [x.id for x in got] == ["a"] and left == ["b"]


@pytest.mark.parametrize("kw", [dict(region=(0, 0, -1, 5)), dict(centre=(0, 0)), dict(radius=5),
                                dict(centre=(0, 0), radius=-1), dict(region=(0, 0, 1, 1), centre=(0, 0), radius=1),
                                dict(region=(0, 0, float("nan"), 1))])
def test_bad_regions_are_parameter_errors(kw):
    with pytest.raises(ParameterError):
        make_region(**kw)


def test_empty_region_is_an_error_not_a_crash():
    with pytest.raises(ParameterError):
        build_case([box()], make_region(region=(1000, 1000, 1010, 1010)), 270.0, 2.0, 0.0)


# --------------------------------------------------------------------------- surfaces

def test_touching_buildings_are_united_and_narrow_gaps_closed():
    a = box(10, 10, 6, origin=(0, 0, 0), id="a")
    touching = box(10, 10, 8, origin=(10, 0, 0), id="touching")
    near = box(10, 10, 6, origin=(20.5, 0, 0), id="near")       # a 0.5 m gap
    far = box(10, 10, 6, origin=(40, 0, 0), id="far")           # a 9.5 m gap
    open_gap = build_case([a, touching, near, far], make_region(), 270.0, 2.0, min_gap=0.0).united
    assert open_gap.bodies == 3 and open_gap.gap_fills == 0
    closed = build_case([a, touching, near, far], make_region(), 270.0, 2.0, min_gap=1.0).united
    assert closed.bodies == 2 and closed.gap_fills == 1
    # the fill is 0.5 m x 10 m up to the lower eave (6 m): ~30 m3 more than the four boxes
    assert closed.volume_above_ground == pytest.approx(600 + 800 + 600 + 600 + 30, abs=3.0)
    assert set(np.unique(closed.codes)) <= set(range(len(SOLIDS)))
    assert (closed.codes == SOLIDS.index("roof")).any() and (closed.codes == SOLIDS.index("wall")).any()


def test_raised_building_is_sunk_to_the_ground():
    """A building standing 0.7 m above the region's lowest ground does not float."""
    low = box(10, 10, 6, origin=(0, 0, 0), id="low")
    raised = gabled_house(id="raised")
    raised = _translated(raised, 30, 0, 0.7)
    case = build_case([low, raised], make_region(), 270.0, 2.0, 0.0)
    assert case.ground_level == pytest.approx(0.0 - case.offset[2], abs=1e-9)
    v = case.united.vertices
    assert v[:, 2].min() < case.ground_level  # bottoms below the floor
    # the house's volume above the ground grows by its footprint x 0.7 m
    house = 10 * 8 * 6 + 0.5 * 8 * 3 * 10
    assert case.united.volume_above_ground == pytest.approx(600 + house + 80 * 0.7, rel=1e-4)


# --------------------------------------------------------------------------- options

def test_cli_arguments_and_options():
    ap = argparse.ArgumentParser()
    add_cli_arguments(ap.add_argument_group("cfd"))
    a = ap.parse_args(["--cfd", "--centre", "10,20", "--radius", "50", "--wind-direction", "225",
                       "--cell-size", "1.5", "--min-gap", "0.5", "--mesh"])
    o = options_from_args(a)
    assert a.cfd and o == CfdOptions(centre=(10.0, 20.0), radius=50.0, wind_direction=225.0, cell_size=1.5,
                                     min_gap=0.5, mesh=True)
    assert options_from_args(ap.parse_args(["--region", "0,0,10,10"])).region == (0.0, 0.0, 10.0, 10.0)
    assert CfdOptions(cell_size=3.0).gap == 3.0
    for bad in (["--region", "0,0,10"], ["--region", "a,b,c,d"], ["--cell-size", "-1"], ["--centre", "1,2"]):
        with pytest.raises(ParameterError):
            options_from_args(ap.parse_args(bad))


def test_an_open_building_is_left_out_with_its_reason_and_the_case_goes_on(tmp_path):
    from factories import open_box
    from lod2energy.exporters.cfd.writer import export_case
    good = box(10, 10, 6, id="good")
    bad = _translated(open_box(id="bad"), 40, 0)
    before = good.vertices.copy()
    res = export_case([good, bad], None, tmp_path, CfdOptions(cell_size=3.0))
    assert res.building_ids == ("good",)
    assert [f["id"] for f in res.stats["buildings_failed"]] == ["bad"]
    assert any("bad" in p for p in res.problems)
    assert np.array_equal(good.vertices, before)  # input untouched
    assert (tmp_path / "cfd" / "case.json").is_file()
    # nothing written outside OUTDIR
    assert {p.name for p in tmp_path.iterdir()} == {"cfd"}


def test_no_building_in_the_region_writes_nothing(tmp_path):
    from lod2energy.exporters.cfd.writer import export_case
    res = export_case([box()], None, tmp_path, CfdOptions(region=(500.0, 500.0, 600.0, 600.0)))
    assert not res.ok and res.path == "" and "no building in the region" in res.problems[0]
    assert not (tmp_path / "cfd").exists()
