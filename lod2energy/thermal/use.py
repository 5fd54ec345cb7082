"""Building use (residential, office, retail, ...) from attributes, and its use conditions.

:func:`building_use` maps the first recognised attribute of :data:`USE_KEYS` (root object
first, then its parts) to one of :data:`USE_TYPES`:

- **AdV ALKIS** ``Gebäudefunktion`` codes (``31001_2020`` as German CityGML tiles give them, or
  a bare code >= 2000): 1xxx residential; 2010-2056 retail, 2020-2040 offices, 2070-2083
  hospitality, 2100-2200 and 2500-2700 industry; 3010-3012 offices, 3020-3024 and 3065
  education, 3050-3052 health; other codes: other.
- **CityGML 1.0 / SIG3D** ``BuildingFunctionType`` bare codes 1000-1299: 1000-1110
  residential, 1120-1140 offices, 1150-1200 retail, 1210-1250 hospitality; other: other.
- **PLATEAU** (Japan) ``usage`` codes: 401 and 421 offices, 402 and 404 retail, 403
  hospitality, 411-415 residential, 422 education, 431 and 441 industry; other: other.
- **BAG** ``gebruiksdoel`` (a list or a comma-separated string; the first recognised one):
  woonfunctie, kantoorfunctie, winkelfunctie, onderwijsfunctie, gezondheidszorgfunctie,
  logiesfunctie, industriefunctie; the others (bijeenkomst-, sport-, cel-, overige
  gebruiksfunctie): other.
- **OSM** ``building`` values and plain English words (house, apartments, office, retail,
  school, hospital, hotel, industrial, warehouse, ...).

Without any: residential (``source = "default"``), as the typology tables are residential.
A ``use`` override (the CLI's ``--use``) wins over every attribute.

:func:`use_conditions` reads ``data/use_conditions.csv`` and ``data/use_schedules.csv``,
derived by ``scripts/derive_use_conditions.py`` from TEASER's DIN V 18599-10 / SIA 2024 use
conditions (see ``data/SOURCES.md``).
"""
from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

from lod2energy import cache
from lod2energy.config import USE_TYPES
from lod2energy.errors import ParameterError
from lod2energy.model import Building

USE_KEYS = ("function", "usage", "gebruiksdoel", "b3_gebruiksdoel", "building", "building_function",
            "buildingFunction", "use")
DATA = Path(__file__).resolve().parent / "data"

_BAG = {"woonfunctie": "residential", "kantoorfunctie": "office", "winkelfunctie": "retail",
        "onderwijsfunctie": "education", "gezondheidszorgfunctie": "health", "logiesfunctie": "hospitality",
        "industriefunctie": "industry", "bijeenkomstfunctie": "other", "sportfunctie": "other",
        "celfunctie": "other", "overige gebruiksfunctie": "other"}
_WORDS = {
    "residential": ("residential", "house", "apartments", "apartment", "detached", "semidetached_house",
                    "terrace", "bungalow", "dormitory", "farm", "cabin", "houseboat", "static_caravan",
                    "dwelling", "housing", "living", "wohnen", "wohnhaus", "wohngebäude"),
    "office": ("office", "offices", "commercial", "government", "civic", "public", "administration"),
    "retail": ("retail", "shop", "supermarket", "kiosk", "store", "mall", "department_store"),
    "education": ("school", "university", "college", "kindergarten", "education", "classroom"),
    "health": ("hospital", "clinic", "health", "healthcare", "nursing_home"),
    "hospitality": ("hotel", "hostel", "motel", "hospitality", "restaurant", "guest_house"),
    "industry": ("industrial", "industry", "warehouse", "factory", "manufacture", "workshop", "storage"),
    "other": ("church", "chapel", "garage", "garages", "shed", "barn", "sports_hall", "other", "yes",
              "train_station", "transportation", "stadium", "parking", "service", "hut", "roof"),
}
_WORD_USE = {w: u for u, ws in _WORDS.items() for w in ws}


def _alkis(code: int) -> str:
    if 1000 <= code < 2000:
        return "residential"
    for lo, hi, use in ((2020, 2040, "office"), (2010, 2056, "retail"), (2070, 2083, "hospitality"),
                        (2100, 2200, "industry"), (2500, 2700, "industry"), (3010, 3012, "office"),
                        (3020, 3024, "education"), (3065, 3065, "education"), (3050, 3052, "health")):
        if lo <= code <= hi:
            return use
    return "other"


def _sig3d(code: int) -> str:
    for lo, hi, use in ((1000, 1110, "residential"), (1120, 1140, "office"), (1150, 1200, "retail"),
                        (1210, 1250, "hospitality")):
        if lo <= code <= hi:
            return use
    return "other"


def _plateau(code: int) -> str:
    return {401: "office", 421: "office", 402: "retail", 404: "retail", 403: "hospitality", 411: "residential",
            412: "residential", 413: "residential", 414: "residential", 415: "residential", 422: "education",
            431: "industry", 441: "industry"}.get(code, "other")


