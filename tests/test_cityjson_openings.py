"""CityJSON LoD3 openings (issue 19 item 3): Window / Door semantic surfaces, in each of their
encodings, become real windows and doors on their wall in the IDF, part of the closed wall
in the STL, and are counted in the report."""
from __future__ import annotations

import collections
import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from export_helpers import EPW
from lod2energy.cli import main
from lod2energy.exporters import energyplus
from lod2energy.exporters.stl.writer import read_stl
from lod2energy.io import read
from lod2energy.io.openings import cut_openings
from lod2energy.model import Building

OFFSET = np.array([85000.0, 446000.0, 0.0])
#: A 10 x 8 x 6 m box; a window in its front wall (y = 0, facing -y), a door in its east wall
#: (x = 10, facing +x); rings counter-clockwise seen from outside.
WINDOW = [(2, 0, 2), (4, 0, 2), (4, 0, 4), (2, 0, 4)]


def door(z0: float) -> list[tuple]:
    return [(10, 3, z0), (10, 4.2, z0), (10, 4.2, 2.3), (10, 3, 2.3)]


def box_doc(*, holes: bool = True, parent: bool = False, solid: bool = False, version: str = "2.0",
            shared: bool = True, door_z: float = 0.3) -> dict:
    """The box as a CityJSON document, in one of the encodings of its openings.

    Parameters
    ----------
    holes : bool
        The walls have a hole (inner ring) for each opening; else the openings lie in the
        plane of their wall, over it.
    parent : bool
        The openings' semantic surfaces name their wall's as ``"parent"`` (and it them as
        ``"children"``).
    solid : bool
        A Solid, else a MultiSurface.
    shared : bool
        The openings use the vertices of their hole; else vertices of their own at the same
        coordinates.
    door_z : float, m
        Height of the door's sill (0: down to the ground, a notch in the wall's outline).
    """
    verts = [(0, 0, 0), (0, 8, 0), (10, 8, 0), (10, 0, 0), (0, 0, 6), (10, 0, 6), (10, 8, 6), (0, 8, 6)]

    def vid(p, new=False):
        if not new and p in verts:
            return verts.index(p)
        verts.append(p)
        return len(verts) - 1

    d = door(door_z)
    hw, hd = [vid(p) for p in WINDOW], [vid(p) for p in d]
    ow, od = [vid(p, not shared) for p in WINDOW], [vid(p, not shared) for p in d]
    front, east = [[0, 3, 5, 4]], [[3, 2, 6, 5]]
    if holes:
        front.append(hw[::-1])
        east.append(hd[::-1])
    faces = [[[0, 1, 2, 3]], [[4, 5, 6, 7]], front, east, [[2, 1, 7, 6]], [[1, 0, 4, 7]], [ow], [od]]
    surfs = [{"type": t} for t in ("GroundSurface", "RoofSurface", "WallSurface", "WallSurface", "WallSurface",
                                   "WallSurface", "Window", "Door")]
    if parent:
        surfs[6]["parent"], surfs[2]["children"] = 2, [6]
        surfs[7]["parent"], surfs[3]["children"] = 3, [7]
    values = list(range(len(faces)))
    g = {"type": "MultiSurface", "lod": "3", "boundaries": faces,
         "semantics": {"surfaces": surfs, "values": values}}
    if solid:
        g = {"type": "Solid", "lod": "3", "boundaries": [faces], "semantics": {"surfaces": surfs, "values": [values]}}
    return {"type": "CityJSON", "version": version,
            "transform": {"scale": [0.001] * 3, "translate": OFFSET.tolist()},
            "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
            "CityObjects": {"box": {"type": "Building", "attributes": {"yearOfConstruction": 1975},
                                    "geometry": [g]}},
            "vertices": [[round(c * 1000) for c in p] for p in verts]}


ENCODINGS = {
    "hole": {},
    "hole-parent": dict(parent=True),
    "over-wall": dict(holes=False),
    "over-wall-parent-solid-1.1": dict(holes=False, parent=True, solid=True, version="1.1"),
    "over-wall-own-vertices": dict(holes=False, shared=False),
    "over-wall-door-to-ground": dict(holes=False, door_z=0.0),
}


def write(tmp_path: Path, doc: dict) -> Path:
    p = tmp_path / "box.city.json"
    p.write_text(json.dumps(doc))
    return p


def one(path: Path) -> Building:
    _, feats = read(str(path))
    (b,) = [f for f in feats if isinstance(f, Building)]
    return b


def idf_objects(text: str, kind: str) -> list[list[str]]:
    """The fields (after the class name) of every ``kind`` object of an IDF."""
    body = "\n".join(line.split("!")[0] for line in text.splitlines())
    out = []
    for obj in body.split(";"):
        f = [x.strip() for x in obj.split(",")]
        if f[0] == kind:
            out.append(f[1:])
    return out


