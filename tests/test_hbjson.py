"""HBJSON (--hbjson): every file written under its good name loads with honeybee-energy's
Model.from_dict and passes its check_all() with no error; its Rooms hold our zones' volumes.
honeybee is AGPL-3: it is a test dependency only, the writer never imports it."""
from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from conftest import shared_path
from export_helpers import energy_ready, shifted
from factories import box, gabled_house
from lod2energy.cli import main
from lod2energy.exporters.energyplus.options import IdfOptions
from lod2energy.exporters.hbjson import writer as hbjson

honeybee_model = pytest.importorskip("honeybee.model")
pytest.importorskip("honeybee_energy")

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "3dbag_b2.city.json"


def load(path) -> "honeybee_model.Model":
    return honeybee_model.Model.from_dict(json.loads(Path(path).read_text()))


def test_the_writer_does_not_import_honeybee():
    src = Path(hbjson.__file__).read_text()
    assert "import honeybee" not in src and "from honeybee" not in src and "ladybug" not in src


def test_a_terrace_of_two_houses_passes_check_all(tmp_path):
    """Two gabled houses wall to wall: storey rooms joined by Surface floors, the party wall
    Adiabatic, windows on the outdoor walls, our U-values in the constructions."""
    a = energy_ready(shifted(gabled_house(id="a")))
    b = energy_ready(shifted(gabled_house(id="b"), (85010.0, 446000.0, 0.0)))
    res = hbjson.write([a, b], tmp_path, IdfOptions(attic="conditioned"))
    assert [r.ok for r in res] == [True, True], [r.problems for r in res]
    for r in res:
        m = load(r.path)
        assert m.check_all(raise_exception=False, detailed=True) == []
        assert len(m.rooms) == 3  # two storeys and the attic
        assert sum(x.volume for x in m.rooms) == pytest.approx(10 * 8 * 6 + 10 * 8 * 3 / 2, rel=5e-3)
        for room in m.rooms:
            assert room.volume == pytest.approx(r.stats["zone_volumes_m3"][room.identifier], rel=5e-3)
        bcs = {type(f.boundary_condition).__name__ for room in m.rooms for f in room.faces}
        assert bcs == {"Outdoors", "Ground", "Adiabatic", "Surface"}
        types = {f.type.name for room in m.rooms for f in room.faces}
        assert types == {"Wall", "RoofCeiling", "Floor"}
        assert any(f.apertures for room in m.rooms for f in room.faces)
        walls = [f for room in m.rooms for f in room.faces
                 if f.type.name == "Wall" and type(f.boundary_condition).__name__ == "Outdoors"]
        u_ours = a.provenance["thermal"]["u_values"]["wall"]
        assert walls[0].properties.energy.construction.u_factor == pytest.approx(u_ours, rel=0.05)


def test_the_self_check_refuses_what_check_all_refuses(tmp_path):
    """The control: a degenerate face and a warped one fail our check and honeybee's."""
    res = hbjson.write([energy_ready(shifted(box(id="b")))], tmp_path, IdfOptions())
    doc = json.loads(Path(res[0].path).read_text())
    assert hbjson.self_check(res[0].path) == []
    face = doc["rooms"][0]["faces"][0]["geometry"]["boundary"]
    face[0][2] += 0.05  # 5 cm off the plane
    bad = tmp_path / "bad.hbjson"
    bad.write_text(json.dumps(doc))
    assert any("not planar" in p for p in hbjson.self_check(str(bad)))
    assert load(bad).check_all(raise_exception=False, detailed=True)


