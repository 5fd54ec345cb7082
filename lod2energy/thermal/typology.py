"""Building typology (country x construction period x building type) from a building's attributes.

Fallbacks (documented, in order):

- **year of construction**: the first usable value of :data:`YEAR_KEYS` on the root object,
  then on its parts (ints, floats, or strings starting with a 4-digit year, 1000-2100);
  unknown -> ``None`` and the table lookup uses :data:`DEFAULT_YEAR` (1970: the middle of the
  European residential stock's age distribution); the construction period is then reported
  with the suffix ``" (assumed)"``.
- **storeys**: :data:`STOREY_KEYS`; else height / 3 m (height from :data:`HEIGHT_KEYS`, else the
  geometry's vertical extent), at least 1.
- **footprint**: area of the GroundSurfaces of the energy geometries; else ``b3_opp_grond``.
- **attached**: a shared-wall area attribute (``b3_opp_scheidingsmuur`` > 1 m2).
- **building type**: storeys <= 3 and footprint <= 250 m2 -> single-family, or terraced when
  attached; storeys <= 5 -> multi-family; otherwise apartment block. A function / usage
  attribute is recorded here; the U-value stage (:mod:`lod2energy.thermal.uvalues`) gives
  German non-residential buildings the IWU office constructions instead of the residential
  row of this type.
- **country**: the caller's choice, else from the CRS (:func:`country_from_crs`), else
  ``"*"`` (generic European default).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Mapping

import numpy as np

from lod2energy.crs import epsg_codes
from lod2energy.model import Building

YEAR_KEYS = ("yearOfConstruction", "oorspronkelijkbouwjaar", "b3_bouwjaar", "bouwjaar",
             "constructionYear", "construction_year", "yearBuilt", "year_built", "Baujahr",
             "baujahr", "bouwjaar_pand", "year")
STOREY_KEYS = ("storeysAboveGround", "b3_bouwlagen", "storeys", "numberOfStoreys", "numberOfFloors",
               "floors", "bouwlagen")
HEIGHT_KEYS = ("measuredHeight", "height", "b3_h_dak_70p")
GROUND_LEVEL_KEYS = ("b3_h_maaiveld",)
FUNCTION_KEYS = ("function", "usage", "class", "gebruiksdoel", "building_function", "buildingFunction")
SHARED_WALL_KEYS = ("b3_opp_scheidingsmuur",)
FOOTPRINT_KEYS = ("b3_opp_grond",)

DEFAULT_YEAR = 1970
STOREY_HEIGHT = 3.0  # m
BUILDING_TYPES = ("single-family", "terraced", "multi-family", "apartment-block")

_CRS_COUNTRY = {
    "28992": "NL", "7415": "NL",
    "25832": "DE", "25833": "DE", "31466": "DE", "31467": "DE", "31468": "DE", "31469": "DE",
    "5677": "DE", "5678": "DE", "4647": "DE", "5650": "DE", "5555": "DE", "5556": "DE",
    "31287": "AT", "31255": "AT", "31256": "AT", "31257": "AT",
    "2056": "CH", "21781": "CH", "5728": "CH",
    "3067": "FI", "3873": "FI", "3874": "FI", "3875": "FI", "3876": "FI", "3877": "FI",
    "3878": "FI", "3879": "FI", "3880": "FI", "3881": "FI", "3882": "FI", "3883": "FI",
    "3884": "FI", "3885": "FI", "2393": "FI",
}


#: CRS names of the German surveying authorities (AdV), as German CityGML tiles give them
#: (``urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH``, ``urn:adv:crs:DE_DHDN_3GK4*DE_DHN92_NH``).
_ADV_CRS = re.compile(r"urn:adv:crs:", re.IGNORECASE)


def country_from_crs(crs: Any) -> str | None:
    """ISO country code guessed from the EPSG codes of a CRS name (:func:`lod2energy.crs.epsg_codes`),
    or from an AdV CRS name (Germany); None when unknown."""

    for code in reversed(epsg_codes(crs)):
        if str(code) in _CRS_COUNTRY:
            return _CRS_COUNTRY[str(code)]
    if crs and _ADV_CRS.search(str(crs)):
        return "DE"
    return None


def parse_year(v: Any) -> int | None:
    """A year of construction from an attribute value (None if not plausible)."""
    if isinstance(v, bool) or v is None:
        return None
    if isinstance(v, (int, float, np.integer, np.floating)):
        if not np.isfinite(v):
            return None
        y = int(v)
    else:
        m = re.match(r"\s*(\d{4})", str(v))
        if not m:
            return None
        y = int(m.group(1))
    return y if 1000 <= y <= 2100 else None


def _number(v: Any) -> float | None:
    if isinstance(v, bool) or v is None:
        return None
    try:
        x = float(v)
    except (TypeError, ValueError):
        return None
    return x if np.isfinite(x) else None


def _first(b: Building, keys: tuple[str, ...], parse) -> tuple[Any, str | None]:
    for o in b.objects:
        for k in keys:
            if k in o.attributes:
                x = parse(o.attributes[k])
                if x is not None:
                    return x, k
    return None, None


@dataclass(frozen=True)
class Typology:
    """The typology chosen for a building and where each input came from.

    Attributes
    ----------
    country : str
        ISO code or ``"*"`` (generic).
    building_type : str
        One of :data:`BUILDING_TYPES`.
    year : int or None
        Year of construction found in the attributes.
    storeys : int
    footprint : float, m2
    height : float, m
    function : str or None
    sources : mapping
        Attribute (or ``"geometry"`` / ``"default"``) used for each input.
    """

    country: str
    building_type: str
    year: int | None
    storeys: int
    footprint: float
    height: float
    function: str | None
    attached: bool
    sources: Mapping[str, str]

    @property
    def lookup_year(self) -> int:
        return self.year if self.year is not None else DEFAULT_YEAR


def classify(b: Building, country: str | None = None, ground_area: float | None = None,
             z_extent: float | None = None) -> Typology:
    """Choose the typology of ``b`` from its attributes (fallbacks in the module docstring).

    Parameters
    ----------
    b : Building
    country : str, optional
        ISO code; ``None`` -> ``"*"``.
    ground_area : float, optional, m2
        Footprint from the geometry (GroundSurface area).
    z_extent : float, optional, m
        Vertical extent of the energy geometry (height fallback).
    """
    src: dict[str, str] = {}
    year, k = _first(b, YEAR_KEYS, parse_year)
    src["year"] = k or "default"
    height, k = _first(b, HEIGHT_KEYS, _number)
    if height is not None and k == "b3_h_dak_70p":
        ground, _ = _first(b, GROUND_LEVEL_KEYS, _number)
        height = height - ground if ground is not None else None
        k = k if height is not None else None
    if height is None or height <= 0:
        height, k = (float(z_extent), "geometry") if z_extent else (STOREY_HEIGHT, "default")
    src["height"] = k
    st, k = _first(b, STOREY_KEYS, _number)
    if st is None or st < 1:
        st, k = max(1.0, round(height / STOREY_HEIGHT)), "height"
    src["storeys"] = k
    fp, k = (ground_area, "geometry") if ground_area else _first(b, FOOTPRINT_KEYS, _number)
    if fp is None:
        fp, k = 0.0, "default"
    src["footprint"] = k
    shared, k = _first(b, SHARED_WALL_KEYS, _number)
    attached = bool(shared is not None and shared > 1.0)
    src["attached"] = k or "default"
    func, k = _first(b, FUNCTION_KEYS, lambda v: None if v in (None, "") else str(v))
    storeys = int(st)
    if storeys <= 3 and fp <= 250.0:
        btype = "terraced" if attached else "single-family"
    elif storeys <= 5:
        btype = "multi-family"
    else:
        btype = "apartment-block"
    return Typology(country or "*", btype, year, storeys, float(fp), float(height), func, attached, src)
