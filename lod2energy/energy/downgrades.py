"""Downgrades of the energy model: where a building's IDF is simpler than its repaired shell, and what that cost.

The energy model writes each Building/BuildingPart as its repaired shell, cut into storey
zones, with its party walls. Where that cannot be done it writes something simpler
(:mod:`lod2energy.energy.fallback`, :func:`lod2energy.energy.zones.storeys.storey_zones`);
each such choice is a :class:`Downgrade` of the building's record, with the change it made to
the zone's height, volume and floor area, so that report.csv, the GeoJSON, the console summary
and report.html say which buildings are not modelled as given.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import partial
from typing import Any, Mapping

from lod2energy.energy.zones.shells import ZoneShell
from lod2energy.geometry import signed_volume
from lod2energy.geometry.polygons import polygon_area3d

#: Kinds of downgrade, least change first.
KINDS = ("cleared_zone", "separated_zone", "storeys_merged", "whole_zone", "party_walls_dropped", "2.5d", "lod1_block")

#: The kind of each fallback of :data:`lod2energy.energy.fallback.FALLBACKS` (by function name).
FALLBACK_KIND = {"cleared_zone": "cleared_zone", "separated_zone": "separated_zone", "roof_zone": "2.5d",
                 "block_zone": "lod1_block"}


@dataclass(frozen=True)
class Downgrade:
    """One simplification of a building's energy model.

    Attributes
    ----------
    kind : str
        One of :data:`KINDS`: ``cleared_zone`` (points within EnergyPlus's tolerance of an
        edge moved clear of it), ``separated_zone`` (touching sheets pulled apart), ``2.5d``
        (roof planes kept, walls vertical), ``lod1_block`` (the footprint extruded),
        ``whole_zone`` (one zone over several storeys: no storey cut gives enclosed zones),
        ``storeys_merged`` (fewer storey zones than the building's storey plan: a dropped cut
        leaves a zone over two storeys),
        ``party_walls_dropped`` (the zone's party walls written as outdoor walls).
    zone : str
        The zone (Building/BuildingPart id) it applies to.
    reason : str
    d_height_m : float, m
        Height of the zone as written minus as repaired (``whole_zone``: minus one storey's).
    d_volume_m3 : float, m3
        Volume as written minus as repaired.
    d_floor_area_m2 : float, m2
        Area of the floor surfaces as written minus as repaired (``whole_zone``: minus the
        floors of its storeys, an area the IDF carries only in the zone's Floor Area field;
        ``party_walls_dropped``: 0, the reason gives the wall area).
    """

    kind: str
    zone: str
    reason: str
    d_height_m: float = 0.0
    d_volume_m3: float = 0.0
    d_floor_area_m2: float = 0.0

    def to_json(self) -> dict:
        return {"kind": self.kind, "zone": self.zone, "reason": self.reason, "d_height_m": self.d_height_m,
                "d_volume_m3": self.d_volume_m3, "d_floor_area_m2": self.d_floor_area_m2}

    @classmethod
    def from_json(cls, d: Mapping[str, Any]) -> "Downgrade":
        return cls(str(d["kind"]), str(d.get("zone") or ""), str(d.get("reason") or ""),
                   float(d.get("d_height_m") or 0.0), float(d.get("d_volume_m3") or 0.0),
                   float(d.get("d_floor_area_m2") or 0.0))


def zone_measures(zone: ZoneShell) -> tuple[float, float, float]:
    """``(height m, volume m3, floor area m2)`` of a zone shell: the z-range of its faces, its
    signed volume and the area of its ground and outdoor floor faces."""
    used = sorted({int(i) for f in zone.faces for r in f.rings for i in r})
    if not used:
        return 0.0, 0.0, 0.0
    z = zone.vertices[used, 2]
    tris, _ = zone.triangles()
    vol = float(signed_volume(zone.vertices, tris)) if len(tris) else 0.0
    floor = sum(polygon_area3d(zone.vertices[list(f.rings[0])]) for f in zone.faces if f.kind in ("ground", "floor"))
    return float(z.max() - z.min()), vol, float(floor)


def fallback_kind(make) -> str:
    """The :data:`KINDS` entry of a fallback of :data:`lod2energy.energy.fallback.FALLBACKS`,
    given as the function or by its name (``"block_zone(opening=0.1)"``)."""
    if isinstance(make, str):
        name = make.split("(")[0]
    else:
        name = (make.func if isinstance(make, partial) else make).__name__
    return FALLBACK_KIND.get(name, name)


def _r(x: float) -> float:
    return round(float(x), 3)


def replaced(kind: str, before: ZoneShell, after: ZoneShell, reason: str) -> Downgrade:
    """The downgrade of a zone ``before`` written as the simpler envelope ``after``."""
    h0, v0, a0 = zone_measures(before)
    h1, v1, a1 = zone_measures(after)
    return Downgrade(kind, before.object_id, reason, _r(h1 - h0), _r(v1 - v0), _r(a1 - a0))


def party_walls_dropped(zone: str, area: float, reason: str) -> Downgrade:
    """Party walls of ``zone`` (``area`` m2) written as outdoor walls."""
    return Downgrade("party_walls_dropped", zone, f"{area:.1f} m2 of party wall written as outdoor wall: {reason}")


def whole_zone(zone: ZoneShell, storey_height: float, upper_floor_area: float, reason: str) -> Downgrade:
    """A zone kept whole over several storeys of ``storey_height`` (m), whose upper storeys'
    floors (``upper_floor_area`` m2) are no surfaces of it."""
    h, _, _ = zone_measures(zone)
    return Downgrade("whole_zone", zone.object_id, reason, _r(max(h - storey_height, 0.0)), 0.0,
                     _r(-upper_floor_area))


def storeys_merged(zone: str, planned: int, written: int, d_height: float, d_floor_area: float) -> Downgrade:
    """Zone ``zone`` cut into ``written`` storey zones where its plan has ``planned``: its
    tallest zone ``d_height`` (m) higher than a storey, ``d_floor_area`` (m2) of storey floors
    not written (the merged storeys' floor sections, an area the IDF does not carry)."""
    return Downgrade("storeys_merged", zone, f"{written} storey zones for {planned} planned storeys: a storey "
                     "cut would pass too close to a vertex, a horizontal surface or an opening, or would not close",
                     _r(max(d_height, 0.0)), 0.0, _r(min(d_floor_area, 0.0)))


def summed(downgrades) -> tuple[float, float, float]:
    """``(d_height_m, d_volume_m3, d_floor_area_m2)`` summed over ``downgrades``; the height
    change is the largest in magnitude (zones side by side do not add heights)."""
    dg = list(downgrades)
    dh = max((d.d_height_m for d in dg), key=abs, default=0.0)
    return _r(dh), _r(sum(d.d_volume_m3 for d in dg)), _r(sum(d.d_floor_area_m2 for d in dg))


def party_area(party: Mapping, zone_index: int, zone: ZoneShell) -> float:
    """Area (m2) of the faces of zone ``zone_index`` with a party-wall overlap in ``party``
    (:func:`lod2energy.energy.surfaces.find_party_faces`): the overlaps' areas."""
    total = 0.0
    for (zi, _fi), overlaps in party.items():
        if zi == zone_index:
            total += sum(float(getattr(g, "area", 0.0)) for _, g in overlaps)
    return float(total)


