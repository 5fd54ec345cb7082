"""Polygon-level checks (101-208): one tiny named polygon per code, snapping, properties."""
from __future__ import annotations

import math
import re
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from factories import box, building_from_polygons, gabled_house
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.model import Shell, Surface
from lod2energy.validate import polygon
from lod2energy.validate.polygon import check_polygons
from lod2energy.geometry.snap import snap_points, snapped_ids


def _codes(b, tol=DEFAULT) -> set[int]:
    out = set()
    for _, _, sh in b.objects[0].geometries[0].iter_shells():
        out.update(code for _, code, _ in check_polygons([(b.vertices, sh)], tol)[0])
    return out


def _poly(*rings, tol=DEFAULT) -> set[int]:
    b = building_from_polygons([[np.asarray(r, float) for r in rings]], "MultiSurface")
    return _codes(b, tol)


def _ring(pts) -> np.ndarray:
    return np.asarray(pts, float)


SQ10 = _ring([[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]])


def _hole(x0, y0, x1, y1, ccw=False) -> np.ndarray:
    r = _ring([[x0, y0, 0], [x1, y0, 0], [x1, y1, 0], [x0, y1, 0]])
    return r if ccw else r[::-1]


# one minimal bad polygon per code; a list of acceptable codes (GEOS versions differ)
NAMED = {
    "101_two_points": ([_ring([[0, 0, 0], [1, 0, 0]])], [{101}]),
    "101_empty_hole": ([SQ10, _ring([[1, 1, 0], [2, 1, 0]])], [{101}]),
    "102_repeated_point": ([_ring([[0, 0, 0], [1, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])], [{102}]),
    "102_first_equals_last": ([_ring([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 0, 0]])], [{102}]),
    "102_snapped_within_tol": ([_ring([[0, 0, 0], [1, 0, 0], [1, 0.0004, 0], [1, 1, 0], [0, 1, 0]])], [{102}]),
    "104_bowtie": ([_ring([[0, 0, 0], [1, 1, 0], [1, 0, 0], [0, 1, 0]])], [{104}]),
    "104_collinear_triangle": ([_ring([[0, 0, 0], [1, 0, 0], [2, 0, 0]])], [{104}]),
    "104_collapsed_ring": ([_ring([[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]])], [{104}]),
    "104_self_touching": ([_ring([[0, 0, 0], [4, 0, 0], [2, 2, 0], [4, 4, 0], [0, 4, 0], [2, 2, 0]])], [{104}]),
    "201_hole_crossing_outer": ([SQ10, _hole(8, 2, 12, 4)], [{201}]),
    "202_duplicated_ring": ([SQ10, SQ10[::-1]], [{202}, {201}]),
    "203_raised_corner": ([_ring([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]])], [{203}]),
    "205_interior_disconnected": ([_ring([[0, 0, 0], [5, 0, 0], [10, 0, 0], [10, 10, 0], [5, 10, 0], [0, 10, 0]]),
                                   _ring([[5, 0, 0], [4, 5, 0], [5, 10, 0], [6, 5, 0]])], [{205}]),
    "206_hole_outside": ([SQ10, _hole(20, 20, 22, 22)], [{206}, {201}]),
    "207_nested_holes": ([SQ10, _hole(1, 1, 9, 9), _hole(3, 3, 5, 5)], [{207}]),
    "208_same_orientation": ([SQ10, _hole(2, 2, 4, 4, ccw=True)], [{208}]),
}


# cases decided by an exact predicate on doubles (collinearity, as CGAL's) or by a
# sub-millimetre distance: a rotation rounds them either way, in val3dity too
EXACT_DEGENERACIES = {"102_snapped_within_tol", "104_collinear_triangle", "104_collapsed_ring"}


@pytest.mark.parametrize("name", sorted(NAMED))
def test_named_invalid_polygon(name):
    rings, acceptable = NAMED[name]
    assert _poly(*rings) in acceptable


