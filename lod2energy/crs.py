"""Coordinate reference systems: what pyproj says about the CRS a city model names.

Every question about a CRS (degrees or a linear unit? which axis first? how many metres in one
unit? where on the Earth?) is answered by pyproj from the CRS itself (:func:`crs_info`), for any
CRS pyproj reads. The names written in city models are read as pyproj reads them: CityJSON
1.1/2.0's ``https://www.opengis.net/def/crs/EPSG/0/<code>``, CityJSON 1.0's
``urn:ogc:def:crs:EPSG::<code>``, OGC URNs with a version, compound URNs
(``urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837``), ``EPSG:<code>``, WKT, PROJ strings; the
German AdV names (``urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH``,
``urn:adv:crs:DE_DHDN_3GK4*DE_DHN92_NH``), which pyproj does not read, stand for the EPSG code of
their horizontal part. A CRS pyproj cannot read counts as no CRS.

>>> epsg_code("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH*GCG2016")
25832
>>> cityjson_reference_system("urn:ogc:def:crs:EPSG::25833", "2.0")
'https://www.opengis.net/def/crs/EPSG/0/25833'
>>> crs_info("EPSG:2263").to_metre
0.30480060960121924
>>> crs_info("urn:ogc:def:crs:OGC:1.3:CRS84").lat_first
False
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

from lod2energy import cache
from lod2energy.errors import ParameterError

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


@dataclass(frozen=True)
class CrsInfo:
    """What pyproj says about a CRS (plain values: picklable, cheap to keep).

    Attributes
    ----------
    name : str
        pyproj's name of the CRS.
    horizontal : str
        The horizontal CRS as pyproj reads it again (``"EPSG:<code>"`` or WKT).
    code : int or None
        EPSG code of the horizontal CRS.
    geographic : bool
        Latitude / longitude in an angular unit (geographic 2D or 3D, or compound with one).
    placeable : bool
        Geographic or projected: its coordinates are positions on the Earth.
    lat_first : bool
        Geographic: latitude is the first axis (EPSG's order; OGC CRS84 is lon, lat).
    north_first : bool
        Projected: the first axis points north (JGD plane CSs, Gauss-Krueger as EPSG defines them).
    unit, vertical_unit : str
        Names of the horizontal and height units ("metre", "US survey foot", "degree").
    to_metre, vertical_to_metre : float
        Metres in one horizontal / height unit (projected CRSs; a CRS that declares no height
        axis has its heights in its horizontal unit). NaN: a unit that is not a length.
    """

    name: str
    horizontal: str
    code: int | None
    geographic: bool
    placeable: bool
    lat_first: bool = True
    north_first: bool = False
    unit: str = "metre"
    vertical_unit: str = "metre"
    to_metre: float = 1.0
    vertical_to_metre: float = 1.0

    @property
    def metric(self) -> bool:
        """Coordinates already in metres (nothing to convert)."""
        return self.geographic or (self.to_metre == 1.0 and self.vertical_to_metre == 1.0)

    @property
    def unit_problem(self) -> str | None:
        """Why the coordinates cannot be converted to metres, else None."""
        if self.geographic:
            return None
        bad = [u for u, f in ((self.unit, self.to_metre), (self.vertical_unit, self.vertical_to_metre))
               if not (math.isfinite(f) and f > 0)]
        if bad:
            return (f"CRS {self.name} declares coordinates in {bad[0]!r}, which is not a length unit "
                    "lod2energy can convert to metres")
        return None


def pyproj_input(crs: Any) -> str | None:
    """``crs`` as pyproj reads it: AdV names as the EPSG code of their horizontal part, a bare
    number as ``EPSG:<number>``, anything else unchanged (None for no CRS)."""
    if crs is None or crs == "":
        return None
    s = str(crs).strip()
    if s.isdigit():
        return f"EPSG:{s}"
    if "adv:crs" in s.lower():
        code = epsg_code(s)
        return f"EPSG:{code}" if code else s
    return s


def _length_factor(axis) -> float:
    f = getattr(axis, "unit_conversion_factor", None)
    kind = (getattr(axis, "unit_name", "") or "").lower()
    if f is None or "degree" in kind or "radian" in kind or "grad" in kind:
        return math.nan
    return float(f)


@cache.memoize("crs", 256)
def _info(text: str) -> CrsInfo | None:
    from pyproj import CRS
    from pyproj.exceptions import CRSError
    try:
        c = CRS.from_user_input(text)
    except (CRSError, TypeError, ValueError):
        code = epsg_codes(text)  # a spelling pyproj does not read, but with an EPSG code in it
        if not code or text.startswith("EPSG:"):
            return None
        try:
            c = CRS.from_user_input("EPSG:" + "+".join(str(x) for x in code[:2]))
        except (CRSError, TypeError, ValueError):
            return None
    subs = c.sub_crs_list if c.is_compound else [c]
    h = subs[0]
    if getattr(h, "is_bound", False) and h.source_crs is not None:
        h = h.source_crs
    axes = list(h.axis_info)
    vaxes = [a for s in subs[1:] for a in s.axis_info] or axes[2:]
    geographic = bool(h.is_geographic)
    placeable = geographic or bool(h.is_projected)
    auth = h.to_authority(min_confidence=100)
    code = int(auth[1]) if auth and auth[0] == "EPSG" and auth[1].isdigit() else None
    horizontal = f"{auth[0]}:{auth[1]}" if auth else h.to_wkt()
    first = (axes[0].direction if axes else "east").lower()
    unit = axes[0].unit_name if axes else "metre"
    to_metre = 1.0 if geographic else (_length_factor(axes[0]) if axes else 1.0)
    vunit, v_to_metre = (vaxes[0].unit_name, _length_factor(vaxes[0])) if vaxes else (unit, to_metre)
    if geographic:
        v_to_metre, vunit = (1.0, "metre") if not vaxes else (v_to_metre, vunit)
    return CrsInfo(name=c.name, horizontal=horizontal, code=code, geographic=geographic, placeable=placeable,
                   lat_first=geographic and first == "north", north_first=not geographic and first == "north",
                   unit=unit, vertical_unit=vunit, to_metre=to_metre, vertical_to_metre=v_to_metre)


def crs_info(crs: Any) -> CrsInfo | None:
    """What pyproj says about ``crs`` (:class:`CrsInfo`), None for no CRS or one pyproj cannot
    read (kept per process in :mod:`lod2energy.cache`)."""
    text = pyproj_input(crs)
    return _info(text) if text else None


def is_geographic(crs: Any) -> bool:
    """Whether ``crs`` is a geographic CRS pyproj reads (coordinates in degrees, not metres)."""
    info = crs_info(crs)
    return bool(info and info.geographic)


def latitude_first(crs: Any) -> bool:
    """Axis order of a geographic CRS from pyproj's ``axis_info``: EPSG's are (lat, lon), OGC
    CRS84's (lon, lat); True for anything else."""
    info = crs_info(crs)
    return True if info is None or not info.geographic else info.lat_first


def no_crs_reason(crs: Any) -> str | None:
    """Why ``crs`` places nothing on the Earth ("no CRS", "CRS ... that pyproj cannot read",
    "CRS ... is not geographic or projected"), None when it does."""
    if crs is None or crs == "":
        return "no CRS"
    info = crs_info(crs)
    if info is None:
        return f"CRS {crs!r} that pyproj cannot read"
    if not info.placeable:
        return f"CRS {crs!r} ({info.name}) that is neither geographic nor projected"
    return None


def metres_note(path: str, crs: Any) -> str | None:
    """The note (logged at INFO) for a file whose coordinates are taken as metres (no CRS pyproj
    reads), None when its CRS is read."""
    why = no_crs_reason(crs)
    if not why:
        return None
    return (f"{path}: {why}: coordinates are taken as metres "
            "(--crs gives the file's CRS)")


def spelled(crs: Any) -> str:
    """A user's CRS (``--crs``: any form pyproj reads) as a CityJSON ``referenceSystem``: the
    OGC URL of the EPSG (or OGC) CRS it is, or that pyproj finds equivalent to it (axis order
    included); as given when there is none.

    Raises
    ------
    ParameterError
        pyproj cannot read it.
    """
    from pyproj import CRS
    text = pyproj_input(crs)
    if not text or crs_info(text) is None:
        raise ParameterError(f"--crs {crs}: not a CRS pyproj can read")
    c = CRS.from_user_input(text)
    for auth in (c.to_authority(min_confidence=100), c.to_authority("EPSG", min_confidence=70),
                 c.to_authority(min_confidence=70)):
        if auth and auth[0] in ("EPSG", "OGC") and c.equals(CRS.from_user_input(f"{auth[0]}:{auth[1]}")):
            return f"https://www.opengis.net/def/crs/{auth[0]}/0/{auth[1]}"
    return text
