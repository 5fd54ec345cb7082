"""The fast paths of the export hot loops give the same bits as the code they replace.

Each reference below is the implementation that was replaced (``np.roll``, ``np.cross``,
``np.linalg.norm``, ``np.setdiff1d``), kept here to compare against on random rings, on
rings with exact zeros, signed zeros and huge offsets, and on degenerate input.
"""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.geometry import polygons
from lod2energy.geometry import vectors


def _ref_newell(points, centred=True):
    p = np.asarray(points, dtype=np.float64)
    if len(p) < 3:
        return np.zeros(3)
    if not centred:
        q = np.roll(p, -1, axis=0)
        return np.array([
            np.sum((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])),
            np.sum((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])),
            np.sum((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])),
        ])
    p = p - p.mean(axis=0)
    return vectors.cross_rows(p, np.roll(p, -1, axis=0)).sum(axis=0)


def _ref_unit(v):
    n = float(np.linalg.norm(v))
    return v / n if n > 0 else v


def _ref_plane_basis(normal):
    n = _ref_unit(np.asarray(normal, dtype=np.float64))
    up = np.array([0.0, 0.0, 1.0])
    u = np.cross(up, n)
    if np.linalg.norm(u) < 1e-6:
        u = np.array([1.0, 0.0, 0.0]) - n[0] * n
    u = _ref_unit(u)
    v = np.cross(n, u)
    return u, v


def _same(a, b) -> bool:
    """Bit-identical arrays (signed zeros and NaNs included)."""
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


def _rings(rng, count=400):
    out = []
    for i in range(count):
        k = int(rng.integers(3, 300 if i % 10 == 0 else 12))
        p = rng.normal(size=(k, 3)) * rng.choice([1e-3, 1.0, 50.0])
        if i % 4 == 0:
            p += np.array([85000.0, 447000.0, 3.0])  # national-grid offsets
        if i % 5 == 0:
            p[:, int(rng.integers(0, 3))] = 0.0  # planar on a coordinate plane
        if i % 7 == 0:
            p[:, 2] = -0.0
        if i % 11 == 0:
            p = np.round(p, 2)
        out.append(p)
    out.append(np.zeros((3, 3)))
    out.append(np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0]]))  # collinear
    out.append(np.array([[0.0, 0, 0], [1, 0, 0]]))  # too short
    return out


@pytest.mark.parametrize("centred", [True, False])
def test_newell_normal_same_bits(centred):
    rng = np.random.default_rng(13)
    # long rings too: numpy sums 8 or more terms pairwise, so a changed summation order shows
    long = [rng.normal(size=(int(k), 3)) * 30 + 1000 for k in rng.integers(9, 400, 150)]
    for p in _rings(rng) + long:
        assert _same(vectors.newell_normal(p, centred), _ref_newell(p, centred)), len(p)
    assert _same(polygons.newell_normal(p), _ref_newell(p, False))


def test_roll_next_is_roll():
    rng = np.random.default_rng(1)
    for k in (0, 1, 2, 5, 40):
        a = rng.normal(size=(k, 3))
        assert _same(vectors.roll_next(a), np.roll(a, -1, axis=0))
        b = rng.normal(size=(k, 2))
        assert _same(vectors.roll_next(b), np.roll(b, -1, axis=0))


def test_unit_and_plane_basis_same_bits():
    rng = np.random.default_rng(7)
    normals = [rng.normal(size=3) * s for s in (1e-9, 1e-3, 1.0, 1e4) for _ in range(300)]
    normals += [np.array(v, dtype=np.float64) for v in (
        [0, 0, 1], [0, 0, -1], [0, 1e-9, 1], [1e-7, 0, -1], [1, 0, 0], [0, -1, 0], [0, 0, 0],
        [-0.0, 0.0, 1.0], [0.0, -0.0, -1.0], [3, 4, 0], [np.nan, 0, 1], [np.inf, 0, 0])]
    for n in normals:
        with np.errstate(invalid="ignore"):
            assert _same(polygons.unit(n), _ref_unit(n))
            u, v = polygons.wall_basis(n)
            ru, rv = _ref_plane_basis(n)
        assert _same(u, ru) and _same(v, rv), n
    # lists and integer arrays still go through np.linalg.norm
    assert _same(polygons.unit(np.array([3, 4])), _ref_unit(np.array([3, 4])))


