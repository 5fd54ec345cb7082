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
from dataclasses import replace

from lod2energy.model import frozen_mapping

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
    if figures.get("shared_faces"):
        out["shared_faces"] = {str(k): list(v) for k, v in figures["shared_faces"].items()}
    return out


def shared_faces(classes: Mapping[str, Mapping[int, set]]) -> dict[str, list[int]]:
    """The input faces written as party walls only: ``{zone id: [face index, ...]}`` (the
    index of the face in its solid's exterior shell, :class:`~lod2energy.energy.zones.shells.ZoneFace`).

    Parameters
    ----------
    classes : mapping
        Zone id -> face index -> the classes (:func:`boundary_of`) of its written pieces.
    """
    out = {}
    for zone, faces in classes.items():
        idx = sorted(int(fi) for fi, c in faces.items() if fi >= 0 and set(c) == {"adiabatic"})
        if idx:
            out[str(zone)] = idx
    return out


def with_shared_boundaries(b, shared: Mapping[str, Iterable[int]], lod: str | None = None):
    """``b`` whose surfaces written as party walls (``shared``, :func:`shared_faces`) carry
    the Energy ADE's ``thermalBoundaryType`` ``sharedWallOrFloor`` (a semantic entry of their
    own where the input shares one with other surfaces)."""
    if not shared:
        return b
    for o, gi, g in b.envelope(lod):
        entries = list(g.semantic_surfaces)
        copies: dict[int, int] = {}
        solids = []
        changed = False
        for si, solid in enumerate(g.solids):
            zone = o.id if len(g.solids) == 1 else f"{o.id}_s{si}"
            faces = set(shared.get(zone, ()))
            if not faces or not solid.shells:
                solids.append(solid)
                continue
            ext = solid.shells[0]
            surfs = list(ext.surfaces)
            for fi in faces:
                if fi >= len(surfs) or surfs[fi].semantic is None or surfs[fi].semantic >= len(entries):
                    continue
                k = surfs[fi].semantic
                if k not in copies:
                    copies[k] = len(entries)
                    entries.append(frozen_mapping({**entries[k], "thermalBoundaryType": ADE_BOUNDARY["adiabatic"]}))
                surfs[fi] = replace(surfs[fi], semantic=copies[k])
                changed = True
            solids.append(replace(solid, shells=(replace(ext, surfaces=tuple(surfs)),) + tuple(solid.shells[1:])))
        if changed:
            b = b.replace_geometry(o.id, gi, replace(g, solids=tuple(solids), semantic_surfaces=tuple(entries)))
    return b


#: The keys of a thermal block that :func:`with_model_figures` sets.
FIGURE_KEYS = ("areas", "A_env", "UA", "UA_geometry", "figures_source", "shared_faces")


def model_figures(thermal: Mapping, recorded: Mapping) -> dict:
    """``thermal`` with the figures of ``recorded`` (a thermal block that went through
    :func:`with_model_figures`, e.g. the building's record)."""
    return {**thermal, **{k: recorded[k] for k in FIGURE_KEYS if k in recorded}}
