"""CFD ground from the file's own TINRelief: reading, resampling, volumes, and the case built on it."""
from __future__ import annotations

import numpy as np
import pytest

from factories import box

from lod2energy.exporters.cfd.case import build_case
from lod2energy.exporters.cfd.region import make_region
from lod2energy.exporters.cfd.terrain import height_function, solid_under, terrain_grid, tin_of, volume_under
from lod2energy.model import Building, CityObject, Geometry, Shell, Solid, Surface


def tin_feature(nx: int = 8, ny: int = 8, size: float = 400.0, slope=(0.01, 0.005), z0: float = -1.0,
                origin=(-150.0, -150.0)) -> Building:
    """A planar TINRelief ``z = z0 + sx*x + sy*y`` over a square, as the CityJSON reader yields it."""
    xs = np.linspace(origin[0], origin[0] + size, nx + 1)
    ys = np.linspace(origin[1], origin[1] + size, ny + 1)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    Z = z0 + slope[0] * X + slope[1] * Y
    v = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
    idx = np.arange(len(v)).reshape(nx + 1, ny + 1)
    surfaces = []
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]
            surfaces += [Surface.from_lists([[a, b, c]]), Surface.from_lists([[a, c, d]])]
    g = Geometry("CompositeSurface", "1", (Solid((Shell(tuple(surfaces)),)),))
    return Building("tin", "TINRelief", v, (CityObject("tin", "TINRelief", (g,)),))


def test_tin_is_read_and_interpolated_exactly_for_a_plane():
    tin = tin_of([tin_feature()])
    assert tin is not None and len(tin[1]) == 2 * 8 * 8
    f = height_function(tin)
    pts = np.array([[0.0, 0.0], [100.0, -50.0], [1000.0, 1000.0]])
    z = f(pts)
    assert z[:2] == pytest.approx([-1.0, -1.0 + 1.0 - 0.25])
    assert np.isfinite(z[2])  # outside the TIN: nearest value


def test_no_tin_gives_none():
    assert tin_of([box()]) is None


def test_volume_under_and_solid_under_a_height_field_agree():
    tin = tin_of([tin_feature()])
    case = build_case([box(10, 10, 6)], make_region(), 250.0, 2.0, 0.0)
    gv, gt, inner = terrain_grid(case.domain, case.mesh.cells, 1, height_function(tin), pad=2)
    floor = float(gv[:, 2].min()) - 3.0
    vol = volume_under(gv, gt, floor)
    s = solid_under(gv, gt, floor)
    import manifold3d as m3
    assert s.status() == m3.Error.NoError
    assert s.volume() == pytest.approx(vol, rel=1e-9)
    # the inner triangles cover exactly the box's plan
    P = gv[gt[inner]]
    area = 0.5 * np.abs((P[:, 1, 0] - P[:, 0, 0]) * (P[:, 2, 1] - P[:, 0, 1])
                        - (P[:, 2, 0] - P[:, 0, 0]) * (P[:, 1, 1] - P[:, 0, 1])).sum()
    lx, ly, _ = case.domain.size
    assert area == pytest.approx(lx * ly, rel=1e-9)


def test_case_on_a_tin_reaches_under_the_terrain():
    tin = tin_feature()
    b = box(10, 10, 6, origin=(0, 0, -1.0))
    case = build_case([b, tin], make_region(), 270.0, 2.0, 0.0, terrain=tin_of([tin]))
    assert case.terrain
    gv, gt = case.ground
    assert case.domain.bottom < gv[:, 2].min()                 # the box floor lies under the terrain
    assert case.united.vertices[:, 2].min() < gv[:, 2].min()   # buildings sunk through it
    # the box's volume above the sloping plane: 600 m3 less the wedge under the plane's rise
    assert 0 < case.united.volume_above_ground <= 600.0 + 1e-6
    assert case.fluid_volume_without_buildings < case.domain.volume
