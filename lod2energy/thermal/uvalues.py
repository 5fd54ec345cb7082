"""U-values per surface and the building's transmission heat-loss coefficient UA.

Table lookup (``country`` x ``building_type`` x construction period), most specific first:

1. rows whose period contains the year: those of ``--u-table`` (user CSV) first, then the
   built-in tables (``data/u_values.csv``, ``data/tabula_de.csv``; sources in
   ``data/SOURCES.md``); within each, the country's row for the building type, the same
   with ``building_type = *``, the related type (terraced <-> single-family, apartment
   block <-> multi-family), then the generic ``*`` country rows in the same order;
2. only then rows of the nearest period (same order);
3. per-element overrides (``--u-wall`` ...) replace the looked-up values last.

Non-residential buildings (use from :func:`lod2energy.thermal.use.building_use`, ``--use``
wins) of a country with a non-residential table (today Germany: ``data/iwu_office_de.csv``,
the IWU office constructions of TEASER's office archetype, derived by
``scripts/derive_iwu_office.py``) whose period holds the year get that table's ``office``
rows, between the user's table and the residential ones. For the other non-residential use
types (retail, education, ...) the office rows are used, stated as such in
``provenance["thermal"]["constructions"]``, as no typology of their own is shipped. Outside
those periods and countries, non-residential buildings keep the residential tables (also
stated there).

Per surface (in ``semantic_surfaces``): RoofSurface / OuterCeilingSurface -> roof U,
``"exterior"``; WallSurface -> wall U (opaque part), ``"exterior"``; GroundSurface -> ground
U, ``"ground"``; OuterFloorSurface -> ground U, ``"exterior"``; ClosureSurface -> wall U,
``"interior"`` (a virtual boundary between parts of one heated building: no heat loss, so
it is left out of the areas and UA).

UA = U_roof A_roof + A_wall ((1 - wwr) U_wall + wwr U_window) + U_ground A_ground (W/K),
without temperature-correction factors (b = 1 also towards the ground).
"""
from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path
from typing import Mapping

import numpy as np

from lod2energy import cache
from lod2energy.errors import ParameterError
from lod2energy.model import Building, frozen_mapping
from lod2energy.semantics import (
    CLOSURE, GROUND, OUTER_CEILING, OUTER_FLOOR, ROOF, WALL, envelope_objects, face_metrics, face_table,
)
from lod2energy.thermal.attributes import AttributeMap
from lod2energy.thermal.facts import (
    Fact, attribute_map, conditioned_fact, facts_json, roof_type_fact, table_row, year_fact,
)
from lod2energy.thermal.storeys import storeys as storey_count
from lod2energy.thermal.typology import Typology, classify, country_from_crs
from lod2energy.thermal.use import building_use
from lod2energy.validate.codes import Defect

ELEMENTS = ("roof", "wall", "ground", "window")
RELATED_TYPE = {"terraced": "single-family", "single-family": "terraced",
                "apartment-block": "multi-family", "multi-family": "apartment-block"}
U_RANGE = (0.05, 6.0)  # W/(m2 K): plausible U-values of envelope elements
NONRES_TYPE = "office"  # the building_type of the non-residential table rows


@dataclass(frozen=True)
class URow:
    """One table row: U-values (W/(m2 K)) for a country, building type and period."""

    country: str
    building_type: str
    period_start: int
    period_end: int
    u: Mapping[str, float]
    wwr: float | None
    source: str


