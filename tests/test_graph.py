"""Face-adjacency graph: features, incidence counts and status on tiny named shells."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from lod2energy.geometry import snap_map
from lod2energy.graph import FEATURE_NAMES, building_graphs, face_graph
from lod2energy.model import Surface

from cityjson_docs import BOX_FACES, BOX_VERTICES

V = np.array(BOX_VERTICES, dtype=float)


def surfaces(faces):
    return [Surface.from_lists(f) for f in faces]


def test_box_is_watertight_with_full_features():
    g = face_graph(V, surfaces(BOX_FACES))
    assert g.x.shape == (6, len(FEATURE_NAMES)) == (6, 10)
    assert g.edge_index.shape == (2, 24) and g.edge_attr.shape == (24, 3)
    assert (g.n_boundary, g.n_nonmanifold, g.status) == (0, 0, "watertight")
    np.testing.assert_allclose(g.x[:, 0], [80, 80, 60, 48, 60, 48])          # areas, m2
    np.testing.assert_allclose(g.x[0, 1:4], [0, 0, -1]) and np.testing.assert_allclose(g.x[1, 1:4], [0, 0, 1])
    np.testing.assert_allclose(g.x[:, 4], [0, 1, .5, .5, .5, .5])          # normalised centroid height
    assert (g.x[:, 9] == 4).all()                                            # degree
    np.testing.assert_allclose(g.edge_attr[:, 0], 0, atol=1e-12)           # all dihedrals at 90 degrees
    assert g.n_inconsistent == 0
    assert g.shell_volumes() == pytest.approx([480.0])


def test_open_box_counts_boundary_edges():
    g = face_graph(V, surfaces(BOX_FACES[:1] + BOX_FACES[2:]))               # roof missing
    assert g.status == "open" and g.n_boundary == 4 and g.n_nonmanifold == 0
    assert g.x[:, 7].sum() == 4
    assert g.edge_attr[:, 1].any()                                           # adjacencies touching the hole


def test_flipped_wall_is_inconsistent_and_shrinks_the_volume():
    faces = [list(f) for f in BOX_FACES]
    faces[2] = [faces[2][0][::-1]]
    g = face_graph(V, surfaces(faces))
    assert g.status == "watertight" and g.n_inconsistent == 4
    assert g.shell_volumes()[0] < 480.0


def test_inward_box_has_negative_volume():
    g = face_graph(V, surfaces([[f[0][::-1]] for f in BOX_FACES]))
    assert g.n_inconsistent == 0 and g.shell_volumes()[0] == pytest.approx(-480.0)


def test_fin_makes_a_nonmanifold_edge():
    v = np.vstack([V, [[10, 4, 12]]])
    faces = BOX_FACES + [[[5, 6, 8]], [[6, 5, 8]]]                            # a fin on the roof edge 5-6
    g = face_graph(v, surfaces(faces))
    assert g.status == "non-manifold" and g.n_nonmanifold == 1
    assert g.edge_attr[:, 2].sum() > 0


def test_duplicate_vertices_within_snap_tol_are_merged():
    v = np.vstack([V, V[4] + 0.0004])
    faces = [list(f) for f in BOX_FACES]
    faces[1] = [[8, 5, 6, 7]]                                                 # roof uses the near-duplicate
    assert face_graph(v, surfaces(faces)).status == "watertight"
    assert snap_map(v, 0.001)[8] == 4


def test_degenerate_and_sliver_faces_are_flagged():
    v = np.vstack([V, [[5, 0, 0]]])
    faces = BOX_FACES + [[[0, 8, 1]]]                                         # collinear triangle
    g = face_graph(v, surfaces(faces))
    assert g.x[-1, 5] == 1 and g.x[:6, 5].sum() == 0


def test_nonplanar_face_reports_its_deviation():
    v = V.copy()
    v[6, 2] = 6.3
    g = face_graph(v, surfaces(BOX_FACES))
    assert g.x[1, 6] > 0.05 and g.x[0, 6] < 1e-9


def test_building_graph_keeps_parts_apart(tmp_path):
    from lod2energy.io import read
    from cityjson_docs import parts_doc, write
    doc = parts_doc()
    _, it = read(write(tmp_path, doc))
    g = building_graphs([next(it)])[0]
    assert g.n_faces == 12 and g.status == "watertight"                      # identical parts: no N_nm
    assert g.face_ids[6][0] == "p2"
    assert g.shell_volumes() == pytest.approx([480.0, 480.0])


@settings(max_examples=30, deadline=None)
@given(st.floats(-np.pi, np.pi), st.floats(-np.pi, np.pi),
       st.tuples(*[st.floats(-1e5, 1e5)] * 3))
def test_rigid_motion_keeps_areas_status_and_volume(a, b, t):
    ca, sa, cb, sb = np.cos(a), np.sin(a), np.cos(b), np.sin(b)
    R = np.array([[ca, -sa, 0], [sa, ca, 0], [0, 0, 1]]) @ np.array([[1, 0, 0], [0, cb, -sb], [0, sb, cb]])
    v2 = V @ R.T + np.array(t)
    g1, g2 = face_graph(V, surfaces(BOX_FACES)), face_graph(v2, surfaces(BOX_FACES))
    np.testing.assert_allclose(g1.x[:, 0], g2.x[:, 0], rtol=1e-6)
    np.testing.assert_allclose(g1.x[:, 1:4] @ R.T, g2.x[:, 1:4], atol=1e-6)
    assert g2.status == "watertight" and g2.shell_volumes()[0] == pytest.approx(480.0, rel=1e-6)


def test_batched_graphs_equal_one_by_one():
    from pathlib import Path
    from lod2energy.graph import building_graphs
    from lod2energy.io import read
    path = Path(__file__).resolve().parents[1] / "examples" / "delft_subset.city.jsonl"
    _, it = read(str(path))
    bs = [b for b in it if hasattr(b, "vertices")]
    assert len(bs) == 10
    for a, b in zip([building_graphs([x])[0] for x in bs], building_graphs(bs)):
        np.testing.assert_allclose(a.x, b.x)
        assert np.array_equal(a.edge_index, b.edge_index) and np.array_equal(a.mesh_edges, b.mesh_edges)
        assert np.array_equal(a.incidence, b.incidence) and a.face_ids == b.face_ids
        np.testing.assert_allclose(a.shell_volumes(), b.shell_volumes())


def test_no_faces_is_empty_not_watertight():
    g = face_graph(V, [])
    assert g.n_faces == 0 and g.status == "empty"


def test_an_unused_vertex_does_not_chain_two_vertices_into_one():
    # roof corners 1.2 mm apart (> snap_tol) with an unused vertex between them (the input's
    # vertex left in the list by a repair): they stay two vertices
    v = np.vstack([V, V[4] + [0, 0, 0.0012], V[4] + [0, 0, 0.0006]])
    faces = BOX_FACES + [[[4, 8, 5]]]                                          # a sliver on edge 4-5
    g = face_graph(v, surfaces(faces))
    g_chained = face_graph(np.vstack([V, V[4] + [0, 0, 0.0012]]), surfaces(faces))
    assert g.n_faces == g_chained.n_faces == 7
    snapped_if_chained = snap_map(v, 0.001)
    assert snapped_if_chained[8] == snapped_if_chained[9] == 4                 # all three, transitively
    # with 9 unused, 8 stays a vertex of its own: the sliver keeps three corners
    assert g.x[6, 0] > 0 and g_chained.x[6, 0] > 0
