"""The energy model: the zones the IDF writer writes, prepared before it runs.

The last stage before the EnergyPlus writer, for the IDF only: the STL and CityJSON writers
keep the Building's own geometry. In the order of the work:

1. floorless parts (:func:`floorless_parts`: a dormer whose underside follows a roof steeper
   than 60 degrees) united with the part they sit on, or left out (:func:`merge_floorless_parts`);
2. one zone shell per Building/BuildingPart (:func:`lod2energy.exporters.zones.zone_shells`)
   in the writer's local frame, the real windows and doors split off (LoD3), the party walls
   found and each zone's written pieces cut (:mod:`lod2energy.exporters.energyplus.surfaces`);
3. a zone whose pieces EnergyPlus would call not fully enclosed replaced by the first simpler
   envelope that passes (:func:`enclosable`, :data:`lod2energy.exporters.energyplus.fallback.FALLBACKS`).

Which fallback passes depends on the frame (the local origin of the buildings *and* their
neighbours, floored to whole metres, :func:`~lod2energy.exporters.zones.local_origin`) and on
the party walls with the neighbours, so the stage takes the buildings and neighbours the
writer gets: the pipeline calls it in the pass that calls the writer (the neighbour pass in
building mode, the dataset pass in dataset mode). :func:`with_energy_model` records the
:class:`EnergyModel` and what was decided in each building's ``provenance["energy_model"]``;
the IDF writer writes that model as it is (:func:`model_of`).
"""
from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass, replace
from functools import partial
from collections.abc import Mapping
from typing import Iterable, Sequence

import numpy as np

from lod2energy.exporters.energyplus.enclosure import enclosure_defects
from lod2energy.exporters.energyplus.openings import Opening, split_openings
from lod2energy.exporters.energyplus.pieces import Piece
from lod2energy.exporters.energyplus.surfaces import find_party_faces, zone_pieces
from lod2energy.exporters.energyplus.zones import FLOOR_NZ
from lod2energy.geometry.polygons import newell_normal, unit
from lod2energy.validate.closed import check_closed_outward
from lod2energy.exporters.zones import COLLINEAR_TOL, local_origin, zone_shells, ZoneShell
from lod2energy.model import BUILDING_TYPES, Building, frozen_mapping
from lod2energy.repair.parts import merge_parts, touching_part, without_geometry
from .fallback import FALLBACKS

def floorless_parts(b: Building, lod: str | None = None) -> list[str]:
    """BuildingParts of ``b`` without a face EnergyPlus can take as a floor (n_z < ``FLOOR_NZ``).

    Typically a dormer or roof superstructure modelled as its own part, whose underside
    follows a roof steeper than 60 degrees.
    """
    out = []
    for o, _, g in b.energy_objects(lod):
        nz = [unit(newell_normal(b.vertices[list(s.rings[0])]))[2] for *_, s in g.iter_surfaces()]
        if o.type == "BuildingPart" and nz and not min(nz) < FLOOR_NZ:
            out.append(o.id)
    return out


def merge_floorless_parts(b: Building, lod: str | None = None) -> tuple[Building, list[str]]:
    """``b`` with no floorless part (:func:`floorless_parts`) left as a zone of its own.

    A dormer is no separately conditioned zone, and EnergyPlus cannot distribute solar gains
    in a zone without a floor. Its solid is united with the part it sits on when the union
    is a valid solid (the repair ladder's criterion); otherwise it is left out of the IDF
    (such parts are small: their underside follows a roof steeper than 60 degrees), and the
    roof under it is then written as an outdoor roof. A union keeps its host's floor, so one
    pass over the floorless parts suffices.

    Returns
    -------
    building : Building
        For the IDF only; the other exports keep the parts.
    warnings : list of str
    """
    lod = lod if lod is not None else b.default_lod()
    warnings: list[str] = []
    for pid in floorless_parts(b, lod):
        host = touching_part(b, pid, lod)
        merged = merge_parts(b, {pid, host}, lod=lod, into=host) if host else b
        if merged is not b:
            b = merged
            warnings.append(f"part {pid} has no surface EnergyPlus can take as a floor: united with {host} "
                            "into one zone")
        else:
            b = without_geometry(b, {pid}, lod)
            warnings.append(f"part {pid} has no surface EnergyPlus can take as a floor (none faces down more "
                            "than 30 degrees past vertical) and no valid union with the part it sits on: left "
                            "out of the IDF")
    return b, warnings


def _fallback_name(make) -> str:
    if isinstance(make, partial):
        args = ", ".join(f"{k}={v}" for k, v in make.keywords.items())
        return f"{make.func.__name__}({args})"
    return make.__name__


