"""OpenFOAM ``surfaceCheck`` on exported STLs (the real CFD client).

External: needs the Debian/Ubuntu package ``openfoam`` (see .ci/install-openfoam.sh).
"""
from __future__ import annotations

import pytest

from export_helpers import DATA, energy_ready, l_shaped, parts_building, real_buildings, two_part_building
from factories import box, box_polygons, gabled_house

from lod2energy.exporters.cfd import openfoam
from lod2energy.exporters.stl import writer as stl


needs_foam = pytest.mark.skipif(openfoam.surface_check_binary() is None,
                                reason="OpenFOAM surfaceCheck not installed: apt-get install openfoam")


@pytest.mark.external
@needs_foam
@pytest.mark.parametrize("ascii_", [True, False], ids=["ascii", "binary"])
@pytest.mark.parametrize("make", [box, gabled_house, l_shaped, two_part_building], ids=lambda f: f.__name__)
def test_canonical_stl_passes_surface_check(tmp_path, make, ascii_):
    res = stl.write([energy_ready(make())], tmp_path, stl.StlOptions(ascii=ascii_))
    sc = openfoam.surface_check(res[0].path)
    assert sc.ok, sc.failures
    assert sc.closed and sc.illegal_triangles == 0 and sc.zones == sc.parts == 1
    if ascii_:
        assert set(sc.regions) == {"roof", "wall", "ground"}


@pytest.mark.external
@needs_foam
def test_surface_check_sees_an_open_surface(tmp_path):
    res = stl.write([energy_ready(box())], tmp_path, stl.StlOptions(ascii=True))
    text = open(res[0].path).read()
    first = text.index("  facet")
    second = text.index("  facet", first + 1)
    bad = tmp_path / "open.stl"
    bad.write_text(text[:first] + text[second:])
    sc = openfoam.surface_check(bad)
    assert not sc.ok and not sc.closed


@pytest.mark.external
@needs_foam
def test_edge_touching_parts_pass(tmp_path):
    b = energy_ready(parts_building([box_polygons(10, 8, 6), box_polygons(5, 5, 6, (10, 8, 0))], "edge"))
    sc = openfoam.surface_check(stl.write([b], tmp_path)[0].path)
    assert sc.ok, sc.failures


CASES = [("3dbag/tile901_trimmed.city.jsonl", False, 6), ("denhaag/DenHaag_01.city.json", True, 8),
         ("rotterdam/Example_CityGML_Converted_Rotterdam.json", False, 4)]


@pytest.mark.external
@needs_foam
@pytest.mark.parametrize("rel,multipart,n", CASES, ids=["3dbag", "denhaag_parts", "rotterdam"])
def test_real_stls_pass_surface_check(tmp_path, rel, multipart, n):
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    bs = real_buildings(rel, n=n, multipart=multipart)
    res = stl.write(bs, tmp_path, stl.StlOptions(ascii=True))
    failures = {}
    for r in res:
        sc = openfoam.surface_check(r.path)
        if not sc.ok:
            failures[r.building_ids[0]] = sc.failures
        assert sc.zones == sc.parts
    assert failures == {}


@pytest.mark.external
@needs_foam
def test_dataset_stl_passes(tmp_path):
    rel = "3dbag/tile901_trimmed.city.jsonl"
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    bs = real_buildings(rel, n=15)
    res = stl.write(bs, tmp_path, stl.StlOptions(mode="dataset", ascii=True))
    sc = openfoam.surface_check(res[0].path)
    assert sc.ok, sc.failures


def test_parse_surface_check_verdicts():
    good = ("Region\tSize\n------\t----\nroof\t5\nwall\t22\n\n\nSurface has no illegal triangles.\n"
            "Surface is closed. All edges connected to two faces.\n\nNumber of unconnected parts : 2\n\n"
            "Number of zones (connected area with consistent normal) : 2\nMore than one normal orientation.\n")
    sc = openfoam.parse_surface_check(good)
    assert sc.ok and sc.regions == {"roof": 5, "wall": 22} and sc.zones == sc.parts == 2
    bad = good.replace("Surface is closed. All edges connected to two faces.",
                       "***Surface is not closed since not all edges (4) connected to two faces:")
    assert not openfoam.parse_surface_check(bad).ok
    flipped = good.replace("unconnected parts : 2", "unconnected parts : 1")
    assert not openfoam.parse_surface_check(flipped).ok


@pytest.mark.external
@needs_foam
@pytest.mark.parametrize("make", ["gap_stl", "float32_pinch_stl"])
def test_self_check_agrees_with_surface_check(tmp_path, make):
    import test_export_stl as helpers
    bad = getattr(helpers, make)(tmp_path / "bad.stl")
    assert not openfoam.surface_check(bad).ok
    assert stl.self_check(bad) != []
    good = helpers.gap_stl(tmp_path / "good.stl", gap=0.0)
    assert openfoam.surface_check(good).ok and stl.self_check(good) == []
