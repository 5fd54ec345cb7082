"""BuildingParts before a writer: the STL's union of the input parts, the IDF's floorless parts."""
from __future__ import annotations

from lod2energy.energy.zones.storeys import FLOOR_NZ
from lod2energy.geometry.polygons import newell_normal, unit
from lod2energy.model import Building
from lod2energy.repair.parts import input_parts, merge_parts, touching_part, without_geometry


def united_input_parts(buildings, options=None, context=()) -> list[Building]:
    """The stage before the STL writer: each building with its input parts united
    (:func:`lod2energy.repair.parts.input_parts`, issue 19)."""
    return [input_parts(b) for b in buildings]


def floorless_parts(b: Building, lod: str | None = None) -> list[str]:
    """BuildingParts of ``b`` without a face EnergyPlus can take as a floor (n_z < ``FLOOR_NZ``).

    Typically a dormer or roof superstructure modelled as its own part, whose underside
    follows a roof steeper than 60 degrees.
    """
    out = []
    for o, _, g in b.envelope(lod):
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
