"""Building typology (country x construction period x building type) from a building's attributes.

Fallbacks (documented, in order):

Attributes are read through the attribute map (:mod:`lod2energy.thermal.attributes`, default
the ``auto`` profile); the ``--buildings`` row wins over them (:mod:`lod2energy.thermal.facts`).

- **year of construction**: the row's, else the first plausible value of the map's ``year``
  keys on the root object, then on its parts (sentinels and years later than the file's date
  are unknown); unknown -> ``None`` and the table lookup uses :data:`DEFAULT_YEAR` (1970: the
  middle of the European residential stock's age distribution); the construction period is
  then reported with the suffix ``" (assumed)"``.
- **storeys**: the building's storey plan (:func:`lod2energy.thermal.storeys.storeys`: the
  row's or the attributes' count, else the geometry's), the count report.json gives and the
  zoning cuts; without one (no geometry) height / 3 m (height from the map's ``height`` keys,
  else the geometry's vertical extent), at least 1.
- **footprint**: area of the GroundSurfaces of the energy geometries; else the map's
  ``footprint`` (``b3_opp_grond``).
- **attached**: a shared-wall area attribute (the map's ``shared_wall``, > 1 m2).
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

from lod2energy.crs import epsg_codes
from lod2energy.model import Building
from lod2energy.thermal.attributes import AttributeMap
from lod2energy.thermal.facts import Fact, attribute_map, count_of, storeys_candidates, year_fact

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
             z_extent: float | None = None, amap: AttributeMap | None = None, year: Fact | None = None,
             storeys: Fact | None = None, function: str | None = None) -> Typology:
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
    amap : AttributeMap, optional
        Default: the ``auto`` profile.
    year, storeys : Fact, optional
        Already resolved (:mod:`lod2energy.thermal.facts`); default: read here. A ``storeys``
        fact of the default (no geometry, no attribute) is not used (height / 3 m is).
    function : str, optional
        The use attribute's value, recorded.
    """
    amap = attribute_map(amap)
    src: dict[str, str] = {}
    year = year if year is not None else year_fact(b, amap)
    src["year"] = (year.key or year.source) if year.value is not None else "default"
    height, k = None, None
    hf = amap.read(b, "height", count_of)
    if hf is not None:
        height, k = hf.value, hf.key
        gkey = amap.field("height").ground.get(hf.key)
        if gkey is not None:
            gf = next((count_of(o.attributes[gkey]) for o in b.objects if gkey in o.attributes), None)
            height = height - gf if gf is not None else None
    if height is None or height <= 0:
        height, k = (float(z_extent), "geometry") if z_extent else (STOREY_HEIGHT, "default")
    src["height"] = k
    if storeys is None:
        storeys = next(iter(storeys_candidates(b, amap)), None)
    if storeys is not None and storeys.source != "default":
        st, k = float(storeys.value), storeys.key or storeys.source
    else:
        st, k = max(1.0, round(height / STOREY_HEIGHT)), "height"
    src["storeys"] = k
    fp, k = (ground_area, "geometry") if ground_area else (None, None)
    if fp is None:
        ff = amap.read(b, "footprint", count_of)
        fp, k = (ff.value, ff.key) if ff is not None else (0.0, "default")
    src["footprint"] = k
    sw = amap.read(b, "shared_wall", count_of)
    attached = bool(sw is not None and sw.value > 1.0)
    src["attached"] = sw.key if sw is not None else "default"
    storeys_n = int(st)
    if storeys_n <= 3 and fp <= 250.0:
        btype = "terraced" if attached else "single-family"
    elif storeys_n <= 5:
        btype = "multi-family"
    else:
        btype = "apartment-block"
    return Typology(country or "*", btype, year.value, storeys_n, float(fp), float(height), function, attached,
                    src)
