"""The storey plan of a building: how many storeys, how high, where its eave and ground are.

:func:`storeys` decides it once for every reader: the thermal stage records its count as the
``storeys`` :class:`~lod2energy.thermal.facts.Fact` (report.json/csv, GeoJSON, the hand-offs),
the typology classifies by that count, and the zoning (:mod:`lod2energy.energy.zones.storeys`)
cuts each Building/BuildingPart into the storeys of its :class:`PartStoreys`. A zone whose
written storeys differ from its part's plan is a recorded downgrade
(:mod:`lod2energy.energy.downgrades`: ``whole_zone``, ``storeys_merged``).

Order of the sources (the first that gives a count wins; :attr:`Storeys.source` says which):

1. the ``--buildings`` row, then the **attributes** of the root object, then of its parts,
   through the attribute map's ``storeys`` field (:mod:`lod2energy.thermal.attributes`; by
   default CityGML ``bldg:storeysAboveGround``, the 3DBAG's ``b3_bouwlagen``, OSM-style
   ``building:levels``, ...); ``storey_heights`` (CityGML ``storeyHeightsAboveGround``, a list
   or a whitespace-separated string of heights, m) gives the heights, and the count when no
   count is given. Sentinels (9999) are unknown, and so is an attribute's count that gives a
   storey height outside 2-6 m (:func:`lod2energy.thermal.facts.storeys_candidates`), with a
   warning; the user's row is taken as given.
2. **geometry** (:func:`roof_levels`): the ground level ``z0`` (lowest point of the ground
   surfaces, else of the shell), the eave level (area-weighted median over the roof faces of
   each face's lowest point: a flat roof's own height, a pitched roof's eave) and the ridge
   (highest roof point). Storeys below the eave: ``max(1, round((eave - z0) / h))`` with
   ``h`` the floor-to-floor height of the use (:data:`STOREY_HEIGHT`); one more storey in
   the roof space when it is at least :data:`ATTIC_MIN_HEIGHT` high (``ridge - eave``), as
   a habitable attic counts as a storey (the 3DBAG ``b3_bouwlagen`` counts it too); storeys
   above the eave where the building rises more than a storey above it
   (:func:`storeys_above_eave`: a tower on a podium, whose eave is the podium's roof). The
   building's count is the largest of its Building/BuildingParts' (:func:`part_levels`, each
   split by :func:`split_storeys`): a five-storey wing makes a five-storey building.

A given count (table or attribute) is split over the parts too: the tallest part gets it
(:func:`split_count`), the others their own storeys of the same height, at most the count.

:data:`STOREY_HEIGHT` values are indicative floor-to-floor heights (clear height plus a
0.3 m floor): residential 2.8 m (Dutch/German stock: 2.4-2.6 m clear), offices 3.5 m,
retail 4.0 m, education and health 3.6 m, hospitality 3.2 m, industry 5.0 m, other 3.0 m.
Measured on the shared 3DBAG tiles by ``benchmarks/bench_storeys.py``.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from lod2energy.geometry import newell_normal
from lod2energy.model import Building
from lod2energy.thermal.attributes import AttributeMap
from lod2energy.thermal.facts import STOREY_HEIGHT_RANGE, Fact, storeys_candidates

#: Floor-to-floor height (m) by use type (indicative, see the module docstring).
STOREY_HEIGHT = {"residential": 2.8, "office": 3.5, "retail": 4.0, "education": 3.6, "health": 3.6,
                 "hospitality": 3.2, "industry": 5.0, "other": 3.0}
#: A roof space at least this high (ridge - eave, m) counts as a storey and is its own zone.
ATTIC_MIN_HEIGHT = 2.0
#: Storey zones are never cut lower than this (m): a count that would need lower storeys
#: (an attribute counting storeys in the roof space, say) gives fewer, taller storey zones.
MIN_STOREY_HEIGHT = 2.2
#: Roof faces tilted less than this (degrees) are flat.
FLAT_TILT = 10.0


@dataclass(frozen=True)
class RoofLevels:
    """Heights of a building's geometry (m, in the input's vertical datum).

    Attributes
    ----------
    ground, eave, ridge : float
    pitched : bool
        The roof faces at and above the eave are mostly pitched (not flat).
    """

    ground: float
    eave: float
    ridge: float
    pitched: bool

    @property
    def attic_height(self) -> float:
        return max(self.ridge - self.eave, 0.0) if self.pitched else 0.0


@dataclass(frozen=True)
class Storeys:
    """Storeys of a building and where the count came from.

    Attributes
    ----------
    count : int
        Storeys above ground, the attic storey included when :attr:`attic` is True.
    source : str
        ``"table"``, ``"map"``, ``"attribute"``, ``"geometry"`` or ``"default"``
        (:mod:`lod2energy.thermal.facts`).
    storey_height : float, m
        Floor-to-floor height of the storeys below the eave.
    attic : bool
        The roof space is tall enough to be a storey (and a zone) of its own.
    heights : tuple of float or None, m
        ``storeyHeightsAboveGround`` when given.
    levels : RoofLevels or None
    """

    count: int
    source: str
    storey_height: float
    attic: bool
    heights: tuple[float, ...] | None = None
    levels: RoofLevels | None = None
    key: str | None = None
    #: The plan of each Building/BuildingPart with geometry (:class:`PartStoreys`).
    parts: tuple["PartStoreys", ...] = ()

    def part(self, object_id: str) -> "PartStoreys | None":
        """The plan of the part a zone was made of (``object_id``, or ``ID_sK`` for a solid of
        several), None when no part has that id."""
        by_id = {p.object_id: p for p in self.parts}
        if object_id in by_id:
            return by_id[object_id]
        base = re.sub(r"_s\d+$", "", object_id)
        return by_id.get(base)

    @property
    def below_eave(self) -> int:
        """Storeys but the attic storey."""
        return max(1, self.count - (1 if self.attic else 0))


@dataclass(frozen=True)
class PartStoreys:
    """The storeys of one Building/BuildingPart: what its zone is cut into.

    Attributes
    ----------
    object_id : str
    below : int
        Storeys under the eave (at least 1).
    attic : bool
        The top storey is the pitched roof space.
    above : int
        Storeys above the eave, the attic included (:func:`storeys_above_eave`).
    levels : RoofLevels
    """

    object_id: str
    below: int
    attic: bool
    above: int
    levels: RoofLevels

    @property
    def count(self) -> int:
        return self.below + self.above


def split_storeys(levels: RoofLevels, storey_height: float) -> tuple[int, bool, int]:
    """``(below, attic, above)``: the storeys of a shell of ``levels`` with storeys of
    ``storey_height`` (m): ``round((eave - ground) / h)`` under the eave, none lower than
    :data:`MIN_STOREY_HEIGHT`; an attic when the pitched roof space is at least
    :data:`ATTIC_MIN_HEIGHT` high; :func:`storeys_above_eave` above it. The one rule of the
    estimate and of the zoning."""
    span = levels.eave - levels.ground
    n = max(1, int(round(span / storey_height))) if storey_height > 0 else 1
    n = max(1, min(n, int(span / MIN_STOREY_HEIGHT)))
    attic = levels.attic_height >= ATTIC_MIN_HEIGHT
    return n, attic, storeys_above_eave(levels.ridge - levels.eave, storey_height, attic)


def split_count(levels: RoofLevels, count: int, storey_height: float, attic: bool) -> tuple[int, bool, int]:
    """``(below, attic, above)`` of a given ``count`` of storeys of ``storey_height`` (m):
    the attic (when ``attic``) on top, the storeys under the eave as many as fit
    (``round((eave - ground) / h)``, at most ``count`` less the attic), the rest above the eave."""
    rest = max(1, count - (1 if attic else 0))
    below = rest
    if storey_height > 0:
        below = max(1, min(rest, int(round((levels.eave - levels.ground) / storey_height))))
    return below, attic and count >= 2, count - below


def storeys_above_eave(span: float, storey_height: float, attic: bool) -> int:
    """Storeys between the eave and the top, the attic included.

    A pitched roof space tall enough (``attic``) is one attic storey, however high. Else the
    space above the eave is part of the top storey under the eave as long as that keeps the
    top storey zone at most two storey heights high; higher (a tower on a podium: the eave,
    the median roof level by area, is the podium's roof), it is ``round(span / storey_height)``
    storeys, none lower than :data:`MIN_STOREY_HEIGHT`.

    Parameters
    ----------
    span : float, m
        ``ridge - eave``.
    storey_height : float, m
    attic : bool
        The roof space is pitched and at least :data:`ATTIC_MIN_HEIGHT` high.

    Returns
    -------
    int
        0 when the space above the eave stays in the top storey, 1 for an attic alone.
    """
    if attic:
        return 1
    if storey_height <= 0 or not span > storey_height:
        return 0
    return max(1, min(int(round(span / storey_height)), int(span / MIN_STOREY_HEIGHT)))


def storeys_from_attributes(b: Building, amap: AttributeMap | None = None
                            ) -> tuple[int | None, str | None, tuple[float, ...] | None]:
    """``(count, attribute key, storey heights)`` from the attributes alone, Nones when absent."""
    f = next((f for f in storeys_candidates(b, amap) if f.source != "table"), None)
    return (f.value, f.key, f.raw) if f is not None else (None, None, None)


def _surfaces(b: Building, lod: str | None):
    """``(object id, semantic type, outer ring (n, 3) m)`` of every surface of ``b``'s envelope."""
    for o, _, g in b.envelope(lod):
        for _, hi, _, s in g.iter_surfaces():
            if hi > 0:
                continue
            yield o.id, g.semantic_type(s), b.vertices[np.asarray(s.outer, dtype=np.intp)]


def part_levels(b: Building, lod: str | None = None) -> dict[str, RoofLevels]:
    """:func:`roof_levels` of each Building/BuildingPart of ``b``'s envelope, by object id (one
    pass over the surfaces)."""
    by_part: dict[str, list] = {}
    for oid, kind, p in _surfaces(b, lod):
        by_part.setdefault(oid, []).append((kind, p))
    levels = {oid: levels_of(surfaces) for oid, surfaces in by_part.items()}
    return {oid: lv for oid, lv in levels.items() if lv is not None}


def roof_levels(b: Building, lod: str | None = None) -> RoofLevels | None:
    """Ground, eave and ridge heights of ``b`` from its labelled surfaces (None without
    geometry): :func:`levels_of` its surfaces."""
    return levels_of((kind, p) for _, kind, p in _surfaces(b, lod))


def levels_of(surfaces) -> RoofLevels | None:
    """Ground, eave and ridge heights of ``(semantic type, outer ring (n, 3) m)`` surfaces (None
    when none is usable).

    Faces without a semantic label count as roof when they face up (n_z > 0.1) and are not the
    lowest horizontal face.
    """
    ground_z, all_z, roofs = [], [], []
    for kind, p in surfaces:
        if len(p) < 3 or not np.all(np.isfinite(p)):
            continue
        all_z.append(p[:, 2])
        n = newell_normal(p)
        area = 0.5 * float(np.linalg.norm(n))
        if area <= 1e-9:
            continue
        nz = float(n[2]) / (2 * area)
        if kind == "GroundSurface" or (kind is None and nz < -0.9):
            ground_z.append(float(p[:, 2].min()))
        elif kind == "RoofSurface" or (kind is None and nz > 0.1):
            tilt = float(np.degrees(np.arccos(np.clip(nz, -1, 1))))
            roofs.append((float(p[:, 2].min()), float(p[:, 2].max()), area * max(nz, 0.0), tilt))
    if not all_z:
        return None
    z = np.concatenate(all_z)
    z0 = min(ground_z) if ground_z else float(z.min())
    if not roofs:
        top = float(z.max())
        return RoofLevels(z0, top, top, False)
    eave, pitched = eave_and_pitch(roofs)
    ridge = max(top for _, top, _, _ in roofs)
    return RoofLevels(z0, max(eave, z0), max(ridge, eave, z0), pitched)


def eave_and_pitch(roofs: list[tuple[float, float, float, float]]) -> tuple[float, bool]:
    """Eave height (m) and whether the roof is pitched, from ``(z min, z max, area x n_z,
    tilt in degrees)`` per roof face: the eave is the lowest point of the face at the weighted
    median of the faces by their lowest point; pitched when faces tilted :data:`FLAT_TILT` or
    more hold most of the area reaching 0.1 m above the eave."""
    r = np.array(roofs)
    order = np.argsort(r[:, 0])
    w = np.cumsum(r[order, 2])
    k = int(np.searchsorted(w, 0.5 * w[-1])) if w[-1] > 0 else 0
    eave = float(r[order[min(k, len(order) - 1)], 0])
    above = r[r[:, 1] > eave + 0.1]
    return eave, bool(len(above) and above[above[:, 3] >= FLAT_TILT, 2].sum() > 0.5 * above[:, 2].sum())


def estimate_storeys(levels: RoofLevels, use: str = "residential",
                     parts: dict[str, RoofLevels] | None = None) -> Storeys:
    """Storeys from the geometry alone (see the module docstring): the largest count of the
    ``parts`` (:func:`part_levels`), else of the building's ``levels``."""
    h = STOREY_HEIGHT.get(use, STOREY_HEIGHT["other"])
    plans = tuple(PartStoreys(k, *split_storeys(lv, h), lv) for k, lv in (parts or {}).items())
    if plans:
        top = max(plans, key=lambda p: p.count)
        return Storeys(top.count, "geometry", h, top.attic, None, levels, None, plans)
    below, attic, above = split_storeys(levels, h)
    return Storeys(below + above, "geometry", h, attic, None, levels)


def _given_parts(parts: dict[str, RoofLevels], n: int, h: float, attic: bool) -> tuple[PartStoreys, ...]:
    """The parts' plans for a given count ``n`` of storeys ``h`` high: the tallest part (by its
    ridge) has the ``n`` storeys, each other its own, at most ``n``."""
    if not parts:
        return ()
    tallest = max(parts, key=lambda k: (parts[k].ridge, k))
    out = []
    for k, lv in parts.items():
        if k == tallest:
            out.append(PartStoreys(k, *split_count(lv, n, h, attic and lv.attic_height >= ATTIC_MIN_HEIGHT), lv))
            continue
        below, a, above = split_storeys(lv, h)
        while below + above > n and above > 0:
            above -= 1
            a = a and above > 0
        below = min(below, n - above)
        out.append(PartStoreys(k, below, a, above, lv))
    return tuple(out)


def storeys(b: Building, use: str = "residential", lod: str | None = None,
            use_attributes: bool = True, amap: AttributeMap | None = None, warnings: list | None = None) -> Storeys:
    """Storeys of ``b``: from its row or attributes when given (and ``use_attributes``), else estimated.

    With a given count, the storey height is the eave height over the storeys under the
    eave (the attic counts as one when the roof space is tall enough); when that is lower
    than :data:`MIN_STOREY_HEIGHT` the storeys reach above the eave (a set-back tower) and
    the storey height is the ridge height over the count. A building prepared by the
    thermal stage carries its count in ``provenance["thermal"]["facts"]``, which is reused.

    Parameters
    ----------
    b : Building
    use : str
        Use type (:data:`STOREY_HEIGHT` keys) for the estimate.
    lod : str, optional
    use_attributes : bool
        False: geometry only (what the benchmark measures).
    amap : AttributeMap, optional
        Default: the ``auto`` profile.
    warnings : list, optional
        ``(field, text)`` appended for each count taken as unknown.
    """
    levels = roof_levels(b, lod)
    parts = part_levels(b, lod) if levels is not None else {}
    cands: list[Fact] = []
    if use_attributes:
        known = ((b.provenance.get("thermal") or {}).get("facts") or {}).get("storeys")
        if known is None:
            cands = storeys_candidates(b, amap, warnings)
        elif known["source"] not in ("geometry", "default"):
            h = known.get("raw")
            cands = [Fact(int(known["value"]), known["source"], known.get("key"), tuple(h) if h else None)]
    for f in cands:
        n, heights = int(f.value), f.raw
        if levels is None:
            return Storeys(n, f.source, float(np.mean(heights)) if heights else STOREY_HEIGHT.get(use, 3.0),
                           False, heights, None, f.key)
        attic = n >= 2 and levels.attic_height >= ATTIC_MIN_HEIGHT
        below = max(1, n - (1 if attic else 0))
        if levels.eave > levels.ground:
            h = (levels.eave - levels.ground) / below
            if not attic and h < MIN_STOREY_HEIGHT and levels.ridge - levels.ground >= n * MIN_STOREY_HEIGHT:
                h = (levels.ridge - levels.ground) / n  # storeys reach above the eave: a set-back tower
            if f.source != "table" and not (STOREY_HEIGHT_RANGE[0] <= h <= STOREY_HEIGHT_RANGE[1]):
                if warnings is not None:
                    warnings.append(("storeys", f"{n} storeys ({f.key or f.source}) taken as unknown: a storey "
                                     f"height of {h:.1f} m is outside {STOREY_HEIGHT_RANGE[0]:g}-"
                                     f"{STOREY_HEIGHT_RANGE[1]:g} m"))
                continue
        else:
            h = STOREY_HEIGHT.get(use, 3.0)
        return Storeys(n, f.source, float(h), attic, heights, levels, f.key, _given_parts(parts, n, float(h), attic))
    if levels is None:
        return Storeys(1, "default", STOREY_HEIGHT.get(use, 3.0), False)
    return estimate_storeys(levels, use, parts)
