"""The energy model: the zones the IDF writer writes, prepared before it runs.

The last stage before the EnergyPlus writer, for the IDF only: the STL and CityJSON writers
keep the Building's own geometry. In the order of the work:

1. floorless parts (:func:`~lod2energy.energy.parts.floorless_parts`: a dormer whose underside follows a roof steeper
   than 60 degrees) united with the part they sit on, or left out (:func:`~lod2energy.energy.parts.merge_floorless_parts`);
2. one zone shell per Building/BuildingPart (:func:`lod2energy.energy.zones.shells.zone_shells`)
   in the writer's local frame, the real windows and doors split off (LoD3), the party walls
   found and each zone's written pieces cut (:mod:`lod2energy.energy.surfaces`);
3. a zone whose pieces EnergyPlus would call not fully enclosed replaced by the first simpler
   envelope that passes (:func:`enclosable`, :data:`lod2energy.energy.fallback.FALLBACKS`).

Which fallback passes depends on the frame (the local origin of the buildings *and* their
neighbours, floored to whole metres, :func:`~lod2energy.energy.zones.shells.local_origin`) and on
the party walls with the neighbours, so the stage takes the buildings and neighbours the
writer gets: the pipeline calls it in the pass that calls the writer (the neighbour pass in
building mode, the dataset pass in dataset mode). :func:`with_energy_model` records the
:class:`EnergyModel` and what was decided in each building's ``provenance["energy_model"]``;
the IDF writer writes that model as it is (:func:`model_of`).
"""
from __future__ import annotations

import hashlib
import pickle
from collections.abc import Mapping
from dataclasses import dataclass, replace
from functools import partial
from typing import Iterable, Sequence

import numpy as np

from lod2energy import cache

from lod2energy.energy import downgrades as dg
from lod2energy.energy.enclosure import enclosure_defects
from lod2energy.energy.openings import Opening, split_openings
from lod2energy.energy.pieces import Piece
from lod2energy.energy.surfaces import find_party_faces, zone_pieces
from lod2energy.energy.parts import merge_floorless_parts
from lod2energy.validate.closed import check_closed_outward
from lod2energy.energy.zones.shells import COLLINEAR_TOL, local_origin, zone_shells, ZoneShell
from lod2energy.model import BUILDING_TYPES, Building, frozen_mapping
from lod2energy.thermal.facts import is_conditioned
from lod2energy.energy.fallback import FALLBACKS

def _fallback_name(make) -> str:
    if isinstance(make, partial):
        args = ", ".join(f"{k}={v}" for k, v in make.keywords.items())
        return f"{make.func.__name__}({args})"
    return make.__name__


def enclosable(zone: ZoneShell, zi: int, pieces: list[Piece]) -> tuple[ZoneShell, list[Piece], str] | None:
    """A simpler envelope for a zone whose pieces EnergyPlus would call not fully enclosed.

    Returns None when the pieces pass (:func:`enclosure_defects`) or no fallback of
    :mod:`lod2energy.energy.fallback` (near misses cleared, sheets separated, 2.5D
    model, then LoD1 block) passes either; else the first fallback zone that does, with its
    pieces (party walls not split) and the fallback's name.
    """
    if not pieces or not enclosure_defects([p.points for p in pieces]):
        return None
    for make in FALLBACKS:
        nz = make(zone)
        if nz is None:
            continue
        np_ = zone_pieces(nz, zi, {}, False)
        pts = [p.points for p in np_]
        if np_ and not check_closed_outward(pts) and not enclosure_defects(pts):
            return nz, np_, _fallback_name(make)
    return None