@dataclass(frozen=True)
class ThermalOptions:
    """Choices for :func:`assign_u_values`.

    Parameters
    ----------
    country : str, optional
        ISO code (NL, DE, AT, CH, FI, ...); ``None``: guessed from ``crs``, else generic.
    crs : str, optional
        CRS of the input (used only to guess the country).
    u_table : str or Path, optional
        CSV with columns ``country, building_type, period_start, period_end, u_roof, u_wall,
        u_ground, u_window`` (optional ``wwr``, ``source``); empty cells and missing
        ``country`` / ``building_type`` / period columns mean "any". Its rows take
        precedence over the built-in ones.
    overrides : mapping
        ``{"wall": 0.35, ...}``, W/(m2 K): replace the looked-up values for every building.
    u_roof, u_wall, u_ground, u_window : float, optional
        The same per class (the CLI's ``--u-wall`` ...); they win over ``overrides``.
    wwr : float, optional
        Window-to-wall ratio for every building (default: per building type).
    lod : str, optional
        LoD of the energy geometries.
    use : str, optional
        Use type for every building (the CLI's ``--use``); default: from the attributes.
    attribute_map : AttributeMap, optional
        Which attributes give year, storeys, use, ... (``--attribute-map``); default the
        ``auto`` profile (:mod:`lod2energy.thermal.attributes`).
    reference_date : str, optional
        The file's ``referenceDate`` (ISO date): years of construction after it are unknown.
    """

    country: str | None = None
    crs: str | None = None
    u_table: str | Path | None = None
    overrides: Mapping[str, float] = field(default_factory=dict)
    wwr: float | None = None
    lod: str | None = None
    u_roof: float | None = None
    u_wall: float | None = None
    u_ground: float | None = None
    u_window: float | None = None
    use: str | None = None
    attribute_map: AttributeMap | None = None
    reference_date: str | None = None

    @property
    def all_overrides(self) -> dict[str, float]:
        """``overrides`` merged with the ``u_*`` fields, W/(m2 K)."""
        out = {k: float(v) for k, v in dict(self.overrides).items()}
        for e in ELEMENTS:
            v = getattr(self, f"u_{e}")
            if v is not None:
                out[e] = float(v)
        return out

    def __post_init__(self):
        items = list(dict(self.overrides).items()) + [(e, getattr(self, f"u_{e}")) for e in ELEMENTS
                                                       if getattr(self, f"u_{e}") is not None]
        for k, v in items:
            if k not in ELEMENTS:
                raise ParameterError(f"unknown U-value class {k!r} (use one of {', '.join(ELEMENTS)})")
            if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ParameterError(f"--u-{k} must be a positive number of W/(m2 K), got {v!r}")
        if self.wwr is not None and not (0.0 <= self.wwr < 1.0):
            raise ParameterError(f"window-to-wall ratio must be in [0, 1), got {self.wwr!r}")


# ----------------------------------------------------------------------------- tables

def _int_or(v: str | None, default: int) -> int:
    v = (v or "").strip()
    if not v:
        return default
    try:
        return int(float(v))
    except ValueError:
        raise ParameterError(f"period {v!r} is not a year") from None


def parse_table(text: str, where: str) -> list[URow]:
    """Rows of a U-value CSV (see :class:`ThermalOptions`)."""
    rows = []
    reader = csv.DictReader(io.StringIO(text))
    if not reader.fieldnames or not any(f"u_{e}" in reader.fieldnames for e in ELEMENTS):
        raise ParameterError(f"{where}: a U-value table needs a header with u_roof, u_wall, u_ground, u_window")
    for i, r in enumerate(reader, start=2):
        u = {}
        for e in ELEMENTS:
            v = (r.get(f"u_{e}") or "").strip()
            if not v:
                continue
            try:
                x = float(v)
            except ValueError:
                raise ParameterError(f"{where} line {i}: u_{e} {v!r} is not a number") from None
            if not (math.isfinite(x) and x > 0):
                raise ParameterError(f"{where} line {i}: u_{e} must be positive, got {v}")
            u[e] = x
        wwr_s = (r.get("wwr") or "").strip()
        try:
            wwr = float(wwr_s) if wwr_s else None
        except ValueError:
            raise ParameterError(f"{where} line {i}: wwr {wwr_s!r} is not a number") from None
        try:
            c = (r.get("country") or "").strip() or "*"
            rows.append(URow("*" if c == "*" else c.upper(),
                             (r.get("building_type") or "").strip() or "*",
                             _int_or(r.get("period_start"), 0), _int_or(r.get("period_end"), 9999),
                             frozen_mapping(u), wwr, (r.get("source") or where).strip()))
        except ParameterError as e:
            raise ParameterError(f"{where} line {i}: {e}") from None
    return rows


def _shipped(*names: str) -> tuple[URow, ...]:
    """The rows of shipped tables (``lod2energy/thermal/data``), read once per process."""
    d = resources.files("lod2energy.thermal") / "data"
    return cache.remember("thermal.tables", names, lambda: tuple(
        r for n in names for r in parse_table(d.joinpath(n).read_text(encoding="utf-8"), n)), 8)


