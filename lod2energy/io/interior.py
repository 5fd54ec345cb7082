"""Interior LoD3/LoD4 detail that is not envelope: left out of a building's envelope, counted.

Any reader's building can carry, besides its envelope, detail inside it: surfaces typed
``InteriorWallSurface`` / ``CeilingSurface`` / ``FloorSurface`` in the geometry of the Building
or a BuildingPart, and child objects such as rooms, furniture, storeys, units, constructive
elements. Those faces would make the envelope non-manifold (an interior wall hangs from the
outer walls) and are not part of the energy balance's boundary. :func:`without_interior`
drops them from the envelope geometries of the Building and its BuildingParts (child objects
are never envelope: ``Building.envelope_objects``) and records what it left out in
``provenance["interior_left_out"]`` (kind -> polygons or objects; the CityGML reader fills
the same record for what it does not read).
"""
from __future__ import annotations

from dataclasses import replace
from collections.abc import Mapping

from lod2energy.model import BUILDING_TYPES, Building, Shell, Solid, frozen_mapping

#: Semantic surface types inside a building.
INTERIOR_SURFACE_TYPES = ("InteriorWallSurface", "CeilingSurface", "FloorSurface")
#: Child CityObject types that are interior detail (counted, never envelope).
INTERIOR_OBJECT_TYPES = ("BuildingRoom", "BuildingFurniture", "BuildingStorey", "BuildingUnit",
                         "BuildingConstructiveElement", "Room", "IntBuildingInstallation")


def without_interior(b: Building) -> Building:
    """``b`` without interior surfaces in its envelope geometries; ``b`` itself if it has none.

    Returns
    -------
    Building
        New building; ``provenance["interior_left_out"]`` counts the interior polygons left
        out (per semantic type) and the interior child objects (per type), added to the
        reader's count.
    """
    if b.type not in BUILDING_TYPES:
        return b
    counts: dict[str, int] = dict(b.provenance.get("interior_left_out", {}) or {})
    out = b
    for o in b.envelope_objects:
        for gi, g in enumerate(o.geometries):
            if not g.is_polygonal or not g.semantic_surfaces:
                continue
            inside = {k for k, e in enumerate(g.semantic_surfaces)
                      if isinstance(e, Mapping) and e.get("type") in INTERIOR_SURFACE_TYPES}
            if not inside:
                continue
            solids = []
            for so in g.solids:
                shells = []
                for sh in so.shells:
                    keep = []
                    for s in sh.surfaces:
                        if s.semantic in inside:
                            t = g.semantic_surfaces[s.semantic]["type"]
                            counts[t] = counts.get(t, 0) + 1
                        else:
                            keep.append(s)
                    shells.append(Shell(tuple(keep)))
                solids.append(Solid(tuple(shells)))
            out = out.replace_geometry(o.id, gi, replace(g, solids=tuple(solids)))
    for o in b.objects:
        if o.type in INTERIOR_OBJECT_TYPES:
            counts[o.type] = counts.get(o.type, 0) + 1
    if counts == dict(b.provenance.get("interior_left_out", {}) or {}):
        return out
    return out.with_provenance(interior_left_out=frozen_mapping(dict(sorted(counts.items()))))
