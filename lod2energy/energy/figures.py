"""A building's envelope figures as its energy model is written: areas by thermal boundary and UA.

One classification of every written surface (:func:`boundary_of`), used by the IDF writer on
the surfaces it writes and by the report, the CityJSON and the GeoJSON through the IDF
export's record, so that every figure of a building is the model's:

- ``roof``: roofs over outside air; ``wall``: walls over outside air, windows included;
- ``ground``: floors on the ground; ``floor_exposed``: floors over outside air;
- ``window``: windows (doors are part of their wall's opaque area);
- ``adiabatic``: party walls (and any other surface without heat flow);
- ``interzone``: floors / ceilings between zones of the model (not in the envelope).

``UA`` (W/K) sums U x A over the opaque part of the exterior walls, the roofs, the ground
floors, the exposed floors and the windows, without temperature-correction factors; U is the
construction's own: 1 / (its layers' R summed), surface films left out, and a window's
U-factor as written.
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping

#: The figures' boundary classes, in report order.
AREA_KEYS = ("roof", "wall", "ground", "floor_exposed", "window", "adiabatic")
#: The Energy ADE's ``thermalBoundaryType`` of each boundary class.
ADE_BOUNDARY = {"roof": "exterior", "wall": "exterior", "ground": "ground", "floor_exposed": "exterior",
                "adiabatic": "sharedWallOrFloor", "interzone": "intermediaryFloor"}


def boundary_of(surface_type: str, boundary: str) -> str:
    """The figures' class of a written surface.

    Parameters
    ----------
    surface_type : {"Wall", "Roof", "Ceiling", "Floor"}
        EnergyPlus's surface type (case-insensitive).
    boundary : {"Outdoors", "Ground", "Adiabatic", "Surface", ...}
        Its outside boundary condition (case-insensitive).
    """
    t, b = surface_type.lower(), boundary.lower()
    if b == "adiabatic":
        return "adiabatic"
    if b in ("surface", "zone"):
        return "interzone"
    if b.startswith("ground"):
        return "ground"
    if t in ("roof", "ceiling"):
        return "roof"
    if t == "floor":
        return "floor_exposed"
    return "wall"


def envelope_figures(surfaces: Iterable[tuple[str, str, float, float]],
                     windows: Iterable[tuple[float, float]] = ()) -> dict:
    """Areas by boundary class and UA of one building's written surfaces.

    Parameters
    ----------
    surfaces : iterable of (class, area, u, window_area)
        Each written surface: its class (:func:`boundary_of`), area (m2), construction U
        without films (W/(m2 K)) and the area of the windows on it (m2).
    windows : iterable of (area, u)
        Every window: area (m2) and U-factor (W/(m2 K)).

    Returns
    -------
    dict
        ``{"areas": {roof, wall, ground, floor_exposed, window, adiabatic} (m2),
        "A_env": m2, "UA": W/K}``, rounded to 3 decimals.
    """
    areas = dict.fromkeys(AREA_KEYS, 0.0)
    ua = 0.0
    for cls, a, u, wa in surfaces:
        if cls not in areas:
            continue
        areas[cls] += a
        if cls != "adiabatic":
            ua += u * max(a - wa, 0.0)
    for a, u in windows:
        areas["window"] += a
        ua += u * a
    env = areas["roof"] + areas["wall"] + areas["ground"] + areas["floor_exposed"]
    return {"areas": {k: round(v, 3) for k, v in areas.items()}, "A_env": round(env, 3), "UA": round(ua, 3)}


def with_model_figures(thermal: Mapping, figures: Mapping) -> dict:
    """A building's ``provenance["thermal"]`` block with the written model's areas, A_env and
    UA (``figures`` of :func:`envelope_figures`) in place of the geometry's estimate; the
    estimate's UA is kept as ``UA_geometry``."""
    out = dict(thermal)
    if "UA" in thermal and "UA_geometry" not in thermal:
        out["UA_geometry"] = thermal["UA"]
    out.update(areas=dict(figures["areas"]), A_env=figures["A_env"], UA=figures["UA"], figures_source="idf")
    return out


#: The keys of a thermal block that :func:`with_model_figures` sets.
FIGURE_KEYS = ("areas", "A_env", "UA", "UA_geometry", "figures_source")


def model_figures(thermal: Mapping, recorded: Mapping) -> dict:
    """``thermal`` with the figures of ``recorded`` (a thermal block that went through
    :func:`with_model_figures`, e.g. the building's record)."""
    return {**thermal, **{k: recorded[k] for k in FIGURE_KEYS if k in recorded}}