def test_204_bent_quad_only_with_loose_distance_tolerance():
    bent = _ring([[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]])
    loose = Tolerances(planarity_d2p_tol=1.0)
    assert _poly(bent) == {203}
    assert _poly(bent, tol=loose) == {204}
    assert _poly(bent, tol=replace(loose, ignore204=True)) == set()
    assert _poly(bent, tol=replace(loose, planarity_n_tol=60.0)) == set()


def test_204_not_reported_when_another_polygon_of_the_shell_is_invalid():
    bent = [_ring([[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]])]
    bowtie = [_ring([[5, 0, 0], [6, 1, 0], [6, 0, 0], [5, 1, 0]])]
    b = building_from_polygons([bent, bowtie], "MultiSurface")
    assert _codes(b, Tolerances(planarity_d2p_tol=1.0)) == {104}


def test_valid_polygons_with_holes_and_touching_hole():
    assert _poly(SQ10, _hole(2, 2, 4, 4), _hole(6, 6, 8, 8)) == set()
    # a hole touching the outer ring at one point is valid (ISO 19107)
    assert _poly(SQ10, _ring([[0, 5, 0], [3, 6, 0], [3, 4, 0]])) == set()


@pytest.mark.parametrize("factory", [box, gabled_house])
def test_canonical_buildings_have_valid_polygons(factory):
    assert _codes(factory()) == set()


def test_info_strings_match_val3dity():
    b = building_from_polygons([[_ring([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]])]], "MultiSurface")
    sh = b.objects[0].geometries[0].solids[0].shells[0]
    (face, code, info), = check_polygons([(b.vertices, sh)])[0]
    assert (face, code) == (0, 203)
    m = re.fullmatch(r"distance to fitted plane: ([0-9.e+-]+) \(tolerance=0\.01\)", info)
    # least-squares plane by SVD: the first point farther than the tolerance is reported
    P = b.vertices[sh.surfaces[0].rings[0]]
    n = np.linalg.svd(P - P.mean(0))[2][-1]
    d = np.abs((P - P.mean(0)) @ n)
    assert m and math.isclose(float(m.group(1)), d[np.argmax(d > 0.01)], rel_tol=1e-5)
    bent = building_from_polygons([[_ring([[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]])]], "MultiSurface")
    sh = bent.objects[0].geometries[0].solids[0].shells[0]
    (_, code, info), = check_polygons([(bent.vertices, sh)], Tolerances(planarity_d2p_tol=1.0))[0]
    assert code == 204 and re.fullmatch(r"deviation normals: [0-9.]+ \(tolerance=20\)", info)


def test_collinear_triangle_info():
    b = building_from_polygons([[_ring([[0, 0, 0], [1, 0, 0], [2, 0, 0]])]], "MultiSurface")
    sh = b.objects[0].geometries[0].solids[0].shells[0]
    assert check_polygons([(b.vertices, sh)])[0] == [(0, 104, " outer ring (a triangle) is collapsed to a line")]


# ----------------------------------------------------------------------------- snapping

def test_snapping_is_first_come_and_not_transitive():
    # 0 -- 0.8 mm -- 1 -- 0.8 mm -- 2: 1 merges into 0, 2 is 1.6 mm from 0 and stays
    pts = np.array([[0, 0, 0], [0.0008, 0, 0], [0.0016, 0, 0]])
    assert snap_points(pts, 0.001).tolist() == [0, 0, 2]
    # order matters: starting from the middle point, both ends merge into it
    assert snap_points(pts[[1, 0, 2]], 0.001).tolist() == [0, 0, 0]


def test_snapping_threshold_is_strict_and_disabled_by_nonpositive_tol():
    pts = np.array([[0, 0, 0], [0.5, 0, 0]])
    assert snap_points(pts, 0.5).tolist() == [0, 1]          # d == tol: kept apart
    assert snap_points(pts, 0.5000001).tolist() == [0, 0]
    assert snap_points(np.zeros((3, 3)), 0.0).tolist() == [0, 1, 2]
    assert snap_points(np.zeros((3, 3)), 1e-12).tolist() == [0, 0, 0]


def test_snapped_ids_maps_duplicates_to_first_vertex():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 0, 0.0002]])
    assert snapped_ids(v, np.array([2, 1, 0, 2]), 0.001).tolist() == [2, 1, 2, 2]