@dataclass(frozen=True, eq=False)
class EnergyModel:
    """What the IDF writer writes: zones and their pieces in one local frame.

    Attributes
    ----------
    buildings : tuple of Building
        The writer's buildings (``n_own`` first), then their neighbours, floorless parts merged
        (for the IDF only).
    n_own : int
    origin : (3,) float, m
        The local frame: subtract from map coordinates.
    zones : tuple of ZoneShell
        Every zone of ``buildings`` in that frame, a simpler envelope where the written one
        would fail EnergyPlus's enclosure test.
    zones_of : mapping of int to tuple of int
        Building index -> its zones' indices.
    openings : mapping of int to tuple of Opening
        Zone index -> its real windows and doors (LoD3 input; none on a simpler envelope).
    party : mapping
        Shared faces (:func:`~lod2energy.energy.surfaces.find_party_faces`),
        none of a simpler envelope's.
    pieces : tuple of list of Piece
        Each zone's written pieces (empty for a neighbour's zones when the IDF has no shading).
    notes : mapping of int to tuple of str
        Building index -> what the stage changed (parts united or left out, unmatched openings).
    simpler : mapping of int to str
        Zone index -> the fallback that replaced its envelope.
    downgrades : mapping of int to tuple of Downgrade
        Building index -> the simpler envelopes of its zones and the party walls they dropped,
        with what they cost (:mod:`lod2energy.energy.downgrades`).
    key : tuple
        The buildings' ids and the options the model was made for (:func:`model_of`).
    unglazed : frozenset of (int, int)
        ``(zone index, face index)`` of the walls a conditioned zone shares with an
        unconditioned building's zone (or the other way round): not adiabatic, written as
        outdoor walls without windows (:func:`unglaze`).
    """

    buildings: tuple[Building, ...]
    n_own: int
    origin: np.ndarray
    zones: tuple[ZoneShell, ...]
    zones_of: Mapping[int, tuple[int, ...]]
    openings: Mapping[int, tuple[Opening, ...]]
    party: Mapping
    pieces: tuple[list[Piece], ...]
    notes: Mapping[int, tuple[str, ...]]
    simpler: Mapping[int, str]
    downgrades: Mapping[int, tuple[dg.Downgrade, ...]]
    key: tuple
    unglazed: frozenset = frozenset()

    def record(self, bi: int) -> dict:
        """What the stage did to building ``bi``, for its provenance (plain values)."""
        return {"frame_origin": tuple(float(x) for x in self.origin),
                "zones": tuple(self.zones[zi].object_id for zi in self.zones_of[bi]),
                "notes": tuple(self.notes[bi]),
                "simpler_zones": tuple({"zone": self.zones[zi].object_id, "envelope": self.simpler[zi]}
                                       for zi in self.zones_of[bi] if zi in self.simpler),
                "downgrades": tuple(d.to_json() for d in self.downgrades.get(bi, ()))}


def _energy_buildings(buildings: Iterable[Building], lod: str | None) -> list[Building]:
    return [b for b in buildings if b.type in BUILDING_TYPES and b.envelope(lod)]


def _key(own: Sequence[Building], context: Sequence[Building], options) -> tuple:
    return (tuple(b.id for b in own), tuple(b.id for b in context), options.lod, options.wwr,
            options.party_walls, options.party_split)


def _neighbours(own: Sequence[Building], context: Iterable[Building], lod: str | None) -> list[Building]:
    own_ids = {b.id for b in own}
    return [b for b in _energy_buildings(context, lod) if b.id not in own_ids]


#: Neighbours' zones a process keeps (:mod:`lod2energy.cache` table :data:`NEIGHBOUR_ZONES`): a
#: building is the neighbour of ~3.8 others in Den Haag, whose jobs often run in the same worker.
NEIGHBOUR_ZONES = "energy.neighbour_zones"
NEIGHBOUR_ZONES_KEPT = 64


def _neighbour_zones(b: Building, lod: str | None, wwr) -> tuple[Building, list[str], tuple]:
    """A neighbour's floorless parts merged and its zone shells in its own frame:
    ``(merged building, notes, (own origin, zone shells))``.

    Without shading a neighbour's zones only find the party faces of the written building's
    (``find_party_faces(first=)``), so they are made in the neighbour's own frame
    (:func:`local_origin` of it alone) and moved into the job's by a whole-metre offset: they do
    not depend on which job needs them, and a process remembers them by the building's whole
    content (a digest of its pickle), so the ~3.8 jobs that neighbour a building make them once
    per worker, not once each. Moved, a vertex differs from one made in the job's frame by
    ~1e-14 m, far below the party faces' 5 cm plane tolerance and the 1 mm weld.
    """
    def make():
        mb, notes = merge_floorless_parts(b, lod)
        o = local_origin([mb])
        return mb, notes, (o, tuple(zone_shells(mb, o, lod, wwr=wwr, collinear_tol=COLLINEAR_TOL)))

    k = hashlib.blake2b(pickle.dumps((b, lod, wwr), protocol=pickle.HIGHEST_PROTOCOL), digest_size=20).digest()
    hit = cache.remember(NEIGHBOUR_ZONES, k, make, NEIGHBOUR_ZONES_KEPT)
    return hit[0], list(hit[1]), hit[2]


