"""The IDF writer's zone pieces skip work that cannot change them:

- :func:`conform.keep_corners` of its own output is that output (so :func:`surfaces.zone_pieces`
  runs it once when the enclosure test passes the pieces as they are);
- :func:`enclosure.enclosure_defects` remembers its verdicts by the exact bits of its input:
  a remembered verdict is the computed one.
"""
from __future__ import annotations

import numpy as np

from lod2energy import cache
from lod2energy.energy import enclosure
from lod2energy.energy.conform import keep_corners
from lod2energy.energy.pieces import Piece, _as_written


def _rings(rng, n=400):
    """Rings keep_corners keeps and rings it fans: planar and bent, with corners EnergyPlus
    finds collinear in its projection, spikes, near-coincident and repeated vertices."""
    out = []
    for i in range(n):
        k = 3 + i % 7
        ang = np.sort(rng.random(k)) * 2 * np.pi
        r = 0.05 + rng.random(k) * 6
        q = np.column_stack([r * np.cos(ang), r * np.sin(ang), np.zeros(k)])
        tilt = rng.random()
        if i % 5 == 0:  # a wall a fraction of a degree off vertical
            q = np.column_stack([q[:, 0], q[:, 2] + q[:, 1] * 1e-3, q[:, 1]])
        elif i % 5 == 1:
            q[:, 2] = q[:, 0] * tilt
        if i % 4 == 0:
            q[:, 2] += rng.normal(0, [0.0, 1e-3, 2e-2][i % 3], k)  # out of plane
        if i % 6 == 0:  # a vertex on the middle of an edge (collinear in 3D)
            q = np.insert(q, 1, (q[0] + q[1]) / 2, axis=0)
        if i % 7 == 0:  # a corner 1e-4 off the line through its neighbours
            m = (q[0] + q[1]) / 2 + [0, 0, 5e-3 * (i % 2)]
            q = np.insert(q, 1, m, axis=0)
        if i % 9 == 0:
            q = np.insert(q, 2, q[2] + 1e-3, axis=0)  # near-coincident
        if i % 11 == 0:
            q = np.insert(q, 2, q[2], axis=0)  # repeated
        out.append(q + np.array([85000.0, 447000.0, 2.0]) * (i % 2))
    return out


def test_keep_corners_of_its_output_is_its_output():
    rng = np.random.default_rng(3)
    pieces = [Piece(q, "wall", "Outdoors", 1.0, i) for i, q in enumerate(_rings(rng))]
    once = keep_corners(_as_written(pieces))
    assert len(once) > len(pieces)  # some pieces were fanned into triangles
    twice = keep_corners(once)
    assert len(twice) == len(once)
    assert all(a is b for a, b in zip(twice, once))


def test_enclosure_verdicts_remembered_are_the_computed_ones():
    rng = np.random.default_rng(5)
    rings = _rings(rng, 120)
    zones = [[np.round(q, 4) for q in rings[i:i + 6]] for i in range(0, 120, 6)]
    box = [np.array(f, dtype=float) for f in (
        [[0, 0, 0], [0, 1, 0], [1, 1, 0], [1, 0, 0]], [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
        [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]], [[1, 0, 0], [1, 1, 0], [1, 1, 1], [1, 0, 1]],
        [[1, 1, 0], [0, 1, 0], [0, 1, 1], [1, 1, 1]], [[0, 1, 0], [0, 0, 0], [0, 0, 1], [0, 1, 1]])]
    zones += [box, box[:-1]]
    cache.clear(enclosure.DEFECTS)
    for z in zones + zones:
        got = enclosure.enclosure_defects([q.copy() for q in z])
        exp = enclosure.face_defects(enclosure.eplus_vertices([np.asarray(q, dtype=np.float64) for q in z]))
        assert len(got) == len(exp)
        for a, b in zip(got, exp):
            assert np.array_equal(a.start, b.start) and np.array_equal(a.end, b.end)
            assert (a.count, a.surfaces) == (b.count, b.surfaces)
    assert enclosure.enclosure_defects(box) == [] and enclosure.enclosure_defects(box[:-1])
    # the same values in another frame or tolerance are another key
    assert enclosure.enclosure_defects([q + 1e-3 for q in box[:-1]], 0.0127)
    assert 0 < cache.sizes()[enclosure.DEFECTS][0] <= enclosure.DEFECTS_KEPT


def test_vertices_and_degenerate_together_as_apart():
    rng = np.random.default_rng(11)
    rings = _rings(rng)
    # rings the coincident test shortens below 3 vertices, and ones it leaves at 3 exactly
    rings += [np.array([[0, 0, 0], [0.004, 0, 0], [0.008, 0.001, 0]], float),
              np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0.003, 0.002, 0]], float),
              np.array([[0, 0, 0], [1, 0, 0], [0.5, 0.001, 0], [0.002, 0, 0]], float),
              np.array([[0, 0, 0], [0, 0, 0]], float), np.zeros((0, 3))]
    faces, degen = enclosure.eplus_vertices_and_degenerate(rings)
    assert degen == enclosure.eplus_degenerate(rings) and any(degen) and not all(degen)
    exp = enclosure.eplus_vertices(rings)
    assert len(faces) == len(exp)
    assert all(a.shape == b.shape and np.array_equal(a, b) for a, b in zip(faces, exp))
    zone = rings[:30]
    assert len(enclosure.face_defects(faces[:30])) == len(enclosure.face_defects(enclosure.eplus_vertices(zone)))


