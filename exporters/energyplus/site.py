"""``Site:Location`` from the buildings' position and ground temperatures from the weather file.

The site is always the buildings' own (:func:`lod2energy.site.site_of`, through the CRS of
their file or the user's ``--crs``); a weather file's location never stands in for it.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from lod2energy import site as site_mod
from lod2energy.exporters.energyplus.names import sanitize_name
from lod2energy.site import SiteError, read_weather_header


def read_epw_header(path: str | Path) -> tuple[dict | None, list[float] | None]:
    """The weather station's ``LOCATION`` fields (None when the EPW has none) and 12 monthly
    ground temperatures (C, ~2 m depth; None when it has none) (:func:`lod2energy.site.read_weather_header`)."""
    h = read_weather_header(path)
    if h is None:
        return None, None
    site = {"name": sanitize_name(h.name, 60), "latitude": h.latitude, "longitude": h.longitude,
            "time_zone": h.time_zone, "elevation": h.elevation}
    return site, (list(h.ground_temperatures) if h.ground_temperatures is not None else None)


def _group_site(gb, crs, frame, stations):
    """``Site:Location`` fields of a group of buildings, warnings, stats and the weather file
    (the station of ``stations`` nearest to the site, :func:`lod2energy.site.nearest_station`;
    None without ``stations``).

    Raises
    ------
    SiteError
        The buildings cannot be placed on the Earth (no CRS pyproj reads, coordinates outside it).
    """
    pts = np.concatenate([b.vertices for b in gb if len(b.vertices)]) if any(len(b.vertices) for b in gb) \
        else np.zeros((0, 3))
    name = sanitize_name(gb[0].id if len(gb) == 1 else "Dataset", 60)
    if not len(pts):
        raise SiteError("no coordinates: Site:Location cannot be found")
    st = site_mod.site_of(pts, crs, frame, name)
    warns, stats = [], {"site": {"latitude": st.latitude, "longitude": st.longitude, "elevation": st.elevation,
                                 "time_zone": st.time_zone}}
    epw = None
    if stations:
        epw, station = site_mod.nearest_station(st, stations)
        stats["weather_file"] = epw
        if station is not None:
            d, w = site_mod.weather_distance(st, station)
            stats["weather_distance_km"] = d
            stats["weather_station"] = station.name
            if w:
                warns.append(w)
    return st.as_idf(), warns, stats, epw