def prepare_energy_model(buildings: Iterable[Building], options, context: Iterable[Building] = ()
                         ) -> EnergyModel | None:
    """The energy model of ``buildings`` with their neighbours ``context``, or None when none
    of them is an energy-ready building.

    Parameters
    ----------
    buildings : iterable of Building
        The buildings the IDF writer writes.
    options : exporters.energyplus.options.IdfOptions
        ``lod``, ``wwr``, ``party_walls`` and ``party_split`` are used.
    context : iterable of Building
        Neighbours: they make party walls and the frame, as they do in the writer.
    """
    own = _energy_buildings(buildings, options.lod)
    if not own:
        return None
    others = _neighbours(own, context, options.lod)
    key = _key(own, others, options)
    shading = bool(getattr(options, "shading", False))
    blist, notes, kept = [], {}, {}
    for bi, b in enumerate(own + others):
        if bi >= len(own) and not shading:  # only its party faces count: remembered per process
            mb, notes[bi], kept[bi] = _neighbour_zones(b, options.lod, options.wwr)
        else:
            mb, notes[bi] = merge_floorless_parts(b, options.lod)
        blist.append(mb)
    origin = local_origin(blist)
    zones: list[ZoneShell] = []
    zones_of: dict[int, tuple[int, ...]] = {}
    for bi, b in enumerate(blist):
        if bi in kept:
            own_origin, shells = kept[bi]
            zs = [replace(z, vertices=z.vertices + (own_origin - origin)) for z in shells]
        else:
            zs = zone_shells(b, origin, options.lod, wwr=options.wwr, collinear_tol=COLLINEAR_TOL)
        zones_of[bi] = tuple(range(len(zones), len(zones) + len(zs)))
        zones.extend(zs)
    openings: dict[int, tuple[Opening, ...]] = {}
    for zi in range(len(zones)):
        zones[zi], openings[zi], unmatched = split_openings(zones[zi])
        if unmatched:
            notes[next(bi for bi, zl in zones_of.items() if zi in zl)].append(
                f"zone {zones[zi].object_id}: {unmatched} window/door face(s) fill no wall hole; written as wall")
    # a neighbour's pieces (and its simpler envelope) only show in the IDF as its shading
    # surfaces; without shading they are not made (each would be made again for every
    # building it neighbours: the bulk of the cost on terraced blocks), and neither are the
    # party faces between two neighbours
    n_own_zones = sum(len(zones_of[bi]) for bi in range(len(own)))
    party = find_party_faces(zones, first=None if shading else n_own_zones) if options.party_walls else {}
    building_of = {zi: bi for bi, zl in zones_of.items() for zi in zl}
    party, unglazed, shared = heat_party(party, [is_conditioned(b) for b in blist], building_of, zones)
    for bi, text in shared.items():
        notes[bi].append(text)
    made = range(len(zones) if shading else n_own_zones)
    pieces = [unglaze(zone_pieces(z, zi, party, options.party_split), zi, unglazed) if zi in made else []
              for zi, z in enumerate(zones)]
    simpler: dict[int, str] = {}
    downgrades: dict[int, list[dg.Downgrade]] = {}
    for zi in made:
        found = enclosable(zones[zi], zi, pieces[zi])
        if found is not None:
            why = "the repaired shell fails EnergyPlus's enclosure test"
            down = downgrades.setdefault(building_of[zi], [])
            down.append(dg.replaced(dg.fallback_kind(found[2]), zones[zi], found[0], f"{found[2]}: {why}"))
            walls = dg.party_area(party, zi, zones[zi])
            if walls > 0:
                down.append(dg.party_walls_dropped(zones[zi].object_id, walls, f"a simpler envelope ({found[2]})"))
            zones[zi], pieces[zi], simpler[zi] = found
            party = {k: v for k, v in party.items() if k[0] != zi}
            openings[zi] = ()  # a fallback envelope: the WWR rule
    return EnergyModel(tuple(blist), len(own), origin, tuple(zones), zones_of, openings, party, tuple(pieces),
                       {bi: tuple(n) for bi, n in notes.items()}, simpler,
                       {bi: tuple(d) for bi, d in downgrades.items()}, key, unglazed)