def test_quantised_millimetre_neighbours_follow_float_distance():
    """Points one quantum (1 mm) apart snap exactly when their float distance is below 1 mm."""
    scale, translate = 0.001, 85000.0
    for a in (1000, 1234, 99999):
        x0, x1 = a * scale + translate, (a + 1) * scale + translate
        expected = (x1 - x0) ** 2 < 0.001 ** 2
        ring = _ring([[x0, 0, 0], [x1, 0, 0], [x1 + 5, 0, 0], [x1 + 5, 5, 0], [x0, 5, 0]])
        assert (_poly(ring) == {102}) == expected


# ----------------------------------------------------------------------------- properties

def _rotation(a, b, c) -> np.ndarray:
    ca, sa, cb, sb, cc, sc = math.cos(a), math.sin(a), math.cos(b), math.sin(b), math.cos(c), math.sin(c)
    rz = np.array([[ca, -sa, 0], [sa, ca, 0], [0, 0, 1]])
    ry = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]])
    rx = np.array([[1, 0, 0], [0, cc, -sc], [0, sc, cc]])
    return rz @ ry @ rx


angles = st.floats(-math.pi, math.pi, allow_nan=False)
offsets = st.floats(-1e5, 1e5, allow_nan=False)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(angles, angles, angles, offsets, offsets, st.floats(-100, 100), st.sampled_from(sorted(NAMED) + ["box", "house"]))
def test_rigid_transforms_keep_polygon_validity(a, b, c, tx, ty, tz, name):
    R = _rotation(a, b, c)
    t = np.array([tx, ty, tz])
    if name in ("box", "house"):
        bld = box() if name == "box" else gabled_house()
        before = _codes(bld)
        moved = replace(bld, vertices=bld.vertices @ R.T + t)
        assert _codes(moved) == before == set()
        return
    rings, acceptable = NAMED[name]
    if name in EXACT_DEGENERACIES:
        return
    moved = [r @ R.T + t for r in rings]
    assert _poly(*moved) in acceptable


ring_pts = st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3), st.integers(-1, 1)), min_size=0, max_size=8)


@settings(max_examples=150, deadline=None)
@given(st.lists(st.lists(ring_pts, min_size=1, max_size=3), min_size=1, max_size=4),
       st.sampled_from([DEFAULT, Tolerances(planarity_d2p_tol=10.0), Tolerances(snap_tol=0.5, ignore204=True)]))
def test_check_polygons_never_raises_on_random_rings(faces, tol):
    pts = sorted({p for f in faces for r in f for p in r})
    assume(pts)
    index = {p: i for i, p in enumerate(pts)}
    surfaces = tuple(Surface.from_lists([[index[p] for p in r] for r in f]) for f in faces)
    out, = check_polygons([(np.asarray(pts, float), Shell(surfaces))], tol)
    for face, code, info in out:
        assert 0 <= face < len(surfaces)
        assert code in (101, 102, 104, 201, 202, 203, 204, 205, 206, 207, 208)
        assert isinstance(info, str)


def test_check_polygons_handles_empty_shell_and_bad_indices():
    assert check_polygons([(np.zeros((0, 3)), Shell(()))]) == [[]]
    out, = check_polygons([(np.zeros((3, 3)), Shell((Surface.from_lists([[0, 1, 7]]),)))])
    assert out and out[0][1] == 999


def test_denhaag_polygon_defects_match_val3dity_report(denhaag_path):
    """Every 1xx/2xx defect of val3dity 2.6 on Den Haag tile 01, location and info."""
    import json

    from conftest import REFERENCE
    from lod2energy.io import read

    ref = REFERENCE / "denhaag_DenHaag_01.city.json.report.json"
    if not ref.exists():
        pytest.skip("reference report not available")
    theirs = {(e["id"], e["code"], e["info"]) for f in json.loads(ref.read_text())["features"]
              for e in f.get("errors", []) if e["code"] < 300}
    _, feats = read(str(denhaag_path))
    where, items = [], []
    for b in feats:
        for o in b.objects:
            for gi, g in enumerate(o.geometries):
                if g.is_polygonal:
                    for si, hi, sh in g.iter_shells():
                        where.append((o.id, gi, si, hi, g))
                        items.append((b.vertices, sh))
    mine = set()
    for (oid, gi, si, hi, g), found in zip(where, check_polygons(items)):
        mine.update((f"coid={oid}|" + g.location(gi, si, hi, f), code, info) for f, code, info in found)
    assert len(theirs) > 100
    assert mine == theirs


