"""One verdict (issue 38 items 1 and 10): the repair's input codes are the validator's, a valid
input is kept as it is, and an input without volume is refused, never wrapped."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import shared_path
from factories import box, box_polygons, building_from_polygons, flipped_wall, inward_box, open_box

from lod2energy.config import DEFAULT
from lod2energy.io import read
from lod2energy.model import Building
from lod2energy.repair.convert import mesh_of_geometry
from lod2energy.repair.pipeline import GLOBAL, repair_building
from lod2energy.repair.verdict import input_codes
from lod2energy.validate.checks import validate_building, validate_geometry
from lod2energy.validate.closed import shell_defects


def _v3(codes) -> list[int]:
    return sorted(c for c in codes if c < 1000)


def _validate_codes(b: Building, coid: str, gi: int) -> list[int]:
    g = next(o for o in b.objects if o.id == coid).geometries[gi]
    return sorted({d.code for d in validate_geometry(b.vertices, coid, gi, g, DEFAULT)})


def step_roof_house(eps: float = 0.0002, dz: float = 0.002) -> Building:
    """A valid L-shaped house (10 x 10 m) of two sloped roofs meeting at y = 5 m, whose inner
    corner B sits ``eps`` (m) south of that line and ``dz`` (m) above the roof plane: the south
    roof's points A, B, C are nearly collinear and B is a reflex corner in plan but a convex one
    in the roof's own (tilted) plane. Ear clipping in that plane cuts the needle ear A-B-C, whose
    side A-C runs north of B through the wall below B (a crossing of that triangulation only);
    val3dity's triangulation (and the project's validator) keeps the reflex corner: valid."""
    def z(x, y):
        return 6 + 0.3 * y if y <= 5 else 7.5 - 0.3 * (y - 5)

    def p(x, y):
        return np.array([x, y, z(x, y)])

    def g(x, y):
        return np.array([x, y, 0.0])

    a, b, c = p(10, 5), np.array([5, 5 - eps, 7.5 + dz]), p(2.6, 5)
    q0, q1, q5, d, n0 = p(0, 0), p(10, 0), p(0, 5), p(5, 10), p(0, 10)
    faces = [
        [q0, q1, a, b, c, q5],                       # south roof
        [q5, c, b, d, n0],                           # north roof
        [g(0, 0), g(0, 10), g(5, 10), g(5, 5 - eps), g(10, 5), g(10, 0)],  # ground
        [g(0, 0), g(10, 0), q1, q0],
        [g(10, 0), g(10, 5), a, q1],
        [g(10, 5), g(5, 5 - eps), b, a],
        [g(5, 5 - eps), g(5, 10), d, b],             # the wall below B
        [g(5, 10), g(0, 10), n0, d],
        [g(0, 10), g(0, 0), q0, q5, n0],
    ]
    return building_from_polygons([[np.array(f)] for f in faces], "Solid", id="step_roof")


def duplicated_point_box() -> Building:
    """A box whose roof repeats a point 0.4 mm from its neighbour (102), not on the wall below."""
    polys = box_polygons()
    r = polys[1][0]
    polys[1] = [np.array([r[0], r[1], r[1] + [0, 0.0004, 0], r[2], r[3]])]
    return building_from_polygons(polys, "Solid", id="dup_point")


NAMED = {"box": box, "open_box": open_box, "flipped_wall": flipped_wall, "inward_box": inward_box,
         "step_roof": step_roof_house, "dup_point": duplicated_point_box}


@pytest.mark.parametrize("name", sorted(NAMED))
def test_repair_input_codes_are_the_validators(name):
    b = NAMED[name]()
    for coid, gi, codes in input_codes(b, DEFAULT):
        assert _v3(codes) == _validate_codes(b, coid, gi)
    rb = repair_building(b, DEFAULT)
    for e in (rb.provenance.get("repair") or {}).get("geometries", ()):
        assert _v3(e["defects_before"]) == _validate_codes(b, e["object"], e["geometry"])


def test_valid_input_kept_though_the_ladders_own_crossing_test_disagrees():
    """The cause of two verdicts: the input check ran the ladder's own crossing test (ear
    clipping in the face's plane) and reported its finding as val3dity's 306, so a valid
    building went up the ladder. The validator's verdict is the one verdict; the input is kept."""
    b = step_roof_house()
    assert not validate_building(b, DEFAULT)
    m = mesh_of_geometry(b.vertices, b.objects[0].geometries[0])
    assert [c for _, c, _ in shell_defects([m], DEFAULT)[0]] == [306]  # the other triangulation
    assert input_codes(b, DEFAULT) == [("step_roof", 0, [])]
    assert repair_building(b, DEFAULT) is b


