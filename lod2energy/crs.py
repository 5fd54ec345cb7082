"""Coordinate reference system names: EPSG codes from the spellings found in city models.

CityJSON 1.1/2.0 want ``https://www.opengis.net/def/crs/EPSG/0/<code>``, CityJSON 1.0
``urn:ogc:def:crs:EPSG::<code>``; CityGML files use OGC URNs, ``EPSG:<code>``, compound
URNs (``urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837``) or the German AdV names
(``urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH``, ``urn:adv:crs:DE_DHDN_3GK4*DE_DHN92_NH``).

>>> epsg_code("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH*GCG2016")
25832
>>> cityjson_reference_system("urn:ogc:def:crs:EPSG::25833", "2.0")
'https://www.opengis.net/def/crs/EPSG/0/25833'
"""
from __future__ import annotations

import re
from typing import Any

_EPSG = re.compile(r"EPSG(?:/[\d.]+/|:[\d.]*:|:)(\d{4,6})", re.IGNORECASE)
#: AdV (German surveying authorities) CRS names -> the EPSG code of their horizontal part.
#: The height reference (DHHN92 / DHHN2016) has no place in a single CityJSON code.
_ADV = (
    (re.compile(r"ETRS89_UTM(3[1-3])", re.IGNORECASE), lambda m: 25800 + int(m.group(1))),
    (re.compile(r"DE_DHDN_3GK([2-5])", re.IGNORECASE), lambda m: 31464 + int(m.group(1))),
)


def epsg_codes(crs: Any) -> list[int]:
    """Every EPSG code a CRS name holds, in order (a compound URN holds two: horizontal,
    vertical); an AdV name gives the code of its horizontal part.

    Parameters
    ----------
    crs : str, int or None
        A CRS name as written in a CityJSON ``referenceSystem`` or a CityGML ``srsName``, or
        a bare code (CityJSON 0.x / 1.0 ``"crs": {"epsg": 7415}``).
    """
    if not crs:
        return []
    s = str(crs).strip()
    if s.isdigit():
        return [int(s)]
    codes = [int(c) for c in _EPSG.findall(s)]
    if not codes and "adv:crs" in s.lower():
        codes = [code(m) for rx, code in _ADV for m in [rx.search(s)] if m][:1]
    return codes


def epsg_code(crs: Any) -> int | None:
    """The first (horizontal) EPSG code of a CRS name (:func:`epsg_codes`), or None."""
    codes = epsg_codes(crs)
    return codes[0] if codes else None


def cityjson_reference_system(crs: Any, version: str = "2.0") -> str | None:
    """``crs`` spelled as CityJSON ``version`` wants it; the input unchanged when no EPSG
    code is recognised (None for no CRS)."""
    if not crs:
        return None
    code = epsg_code(crs)
    if code is None:
        return str(crs)
    return f"urn:ogc:def:crs:EPSG::{code}" if version == "1.0" else f"https://www.opengis.net/def/crs/EPSG/0/{code}"


#: Geographic (latitude / longitude in degrees) EPSG CRSs met in city models, 2D and 3D:
#: WGS 84, ETRS89, NAD83, JGD2000/2011 (and PLATEAU's JGD2011 + height), GDA94/2020, NZGD2000,
#: CGCS2000, KGD2002, TWD97.
GEOGRAPHIC_EPSG = frozenset({4326, 4979, 4258, 4937, 4269, 4759, 4612, 6667, 6668, 6697, 4283, 4939, 7843, 7844,
                             4167, 4959, 4490, 4480, 4737, 3824})
_CRS84 = re.compile(r"CRS[ :_]?84", re.IGNORECASE)


def is_geographic(crs: Any) -> bool:
    """Whether ``crs`` names a geographic CRS (coordinates in degrees, not metres)."""
    if not crs:
        return False
    return bool(_CRS84.search(str(crs))) or epsg_code(crs) in GEOGRAPHIC_EPSG


def latitude_first(crs: Any) -> bool:
    """Axis order of a geographic CRS: EPSG's are (lat, lon), OGC CRS84's (lon, lat)."""
    return not _CRS84.search(str(crs or ""))