def builtin_rows() -> tuple[URow, ...]:
    """The shipped tables (``data/tabula_de.csv``, ``data/u_values.csv``)."""
    return _shipped("tabula_de.csv", "u_values.csv")


def builtin_nonres_rows() -> tuple[URow, ...]:
    """The shipped non-residential table (``data/iwu_office_de.csv``)."""
    return _shipped("iwu_office_de.csv")


def nonresidential_rows(country: str, year: int) -> tuple[URow, ...]:
    """Rows of the non-residential table for ``country`` whose period holds ``year`` (may be empty)."""
    return tuple(r for r in builtin_nonres_rows()
                 if r.country == country and r.period_start <= year <= r.period_end)


def builtin_wwr() -> Mapping[str, float]:
    """Window-to-wall ratios by building type (``data/wwr.csv``), read once per process."""
    d = resources.files("lod2energy.thermal") / "data"
    return cache.remember("thermal.tables", "wwr", lambda: frozen_mapping(
        {r["building_type"]: float(r["wwr"]) for r in csv.DictReader(io.StringIO(d.joinpath("wwr.csv").read_text()))}), 8)


def load_table(path: str | Path) -> list[URow]:
    """Rows of a user ``--u-table`` file (ParameterError with one line on any problem)."""
    try:
        text = Path(path).read_text(encoding="utf-8-sig")
    except OSError as e:
        raise ParameterError(f"cannot read U-value table {path}: {e.strerror}") from None
    return parse_table(text, str(path))


def _matches(rows, country, btype, year, exact_period=True) -> list[URow]:
    """Rows of ``country`` and ``btype`` whose period holds ``year`` (or, when not
    ``exact_period``, all of them, nearest period first)."""
    cand = [r for r in rows if r.country == country and r.building_type == btype]
    if exact_period:
        return [r for r in cand if r.period_start <= year <= r.period_end]
    return sorted(cand, key=lambda r: min(abs(year - r.period_start), abs(year - r.period_end)))


def lookup(country: str, btype: str, year: int, rows, *more_tiers) -> tuple[dict[str, float], list[URow]]:
    """U-values per element (most specific row first; see the module docstring).

    Elements missing in a row are filled from the next matching row. ``more_tiers`` are
    further row sets searched only for what ``rows`` left open (the user's table is the
    first tier, the built-in tables the second).

    Returns
    -------
    u : dict
        ``{"roof", "wall", "ground", "window"}`` -> W/(m2 K) (only those found).
    used : list of URow
        Rows that contributed, most specific first.
    """
    countries = [country] + (["*"] if country != "*" else [])
    types = [btype, "*", RELATED_TYPE.get(btype, "*")]
    u: dict[str, float] = {}
    used: list[URow] = []
    for exact in (True, False):
        for tier in (rows,) + more_tiers:
            for c in countries:
                for t in types:
                    for r in _matches(tier, c, t, year, exact):
                        if r in used or all(e in u for e in r.u):
                            continue
                        used.append(r)
                        for e, v in r.u.items():
                            u.setdefault(e, v)
                        if len(u) == len(ELEMENTS):
                            return u, used
    return u, used


# ----------------------------------------------------------------------------- geometry sums

def _solid_volume(vertices: np.ndarray, g, origin: np.ndarray) -> float:
    vol = 0.0
    if not g.is_volumetric:
        return 0.0
    for si, hi, fi, s in g.iter_surfaces():
        a, n, c = face_metrics(vertices, s)
        vol += float((c - origin) @ (n * a)) / 3.0
    return vol


def _azimuth_inclination(n: np.ndarray) -> tuple[float, float]:
    """Azimuth (deg clockwise from north = +y, of the horizontal normal part) and inclination
    (deg from the upward vertical: 0 roof facing up, 90 wall, 180 floor facing down)."""
    incl = math.degrees(math.acos(max(-1.0, min(1.0, float(n[2])))))
    if math.hypot(n[0], n[1]) < 1e-9:
        return 0.0, incl
    return (math.degrees(math.atan2(n[0], n[1])) + 360.0) % 360.0, incl


