"""Zones as written: one per Building/BuildingPart or per storey, floors, what each zone is.

Floorless parts and simpler envelopes are decided before the writer, by the energy model
stage (:mod:`lod2energy.energy.model`).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np

from lod2energy.energy import downgrades as dg
from lod2energy.energy.enclosure import enclosure_defects
from lod2energy.energy.openings import Opening
from lod2energy.energy.pieces import Piece, _pieces_from_points
from lod2energy.energy.zones import cut as zoning
from lod2energy.energy.zones.shells import ZoneShell
from lod2energy.geometry.polygons import newell_normal, polygon_area3d, unit
from lod2energy.validate.closed import check_closed_outward
from lod2energy.thermal.storeys import PartStoreys, RoofLevels, split_storeys, storeys
from lod2energy.thermal.facts import is_conditioned
from lod2energy.thermal.use import recorded_use


#: EnergyPlus puts a zone's interior solar gains on its floors, and counts a surface as one
#: only when it faces down more than 30 degrees past vertical (tilt > 120 degrees): outward
#: n_z below this. A zone without one stops with a severe error.
FLOOR_NZ = -0.5


def with_floor(pieces: list[Piece], tilt_band: float = 0.05) -> tuple[list[Piece], int]:
    """Pieces of a zone with at least one Floor: EnergyPlus needs one in every zone.

    A zone without ground or floor surfaces (a roof superstructure whose underside sits on
    the main roof) has EnergyPlus guess its floor. Its most downward-facing pieces (outward
    ``n_z`` within ``tilt_band`` of the lowest, and under ``FLOOR_NZ``) are written as
    Floor, boundary condition unchanged.

    Returns
    -------
    pieces : list of Piece
    changed : int
        How many pieces became Floor (0 when the zone had a floor).
    """
    if not pieces or any(p.kind in ("ground", "floor") for p in pieces):
        return pieces, 0
    nz = np.array([unit(newell_normal(p.points))[2] for p in pieces])
    low = float(nz.min())
    if not low < FLOOR_NZ:  # EnergyPlus would not take it as a floor either
        return pieces, 0
    pick = (nz <= low + tilt_band) & (nz < FLOOR_NZ)
    out = [replace(p, kind="floor") if k else p for p, k in zip(pieces, pick)]
    return out, int(pick.sum())


@dataclass(frozen=True)
class ZoneInfo:
    """What a written zone is: its storey, use and whether it is conditioned.

    Attributes
    ----------
    building_id : str
    storey : int or None
        1 for the ground storey; None for a whole-building zone.
    attic : bool
    conditioned : bool
    use : str
        Use type (:data:`lod2energy.thermal.use.USE_TYPES`).
    upper_floor_area : float, m2
        For a zone kept whole over several storeys (``--zoning building``, or a storey cut that
        would not close): the gross floor area of its storeys above the lowest
        (:func:`upper_floor_area`), which the IDF adds to the area of its floor surfaces as the
        ``Zone``'s Floor Area. 0 for a storey zone and a one-storey zone.
    """
    building_id: str
    storey: int | None
    attic: bool
    conditioned: bool
    use: str
    upper_floor_area: float = 0.0


def _storey_plan(pieces: list[Piece], storey_height: float, part: PartStoreys | None = None
                 ) -> tuple[float, float, float, int, bool, int]:
    """``(ground, eave, ridge, storeys below the eave, attic, storeys above the eave)`` of a
    zone's pieces (m): the storeys :func:`storey_zones` cuts it into and the ones
    :func:`upper_floor_area` counts. The counts are the building's plan for the zone's part
    (``part``, :class:`lod2energy.thermal.storeys.PartStoreys`) when given, else split from the
    zone's own levels as the plan splits a part (:func:`lod2energy.thermal.storeys.split_storeys`);
    the levels are the zone's own, each roof face's eave taken from the whole face (not from the
    convex pieces it is written as)."""
    ground, eave, ridge, pitched = zoning.zone_levels([(p.points, p.kind) for p in pieces],
                                                      [p.face_index for p in pieces])
    if part is not None:
        return ground, eave, ridge, part.below, part.attic, part.above
    n, attic, above = split_storeys(RoofLevels(ground, eave, ridge, pitched), storey_height)
    return ground, eave, ridge, n, attic, above


def _levels(ground: float, eave: float, ridge: float, n: int, attic: bool, above: int) -> list[float]:
    """Floor levels (m) of the storeys above the lowest, as :func:`zoning.storey_cuts` aims at them;
    the attic floor last when ``attic``."""
    levels = [ground + k * (eave - ground) / n for k in range(1, n)]
    return levels + [eave + k * (ridge - eave) / above for k in range(above)]


def upper_floor_area(pieces: list[Piece], storey_height: float, attic_mode: str,
                     part: PartStoreys | None = None) -> float:
    """Gross floor area (m2) of the storeys above the lowest of a zone kept whole.

    A zone that spans ``n`` storeys (counted as :func:`storey_zones` counts them: the storeys
    under the eave split ``eave - ground`` evenly, those above it ``ridge - eave``) has, besides
    its floor surfaces (the lowest storey's floor), the floors of storeys ``2 .. n``: each the
    horizontal section of its closed shell at that storey's floor level
    (:func:`lod2energy.energy.zones.cut.section_area`), and, with ``attic_mode == "conditioned"``, the
    attic floor as a conditioned attic zone would have. These are
    the floors storey zoning would write, so a building has the same conditioned floor area
    whether it is cut into storey zones or kept whole. The sections follow the real shell
    (a set-back top storey or a lower wing counts only where it is), which footprint x storeys
    would not.

    Parameters
    ----------
    pieces : list of Piece
        The zone's final pieces (closed, outward).
    storey_height : float, m
        The building's (:attr:`lod2energy.thermal.storeys.Storeys.storey_height`).
    attic_mode : {"unconditioned", "conditioned"}
    part : PartStoreys, optional
        The building's plan for the zone's part (:func:`_storey_plan`).

    Returns
    -------
    float, m2
        0 for a one-storey zone without a conditioned attic.
    """
    if not pieces:
        return 0.0
    ground, eave, ridge, n, attic, above = _storey_plan(pieces, storey_height, part)
    levels = _levels(ground, eave, ridge, n, attic, above)
    if attic and attic_mode != "conditioned":
        levels = levels[:-1]
    polys = [p.points for p in pieces]
    return float(sum(zoning.section_area(polys, z) for z in levels))


def storey_zones(zone: ZoneShell, zi: int, pieces: list[Piece], storey_height: float,
                 attic_mode: str, openings: Sequence[Opening] = (), part: PartStoreys | None = None
                 ) -> tuple[list[tuple[ZoneShell, list[Piece], bool]], str | None]:
    """One zone per storey of a zone's written pieces (:func:`lod2energy.energy.zones.cut.split_storeys`).

    Parameters
    ----------
    zone : ZoneShell
    zi : int
        Its index (keys the interzone pairs).
    pieces : list of Piece
        Its final pieces (closed, as written).
    storey_height : float, m
        The building's: the zone gets ``round((eave - ground) / storey_height)`` storeys under
        its eave and :func:`~lod2energy.thermal.storeys.storeys_above_eave` above it.
    attic_mode : {"unconditioned", "conditioned"}
    openings : sequence of Opening
        The zone's real windows and doors: no storey cut passes through one.
    part : PartStoreys, optional
        The building's plan for the zone's part: its storeys are cut (:func:`_storey_plan`).

    Returns
    -------
    zones : list of (ZoneShell, pieces, attic)
        The storey zones, lowest first; ``[(zone, pieces, False)]`` when it stays one zone.
        Fewer than planned where a cut was dropped (:func:`planned_storeys` tells).
    note : str or None
        Why it stayed one zone (a cut that would not close, a storey EnergyPlus would find not
        enclosed), when it did.
    """
    single = [(zone, pieces, False)]
    if not pieces:
        return single, None
    ground, eave, ridge, n, attic, above = _storey_plan(pieces, storey_height, part)
    allz = np.concatenate([p.points[:, 2] for p in pieces])
    horiz = [float(p.points[0, 2]) for p in pieces if np.ptp(p.points[:, 2]) <= 1e-6]
    spans = [(float(o.points[:, 2].min()), float(o.points[:, 2].max())) for o in openings]
    cuts, attic = zoning.storey_cuts(allz, ground, eave, ridge, n, attic, horiz, spans, above)
    if not cuts:
        return single, None
    note = None
    variants = zoning.cut_variants(cuts, attic, allz, horiz)
    if len(cuts) > 1:  # then one cut fewer: a zone over two storeys (recorded) rather than one zone
        variants += [(cuts[:i] + cuts[i + 1:], attic and i < len(cuts) - 1) for i in range(len(cuts) - 1, -1, -1)]
    for cs, with_attic in variants:
        slabs = zoning.split_storeys([(p.points, p) for p in pieces], cs, _pieces_from_points, with_attic)
        if slabs is None:
            note = f"zone {zone.object_id}: kept as one zone (no storey section closes)"
            continue
        out = []
        for k, sl in enumerate(slabs):
            zp = [replace(tag, points=q) for q, tag in sl.polygons]
            zp += [Piece(q, "floor", "Surface", 0.0, -1, f"{zi}.{k - 1}.{i}:f") for i, q in enumerate(sl.floor)]
            zp += [Piece(q, "ceiling", "Surface", 0.0, -1, f"{zi}.{k}.{i}:c") for i, q in enumerate(sl.ceiling)]
            pts = [p.points for p in zp]
            if check_closed_outward(pts) or enclosure_defects(pts):
                note = (f"zone {zone.object_id}: kept as one zone (no storey cut gives zones EnergyPlus "
                        "would find enclosed)")
                out = None
                break
            name = f"{zone.object_id}_Attic" if sl.attic else f"{zone.object_id}_S{k + 1}"
            wwr = zone.wwr if (not sl.attic or attic_mode == "conditioned") else 0.0
            out.append((replace(zone, object_id=name, wwr=wwr), zp, sl.attic))
        if out:
            return out, None
    return single, note


def planned_storeys(pieces: list[Piece], storey_height: float, part: PartStoreys | None = None) -> int:
    """Storeys (zones) the plan gives a zone of ``pieces`` (:func:`_storey_plan`), the attic included."""
    if not pieces:
        return 1
    _, _, _, n, _, above = _storey_plan(pieces, storey_height, part)
    return n + above


def _merged(zone: ZoneShell, written: list, pieces: list[Piece], storey_height: float, planned: int,
            part: PartStoreys | None) -> dg.Downgrade:
    """The ``storeys_merged`` downgrade of a zone cut into fewer storey zones than planned."""
    upper = upper_floor_area(pieces, storey_height, "conditioned", part)
    floors = sum(polygon_area3d(p.points) for _, zp, _ in written for p in zp
                 if p.kind == "floor" and p.boundary == "Surface")
    tallest = max(float(np.ptp(np.concatenate([p.points[:, 2] for p in zp]))) for _, zp, _ in written)
    return dg.storeys_merged(zone.object_id, planned, len(written), tallest - storey_height, floors - upper)


def _written_zones(blist, zones, zones_of, pieces, options, openings):
    """Per building: the zones to write ``[(ZoneShell, pieces, ZoneInfo, source zone index)]``, notes,
    stats and downgrades (zones kept whole where storey zoning was asked for,
    :func:`lod2energy.energy.downgrades.whole_zone`; storey cuts dropped,
    :func:`lod2energy.energy.downgrades.storeys_merged`). Each zone is cut into the storeys of
    its part in the building's one plan (:func:`lod2energy.thermal.storeys.storeys`)."""
    written_of, notes, bstats, downgrades = {}, {}, {}, {}
    for bi, b in enumerate(blist):
        use = recorded_use(b, options.use)
        st = storeys(b, use.type, options.lod)
        heated = is_conditioned(b)  # an unconditioned building: every zone without HVAC
        notes[bi] = []
        downgrades[bi] = []
        out = []
        for zi in zones_of[bi]:
            part = st.part(zones[zi].object_id)
            if part is None and len(zones_of[bi]) == 1 and st.parts:
                part = max(st.parts, key=lambda p: p.count)  # the building as one zone (merged parts)
            note = None
            if options.zoning == "storey":
                sz, note = storey_zones(zones[zi], zi, pieces[zi], st.storey_height, options.attic,
                                        openings.get(zi, ()), part)
                if note:
                    notes[bi].append(note)
            else:
                sz = [(zones[zi], pieces[zi], False)]
            upper = (upper_floor_area(pieces[zi], st.storey_height, options.attic, part)
                     if len(sz) == 1 else 0.0)
            if options.zoning == "storey":
                planned = planned_storeys(pieces[zi], st.storey_height, part)
                if len(sz) == 1 and planned > 1:
                    downgrades[bi].append(dg.whole_zone(zones[zi], st.storey_height, upper, note or (
                        f"zone {zones[zi].object_id}: kept as one zone (no storey cut clears its vertices)")))
                elif len(sz) < planned:
                    downgrades[bi].append(_merged(zones[zi], sz, pieces[zi], st.storey_height, planned, part))
            for k, (z, zp, attic) in enumerate(sz):
                info = ZoneInfo(b.id, (k + 1 if not attic else None) if len(sz) > 1 else None, attic,
                                (not attic or options.attic == "conditioned") and heated, use.type, upper)
                out.append((z, zp, info, zi))  # zi: the source zone (its real openings)
        written_of[bi] = out
        bstats[bi] = {"use": use.type, "use_source": use.source, "storeys": st.count,
                      "storeys_source": st.source, "storey_height_m": round(st.storey_height, 3),
                      "attic": st.attic, "conditioned": heated}
    return written_of, notes, bstats, downgrades