@pytest.mark.parametrize("src", ["example", "delft", "berlin", "denhaag"])
def test_every_hbjson_of_a_tile_passes_check_all_with_our_volumes(tmp_path, src):
    """Den Haag: its first 100 buildings (warped roofs beside attic floors, slivers, parts
    interpenetrating by a millimetre), the others as neighbours."""
    path = {"example": lambda: EXAMPLE, "delft": lambda: shared_path("3dbag", "delft_subset.city.jsonl"),
            "berlin": lambda: shared_path("citygml-real", "berlin", "3920_5820.gml"),
            "denhaag": lambda: shared_path("denhaag", "DenHaag_01.city.json")}[src]()
    extra = []
    if src == "denhaag":
        objs = json.loads(path.read_text())["CityObjects"]
        (tmp_path / "ids.txt").write_text("\n".join([k for k, v in objs.items() if v["type"] == "Building"][:100]))
        extra = ["--ids", f"@{tmp_path / 'ids.txt'}"]
    out = tmp_path / "out"
    assert main(["export", str(path), "-o", str(out), "--hbjson", "--no-html", "-q", "-j", "1", *extra]) in (0, 1)
    report = json.loads((out / "report.json").read_text())
    ok = {b["id"]: b for b in report["buildings"] if b.get("exports", {}).get("hbjson", {}).get("ok")}
    assert ok
    files = sorted(out.glob(f"*{hbjson.SUFFIX}"))
    assert len(files) == len(ok)
    for f in files:
        m = load(f)
        assert m.check_all(raise_exception=False, detailed=True) == [], f
        assert _kept_orientation(f, m), f
        b = ok[m.user_data["building"]]
        if not b.get("downgrades"):  # the zones are the shell: their volumes add up to it
            assert sum(r.volume for r in m.rooms) == pytest.approx(b["volume_m3"], rel=5e-3)
    for b in report["buildings"]:  # a building without a good HBJSON says why
        e = b.get("exports", {}).get("hbjson")
        if e is not None and not e["ok"]:
            assert e["problems"]


def _kept_orientation(path, model) -> bool:
    """Honeybee re-orients a closed room's faces by its own ray test on loading: every face
    must keep the normal we wrote."""
    doc = json.loads(Path(path).read_text())
    ours = {f["identifier"]: np.asarray(f["geometry"]["boundary"], float) for r in doc["rooms"] for f in r["faces"]}
    for room in model.rooms:
        for f in room.faces:
            p = ours[f.identifier]
            n = np.cross(p[1:-1] - p[0], p[2:] - p[0]).sum(axis=0)
            if float(np.dot(n, [f.normal.x, f.normal.y, f.normal.z])) <= 0:
                return False
    return True


def test_a_warped_roof_is_written_as_triangles_and_keeps_its_orientation(tmp_path):
    """A roof 4 mm out of plane (the ridge's end moved sideways): its faces are written as exact
    triangles, the model keeps 1 mm, honeybee keeps every face's orientation (a warped roof beside
    an attic floor flipped that floor upward: 000109)."""
    b = gabled_house(id="w")
    v = b.vertices.copy()
    end = np.flatnonzero(np.all(np.isclose(v, [10.0, 4.0, 9.0]), axis=1))
    assert len(end) == 1
    v[end[0], 1] += 0.004
    res = hbjson.write([energy_ready(shifted(replace(b, vertices=v)))], tmp_path, IdfOptions(attic="conditioned"))
    assert res[0].ok, res[0].problems
    doc = json.loads(Path(res[0].path).read_text())
    assert doc["tolerance"] == hbjson.TOLERANCE
    faces = [np.asarray(f["geometry"]["boundary"], float) for r in doc["rooms"] for f in r["faces"]]
    assert max(hbjson._deviation(p) for p in faces) < 1e-5
    assert sum(len(p) == 3 for p in faces) >= 4  # the two roof planes as triangles (besides the gables')
    m = load(res[0].path)
    assert m.check_all(raise_exception=False, detailed=True) == []
    assert _kept_orientation(res[0].path, m)
    assert sum(r.volume for r in m.rooms) == pytest.approx(10 * 8 * 6 + 10 * 8 * 3 / 2, rel=5e-3)