# ----------------------------------------------------------------------------- batching, cache

def _named_shells():
    out = []
    for name in sorted(NAMED):
        rings, _ = NAMED[name]
        b = building_from_polygons([[np.asarray(r, float) for r in rings]], "MultiSurface", id=name)
        out.append((b.vertices, b.objects[0].geometries[0].solids[0].shells[0]))
    for bld in (box(), gabled_house()):
        out.append((bld.vertices, bld.objects[0].geometries[0].solids[0].shells[0]))
    return out


@pytest.mark.parametrize("tol", [DEFAULT, Tolerances(planarity_d2p_tol=1.0)])
def test_batched_checks_equal_shell_by_shell(tol):
    items = _named_shells()
    one_by_one = [polygon._check([it], tol)[0] for it in items]  # without the cache
    assert polygon._check(items, tol) == one_by_one
    assert any(one_by_one) and not all(one_by_one)


def test_kept_answers_are_keyed_on_vertices_shell_and_tolerances():
    bent = building_from_polygons([[_ring([[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]])]], "MultiSurface")
    sh = bent.objects[0].geometries[0].solids[0].shells[0]
    assert [c for _, c, _ in check_polygons([(bent.vertices, sh)])[0]] == [203]
    assert [c for _, c, _ in check_polygons([(bent.vertices, sh)])[0]] == [203]  # kept
    # other tolerances, or other vertices for the same shell: computed afresh
    assert [c for _, c, _ in check_polygons([(bent.vertices, sh)], Tolerances(planarity_d2p_tol=1.0))[0]] == [204]
    flat = bent.vertices.copy()
    flat[:, 2] = 0
    assert check_polygons([(flat, sh)]) == [[]]


def test_geometry_instance_is_validated_on_its_template(tmp_path):
    import json

    from lod2energy.io import cityjson_write, read
    from lod2energy.validate.checks import validate_building

    bent = [[0, 1, 2, 3]]
    doc = {"type": "CityJSON", "version": "2.0",
           "transform": {"scale": [0.001] * 3, "translate": [0, 0, 0]},
           "geometry-templates": {"templates": [{"type": "MultiSurface", "lod": "2", "boundaries": [bent]}],
                                  "vertices-templates": [[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]]},
           "CityObjects": {"tree": {"type": "SolitaryVegetationObject", "geometry": [
               {"type": "GeometryInstance", "template": 0, "boundaries": [0],
                "transformationMatrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]}},
           "vertices": [[100, 200, 0]]}
    p = tmp_path / "tpl.city.json"
    p.write_text(json.dumps(doc))
    model, feats = read(str(p))
    (b,) = list(feats)
    defects = validate_building(b)
    assert [(d.code, d.location) for d in defects] == [(203, "coid=tree|geom=0|face=0")]
    # the template reference does not leak into what is written back
    out = tmp_path / "out.city.json"
    cityjson_write.write(str(out), model, [b])
    back = json.loads(out.read_text())
    assert back["geometry-templates"] == doc["geometry-templates"]
    assert back["CityObjects"]["tree"]["geometry"][0]["template"] == 0


@pytest.mark.parametrize("factory,codes", [("box", set()), ("gabled_house", set()), ("open_box", {302}),
                                           ("flipped_wall", {307}), ("inward_box", {405})])
def test_factories_carry_the_defect_they_are_named_after(factory, codes):
    import factories
    from lod2energy.validate.checks import validate_building

    b = getattr(factories, factory)()
    assert {d.code for d in validate_building(b)} == codes
    v = b.vertices
    assert v.shape[1] == 3 and not v.flags.writeable