def test_surely_planar_only_when_the_tests_pass():
    from lod2energy.energy.conform import PIECE_PLANAR
    from lod2energy.energy.pieces import _planar_dev_of, _surely_planar
    from lod2energy.geometry.polygons import newell_normal
    from lod2energy.energy.zones.shells import MIN_PIECE_AREA

    rng = np.random.default_rng(13)
    rings = []
    for i in range(3000):
        k = 3 + i % 9
        ang = np.sort(rng.random(k)) * 2 * np.pi
        r = np.full(k, 1.0)
        q = np.column_stack([r * np.cos(ang), r * np.sin(ang), np.zeros(k)])
        area_target = MIN_PIECE_AREA * (1 + rng.normal(0, 1e-3)) if i % 3 == 0 else 10 ** rng.uniform(-5, 3)
        q *= np.sqrt(area_target / max(0.5 * np.linalg.norm(newell_normal(q)), 1e-300))
        bend = 2 * PIECE_PLANAR * (1 + rng.normal(0, 1e-4)) if i % 3 == 1 else rng.uniform(0, 0.03)
        q[:, 2] = np.where(np.arange(k) % 2, bend, -bend) * (k > 3)
        rot, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        rings.append(np.round(q @ rot + rng.uniform(-200, 200, 3), 4))
    # as the self-check tests a surface: area and twice the piece tolerance
    sure = _surely_planar(rings, 2 * PIECE_PLANAR, MIN_PIECE_AREA)
    n_pass = 0
    for q, s in zip(rings, sure):
        nn = newell_normal(q)
        ok = 0.5 * float(np.linalg.norm(nn)) > MIN_PIECE_AREA and _planar_dev_of(q, nn) <= 2 * PIECE_PLANAR
        n_pass += ok
        assert ok or not s
    assert sum(sure) > 0.9 * n_pass > 300  # it decides almost every passing ring
    # as keep_corners tests a piece: the tolerance alone (tiny and zero-area rings too)
    rings += [np.zeros((4, 3)), np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 1e-9]]),
              np.array([[0, 0, 0], [1e-9, 0, 0], [1e-9, 1e-9, 0.02], [0, 1e-9, 0]])]
    sure = _surely_planar(rings, PIECE_PLANAR)
    n_pass = 0
    for q, s in zip(rings, sure):
        ok = _planar_dev_of(q, newell_normal(q)) <= PIECE_PLANAR
        n_pass += ok
        assert ok or not s
    assert sum(sure) > 0.9 * n_pass > 300


def test_degenerate_given_collinear_same_verdicts():
    from lod2energy.energy.conform import _degenerate_given

    rings = _rings(np.random.default_rng(17))
    rings += [np.array([[0, 0, 0], [0.004, 0, 0], [0.008, 0.001, 0]], float),
              np.array([[0, 0, 0], [1, 0, 0], [0.5, 0.001, 0], [0.002, 0, 0]], float)]
    got = _degenerate_given(rings, enclosure.eplus_collinear(rings))
    assert got == enclosure.eplus_degenerate(rings) and any(got)


def _ref_find_party_faces(zones, plane_tol=0.05, min_area=0.01, angle_cos=0.985):
    """surfaces.find_party_faces before its face pairs were filtered all at once."""
    import shapely

    from lod2energy.energy.pieces import _face_frame
    from lod2energy.energy.surfaces import _shapely_poly
    from lod2energy.geometry.polygons import wall_basis as plane_basis

    boxes = np.array([[*z.vertices.min(axis=0), *z.vertices.max(axis=0)] if len(z.vertices)
                      else [np.inf] * 3 + [-np.inf] * 3 for z in zones])
    frames = {}

    def zone_frames(zi):
        if zi not in frames:
            fr = []
            for f in zones[zi].faces:
                pts, ends, n, c = _face_frame(zones[zi], f)
                fr.append((pts, ends, n, c, float(n @ c), pts.min(axis=0), pts.max(axis=0)))
            frames[zi] = fr
        return frames[zi]

    out = {}
    lo, hi = boxes[:, :3], boxes[:, 3:]
    for a in range(len(zones)):
        cand = np.nonzero(np.all(lo[a] <= hi + plane_tol, axis=1) & np.all(hi[a] >= lo - plane_tol, axis=1))[0]
        for b in cand[cand > a]:
            if zones[a].building_id == zones[b].building_id and zones[a].object_id == zones[b].object_id:
                continue
            for ia, (pa, ea, na, ca, da, mina, maxa) in enumerate(zone_frames(a)):
                for ib, (pb, eb, nb, cb, db, minb, maxb) in enumerate(zone_frames(int(b))):
                    if float(na @ nb) > -angle_cos:
                        continue
                    if np.any(mina > maxb + plane_tol) or np.any(maxa < minb - plane_tol):
                        continue
                    if abs(da + db) > plane_tol or np.max(np.abs((pb - ca) @ na)) > plane_tol:
                        continue
                    u, v = plane_basis(na)
                    inter = shapely.intersection(_shapely_poly(pa, ea, ca, u, v), _shapely_poly(pb, eb, ca, u, v))
                    if inter.area < min_area:
                        continue
                    out.setdefault((a, ia), []).append((int(b), inter))
                    ub, vb = plane_basis(nb)
                    out.setdefault((int(b), ib), []).append(
                        (a, shapely.intersection(_shapely_poly(pb, eb, cb, ub, vb), _shapely_poly(pa, ea, cb, ub, vb))))
    return out


