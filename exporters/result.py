"""The one result type of every writer: what was written, and whether its self-check passed."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping


@dataclass(frozen=True)
class ExportResult:
    """Outcome of writing one file (or one case folder).

    Parameters
    ----------
    building_ids : tuple of str
        Ids of the buildings written to ``path``.
    path : str
        The file written (for a file that failed its self-check: its ``.invalid`` name).
    ok : bool
        True when the self-check (and the simulation, after a run) found no problem.
    problems : tuple of str
        Self-check / simulation failures (one line each).
    offset : (3,) tuple of float or None, m
        Local origin: map coordinate = file coordinate + offset (None: no local frame).
    warnings : tuple of str
        Things the user should know that do not make the file wrong (default U-values...).
    stats : mapping
        Counts (zones, surfaces, windows, shading surfaces, triangles ...).
    heating_kwh, cooling_kwh : float or None, kWh
        Annual ideal-loads heating / cooling demand (after an EnergyPlus run).
    severe_errors : int or None
        Severe errors in ``eplusout.err`` (after a run).
    not_enclosed : tuple of str or None
        Zones EnergyPlus found not fully enclosed (after a run).
    sidecars : tuple of str
        Files written beside ``path`` (the STL's offset JSON, the CityJSON Energy extension).
    given : tuple of str or None
        For one file written for many given buildings, some of them left out (CityJSON,
        GeoJSON): the ids of the given buildings that each get a record, in order.
    skipped : tuple of (str, str)
        ``(building id, reason)`` of given buildings left out.
    version : str
        CityJSON version written.
    notes : tuple of str
        Changes made to the input's header to fit the target version (CityJSON).
    terrain : tuple of (str, int)
        ``(id, faces)`` of the terrain objects (``TINRelief``) carried into the file (CityJSON).
    record : mapping
        More fields of the buildings' export records (the CFD case's figures).
    """

    building_ids: tuple[str, ...]
    path: str
    ok: bool
    problems: tuple[str, ...] = ()
    offset: tuple[float, float, float] | None = (0.0, 0.0, 0.0)
    warnings: tuple[str, ...] = ()
    stats: Mapping[str, Any] = field(default_factory=dict)
    heating_kwh: float | None = None
    cooling_kwh: float | None = None
    severe_errors: int | None = None
    not_enclosed: tuple[str, ...] | None = None
    sidecars: tuple[str, ...] = ()
    given: tuple[str, ...] | None = None
    skipped: tuple[tuple[str, str], ...] = ()
    version: str = ""
    notes: tuple[str, ...] = ()
    terrain: tuple[tuple[str, int], ...] = ()
    record: Mapping[str, Any] = field(default_factory=dict)
