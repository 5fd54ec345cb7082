"""Semantic labels: the rules and their thresholds, keeping / transferring input labels,
ClosureSurfaces between parts, plausibility checks (1101-1104) and rule agreement."""
from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from factories import box, box_polygons, building_from_polygons, gabled_house
from lod2energy import semantics as S
from lod2energy.model import Building, CityObject, Geometry, Shell, Solid, Surface, frozen_mapping
from conftest import shared_path

R = S.DEFAULT_RULES


# ----------------------------------------------------------------------------- helpers

def types_of(b: Building) -> list[str]:
    out = []
    for o, gi, g in S.envelope_objects(b):
        out += [g.semantic_type(s) for *_, s in g.iter_surfaces()]
    return out


def entries_of(b: Building) -> list:
    out = []
    for o, gi, g in S.envelope_objects(b):
        out += [g.semantic_surfaces[s.semantic] for *_, s in g.iter_surfaces()]
    return out


def with_semantics(b: Building, values, surfaces) -> Building:
    """``b`` with its single geometry's surfaces pointing at ``values`` into ``surfaces``."""
    o, gi, g = b.envelope()[0]
    sh = g.solids[0].shells[0]
    shell = Shell(tuple(Surface(s.rings, v) for s, v in zip(sh.surfaces, values)))
    ng = Geometry(g.type, g.lod, (Solid((shell,) + g.solids[0].shells[1:]),),
                  tuple(frozen_mapping(x) for x in surfaces))
    return b.replace_geometry(o.id, gi, ng)


def two_part_building(semantics: bool = False) -> Building:
    """Two 10 x 8 x 6 boxes side by side as BuildingParts, touching along x = 10."""
    a = box(origin=(0, 0, 0), semantics=semantics, id="a")
    c = box(origin=(10, 0, 0), semantics=semantics, id="c")
    off = len(a.vertices)
    gc = c.objects[0].geometries[0]
    shifted = Geometry(gc.type, gc.lod, tuple(Solid(tuple(Shell(tuple(
        Surface(tuple(r + off for r in s.rings), s.semantic) for s in sh.surfaces)) for sh in so.shells))
        for so in gc.solids), gc.semantic_surfaces)
    root = CityObject("b", "Building", (), frozen_mapping({}), (), ("b-0", "b-1"))
    p0 = CityObject("b-0", "BuildingPart", a.objects[0].geometries, frozen_mapping({}), ("b",))
    p1 = CityObject("b-1", "BuildingPart", (shifted,), frozen_mapping({}), ("b",))
    return Building("b", "Building", np.vstack([a.vertices, c.vertices]), (root, p0, p1))


# ----------------------------------------------------------------------------- the rules

@pytest.mark.parametrize("nz, dz, h_rel, expected", [
    (-1.0, 0.0, 0.0, "GroundSurface"),      # bottom face
    (0.0, 0.05, 0.01, "GroundSurface"),     # at the ground threshold exactly
    (-1.0, 0.051, 0.01, "OuterFloorSurface"),  # just above it, facing down: an exterior floor
    (-0.70, 3.0, 0.5, "OuterFloorSurface"),  # the floor threshold exactly
    (-0.699, 3.0, 0.5, "WallSurface"),       # just above it
    (0.70, 3.0, 0.1, "RoofSurface"),        # steep threshold, any height
    (0.699, 3.0, 0.64, "WallSurface"),      # just under both roof conditions
    (0.30, 5.0, 0.65, "RoofSurface"),       # the high-and-inclined rule at both thresholds
    (0.299, 5.0, 0.99, "WallSurface"),      # too steep even at the top
    (0.50, 5.0, 0.649, "WallSurface"),      # inclined but below h_rel 0.65
    (0.0, 5.0, 0.5, "WallSurface"),
])
def test_rule_thresholds(nz, dz, h_rel, expected):
    assert S.rule_label(nz, dz, h_rel, R) == expected


def test_rule_thresholds_are_configurable():
    rules = S.LabelRules(ground_dz=0.5, roof_nz=0.9, roof_nz_high=0.5, roof_hrel=0.8)
    assert S.rule_label(0.0, 0.4, 0.1, rules) == "GroundSurface"
    assert S.rule_label(0.8, 3.0, 0.5, rules) == "WallSurface"     # roof by default rules
    assert S.rule_label(0.8, 3.0, 0.8, R) == "RoofSurface"
    assert S.rule_label(0.6, 3.0, 0.85, rules) == "RoofSurface"


