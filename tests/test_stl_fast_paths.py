"""The STL writer's fast paths give what the code they replace gave.

:func:`exporters.stl.rows.unique_rows` against ``np.unique(axis=0)`` on random index arrays;
the one-pass cap test of :func:`exporters.stl.writer._zone_mesh` against :func:`exporters.stl.writer.flip_caps`
face by face (the replaced loop), on random faces with caps and on zones of a real building.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from lod2energy.exporters.stl import writer as stl
from lod2energy.exporters.stl.rows import row_keys, same_position, unique_rows
from lod2energy.energy.zones.shells import local_origin, zone_shells
from factories import box, building_from_polygons, gabled_house


@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("m", [2, 3])
def test_unique_rows_as_numpy(seed, m):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 60))
    a = rng.integers(0, n, size=(int(rng.integers(1, 200)), m)).astype(np.intp)
    ref_u, ref_inv, ref_cnt = np.unique(a, axis=0, return_inverse=True, return_counts=True)
    u, inv, cnt = unique_rows(a, return_inverse=True, return_counts=True)
    assert np.array_equal(u, ref_u)
    assert np.array_equal(inv, ref_inv.ravel())
    assert np.array_equal(cnt, ref_cnt)
    u2, cnt2 = unique_rows(a, return_counts=True)
    assert np.array_equal(u2, ref_u) and np.array_equal(cnt2, ref_cnt)
    assert np.array_equal(unique_rows(a), ref_u)


def test_unique_rows_falls_back():
    a = np.array([[3, -1], [3, -1], [0, 2]])
    assert row_keys(a) is None  # a negative entry: numpy decides
    u, inv, cnt = unique_rows(a, return_inverse=True, return_counts=True)
    assert u.tolist() == [[0, 2], [3, -1]] and inv.tolist() == [1, 1, 0] and cnt.tolist() == [1, 2]
    big = np.array([[2 ** 40, 1, 0], [0, 1, 2 ** 40]])
    assert row_keys(big) is None  # keys beyond int64
    assert unique_rows(big).tolist() == np.unique(big, axis=0).tolist()
    keys = row_keys(np.array([[0, 5], [1, 0], [0, 6]]))
    assert keys.tolist() == sorted(keys.tolist(), key=lambda k: keys.tolist().index(k)) and keys[0] < keys[2] < keys[1]


def _face_with_cap(rng):
    """A fan of triangles of a random convex-ish polygon, some with a corner on an edge (a cap)."""
    k = int(rng.integers(3, 8))
    ang = np.sort(rng.uniform(0, 2 * np.pi, k))
    ring = np.c_[np.cos(ang), np.sin(ang), np.zeros(k)] * rng.uniform(1, 20)
    pts = [p for p in ring]
    tris = [(0, i, i + 1) for i in range(1, k - 1)]
    if rng.random() < 0.6:  # a point on the edge 0-1, and the cap (0, 1, mid) with its neighbour
        mid = (ring[0] + ring[1]) / 2 + rng.normal(0, 1e-9, 3) * rng.integers(0, 2)
        pts.append(mid)
        tris.append((1, 0, len(pts) - 1))
    return np.array(pts), np.array(tris, dtype=np.intp)


@pytest.mark.parametrize("seed", range(30))
def test_one_pass_caps_as_flip_caps(seed):
    rng = np.random.default_rng(seed)
    faces, verts, k = [], [], 0
    for _ in range(int(rng.integers(1, 6))):
        p, t = _face_with_cap(rng)
        verts.append(p)
        faces.append(t + k)
        k += len(p)
    v = np.concatenate(verts)
    flags = stl._faces_with_caps(v, faces)
    for t, has in zip(faces, flags):
        ref, _ = stl.flip_caps(v, t, np.zeros(len(t), dtype=np.intp))
        caps, _ = stl._caps(v, t)
        assert has == bool(caps.any())
        if not has:  # what _zone_mesh uses instead of flip_caps
            assert np.array_equal(ref, np.array(t, dtype=np.intp).reshape(-1, 3))


def _old_zone_mesh(z):
    """:func:`stl._zone_mesh` as it was: flip_caps on every face."""
    z = stl.split_t_junctions(z)
    tris, codes = [], []
    for f in z.faces:
        t = z.face_triangles(f)
        if len(t):
            t, _ = stl.flip_caps(z.vertices, t, np.zeros(len(t), dtype=np.intp))
            tris.append(t)
            codes.append(np.full(len(t), stl.PATCHES.index(f.kind), dtype=np.intp))
    if not tris:
        return z.vertices, np.zeros((0, 3), dtype=np.intp), np.zeros(0, dtype=np.intp)
    tris, codes = np.concatenate(tris), np.concatenate(codes)
    tris, codes = stl.cancel_fins(tris, codes)
    tris, codes = stl.flip_caps(z.vertices, tris, codes)
    tris, codes = stl.split_open_edges(z.vertices, tris, codes)
    return z.vertices, tris, codes


@pytest.mark.parametrize("make", [lambda: box(), lambda: gabled_house(), lambda: _box_with_collinear_points()])
def test_zone_mesh_as_before(make):
    """Whole zones: the same vertices, triangles and codes as the loop with flip_caps on every face."""
    b = make()
    zs = zone_shells(b, local_origin([b]), weld_tol=stl.ZONE_WELD_TOL)
    assert zs
    for z in zs:
        new, old = stl._zone_mesh(z), _old_zone_mesh(z)
        for a, r in zip(new, old):
            assert a.dtype == r.dtype and np.array_equal(a, r)


def test_random_faces_have_caps():
    """The random faces above do have caps (the one-pass test has something to find)."""
    rng = np.random.default_rng(0)
    found = 0
    for _ in range(20):
        p, t = _face_with_cap(rng)
        found += any(stl._faces_with_caps(p, [t]))
    assert found >= 5


def _box_with_collinear_points():
    """A box whose south wall, ground and roof carry extra points along their edges."""
    p = np.array([[0, 0, 0], [10, 0, 0], [10, 6, 0], [0, 6, 0], [0, 0, 4], [10, 0, 4], [10, 6, 4], [0, 6, 4],
                  [5, 0, 0], [5, 0, 4], [2.5, 0, 0], [7.5, 0, 4]], dtype=float)
    faces = [[0, 3, 2, 1, 8, 10], [4, 9, 11, 5, 6, 7], [0, 10, 8, 1, 5, 11, 9, 4], [1, 2, 6, 5], [2, 3, 7, 6],
             [3, 0, 4, 7]]
    sem = ["GroundSurface", "RoofSurface", "WallSurface", "WallSurface", "WallSurface", "WallSurface"]
    return building_from_polygons([[p[f]] for f in faces], "Solid", sem, id="collinear")


def _classes(inv):
    """The partition an inverse makes (frozensets of row indices)."""
    groups: dict = {}
    for i, g in enumerate(np.asarray(inv).ravel().tolist()):
        groups.setdefault(g, set()).add(i)
    return {frozenset(s) for s in groups.values()}


@pytest.mark.parametrize("seed", range(25))
def test_same_position_groups_as_numpy(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 80))
    p = rng.choice([-1.0, -0.0, 0.0, 0.5, 2.0, 1e-7], size=(n, 3)).astype(np.float32)
    if seed % 5 == 0:
        p[rng.integers(n)] = np.nan
    _, ref = np.unique(p, axis=0, return_inverse=True)
    inv = same_position(p)
    assert _classes(inv) == _classes(ref)
    if not np.isnan(p).any():  # the same numbers, too (both sort the rows lexicographically)
        assert np.array_equal(inv, ref.ravel())


def _old_closed_by_position(v, t):
    _, inv = np.unique(np.asarray(v, dtype=np.float32), axis=0, return_inverse=True)
    tt = inv.ravel()[t]
    e = np.concatenate([tt[:, [0, 1]], tt[:, [1, 2]], tt[:, [2, 0]]])
    if np.any(e[:, 0] == e[:, 1]):
        return False
    fwd = {tuple(x) for x in e.tolist()}
    return len(fwd) == len(e) and all((b, a) in fwd for a, b in fwd)


def _box_mesh():
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    t = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5],
                  [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]], dtype=np.intp)
    return v, t


@pytest.mark.parametrize("seed", range(40))
def test_closed_by_position_as_before(seed):
    rng = np.random.default_rng(seed)
    v, t = _box_mesh()
    k = seed % 8
    if k == 1:
        t = t[1:]  # open
    elif k == 2:
        t[3] = t[3][::-1]  # one flipped
    elif k == 3:
        v = np.concatenate([v, v[:1]])  # a duplicate vertex (same position): the closedness is by position
        t[t == 0] = np.where(rng.random((t == 0).sum()) < 0.5, 0, 8)
    elif k == 4:
        t = np.concatenate([t, t[:2]])  # a repeated triangle
    elif k == 5:
        v = v + rng.normal(0, 1e-9, v.shape)  # below float32's resolution at 1 m: same positions
    elif k == 6:
        t[0, 1] = t[0, 0]  # a collapsed triangle
    elif k == 7:
        t = np.zeros((0, 3), dtype=np.intp)
    assert stl._closed_by_position(v, t) == _old_closed_by_position(v, t)


def test_closed_by_position_sees_both_verdicts():
    v, t = _box_mesh()
    assert stl._closed_by_position(v, t) and not stl._closed_by_position(v, t[1:])


def _old_same32(v):
    _, inv, cnt = np.unique(np.asarray(v, dtype=np.float32), axis=0, return_inverse=True, return_counts=True)
    return np.nonzero(cnt[inv.ravel()] > 1)[0]


@pytest.mark.parametrize("shift", [(1.0, 1.0, 0.0), (1.0, 0.0, 0.0), (1.0 + 1e-9, 1.0, 0.0), (3.0, 0.0, 0.0)])
def test_separate_touching_as_before(shift):
    """Two boxes touching along an edge / a face / not at all: the same vertices moved."""
    v, t = _box_mesh()
    v2 = np.concatenate([v, v + np.array(shift)])
    t2 = np.concatenate([t, t + len(v)])
    new, moved = stl.separate_touching(v2, t2)
    inv = same_position(np.asarray(v2, dtype=np.float32))
    assert np.array_equal(np.nonzero(np.bincount(inv)[inv] > 1)[0], _old_same32(v2))
    pairs = cKDTree(v2).query_pairs(1e-6, output_type="ndarray")
    assert moved == len(np.union1d(np.unique(pairs.ravel()), _old_same32(v2)))
    assert (moved > 0) == (shift[0] < 2)