def test_triangulate_keeps_dropped_vertices():
    """The collinear vertices earcut skips are still put back (the set difference changed)."""
    ring = np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]])
    tri = polygons.triangulate(ring, [len(ring)])
    assert set(tri.ravel()) == set(range(len(ring)))
    assert len(tri) == 3


def _ref_eplus_collinear(points):
    """lod2energy.energy.enclosure.eplus_collinear before it was batched (np.roll per ring)."""
    from lod2energy.energy.enclosure import PLANE_DET, PROJECTED_EPS, TURN_THRESHOLD
    q = np.asarray(points, dtype=np.float64)
    k = len(q)
    if k < 3:
        return []
    for i, j in ((0, 1), (0, 2), (1, 2)):
        A, B = q[:, i], q[:, j]
        if abs(float(np.sum(A * np.roll(B, -1) - np.roll(A, -1) * B))) > PLANE_DET:
            break
    p0, p2 = np.roll(np.arange(k), 1), np.roll(np.arange(k), -1)
    ua, ub = A - A[p0], B - B[p0]
    va, vb = A[p2] - A, B[p2] - B
    turn = np.arctan2(ua * vb - ub * va, ua * va + ub * vb)
    seen = (np.hypot(ua, ub) > PROJECTED_EPS) & (np.hypot(va, vb) > PROJECTED_EPS)
    return [int(i) for i in np.nonzero(seen & (np.abs(np.sin(turn)) < TURN_THRESHOLD))[0]]


def test_batched_collinear_test_is_the_single_one():
    """Batched over many rings, EnergyPlus's collinear test finds what it finds on each ring
    alone: rings with collinear runs, spikes, vertical walls (XY projection degenerate) and
    projected areas at the plane threshold."""
    from lod2energy.energy import enclosure as ee
    rng = np.random.default_rng(3)
    rings = []
    for i in range(300):
        k = int(rng.integers(0, 40 if i % 9 == 0 else 9))
        p = rng.normal(size=(k, 3)) * 5
        if i % 3 == 0 and k >= 3:  # a collinear point between two others
            p[1] = 0.5 * (p[0] + p[2])
        if i % 4 == 0:
            p[:, 0] = 1.0  # vertical: XY area 0, XZ area 0, YZ plane
        if i % 5 == 0 and k >= 4:
            p[3] = p[1]  # spike
        if i % 7 == 0:
            p *= 1e-2 * rng.random()  # around PLANE_DET
        rings.append(p)
    rings += [r for r in _rings(rng, 60)]
    got = ee.eplus_collinear(rings)
    assert got == [_ref_eplus_collinear(r) for r in rings]
    assert any(got) and not all(got)


# ---------------------------------------------------------------- ring centroids, piece volumes, corners

def _ref_ring_centroid(p, n_hat):
    if len(p) < 3:
        return 0.0, p.mean(axis=0) if len(p) else np.zeros(3)
    a, b, c = p[0], p[1:-1], p[2:]
    w = 0.5 * np.cross(b - a, c - a) @ n_hat
    tot = w.sum()
    cent = (a + b + c) / 3.0
    if abs(tot) < 1e-15:
        return 0.0, p.mean(axis=0)
    return float(tot), (w[:, None] * cent).sum(axis=0) / tot


def test_cross_rows_and_ring_centroid_same_bits():
    from lod2energy import semantics

    rng = np.random.default_rng(22)
    for p in _rings(rng):
        if len(p) >= 3:
            d1, d2 = p[1:-1] - p[0], p[2:] - p[0]
            assert _same(vectors.cross_rows(d1, d2), np.cross(d1, d2)), len(p)
        n = vectors.newell_normal(p)
        ln = float(np.linalg.norm(n))
        n_hat = n / ln if ln > 0 else np.array([0.0, 0.0, 1.0])
        p0 = p - p[0] if len(p) else p
        got, ref = semantics._ring_centroid(p0, n_hat), _ref_ring_centroid(p0, n_hat)
        assert got[0] == ref[0] and np.signbit(got[0]) == np.signbit(ref[0]), len(p)
        assert _same(got[1], ref[1]), len(p)


