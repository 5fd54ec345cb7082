"""The region of a CFD case: a rectangle or a circle in the input CRS, and the buildings it takes.

A building is in the region when the convex hull of its vertices (map plane) meets the region;
a building cut by the region's edge is kept whole (never clipped), one wholly outside is left out.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, Sequence

import numpy as np
from shapely import MultiPoint
from shapely.geometry import Point, box

from lod2energy.errors import ParameterError
from lod2energy.model import Building


@dataclass(frozen=True)
class Region:
    """A rectangle ``(xmin, ymin, xmax, ymax)`` or a circle ``(cx, cy, r)`` (input CRS units, m).

    ``kind`` is "all" (no region given: every building), "box" or "circle".
    """
    kind: str = "all"
    bounds: tuple[float, ...] = ()

    def shape(self):
        """The shapely geometry of the region, or None for "all"."""
        if self.kind == "box":
            return box(*self.bounds)
        if self.kind == "circle":
            cx, cy, r = self.bounds
            return Point(cx, cy).buffer(r, quad_segs=64)
        return None

    def as_dict(self) -> dict:
        if self.kind == "box":
            return {"kind": "box", "xmin": self.bounds[0], "ymin": self.bounds[1],
                    "xmax": self.bounds[2], "ymax": self.bounds[3]}
        if self.kind == "circle":
            return {"kind": "circle", "centre": list(self.bounds[:2]), "radius": self.bounds[2]}
        return {"kind": "all"}


def make_region(region: Sequence[float] | None = None, centre: Sequence[float] | None = None,
                radius: float | None = None) -> Region:
    """Region from ``--region xmin,ymin,xmax,ymax`` or ``--centre X,Y --radius R``.

    Raises
    ------
    ParameterError
        Both forms given, a centre without radius (or the reverse), a non-finite number, an
        empty rectangle or a non-positive radius.
    """
    if region is not None and (centre is not None or radius is not None):
        raise ParameterError("give either --region or --centre/--radius, not both")
    if region is not None:
        b = tuple(float(x) for x in region)
        if len(b) != 4 or not all(math.isfinite(x) for x in b):
            raise ParameterError(f"--region needs four finite numbers xmin,ymin,xmax,ymax, not {region!r}")
        if not (b[2] > b[0] and b[3] > b[1]):
            raise ParameterError(f"--region {','.join(f'{x:g}' for x in b)}: xmax must exceed xmin and ymax ymin")
        return Region("box", b)
    if centre is not None or radius is not None:
        if centre is None or radius is None:
            raise ParameterError("--centre and --radius go together")
        c = tuple(float(x) for x in centre)
        r = float(radius)
        if len(c) != 2 or not all(math.isfinite(x) for x in c + (r,)):
            raise ParameterError(f"--centre needs two finite numbers X,Y and --radius one, not {centre!r}, {radius!r}")
        if r <= 0:
            raise ParameterError(f"--radius must be positive, not {r:g}")
        return Region("circle", c + (r,))
    return Region()


def building_hull(b: Building):
    """Convex hull (shapely) of a building's vertices in the map plane, or None without vertices."""
    v = np.asarray(b.vertices)
    if len(v) == 0:
        return None
    return MultiPoint(v[:, :2]).convex_hull


def select(buildings: Iterable[Building], region: Region) -> tuple[list[Building], list[str]]:
    """Buildings meeting the region (kept whole) and the ids of those left out.

    Returns
    -------
    (included buildings, excluded ids)
    """
    shape = region.shape()
    inside, outside = [], []
    for b in buildings:
        if shape is None:
            inside.append(b)
            continue
        h = building_hull(b)
        (inside if h is not None and h.intersects(shape) else outside).append(b)
    return inside, [b.id for b in outside]
