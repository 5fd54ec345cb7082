"""The window of a wall piece as ``window_for`` found it before its shortcuts: always the
24-step bisection of the largest centred box that fits (the oracle of the equivalence tests)."""
from __future__ import annotations

import math

import numpy as np
from shapely.geometry import Polygon, box

from lod2energy.geometry import polygons


def bisection_window(piece: np.ndarray, wwr: float):
    """The window (4, 3) of wall piece ``piece`` (k, 3) at window-to-wall ratio ``wwr``, or None."""
    area = polygons.polygon_area3d(piece)
    n = polygons.unit(polygons.newell_normal(piece))
    u, v = polygons.wall_basis(n)
    c0 = piece.mean(axis=0)
    xy = np.column_stack([(piece - c0) @ u, (piece - c0) @ v])
    poly = Polygon(xy)
    cen = np.asarray(poly.centroid.coords[0])
    w, h = np.ptp(xy[:, 0]), np.ptp(xy[:, 1])
    lo_t, hi_t = 0.0, 1.0
    for _ in range(24):
        t = (lo_t + hi_t) / 2
        r = box(cen[0] - t * w / 2, cen[1] - t * h / 2, cen[0] + t * w / 2, cen[1] + t * h / 2)
        lo_t, hi_t = (t, hi_t) if poly.contains(r) else (lo_t, t)
    t = min(math.sqrt(wwr * area / (w * h)), 0.95 * lo_t)
    if t <= 0:
        return None
    hw, hh = t * w / 2, t * h / 2
    rect = np.array([[cen[0] - hw, cen[1] + hh], [cen[0] - hw, cen[1] - hh],
                     [cen[0] + hw, cen[1] - hh], [cen[0] + hw, cen[1] + hh]])
    return c0 + rect[:, :1] * u + rect[:, 1:2] * v