def test_face_metrics_of_polygon_with_hole():
    outer = np.array([[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]], float)
    hole = np.array([[1, 1, 0], [1, 2, 0], [2, 2, 0], [2, 1, 0]], float)   # clockwise
    b = building_from_polygons([[outer, hole]], "MultiSurface")
    s = b.objects[0].geometries[0].solids[0].shells[0].surfaces[0]
    area, n, c = S.face_metrics(b.vertices, s)
    assert area == pytest.approx(15.0)
    assert n == pytest.approx([0, 0, 1])
    # centroid of the square minus the hole's: (16*2 - 1*1.5) / 15
    assert c[:2] == pytest.approx([(32 - 1.5) / 15] * 2)


# ----------------------------------------------------------------------------- labelling

def test_rules_fill_a_building_without_semantics():
    b = S.label_building(box(semantics=False))
    assert sorted(types_of(b)) == sorted(["GroundSurface", "RoofSurface"] + ["WallSurface"] * 4)
    assert {e["labelSource"] for e in entries_of(b)} == {"rule"}
    assert b.provenance["labels"]["rule"] == 6


def test_gabled_house_by_rules_matches_its_labels():
    h = gabled_house()
    lab = S.label_building(replace(h, objects=tuple(
        replace(o, geometries=tuple(replace(g, semantic_surfaces=()) for g in o.geometries)) for o in h.objects)))
    assert types_of(lab) == types_of(h)


def test_one_entry_per_surface_and_input_attributes_kept():
    b = box()
    # input shares one WallSurface entry between the 4 walls and carries an attribute
    shared = with_semantics(b, [0, 1, 2, 2, 2, 2],
                            [{"type": "GroundSurface"}, {"type": "RoofSurface"},
                             {"type": "WallSurface", "on_footprint_edge": True, "children": [3]}])
    lab = S.label_building(shared)
    o, gi, g = lab.envelope()[0]
    idx = [s.semantic for *_, s in g.iter_surfaces()]
    assert sorted(idx) == list(range(6)) and len(g.semantic_surfaces) == 6
    walls = [e for e in g.semantic_surfaces if e["type"] == "WallSurface"]
    assert len(walls) == 4 and all(e["on_footprint_edge"] is True for e in walls)
    assert all("children" not in e for e in walls)      # indices would be stale


def test_input_labels_are_kept_even_when_rules_disagree():
    b = box()
    wrong = with_semantics(b, range(6), [{"type": t} for t in
                                         ["GroundSurface", "RoofSurface", "RoofSurface", "WallSurface",
                                          "WallSurface", "WallSurface"]])
    lab = S.label_building(wrong)
    assert types_of(lab)[2] == "RoofSurface"
    assert entries_of(lab)[2]["labelSource"] == "input"


def test_rules_fill_only_missing_labels():
    b = with_semantics(box(), [None, 0, None, 1, None, None],
                       [{"type": "RoofSurface"}, {"type": "OuterCeilingSurface"}])
    lab = S.label_building(b)
    assert types_of(lab) == ["GroundSurface", "RoofSurface", "WallSurface", "OuterCeilingSurface",
                             "WallSurface", "WallSurface"]
    assert [e["labelSource"] for e in entries_of(lab)] == ["rule", "input", "rule", "input", "rule", "rule"]


def test_label_building_does_not_mutate_its_input():
    b = box(semantics=False)
    before = [s.semantic for *_, s in b.objects[0].geometries[0].iter_surfaces()]
    S.label_building(b)
    assert [s.semantic for *_, s in b.objects[0].geometries[0].iter_surfaces()] == before
    assert b.objects[0].geometries[0].semantic_surfaces == ()
    assert "labels" not in b.provenance


def split_face(b: Building, face: int, semantic_of_new=None) -> Building:
    """Replace quad ``face`` by two triangles (as a repair could), with ``semantic_of_new``."""
    o, gi, g = b.envelope()[0]
    sh = g.solids[0].shells[0]
    q = sh.surfaces[face].outer
    tri = [Surface.from_lists([[q[0], q[1], q[2]]], semantic_of_new),
           Surface.from_lists([[q[0], q[2], q[3]]], semantic_of_new)]
    surfs = list(sh.surfaces[:face]) + tri + list(sh.surfaces[face + 1:])
    ng = replace(g, solids=(Solid((Shell(tuple(surfs)),)),))
    return b.replace_geometry(o.id, gi, ng).with_provenance(repair={"stage": "test"})