def test_valid_input_with_a_sliver_is_never_replaced():
    """Only the project's sliver code (1003): local stages may collapse it, no global stage runs."""
    polys = box_polygons()
    # a 5 mm x 5 mm triangle cut off the top corner (x1, y1): area 1.25e-5 m2, a sliver
    d = 0.005
    roof = np.array([[0, 0, 6], [10, 0, 6], [10, 8 - d, 6], [10 - d, 8, 6], [0, 8, 6]])
    east = np.array([[10, 0, 0], [10, 8, 0], [10, 8, 6], [10, 8 - d, 6], [10, 0, 6]])
    north = np.array([[10, 8, 0], [0, 8, 0], [0, 8, 6], [10 - d, 8, 6], [10, 8, 6]])
    cut = np.array([[10, 8 - d, 6], [10, 8, 6], [10 - d, 8, 6]])
    polys[1], polys[3], polys[4] = [roof], [east], [north]
    b = building_from_polygons(polys + [[cut]], "Solid", id="sliver_corner")
    assert not validate_building(b, DEFAULT)
    (_, _, codes), = input_codes(b, DEFAULT)
    assert codes == [1003]
    rec = repair_building(b, DEFAULT).provenance["repair"]
    assert rec["stage"] not in GLOBAL and rec["stage"] != "irreparable"
    assert rec["defects_before"] == [1003]


# ----------------------------------------------------------------------------- nothing invented

def _flat_faces(n: int, shift=None) -> Building:
    sq = np.array([[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]], float)
    faces = []
    for k in range(n):
        r = sq if shift is None else sq + np.asarray(shift) * k
        faces.append([r])
    return building_from_polygons(faces, "MultiSurface", id=f"flat{n}")


@pytest.mark.parametrize("b", [
    _flat_faces(6),                                    # six identical 10 x 10 m faces
    _flat_faces(1),                                    # a single flat face
    _flat_faces(3, shift=(10.0, 0.0, 0.0)),            # coplanar faces side by side
], ids=["six_identical", "single", "coplanar"])
@pytest.mark.parametrize("type_", ["MultiSurface", "Solid"])
def test_no_volume_input_refused(b, type_):
    if type_ == "Solid":
        g = b.objects[0].geometries[0]
        b = building_from_polygons([[b.vertices[list(s.rings[0])]] for s in g.solids[0].shells[0].surfaces],
                                   "Solid", id=b.id)
    rb = repair_building(b, DEFAULT)
    rec = rb.provenance["repair"]
    assert rec["stage"] == "irreparable"
    assert "no volume" in rec["error"]
    assert rec["iou"] is None  # never 1.0
    # nothing invented: the geometry is the input's
    assert rb.objects[0].geometries == b.objects[0].geometries


def test_no_volume_input_not_compliant():
    from lod2energy.options import PrepareOptions
    from lod2energy.prepare import prepare_building
    _, rec = prepare_building(_flat_faces(6), PrepareOptions())
    assert not rec.energy.compliant and not rec.energy.geometry_ready
    assert any("no volume" in r for r in rec.energy.reasons)
    assert rec.repair.iou != 1.0


# ----------------------------------------------------------------------------- real tiles

@pytest.mark.parametrize("rel", [("3dbag", "tile901_trimmed.city.jsonl"),
                                 ("citygml-real", "munich", "LOD2_4424_5482_solid.gml")])
def test_real_tile_repair_input_equals_validate(rel):
    path = shared_path(*rel)
    _, feats = read(str(path))
    n = 0
    for b in feats:
        if not isinstance(b, Building) or not b.is_building:
            continue
        for coid, gi, codes in input_codes(b, DEFAULT):
            want = _validate_codes(b, coid, gi)
            assert _v3(codes) == want, (b.id, coid, gi)
            g = next(o for o in b.objects if o.id == coid).geometries[gi]
            if not codes and g.type == "Solid":
                n += 1
    assert n > 0


def test_report_page_valid_before_is_validates_verdict():
    """report.html's "valid before" counts the validator's verdict of the input (report.csv's
    input_errors); the repair's energy codes (a sliver, 1003) are no val3dity error."""
    from lod2energy.viz.data import Tally, rows
    report = {"buildings": [
        {"id": "a", "input_errors": "", "repair": {"stage": "cleanup", "defects_before": [1003],
                                                     "defects_after": []}, "energy": {"compliant": True}},
        {"id": "b", "input_errors": "601", "repair": {"stage": "valid", "defects_before": [],
                                                        "defects_after": [601]}, "energy": {}},
        {"id": "c", "input_errors": "102", "repair": {"stage": "cleanup", "defects_before": [102],
                                                        "defects_after": []}, "energy": {}},
    ]}
    t = Tally(rows(report))
    assert t.summary()["valid_before"] == 2
    assert t.validity_by_code()["1003"] == [1, 0]


def test_a_thin_valid_solid_is_kept_not_refused():
    """A closed, valid 10 x 10 m slab 5 mm thick encloses a volume: valid as it is, kept."""
    b = box(10.0, 10.0, 0.005, id="slab")
    assert not validate_building(b, DEFAULT)
    assert repair_building(b, DEFAULT) is b
