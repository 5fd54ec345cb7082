"""The ladder judges each result on the grid the building is written on: a repair that the
rounding spoils goes on up the ladder, and the final check agrees with its verdict."""
from __future__ import annotations

import numpy as np

from lod2energy.config import DEFAULT
from lod2energy.model import Building, CityObject, Geometry, Shell, Solid, Surface
from lod2energy.repair.accept import grid_rounding, output_grid, repair_verdict
from lod2energy.validate.closed import export_problem
from lod2energy.repair.convert import mesh_of_geometry
from lod2energy.repair.pipeline import repair_building, repair_info
from lod2energy.validate.checks import validate_building

#: A 10 x 8 m shed whose roof plane z = 6 + 0.013 x + 0.017 y is exact as computed, but whose
#: corners round (on a 0.1 m grid) to 6.0, 6.1, 6.3, 6.1: 5 cm out of any common plane.
CORNERS = [(0, 0), (10, 0), (10, 8), (0, 8)]
COARSE = {"scale": [0.1, 0.1, 0.1], "translate": [0.0, 0.0, 0.0]}
SEM = ({"type": "GroundSurface"}, {"type": "RoofSurface"}, {"type": "WallSurface"})


def shed(flip_wall: bool = True, transform=COARSE) -> Building:
    v = [(x, y, 0.0) for x, y in CORNERS] + [(x, y, 6 + 0.013 * x + 0.017 * y) for x, y in CORNERS]
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    if flip_wall:  # one wall inside out: the orientation stage is the first that repairs it
        faces[3] = faces[3][::-1]
    sem = [0, 1, 2, 2, 2, 2]
    g = Geometry("Solid", "2", (Solid((Shell(tuple(Surface.from_lists([f], s) for f, s in zip(faces, sem))),)),), SEM)
    b = Building("shed", "Building", np.asarray(v, dtype=float), (CityObject("shed", "Building", (g,)),))
    return b.with_provenance(file_transform=transform) if transform is not None else b


def geometry_log(b: Building) -> list[str]:
    (entry,) = repair_info(b)["geometries"]
    return entry["log"]


def test_the_shed_is_planar_as_computed_and_not_on_the_coarse_grid():
    b = shed(flip_wall=False)
    assert validate_building(b, DEFAULT) == []
    m = mesh_of_geometry(b.vertices, b.objects[0].geometries[0])
    assert repair_verdict(m, "2", DEFAULT) is None
    with output_grid(grid_rounding(b)):
        why = repair_verdict(m, "2", DEFAULT)
    assert why is not None and "output grid" in why and "203" in why


def test_without_the_grid_the_first_repair_is_kept():
    r = repair_building(shed(transform={"scale": [0.001] * 3, "translate": [0.0] * 3}), DEFAULT, timeout=20)
    assert repair_info(r)["stage"] == "orientation"


def test_a_repair_the_grid_spoils_goes_up_the_ladder_and_says_why():
    r = repair_building(shed(), DEFAULT, timeout=20)
    info = repair_info(r)
    log = geometry_log(r)
    # the orientation stage repaired it as computed; on the file's grid its roof is not planar
    assert any(line.startswith("orientation: rejected on the output grid") and "203" in line for line in log)
    assert info["stage"] not in ("valid", "cleanup", "orientation")
    if info["stage"] != "irreparable":
        # the later stage's result passes the final check on the same grid
        with output_grid(grid_rounding(r)):
            m = mesh_of_geometry(r.vertices, r.objects[0].geometries[0])
            assert repair_verdict(m, "2", DEFAULT) is None
        bad = export_problem(r.with_provenance(thermal={}), "2", DEFAULT)
        assert bad is None or "invalid geometry" not in bad
    else:
        assert any("rejected on the output grid" in line for line in log)


def test_the_pipeline_calls_the_later_result_compliant_and_the_final_check_agrees():
    from lod2energy.options import PrepareOptions
    from lod2energy.prepare import final_check, prepare_building
    out, rec = prepare_building(shed(), PrepareOptions())
    assert rec.repair.stage not in ("orientation", "irreparable")
    assert rec.energy.compliant and rec.energy.geometry_ready, rec.energy.reasons
    assert final_check(out, validate_building(out, DEFAULT), "2", DEFAULT) is None