def test_after_repair_new_faces_take_the_nearest_compatible_input_label():
    # the input labels its south wall ClosureSurface: the rules would say WallSurface
    src = with_semantics(box(), range(6), [{"type": t} for t in
                                           ["GroundSurface", "RoofSurface", "ClosureSurface", "WallSurface",
                                            "WallSurface", "WallSurface"]])
    rep = split_face(src, 2, None)                       # repair re-created the south wall
    lab = S.label_building(rep, source=src)
    ts, es = types_of(lab), entries_of(lab)
    assert ts[2] == ts[3] == "ClosureSurface"
    assert es[2]["labelSource"] == es[3]["labelSource"] == "transfer"
    assert es[0]["labelSource"] == "input"


def test_after_repair_without_compatible_input_face_the_rule_decides():
    src = building_from_polygons(box_polygons()[1:], "Solid",
                                 ["RoofSurface", "WallSurface", "WallSurface", "WallSurface", "WallSurface"])
    # repaired: the ground face was added (no input face faces down)
    rep = building_from_polygons(box_polygons(), "Solid", None)
    rep = with_semantics(rep, [None, 0, 1, 2, 3, 4], [{"type": "RoofSurface"}] + [{"type": "WallSurface"}] * 4)
    rep = rep.with_provenance(repair={"stage": "test"})
    lab = S.label_building(rep, source=src)
    assert types_of(lab)[0] == "GroundSurface"
    assert entries_of(lab)[0]["labelSource"] == "rule"


def test_without_repair_provenance_source_is_not_used():
    src = with_semantics(box(), range(6), [{"type": t} for t in
                                           ["GroundSurface", "RoofSurface", "ClosureSurface", "WallSurface",
                                            "WallSurface", "WallSurface"]])
    rep = split_face(src, 2, None)
    rep = replace(rep, provenance=frozen_mapping({}))
    lab = S.label_building(rep, source=src)
    assert types_of(lab)[2] == "WallSurface"


def test_transfer_respects_the_normal_threshold():
    src = with_semantics(box(), range(6), [{"type": t} for t in
                                           ["GroundSurface", "RoofSurface", "ClosureSurface", "WallSurface",
                                            "WallSurface", "WallSurface"]])
    rep = split_face(src, 2, None)
    strict = S.LabelRules(transfer_max_dist=0.0, transfer_normal_cos=1.01)   # nothing is compatible
    lab = S.label_building(rep, source=src, rules=strict)
    assert types_of(lab)[2] == "WallSurface" and entries_of(lab)[2]["labelSource"] == "rule"


def test_faces_between_parts_become_closure_surfaces():
    b = S.label_building(two_part_building())
    kinds = []
    for o, gi, g in S.envelope_objects(b):
        t = S.face_table(b.vertices, g)
        for i, s in enumerate(t.surfaces):
            kinds.append((o.id, g.semantic_type(s), round(float(t.centroid[i, 0]), 3)))
    closures = [k for k in kinds if k[1] == "ClosureSurface"]
    assert sorted(closures) == [("b-0", "ClosureSurface", 10.0), ("b-1", "ClosureSurface", 10.0)]
    assert b.provenance["labels"]["closure"] == 2
    off = S.label_building(two_part_building(), rules=S.LabelRules(closure_between_parts=False))
    assert "ClosureSurface" not in types_of(off)


def test_installations_are_not_labelled():
    b = box()
    inst = CityObject("i", "BuildingInstallation", b.objects[0].geometries, frozen_mapping({}), ("box",))
    b2 = replace(b, objects=(replace(b.root, children=("i",)), inst))
    lab = S.label_building(b2)
    assert [o.id for o, _, _ in S.envelope_objects(lab)] == ["box"]
    assert lab.objects[1].geometries[0] is inst.geometries[0]


# ----------------------------------------------------------------------------- checks

def test_check_labels_on_a_plausible_house_is_empty():
    assert S.check_labels(S.label_building(gabled_house())) == []


def test_roof_facing_down_and_ground_at_the_top():
    swapped = with_semantics(box(), range(6), [{"type": t} for t in
                                               ["RoofSurface", "GroundSurface", "WallSurface", "WallSurface",
                                                "WallSurface", "WallSurface"]])
    codes = sorted(d.code for d in S.check_labels(swapped))
    assert codes == [1101, 1102, 1104]
    d1101 = [d for d in S.check_labels(swapped) if d.code == 1101][0]
    assert d1101.location == "coid=box|geom=0|shell=0|face=0"


def test_wall_above_the_roof():
    polys = box_polygons() + [[np.array([[0, -1, 8], [10, -1, 8], [10, -1, 9], [0, -1, 9]], float)]]
    b = building_from_polygons(polys, "MultiSurface", ["GroundSurface", "RoofSurface"] + ["WallSurface"] * 5)
    defects = S.check_labels(b)
    assert [d.code for d in defects] == [1103]
    assert defects[0].location.endswith("face=6")
    # the same wall reaching down to the roof top is fine
    polys[-1] = [np.array([[0, -1, 6], [10, -1, 6], [10, -1, 9], [0, -1, 9]], float)]
    ok = building_from_polygons(polys, "MultiSurface", ["GroundSurface", "RoofSurface"] + ["WallSurface"] * 5)
    assert S.check_labels(ok) == []