_CLASS = {ROOF: ("roof", "exterior"), OUTER_CEILING: ("roof", "exterior"), WALL: ("wall", "exterior"),
          GROUND: ("ground", "ground"), OUTER_FLOOR: ("ground", "exterior"), CLOSURE: ("wall", "interior")}


def period_label(row: URow | None, typ: Typology) -> str:
    if row is None:
        return "unknown"
    end = "" if row.period_end >= 2100 else str(row.period_end)
    start = "" if row.period_start <= 0 else str(row.period_start)
    s = f"{start}-{end}" if (start or end) else "any"
    return s + (" (assumed)" if typ.year is None else "")


def assign_u_values(b: Building, options: ThermalOptions = ThermalOptions()) -> Building:
    """Typology, per-surface Energy ADE quantities and the UA of one labelled building.

    Parameters
    ----------
    b : Building
        Output of :func:`lod2energy.semantics.label_building` (one semantic entry per surface).
    options : ThermalOptions

    Returns
    -------
    Building
        Every surface's semantic entry gains ``uValue`` (W/(m2 K)), ``thermalBoundaryType``,
        ``area`` (m2), ``azimuth`` and ``inclination`` (deg); ``provenance["thermal"]`` holds
        country, typology, construction_period, u_values, wwr, areas {roof, wall, ground},
        A_env (m2), volume (m3), UA (W/K) and the attributes used.
    """

    lod = options.lod if options.lod is not None else b.default_lod()
    energy = envelope_objects(b, lod)
    tables = [face_table(b.vertices, g) for _, _, g in energy]
    ground_area = sum(float(t.area[i]) for (o, gi, g), t in zip(energy, tables)
                      for i, s in enumerate(t.surfaces) if g.semantic_type(s) == GROUND)
    zs = [(t.z_min, t.z_max) for t in tables if len(t.area)]
    z_extent = (max(z[1] for z in zs) - min(z[0] for z in zs)) if zs else None
    country = (options.country or country_from_crs(options.crs) or "*")
    country = country.upper() if country != "*" else "*"
    amap = attribute_map(options.attribute_map)
    warnings: list[tuple[str, str]] = []
    use = building_use(b, options.use, amap)
    year = year_fact(b, amap, options.reference_date, warnings)
    st = storey_count(b, use.type, lod, amap=amap, warnings=warnings)
    st_fact = Fact(st.count, st.source, st.key)
    typ = classify(b, country, ground_area or None, z_extent, amap, year, st_fact, use.value)
    rows = tuple(load_table(options.u_table)) if options.u_table else ()
    nonres = nonresidential_rows(typ.country, typ.lookup_year) if use.type != "residential" else ()
    if nonres:
        u, used = lookup(typ.country, NONRES_TYPE, typ.lookup_year, rows, nonres, builtin_rows())
    else:
        u, used = lookup(typ.country, typ.building_type, typ.lookup_year, rows, builtin_rows())
    u_src = {}
    for e in u:  # the row that gave each element: the user's --u-table (an option) or a shipped table
        r = next(r for r in used if e in r.u)
        u_src[e] = Fact(u[e], "option" if r in rows else "default", r.source)
    for e, v in options.all_overrides.items():
        u[e] = v
        u_src[e] = Fact(v, "option", f"u_{e}")
    row = table_row(b)
    for e in ELEMENTS:
        if row.get(f"u_{e}") is not None:
            u[e] = float(row[f"u_{e}"])
            u_src[e] = Fact(u[e], "table", f"u_{e}")
    missing = [e for e in ELEMENTS if e not in u]
    if missing:
        raise ParameterError(f"no U-value for {', '.join(missing)} (country {typ.country}); "
                             f"give them with --u-table or --u-{missing[0]}")
    wwr, wwr_src = (float(row["wwr"]), "table") if row.get("wwr") is not None else (options.wwr, "option")
    if wwr is None:
        wwr, wwr_src = next((r.wwr for r in used if r.wwr is not None), None), "default"
    if wwr is None:
        wwr = builtin_wwr().get(typ.building_type, 0.25)

    areas = {"roof": 0.0, "wall": 0.0, "ground": 0.0}
    volume = 0.0
    origin = b.vertices.mean(axis=0) if len(b.vertices) else np.zeros(3)
    out = b
    for (o, gi, g), t in zip(energy, tables):
        entries = list(g.semantic_surfaces)
        done = set()
        for i, s in enumerate(t.surfaces):
            if s.semantic is None or s.semantic >= len(entries) or s.semantic in done:
                continue
            done.add(s.semantic)
            stype = entries[s.semantic].get("type")
            cls, boundary = _CLASS.get(stype, ("wall", "exterior"))
            az, inc = _azimuth_inclination(t.normal[i])
            e = dict(entries[s.semantic])
            e.update({"uValue": round(u[cls], 4), "thermalBoundaryType": boundary,
                      "area": round(float(t.area[i]), 4), "azimuth": round(az, 2),
                      "inclination": round(inc, 2)})
            entries[s.semantic] = frozen_mapping(e)
            if boundary != "interior":
                areas[cls] += float(t.area[i])
        volume += _solid_volume(b.vertices, g, origin)
        out = out.replace_geometry(o.id, gi, replace(g, semantic_surfaces=tuple(entries)))
    ua = (u["roof"] * areas["roof"] + areas["wall"] * ((1 - wwr) * u["wall"] + wwr * u["window"])
          + u["ground"] * areas["ground"])
    thermal = {
        "lod": lod, "country": typ.country, "typology": typ.building_type,
        "construction_period": period_label(used[0] if used else None, typ),
        "year_of_construction": typ.year,
        "u_values": {e: round(u[e], 4) for e in ELEMENTS}, "wwr": wwr,
        "areas": {k: round(v, 3) for k, v in areas.items()},
        "A_env": round(sum(areas.values()), 3), "volume": round(volume, 3), "UA": round(ua, 3),
        "storeys": typ.storeys, "footprint": round(typ.footprint, 3), "function": typ.function,
        "sources": dict(typ.sources), "table_sources": [r.source for r in used],
        "overrides": options.all_overrides,
        "attribute_map": amap.name,
        "facts": facts_json({
            "year": year, "storeys": Fact(st.count, st.source, st.key, st.heights), "use": use.fact(),
            "conditioned": conditioned_fact(b, amap, ground_area * max(st.count or 1, 1) if ground_area else None),
            "roof_type": roof_type_fact(b, amap),
            **{f"u_{e}": u_src[e] for e in ELEMENTS}, "wwr": Fact(wwr, wwr_src)}),
    }
    if warnings:
        thermal["warnings"] = [{"field": f, "message": m} for f, m in warnings]
    if use.type != "residential":
        thermal.update(use=use.type, use_source=use.source,
                       constructions=_constructions_note(use.type, typ, used))
    return out.with_provenance(thermal=frozen_mapping(thermal))


