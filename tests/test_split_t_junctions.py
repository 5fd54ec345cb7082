"""T-junction splitting (:func:`lod2energy.repair.cleanup.split_t_junctions`) tests exactly only the
edges a vertex may lie on, and gives the answer of testing every edge; the ladder cleans its input
once for itself and the fidelity envelope.

The cost on detailed LoD2.2 roofs (3DBAG tile 5908) was one ball query and one small numpy
computation per ring edge, at every clean-up of every ladder stage: most of those balls hold
neighbouring vertices that lie on no edge. Here a roof of many strips (every edge has vertices in
its ball, none on it) must need no exact test at all, and a box with one T-junction two.
"""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.config import DEFAULT
from lod2energy.polymesh import Face, PolyMesh
from lod2energy.repair import cleanup as cleanup_mod
from lod2energy.repair import pipeline
from lod2energy.repair.cleanup import clean_ring, snap_vertices, split_t_junctions
from lod2energy.repair.convert import mesh_of_geometry
from lod2energy.repair.orientation import orient
from lod2energy.repair.verdict import targets

from conftest import shared_path


def _reference(m: PolyMesh, tol: float, min_gap: float = 0.001) -> PolyMesh:
    """Every edge queried and tested, as before the prefilter."""
    from scipy.spatial import cKDTree
    V = m.vertices
    used = np.array(sorted({i for f in m.faces for r in f.rings for i in r}), dtype=np.int64)
    if len(used) < 3:
        return m
    tree = cKDTree(V[used])
    changed, faces = False, []
    for f in m.faces:
        rings = []
        for r in f.rings:
            new = []
            for i in range(len(r)):
                a, b = r[i], r[(i + 1) % len(r)]
                new.append(a)
                pa, pb = V[a], V[b]
                e = pb - pa
                L = float(np.linalg.norm(e))
                if L <= 2 * min_gap:
                    continue
                cand = tree.query_ball_point((pa + pb) / 2, L / 2 + tol)
                if len(cand) <= 2:
                    continue
                ids = used[cand]
                Q = V[ids]
                t = (Q - pa) @ e / (L * L)
                d = np.linalg.norm(pa + t[:, None] * e - Q, axis=1)
                ok = (d <= tol) & (t * L > min_gap) & ((1 - t) * L > min_gap) & (ids != a) & (ids != b)
                if ok.any():
                    sel = np.flatnonzero(ok)
                    new.extend(int(ids[k]) for k in sel[np.argsort(t[sel], kind="stable")])
                    changed = True
            rings.append(clean_ring(tuple(new)))
        faces.append(Face(tuple(rings), f.source, f.semantic))
    return m.with_faces(faces) if changed else m


def strip_roof_box(n: int = 20, dx: float = 1.0, w: float = 0.05, dz: float = 6.0) -> PolyMesh:
    """A closed box ``dx`` x ``n w`` x ``dz`` m whose ground and roof are ``n`` strips ``w`` wide,
    the side walls holding every strip's corners: no T-junction, but the ball of every long strip
    edge (centre its midpoint, radius half its length) holds the neighbouring strips' corners."""
    V = []
    for z in (0.0, dz):
        for y in range(n + 1):
            V += [(0.0, y * w, z), (dx, y * w, z)]
    V = np.array(V)
    top = 2 * (n + 1)

    def vid(y, x, up):
        return (top if up else 0) + 2 * y + x

    faces = []
    for y in range(n):
        faces.append((vid(y, 0, 0), vid(y + 1, 0, 0), vid(y + 1, 1, 0), vid(y, 1, 0)))  # ground, down
        faces.append((vid(y, 0, 1), vid(y, 1, 1), vid(y + 1, 1, 1), vid(y + 1, 0, 1)))  # roof, up
    faces.append((vid(0, 0, 0), vid(0, 1, 0), vid(0, 1, 1), vid(0, 0, 1)))  # y = 0
    faces.append((vid(n, 1, 0), vid(n, 0, 0), vid(n, 0, 1), vid(n, 1, 1)))  # y = n
    faces.append(tuple(vid(y, 1, 0) for y in range(n + 1)) + tuple(vid(y, 1, 1) for y in range(n, -1, -1)))  # x = dx
    faces.append(tuple(vid(y, 0, 0) for y in range(n, -1, -1)) + tuple(vid(y, 0, 1) for y in range(n + 1)))  # x = 0
    return PolyMesh(V, tuple(Face((f,), k) for k, f in enumerate(faces)))


def t_junction_box() -> PolyMesh:
    """A box whose front wall (y = 0) is split at x = 5; ground and roof do not know the split."""
    V = np.array([(0, 0, 0), (10, 0, 0), (10, 8, 0), (0, 8, 0), (0, 0, 6), (10, 0, 6), (10, 8, 6), (0, 8, 6),
                  (5, 0, 0), (5, 0, 6)], dtype=float)
    F = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 8, 9, 4), (8, 1, 5, 9), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    return PolyMesh(V, tuple(Face((f,), k) for k, f in enumerate(F)))