def test_rule_agreement_is_area_weighted():
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    from bench_labels import rule_agreement
    b = box(10, 8, 6)
    assert rule_agreement(b) == pytest.approx((2 * 80 + 2 * 60 + 2 * 48, 2 * 80 + 2 * 60 + 2 * 48))
    wrong = with_semantics(b, [0, 1, 2, 3, 4, None], [{"type": t} for t in
                                                      ["GroundSurface", "RoofSurface", "RoofSurface",
                                                       "WallSurface", "WallSurface"]])
    agree, total = rule_agreement(wrong)
    assert total == pytest.approx(2 * 80 + 2 * 60 + 48)           # unlabelled west wall left out
    assert agree == pytest.approx(total - 60)                      # the south wall disagrees


# ----------------------------------------------------------------------------- real tiles

def test_real_tile_every_surface_labelled_and_input_labels_kept():
    from lod2energy.io import cityjson

    model, feats = cityjson.read(str(shared_path("3dbag", "small.city.jsonl")))
    n = 0
    for f in feats:
        assert isinstance(f, Building)
        lab = S.label_building(f)
        for (o, gi, g), (o2, gi2, g2) in zip(S.envelope_objects(f), S.envelope_objects(lab)):
            assert len(g2.semantic_surfaces) == g2.n_surfaces
            for (*_, s), (*_, s2) in zip(g.iter_surfaces(), g2.iter_surfaces()):
                assert g2.semantic_type(s2) in S.ENVELOPE_TYPES
                if g.semantic_type(s) is not None:
                    assert g2.semantic_type(s2) == g.semantic_type(s)
                n += 1
        assert not [d for d in S.check_labels(lab) if d.code in (1101, 1104)]
    assert n > 0


def test_transfer_picks_the_nearest_of_several_compatible_faces():
    def wall(y, x0=0.0):
        return [np.array([[x0, y, 0], [x0 + 4, y, 0], [x0 + 4, y, 3], [x0, y, 3]], float)]

    # three south-facing input walls (normal -y): a big one far away, two small ones
    src = building_from_polygons([wall(0.0), wall(-5.0, 20.0), wall(-9.0)], "MultiSurface",
                                 ["WallSurface", "OuterCeilingSurface", "ClosureSurface"])
    new = building_from_polygons([wall(-8.5, 1.0)], "MultiSurface").with_provenance(repair={"stage": "test"})
    lab = S.label_building(new, source=src)
    assert types_of(lab) == ["ClosureSurface"] and entries_of(lab)[0]["labelSource"] == "transfer"
    # with a distance limit, a face far from every input face goes to the rules
    far = building_from_polygons([wall(-30.0)], "MultiSurface").with_provenance(repair={"stage": "test"})
    assert types_of(S.label_building(far, source=src)) == ["ClosureSurface"]
    limited = S.label_building(far, source=src, rules=S.LabelRules(transfer_max_dist=2.0))
    assert types_of(limited) == ["WallSurface"] and entries_of(limited)[0]["labelSource"] == "rule"


def test_transfer_from_an_input_oriented_inwards():
    from factories import inward_box

    src = with_semantics(inward_box(), range(6), [{"type": t} for t in
                                                  ["GroundSurface", "RoofSurface", "ClosureSurface",
                                                   "WallSurface", "WallSurface", "WallSurface"]])
    rep = split_face(with_semantics(box(), range(6), [dict(e) for e in
                                                      src.objects[0].geometries[0].semantic_surfaces]), 2, None)
    lab = S.label_building(rep, source=src)
    assert types_of(lab)[2:4] == ["ClosureSurface", "ClosureSurface"]


def test_envelope_prefers_the_solid_beside_a_multisurface():
    b = box()
    g = b.objects[0].geometries[0]
    ms = Geometry("MultiSurface", g.lod, (Solid((Shell(g.solids[0].shells[0].surfaces[:1]),)),), g.semantic_surfaces)
    b2 = replace(b, objects=(replace(b.root, geometries=(ms, g)),))
    (o, gi, eg), = S.envelope_objects(b2)
    assert gi == 1 and eg.type == "Solid"
    lab = S.label_building(b2)
    assert lab.objects[0].geometries[0] is ms and len(lab.objects[0].geometries[1].semantic_surfaces) == 6
