"""STL writer: a face whose edge the neighbour holds in two pieces (a T-junction) is split at
the T-vertex before it is triangulated, so the STL has every edge twice."""
from __future__ import annotations

import numpy as np

from test_repair import box, t_junction
from lod2energy.exporters import stl
from lod2energy.exporters.zones import zone_shells


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