@pytest.fixture
def exact_tests(monkeypatch):
    calls = []
    real = cleanup_mod._on_edge

    def counted(V, used, tree, a, b, *args):
        calls.append((a, b))
        return real(V, used, tree, a, b, *args)
    monkeypatch.setattr(cleanup_mod, "_on_edge", counted)
    return calls


def _edges_with_neighbours(m: PolyMesh, tol: float) -> int:
    """Edges whose ball holds more than their two ends: each cost an exact test before."""
    from scipy.spatial import cKDTree
    tree, n = cKDTree(m.vertices), 0
    for f in m.faces:
        for a, b in f.edges():
            pa, pb = m.vertices[a], m.vertices[b]
            n += len(tree.query_ball_point((pa + pb) / 2, np.linalg.norm(pb - pa) / 2 + tol)) > 2
    return n


def test_a_strip_roof_needs_no_exact_edge_test(exact_tests):
    m = strip_roof_box(20)
    assert _edges_with_neighbours(m, DEFAULT.tjunction_tol) >= 80  # the 80 long strip edges at least
    assert split_t_junctions(m, DEFAULT.tjunction_tol, DEFAULT.snap_tol) is m
    assert exact_tests == []
    assert _reference(m, DEFAULT.tjunction_tol, DEFAULT.snap_tol) is m


def test_a_t_junction_is_tested_and_split_on_its_two_edges_only(exact_tests):
    m = t_junction_box()
    out = split_t_junctions(m, DEFAULT.tjunction_tol, DEFAULT.snap_tol)
    assert sorted(tuple(sorted(e)) for e in exact_tests) == [(0, 1), (4, 5)]
    assert out.faces[0].outer == (0, 3, 2, 1, 8) and out.faces[1].outer == (4, 9, 5, 6, 7)
    assert out.faces == _reference(m, DEFAULT.tjunction_tol, DEFAULT.snap_tol).faces


def test_random_meshes_agree_with_every_edge_tested():
    rng = np.random.default_rng(7)
    for _ in range(30):
        V = rng.integers(0, 6, size=(60, 3)).astype(float) * rng.choice([0.5, 1.0]) + rng.normal(0, 2e-3, (60, 3))
        faces = tuple(Face((tuple(int(i) for i in rng.choice(60, size=rng.integers(3, 7), replace=False)),), k)
                      for k in range(40))
        m = PolyMesh(V, faces)
        for tol in (0.005, 0.05, 0.3):
            got, want = split_t_junctions(m, tol), _reference(m, tol)
            assert (got is m) == (want is m) and got.faces == want.faces


def test_real_lod22_buildings_agree_with_every_edge_tested():
    from lod2energy.io import read
    path = shared_path("3dbag/tile5908_subset_ext.city.jsonl")
    _, feats = read(str(path))
    n = 0
    for b in feats:
        for _, _, g in targets(b, None):
            m = snap_vertices(mesh_of_geometry(b.vertices, g), DEFAULT.snap_tol)
            got, want = split_t_junctions(m, DEFAULT.tjunction_tol, DEFAULT.snap_tol), \
                _reference(m, DEFAULT.tjunction_tol, DEFAULT.snap_tol)
            assert (got is m) == (want is m) and got.faces == want.faces
            n += 1
        if n >= 60:
            break
    assert n >= 60


def test_the_input_is_cleaned_once_for_the_ladder_and_the_fidelity_envelope(monkeypatch):
    # internal_wall: non-manifold input, repaired by refill or a global stage, then measured
    # against its envelope (the ladder's hole-filled input): one clean-up of the input, not two
    from lod2energy import cache
    from test_repair import internal_wall
    b = internal_wall()
    m = mesh_of_geometry(b.vertices, b.objects[0].geometries[0])
    cleaned, closed = [], []
    real_cleanup, real_close = pipeline.cleanup, pipeline.close

    def counting_cleanup(x, tol):
        cleaned.append(np.array_equal(x.vertices, m.vertices) and x.faces == m.faces)
        return real_cleanup(x, tol)

    def counting_close(x, tol):
        closed.append(x)
        return real_close(x, tol)
    counting_cleanup.__name__, counting_close.__name__ = "cleanup", "close"
    monkeypatch.setattr(pipeline, "cleanup", counting_cleanup)
    monkeypatch.setattr(pipeline, "close", counting_close)
    cache.clear("repair.ladder-steps")
    r = pipeline.repair_building(b, timeout=600).provenance["repair"]
    assert r["geometries"][0]["stage"] in ("refill", "alphashape") and r["geometries"][0]["iou"] is not None
    assert cleaned.count(True) == 1
    m1 = orient(real_cleanup(m, DEFAULT))  # the ladder's oriented clean-up: filled once, reused
    assert sum(np.array_equal(x.vertices, m1.vertices) and x.faces == m1.faces for x in closed) == 1