def enclosable(zone: ZoneShell, zi: int, pieces: list[Piece]) -> tuple[ZoneShell, list[Piece], str] | None:
    """A simpler envelope for a zone whose pieces EnergyPlus would call not fully enclosed.

    Returns None when the pieces pass (:func:`enclosure_defects`) or no fallback of
    :mod:`lod2energy.exporters.energyplus.fallback` (near misses cleared, sheets separated, 2.5D
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
        Shared faces (:func:`~lod2energy.exporters.energyplus.surfaces.find_party_faces`),
        none of a simpler envelope's.
    pieces : tuple of list of Piece
        Each zone's written pieces (empty for a neighbour's zones when the IDF has no shading).
    notes : mapping of int to tuple of str
        Building index -> what the stage changed (parts united or left out, unmatched openings).
    simpler : mapping of int to str
        Zone index -> the fallback that replaced its envelope.
    key : tuple
        The buildings' ids and the options the model was made for (:func:`model_of`).
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
    key: tuple

    def record(self, bi: int) -> dict:
        """What the stage did to building ``bi``, for its provenance (plain values)."""
        return {"frame_origin": tuple(float(x) for x in self.origin),
                "zones": tuple(self.zones[zi].object_id for zi in self.zones_of[bi]),
                "notes": tuple(self.notes[bi]),
                "simpler_zones": tuple({"zone": self.zones[zi].object_id, "envelope": self.simpler[zi]}
                                       for zi in self.zones_of[bi] if zi in self.simpler)}


def _energy_buildings(buildings: Iterable[Building], lod: str | None) -> list[Building]:
    return [b for b in buildings if b.type in BUILDING_TYPES and b.energy_objects(lod)]


def _key(own: Sequence[Building], context: Sequence[Building], options) -> tuple:
    return (tuple(b.id for b in own), tuple(b.id for b in context), options.lod, options.wwr,
            options.party_walls, options.party_split)


def _neighbours(own: Sequence[Building], context: Iterable[Building], lod: str | None) -> list[Building]:
    own_ids = {b.id for b in own}
    return [b for b in _energy_buildings(context, lod) if b.id not in own_ids]


#: Neighbours' zones a process keeps (least recently used dropped first): a building is the
#: neighbour of ~3.8 others in Den Haag, whose jobs often run in the same worker.
NEIGHBOUR_ZONES_KEPT = 64
_NEIGHBOUR_ZONES: "OrderedDict[bytes, tuple]" = OrderedDict()


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
    import hashlib
    import pickle
    k = hashlib.blake2b(pickle.dumps((b, lod, wwr), protocol=pickle.HIGHEST_PROTOCOL), digest_size=20).digest()
    hit = _NEIGHBOUR_ZONES.get(k)
    if hit is None:
        mb, notes = merge_floorless_parts(b, lod)
        o = local_origin([mb])
        hit = (mb, notes, (o, tuple(zone_shells(mb, o, lod, wwr=wwr, collinear_tol=COLLINEAR_TOL))))
        _NEIGHBOUR_ZONES[k] = hit
        while len(_NEIGHBOUR_ZONES) > NEIGHBOUR_ZONES_KEPT:
            _NEIGHBOUR_ZONES.popitem(last=False)
    else:
        _NEIGHBOUR_ZONES.move_to_end(k)
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
    made = range(len(zones) if shading else n_own_zones)
    pieces = [zone_pieces(z, zi, party, options.party_split) if zi in made else []
              for zi, z in enumerate(zones)]
    simpler: dict[int, str] = {}
    for zi in made:
        found = enclosable(zones[zi], zi, pieces[zi])
        if found is not None:
            zones[zi], pieces[zi], simpler[zi] = found
            party = {k: v for k, v in party.items() if k[0] != zi}
            openings[zi] = ()  # a fallback envelope: the WWR rule
    return EnergyModel(tuple(blist), len(own), origin, tuple(zones), zones_of, openings, party, tuple(pieces),
                       {bi: tuple(n) for bi, n in notes.items()}, simpler, key)


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
        if bi < model.n_own and b.type in BUILDING_TYPES and b.energy_objects(options.lod):
            b = b.with_provenance(energy_model=frozen_mapping({"model": model, **model.record(bi)}))
            bi += 1
        out.append(b)
    return out


def model_of(buildings: Iterable[Building], options, context: Iterable[Building] = ()) -> EnergyModel | None:
    """The energy model the writer writes: the one the stage recorded in the buildings'
    provenance when it was made for these buildings, neighbours and options, else made now
    (a direct call of the writer, without the pipeline) the same way."""
    own = _energy_buildings(buildings, options.lod)
    if not own:
        return None
    entries = [b.provenance.get("energy_model") for b in own]
    models = {id(e["model"]): e["model"] for e in entries if isinstance(e, Mapping) and "model" in e}
    if len(models) == 1 and all(isinstance(e, Mapping) for e in entries):
        model = next(iter(models.values()))
        if model.key == _key(own, _neighbours(own, context, options.lod), options):
            return model
    return prepare_energy_model(own, options, context)
