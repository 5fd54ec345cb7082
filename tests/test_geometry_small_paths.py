"""The small-array fast paths of the shared geometry give the same bits as the numpy code they replace.

References below are the replaced implementations, kept verbatim: numpy's summation order
(pairwise, starting from 0.0) and its element-wise IEEE operations are what the Python-float
paths reproduce, so any drift in a last bit (or a signed zero) fails here.
"""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.geometry import polygons
from lod2energy.energy.zones import cut as zoning
from lod2energy.geometry import earcut_rings, vectors


def _same(a, b) -> bool:
    """Bit-identical arrays (signed zeros and NaNs included)."""
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


def _rings(rng, count=3000):
    """Small rings as buildings have them: random, on national-grid offsets, axis-aligned
    walls and flat roofs (exact and signed zeros), rounded to mm, degenerate."""
    out = []
    for i in range(count):
        k = int(rng.integers(3, 12))
        p = rng.normal(size=(k, 3)) * rng.choice([1e-3, 1.0, 20.0])
        if i % 3 == 0:
            p += np.array([85000.0, 447000.0, 3.0])
        if i % 5 == 0:
            p[:, int(rng.integers(0, 3))] = rng.choice([0.0, -0.0, 7.25])
        if i % 7 == 0:
            p = np.round(p, 3)
        if i % 13 == 0:
            p[1] = p[0]  # repeated vertex
        out.append(p)
    out += [np.zeros((4, 3)), -np.zeros((3, 3)), np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0]]),
            np.array([[0.0, 0, 0], [1, 0, np.nan], [2, 1, 0]]), np.array([[0.0, 0, 0], [1, 0, np.inf], [2, 1, 0]])]
    return out


@pytest.mark.parametrize("centred", [True, False])
def test_newell_small_is_numpy(centred):
    rng = np.random.default_rng(8)
    with np.errstate(invalid="ignore"):
        for p in _rings(rng):
            got = vectors.newell_normal(p, centred)
            assert _same(got, vectors._newell_numpy(p, centred)), p
        # Fortran-ordered and strided views (the old code on the same view is the reference)
        for p in _rings(rng, 300):
            w = np.zeros((len(p), 6))
            w[:, ::2] = p
            for q in (np.asfortranarray(p), w[:, ::2]):
                assert _same(vectors.newell_normal(q, centred), vectors._newell_numpy(q, centred))


def test_newell_small_on_real_buildings(denhaag_path):
    from itertools import islice

    from lod2energy.io import read

    _, feats = read(str(denhaag_path))
    n = 0
    for b in islice(feats, 60):
        for o in b.objects:
            for g in o.geometries:
                if not g.is_polygonal:
                    continue
                for _, _, sh in g.iter_shells():
                    for s in sh.surfaces:
                        for r in s.rings:
                            p = b.vertices[list(r)]
                            for q in (p, p - np.floor(p.min(axis=0))):  # map and local frames
                                for centred in (True, False):
                                    assert _same(vectors.newell_normal(q, centred),
                                                 vectors._newell_numpy(q, centred))
                            n += 1
    assert n > 1000


