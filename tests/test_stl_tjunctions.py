"""STL writer: a face whose edge the neighbour holds in two pieces (a T-junction) is split at
the T-vertex before it is triangulated, so the STL has every edge twice."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from test_repair import box, t_junction
from lod2energy.exporters.cfd import openfoam
from lod2energy.cli import main
from lod2energy.exporters.stl import writer as stl
from lod2energy.energy.zones.shells import zone_shells


def test_split_adds_the_t_vertices_to_the_edges_without_a_twin():
    (z,) = zone_shells(t_junction(), np.zeros(3))
    s = stl.split_t_junctions(z)
    n_before = sum(len(r) for f in z.faces for r in f.rings)
    n_after = sum(len(r) for f in s.faces for r in f.rings)
    assert n_after == n_before + 2  # ground and roof each get the split wall's vertex
    directed = {(r[k], r[(k + 1) % len(r)]) for f in s.faces for r in f.rings for k in range(len(r))}
    assert all((b, a) in directed for a, b in directed)


def test_a_closed_zone_is_left_as_it_is():
    (z,) = zone_shells(box(), np.zeros(3))
    assert stl.split_t_junctions(z) is z


def test_the_stl_of_a_t_junction_building_is_closed(tmp_path):
    (r,) = stl.write([t_junction()], tmp_path)
    assert r.ok, r.problems
    assert r.stats["volume_m3"] == 480.0
    v, t, _ = stl.read_stl(r.path)
    assert stl.self_check(r.path) == []


def test_open_triangle_edges_are_split_at_the_vertices_on_them():
    # triangle 0-1-2 has the long edge 0-1; across it the pieces 0-3 and 3-1 (3 on 0-1)
    v = np.array([[0, 0, 0], [2, 0, 0], [1, 1, 0], [1, 0, 0], [1, -1, 0]], dtype=float)
    t = np.array([[0, 1, 2], [3, 0, 4], [1, 3, 4]])
    c = np.array([7, 8, 9])
    t2, c2 = stl.split_open_edges(v, t, c)
    e = np.sort(np.concatenate([t2[:, [0, 1]], t2[:, [1, 2]], t2[:, [2, 0]]]), axis=1)
    pairs, n = np.unique(e, axis=0, return_counts=True)
    count = {tuple(p): k for p, k in zip(pairs.tolist(), n.tolist())}
    assert (0, 1) not in count and count[(0, 3)] == 2 and count[(1, 3)] == 2
    assert sorted(c2.tolist()) == [7, 7, 8, 9]                      # the pieces keep their value
    area = stl.triangle_areas(v, t2).sum()
    assert area == stl.triangle_areas(v, t).sum()                  # same surface
    normals = np.cross(v[t2[:, 1]] - v[t2[:, 0]], v[t2[:, 2]] - v[t2[:, 0]])
    assert (normals[c2 == 7][:, 2] > 0).all()                       # orientation kept


def test_split_open_edges_leaves_a_closed_mesh_as_it_is():
    (z,) = zone_shells(box(), np.zeros(3))
    v, t, c = stl._zone_mesh(z)
    t2, c2 = stl.split_open_edges(v, t, c)
    assert t2 is t and c2 is c


@pytest.mark.external
@pytest.mark.skipif(openfoam.surface_check_binary() is None, reason="OpenFOAM surfaceCheck not installed")
def test_lod3_fzk_haus_stl_is_closed_for_surface_check(tmp_path, capsys):
    # its windows' sills lie on one line: a wall triangle along that line left open edges
    src = Path(__file__).parent / "data" / "fzk_haus_lod3.gml"
    assert main(["export", str(src), "-o", str(tmp_path), "--stl", "-q", "--no-html"]) == 0
    capsys.readouterr()
    (r,) = json.loads((tmp_path / "report.json").read_text())["buildings"]
    assert r["exports"]["stl"]["ok"], r["exports"]["stl"]
    sc = openfoam.surface_check(r["exports"]["stl"]["path"])
    assert sc.closed and sc.illegal_triangles == 0 and sc.parts == 1
