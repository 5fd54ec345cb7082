"""The real site of a building: EnergyPlus ``Site:Location`` from its own coordinates, ground
temperatures from the weather file, and the weather station's distance.

- **latitude / longitude**: the centre of the building's (or dataset's) bounding box, taken
  through its CRS to WGS84 with pyproj (the horizontal part of any CRS pyproj reads, AdV names
  included, :func:`lod2energy.crs.crs_info`), read in the CRS's own axis order (north first
  for the JGD plane CSs) unless only the other order falls in the CRS's area of use; a file
  in a geographic CRS is read in a local frame (:class:`lod2energy.geodesy.LocalFrame`) and
  goes back through it, one in feet is scaled back (:class:`lod2energy.geodesy.ScaledFrame`).
  A file with no CRS pyproj reads has no site: nothing is assumed.
- **elevation**: the lowest point of the geometry (m above the CRS's vertical datum: NAP,
  DHHN, TP; ellipsoidal where the file has no vertical datum), clipped to EnergyPlus's range
  -300 .. 8900 m.
- **time zone**: the standard time of the country (from the CRS, :data:`TIME_ZONES`; JGD
  CRSs mean Japan), else ``round(longitude / 15)`` hours.
- **ground temperatures**: the EPW header's ``GROUND TEMPERATURES`` row at the depth nearest
  to 2 m (12 monthly values), else ``None`` (the exporter writes 10 C and warns).
- **distance**: great-circle distance (km) from the site to the EPW's ``LOCATION``; more
  than :data:`MAX_WEATHER_KM` gives a warning.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from lod2energy import cache
from lod2energy.crs import crs_info, epsg_codes, no_crs_reason
from lod2energy.errors import Lod2EnergyError
from lod2energy.thermal import country_from_crs

#: Standard time (hours from UTC) by ISO country code.
TIME_ZONES = {"NL": 1.0, "DE": 1.0, "AT": 1.0, "CH": 1.0, "BE": 1.0, "FR": 1.0, "LU": 1.0, "DK": 1.0,
              "IT": 1.0, "ES": 1.0, "PL": 1.0, "CZ": 1.0, "NO": 1.0, "SE": 1.0, "FI": 2.0, "EE": 2.0,
              "GB": 0.0, "IE": 0.0, "PT": 0.0, "JP": 9.0}
#: JGD2000 / JGD2011 geographic and plane-rectangular CRSs (Japan).
_JGD = set(range(2443, 2462)) | set(range(6669, 6688)) | {4612, 6667, 6668, 6697, 4301}
MAX_WEATHER_KM = 50.0
EARTH_KM = 6371.0088


class SiteError(Lod2EnergyError, ValueError):
    """The coordinates cannot be placed on the Earth (no CRS pyproj reads, not finite)."""


@dataclass(frozen=True)
class Site:
    """A site for EnergyPlus ``Site:Location``.

    Attributes
    ----------
    name : str
    latitude, longitude : float, degrees (WGS84)
    time_zone : float, hours from UTC
    elevation : float, m
    source : str
        How it was found ("crs EPSG:28992", "local frame", "weather file").
    """
    name: str
    latitude: float
    longitude: float
    time_zone: float
    elevation: float
    source: str

    def as_idf(self) -> dict:
        """The fields :func:`exporters.energyplus.render.render_idf` writes."""
        return {"name": self.name, "latitude": self.latitude, "longitude": self.longitude,
                "time_zone": self.time_zone, "elevation": self.elevation}


def distance_km(lat1: float, lon1: float, lat2: float, lon2: float) -> float:
    """Great-circle (haversine) distance in km."""
    p1, p2 = math.radians(lat1), math.radians(lat2)
    dp, dl = p2 - p1, math.radians(lon2 - lon1)
    a = math.sin(dp / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    return 2 * EARTH_KM * math.asin(min(1.0, math.sqrt(a)))


def time_zone(longitude: float, country: str | None = None) -> float:
    """Standard time of ``country`` (:data:`TIME_ZONES`), else ``round(longitude / 15)``."""
    if country and country in TIME_ZONES:
        return TIME_ZONES[country]
    return float(max(-12, min(14, round(longitude / 15.0))))


def _country(crs: Any) -> str | None:

    if any(c in _JGD for c in epsg_codes(crs)):
        return "JP"
    return country_from_crs(crs)


def _inside(t, p: np.ndarray, area) -> np.ndarray:
    """Latitude/longitude of ``p`` read as (easting, northing), or as (northing, easting) when
    only that order falls inside the CRS's area of use (German Gauss-Krueger files write
    east-north although EPSG defines north-east). The caller gives a north-first CRS's
    points swapped, in its own order first: the JGD plane CSs, which PLATEAU writes in that
    order, have areas of use too large to tell the two orders apart."""
    out = []
    for a, b in ((0, 1), (1, 0)):
        lon, lat = t.transform(p[:, a], p[:, b])
        ll = np.column_stack([lat, lon])
        if area is None:
            return ll
        ok = bool(np.all(np.isfinite(ll)) and np.all((ll[:, 1] >= area.west - 0.5) & (ll[:, 1] <= area.east + 0.5)
                                                     & (ll[:, 0] >= area.south - 0.5) & (ll[:, 0] <= area.north + 0.5)))
        if ok:
            return ll
        out.append(ll)
    return out[0]


@cache.memoize("site_transformer", 32)
def _transformer(horizontal: str):
    """The pyproj ``Transformer`` from the horizontal CRS ``horizontal`` (``"EPSG:<code>"`` or
    WKT) to EPSG:4326 (x/y order) and the source CRS's area of use, built once per process
    (building one costs about 0.1 s CPU)."""
    from pyproj import Transformer
    from pyproj.exceptions import CRSError
    try:
        t = Transformer.from_crs(horizontal, "EPSG:4326", always_xy=True)
        return t, t.source_crs.area_of_use
    except CRSError as e:
        raise SiteError(f"pyproj cannot transform {horizontal} to latitude/longitude: {e}") from e


def to_wgs84(points: np.ndarray, crs: Any = None, frame=None) -> np.ndarray:
    """Latitude, longitude (degrees) ``(n, 2)`` of points ``(n, 3)`` in ``crs`` (or in the local
    ``frame`` of a geographic file; in metres of a ``frame`` of feet).

    Raises
    ------
    SiteError
        No CRS pyproj reads and no geographic frame, or non-finite results.
    """
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if frame is not None and getattr(frame, "geographic", True):
        g = frame.to_geodetic(p)
        ll = g[:, :2] if frame.lat_first else g[:, [1, 0]]
        src = "local frame"
    else:
        if frame is not None:  # metres of a CRS in feet: back to the file's unit
            p = frame.to_file(p)
        why = no_crs_reason(crs)
        if why:
            raise SiteError(f"{why}: the buildings cannot be placed on the Earth")
        info = crs_info(crs)
        if info.geographic:
            ll = p[:, :2] if info.lat_first else p[:, [1, 0]]
        else:
            t, area = _transformer(info.horizontal)
            ll = _inside(t, p[:, [1, 0, 2]] if info.north_first else p, area)
        src = f"crs {info.horizontal}"
    ll = np.asarray(ll, dtype=np.float64)
    if not np.all(np.isfinite(ll)) or np.any(np.abs(ll[:, 0]) > 90) or np.any(np.abs(ll[:, 1]) > 180):
        raise SiteError(f"coordinates do not map to latitude/longitude through {src}")
    return ll


def site_of(points: np.ndarray, crs: Any = None, frame=None, name: str = "Site") -> Site:
    """The :class:`Site` of a building or dataset from its coordinates ``(n, 3)`` (real-world,
    in ``crs``, or in the local ``frame`` of a geographic file)."""
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    p = p[np.all(np.isfinite(p), axis=1)]
    if len(p) == 0:
        raise SiteError("no finite coordinate")
    centre = (p.min(axis=0) + p.max(axis=0)) / 2
    centre[2] = p[:, 2].min()
    ll = to_wgs84(centre[None, :], crs, frame)[0]
    geographic = frame is not None and getattr(frame, "geographic", True)
    elev = float(frame.to_geodetic(centre[None, :])[0, 2]) if geographic else float(centre[2])
    country = _country(crs)
    src = "local frame" if geographic else f"crs {crs}"
    return Site(name, round(float(ll[0]), 6), round(float(ll[1]), 6), time_zone(float(ll[1]), country),
                round(min(max(elev, -300.0), 8900.0), 2), src)


@dataclass(frozen=True)
class WeatherHeader:
    """What an EPW header says about its station.

    Attributes
    ----------
    name : str
    latitude, longitude, time_zone, elevation : float
    ground_depth : float or None, m
    ground_temperatures : tuple of 12 float or None, C
    """
    name: str
    latitude: float
    longitude: float
    time_zone: float
    elevation: float
    ground_depth: float | None
    ground_temperatures: tuple[float, ...] | None


def read_weather_header(path: str | Path, depth: float = 2.0) -> WeatherHeader | None:
    """``LOCATION`` and ``GROUND TEMPERATURES`` (the depth nearest to ``depth`` m) of an EPW,
    None when the file has no readable ``LOCATION`` line."""
    try:
        with open(path, encoding="latin-1") as f:
            lines = [next(f, "") for _ in range(8)]
    except OSError:
        return None
    loc = lines[0].strip().split(",")
    if loc[0].upper() != "LOCATION" or len(loc) < 10:
        return None
    try:
        lat, lon, tz, el = (float(x) for x in loc[6:10])
    except ValueError:
        return None
    g_depth, g = None, None
    for line in lines:
        parts = line.strip().split(",")
        if parts[0].upper() == "GROUND TEMPERATURES" and len(parts) > 2:
            try:
                k = int(parts[1])
                blocks = [parts[2 + i * 16: 2 + (i + 1) * 16] for i in range(k)]
                best = min((b for b in blocks if len(b) == 16), key=lambda b: abs(float(b[0]) - depth))
                g_depth, g = float(best[0]), tuple(float(x) for x in best[4:16])
            except (ValueError, IndexError):
                g_depth, g = None, None
    return WeatherHeader("_".join(x for x in loc[1:4] if x), lat, lon, tz, el, g_depth, g)


@cache.memoize("weather_stations", 8)
def _stations(folder: str, listing: tuple) -> tuple:
    out = []
    for name, _, _ in listing:
        h = read_weather_header(os.path.join(folder, name))
        if h is not None:
            out.append((os.path.join(folder, name), h))
    return tuple(out)


def weather_stations(path: str | Path) -> list[tuple[str, WeatherHeader | None]]:
    """``(EPW path, header)`` of the weather file ``path``, or of every ``*.epw`` with a
    ``LOCATION`` line in the folder ``path`` (sorted by name; read once per process while the
    folder is unchanged). A single file without ``LOCATION`` gives ``[(path, None)]``."""
    p = str(path)
    if not os.path.isdir(p):
        return [(p, read_weather_header(p))]
    listing = tuple(sorted((e.name, e.stat().st_mtime_ns, e.stat().st_size) for e in os.scandir(p)
                           if e.name.lower().endswith(".epw") and e.is_file()))
    return list(_stations(p, listing))


def nearest_station(site: Site, stations: list[tuple[str, WeatherHeader | None]]
                    ) -> tuple[str, WeatherHeader | None]:
    """The station of ``stations`` nearest to ``site`` (great-circle distance); the first when
    none has a known location."""
    known = [s for s in stations if s[1] is not None]
    if not known:
        return stations[0]
    return min(known, key=lambda s: distance_km(site.latitude, site.longitude, s[1].latitude, s[1].longitude))


def weather_distance(site: Site, weather: WeatherHeader) -> tuple[float, str | None]:
    """``(km, warning or None)`` between the site and the weather station."""
    d = distance_km(site.latitude, site.longitude, weather.latitude, weather.longitude)
    warn = None
    if d > MAX_WEATHER_KM:
        warn = (f"weather file {weather.name} is {d:.0f} km from the site ({site.latitude:.4f}, "
                f"{site.longitude:.4f}): more than {MAX_WEATHER_KM:.0f} km, its climate may not be the site's")
    return round(d, 2), warn
