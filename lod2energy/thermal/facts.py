"""A building's study inputs (year, storeys, use, conditioned, roof type, U-values, WWR), each
with its source.

Sources, most specific first (the first that gives a usable value wins):

- ``table``: the ``--buildings`` CSV row of the building (:mod:`lod2energy.thermal.table`);
- ``option``: a CLI option for every building (``--use``, ``--u-wall``, ``--wwr``, ...);
- ``map``: an attribute named by the user's ``--attribute-map``;
- ``attribute``: an attribute of a built-in profile (:mod:`lod2energy.thermal.attributes`);
- ``geometry``: derived from the LoD2 geometry (storeys from the eave height);
- ``default``: the documented default (year unknown, residential, conditioned, the
  typology's U-values and WWR).

Sentinels and implausible values are unknown, with a warning, and the next source is tried:
a year <= 1000, 9999, or later than the building's ``creationDate``, else the file's
``referenceDate``, else today; a storey count of 9999 (or < 1, > 200), or an attribute's count
that gives a storey height outside :data:`STOREY_HEIGHT_RANGE`.
"""
from __future__ import annotations

import datetime
import re
from dataclasses import dataclass
from typing import Any, Mapping

import numpy as np

from lod2energy.model import Building, frozen_mapping
from lod2energy.thermal.attributes import AttributeMap, load_attribute_map

SENTINELS = (9999, 99999, -9999)
STOREY_HEIGHT_RANGE = (2.0, 6.0)  # m, floor to floor
#: Where :func:`table_row` finds a building's ``--buildings`` row (joined by the pipeline).
TABLE_KEY = "buildings_table"


@dataclass(frozen=True)
class Fact:
    """One input of one building and where it came from.

    Attributes
    ----------
    value : Any
    source : {"table", "option", "map", "attribute", "geometry", "default"}
    key : str or None
        The attribute (or CSV column) read.
    raw : Any
        The attribute's value as given, when a table translated it.
    scheme : str
        The code table that translated it ("" without one).
    """

    value: Any
    source: str
    key: str | None = None
    raw: Any = None
    scheme: str = ""

    def to_json(self) -> dict:
        d = {"value": self.value, "source": self.source}
        if self.key is not None:
            d["key"] = self.key
        if self.raw is not None and self.raw != self.value:
            d["raw"] = (self.raw if isinstance(self.raw, (int, float, bool)) else list(self.raw)
                        if isinstance(self.raw, (list, tuple)) and len(self.raw) <= 200 else str(self.raw)[:80])
        if self.scheme:
            d["scheme"] = self.scheme
        return d


def table_row(b: Building) -> Mapping[str, Any]:
    """The building's ``--buildings`` row (``{}`` without one)."""
    return b.provenance.get(TABLE_KEY) or {}


def attribute_map(amap: AttributeMap | None) -> AttributeMap:
    return amap if amap is not None else load_attribute_map(None)


def year_of(v: Any) -> int | None:
    """A year from an attribute value (ints, floats, strings starting with 4 digits), else None."""
    if isinstance(v, bool) or v is None:
        return None
    if isinstance(v, (int, float, np.integer, np.floating)):
        return int(v) if np.isfinite(v) else None
    m = re.match(r"\s*(-?\d{1,5})", str(v))
    return int(m.group(1)) if m else None


def count_of(v: Any) -> float | None:
    """A number from an attribute value, else None."""
    if isinstance(v, bool) or v is None:
        return None
    try:
        x = float(str(v).strip())
    except (TypeError, ValueError):
        return None
    return x if np.isfinite(x) else None


def latest_year(b: Building, reference_date: str | None = None) -> tuple[int, str]:
    """The latest plausible year of construction and what sets it: the building's
    ``creationDate``, the file's ``referenceDate`` (``reference_date``), else today."""
    for o in b.objects[:1]:
        y = year_of(o.attributes.get("creationDate"))
        if y is not None and y > 1000:
            return y, "creationDate"
    y = year_of(reference_date)
    if y is not None and y > 1000:
        return y, "referenceDate"
    return datetime.date.today().year, "today"


def year_fact(b: Building, amap: AttributeMap | None = None, reference_date: str | None = None,
              warnings: list | None = None) -> Fact:
    """The year of construction of ``b`` (``value`` None when unknown)."""
    row = table_row(b)
    if row.get("year") is not None:
        return Fact(int(row["year"]), "table", "year")
    amap = attribute_map(amap)
    latest, why = latest_year(b, reference_date)

    def plausible(v):
        y = year_of(v)
        if y is None:
            return None
        if y <= 1000 or y in SENTINELS or y > latest:
            if warnings is not None:
                warnings.append(("year", f"year {v!r} taken as unknown"
                                 + (f" (later than the {why}, {latest})" if y > latest and y not in SENTINELS else "")))
            return None
        return y

    f = amap.read(b, "year", plausible)
    if f is not None:
        return Fact(f.value, amap.source(f.key), f.key, f.raw if f.raw != f.value else None)
    return Fact(None, "default")


