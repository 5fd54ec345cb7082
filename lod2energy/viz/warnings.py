"""The warnings of an export grouped by kind: report.html's summary of what report.json records.

A building's kinds (:func:`warning_kinds`), each counted once per building: a sentinel or
implausible value taken as unknown (``thermal.warnings``, by field), an energy model simpler
than its shell (``energy_downgrades``, by kind), a weather station farther than
:data:`lod2energy.site.MAX_WEATHER_KM`, an export not written or failing its self-check (by
format), a job past its time budget. The study's own (``study``: ``--buildings`` ids not in the
input) are :func:`study_warnings`.
"""
from __future__ import annotations

from typing import Mapping

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
            kinds.append(f"{fmt}: not written or failed its self-check")
    if b.get("outcome") == "timeout":
        kinds.append("job stopped at its time budget (timeout)")
    return tuple(dict.fromkeys(kinds))


def study_warnings(report: Mapping) -> dict[str, int]:
    """The study's warnings of ``report`` (report.json): kind -> count."""
    study = report.get("study") or {}
    missing = study.get("buildings_table_not_in_input") or ()
    return {"--buildings ids not in the input": len(missing)} if missing else {}