def test_a_sliver_face_is_merged_into_its_neighbour_and_the_room_stays_closed(tmp_path):
    """A wall split into a face and a sliver 0.4 mm high (0.002 m2): honeybee calls the sliver
    degenerate (000103); mended, it is part of the floor and the room is still closed."""
    res = hbjson.write([energy_ready(shifted(box(id="s")))], tmp_path, IdfOptions())
    doc = json.loads(Path(res[0].path).read_text())
    room = doc["rooms"][0]
    # a wall's bottom edge a -> b, shared with the ground face (b -> a)
    k, wall = next((k, f) for k, f in enumerate(room["faces"]) if f["face_type"] == "Wall")
    ring = [tuple(p) for p in wall["geometry"]["boundary"]]
    i = next(i for i in range(len(ring)) if ring[i][2] == ring[(i + 1) % len(ring)][2] == min(p[2] for p in ring))
    a, b_ = np.array(ring[i]), np.array(ring[(i + 1) % len(ring)])
    m = tuple((0.5 * (a + b_) + [0.0, 0.0, 0.0004]).tolist())
    wall["geometry"]["boundary"] = [list(p) for p in ring[:i + 1] + [m] + ring[i + 1:]]
    sliver = {**{key: v for key, v in wall.items() if key != "apertures"}, "identifier": wall["identifier"] + "_sliver",
              "geometry": {"type": "Face3D", "boundary": [list(ring[i]), list(ring[(i + 1) % len(ring)]), list(m)]}}
    room["faces"].insert(k + 1, sliver)
    assert hbjson.collapsed(np.array(sliver["geometry"]["boundary"]), doc["tolerance"])
    bad = tmp_path / "bad.hbjson"
    bad.write_text(json.dumps(doc))
    assert any("degenerate" in p for p in hbjson.self_check(str(bad)))
    assert any(e["code"] == "000103" for e in load(bad).check_all(raise_exception=False, detailed=True))
    room["faces"] = hbjson.mend_slivers(room["faces"], doc["tolerance"])
    assert len(room["faces"]) == 6 and not any(f["identifier"].endswith("_sliver") for f in room["faces"])
    good = tmp_path / "good.hbjson"
    good.write_text(json.dumps(doc))
    assert hbjson.self_check(str(good)) == []
    m_ = load(good)
    assert m_.check_all(raise_exception=False, detailed=True) == []
    assert m_.rooms[0].volume == pytest.approx(res[0].stats["zone_volumes_m3"][room["identifier"]], rel=1e-4)


def test_rooms_of_overlapping_parts_are_refused_with_the_reason(tmp_path):
    """Two boxes that overlap by a metre (BuildingParts of one building in the input): honeybee's
    room collision check (000108) fails, so our self-check refuses and says why."""
    floors = [(0, np.array([[0, 0, 0], [0, 5, 0], [5, 5, 0], [5, 0, 0]], float)),
              (1, np.array([[4, 0, 0], [4, 5, 0], [9, 5, 0], [9, 0, 0]], float)),
              (2, np.array([[9.0015, 0, 0], [9.0015, 5, 0], [12, 5, 0], [12, 0, 0]], float))]
    assert hbjson.collisions(floors, 0.001) == [(0, 1)]
    # a millimetre's interpenetration is within a coarser tolerance, a metre's in none
    touching = [floors[1], (2, floors[2][1] - [0.0025, 0, 0])]
    assert hbjson.collisions(touching, 0.001) == [(1, 2)]
    assert hbjson.overlap_tolerance(touching) == 0.002 and hbjson.overlap_tolerance(floors) == hbjson.TOLERANCES[0]
    # a file of two such rooms: honeybee's 000108, and our self-check says which rooms
    res = hbjson.write([energy_ready(shifted(box(id="o")))], tmp_path, IdfOptions())
    doc = json.loads(Path(res[0].path).read_text())
    twin = json.loads(json.dumps(doc["rooms"][0]).replace(doc["rooms"][0]["identifier"], "twin"))
    for f in twin["faces"]:
        f["geometry"]["boundary"] = [[x + 1.0, y, z] for x, y, z in f["geometry"]["boundary"]]
        f.pop("apertures", None)
    doc["rooms"].append(twin)
    bad = tmp_path / "two.hbjson"
    bad.write_text(json.dumps(doc))
    assert any(e["code"] == "000108" for e in load(bad).check_all(raise_exception=False, detailed=True))
    assert any("and twin overlap" in p for p in hbjson.self_check(str(bad)))
