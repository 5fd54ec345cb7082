"""No stage and no writer changes its input: every repair stage, the label and U-value stages,
the energy model stage and the three writers leave the input Building (vertices, rings,
attributes, provenance) and the input PolyMesh as they were."""
from __future__ import annotations

from types import MappingProxyType

import numpy as np
import pytest

from export_helpers import energy_ready, write_idf
from factories import box, flipped_wall, gabled_house, inward_box, open_box
from lod2energy.config import DEFAULT
from lod2energy.model import Building, CityModel, frozen_mapping
from lod2energy.polymesh import PolyMesh
from lod2energy.repair.alphashape import alpha_repair
from lod2energy.repair.cleanup import cleanup
from lod2energy.repair.convert import mesh_of_geometry
from lod2energy.repair.footprint import convex_hull, extrude_footprint
from lod2energy.repair.holefill import fill_holes
from lod2energy.repair.orientation import orient
from lod2energy.repair.pipeline import STAGES, repair_building
from lod2energy.repair.refill import refill
from lod2energy.repair.roofs import roof_model
from lod2energy.repair.unpinch import unpinch
from lod2energy.semantics import label_building
from lod2energy.thermal import assign_u_values

BUILDINGS = {"box": box, "gabled_house": gabled_house, "open_box": open_box, "flipped_wall": flipped_wall,
             "inward_box": inward_box}

#: every stage of the ladder that changes geometry, as PolyMesh -> PolyMesh | None
MESH_STAGES = {
    "cleanup": lambda m: cleanup(m, DEFAULT),
    "orientation": orient,
    "holefill": lambda m: fill_holes(m, DEFAULT),
    "refill": lambda m: refill(m, DEFAULT),
    "unpinch": lambda m: unpinch(m, DEFAULT),
    "roofs": lambda m: roof_model(m, "2", DEFAULT),
    "alphashape": lambda m: alpha_repair(m, DEFAULT, alphas=(4.0,)),
    "footprint": extrude_footprint,
    "hull": convex_hull,
}


def _plain(x):
    """A comparable, deep copy of mappings, sequences and arrays."""
    if isinstance(x, (dict, MappingProxyType)):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.ndarray):
        return ("array", x.dtype.str, x.shape, x.tobytes())
    return x


def snapshot(b: Building):
    """Everything of a building a stage must not change."""
    objects = [(o.id, o.type, _plain(o.attributes), o.parents, o.children,
                [(g.type, g.lod, [s.to_lists() for _, _, _, s in g.iter_surfaces()], _plain(g.semantic_surfaces))
                 for g in o.geometries])
               for o in b.objects]
    return b.id, b.type, b.vertices.tobytes(), objects, _plain(b.provenance)


def mesh_snapshot(m: PolyMesh):
    return m.vertices.tobytes(), m.vertices.shape, [(f.rings, f.source, f.semantic) for f in m.faces]


def test_every_geometry_stage_is_listed():
    assert set(STAGES) - {"valid", "irreparable"} <= set(MESH_STAGES)


@pytest.mark.parametrize("name", sorted(BUILDINGS))
@pytest.mark.parametrize("stage", sorted(MESH_STAGES))
def test_repair_stage_keeps_its_input(stage, name):
    b = BUILDINGS[name]()
    m = mesh_of_geometry(b.vertices, b.root.geometries[0])
    m.vertices.setflags(write=True)  # a stage writing into it would otherwise raise, not be seen
    before = mesh_snapshot(m)
    MESH_STAGES[stage](m)
    assert mesh_snapshot(m) == before


@pytest.mark.parametrize("name", sorted(BUILDINGS))
@pytest.mark.parametrize("stage", ["repair", "labels", "u_values"])
def test_building_stage_keeps_its_input(stage, name):
    b = BUILDINGS[name]()
    if stage == "u_values":
        b = label_building(b)
    before = snapshot(b)
    out = {"repair": lambda x: repair_building(x, DEFAULT, timeout=10.0),
           "labels": label_building, "u_values": assign_u_values}[stage](b)
    assert snapshot(b) == before
    assert out is not None


@pytest.mark.parametrize("name", ["box", "gabled_house"])
@pytest.mark.parametrize("writer", ["idf", "stl", "cityjson"])
def test_writer_keeps_its_input(writer, name, tmp_path):
    from lod2energy.exporters import energyplus
    from lod2energy.exporters.cityjson import writer as cityjson
    from lod2energy.exporters.stl import writer as stl

    b = energy_ready(BUILDINGS[name]())
    before = snapshot(b)
    if writer == "idf":
        res = write_idf([b], tmp_path)
    elif writer == "stl":
        res = stl.write([b], tmp_path)
    else:
        model = CityModel(version="2.0", metadata=frozen_mapping({"referenceSystem": "urn:ogc:def:crs:EPSG::7415"}))
        res = cityjson.write(str(tmp_path / "out.city.json"), model, [b])
    assert res
    assert snapshot(b) == before


@pytest.mark.parametrize("name", ["box", "gabled_house", "dormer_house"])
def test_energy_model_stage_keeps_its_input(name):
    # the stage before the IDF writer: a dormer without a floor is united for the IDF only
    from export_helpers import parts_with_semantics, steep_house_with_dormer
    from lod2energy.exporters.energyplus.options import IdfOptions
    from lod2energy.energy.model import with_energy_model

    if name == "dormer_house":
        house, ht, dormer, dt = steep_house_with_dormer()
        b = energy_ready(parts_with_semantics([(house, ht), (dormer, dt)]))
    else:
        b = energy_ready(BUILDINGS[name]())
    before = snapshot(b)
    [out] = with_energy_model([b], IdfOptions())
    assert snapshot(b) == before
    assert "energy_model" in out.provenance and snapshot(out)[:4] == before[:4]  # geometry as it was
