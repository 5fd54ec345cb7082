"""The vectorised enclosure emulation (lod2energy.energy.enclosure) agrees with the pure-Python
one it replaced (tests/_enclosure_reference.py) on random and on real zones."""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.energy import enclosure as ee
from lod2energy.energy import conform, model as energy_model
from lod2energy.energy.zones import storeys
from lod2energy.exporters import energyplus

from _enclosure_reference import (reference_edges_not_two, reference_enclosure_defects,
                                  reference_eplus_degenerate, reference_face_defects, reference_eplus_merge,
                                  reference_eplus_vertices, reference_insert_collinear,
                                  reference_unique_vertices)
from export_helpers import DATA, energy_ready, real_buildings, write_idf

TOL = ee.POINT_TOL


def _same_edges(a, b) -> bool:
    return len(a) == len(b) and all(
        np.array_equal(x[0], y[0]) and np.array_equal(x[1], y[1]) and list(x[2]) == list(y[2])
        for x, y in zip(a, b))


def _same_defects(a, b) -> bool:
    return len(a) == len(b) and all(
        np.array_equal(x.start, y.start) and np.array_equal(x.end, y.end) and x.count == y.count
        and x.surfaces == y.surfaces for x, y in zip(a, b))


def assert_agree(surfaces) -> None:
    """Every step of the emulation gives what the reference gives, bit for bit."""
    faces = [ee.eplus_vertices([np.asarray(s, dtype=np.float64)])[0] for s in surfaces]
    for s, f in zip(surfaces, faces):
        assert np.array_equal(f, reference_eplus_vertices(s))
        assert ee.eplus_degenerate([s])[0] == reference_eplus_degenerate(s)
    allp = np.concatenate(faces)
    u_new, i_new = ee.eplus_merge(allp)
    u_ref, i_ref = reference_eplus_merge(allp)
    assert np.array_equal(u_new, u_ref) and np.array_equal(i_new, i_ref)
    uniq = np.asarray(reference_unique_vertices(faces, TOL))
    assert np.array_equal(np.asarray(ee.unique_vertices(faces, TOL)), uniq)
    assert _same_edges(ee._edges_not_two(faces, TOL), reference_edges_not_two(faces, TOL))
    for f in faces:
        assert np.array_equal(ee._insert_collinear(f, uniq, TOL), reference_insert_collinear(f, uniq, TOL))
    assert _same_defects(ee.enclosure_defects(surfaces), reference_enclosure_defects(surfaces))


def _box(lo=(0.0, 0.0, 0.0), hi=(10.0, 8.0, 6.0)):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [np.array(p, float) for p in (
        [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
        [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
        [(x1, y1, z0), (x0, y1, z0), (x0, y1, z1), (x1, y1, z1)],
        [(x0, y1, z0), (x0, y0, z0), (x0, y0, z1), (x0, y1, z1)])]


def _random_zone(rng) -> list[np.ndarray]:
    """A box with T-junctions (split walls and roof), points jittered around EnergyPlus's
    1.27 cm, some surfaces dropped or doubled, some edges subdivided."""
    hi = rng.uniform(3, 20, size=3)
    polys = _box(hi=tuple(hi))
    out = []
    for p in polys:
        r = rng.random()
        if r < 0.25:      # split the polygon in two along its first edge's direction
            a, b, c, d = p
            t = rng.uniform(0.2, 0.8)
            m1, m2 = a + t * (b - a), d + t * (c - d)
            out += [np.array([a, m1, m2, d]), np.array([m1, b, c, m2])]
        elif r < 0.4:     # a vertex on an edge of the polygon (collinear point)
            t = rng.uniform(0.1, 0.9)
            out.append(np.insert(p, 1, p[0] + t * (p[1] - p[0]), axis=0))
        elif r < 0.45:
            continue      # an open zone
        elif r < 0.5:
            out += [p, p]  # an edge used four times
        else:
            out.append(p)
    scale = rng.choice([0.0, 0.004, 0.01, 0.0127, 0.02])
    return [q + rng.uniform(-scale, scale, size=q.shape) * (rng.random(q.shape[0]) < 0.5)[:, None]
            for q in out]


@pytest.mark.parametrize("seed", range(60))
def test_random_zones_agree(seed):
    rng = np.random.default_rng(seed)
    assert_agree(_random_zone(rng))


def test_random_points_merge_agree():
    rng = np.random.default_rng(7)
    for _ in range(20):
        # clusters of points a few mm apart: chains where "almost equal" is not transitive
        base = rng.uniform(0, 0.2, size=(40, 3))
        pts = np.concatenate([base, base + rng.uniform(-0.015, 0.015, size=base.shape)])[rng.permutation(80)]
        for tol in (0.0127, 0.03):
            u1, i1 = ee.eplus_merge(pts, tol)
            u2, i2 = reference_eplus_merge(pts, tol)
            assert np.array_equal(u1, u2) and np.array_equal(i1, i2)


REAL = [("3dbag/tile901_trimmed.city.jsonl", 6), ("denhaag/DenHaag_01.city.json", 6),
        ("3dbag/3dbag_b2.city.json", 2)]


@pytest.mark.parametrize("rel,n", REAL, ids=[r[0].split("/")[-1] for r in REAL])
def test_real_zones_agree(tmp_path, monkeypatch, rel, n):
    """Every zone the IDF writer tests while exporting real buildings (its candidates, the
    written zones of the self-check) gets the same answer from both implementations."""
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    seen, kept = [], []

    def recording(fn, into):
        def rec(surfaces, *a, **k):
            into.append([np.array(s, dtype=np.float64) for s in surfaces])
            return fn(surfaces, *a, **k)
        return rec

    # every caller in the writer: the zone candidates test the IDF's surfaces, the self-check
    # the vertices EnergyPlus keeps of the written ones
    for mod in (conform, storeys, energy_model):
        monkeypatch.setattr(mod, "enclosure_defects", recording(ee.enclosure_defects, seen))
    monkeypatch.setattr(energyplus.check, "face_defects", recording(ee.face_defects, kept))
    bs = [energy_ready(b) for b in real_buildings(rel, n=n)]
    write_idf(bs, tmp_path)
    assert seen and kept
    for surfaces in seen:
        assert_agree(surfaces)
    for faces in kept:
        assert _same_defects(ee.face_defects(faces), reference_face_defects(faces))


def test_near_degenerate_surfaces_agree():
    """Surfaces at EnergyPlus's coincident/collinear limits (tests/test_eplus_degenerate.py)."""
    from test_eplus_degenerate import near_degenerate
    rng = np.random.default_rng(5)
    for _ in range(400):
        P = near_degenerate(rng)
        assert np.array_equal(ee.eplus_vertices([P])[0], reference_eplus_vertices(P))
        assert ee.eplus_degenerate([P])[0] == reference_eplus_degenerate(P)
        assert ee.eplus_degenerate([P[:2]])[0] == reference_eplus_degenerate(P[:2])
