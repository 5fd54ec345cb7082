"""HBJSON (--hbjson): every file written under its good name loads with honeybee-energy's
Model.from_dict and passes its check_all() with no error; its Rooms hold our zones' volumes.
honeybee is AGPL-3: it is a test dependency only, the writer never imports it."""
from __future__ import annotations

import json
from pathlib import Path

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


@pytest.mark.parametrize("src", ["example", "delft", "berlin"])
def test_every_hbjson_of_a_tile_passes_check_all_with_our_volumes(tmp_path, src):
    path = {"example": lambda: EXAMPLE, "delft": lambda: shared_path("3dbag", "delft_subset.city.jsonl"),
            "berlin": lambda: shared_path("citygml-real", "berlin", "3920_5820.gml")}[src]()
    out = tmp_path / "out"
    assert main(["export", str(path), "-o", str(out), "--hbjson", "--no-html", "-q", "-j", "1"]) in (0, 1)
    report = json.loads((out / "report.json").read_text())
    ok = {b["id"]: b for b in report["buildings"] if b.get("exports", {}).get("hbjson", {}).get("ok")}
    assert ok
    files = sorted(out.glob(f"*{hbjson.SUFFIX}"))
    assert len(files) == len(ok)
    for f in files:
        m = load(f)
        assert m.check_all(raise_exception=False, detailed=True) == [], f
        b = ok[m.user_data["building"]]
        if not b.get("downgrades"):  # the zones are the shell: their volumes add up to it
            assert sum(r.volume for r in m.rooms) == pytest.approx(b["volume_m3"], rel=5e-3)
    for b in report["buildings"]:  # a building without a good HBJSON says why
        e = b.get("exports", {}).get("hbjson")
        if e is not None and not e["ok"]:
            assert e["problems"]
