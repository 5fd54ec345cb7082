"""Geographic coordinates (latitude, longitude, height) to a local metric frame and back.

Every check and export works in metres: a city model in a geographic CRS (Japan's PLATEAU
tiles are in EPSG:6697, JGD2011 latitude / longitude / height) is moved into a local
east-north-up (ENU) frame tangent to the GRS80 ellipsoid at the tile's origin. Geodetic to
Earth-centred (ECEF) coordinates is exact and ECEF to ENU is a rotation, so distances,
areas, volumes and angles are kept exactly; only "up" tilts with the distance from the
origin (0.009 degrees per km), far below any tolerance of the validator. Heights are taken
as ellipsoidal: a geoid height that is constant over a tile only shifts the frame.

>>> f = LocalFrame(35.68, 139.76, 0.0)
>>> p = f.to_local(np.array([[35.68, 139.76 + 0.001, 10.0]]))
>>> round(float(p[0, 0]), 2), round(float(p[0, 2]), 2)     # 90.5 m east, 10 m up
(90.53, 10.0)
>>> np.allclose(f.to_geodetic(p), [[35.68, 139.761, 10.0]], atol=1e-10)
True
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: GRS80 (WGS84 differs by 0.1 mm in the semi-minor axis).
A = 6378137.0
F = 1.0 / 298.257222101
E2 = F * (2.0 - F)


def geodetic_to_ecef(lat: np.ndarray, lon: np.ndarray, h: np.ndarray) -> np.ndarray:
    """ECEF coordinates ``(n, 3)`` (m) of geodetic latitude / longitude (degrees) and
    ellipsoidal height (m)."""
    phi, lam = np.radians(lat), np.radians(lon)
    n = A / np.sqrt(1.0 - E2 * np.sin(phi) ** 2)
    return np.stack([(n + h) * np.cos(phi) * np.cos(lam),
                     (n + h) * np.cos(phi) * np.sin(lam),
                     (n * (1.0 - E2) + h) * np.sin(phi)], axis=-1)


def ecef_to_geodetic(xyz: np.ndarray) -> np.ndarray:
    """Latitude, longitude (degrees) and ellipsoidal height (m) ``(n, 3)`` of ECEF points
    (iterated to well under a micrometre for points near the surface)."""
    x, y, z = xyz[..., 0], xyz[..., 1], xyz[..., 2]
    lam = np.arctan2(y, x)
    p = np.hypot(x, y)
    phi = np.arctan2(z, p * (1.0 - E2))
    h = np.zeros_like(p)
    for _ in range(6):
        n = A / np.sqrt(1.0 - E2 * np.sin(phi) ** 2)
        h = p / np.cos(phi) - n
        phi = np.arctan2(z, p * (1.0 - E2 * n / (n + h)))
    n = A / np.sqrt(1.0 - E2 * np.sin(phi) ** 2)
    h = p / np.cos(phi) - n
    return np.stack([np.degrees(phi), np.degrees(lam), h], axis=-1)


@dataclass(frozen=True)
class LocalFrame:
    """An east-north-up frame tangent to the ellipsoid at ``(lat0, lon0, h0)``.

    Parameters
    ----------
    lat0, lon0 : float, degrees
    h0 : float, m
    lat_first : bool
        Axis order of the geographic coordinates: (lat, lon, h) as EPSG defines its
        geographic CRSs (PLATEAU writes them so), else (lon, lat, h) as OGC CRS84.
    """

    lat0: float
    lon0: float
    h0: float = 0.0
    lat_first: bool = True

    @property
    def _rotation(self) -> np.ndarray:
        phi, lam = np.radians(self.lat0), np.radians(self.lon0)
        return np.array([[-np.sin(lam), np.cos(lam), 0.0],
                         [-np.sin(phi) * np.cos(lam), -np.sin(phi) * np.sin(lam), np.cos(phi)],
                         [np.cos(phi) * np.cos(lam), np.cos(phi) * np.sin(lam), np.sin(phi)]])

    @property
    def _origin(self) -> np.ndarray:
        return geodetic_to_ecef(np.array(self.lat0), np.array(self.lon0), np.array(self.h0))

    def to_local(self, coords: np.ndarray) -> np.ndarray:
        """ENU coordinates ``(n, 3)`` (m) of geographic coordinates ``(n, 3)`` in the file's
        axis order."""
        c = np.asarray(coords, dtype=np.float64).reshape(-1, 3)
        lat, lon = (c[:, 0], c[:, 1]) if self.lat_first else (c[:, 1], c[:, 0])
        return (geodetic_to_ecef(lat, lon, c[:, 2]) - self._origin) @ self._rotation.T

    def to_geodetic(self, enu: np.ndarray) -> np.ndarray:
        """Geographic coordinates ``(n, 3)`` in the file's axis order of ENU points (m)."""
        e = np.asarray(enu, dtype=np.float64).reshape(-1, 3)
        g = ecef_to_geodetic(e @ self._rotation + self._origin)
        return g if self.lat_first else g[:, [1, 0, 2]]

    #: The frame of a geographic CRS (degrees), not of a linear unit (:class:`ScaledFrame`).
    geographic = True

    def to_file(self, enu: np.ndarray) -> np.ndarray:
        """The file's coordinates of points in the frame (:meth:`to_geodetic`)."""
        return self.to_geodetic(enu)

    def as_dict(self) -> dict:
        return {"lat0": self.lat0, "lon0": self.lon0, "h0": self.h0, "axes": "east, north, up (m)",
                "ellipsoid": "GRS80", "geographic_axis_order": "lat, lon, h" if self.lat_first else "lon, lat, h"}


@dataclass(frozen=True)
class ScaledFrame:
    """Coordinates of a projected CRS in a linear unit other than the metre (US survey feet,
    feet), in metres: every check and export sees metres, writers of the file's own CRS move
    them back.

    Parameters
    ----------
    to_metre, vertical_to_metre : float
        Metres in one horizontal / height unit (pyproj's ``unit_conversion_factor``).
    unit, vertical_unit : str
        The units' names.

    >>> f = ScaledFrame(0.3048006096012192, 0.3048006096012192, "US survey foot", "US survey foot")
    >>> round(float(f.to_local(np.array([[0.0, 0.0, 342.8]]))[0, 2]), 2)
    104.49
    """

    to_metre: float
    vertical_to_metre: float
    unit: str = "metre"
    vertical_unit: str = "metre"
    geographic = False

    @property
    def _factors(self) -> np.ndarray:
        return np.array([self.to_metre, self.to_metre, self.vertical_to_metre])

    def to_local(self, coords: np.ndarray) -> np.ndarray:
        """Metres ``(n, 3)`` of coordinates ``(n, 3)`` in the file's units."""
        return np.asarray(coords, dtype=np.float64).reshape(-1, 3) * self._factors

    def to_file(self, metres: np.ndarray) -> np.ndarray:
        """The file's coordinates ``(n, 3)`` of points in metres ``(n, 3)``."""
        return np.asarray(metres, dtype=np.float64).reshape(-1, 3) / self._factors

    to_geodetic = to_file

    def as_dict(self) -> dict:
        return {"unit": self.unit, "to_metre": self.to_metre, "vertical_unit": self.vertical_unit,
                "vertical_to_metre": self.vertical_to_metre}
