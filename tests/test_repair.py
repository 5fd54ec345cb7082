"""Repair ladder: one tiny named geometry per defect kind, the stage that fixes it, guarantees."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings, strategies as st

from lod2energy.config import DEFAULT
from lod2energy.model import Building, CityObject, FeatureError, Geometry, Shell, Solid, Surface
from lod2energy.repair.pipeline import (
    STAGES, dataset_table, mesh_of_geometry, repair_building, repair_features, repair_info,
)
from lod2energy.validate.closed import shell_defects
from lod2energy.validate.checks import validate_building

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared"

# ----------------------------------------------------------------------------- factories

BOX_V = [(0, 0, 0), (10, 0, 0), (10, 8, 0), (0, 8, 0), (0, 0, 6), (10, 0, 6), (10, 8, 6), (0, 8, 6)]
BOX_F = [
    [0, 3, 2, 1],  # ground
    [4, 5, 6, 7],  # roof
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
]
SEM = ({"type": "GroundSurface"}, {"type": "RoofSurface"}, {"type": "WallSurface"})
SEM_OF = [0, 1, 2, 2, 2, 2]


def building(vertices, faces, gtype="Solid", semantics=None, bid="b"):
    """A Building with one LoD2 geometry; ``faces`` are outer rings (or lists of rings)."""
    surfs = []
    for i, f in enumerate(faces):
        rings = f if isinstance(f[0], (list, tuple)) else [f]
        sem = None if semantics is None else semantics[i]
        surfs.append(Surface.from_lists(rings, sem))
    g = Geometry(gtype, "2", (Solid((Shell(tuple(surfs)),)),), SEM if semantics is not None else ())
    return Building(bid, "Building", np.asarray(vertices, dtype=float),
                    (CityObject(bid, "Building", (g,), {"name": "test"}),))


def box(**kw):
    return building(BOX_V, BOX_F, semantics=SEM_OF, **kw)


def flipped_wall():
    f = [list(r) for r in BOX_F]
    f[3] = f[3][::-1]
    return building(BOX_V, f, semantics=SEM_OF)


def inside_out():
    return building(BOX_V, [r[::-1] for r in BOX_F], semantics=SEM_OF)


def open_box():
    return building(BOX_V, BOX_F[:5], semantics=SEM_OF[:5])


def multisurface_box():
    return building(BOX_V, BOX_F, gtype="MultiSurface", semantics=SEM_OF)


def near_duplicate_vertex():
    # vertex 8 is vertex 6 moved by 0.4 mm: the roof uses it, the walls do not
    v = BOX_V + [(10, 8.0004, 6)]
    f = [list(r) for r in BOX_F]
    f[1] = [4, 5, 8, 7]
    return building(v, f, semantics=SEM_OF)


def t_junction():
    # the front wall is split in two by a vertical edge at x=5; ground and roof do not know it
    v = BOX_V + [(5, 0, 0), (5, 0, 6)]
    f = [list(r) for r in BOX_F]
    f[2:3] = [[0, 8, 9, 4], [8, 1, 5, 9]]
    sem = SEM_OF[:2] + [2, 2] + SEM_OF[3:]
    return building(v, f, semantics=sem)


def non_planar_roof():
    v = [list(p) for p in BOX_V]
    v[6] = [10, 8, 6.5]  # 0.5 m out of the roof's plane (203)
    return building(v, BOX_F, semantics=SEM_OF)


def missing_party_wall():
    """An L-shaped hole: one wall and part of the ground missing (non-planar boundary loop)."""
    v = BOX_V + [(5, 0, 0), (5, 8, 0)]
    f = [[0, 3, 9, 8], [4, 5, 6, 7], [0, 8, 1, 5, 4], [2, 3, 7, 6], [3, 0, 4, 7]]  # ground half, no x=10 wall
    return building(v, f, semantics=[0, 1, 2, 2, 2])


def duplicated_face():
    f = [list(r) for r in BOX_F] + [list(BOX_F[2])]
    return building(BOX_V, f, semantics=SEM_OF + [2])


def internal_wall():
    """Two boxes sharing a wall that both keep (non-manifold edges all around it)."""
    v = BOX_V + [(20, 0, 0), (20, 8, 0), (20, 0, 6), (20, 8, 6)]
    f = [list(r) for r in BOX_F]
    f += [[1, 8, 9, 2], [5, 6, 11, 10], [1, 5, 10, 8], [8, 10, 11, 9], [9, 11, 6, 2]]
    return building(v, f, semantics=SEM_OF + [0, 1, 2, 2, 2])


def soup():
    """Triangles scattered over a box with no shared edges at all."""
    rng = np.random.default_rng(1)
    pts = rng.uniform([0, 0, 0], [10, 8, 6], size=(30, 3))
    pts = np.vstack([pts, np.array(BOX_V, dtype=float)])
    faces = [[i, i + 1, i + 2] for i in range(0, 36, 3)]
    return building(pts, faces)


CASES = {
    # name: (factory, stages that may fix it)
    "flipped_wall": (flipped_wall, {"orientation"}),
    "inside_out": (inside_out, {"orientation"}),
    "open_box": (open_box, {"holefill"}),
    "multisurface_box": (multisurface_box, {"cleanup"}),
    "near_duplicate_vertex": (near_duplicate_vertex, {"cleanup"}),
    "t_junction": (t_junction, {"cleanup"}),
    "non_planar_roof": (non_planar_roof, {"cleanup"}),
    "missing_party_wall": (missing_party_wall, {"holefill"}),
    "duplicated_face": (duplicated_face, {"cleanup", "refill"}),
    "internal_wall": (internal_wall, {"refill", "alphashape"}),
    "soup": (soup, {"alphashape", "footprint", "hull"}),
}


def output_shells(b):
    for o in b.objects:
        for g in o.geometries:
            if g.is_polygonal:
                yield g


def assert_energy_ready(b):
    assert [d for d in validate_building(b, DEFAULT) if d.code != 601] == []
    for g in output_shells(b):
        assert g.type == "Solid"
        m = mesh_of_geometry(b.vertices, g)
        assert shell_defects([m], DEFAULT) == [[]]
        tris = []
        from lod2energy.polymesh import triangulate_mesh
        tris, _ = triangulate_mesh(m)
        tm = trimesh.Trimesh(m.vertices, tris, process=False)
        assert tm.is_watertight
        assert tm.is_winding_consistent
        assert tm.volume > 0


# ----------------------------------------------------------------------------- tests

def test_valid_box_passes_through_untouched():
    b = box()
    assert repair_building(b) is b
    assert repair_info(b)["stage"] == "valid"


@pytest.mark.parametrize("name", sorted(CASES))
def test_defect_fixed_by_expected_stage(name):
    factory, stages = CASES[name]
    b = factory()
    r = repair_building(b)
    info = r.provenance["repair"]
    assert info["stage"] in stages, info.get("geometries")
    if name != "multisurface_box":  # closed already: only its type changes
        assert info["defects_before"], "the fixture must be defective"
    assert r.root.geometries[0].type == "Solid"
    assert_energy_ready(r)
    assert r.root.attributes["name"] == "test"
    assert 0.0 <= info["iou"] <= 1.0 + 1e-9
    for key in ("mean_displacement", "hausdorff", "n_faces_before", "n_faces_after", "seconds", "closure"):
        assert key in info


@pytest.mark.parametrize("name", ["flipped_wall", "open_box", "t_junction", "near_duplicate_vertex",
                                  "multisurface_box", "missing_party_wall"])
def test_local_repairs_keep_the_input_geometry(name):
    r = repair_building(CASES[name][0]())
    info = r.provenance["repair"]
    assert info["mean_displacement"] <= 1e-3
    assert info["iou"] >= 0.999


def test_semantics_kept_and_new_faces_unlabelled():
    b = open_box()
    r = repair_building(b)
    g = r.root.geometries[0]
    sems = [s.semantic for s in g.solids[0].shells[0].surfaces]
    assert sems.count(None) == 1  # the filled wall
    assert sorted(s for s in sems if s is not None) == sorted(SEM_OF[:5])
    assert g.semantic_surfaces == b.root.geometries[0].semantic_surfaces


def test_open_box_filled_with_one_polygon():
    r = repair_building(open_box())
    assert r.provenance["repair"]["n_faces_after"] == 6


def test_missing_wall_loop_split_into_planar_polygons():
    r = repair_building(missing_party_wall())
    info = r.provenance["repair"]
    # ground half + wall: split along a chord, not a triangle fan
    assert info["n_faces_after"] <= 8


def test_input_not_mutated_and_output_deterministic():
    b = internal_wall()
    before = (b.vertices.copy(), [s.to_lists() for _, _, _, s in b.root.geometries[0].iter_surfaces()])
    r1 = repair_building(b)
    r2 = repair_building(b)
    assert np.array_equal(b.vertices, before[0])
    assert [s.to_lists() for _, _, _, s in b.root.geometries[0].iter_surfaces()] == before[1]
    assert np.array_equal(r1.vertices, r2.vertices)
    s1 = [s.to_lists() for _, _, _, s in r1.root.geometries[0].iter_surfaces()]
    s2 = [s.to_lists() for _, _, _, s in r2.root.geometries[0].iter_surfaces()]
    assert s1 == s2


def test_empty_geometry_is_irreparable_and_kept():
    g = Geometry("MultiSurface", "2", (Solid((Shell(()),)),))
    b = Building("e", "Building", np.zeros((0, 3)), (CityObject("e", "Building", (g,)),))
    r = repair_building(b)
    assert r.provenance["repair"]["stage"] == "irreparable"
    assert r.root.geometries[0] is g


def test_timeout_escalates_to_a_global_stage():
    r = repair_building(internal_wall(), timeout=0.0)
    assert r.provenance["repair"]["stage"] in ("hull", "irreparable")


def test_repair_features_keeps_everything_in_order():
    err = FeatureError("x", 901, "broken")
    other = Building("t", "TINRelief", np.zeros((0, 3)), (CityObject("t", "TINRelief"),))
    items = [box(bid="a"), err, open_box(), other]
    out = list(repair_features(items))
    assert [getattr(o, "id", None) for o in out] == ["a", "x", "b", "t"]
    assert out[0] is items[0] and out[1] is err and out[3] is other


def test_dataset_table_counts():
    out = [repair_building(f()) for f in (box, open_box, flipped_wall, soup)]
    t = dataset_table(out)
    assert t["total"] == 4
    assert t["invalid"] == 3
    assert t["local_repairs"] == 2
    assert t["global_repairs"] == 1
    assert t["left"] == 0
    assert t["compliant_after"] == 4
    assert sum(t["stages"].values()) == 4
    assert set(t["stages"]) <= set(STAGES)


_rot = st.floats(0, 2 * np.pi)
_shift = st.floats(-1e5, 1e5)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(["flipped_wall", "open_box", "t_junction", "inside_out", "missing_party_wall"]),
       angle=_rot, dx=_shift, dy=_shift)
def test_repair_is_idempotent_under_rigid_transforms(name, angle, dx, dy):
    b = CASES[name][0]()
    c, s = np.cos(angle), np.sin(angle)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    # quantise as CityJSON does (mm), so the transformed input is what a file would hold
    V = np.round(b.vertices @ R.T + [dx, dy, 0], 3)
    b = Building(b.id, b.type, V, b.objects)
    r = repair_building(b)
    assert r.provenance["repair"]["stage"] != "irreparable"
    assert_energy_ready(r)
    assert repair_building(r) is r  # a repaired building is valid input: untouched


# ----------------------------------------------------------------------------- real data

def _tile(rel):
    p = SHARED / "data" / rel
    if not p.exists():
        pytest.skip(f"{rel} not available")
    from lod2energy.io.cityjson import read
    _, it = read(str(p))
    return [b for b in it if isinstance(b, Building)]


def test_real_rotterdam_surfaces_become_solids():
    bs = _tile("rotterdam/fme_msurface_buildings_semsrf_attributes.json")
    for b in bs:
        r = repair_building(b)
        assert r.id == b.id
        assert_energy_ready(r)


@pytest.mark.slow
@pytest.mark.parametrize("rel", ["3dbag/tile901_trimmed.city.jsonl", "rotterdam/rotterdam_subset.json",
                                 "delft-3dfier-lod1/delft.json"])
def test_real_tile_repaired(rel):
    bs = [b for b in _tile(rel) if b.type == "Building"]
    out = [repair_building(b) for b in bs]
    assert [b.id for b in out] == [b.id for b in bs]
    ok = sum(all(d.code == 601 for d in validate_building(b)) for b in out)
    assert ok >= 0.97 * len(bs)
    t = dataset_table(out)
    if t["miou"] is not None:
        assert t["miou"] >= 0.9


def two_overlapping_parts():
    """A Building made of two BuildingParts (boxes) overlapping by 2 m (601)."""
    from lod2energy.model import CityObject as CO
    V = np.array(BOX_V + [(p[0] + 8, p[1], p[2]) for p in BOX_V], dtype=float)
    geoms = []
    for k in range(2):
        surfs = tuple(Surface.from_lists([[i + 8 * k for i in r]], SEM_OF[j]) for j, r in enumerate(BOX_F))
        geoms.append(Geometry("Solid", "2", (Solid((Shell(surfs),)),), SEM))
    objs = (CO("p", "Building", (), {}, (), ("p-0", "p-1")),
            CO("p-0", "BuildingPart", (geoms[0],), {}, ("p",)),
            CO("p-1", "BuildingPart", (geoms[1],), {}, ("p",)))
    return Building("p", "Building", V, objs)


def test_overlapping_parts_stay_separate_unless_merged():
    from lod2energy.repair.parts import overlapping_parts
    b = two_overlapping_parts()
    assert [(a, c) for a, c, _ in overlapping_parts(b)] == [("p-0", "p-1")]
    assert repair_building(b) is b  # both parts are valid solids: untouched
    m = repair_building(b, merge_parts=True)
    assert m is not b
    g = [g for g in m.root.geometries if g.lod == "2"]
    assert len(g) == 1 and g[0].type == "Solid"
    assert all(not o.geometries for o in m.objects[1:])
    assert_energy_ready(m)
    faces = g[0].solids[0].shells[0].surfaces
    assert len(faces) <= 10  # a box whose roof, ground and long walls keep one face per part
    assert all(s.semantic is not None for s in faces)


def test_composite_solid_becomes_one_solid_without_internal_wall():
    """Two boxes of a CompositeSolid share the wall x=10 (once per solid, opposite ways)."""
    V = np.array(BOX_V + [(p[0] + 10, p[1], p[2]) for p in BOX_V], dtype=float)
    solids = []
    for k in range(2):
        surfs = tuple(Surface.from_lists([[i + 8 * k for i in r]], SEM_OF[j]) for j, r in enumerate(BOX_F))
        solids.append(Solid((Shell(surfs),)))
    # the second box's x=10 wall uses the first box's vertices (1, 2, 5, 6) so they are shared
    lut = {8: 1, 11: 2, 12: 5, 15: 6}
    s1 = Shell(tuple(Surface.from_lists([[lut.get(int(i), int(i)) for i in s.outer]], s.semantic)
                     for s in solids[1].exterior.surfaces))
    g = Geometry("CompositeSolid", "2", (solids[0], Solid((s1,))), SEM)
    b = Building("c", "Building", V, (CityObject("c", "Building", (g,)),))
    r = repair_building(b)
    info = r.provenance["repair"]
    assert info["stage"] in ("cleanup", "holefill")
    assert_energy_ready(r)
    m = mesh_of_geometry(r.vertices, r.root.geometries[0])
    from lod2energy.polymesh import signed_volume
    assert signed_volume(m) == pytest.approx(20 * 8 * 6)
    assert info["iou"] == pytest.approx(1.0, abs=1e-6)


def test_provenance_records_face_sources_and_attributes():
    from lod2energy.repair.pipeline import repair_attributes
    r = repair_building(open_box())
    g = r.provenance["repair"]["geometries"][0]
    assert sorted(g["source_faces"]) == [-1, 0, 1, 2, 3, 4]
    a = repair_attributes(r)
    assert a["repair_stage"] == "holefill" and a["repair_defects_before"] == [302]
    assert a["repair_defects_after"] == []
    assert repair_attributes(box())["repair_stage"] == "valid"


@pytest.mark.parametrize("suffix", [".city.json", ".city.jsonl"])
def test_repaired_building_round_trips_through_cityjson(tmp_path, suffix):
    from lod2energy.io.cityjson import read
    from lod2energy.io.cityjson_write import write
    from lod2energy.model import CityModel
    from dataclasses import replace as dc_replace
    out = []
    for k, f in enumerate((open_box, t_junction, missing_party_wall)):
        b = f()
        root = dc_replace(b.root, id=f"b{k}")
        out.append(repair_building(dc_replace(b, id=f"b{k}", objects=(root,))))
    p = tmp_path / ("out" + suffix)
    write(str(p), CityModel(), out)
    _, it = read(str(p))
    back = [b for b in it if isinstance(b, Building)]
    assert [b.id for b in back] == [b.id for b in out]
    for b in back:
        assert_energy_ready(b)
        assert repair_building(b) is b


def test_solid_without_lod_is_repaired_and_keeps_its_901():
    """A Solid whose 'lod' is missing or junk (FME's reader tests) is a volume by its type:
    it is repaired like any other; its LoD is not invented."""
    from factories import box_polygons, building_from_polygons, BOX_SEMANTICS
    from lod2energy.validate.compliance import energy_compliance
    polys = box_polygons()[:5]
    b = building_from_polygons(polys, "Solid", BOX_SEMANTICS[:5], lod=None)
    codes = {d.code for d in validate_building(b)}
    assert 302 in codes
    r = repair_building(b)
    assert r.provenance["repair"]["stage"] not in ("valid", None, "irreparable")
    assert {d.code for d in validate_building(r)} <= {901}
    comp = energy_compliance(r, validate_building(r))
    assert comp["closed_2manifold"] and not any("LoDNone" in x for x in comp["reasons"])


def test_alpha_search_keeps_a_slender_tower():
    """A 55 m shaft under a 20 m deck (Euromast-like) fills less than a third of its convex
    hull; the alpha search must not take it for a hollow skin."""
    from factories import box_polygons, building_from_polygons
    from lod2energy.repair.alphashape import alpha_repair
    from lod2energy.repair.pipeline import mesh_of_geometry
    from lod2energy.polymesh import signed_volume
    shaft = box_polygons(3, 3, 55)
    del shaft[1]  # no top: the deck sits on it
    deck = box_polygons(20, 20, 5, origin=(-8.5, -8.5, 55))
    b = building_from_polygons(shaft + deck, "Solid")
    m = mesh_of_geometry(b.vertices, b.root.geometries[0])
    r = alpha_repair(m)
    assert r is not None
    assert signed_volume(r) == pytest.approx(3 * 3 * 55 + 20 * 20 * 5, rel=0.15)


def test_lone_wall_beside_a_solid_is_not_made_a_volume():
    """A LoD2 MultiSurface of one face beside the object's LoD2 Solid (as in Euromast) is an
    extra: it is left a surface, not wrapped into a slab; alone it is a building with missing
    walls and is repaired."""
    from dataclasses import replace as dc_replace
    from factories import box_polygons, building_from_polygons
    from lod2energy.repair.pipeline import _targets
    wall = building_from_polygons([box_polygons()[2]], "MultiSurface")
    solid = building_from_polygons(box_polygons(), "Solid")
    g_wall, g_solid = wall.root.geometries[0], solid.root.geometries[0]
    both = Building("b", "Building", solid.vertices,
                    (dc_replace(solid.root, geometries=(g_wall, g_solid)),))
    assert [gi for _, gi, _ in _targets(both, None)] == [1]
    assert [gi for _, gi, _ in _targets(wall, None)] == [0]
