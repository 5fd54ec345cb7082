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
from lod2energy.geometry.polygons import newell_normal, unit
from lod2energy.validate.closed import check_closed_outward
from lod2energy.thermal.storeys import ATTIC_MIN_HEIGHT, MIN_STOREY_HEIGHT, storeys, storeys_above_eave
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


def _storey_plan(pieces: list[Piece], storey_height: float) -> tuple[float, float, float, int, bool, int]:
    """``(ground, eave, ridge, storeys below the eave, attic, storeys above the eave)`` of a
    zone's pieces (m): the storeys :func:`storey_zones` cuts it into and the ones
    :func:`upper_floor_area` counts. Counted from the zone's own levels and the building's
    storey height, so that a BuildingPart taller than the building's eave gets its storeys."""
    ground, eave, ridge, pitched = zoning.zone_levels([(p.points, p.kind) for p in pieces])
    n = max(1, int(round((eave - ground) / storey_height))) if storey_height > 0 else 1
    n = max(1, min(n, int((eave - ground) / MIN_STOREY_HEIGHT)))
    attic = pitched and ridge - eave >= ATTIC_MIN_HEIGHT
    return ground, eave, ridge, n, attic, storeys_above_eave(ridge - eave, storey_height, attic)


def _levels(ground: float, eave: float, ridge: float, n: int, attic: bool, above: int) -> list[float]:
    """Floor levels (m) of the storeys above the lowest, as :func:`zoning.storey_cuts` aims at them;
    the attic floor last when ``attic``."""
    levels = [ground + k * (eave - ground) / n for k in range(1, n)]
    return levels + [eave + k * (ridge - eave) / above for k in range(above)]


def upper_floor_area(pieces: list[Piece], storey_height: float, attic_mode: str) -> float:
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

    Returns
    -------
    float, m2
        0 for a one-storey zone without a conditioned attic.
    """
    if not pieces:
        return 0.0
    ground, eave, ridge, n, attic, above = _storey_plan(pieces, storey_height)
    levels = _levels(ground, eave, ridge, n, attic, above)
    if attic and attic_mode != "conditioned":
        levels = levels[:-1]
    polys = [p.points for p in pieces]
    return float(sum(zoning.section_area(polys, z) for z in levels))


def storey_zones(zone: ZoneShell, zi: int, pieces: list[Piece], storey_height: float,
                 attic_mode: str, openings: Sequence[Opening] = ()) -> tuple[list[tuple[ZoneShell, list[Piece], bool]], str | None]:
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

    Returns
    -------
    zones : list of (ZoneShell, pieces, attic)
        The storey zones, lowest first; ``[(zone, pieces, False)]`` when it stays one zone.
    note : str or None
        Why it stayed one zone (a cut that would not close, a storey EnergyPlus would find not
        enclosed), when it did.
    """
    single = [(zone, pieces, False)]
    if not pieces:
        return single, None
    ground, eave, ridge, n, attic, above = _storey_plan(pieces, storey_height)
    allz = np.concatenate([p.points[:, 2] for p in pieces])
    horiz = [float(p.points[0, 2]) for p in pieces if np.ptp(p.points[:, 2]) <= 1e-6]
    spans = [(float(o.points[:, 2].min()), float(o.points[:, 2].max())) for o in openings]
    cuts, attic = zoning.storey_cuts(allz, ground, eave, ridge, n, attic, horiz, spans, above)
    if not cuts:
        return single, None
    note = None
    for cs, with_attic in zoning.cut_variants(cuts, attic, allz, horiz):
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


def _written_zones(blist, zones, zones_of, pieces, options, openings):
    """Per building: the zones to write ``[(ZoneShell, pieces, ZoneInfo, source zone index)]``, notes,
    stats and downgrades (zones kept whole where storey zoning was asked for,
    :func:`lod2energy.energy.downgrades.whole_zone`)."""
    written_of, notes, bstats, downgrades = {}, {}, {}, {}
    for bi, b in enumerate(blist):
        use = recorded_use(b, options.use)
        st = storeys(b, use.type, options.lod)
        heated = is_conditioned(b)  # an unconditioned building: every zone without HVAC
        notes[bi] = []
        downgrades[bi] = []
        out = []
        for zi in zones_of[bi]:
            if options.zoning == "storey":
                sz, note = storey_zones(zones[zi], zi, pieces[zi], st.storey_height, options.attic,
                                        openings.get(zi, ()))
                if note:
                    notes[bi].append(note)
            else:
                sz = [(zones[zi], pieces[zi], False)]
            upper = (upper_floor_area(pieces[zi], st.storey_height, options.attic)
                     if len(sz) == 1 else 0.0)
            if options.zoning == "storey" and note:
                downgrades[bi].append(dg.whole_zone(zones[zi], st.storey_height, upper, note))
            for k, (z, zp, attic) in enumerate(sz):
                info = ZoneInfo(b.id, (k + 1 if not attic else None) if len(sz) > 1 else None, attic,
                                (not attic or options.attic == "conditioned") and heated, use.type, upper)
                out.append((z, zp, info, zi))  # zi: the source zone (its real openings)
        written_of[bi] = out
        bstats[bi] = {"use": use.type, "use_source": use.source, "storeys": st.count,
                      "storeys_source": st.source, "storey_height_m": round(st.storey_height, 3),
                      "attic": st.attic, "conditioned": heated}
    return written_of, notes, bstats, downgrades
