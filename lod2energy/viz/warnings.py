"""The warnings of an export grouped by kind: report.html's summary of what report.json records.

A building's kinds (:func:`warning_kinds`), each counted once per building: a sentinel or
implausible value taken as unknown (``thermal.warnings``, by field), an energy model simpler
than its shell (``energy_downgrades``, by kind), a weather station farther than
:data:`lod2energy.site.MAX_WEATHER_KM`, an export not written, refused or failing its
self-check (by format, :func:`export_trouble`), a job past its time budget. The study's own (``study``: ``--buildings`` ids not in the
input) are :func:`study_warnings`. :class:`WarningTally` groups them by kind, for report.html's
"Warnings by kind" table and for the lines ``lod2energy export`` prints at its end
(:func:`warning_lines`).
"""
from __future__ import annotations

from typing import Iterable, Mapping

from lod2energy.records import ExportRecord
from lod2energy.site import MAX_WEATHER_KM


def warning_kinds(b: Mapping) -> tuple[str, ...]:
    """The kinds of warning report.json records for building ``b`` (an entry of its
    ``buildings``), each once, in a fixed order."""
    kinds = []
    for w in (b.get("thermal") or {}).get("warnings") or ():
        f = w.get("field") if isinstance(w, Mapping) else None
        kinds.append(f"{f or 'a value'}: a sentinel or implausible value taken as unknown")
    for d in b.get("energy_downgrades") or ():
        kinds.append(f"energy model downgraded ({d.get('kind')})")
    for fmt, e in sorted((b.get("exports") or {}).items()):
        d = (e.get("weather") or {}).get("distance_km")
        if d is not None and d > MAX_WEATHER_KM:
            kinds.append(f"weather station more than {MAX_WEATHER_KM:.0f} km away")
        if e.get("ok") is False:
            kinds.append(f"{fmt}: {export_trouble(fmt, e)}")
    if b.get("outcome") == "timeout":
        kinds.append("job stopped at its time budget (timeout)")
    return tuple(dict.fromkeys(kinds))


def export_trouble(fmt: str, e: Mapping) -> str:
    """Why export ``e`` (a building's ``exports[fmt]`` in report.json, not ok) is not ok, as a
    kind: its file failed the writer's self-check, the writer refused the building (not
    energy-compliant, left out), or no file was written (a timeout, an error)."""
    rec = ExportRecord(fmt, False, str(e.get("path") or ""), tuple(e.get("problems") or ()))
    if rec.refused:
        return "left out (not energy-compliant)"
    return "failed its self-check" if rec.failed_check else "not written"


def study_warnings(report: Mapping) -> dict[str, int]:
    """The study's warnings of ``report`` (report.json): kind -> count."""
    study = report.get("study") or {}
    missing = study.get("buildings_table_not_in_input") or ()
    return {"--buildings ids not in the input": len(missing)} if missing else {}


class WarningTally:
    """Warnings grouped by kind over the buildings of a run: per kind, how many buildings have
    it and the first of them (its id). Fed one building at a time (:meth:`add`)."""

    def __init__(self):
        self._kinds: dict[str, list] = {}  # kind -> [buildings, the first one's id]

    def add(self, bid: str, kinds: Iterable[str]) -> None:
        """Count building ``bid`` once for each of its ``kinds`` (:func:`warning_kinds`)."""
        for k in kinds:
            self._kinds.setdefault(k, [0, bid])[0] += 1

    def add_entry(self, entry: Mapping) -> None:
        """Count a building of report.json (an entry of its ``buildings``)."""
        self.add(str(entry.get("id")), warning_kinds(entry))

    def table(self, study: Mapping[str, int] | None = None) -> list[dict]:
        """The warnings by kind, the most frequent first: ``[{"kind", "count", "example"}]``
        (``example``: the first building of that kind, None for the study's own, ``study``:
        :func:`study_warnings`)."""
        rows = [{"kind": k, "count": v[0], "example": v[1]} for k, v in self._kinds.items()]
        rows += [{"kind": k, "count": n, "example": None} for k, n in (study or {}).items()]
        return sorted(rows, key=lambda w: (-w["count"], w["kind"]))


def warning_lines(table: Iterable[Mapping]) -> list[str]:
    """The console's lines of a :meth:`WarningTally.table`: one per kind, with its count and an
    example building (``"3 building(s): energy model downgraded (whole_zone), e.g. b1"``);
    none when there is no warning."""
    out = []
    for w in table:
        if w.get("example") is None:
            out.append(f"{w['count']}: {w['kind']}")
        else:
            out.append(f"{w['count']} building(s): {w['kind']}, e.g. {w['example']}")
    return out
