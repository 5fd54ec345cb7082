"""The one result type of every writer: what was written, and whether its self-check passed."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping

#: Fields only the CityJSON writer fills; :meth:`ExportResult.to_dict` leaves them out while
#: they hold their defaults, so the other writers' dictionaries keep their keys.
_CITYJSON_FIELDS = ("version", "skipped", "extension_path", "notes", "terrain")


@dataclass(frozen=True)
class ExportResult:
    """Outcome of writing one file.

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
    offset : (3,) tuple of float, m
        Local origin: map coordinate = file coordinate + offset.
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
    version : str
        CityJSON version written (CityJSON writer).
    skipped : tuple of (str, str)
        ``(building id, reason)`` of buildings left out (CityJSON writer).
    extension_path : str or None
        The Energy extension file written next to the output (CityJSON writer).
    notes : tuple of str
        Changes made to the input's header to fit the target version (CityJSON writer).
    terrain : tuple of (str, int)
        ``(id, faces)`` of the terrain objects (``TINRelief``) carried into the file, with
        the number of faces (triangles) of each (CityJSON writer).
    """

    building_ids: tuple[str, ...]
    path: str
    ok: bool
    problems: tuple[str, ...] = ()
    offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    warnings: tuple[str, ...] = ()
    stats: Mapping[str, Any] = field(default_factory=dict)
    heating_kwh: float | None = None
    cooling_kwh: float | None = None
    severe_errors: int | None = None
    not_enclosed: tuple[str, ...] | None = None
    version: str = ""
    skipped: tuple[tuple[str, str], ...] = ()
    extension_path: str | None = None
    notes: tuple[str, ...] = ()
    terrain: tuple[tuple[str, int], ...] = ()

    def to_dict(self) -> dict:
        d = {k: getattr(self, k) for k in self.__dataclass_fields__
             if k not in _CITYJSON_FIELDS or getattr(self, k) not in ("", (), None)}
        d["building_ids"] = list(self.building_ids)
        d["problems"] = list(self.problems)
        d["warnings"] = list(self.warnings)
        d["offset"] = list(self.offset)
        d["stats"] = dict(self.stats)
        if self.not_enclosed is not None:
            d["not_enclosed"] = list(self.not_enclosed)
        for k in ("skipped", "notes", "terrain"):
            if k in d:
                d[k] = [list(x) if isinstance(x, tuple) else x for x in d[k]]
        return d