def _ref_triangulate(points, ring_ends, normal=None):
    p = np.asarray(points, dtype=np.float64)
    if normal is None:
        normal = vectors._newell_numpy(p[: ring_ends[0]], False)
    n = polygons.unit(normal)
    if not n.any():
        return np.zeros((0, 3), dtype=np.intp)
    u, v = polygons.wall_basis(n)
    c = np.add.reduce(p, axis=0) / len(p)
    xy = np.column_stack([(p - c) @ u, (p - c) @ v])
    tri = earcut_rings(xy, ring_ends)
    if len(tri) == 0:
        return tri
    a, b, cc = xy[tri[:, 0]], xy[tri[:, 1]], xy[tri[:, 2]]
    cross = (b[:, 0] - a[:, 0]) * (cc[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (cc[:, 0] - a[:, 0])
    flip = cross < 0
    tri[flip] = tri[flip][:, ::-1]
    used = np.zeros(len(p), dtype=bool)
    used[tri.ravel()] = True
    missing = np.flatnonzero(~used)
    if len(missing):
        tri = polygons._insert_dropped(tri, xy, missing)
    return tri


def test_triangulate_same_triangles():
    rng = np.random.default_rng(5)
    flipped = dropped = 0
    for i, p in enumerate(_rings(rng, 1500)):
        ends = [len(p)]
        if i % 4 == 0 and len(p) >= 3:  # a hole
            c = p.mean(axis=0)
            p = np.concatenate([p, (p[:3] - c) * 0.2 + c])
            ends.append(len(p))
        if i % 6 == 0:  # collinear vertices earcut drops
            p = np.concatenate([p[:1], (p[:1] + p[1:2]) / 2, p[1:]])
            ends = [e + 1 for e in ends]
        with np.errstate(invalid="ignore", divide="ignore"):
            got, ref = polygons.triangulate(p, ends), _ref_triangulate(p, ends)
            given = polygons.triangulate(p, ends, -polygons.newell_normal(p[: ends[0]]))
            ref_given = _ref_triangulate(p, ends, -vectors._newell_numpy(p[: ends[0]], False))
        assert _same(got, ref) and _same(given, ref_given), i
        flipped += len(got) and not _same(given[:, ::-1], got)
        dropped += i % 6 == 0 and len(got) > 0 and set(got.ravel().tolist()) == set(range(len(p)))
    assert flipped > 100 and dropped > 10  # both orientations and put-back vertices were exercised


from _zoning_reference import clip_before_fast_path as _ref_clip  # noqa: E402


def test_clip_same_polygons():
    rng = np.random.default_rng(11)
    cut = 0
    for i, p in enumerate(_rings(rng, 1500)):
        p = np.round(p, 4) if i % 2 else p
        z = p[:, 2][np.isfinite(p[:, 2])]
        for c in (float(np.median(z)) if len(z) else 0.0, float(p[0, 2]), 0.123456789, float(z.min()) - 1 if len(z) else -1):
            for above in (True, False):
                with np.errstate(invalid="ignore"):
                    got, ref = zoning._clip(p, c, above), _ref_clip(p, c, above)
                assert _same(got, ref), (i, c, above)
                cut += 0 < len(got) != len(p)
    assert cut > 500


def test_newell_cache_returns_fresh_arrays():
    p = np.array([[0.0, 0, 0], [2, 0, 0], [2, 3, 0], [0, 3, 0]])
    first = vectors.newell_normal(p, False)
    first *= 0.0  # a caller scaling its result in place must not change the next answer
    again = vectors.newell_normal(p.copy(), False)
    assert _same(again, np.array([0.0, 0.0, 12.0])) and again is not vectors.newell_normal(p, False)
    assert _same(vectors.newell_normal(p, True), vectors._newell_numpy(p, True))


def _ref_is_convex_2d(xy, eps=1e-9, strict=False):
    d1 = np.roll(xy, -1, axis=0) - xy
    d2 = np.roll(d1, -1, axis=0)
    cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    scale = np.maximum(np.linalg.norm(d1, axis=1) * np.linalg.norm(d2, axis=1), 1e-12)
    if strict:
        return bool(np.all(cross >= polygons.STRICT_SIN * scale))
    return bool(np.all(cross >= -eps * scale))


def test_is_convex_2d_same_answers():
    rng = np.random.default_rng(2)
    answers = set()
    for i in range(3000):
        k = int(rng.integers(0, 9))
        ang = np.sort(rng.random(k)) * 2 * np.pi
        xy = np.column_stack([np.cos(ang), np.sin(ang)]) * rng.choice([1e-7, 1.0, 30.0])
        if i % 3 == 0 and k:
            xy[int(rng.integers(0, k))] *= rng.choice([0.2, 0.999999, 1.5])  # reflex or nearly straight
        if i % 5 == 0 and k > 1:
            xy[1] = xy[0]  # zero-length edge
        if i % 7 == 0 and k > 2:
            xy[2] = (xy[1] + xy[3 % k]) / 2  # collinear
        if i % 11 == 0:
            xy = xy[::-1]  # clockwise
        if i % 97 == 0 and k:
            xy[0, 0] = np.nan
        for strict in (False, True):
            with np.errstate(invalid="ignore"):
                got, ref = polygons.is_convex_2d(xy, strict=strict), _ref_is_convex_2d(xy, strict=strict)
            assert got == ref, (i, strict)
            answers.add(got)
    assert answers == {True, False}


def test_cross_rows_unit_rows_and_plane_basis_same_bits():
    rng = np.random.default_rng(3)
    for shape in ((3,), (1, 3), (7, 3), (4, 5, 3)):
        a, b = rng.normal(size=shape) * 1e3, rng.normal(size=shape)
        a[..., 0] = -0.0
        assert _same(vectors.cross_rows(a, b), np.stack(
            [a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1], a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
             a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]], axis=-1))
        assert _same(vectors.cross_rows(a, b), np.cross(a, b))
        v = np.concatenate([a.reshape(-1, 3), np.zeros((2, 3))])
        u, ln = vectors.unit_rows(v)
        ref_ln = np.linalg.norm(v, axis=-1, keepdims=True)
        assert _same(ln, ref_ln[..., 0])
        assert _same(u, np.divide(v, ref_ln, out=np.zeros_like(v), where=ref_ln > 0))
    assert _same(vectors.cross_rows(np.array([1, 2, 3]), np.array([4, 5, 6])), np.cross([1, 2, 3], [4, 5, 6]))

    def ref_basis(normal):
        n = polygons.unit(np.asarray(normal, dtype=np.float64))
        u = np.cross(np.array([0.0, 0.0, 1.0]), n)
        if np.linalg.norm(u) < 1e-6:
            u = np.array([1.0, 0.0, 0.0]) - n[0] * n
        u = polygons.unit(u)
        return u, np.cross(n, u)

    normals = [rng.normal(size=3) * s for s in (1e-9, 1.0, 1e4) for _ in range(500)]
    normals += [np.array(v, dtype=np.float64) for v in ([0, 0, 1], [0, 0, -1], [1e-8, 0, 1], [0, 0, 0], [1, 0, 0])]
    for n in normals:
        with np.errstate(invalid="ignore"):
            got, ref = polygons.wall_basis(n), ref_basis(n)
        assert _same(got[0], ref[0]) and _same(got[1], ref[1]), n


