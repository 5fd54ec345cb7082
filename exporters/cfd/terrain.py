"""The file's own terrain for a CFD case: a CityJSON ``TINRelief`` turned into a ground surface.

The TIN is read as triangles, then resampled (linear interpolation over its vertices, nearest
value outside them) onto a regular grid in the domain's wind frame that runs along the lines of
the background mesh at the terrain's refinement level and reaches two grid steps past the box
on every side: snappyHexMesh snaps cell points onto the grid's own points, so the meshed
ground follows the surface written, and the volume under it is known exactly.
"""
from __future__ import annotations

import manifold3d as m3
import numpy as np
from scipy.interpolate import LinearNDInterpolator, NearestNDInterpolator

from lod2energy.exporters.cfd.domain import from_wind_frame
from lod2energy.geometry import triangulate_surface


def tin_of(features) -> tuple[np.ndarray, np.ndarray] | None:
    """Triangles of the ``TINRelief`` features ``(vertices (n, 3), triangles (t, 3))`` in map
    coordinates, or None when there is none."""
    vs, ts, k = [], [], 0
    for f in features:
        if f.type != "TINRelief":
            continue
        v = np.asarray(f.vertices, dtype=np.float64)
        for o in f.objects:
            for g in o.geometries:
                for _si, _sh, shell in g.iter_shells():
                    for s in shell.surfaces:
                        ring = [int(i) for i in s.rings[0]]
                        if len(ring) == 3:
                            ts.append(np.array(ring) + k)
                        elif len(ring) > 3:
                            ts.extend(np.asarray(triangulate_surface(v, s)).reshape(-1, 3) + k)
        vs.append(v)
        k += len(v)
    if not ts:
        return None
    return np.concatenate(vs), np.asarray(ts, dtype=np.intp).reshape(-1, 3)


def local_tin(tin, offset) -> tuple[np.ndarray, np.ndarray]:
    """``tin`` moved into the case's local frame."""
    v, t = tin
    return np.asarray(v) - np.asarray(offset), t


def height_function(tin):
    """``f(xy (n, 2)) -> z (n,)``: linear over the TIN's vertices, nearest outside their hull."""
    v, t = tin
    used = np.unique(np.asarray(t).ravel())
    p = np.asarray(v)[used]
    lin = LinearNDInterpolator(p[:, :2], p[:, 2])
    near = NearestNDInterpolator(p[:, :2], p[:, 2])

    def f(xy):
        xy = np.asarray(xy, dtype=np.float64).reshape(-1, 2)
        z = lin(xy)
        bad = ~np.isfinite(z)
        if bad.any():
            z[bad] = near(xy[bad])
        return z
    return f


def terrain_grid(domain, cells: tuple[int, int, int], level: int, height, pad: int = 2):
    """The ground grid of a domain.

    Parameters
    ----------
    domain : Domain
    cells : (3,) int
        blockMesh cells (along the wind, across, up).
    level : int
        Refinement level of the terrain (grid step = background cell / 2**level).
    height : callable
        :func:`height_function`.
    pad : int
        Grid steps beyond the box on each side.

    Returns
    -------
    vertices (n, 3), triangles (t, 3) (upward), inner : (t,) bool
        ``inner`` marks the triangles inside the box's plan.
    """
    nx, ny = cells[0] * 2 ** level, cells[1] * 2 ** level
    dx = (domain.x_max - domain.x_min) / nx
    dy = (domain.y_max - domain.y_min) / ny
    iu = np.arange(-pad, nx + pad + 1)
    iv = np.arange(-pad, ny + pad + 1)
    U, V = np.meshgrid(domain.x_min + iu * dx, domain.y_min + iv * dy, indexing="ij")
    xy = from_wind_frame(np.column_stack([U.ravel(), V.ravel()]), np.asarray(domain.centre), domain.wind_direction)
    z = height(xy)
    verts = np.column_stack([xy, z])
    m, n = len(iu), len(iv)
    idx = np.arange(m * n).reshape(m, n)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    tris = np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    I, J = np.meshgrid(iu[:-1], iv[:-1], indexing="ij")
    inside = ((I >= 0) & (I < nx) & (J >= 0) & (J < ny)).ravel()
    return verts, tris, np.concatenate([inside, inside])


def volume_under(verts: np.ndarray, tris: np.ndarray, floor: float) -> float:
    """Volume (m3) between the triangles (upward, a height field) and the plane ``z = floor``."""
    P = verts[tris]
    area = 0.5 * np.abs((P[:, 1, 0] - P[:, 0, 0]) * (P[:, 2, 1] - P[:, 0, 1])
                        - (P[:, 2, 0] - P[:, 0, 0]) * (P[:, 1, 1] - P[:, 0, 1]))
    return float((area * (P[:, :, 2].mean(axis=1) - floor)).sum())


def solid_under(verts: np.ndarray, tris: np.ndarray, bottom: float):
    """The closed solid (manifold3d) between a grid height field and ``z = bottom``."""
    n = len(verts)
    low = verts.copy()
    low[:, 2] = bottom
    V = np.vstack([verts, low])
    T = [tris, tris[:, ::-1] + n]
    e = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    key = {tuple(x) for x in e.tolist()}
    border = [(a, b) for a, b in e.tolist() if (b, a) not in key]
    side = []
    for a, b in border:  # outward: the top edge a->b seen from outside, down to the bottom copy
        side.append((b, a, a + n))
        side.append((b, a + n, b + n))
    T.append(np.asarray(side, dtype=np.intp))
    T = np.concatenate(T)
    return m3.Manifold(m3.Mesh64(vert_properties=np.ascontiguousarray(V, dtype=np.float64),
                                 tri_verts=np.ascontiguousarray(T, dtype=np.uint64)))