def storey_count(v: Any, warnings: list | None = None) -> int | None:
    """A storey count from an attribute value; sentinels (9999) and counts outside 1-200 are None."""
    x = count_of(v)
    if x is None:
        return None
    if x in SENTINELS or x < 1 or x > 200:
        if warnings is not None:
            warnings.append(("storeys", f"storeys {v!r} taken as unknown"))
        return None
    return int(round(x))


def storeys_candidates(b: Building, amap: AttributeMap | None = None, warnings: list | None = None
                       ) -> list[Fact]:
    """Storey counts of ``b`` from its ``--buildings`` row and its attributes, in order of
    precedence (sentinels left out); each ``raw`` holds the storey heights (m) when given."""
    out = []
    row = table_row(b)
    if row.get("storeys") is not None:
        out.append(Fact(int(row["storeys"]), "table", "storeys"))
    amap = attribute_map(amap)
    hf = amap.read(b, "storey_heights", _heights)
    seen = set()
    for o in b.objects:
        for k in amap.field("storeys").keys:
            if k in o.attributes and k not in seen:
                n = storey_count(o.attributes[k], warnings)
                if n is not None:
                    seen.add(k)
                    out.append(Fact(n, amap.source(k), k, hf.value if hf else None))
    if hf is not None and not any(f.source != "table" for f in out):
        out.append(Fact(len(hf.value), amap.source(hf.key), hf.key, hf.value))
    return out


def _heights(v: Any) -> tuple[float, ...] | None:
    if v is None or isinstance(v, bool):
        return None
    items = v if isinstance(v, (list, tuple)) else re.split(r"[\s,;]+", str(v).strip())
    try:
        h = tuple(float(x) for x in items if str(x) != "")
    except (TypeError, ValueError):
        return None
    return h if h and all(np.isfinite(x) and 0.5 < x < 30 for x in h) else None


#: Gross floor area (m2) under which a building is taken as an unheated annex (a shed, a
#: garage, a carport) when neither its row nor its attributes say whether it is conditioned:
#: below the 50 m2 under which the EU EPBD (Art. 4) lets member states exempt stand-alone
#: buildings, and smaller than any dwelling.
ANNEX_FLOOR_AREA = 20.0


def conditioned_fact(b: Building, amap: AttributeMap | None = None, floor_area: float | None = None) -> Fact:
    """Whether ``b`` is heated / cooled: its row, its attributes (a use that is never heated:
    parking, sheds, barns, transformer and pump stations ...), its gross floor area
    ``floor_area`` (m2) under :data:`ANNEX_FLOOR_AREA` (``geometry``), else True (``default``)."""
    row = table_row(b)
    if row.get("conditioned") is not None:
        return Fact(bool(row["conditioned"]), "table", "conditioned")
    amap = attribute_map(amap)
    f = amap.read(b, "conditioned", boolean)
    if f is not None:
        return Fact(f.value, amap.source(f.key), f.key, f.raw if f.raw != f.value else None)
    if floor_area is not None and 0 < floor_area < ANNEX_FLOOR_AREA:
        return Fact(False, "geometry", "floor_area", round(float(floor_area), 2))
    return Fact(True, "default")


def is_conditioned(b: Building) -> bool:
    """The ``conditioned`` fact the thermal stage recorded for ``b`` (True without one)."""
    facts = (b.provenance.get("thermal") or {}).get("facts") or {}
    v = (facts.get("conditioned") or {}).get("value")
    return v is not False


def roof_type_fact(b: Building, amap: AttributeMap | None = None) -> Fact:
    """The roof type attribute of ``b`` (through the map's value table), else None."""
    amap = attribute_map(amap)
    f = amap.read(b, "roof_type", lambda v: None if v in (None, "") else v)
    if f is not None:
        return Fact(f.value, amap.source(f.key), f.key, f.raw if f.raw != f.value else None)
    return Fact(None, "default")


_TRUE = {"true", "yes", "y", "1", "ja", "j", "on", "heated", "conditioned"}
_FALSE = {"false", "no", "n", "0", "nee", "nein", "off", "unheated", "unconditioned"}


def boolean(v: Any) -> bool | None:
    """A yes / no value (bools, 0 / 1, true / false, yes / no, ja / nee / nein), else None."""
    if isinstance(v, bool):
        return v
    if isinstance(v, (int, float, np.integer, np.floating)) and v in (0, 1):
        return bool(v)
    s = str(v).strip().lower()
    return True if s in _TRUE else False if s in _FALSE else None


def facts_json(facts: Mapping[str, Fact]) -> Mapping[str, Any]:
    """``{field: {"value", "source", "key"?, "raw"?}}`` for the record."""
    return frozen_mapping({k: f.to_json() for k, f in facts.items()})