def test_zoning_measures_same_bits():
    rng = np.random.default_rng(12)
    rings = [p for p in _rings(rng, 1500) if np.isfinite(p).all()]
    for p in rings:
        ref = np.cross(p - p[0], np.roll(p, -1, axis=0) - p[0]).sum(axis=0)
        assert _same(zoning._cross_sum(p), ref)
        assert zoning._area(p) == 0.5 * float(np.linalg.norm(ref))
        x, y = p[:, 0], p[:, 1]
        ref_xy = 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
        assert zoning._signed_xy(p) == ref_xy and np.signbit(zoning._signed_xy(p)) == np.signbit(ref_xy)
    # zone_levels: the roof normals and areas it weighs the eave with
    walls = [(np.array([[0.0, 0, 0], [5, 0, 0], [5, 0, 3], [0, 0, 3]]), "wall")]
    for i in range(0, len(rings) - 3, 3):
        roofs = [(np.abs(q) + [0.0, 0.0, 3.0], "roof") for q in rings[i:i + 3]]
        got = zoning.zone_levels(walls + roofs)
        assert got == _ref_zone_levels(walls + roofs), i


def _ref_zone_levels(polygons):
    from lod2energy.thermal.storeys import FLAT_TILT

    allz = np.concatenate([p[:, 2] for p, _ in polygons])
    roofs = []
    for p, kind in polygons:
        if kind != "roof":
            continue
        n = np.cross(p - p[0], np.roll(p, -1, axis=0) - p[0]).sum(axis=0) / 2
        a = float(np.linalg.norm(n))
        if a <= 1e-9:
            continue
        nz = float(n[2]) / a
        roofs.append((float(p[:, 2].min()), float(p[:, 2].max()), a * max(nz, 0.0),
                      float(np.degrees(np.arccos(np.clip(nz, -1, 1))))))
    ground = float(allz.min())
    if not roofs:
        return ground, float(allz.max()), float(allz.max()), False
    r = np.array(roofs)
    order = np.argsort(r[:, 0])
    w = np.cumsum(r[order, 2])
    k = int(np.searchsorted(w, 0.5 * w[-1])) if w[-1] > 0 else 0
    eave = float(r[order[min(k, len(order) - 1)], 0])
    above = r[r[:, 1] > eave + 0.1]
    pitched = bool(len(above) and above[above[:, 3] >= FLAT_TILT, 2].sum() > 0.5 * above[:, 2].sum())
    return ground, max(eave, ground), float(allz.max()), pitched


def test_polymesh_face_area_same_value():
    from lod2energy.polymesh import Face, face_area

    rng = np.random.default_rng(21)
    for p in _rings(rng, 600):
        c = p.mean(axis=0)
        V = np.concatenate([p, (p[:3] - c) * 0.3 + c])
        for rings in ((tuple(range(len(p))),), (tuple(range(len(p))), tuple(range(len(p), len(V))))):
            f = Face(rings)
            ref = np.linalg.norm(vectors._newell_numpy(V[list(rings[0])], False)) / 2
            for r in rings[1:]:
                ref -= np.linalg.norm(vectors._newell_numpy(V[list(r)], False)) / 2
            with np.errstate(invalid="ignore"):
                got = face_area(V, f)
            assert _same(np.float64(got), np.float64(ref))


def test_triangulate_cache_returns_fresh_arrays():
    p = np.array([[0.0, 0, 0], [4, 0, 0], [4, 3, 0], [2, 5, 0], [0, 3, 0]])
    first = polygons.triangulate(p, [5])
    ref = first.copy()
    first[:] = 0  # a caller editing its triangles must not change the next answer
    assert _same(polygons.triangulate(p.copy(), (5,)), ref) and len(set(ref.ravel().tolist())) == 5
    assert _same(polygons.triangulate(p, np.array([5])), _ref_triangulate(p, [5]))
