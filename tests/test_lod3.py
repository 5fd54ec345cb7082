"""LoD3 input: openings recognised and kept, the envelope closed through them, real windows and
doors in the IDF, interior detail left out and counted."""
from __future__ import annotations

import collections
import json
from pathlib import Path

import numpy as np
import pytest

from export_helpers import EPW
from lod2energy.energy.zones.shells import local_origin, zone_shells
from lod2energy.energy.openings import Opening, opening_polygon, split_openings
from lod2energy.exporters import energyplus
from lod2energy.cli import main
from lod2energy.io import read
from lod2energy.io.interior import without_interior
from lod2energy.model import Building

HERE = Path(__file__).parent / "data"
FZK = HERE / "fzk_haus_lod3.gml"            # real: KIT FZK-Haus LoD3, 11 windows, 2 doors
BOX = HERE / "lod3_box_openings.city.json"  # hand-made: a flush window, a recessed door, interior


def one(path: Path) -> Building:
    model, feats = read(str(path))
    (b,) = [f for f in feats if isinstance(f, Building)]
    return b


def semantic_counts(b: Building) -> collections.Counter:
    c = collections.Counter()
    for _o, _gi, g in b.envelope():
        c.update(g.semantic_type(s) for *_, s in g.iter_surfaces())
    return c


def fenestration(idf: Path) -> collections.Counter:
    lines = idf.read_text().splitlines()
    return collections.Counter(lines[i + 2].split(",")[0].strip() for i, ln in enumerate(lines)
                               if ln.startswith("FenestrationSurface:Detailed"))


def test_citygml_lod3_windows_and_doors_are_read_as_openings():
    b = one(FZK)
    c = semantic_counts(b)
    assert b.default_lod() == "3" and c["Window"] >= 11 and c["Door"] >= 2


@pytest.mark.parametrize("path,windows,doors", [(FZK, 11, 2), (BOX, 1, 1)])
def test_split_openings_keeps_the_zone_closed(path, windows, doors):
    b = without_interior(one(path))
    (z,) = zone_shells(b, local_origin([b]))
    nz, ops, unmatched = split_openings(z)
    assert collections.Counter(o.kind for o in ops) == {"Window": windows, "Door": doors}
    assert unmatched == 0
    assert not any(f.semantic_type in ("Window", "Door") for f in nz.faces)
    assert all(len(f.rings) == 1 for f in nz.faces if f.index in {o.wall_index for o in ops})  # holes filled
    assert open_edges(nz) == open_edges(z)        # as closed as before (FZK-Haus has T-junctions)
    assert sum(len(f.rings) - 1 for f in z.faces) == windows + doors


def open_edges(z) -> int:
    """Undirected ring edges used by one face only."""
    c = collections.Counter(tuple(sorted((r[k], r[(k + 1) % len(r)]))) for f in z.faces for r in f.rings
                            for k in range(len(r)))
    return sum(1 for n in c.values() if n == 1)


def test_opening_polygon_makes_a_round_window_an_upright_rectangle_of_its_area():
    t = np.linspace(0, 2 * np.pi, 33)[:-1]
    circle = np.column_stack([2 + 0.5 * np.cos(t), np.zeros_like(t), 3 + 0.5 * np.sin(t)])
    wall = np.array([[0, 0, 0], [10, 0, 0], [10, 0, 6], [0, 0, 6]], dtype=float)
    w = opening_polygon(Opening(circle, "Window", 0), wall)
    assert w is not None and len(w) == 4
    assert np.allclose(w[:, 1], 0.0)                                        # in the wall plane
    area = 0.5 * np.linalg.norm(np.cross(w[2] - w[0], w[1] - w[3]))
    assert area == pytest.approx(np.pi * 0.25, rel=0.03)
    assert np.allclose(w.mean(axis=0), [2, 0, 3], atol=1e-6)
    assert np.cross(w[1] - w[0], w[2] - w[1]) @ np.array([0, -1, 0]) > 0  # faces out like the wall
    assert opening_polygon(Opening(circle + [20, 0, 0], "Window", 0), wall) is None  # off the wall


def test_interior_detail_is_left_out_and_counted(tmp_path, capsys):
    b = without_interior(one(BOX))
    assert dict(b.provenance["interior_left_out"]) == {"InteriorWallSurface": 1, "BuildingFurniture": 1}
    assert "InteriorWallSurface" not in semantic_counts(b)
    out = tmp_path / "o"
    assert main(["export", str(BOX), "-o", str(out), "--idf", "--stl", "--cityjson", "-q"]) == 0
    capsys.readouterr()
    (r,) = json.loads((out / "report.json").read_text())["buildings"]
    assert r["repair"]["interior_left_out"] == {"BuildingFurniture": 1, "InteriorWallSurface": 1}
    assert r["energy"]["compliant"] and all(e["ok"] for e in r["exports"].values())
    assert fenestration(out / "box.idf") == {"Window": 1, "Door": 1}


@pytest.mark.external
@pytest.mark.skipif(energyplus.run.binary() is None, reason="EnergyPlus not installed")
def test_lod3_building_is_simulated_with_its_real_windows(tmp_path, capsys):
    out = tmp_path / "fzk"
    rc = main(["export", str(FZK), "-o", str(out), "--idf", "--run", "--weather", str(EPW), "-q"])
    capsys.readouterr()
    assert rc == 0
    (r,) = json.loads((out / "report.json").read_text())["buildings"]
    idf = r["exports"]["idf"]
    assert r["energy"]["compliant"] and idf["ok"] and idf["severe_errors"] == 0
    (path,) = out.glob("*.idf")
    assert fenestration(path) == {"Window": 11, "Door": 2}       # the input's, not the WWR rule's
    assert "_Win," not in path.read_text()
