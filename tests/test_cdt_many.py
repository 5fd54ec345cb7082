"""``constrained_delaunay_many``: GEOS's CDT of many polygons in one call, with the Python
CDT where GEOS does not apply; and the false 204 the Python fast path used to report on a
wall with collinear corners (a Berlin LoD2 building; val3dity 2.6 finds it valid)."""
from __future__ import annotations

import numpy as np
import pytest
import shapely

from lod2energy.geometry import cdt
from lod2energy.model import Shell, Surface
from lod2energy.validate.polygon import check_polygons


def _star(rng, k, r0=1.0, jitter=0.6):
    a = np.sort(rng.random(k)) * 2 * np.pi
    r = r0 * (1 - jitter * rng.random(k))
    return np.c_[r * np.cos(a), r * np.sin(a)]


def _general_position(seed: int, count: int):
    """Star polygons, some with a hole, with random float corners: no four co-circular points,
    so the CDT is unique and every correct implementation gives the same triangles."""
    rng = np.random.default_rng(seed)
    for i in range(count):
        scale, centre = 10 ** rng.uniform(-1, 2), rng.uniform(-1e3, 1e3, 2)
        outer = _star(rng, int(rng.integers(3, 40))) * scale + centre   # radii 0.4 to 1 scale
        rings = [outer]
        if i % 3 == 0:
            rings.append(_star(rng, int(rng.integers(3, 8)), 0.3, 0.2)[::-1] * scale + centre)
        yield np.concatenate(rings), np.cumsum([len(r) for r in rings])


def _key(t):
    return sorted(tuple(sorted(r)) for r in np.asarray(t).tolist())


def _ccw(pts, t):
    a, b, c = pts[t[:, 0]], pts[t[:, 1]], pts[t[:, 2]]
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) > 0


@pytest.mark.skipif(not hasattr(shapely, "constrained_delaunay_triangles"), reason="shapely < 2.1")
@pytest.mark.parametrize("seed", range(3))
def test_geos_gives_the_python_cdt_in_general_position(seed, monkeypatch):
    polys = list(_general_position(seed, 150))
    python_did = []
    real = cdt.constrained_delaunay
    monkeypatch.setattr(cdt, "constrained_delaunay", lambda p, e, *a: python_did.append(id(p)) or real(p, e, *a))
    got = cdt.constrained_delaunay_many(polys)
    assert len(python_did) < len(polys) // 10  # GEOS did nearly all of them
    for (pts, ends), t in zip(polys, got):
        assert t is not None and t.dtype == np.intp
        assert _key(t) == _key(real(pts, ends))
        if id(pts) not in python_did:  # GEOS's: a full triangulation, counter-clockwise
            assert len(t) == len(pts) - 2 + 2 * (len(ends) - 1)
            assert _ccw(pts, t).all()


def test_without_geos_every_polygon_takes_the_python_cdt(monkeypatch):
    polys = list(_general_position(7, 40))
    monkeypatch.delattr(shapely, "constrained_delaunay_triangles", raising=False)
    got = cdt.constrained_delaunay_many(polys)
    for (pts, ends), t in zip(polys, got):
        assert np.array_equal(t, cdt.constrained_delaunay(pts, ends))


def test_polygons_geos_cannot_take_fall_back_one_by_one():
    sq = np.array([[0.0, 0], [4, 0], [4, 4], [0, 4]])
    touching = np.array([[0.0, 0], [4, 0], [4, 4], [2, 2], [0, 4], [2, 2]])   # repeats a point
    bowtie = np.array([[0.0, 0], [4, 4], [4, 0], [0, 4]])                      # self-intersecting
    nan = np.array([[0.0, 0], [4, 0], [np.nan, 4], [0, 4]])
    polys = [(sq, np.array([4])), (touching, np.array([6])), (bowtie, np.array([4])), (nan, np.array([4])),
             (sq[:2], np.array([2])), (sq, np.array([3]))]
    got = cdt.constrained_delaunay_many(polys)
    assert len(got[0]) == 2 and _ccw(sq, got[0]).all()
    for (pts, ends), t in list(zip(polys, got))[1:]:
        try:
            want = cdt.constrained_delaunay(pts, ends)
        except Exception:  # noqa: BLE001 - then the batch answers None
            assert t is None
        else:
            assert np.array_equal(t, np.asarray(want, dtype=np.intp).reshape(-1, 3))
    assert cdt.constrained_delaunay_many([]) == []


# a wall of a Berlin LoD2 building (3920_5818.gml, BLDG_0003000e002fa83f, face 51): four corners
# along its foot and three along its top are collinear to 1e-9
BERLIN_WALL = np.array([
    [392097.754185834, 5818546.57202398, 34.5699996948242], [392097.754670646, 5818546.57274048, 57.25],
    [392100.038451906, 5818547.5426315, 57.25], [392100.573530255, 5818547.76987204, 57.25],
    [392102.316683435, 5818548.51016563, 57.25], [392102.316198621, 5818548.50944912, 34.5699996948242],
    [392100.037967094, 5818547.541915, 34.5699996948242]])


@pytest.mark.parametrize("shift", [False, True])
def test_a_wall_with_collinear_corners_is_planar(shift):
    # the Delaunay fast path counted a flat triangle of three collinear foot corners inside the
    # wall (6 triangles for 7 corners) and its noise normal gave 204 at 90 degrees
    V = BERLIN_WALL - BERLIN_WALL.mean(axis=0) if shift else BERLIN_WALL
    shell = Shell(surfaces=(Surface(rings=(np.arange(len(V)),)),))
    assert check_polygons([(V, shell)]) == [[]]


def test_the_fast_path_refuses_a_flat_triangle():
    from lod2energy.geometry import newell_normal, project_2d
    p2 = project_2d(BERLIN_WALL, newell_normal(BERLIN_WALL))
    p2 = p2 - p2.mean(axis=0)
    ends = np.array([len(p2)])
    fast = cdt._delaunay_if_conforming(p2, ends)
    assert fast is None or len(fast) == len(p2) - 2
    t = cdt.constrained_delaunay(p2, ends)
    assert len(t) == len(p2) - 2
    (many,) = cdt.constrained_delaunay_many([(p2, ends)])
    assert len(many) == len(p2) - 2


def test_signed_zero_points_are_duplicates():
    sq = np.array([[0.0, 0.0], [1, 0], [1, 1], [0, 1], [-0.0, 0.0], [0.5, 0.5]])
    assert cdt._delaunay_if_conforming(sq, np.array([4, 6])) is None
    assert cdt._delaunay_if_conforming(sq[:4], np.array([4])) is not None
