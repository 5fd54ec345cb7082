"""A building's footprint: the union of its envelope's projections, in metres and in WGS84.

The footprint of the GIS layer (:mod:`lod2energy.exporters.geojson.writer`) and of the hand-offs
(:mod:`lod2energy.exporters.handoff`): the union of the 2D projections of the envelope's faces
(an overhanging storey or roof counts; a Building with its BuildingParts is one footprint),
snapped to a 1 cm grid so that faces sharing an edge leave no sliver; taken to WGS84 through the
file's CRS with pyproj (:func:`lod2energy.site.to_wgs84`) as ``[longitude, latitude]``, exterior
rings counter-clockwise and holes clockwise, 8 decimals (about 1 mm), as RFC 7946 asks.
"""
from __future__ import annotations

from typing import Any, Sequence

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon

from lod2energy.model import Building
from lod2energy.site import to_wgs84

#: Decimal places of the coordinates (1e-8 degree is about 1 mm).
DECIMALS = 8
#: Snapping grid of the footprint union, m (ten times the coordinates' precision, so that no
#: two vertices of the snapped footprint fall on one rounded position).
GRID = 0.01
#: Footprint pieces and holes smaller than this are dropped, m2.
MIN_AREA = 0.01


def footprint(b: Building, lod: str | None = None):
    """The building's footprint: union of its envelope faces' projections on the xy plane.

    Parameters
    ----------
    b : Building
        Coordinates in metres (a projected CRS, or the local frame of a geographic file).
    lod : str, optional
        The envelope's LoD (default: the building's highest).

    Returns
    -------
    shapely Polygon or MultiPolygon, or None
        In the building's xy coordinates (m); None when no face has a projected area.
    """
    v = np.asarray(b.vertices, dtype=np.float64)
    polys = []
    for _, _, g in b.envelope(lod):
        for _, hi, _, s in g.iter_surfaces():
            if hi > 0:
                continue
            rings = [v[np.asarray(r, dtype=np.intp)][:, :2] for r in s.rings]
            if len(rings[0]) < 3 or not np.all(np.isfinite(rings[0])):
                continue
            p = Polygon(rings[0], [r for r in rings[1:] if len(r) >= 3])
            if not p.is_valid:
                p = shapely.make_valid(p)
            if p.area > 1e-9:
                polys.append(p)
    if not polys:
        return None
    u = shapely.union_all(polys, grid_size=GRID)
    parts = [g for g in getattr(u, "geoms", [u]) if g.geom_type == "Polygon" and g.area >= MIN_AREA]
    if not parts:
        return None
    clean = [Polygon(p.exterior.coords, [h.coords for h in p.interiors if Polygon(h).area >= MIN_AREA])
             for p in parts]
    return clean[0] if len(clean) == 1 else MultiPolygon(clean)


def _ring_lonlat(xy: np.ndarray, z: float, crs: Any, frame) -> list[list[float]]:
    p = np.column_stack([xy, np.full(len(xy), z)])
    ll = to_wgs84(p, crs, frame)
    return [[round(float(lon), DECIMALS), round(float(lat), DECIMALS)] for lat, lon in ll]


def _signed_area(ring: Sequence[Sequence[float]]) -> float:
    a = np.asarray(ring, dtype=np.float64)
    return 0.5 * float(np.sum(a[:-1, 0] * a[1:, 1] - a[1:, 0] * a[:-1, 1]))


def _oriented(ring: list, ccw: bool) -> list:
    return ring if (_signed_area(ring) > 0) == ccw else ring[::-1]


def footprint_geometry(b: Building, crs: Any = None, frame=None, lod: str | None = None, fp=None) -> dict | None:
    """The GeoJSON geometry (WGS84, ``[lon, lat]``, RFC 7946 winding) of ``b``'s footprint
    (``fp``: :func:`footprint` of ``b`` when the caller has it).

    Raises
    ------
    lod2energy.site.SiteError
        The coordinates cannot be placed on the Earth (no CRS, unknown CRS).
    """
    fp = footprint(b, lod) if fp is None else fp
    if fp is None:
        return None
    v = np.asarray(b.vertices, dtype=np.float64)
    fin = v[np.all(np.isfinite(v), axis=1)]
    z = float(fin[:, 2].min()) if len(fin) else 0.0
    # one transform of all the rings together: to_wgs84 chooses the axis order once per call
    rings = []
    for p in getattr(fp, "geoms", [fp]):
        rings.append([np.asarray(p.exterior.coords)[:, :2]] + [np.asarray(h.coords)[:, :2] for h in p.interiors])
    flat = np.concatenate([r for poly in rings for r in poly])
    ll = _ring_lonlat(flat, z, crs, frame)
    polys, k = [], 0
    for poly in rings:
        out = []
        for i, r in enumerate(poly):
            ring = ll[k:k + len(r)]
            k += len(r)
            ring[-1] = list(ring[0])
            out.append(_oriented(ring, ccw=(i == 0)))
        polys.append(out)
    if len(polys) == 1:
        return {"type": "Polygon", "coordinates": polys[0]}
    return {"type": "MultiPolygon", "coordinates": polys}
