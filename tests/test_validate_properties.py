"""Property tests of the whole validator: robust on random soups, invariant under rigid motions."""
from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

from lod2energy.config import DEFAULT
from lod2energy.graph import building_graphs
from lod2energy.model import Building, CityObject, Geometry, Shell, Solid, Surface
from lod2energy.validate.checks import validate_building
from lod2energy.validate.compliance import energy_compliance

from cityjson_docs import BOX_FACES, BOX_VERTICES


def building(vertices, faces, gtype="Solid") -> Building:
    shell = Shell(tuple(Surface.from_lists(f) for f in faces))
    g = Geometry(gtype, "2", (Solid((shell,)),))
    return Building("b", "Building", np.asarray(vertices, float), (CityObject("b", "Building", (g,)),))


def gabled():
    v = [[0, 0, 0], [10, 0, 0], [10, 6, 0], [0, 6, 0], [0, 0, 4], [10, 0, 4], [10, 6, 4], [0, 6, 4],
         [0, 3, 7], [10, 3, 7]]
    f = [[[0, 3, 2, 1]], [[0, 1, 5, 4]], [[2, 3, 7, 6]], [[1, 2, 6, 9, 5]], [[3, 0, 4, 8, 7]],
         [[4, 5, 9, 8]], [[6, 7, 8, 9]]]
    return v, f


coords = st.floats(-50, 50, allow_nan=False, allow_infinity=False)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(coords, coords, coords), min_size=3, max_size=12),
       st.lists(st.lists(st.integers(0, 11), min_size=0, max_size=7), min_size=0, max_size=10),
       st.sampled_from(["Solid", "MultiSurface", "CompositeSurface"]))
def test_validator_never_raises_on_random_polygon_soups(points, rings, gtype):
    n = len(points)
    faces = [[[i % n for i in r]] for r in rings]
    b = building(points, faces, gtype)
    defects = validate_building(b)
    assert all(isinstance(d.code, int) and 100 <= d.code < 1000 for d in defects)
    energy_compliance(b, defects)


@settings(max_examples=25, deadline=None)
@given(st.floats(-np.pi, np.pi), st.floats(-0.5, 0.5), st.tuples(*[st.floats(-2e5, 2e5)] * 2),
       st.sampled_from(["box", "gabled"]))
def test_rigid_motions_keep_validity_area_and_volume(yaw, tilt, shift, shape):
    v, f = (BOX_VERTICES, BOX_FACES) if shape == "box" else gabled()
    v = np.asarray(v, float)
    c, s, ct, st_ = np.cos(yaw), np.sin(yaw), np.cos(tilt), np.sin(tilt)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ np.array([[1, 0, 0], [0, ct, -st_], [0, st_, ct]])
    moved = v @ R.T + np.array([shift[0], shift[1], 10.0])
    b0, b1 = building(v, f), building(moved, f)
    d0, d1 = validate_building(b0), validate_building(b1)
    assert [d.code for d in d0] == [] and [d.code for d in d1] == []
    g0, g1 = building_graphs([b0])[0], building_graphs([b1])[0]
    np.testing.assert_allclose(g0.x[:, 0], g1.x[:, 0], rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(g0.shell_volumes(), g1.shell_volumes(), rtol=1e-6)


def test_validation_does_not_mutate_its_input():
    v, f = gabled()
    b = building(v, f)
    before = b.vertices.copy(), [r.copy() for _, _, _, s in b.root.geometries[0].iter_surfaces() for r in s.rings]
    validate_building(b, DEFAULT)
    building_graphs([b])[0]
    assert np.array_equal(before[0], b.vertices)
    after = [r for _, _, _, s in b.root.geometries[0].iter_surfaces() for r in s.rings]
    assert all(np.array_equal(x, y) for x, y in zip(before[1], after))