def _ref_pieces_volume(pieces):
    vol = 0.0
    for p in pieces:
        q = p.points
        for k in range(1, len(q) - 1):
            vol += float(np.dot(q[0], np.cross(q[k], q[k + 1]))) / 6.0
    return vol


def test_pieces_volume_same_bits():
    from lod2energy.energy.pieces import Piece, _pieces_volume

    rng = np.random.default_rng(5)
    rings = _rings(rng)
    for i in range(0, len(rings), 7):
        pieces = [Piece(q, "wall", "Outdoors", 1.0, k) for k, q in enumerate(rings[i:i + 7])]
        got, ref = _pieces_volume(pieces), _ref_pieces_volume(pieces)
        assert got == ref and np.signbit(got) == np.signbit(ref), i
    ints = [Piece(np.array([[0, 0, 0], [4, 0, 0], [4, 3, 0], [0, 3, 1]]), "roof", "Outdoors", 1.0, 0)]
    assert _pieces_volume(ints) == _ref_pieces_volume(ints)


def _ref_upper_left_first(points):
    n = polygons.unit(polygons.newell_normal(points))
    up = np.array([0.0, 0.0, 1.0]) - n[2] * n
    if np.linalg.norm(up) < 1e-6:
        up = np.array([0.0, 1.0, 0.0]) - n[1] * n
    up = polygons.unit(up)
    right = np.cross(up, n)
    h = points @ up
    cand = np.nonzero(h >= h.max() - 1e-3)[0]
    start = int(cand[np.argmin(points[cand] @ right)])
    return np.roll(points, -start, axis=0)


def test_upper_left_first_and_vertex_lines_same_as_before():
    from lod2energy.exporters.energyplus import render

    rng = np.random.default_rng(9)
    rings = _rings(rng)[:-1]  # the 2-vertex ring has no plane
    rings += [np.array([[0.0, 0, 3], [0, 5, 3], [4, 5, 3], [4, 0, 3]]),  # horizontal: "up" is +y
              np.array([[0.0, 0, 0], [4, 0, 0], [4, 0, 3], [0, 0, 3]]),  # a wall
              np.round(rng.normal(size=(6, 3)), 1)]  # ties in height and "right"
    for p in rings:
        with np.errstate(invalid="ignore", divide="ignore"):
            got = render.upper_left_first(p)
            ref = _ref_upper_left_first(p)
            fallback = render._upper_left_first_ref(p, polygons.unit(polygons.newell_normal(p)))
        assert _same(got, ref) and _same(fallback, ref), len(p)
        old = [f"{render._fmt(q[0])}, {render._fmt(q[1])}, {render._fmt(q[2])}" for q in got]
        assert render._vertex_lines(got) == old


def _ref_keep_corners(pieces, tol=1e-3):
    from dataclasses import replace

    from lod2energy.energy.conform import PIECE_PLANAR
    from lod2energy.energy.enclosure import eplus_collinear, eplus_degenerate, _on_line
    from lod2energy.energy.pieces import WRITE_DECIMALS
    from lod2energy.energy.pieces import _planar_dev

    out = []
    for p in pieces:
        q = p.points
        lost = [i for i in eplus_collinear([q])[0] if not _on_line(q[i - 1], q[(i + 1) % len(q)], q[i], tol)]
        if not lost and not eplus_degenerate([q])[0] and (len(q) == 3 or _planar_dev(q) <= PIECE_PLANAR):
            out.append(p)
            continue
        c = np.round(q.mean(axis=0), WRITE_DECIMALS)
        for i in range(len(q)):
            tri = np.array([c, q[i], q[(i + 1) % len(q)]])
            if polygon_area(tri) > 1e-9 and not eplus_degenerate([tri])[0]:
                out.append(replace(p, points=tri))
    return out


def polygon_area(p):
    return polygons.polygon_area3d(p)