def vertices_of(fields: list[str], n_head: int) -> np.ndarray:
    """The ``(k, 3)`` vertices after ``n_head`` fields and the vertex count."""
    return np.array([float(x) for x in fields[n_head + 1:]]).reshape(-1, 3)


def test_cut_openings_gives_walls_the_holes_of_the_openings_drawn_over_them(tmp_path):
    b = one(write(tmp_path, box_doc(holes=False, door_z=0.0)))
    c = cut_openings(b)
    assert dict(c.provenance["openings_cut"]) == {"Door": 1, "Window": 1}
    (g,) = c.objects[0].geometries
    types = [g.semantic_type(s) for *_, s in g.iter_surfaces()]
    front = [s for *_, s in g.iter_surfaces()][types.index("WallSurface")]
    assert len(front.rings) == 2                                       # the window's hole
    win = [s for *_, s in g.iter_surfaces()][types.index("Window")]
    assert set(front.rings[1].tolist()) == set(win.outer.tolist())     # made of the window's vertices
    # every edge of the shell is used by exactly two surfaces: the box is closed through its openings
    edges = collections.Counter(tuple(sorted((int(r[k]), int(r[(k + 1) % len(r)]))))
                                for *_, s in g.iter_surfaces() for r in s.rings for k in range(len(r)))
    assert set(edges.values()) == {2}
    # a box whose walls already have the holes is left as it is
    h = one(write(tmp_path, box_doc()))
    assert cut_openings(h) is h


@pytest.mark.parametrize("name", list(ENCODINGS))
def test_cityjson_openings_become_real_windows_and_doors_on_their_wall(tmp_path, capsys, name):
    src = write(tmp_path, box_doc(**ENCODINGS[name]))
    out = tmp_path / "o"
    assert main(["export", str(src), "-o", str(out), "--idf", "--stl", "-q"]) == 0
    capsys.readouterr()
    (r,) = json.loads((out / "report.json").read_text())["buildings"]
    assert r["energy"]["compliant"] and r["exports"]["idf"]["ok"] and r["exports"]["stl"]["ok"]
    assert r["exports"]["idf"]["openings"] == {"Window": 1, "Door": 1}
    assert r["volume_m3"] == pytest.approx(480.0, rel=1e-6)             # nothing lost or doubled
    # every opening is written by the storey zone its wall part belongs to: no false "not written"
    assert "lies on no outdoor piece" not in json.dumps(r)
    if not ENCODINGS[name].get("holes", True):
        assert r["repair"]["openings_cut"] == {"Door": 1, "Window": 1}
    text = (out / "box.idf").read_text()
    assert "_Win," not in text                                          # not the window-to-wall rule
    offset = np.array(r["exports"]["idf"]["offset"])
    walls = {f[0]: vertices_of(f, 10) for f in idf_objects(text, "BuildingSurface:Detailed")}
    fen = {f[1]: f for f in idf_objects(text, "FenestrationSurface:Detailed")}
    assert set(fen) == {"Window", "Door"}
    for kind, real, axis, at in (("Window", WINDOW, 1, 0.0), ("Door", door(ENCODINGS[name].get("door_z", 0.3)), 0, 10.0)):
        pts = vertices_of(fen[kind], 8) + offset - OFFSET
        assert sorted(map(tuple, pts.round(6))) == sorted(map(tuple, np.array(real, dtype=float)))
        host = walls[fen[kind][3]]
        assert np.allclose(host[:, axis], at)                           # on its own wall
        n = np.cross(pts[1] - pts[0], pts[2] - pts[1])
        assert n[axis] * (1 if at > 0 else -1) > 0                       # facing out like the wall
    tris, _, _ = read_stl(out / "box.stl")
    mesh = trimesh.Trimesh(tris.reshape(-1, 3), np.arange(len(tris) * 3).reshape(-1, 3), process=True)
    assert mesh.is_watertight and mesh.volume == pytest.approx(480.0, rel=1e-4)


@pytest.mark.external
@pytest.mark.skipif(energyplus.run.binary() is None, reason="EnergyPlus not installed")
def test_cityjson_lod3_box_is_simulated_with_its_real_windows(tmp_path, capsys):
    src = write(tmp_path, box_doc(holes=False, parent=True, door_z=0.0))
    out = tmp_path / "o"
    rc = main(["export", str(src), "-o", str(out), "--idf", "--run", "--weather", str(EPW), "-q"])
    capsys.readouterr()
    assert rc == 0
    (r,) = json.loads((out / "report.json").read_text())["buildings"]
    idf = r["exports"]["idf"]
    assert idf["ok"] and idf["severe_errors"] == 0 and idf["openings"] == {"Window": 1, "Door": 1}
    assert idf["heating_kwh"] > 0