def heat_party(party: Mapping, conditioned: Sequence[bool], building_of: Mapping[int, int],
               zones: Sequence[ZoneShell]) -> tuple[dict, frozenset, dict[int, str]]:
    """Party faces without those between a conditioned and an unconditioned building.

    Such a wall is not adiabatic: heat flows through it to the unheated neighbour, so it is
    written as an outdoor wall without windows.

    Parameters
    ----------
    party : mapping
        :func:`~lod2energy.energy.surfaces.find_party_faces`.
    conditioned : sequence of bool
        Per building index.
    building_of : mapping of int to int
        Zone index -> building index.

    Returns
    -------
    party : dict
        The faces kept adiabatic.
    unglazed : frozenset of (int, int)
        ``(zone, face)`` that lost a shared part.
    notes : dict of int to str
        Building index -> what was done, with the area (m2).
    """
    kept, unglazed, area = {}, set(), {}
    for (zi, fi), entries in party.items():
        mine = conditioned[building_of[zi]]
        same = [(o, poly) for o, poly in entries if conditioned[building_of[o]] == mine]
        if len(same) < len(entries):
            unglazed.add((zi, fi))
            bi = building_of[zi]
            area[bi] = area.get(bi, 0.0) + sum(float(getattr(poly, "area", 0.0)) for o, poly in entries
                                               if conditioned[building_of[o]] != mine)
        if same:
            kept[(zi, fi)] = same
    notes = {bi: (f"{a:.1f} m2 of party wall shared with "
                  f"{'an unconditioned' if conditioned[bi] else 'a conditioned'} building: "
                  "written as outdoor wall without windows, not adiabatic") for bi, a in area.items()}
    return kept, frozenset(unglazed), notes


def unglaze(pieces: list[Piece], zi: int, unglazed: frozenset) -> list[Piece]:
    """``pieces`` of zone ``zi`` with the outdoor wall pieces of the faces ``unglazed`` marked
    to get no windows."""
    if not unglazed:
        return pieces
    return [replace(p, glazed=False) if (zi, p.face_index) in unglazed and p.kind == "wall" else p
            for p in pieces]


def with_energy_model(buildings: Iterable[Building], options, context: Iterable[Building] = ()) -> list[Building]:
    """The stage: ``buildings`` with ``provenance["energy_model"]`` (their geometry unchanged).

    The entry holds the :class:`EnergyModel` (``"model"``, shared by the buildings of one
    call) and what it did to the building (:meth:`EnergyModel.record`). Buildings that are
    not energy-ready come back as they are.
    """
    buildings = list(buildings)
    model = prepare_energy_model(buildings, options, context)
    if model is None:
        return buildings
    out, bi = [], 0
    for b in buildings:
        if bi < model.n_own and b.type in BUILDING_TYPES and b.envelope(options.lod):
            b = b.with_provenance(energy_model=frozen_mapping({"model": model, **model.record(bi)}))
            bi += 1
        out.append(b)
    return out


def model_of(buildings: Iterable[Building], options, context: Iterable[Building] = ()) -> EnergyModel | None:
    """The energy model the writer writes: the one the stage recorded in the buildings'
    provenance, or, when they carry none (the writer called without the pipeline), the
    stage's model made now.

    Raises
    ------
    ValueError
        The buildings carry a model made for other buildings, neighbours or options: the
        writer writes the model it is given, never one of its own.
    """
    own = _energy_buildings(buildings, options.lod)
    if not own:
        return None
    entries = [b.provenance.get("energy_model") for b in own]
    if all(e is None for e in entries):
        return prepare_energy_model(own, options, context)
    models = {id(e["model"]): e["model"] for e in entries if isinstance(e, Mapping) and "model" in e}
    if len(models) != 1 or not all(isinstance(e, Mapping) for e in entries):
        raise ValueError("the buildings carry no one energy model: run with_energy_model on them together")
    model = next(iter(models.values()))
    if model.key != _key(own, _neighbours(own, context, options.lod), options):
        raise ValueError("the buildings' energy model was made for other buildings, neighbours or options: "
                         "run with_energy_model again")
    return model