def _wall_pieces(rng, count=150):
    """Wall-like pieces: off-vertical walls with stepped bottoms (EnergyPlus drops corners),
    near-coincident vertices, out-of-plane ones, slivers, as the writer rounds them."""
    out = []
    for i in range(count):
        k = int(rng.integers(3, 9))
        x = np.sort(rng.random(k)) * rng.choice([0.02, 1.0, 8.0])
        z = rng.random(k) * rng.choice([1e-4, 0.01, 3.0])
        lean = rng.choice([0.0, 1e-4, 0.01])
        p = np.column_stack([x, lean * z + rng.normal(size=k) * rng.choice([0.0, 1e-3, 0.02]), z])
        if i % 3 == 0:
            p = np.concatenate([p, p[::-1] + [0.0, 0.0, 2.5]])  # a closed-ish wall outline
        if i % 4 == 0:
            p += [85000.0, 447000.0, 0.0]
        out.append(np.round(p, 4))
    return out


def test_keep_corners_batched_same_pieces():
    from lod2energy.energy.conform import keep_corners
    from lod2energy.energy.pieces import Piece

    rng = np.random.default_rng(31)
    rings = _wall_pieces(rng) + [q for q in _rings(rng, 120) if len(q) >= 3]
    pieces = [Piece(q, "wall", "Outdoors", 1.0, k) for k, q in enumerate(rings)]
    with np.errstate(invalid="ignore", divide="ignore"):
        got, ref = keep_corners(pieces), _ref_keep_corners(pieces)
    assert len(got) == len(ref) and len(ref) > len(pieces)  # some pieces were fanned
    for a, b in zip(got, ref):
        assert _same(a.points, b.points) and a.face_index == b.face_index


def test_window_for_same_with_vectorised_box():

    from lod2energy.energy.openings import window_for

    from _window_reference import bisection_window as ref

    rng = np.random.default_rng(4)
    for i in range(60):
        w, h = rng.random(2) * 10 + 0.1
        top = h * (1 + rng.random() * (i % 2))  # rectangles and trapezoids (gables)
        p = np.array([[0.0, 0, 0], [w, 0, 0], [w, 0, h], [0, 0, top]])
        ang = rng.random() * 6.28
        rot = np.array([[np.cos(ang), -np.sin(ang), 0], [np.sin(ang), np.cos(ang), 0], [0, 0, 1]])
        p = np.round(p @ rot.T + [85000.0, 447000.0, 1.0], 4)
        for wwr in (0.2, 0.6):
            got, exp = window_for(p, wwr), ref(p, wwr)
            assert (got is None and exp is None) or _same(got, exp), i


def test_face_metrics_same_bits():
    from lod2energy import semantics
    from lod2energy.geometry import newell_normal
    from lod2energy.model import Surface

    def ref(vertices, surface):
        outer = vertices[surface.outer]
        origin = outer.mean(axis=0) if len(outer) else np.zeros(3)
        outer = outer - origin
        vec = 0.5 * newell_normal(vertices[surface.outer]) if len(outer) >= 3 else np.zeros(3)
        norm = float(np.linalg.norm(vec))
        if norm < 1e-15:
            return 0.0, np.zeros(3), origin
        n_hat = vec / norm
        a0, c0 = _ref_ring_centroid(outer, n_hat)
        area, moment = abs(a0), abs(a0) * c0
        for r in surface.inners:
            ai, ci = _ref_ring_centroid(vertices[r] - origin, n_hat)
            area -= abs(ai)
            moment = moment - abs(ai) * ci
        if area <= 1e-15:
            return 0.0, n_hat, origin + c0
        return float(area), n_hat, origin + moment / area

    rng = np.random.default_rng(17)
    for p in _rings(rng, 200):
        k = len(p)
        hole = (p[: min(k, 4)] - p.mean(axis=0)) * 0.3 + p.mean(axis=0)
        verts = np.concatenate([p, hole])
        for rings in ([list(range(k))], [list(range(k)), list(range(k, len(verts)))]):
            s = Surface.from_lists(rings)
            got, exp = semantics.face_metrics(verts, s), ref(verts, s)
            assert got[0] == exp[0] and _same(got[1], exp[1]) and _same(got[2], exp[2]), k