def use_of_value(key: str, value: Any) -> tuple[str, str] | None:
    """``(use type, scheme)`` for one attribute value, None when not recognised."""
    if value is None or isinstance(value, bool):
        return None
    if isinstance(value, (list, tuple)):
        for v in value:
            r = use_of_value(key, v)
            if r is not None:
                return r
        return None
    s = str(value).strip()
    if not s:
        return None
    low = s.lower()
    if key in ("gebruiksdoel", "b3_gebruiksdoel") or low in _BAG:
        for part in re.split(r"\s*[,;|]\s*", low):
            if part in _BAG:
                return _BAG[part], "BAG gebruiksdoel"
    m = re.fullmatch(r"31001_(\d{4})", s)
    if m:
        return _alkis(int(m.group(1))), "ALKIS"
    if re.fullmatch(r"\d{3}", s):
        return _plateau(int(s)), "PLATEAU"
    if re.fullmatch(r"\d{4}", s):
        c = int(s)
        return (_sig3d(c), "CityGML 1.0 codelist") if c < 2000 else (_alkis(c), "ALKIS")
    w = low.replace(" ", "_").replace("-", "_")
    if w in _WORD_USE:
        return _WORD_USE[w], "word"
    if w in USE_TYPES:
        return w, "word"
    return None


@dataclass(frozen=True)
class Use:
    """A building's use type and where it came from.

    Attributes
    ----------
    type : str
        One of :data:`USE_TYPES`.
    source : str
        ``"attribute:<key> (<scheme>)"``, ``"option"`` or ``"default"``.
    value : str or None
        The attribute value read.
    """

    type: str
    source: str
    value: str | None = None


def check_use(use: str) -> str:
    """``use`` lower-cased; ParameterError when it is not one of :data:`USE_TYPES`."""
    u = str(use).strip().lower()
    if u not in USE_TYPES:
        raise ParameterError(f"--use must be one of {', '.join(USE_TYPES)}, not {use!r}")
    return u


def building_use(b: Building, override: str | None = None) -> Use:
    """The use of ``b`` (see the module docstring); ``override`` wins."""
    if override:
        return Use(check_use(override), "option")
    for o in b.objects:
        for k in USE_KEYS:
            if k in o.attributes:
                r = use_of_value(k, o.attributes[k])
                if r is not None:
                    return Use(r[0], f"attribute:{k} ({r[1]})", str(o.attributes[k])[:80])
    return Use("residential", "default")


@dataclass(frozen=True)
class UseConditions:
    """Internal loads, setpoints and air change of one use type (per m2 of floor area).

    Attributes
    ----------
    use : str
    teaser_entry : str
        The TEASER ``UseConditions.json`` entry it was derived from.
    people_per_m2 : float, 1/m2
    activity_w_per_person : float, W (total heat per person)
    sensible_fraction : float
    lighting_w_per_m2, equipment_w_per_m2 : float, W/m2
    heating_setpoint, heating_setback, cooling_setpoint, cooling_setback : float, C
    infiltration_ach : float, 1/h
    ventilation_m3h_per_m2 : float, m3/(h m2), while occupied
    schedules : mapping
        ``{"occupancy" | "lighting" | "equipment" | "heating" | "cooling": 24 hourly values}``
        (fractions; setpoints in C).
    """

    use: str
    teaser_entry: str
    people_per_m2: float
    activity_w_per_person: float
    sensible_fraction: float
    lighting_w_per_m2: float
    equipment_w_per_m2: float
    heating_setpoint: float
    heating_setback: float
    cooling_setpoint: float
    cooling_setback: float
    infiltration_ach: float
    ventilation_m3h_per_m2: float
    schedules: Mapping[str, tuple[float, ...]]


_FLOATS = ("people_per_m2", "activity_w_per_person", "sensible_fraction", "lighting_w_per_m2",
           "equipment_w_per_m2", "heating_setpoint", "heating_setback", "cooling_setpoint", "cooling_setback",
           "infiltration_ach", "ventilation_m3h_per_m2")


def _table() -> dict[str, UseConditions]:
    """The shipped use conditions by use, read once per process."""
    return cache.remember("thermal.use-conditions", None, _read_table, 1)


def _read_table() -> dict[str, UseConditions]:
    sched: dict[str, dict[str, tuple[float, ...]]] = {}
    with open(DATA / "use_schedules.csv", newline="", encoding="utf-8") as f:
        for r in csv.DictReader(f):
            sched.setdefault(r["use"], {})[r["schedule"]] = tuple(float(r[f"h{h:02d}"]) for h in range(24))
    out = {}
    with open(DATA / "use_conditions.csv", newline="", encoding="utf-8") as f:
        for r in csv.DictReader(f):
            out[r["use"]] = UseConditions(r["use"], r["teaser_entry"], *(float(r[k]) for k in _FLOATS),
                                          schedules=sched.get(r["use"], {}))
    return out


def use_conditions(use: str) -> UseConditions:
    """The shipped use conditions of ``use`` (one of :data:`USE_TYPES`)."""
    return _table()[check_use(use)]