def test_party_faces_same_as_pair_by_pair():
    from factories import box

    from export_helpers import energy_ready
    from lod2energy.energy.surfaces import find_party_faces
    from lod2energy.energy.zones.shells import local_origin, zone_shells

    rng = np.random.default_rng(19)
    bs = []
    x = 0.0
    for i in range(10):  # a terrace: touching or a few mm apart, offset, different heights
        dx = float(rng.uniform(4, 9))
        b = box(dx=dx, dz=float(rng.uniform(3, 12)), id=f"b{i}",
                origin=(x + [0.0, 0.004, -0.003, 0.0, 0.2][i % 5], float(rng.uniform(-2, 2)), 0.0))
        bs.append(energy_ready(b))
        x += dx
    origin = local_origin(bs)
    zones = [z for b in bs for z in zone_shells(b, origin)]
    got, exp = find_party_faces(zones), _ref_find_party_faces(zones)
    assert got.keys() == exp.keys() and len(got) > 4
    for k in exp:
        assert [(b, g.wkb) for b, g in got[k]] == [(b, g.wkb) for b, g in exp[k]]


def test_drop_coincident_all_at_once_as_one_by_one():
    rng = np.random.default_rng(29)
    rings = _rings(rng)
    C = enclosure.COINCIDENT
    for i in range(600):  # consecutive and closing distances at and around the threshold
        k = 2 + i % 7
        q = np.cumsum(rng.normal(0, 1, (k, 3)), axis=0) + rng.uniform(-300, 300, 3)
        j = i % k
        step = C * (1 + [0.0, 1e-16, -1e-16, 1e-12, -1e-12, 1e-3][i % 6])
        direction = rng.normal(size=3)
        direction /= np.linalg.norm(direction)
        if i % 2:
            q[j] = q[j - 1] + step * direction  # around the threshold (the closing pair when j = 0)
        rings.append(q)
    rings += [np.zeros((0, 3)), np.zeros((1, 3)), np.array([[0, 0, 0], [np.nan, 0, 0], [1, 1, 0]])]
    for floor in (1, 3):
        got = enclosure._drop_coincident(rings, floor)
        exp = [enclosure._drop_coincident_one(q, floor) for q in rings]
        for a, b in zip(got, exp):
            assert a.shape == b.shape and np.array_equal(a, b, equal_nan=True)
    assert sum(len(a) < len(q) for a, q in zip(got, rings)) > 20  # some vertices were dropped


def test_party_faces_of_the_first_zones_only():
    # a block whose neighbours touch each other too: with ``first`` the entries of the first
    # zones are those of the full search, the later zones keep only their pairs with them
    from export_helpers import energy_ready
    from factories import box
    from lod2energy.energy.surfaces import find_party_faces
    from lod2energy.energy.zones.shells import local_origin, zone_shells

    bs = [energy_ready(box(dx=6.0, dz=h, id=f"b{i}", origin=(6.0 * (i % 3), 8.0 * (i // 3), 0.0)))
          for i, h in enumerate((9.0, 6.0, 12.0, 7.5, 10.0, 6.0))]
    origin = local_origin(bs)
    zones = [z for b in bs for z in zone_shells(b, origin)]
    full = find_party_faces(zones)
    first = len(zone_shells(bs[0], origin))
    part = find_party_faces(zones, first=first)
    later = {k: [(o, g.wkb) for o, g in v if o < first] for k, v in full.items() if k[0] >= first}
    assert sum(1 for k in full if k[0] >= first and all(o >= first for o, _ in full[k])) > 4  # pairs skipped
    for k, v in full.items():
        if k[0] < first:
            assert [(o, g.wkb) for o, g in part[k]] == [(o, g.wkb) for o, g in v]
    assert {k: [(o, g.wkb) for o, g in v] for k, v in part.items() if k[0] >= first} == \
        {k: v for k, v in later.items() if v}
