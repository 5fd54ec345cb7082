"""Is a geometry's size believable for a building? Checked before the repair ladder runs, and
on its result (a hollow result goes further up the ladder).

A geometry with non-finite coordinates, or spanning kilometres, has misplaced vertices (a
no-data value such as ``-2**31`` in integer CityJSON coordinates, a wrong CRS or unit). No
repair can recover the intended shape from it, and the global stages would not end: the work
of CGAL's alpha wrap grows with the wrapped surface area (a building reaching 2,000 km down
has some 10^8 m2 of walls), and it runs in C++ out of reach of the time budget. The ladder
therefore leaves such a geometry as it is, stage "irreparable", with the reason. So it does
with a geometry that encloses no volume (:func:`flat`: one face, coplanar faces, a face
repeated): a wrap or an extrusion of it would invent a shape the input did not have.

After the ladder, a result is *hollow* when its volume is under a quarter of the convex hull
of the input (:data:`HOLLOW_FRACTION`) while the input is not itself thin (hull volume over
hull area at least :data:`THIN`, m) and not a closed solid of about that volume itself: the
repair wrapped a skin (walls modelled on both sides, an open shell) into a thin-walled body
instead of closing the building. :func:`not_hollow` then takes the global stages' result,
else the convex hull, and logs what it did.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from lod2energy.polymesh import PolyMesh, signed_volume, topology

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


def flat(m: PolyMesh, thickness: float) -> str | None:
    """Why ``m`` encloses no volume (every vertex it uses within ``thickness`` of one plane:
    one face, coplanar faces, a face repeated), or None when it may.

    Parameters
    ----------
    m : PolyMesh
        One shell, vertices in m.
    thickness : float, m
        Largest distance from the best-fitting plane of a flat input (the planarity tolerance).

    Returns
    -------
    str or None
        A one-line message, e.g. ``"no volume: all 4 vertices within 0 m of one plane (6 faces):
        nothing to repair into a solid"``.
    """
    used = np.unique([i for f in m.faces for r in f.rings for i in r]).astype(np.int64)
    if len(used) == 0:
        return None
    P = np.asarray(m.vertices, dtype=np.float64)[used]
    if not np.isfinite(P).all():
        return None
    P = P - P.mean(axis=0)
    if len(P) >= 3:
        n = np.linalg.svd(P, full_matrices=False)[2][-1]
        d = float(np.abs(P @ n).max())
    else:
        d = 0.0
    if d > thickness:
        return None
    return (f"no volume: all {len(used)} vertices within {d:.3g} m of one plane ({m.n_faces} faces): "
            "nothing to repair into a solid")


HOLLOW_FRACTION = 0.25
"""A repaired volume under this fraction of the input's convex hull volume is hollow."""

THIN = 0.1
"""An input whose convex hull has volume / area under this (m) is thin (a wall, a slab: a
slab of thickness t has about t / 2): a small repaired volume is then no sign of hollowness."""


def _hull(m: PolyMesh) -> tuple[float, float]:
    """Volume (m3) and area (m2) of the convex hull of the vertices ``m`` uses; (0, 0) if flat."""
    from scipy.spatial import ConvexHull, QhullError
    used = np.unique([i for f in m.faces for r in f.rings for i in r]).astype(np.int64)
    if len(used) < 4:
        return 0.0, 0.0
    P = np.asarray(m.vertices, dtype=np.float64)[used]
    try:
        h = ConvexHull(P - P.mean(axis=0))
    except (QhullError, ValueError):
        return 0.0, 0.0
    return float(h.volume), float(h.area)


def hollow(m_in: PolyMesh, res: PolyMesh | None, input_volume: float | None = None,
           fraction: float = HOLLOW_FRACTION, thin: float = THIN) -> str | None:
    """Why the repair result ``res`` of ``m_in`` is hollow, or None when it is not.

    Parameters
    ----------
    m_in : PolyMesh
        The input shell.
    res : PolyMesh or None
        The repaired shell (closed, outward).
    input_volume : float, m3, optional
        The input's own volume when it is a closed shell: a result about as large (at least
        90 %) is not hollow however concave the building is (courtyards, L-shapes).
    """
    if res is None or not res.faces:
        return None
    hv, ha = _hull(m_in)
    if hv <= 0 or hv / ha < thin:
        return None
    v = signed_volume(res)
    if v >= fraction * hv or (input_volume is not None and v >= 0.9 * input_volume):
        return None
    return (f"hollow result: {v:.2f} m3, under {fraction:g} of the input's convex hull "
            f"({hv:.2f} m3)")


def not_hollow(m_in: PolyMesh, stage: str, res: PolyMesh | None, log: list[str],
               retry: Callable[[], tuple], hull: Callable[[], PolyMesh | None],
               input_volume: float | None = None) -> tuple[str, PolyMesh | None, list[str]]:
    """The ladder's result, or a higher stage's when it is :func:`hollow`.

    Parameters
    ----------
    retry : callable
        The global stages on the cleaned input: ``() -> (stage, result, log)``.
    hull : callable
        ``() -> convex hull result or None`` (valid or None), the last rung.

    Returns
    -------
    stage, result, log
        ``log`` extended with what was found and done.
    """
    why = hollow(m_in, res, input_volume)
    if why is None:
        return stage, res, log
    log = list(log) + [f"{stage}: {why}"]
    if stage not in ("roofs", "alphashape", "footprint", "hull"):
        gstage, gres, glog = retry()
        if gres is not None and hollow(m_in, gres, input_volume) is None:
            return gstage, gres, log + list(glog) + [f"escalated to {gstage}"]
    h = hull()
    if h is not None:
        return "hull", h, log + ["escalated to the convex hull"]
    return stage, res, log + ["no higher stage closes it: kept, reported hollow"]


def closed_volume(m: PolyMesh) -> float | None:
    """Volume (m3) of ``m`` when it is a closed 2-manifold shell, else None."""
    t = topology(m)
    if t.boundary or t.nonmanifold or not m.faces:
        return None
    return abs(signed_volume(m))


__all__ = ["HOLLOW_FRACTION", "MAX_EXTENT", "THIN", "closed_volume", "flat", "hollow", "implausible",
           "not_hollow"]
