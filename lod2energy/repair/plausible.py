"""Is a geometry's size believable for a building? Checked before the repair ladder runs.

A geometry with non-finite coordinates, or spanning kilometres, has misplaced vertices (a
no-data value such as ``-2**31`` in integer CityJSON coordinates, a wrong CRS or unit). No
repair can recover the intended shape from it, and the global stages would not end: the work
of CGAL's alpha wrap grows with the wrapped surface area (a building reaching 2,000 km down
has some 10^8 m2 of walls), and it runs in C++ out of reach of the time budget. The ladder
therefore leaves such a geometry as it is, stage "irreparable", with the reason.
"""
from __future__ import annotations

import numpy as np

from lod2energy.polymesh import PolyMesh

MAX_EXTENT = 5_000.0
"""Largest plausible bounding-box side of one Building/BuildingPart geometry, m.

The longest and tallest buildings are about 1 km (Boeing's Everett factory, Jeddah Tower);
5 km leaves room for long terraces, sheds or dams modelled as one building. Beyond it the
coordinates are taken to be wrong.
"""


def _km(x: float) -> str:
    return f"{x / 1000:,.1f} km" if x >= 1000 else f"{x:,.1f} m"


def implausible(m: PolyMesh, max_extent: float = MAX_EXTENT) -> str | None:
    """Why the vertices used by ``m`` cannot be a building's, or None when they can.

    Parameters
    ----------
    m : PolyMesh
        One shell, vertices in m.
    max_extent : float, m
        Largest accepted side of the axis-aligned bounding box (:data:`MAX_EXTENT`).

    Returns
    -------
    str or None
        A one-line message, e.g. ``"geometry spans 2,147.6 km (z from -2,147,483.6 to 145.2 m,
        limit 5.0 km): coordinates implausible"``.
    """
    used = np.unique([i for f in m.faces for r in f.rings for i in r]).astype(np.int64)
    if len(used) == 0:
        return None
    P = np.asarray(m.vertices, dtype=np.float64)[used]
    finite = np.isfinite(P).all(axis=1)
    if not finite.all():
        return f"{int((~finite).sum())} vertices with non-finite (NaN/inf) coordinates"
    lo, hi = P.min(axis=0), P.max(axis=0)
    ext = hi - lo
    k = int(np.argmax(ext))
    if ext[k] <= max_extent:
        return None
    return (f"geometry spans {_km(float(ext[k]))} ({'xyz'[k]} from {lo[k]:,.1f} to {hi[k]:,.1f} m, "
            f"limit {_km(max_extent)}): coordinates implausible")


__all__ = ["MAX_EXTENT", "implausible"]
