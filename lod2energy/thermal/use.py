"""Building use (residential, office, retail, ...) from attributes, and its use conditions.

:func:`building_use` reads the ``use`` field of the attribute map
(:mod:`lod2energy.thermal.attributes`; default the ``auto`` profile, which holds the code
tables of the producers recognised today: AdV ALKIS ``Gebaeudefunktion``, CityGML 1.0 /
SIG3D ``BuildingFunctionType``, PLATEAU ``usage``, BAG ``gebruiksdoel``, OSM ``building``
and plain words; see ``lod2energy/data/attribute_maps/``). Precedence: the ``--buildings``
row (the more specific, as for every field of the table), the ``--use`` option, the
attributes, else residential (``source = "default"``), as the typology tables are residential.
A building prepared by the thermal stage carries its use in ``provenance["thermal"]["facts"]``:
:func:`recorded_use` reads it (the use report.json shows), as every writer must.

:func:`use_conditions` reads ``data/use_conditions.csv`` and ``data/use_schedules.csv``,
derived by ``scripts/derive_use_conditions.py`` from TEASER's DIN V 18599-10 / SIA 2024 use
conditions (see ``data/SOURCES.md``).
"""
from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from lod2energy import cache
from lod2energy.config import USE_TYPES
from lod2energy.errors import ParameterError
from lod2energy.model import Building
from lod2energy.thermal.attributes import AttributeMap
from lod2energy.thermal.facts import Fact, attribute_map, table_row

DATA = Path(__file__).resolve().parent / "data"


@dataclass(frozen=True)
class Use:
    """A building's use type and where it came from.

    Attributes
    ----------
    type : str
        One of :data:`USE_TYPES`.
    source : str
        ``"option"``, ``"table"``, ``"map"``, ``"attribute"`` or ``"default"``.
    value : str or None
        The attribute value read.
    key : str or None
        The attribute (or column) read.
    scheme : str
        The code table that translated it ("ALKIS", "BAG gebruiksdoel", ...).
    """

    type: str
    source: str
    value: str | None = None
    key: str | None = None
    scheme: str = ""

    def fact(self) -> Fact:
        return Fact(self.type, self.source, self.key, self.value, self.scheme)


def check_use(use: str) -> str:
    """``use`` lower-cased; ParameterError when it is not one of :data:`USE_TYPES`."""
    u = str(use).strip().lower()
    if u not in USE_TYPES:
        raise ParameterError(f"--use must be one of {', '.join(USE_TYPES)}, not {use!r}")
    return u


def building_use(b: Building, override: str | None = None, amap: AttributeMap | None = None) -> Use:
    """The use of ``b`` (see the module docstring): its ``--buildings`` row, else ``override``,
    else its recorded use, else its attributes through ``amap``."""
    row = table_row(b)
    if row.get("use"):
        return Use(row["use"], "table", None, "use")
    if override:
        return Use(check_use(override), "option")
    known = ((b.provenance.get("thermal") or {}).get("facts") or {}).get("use")
    if known:
        return Use(known["value"], known["source"], known.get("raw"), known.get("key"), known.get("scheme", ""))
    amap = attribute_map(amap)
    f = amap.read(b, "use")
    if f is not None:
        return Use(f.value, amap.source(f.key), str(f.raw)[:80], f.key, f.scheme)
    return Use("residential", "default")


def recorded_use(b: Building, override: str | None = None) -> Use:
    """The use the thermal stage recorded for ``b`` (``provenance["thermal"]["facts"]["use"]``:
    the one report.json shows, made with the attribute map and the ``--buildings`` row), else
    :func:`building_use` of ``b`` and ``override``."""
    known = ((b.provenance.get("thermal") or {}).get("facts") or {}).get("use")
    if known:
        return Use(known["value"], known["source"], known.get("raw"), known.get("key"), known.get("scheme", ""))
    return building_use(b, override)


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
