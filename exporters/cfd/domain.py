"""The CFD domain box: sized by the urban-flow guidelines around the tallest building, turned to the wind.

Guidelines (the numbers are stated again in every case's README):

- COST Action 732 (Franke, Hellsten, Schluenzen and Carissimo 2007, *Best practice guideline
  for the CFD simulation of flows in the urban environment*, section 5.2) and AIJ (Tominaga,
  Mochida, Yoshie, Kataoka, Nozu, Yoshikawa and Shirasawa 2008, *AIJ guidelines for practical
  applications of CFD to pedestrian wind environment around buildings*, J. Wind Eng. Ind.
  Aerodyn. 96, 1749-1761): the inlet 5 H_max upstream of the built area, the lateral
  boundaries 5 H_max beside it, the outlet 15 H_max downstream, the top 5 H_max above the
  tallest building (a domain height of 6 H_max above the ground), H_max being the height of
  the tallest building above the ground level;
- blockage ratio (frontal area of the buildings over the domain's cross-section) under 3%
  (Franke et al. 2007; Tominaga et al. 2008); when it is not, the lateral margins and the
  height are enlarged by the same factor until it is.

Frame: the wind direction is meteorological, the direction the wind comes FROM in degrees
clockwise from north (0 = from the north, 90 = from the east, 270 = from the west). The
domain frame has its x axis along the flow (downwind, ``(-sin d, -cos d)`` in map east/north),
y to the left of the flow, z up; its origin is the rotation centre (the centre of the built
area) at the ground level.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely import box, polygons, union_all

from lod2energy.errors import ParameterError

#: Guideline distances in multiples of H_max (Franke et al. 2007; Tominaga et al. 2008).
UPSTREAM_H = 5.0
LATERAL_H = 5.0
DOWNSTREAM_H = 15.0
HEIGHT_H = 6.0
#: Largest blockage ratio the guidelines accept.
MAX_BLOCKAGE = 0.03


def flow_direction(wind_direction: float) -> np.ndarray:
    """Unit vector (east, north) the air moves to for a meteorological wind direction (deg, from)."""
    if not math.isfinite(wind_direction):
        raise ParameterError(f"--wind-direction must be a finite number of degrees, not {wind_direction!r}")
    a = math.radians(wind_direction)
    return np.array([-math.sin(a), -math.cos(a)])


def to_wind_frame(xy: np.ndarray, centre: np.ndarray, wind_direction: float) -> np.ndarray:
    """Map coordinates ``(n, 2)`` (m) -> domain frame ``(n, 2)``: x downwind, y to the left."""
    ex = flow_direction(wind_direction)
    ey = np.array([-ex[1], ex[0]])
    d = np.asarray(xy, dtype=np.float64).reshape(-1, 2) - np.asarray(centre, dtype=np.float64)[:2]
    return np.stack([d @ ex, d @ ey], axis=1)


def from_wind_frame(uv: np.ndarray, centre: np.ndarray, wind_direction: float) -> np.ndarray:
    """Domain frame ``(n, 2)`` -> map coordinates ``(n, 2)`` (m)."""
    ex = flow_direction(wind_direction)
    ey = np.array([-ex[1], ex[0]])
    uv = np.asarray(uv, dtype=np.float64).reshape(-1, 2)
    return np.asarray(centre, dtype=np.float64)[:2] + uv[:, :1] * ex + uv[:, 1:2] * ey


@dataclass(frozen=True)
class Domain:
    """A domain box in the wind frame.

    Parameters
    ----------
    centre : (2,) float, m
        Rotation centre in the case's (local) map coordinates.
    wind_direction : float, deg
        Meteorological (from, clockwise from north).
    x_min, x_max, y_min, y_max : float, m
        Box extents in the wind frame (x downwind, y to the left).
    z_min, z_max : float, m
        Ground level and top.
    h_max : float, m
        Tallest building above the ground level.
    built_extent : (4,) float, m
        ``(x_min, x_max, y_min, y_max)`` of the buildings in the wind frame.
    frontal_area : float, m2
        Buildings' area projected on a plane normal to the wind.
    blockage_ratio : float
        ``frontal_area / ((y_max - y_min) * (z_max - z_min))``.
    enlarged : float
        Factor applied to the lateral margins and the height to meet the blockage limit (1 = none).
    floor : float or None, m
        Bottom of the box when it lies under ``z_min`` (a terrain surface meshed by
        snappyHexMesh above it); None: the box stands on the ground level ``z_min``.
    """
    centre: tuple[float, float]
    wind_direction: float
    x_min: float
    x_max: float
    y_min: float
    y_max: float
    z_min: float
    z_max: float
    h_max: float
    built_extent: tuple[float, float, float, float]
    frontal_area: float
    blockage_ratio: float
    enlarged: float = 1.0
    floor: float | None = None

    @property
    def bottom(self) -> float:
        """z of the box's bottom face (m)."""
        return self.z_min if self.floor is None else self.floor

    @property
    def size(self) -> tuple[float, float, float]:
        """Length (along the wind), width, height (m) of the box."""
        return (self.x_max - self.x_min, self.y_max - self.y_min, self.z_max - self.bottom)

    @property
    def volume(self) -> float:
        """m3."""
        lx, ly, lz = self.size
        return lx * ly * lz

    @property
    def flow_dir(self) -> tuple[float, float, float]:
        ex = flow_direction(self.wind_direction)
        return (float(ex[0]), float(ex[1]), 0.0)

    def corners(self) -> np.ndarray:
        """``(8, 3)`` corners in map coordinates, in blockMesh hex order (bottom 0-3, top 4-7,
        counter-clockwise seen from above, starting at the upwind right corner)."""
        uv = np.array([[self.x_min, self.y_min], [self.x_max, self.y_min],
                       [self.x_max, self.y_max], [self.x_min, self.y_max]])
        xy = from_wind_frame(uv, np.asarray(self.centre), self.wind_direction)
        bottom = np.column_stack([xy, np.full(4, self.bottom)])
        top = np.column_stack([xy, np.full(4, self.z_max)])
        return np.vstack([bottom, top])

    def contains(self, points: np.ndarray, margin: float = 0.0) -> np.ndarray:
        """Whether map points ``(n, 3)`` lie inside the box shrunk by ``margin`` (m)."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        uv = to_wind_frame(p[:, :2], np.asarray(self.centre), self.wind_direction)
        return ((uv[:, 0] > self.x_min + margin) & (uv[:, 0] < self.x_max - margin)
                & (uv[:, 1] > self.y_min + margin) & (uv[:, 1] < self.y_max - margin)
                & (p[:, 2] > self.bottom + margin) & (p[:, 2] < self.z_max - margin))

    def as_dict(self) -> dict:
        lx, ly, lz = self.size
        bx0, bx1, by0, by1 = self.built_extent
        return {
            "wind_direction_deg": self.wind_direction,
            "wind_direction_convention": "meteorological: direction the wind comes from, degrees clockwise from north",
            "flow_dir": list(self.flow_dir),
            "centre": list(self.centre),
            "h_max_m": round(self.h_max, 3),
            "ground_level_m": round(self.z_min, 3),
            "upstream_m": round(bx0 - self.x_min, 3),
            "downstream_m": round(self.x_max - bx1, 3),
            "lateral_m": [round(by0 - self.y_min, 3), round(self.y_max - by1, 3)],
            "top_above_ground_m": round(self.z_max - self.z_min, 3),
            "box_floor_m": round(self.bottom, 3),
            "length_m": round(lx, 3), "width_m": round(ly, 3), "height_m": round(lz, 3),
            "frontal_area_m2": round(self.frontal_area, 3),
            "blockage_ratio": round(self.blockage_ratio, 5),
            "blockage_limit": MAX_BLOCKAGE,
            "enlarged_factor": round(self.enlarged, 4),
            "corners": np.round(self.corners(), 4).tolist(),
        }


def size_domain(xy: np.ndarray, h_max: float, ground: float, wind_direction: float,
                frontal_area: float, centre: np.ndarray | None = None) -> Domain:
    """The guideline domain around buildings.

    Parameters
    ----------
    xy : (n, 2) float, m
        Building vertices (map plane).
    h_max : float, m
        Height of the tallest building above ``ground``.
    ground : float, m
        Ground level (the domain floor).
    wind_direction : float, deg
        Meteorological direction (from, clockwise from north).
    frontal_area : float, m2
        Buildings' area projected on a plane normal to the wind (see :func:`frontal_area`).
    centre : (2,) float, optional
        Rotation centre; default the centre of the buildings' bounding box.

    Returns
    -------
    Domain
        Inlet ``5 h_max`` upstream, sides ``5 h_max`` beside, outlet ``15 h_max`` downstream of
        the buildings' extent in the wind frame, top at ``ground + 6 h_max``; lateral margins and
        height enlarged together when the blockage ratio would exceed 3%.
    """
    xy = np.asarray(xy, dtype=np.float64).reshape(-1, 2)
    if len(xy) == 0:
        raise ParameterError("no building in the region: nothing to build a CFD domain around")
    if not (h_max > 0 and math.isfinite(h_max)):
        raise ParameterError(f"tallest building height must be positive, not {h_max!r}")
    if centre is None:
        centre = (xy.min(axis=0) + xy.max(axis=0)) / 2
    centre = np.asarray(centre, dtype=np.float64)[:2]
    uv = to_wind_frame(xy, centre, wind_direction)
    bx0, by0 = uv.min(axis=0)
    bx1, by1 = uv.max(axis=0)
    lat, top = LATERAL_H * h_max, HEIGHT_H * h_max
    width, height = (by1 - by0) + 2 * lat, top
    br = frontal_area / (width * height)
    factor = 1.0
    if br > MAX_BLOCKAGE:
        # width and height both scaled by f: the ratio drops by f^2
        factor = math.sqrt(br / MAX_BLOCKAGE) * 1.001
        new_w = width * factor
        lat = (new_w - (by1 - by0)) / 2
        top = height * factor
        width, height = new_w, top
        br = frontal_area / (width * height)
    return Domain((float(centre[0]), float(centre[1])), float(wind_direction),
                  float(bx0 - UPSTREAM_H * h_max), float(bx1 + DOWNSTREAM_H * h_max),
                  float(by0 - lat), float(by1 + lat), float(ground), float(ground + top), float(h_max),
                  (float(bx0), float(bx1), float(by0), float(by1)), float(frontal_area), float(br), float(factor))


def frontal_area(vertices: np.ndarray, tris: np.ndarray, wind_direction: float, ground: float) -> float:
    """Area (m2) of the triangles ``(t, 3)`` of ``vertices (n, 3)`` above ``ground`` projected on a
    vertical plane normal to the wind (the buildings' frontal area)."""
    v = np.asarray(vertices, dtype=np.float64)
    t = np.asarray(tris, dtype=np.intp).reshape(-1, 3)
    if len(t) == 0:
        return 0.0
    y = to_wind_frame(v[:, :2], np.zeros(2), wind_direction)[:, 1]
    P = np.stack([y[t], v[t][:, :, 2]], axis=2)  # (t, 3, 2)
    a = 0.5 * np.abs((P[:, 1, 0] - P[:, 0, 0]) * (P[:, 2, 1] - P[:, 0, 1])
                     - (P[:, 2, 0] - P[:, 0, 0]) * (P[:, 1, 1] - P[:, 0, 1]))
    P = P[a > 1e-9]
    if len(P) == 0:
        return 0.0
    shape = union_all(polygons(P))
    lo = float(P[:, :, 0].min()) - 1
    hi = float(P[:, :, 0].max()) + 1
    return float(shape.intersection(box(lo, ground, hi, float(P[:, :, 1].max()) + 1)).area)
