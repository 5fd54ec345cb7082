"""``Site:Location`` and ground temperatures: from the weather file header and the buildings' position."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from lod2energy import site as site_mod
from lod2energy.exporters.energyplus.names import sanitize_name
from lod2energy.site import read_weather_header


#: Default site (Heino, NL; the project's weather file) when no weather file is given.
DEFAULT_SITE = {"name": "Heino_NL", "latitude": 52.43, "longitude": 6.27, "time_zone": 1.0, "elevation": 4.0}


def read_epw_header(path: str | Path) -> tuple[dict, list[float] | None]:
    """``Site:Location`` fields and 12 monthly ground temperatures (C, ~2 m depth) from an EPW
    (read by :func:`lod2energy.site.read_weather_header`; the Heino site when it has no LOCATION)."""
    site = dict(DEFAULT_SITE)
    h = read_weather_header(path)
    if h is None:
        return site, None
    site = {"name": sanitize_name(h.name, 60), "latitude": h.latitude, "longitude": h.longitude,
            "time_zone": h.time_zone, "elevation": h.elevation}
    return site, (list(h.ground_temperatures) if h.ground_temperatures is not None else None)


def _group_site(gb, crs, frame, epw_site, station):
    """``Site:Location`` fields of a group of buildings, warnings and stats."""
    pts = np.concatenate([b.vertices for b in gb if len(b.vertices)]) if any(len(b.vertices) for b in gb) \
        else np.zeros((0, 3))
    name = sanitize_name(gb[0].id if len(gb) == 1 else "Dataset", 60)
    st, why = site_mod.site_or_none(pts, crs, frame, name) if len(pts) else (None, "no coordinates")
    warns, stats = [], {}
    if st is None:
        warns.append(f"Site:Location from the weather file, not from the buildings: {why}")
        return epw_site, warns, stats
    stats["site"] = {"latitude": st.latitude, "longitude": st.longitude, "elevation": st.elevation,
                     "time_zone": st.time_zone}
    if station is not None:
        d, w = site_mod.weather_distance(st, station)
        stats["weather_distance_km"] = d
        if w:
            warns.append(w)
    return st.as_idf(), warns, stats
