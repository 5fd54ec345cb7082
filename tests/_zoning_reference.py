"""``zoning._clip`` as it was before its fast paths: the per-vertex numpy walk (the oracle of
the equivalence tests in test_idf_fast_paths.py and test_geometry_small_paths.py)."""
from __future__ import annotations

import numpy as np

from lod2energy.energy.zones.cut import DECIMALS, ON_PLANE


def clip_before_fast_path(poly: np.ndarray, c: float, keep_above: bool) -> np.ndarray:
    """The part of polygon ``poly`` (k, 3) above (``keep_above``) or below the plane z = ``c``
    (m), as (m, 3), or (0, 3) when fewer than 3 points are left."""
    out = []
    n = len(poly)
    s = (poly[:, 2] - c) if keep_above else (c - poly[:, 2])
    s = np.where(np.abs(s) <= ON_PLANE, 0.0, s)
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        sa, sb = s[i], s[(i + 1) % n]
        if sa >= 0:
            out.append(a if sa > 0 else np.array([a[0], a[1], c]))
        if (sa > 0 > sb) or (sa < 0 < sb):
            p, q = (a, b) if tuple(a) <= tuple(b) else (b, a)
            t = (c - p[2]) / (q[2] - p[2])
            x = p + t * (q - p)
            out.append(np.round(np.array([x[0], x[1], c]), DECIMALS))
    if len(out) < 3:
        return np.zeros((0, 3))
    o = np.array(out)
    keep = np.ones(len(o), bool)
    for i in range(len(o)):
        if np.all(np.abs(o[i] - o[i - 1]) < 1e-9):
            keep[i] = False
    o = o[keep]
    return o if len(o) >= 3 else np.zeros((0, 3))