def _constructions_note(use: str, typ: Typology, used: list[URow]) -> str:
    """Where a non-residential building's constructions come from, in words."""
    if any(r.source == "TEASER-IWU-OFFICE" for r in used):
        s = "IWU office typology (TEASER office archetype, heavy construction; iwu_office_de.csv)"
        return s if use == NONRES_TYPE else s + f", used for {use}: no {use} typology is shipped"
    why = (f"no non-residential table for country {typ.country}" if not any(
        r.country == typ.country for r in builtin_nonres_rows()) else
        f"the non-residential table has no period for {typ.lookup_year}")
    return f"residential typology of the country and period, used for {use}: {why}"


def check_u_values(b: Building, lod: str | None = None) -> list[Defect]:
    """Surfaces of the energy geometries without a U-value (1201) or with an implausible one (1202)."""
    out = []
    for o, gi, g in envelope_objects(b, lod):
        for si, hi, fi, s in g.iter_surfaces():
            loc = f"coid={o.id}|" + g.location(gi, si, hi, fi)
            e = g.semantic_surfaces[s.semantic] if s.semantic is not None and s.semantic < len(
                g.semantic_surfaces) else {}
            v = e.get("uValue")
            if not isinstance(v, (int, float)) or isinstance(v, bool):
                out.append(Defect(1201, loc, "no uValue"))
            elif not (U_RANGE[0] <= v <= U_RANGE[1]):
                out.append(Defect(1202, loc, f"uValue {v} W/(m2 K) outside [{U_RANGE[0]}, {U_RANGE[1]}]"))
    return out
