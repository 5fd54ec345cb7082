"""Shell (301-307), solid (401-405), Multi/CompositeSolid (501-503) and BuildingPart (601) checks.

One tiny named geometry per code, plus valid counterparts that must stay clean, plus
the geometry helpers the checks rely on.
"""
from __future__ import annotations

import numpy as np
import pytest

from factories import box, box_polygons, building_from_polygons, flipped_wall, gabled_house, inward_box, open_box
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import (
    bbox_pairs, signed_volume, snap_map, triangle_pairs_intersect, triangulate_flat, triangulate_surface,
    winding_number,
)
from lod2energy.model import Building, CityObject, Geometry, Shell, Solid, Surface
from lod2energy.validate import shell as shell_checks
from lod2energy.validate import solid as solid_checks
from lod2energy.validate.checks import validate_building, validate_buildings


def codes(b: Building, tol: Tolerances = DEFAULT) -> set[int]:
    return {d.code for d in validate_building(b, tol)}


# ----------------------------------------------------------------------------- builders

def _merge(parts: list[Building], kind: str, id: str = "b") -> Building:
    """One object whose geometry gathers the exterior shells of ``parts`` as
    MultiSolid / CompositeSolid members ("MultiSolid", "CompositeSolid"), or the
    shells of one Solid ("Solid": first = exterior, others = interior shells), or all
    their faces in one shell ("shell")."""
    verts, solids = [], []
    off = 0
    for p in parts:
        sh = p.root.geometries[0].solids[0].shells[0]
        solids.append(Shell(tuple(Surface.from_lists([r + off for r in s.rings]) for s in sh.surfaces)))
        verts.append(p.vertices)
        off += len(p.vertices)
    if kind == "shell":
        sol = (Solid((Shell(tuple(s for sh in solids for s in sh.surfaces)),)),)
        g = Geometry("Solid", "2", sol)
    elif kind == "Solid":
        g = Geometry("Solid", "2", (Solid(tuple(solids)),))
    else:
        g = Geometry(kind, "2", tuple(Solid((sh,)) for sh in solids))
    return Building(id, "Building", np.concatenate(verts), (CityObject(id, "Building", (g,)),))


def _with_parts(parts: list[Building], id: str = "b") -> Building:
    """A Building without geometry whose BuildingParts are ``parts`` (one Solid each)."""
    verts, objs, off = [], [], 0
    kids = tuple(f"{id}_{k}" for k in range(len(parts)))
    for k, p in enumerate(parts):
        g = p.root.geometries[0]
        sh = g.solids[0].shells[0]
        shifted = Shell(tuple(Surface.from_lists([r + off for r in s.rings]) for s in sh.surfaces))
        objs.append(CityObject(kids[k], "BuildingPart", (Geometry("Solid", "2", (Solid((shifted,)),)),),
                               parents=(id,)))
        verts.append(p.vertices)
        off += len(p.vertices)
    root = CityObject(id, "Building", (), children=kids)
    return Building(id, "Building", np.concatenate(verts), (root,) + tuple(objs))


def _reversed(b: Building) -> Building:
    sh = b.root.geometries[0].solids[0].shells[0]
    rev = Shell(tuple(Surface.from_lists([r[::-1] for r in s.rings]) for s in sh.surfaces))
    return b.replace_geometry(b.root.id, 0, Geometry("Solid", "2", (Solid((rev,)),)))


def too_few_polygons() -> Building:
    p = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    return building_from_polygons([[p[[0, 2, 1]]], [p[[0, 1, 3]]], [p[[1, 2, 3]]]], "Solid", id="three_faces")


def fin_on_box() -> Building:
    """A box with an extra face hanging on one of its edges: the edge bounds 3 faces (303)."""
    polys = box_polygons(1, 1, 1)
    polys.append([np.array([[1, 0, 1], [1, 1, 1], [2, 1, 1.5], [2, 0, 1.5]], float)])
    return building_from_polygons(polys, "Solid", id="fin")


def boxes_sharing_edge() -> Building:
    """Two boxes in one shell touching along an edge: the edge bounds 4 faces (303)."""
    return _merge([box(1, 1, 1), box(1, 1, 1, origin=(1, 1, 0))], "shell", id="edge_pair")


def two_components() -> Building:
    """Two disjoint closed boxes in one shell (305)."""
    return _merge([box(1, 1, 1), box(1, 1, 1, origin=(3, 0, 0))], "shell", id="two_boxes")


def dented_box() -> Building:
    """A unit cube whose top is a pyramid pushed through the floor (306, val3dity's 306.poly)."""
    p = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
                  [0.5, 0.5, -1]], float)
    faces = [[0, 3, 2, 1], [4, 5, 8], [5, 6, 8], [6, 7, 8], [7, 4, 8], [0, 1, 5, 4], [1, 2, 6, 5],
             [2, 3, 7, 6], [3, 0, 4, 7]]
    return building_from_polygons([[p[f]] for f in faces], "Solid", id="dented")


def pinched_surface() -> Building:
    """A CompositeSurface whose centre vertex joins two open fans (303, non-manifold vertex)."""
    c, a, b_, d, e = (np.array(x, float) for x in ([0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]))
    up = np.array([0, 0, 1.0])
    polys = [[np.array([c, a, b_])], [np.array([c, d, e])],
             [np.array([b_, a, a + up, b_ + up])], [np.array([b_ + up, a + up, e + up, d + up])],
             [np.array([e, d, d + up, e + up])]]
    return building_from_polygons(polys, "CompositeSurface", id="pinched")


def cube_with_cavity(inner: list) -> Building:
    """A 10 m cube whose interior shells are given as lists of polygons (oriented inwards)."""
    return building_from_polygons([box_polygons(10, 10, 10)] + inner, "Solid", id="cavity")


def _inward_box(dx, dy, dz, origin):
    return [[p[0][::-1]] for p in box_polygons(dx, dy, dz, origin)]


def _splitting_octahedron():
    """A cavity whose equator lies on the walls: it cuts the cube's interior in two (404)."""
    e = np.array([[0, 0, 5], [10, 0, 5], [10, 10, 5], [0, 10, 5]], float)
    t, u = np.array([5, 5, 7.0]), np.array([5, 5, 3.0])
    out = [np.array([e[i], e[(i + 1) % 4], t]) for i in range(4)] + \
          [np.array([e[(i + 1) % 4], e[i], u]) for i in range(4)]
    return [[f[::-1]] for f in out]


SHELL_CASES = {
    301: too_few_polygons,
    302: open_box,
    303: fin_on_box,
    305: two_components,
    306: dented_box,
    307: flipped_wall,
}

SOLID_CASES = {
    401: lambda: cube_with_cavity([_inward_box(4, 4, 4, (8, 3, 3))]),            # cavity crosses the wall
    402: lambda: cube_with_cavity([_inward_box(2, 2, 2, (3, 3, 3)), _inward_box(2, 2, 2, (3, 3, 3))]),
    403: lambda: cube_with_cavity([_inward_box(2, 2, 2, (20, 3, 3))]),
    404: lambda: cube_with_cavity([_splitting_octahedron()]),
    405: inward_box,
}

MULTI_CASES = {
    501: lambda: _merge([box(2, 2, 2), box(2, 2, 2, origin=(1, 1, 1))], "MultiSolid"),
    502: lambda: _merge([box(2, 2, 2), box(2, 2, 2)], "MultiSolid"),
    503: lambda: _merge([box(2, 2, 2), box(2, 2, 2, origin=(5, 0, 0))], "CompositeSolid"),
    601: lambda: _with_parts([box(2, 2, 2), box(2, 2, 2, origin=(1, 0, 0))]),
}

VALID = {
    "box": lambda: box(),
    "gabled_house": lambda: gabled_house(),
    "cube_with_cavity": lambda: cube_with_cavity([_inward_box(2, 2, 2, (3, 3, 3))]),
    "composite_solid_sharing_face": lambda: _merge([box(2, 2, 2), box(2, 2, 2, origin=(2, 0, 0))],
                                                   "CompositeSolid"),
    "multisolid_touching": lambda: _merge([box(2, 2, 2), box(2, 2, 2, origin=(2, 0, 0))], "MultiSolid"),
    "parts_sharing_wall": lambda: _with_parts([box(2, 2, 2), box(2, 3, 1, origin=(2, 0, 0))]),
    "composite_surface_strip": lambda: building_from_polygons(box_polygons(1, 1, 1)[:3], "CompositeSurface"),
    "large_coordinates": lambda: box(origin=(85000.123, 447000.456, 0.0)),
}


# ----------------------------------------------------------------------------- one geometry per code

@pytest.mark.parametrize("code", sorted(SHELL_CASES))
def test_shell_code(code):
    assert code in codes(SHELL_CASES[code]())


def test_303_non_manifold_vertex_of_composite_surface():
    found = validate_building(pinched_surface())
    assert [d.code for d in found] == [303]
    assert found[0].info.startswith("Non-manifold vertex at (0, 0, 0)")


def test_303_edge_of_four_faces():
    assert codes(boxes_sharing_edge()) == {303}


def test_302_reports_hole_location():
    found = [d for d in validate_building(open_box()) if d.code == 302]
    assert len(found) == 1 and found[0].info.startswith("Location hole: (")
    assert found[0].location.endswith("|shell=0|face=")


def test_307_names_the_flipped_face():
    found = [d for d in validate_building(flipped_wall(face=3)) if d.code == 307]
    assert found and all(d.location.endswith("face=3") for d in found)


@pytest.mark.parametrize("code", sorted(SOLID_CASES))
def test_solid_code(code):
    assert code in codes(SOLID_CASES[code]())


@pytest.mark.parametrize("code", sorted(MULTI_CASES))
def test_multisolid_and_parts_code(code):
    assert codes(MULTI_CASES[code]()) == {code}


@pytest.mark.parametrize("name", sorted(VALID))
def test_valid_geometry_stays_clean(name):
    assert codes(VALID[name]()) == set()


def test_601_location_names_both_parts():
    found = validate_building(MULTI_CASES[601]())
    assert [(d.code, d.location, d.info) for d in found] == [
        (601, "coid=b_0|geom=0&&coid=b_1|geom=0", "geometries are lod=2")]


def test_overlap_tol_tolerates_thin_overlap():
    thin = _with_parts([box(2, 2, 2), box(2, 2, 2, origin=(1.99, 0, 0))])    # 1 cm overlap
    assert 601 in codes(thin)
    assert 601 not in codes(thin, Tolerances(overlap_tol=0.05))


def test_snap_tol_merges_close_vertices():
    b = box(1, 1, 1)
    sh = b.root.geometries[0].solids[0].shells[0]
    corner = int(sh.surfaces[1].rings[0][0])
    n = len(b.vertices)
    v = np.vstack([b.vertices, b.vertices[corner] + 0.0004])   # a copy of a corner, 0.7 mm away ...
    roof = Surface.from_lists([np.where(sh.surfaces[1].rings[0] == corner, n, sh.surfaces[1].rings[0])])
    sh2 = Shell(sh.surfaces[:1] + (roof,) + sh.surfaces[2:])
    b2 = Building(b.id, b.type, v, b.objects).replace_geometry(b.id, 0, Geometry("Solid", "2", (Solid((sh2,)),)))
    assert codes(b2) == set()
    assert 302 in codes(b2, Tolerances(snap_tol=1e-5))   # ... used by the roof only: a hole without snapping


def test_batched_validation_equals_one_by_one():
    bs = [f() for f in list(SHELL_CASES.values()) + list(MULTI_CASES.values())] + [box(), gabled_house()]
    one = [sorted((d.code, d.location) for d in validate_building(b)) for b in bs]
    many = [sorted((d.code, d.location) for d in ds) for ds in validate_buildings(bs)]
    assert one == many


def test_checks_do_not_mutate_input():
    b = flipped_wall()
    before = b.vertices.copy(), [r.copy() for s in b.root.geometries[0].solids[0].shells[0].surfaces
                                   for r in s.rings]
    validate_building(b)
    assert np.array_equal(b.vertices, before[0])
    after = [r for s in b.root.geometries[0].solids[0].shells[0].surfaces for r in s.rings]
    assert all(np.array_equal(x, y) for x, y in zip(before[1], after))


def test_check_shell_contract_returns_plain_tuples():
    b = open_box()
    sh = b.root.geometries[0].solids[0].shells[0]
    out, composite = shell_checks.check_shells([(b.vertices, sh, True), (b.vertices, sh, False)], DEFAULT)
    assert out and all(len(t) == 3 and isinstance(t[1], int) for t in out)
    assert composite == []   # fine as a CompositeSurface


def test_exterior_shell_orientation_is_checked_once_shell_is_valid():
    b = _reversed(box())
    assert solid_checks.check_solids([(b.vertices, b.root.geometries[0].solids[0])], DEFAULT)[0][0][1] == 405


# ----------------------------------------------------------------------------- geometry helpers

def triangulate_surfaces(vertices, ringsets):
    """:func:`triangulate_flat` of polygons given as lists of rings."""
    rings = [np.asarray(r) for rs in ringsets for r in rs]
    return triangulate_flat(vertices, np.concatenate(rings), [len(r) for r in rings], [len(rs) for rs in ringsets])


def test_triangulation_keeps_orientation_and_area():
    b = gabled_house()
    sh = b.root.geometries[0].solids[0].shells[0]
    tris, fot = triangulate_surfaces(b.vertices, [f.rings for f in sh.surfaces])
    assert len(tris) == 2 + 2 * 4 + 2 * 3 and fot.max() == 6
    assert signed_volume(b.vertices, tris) == pytest.approx(10 * 8 * 6 + 0.5 * 8 * 3 * 10)


def test_triangulate_surface_with_hole():
    v = np.array([[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0], [1, 1, 0], [1, 2, 0], [2, 2, 0], [2, 1, 0]], float)
    t = triangulate_surface(v, Surface.from_lists([[0, 1, 2, 3], [4, 5, 6, 7]]))
    p = v[t]
    area = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2]
    assert (area > 0).all() and area.sum() == pytest.approx(15.0)


def test_collinear_vertex_gives_no_zero_area_triangle():
    v = np.array([[0, 0, 0], [2, 0, 0], [1, 1, 0], [0, 2, 0]], float)    # (1,1) lies on the diagonal
    t, _ = triangulate_surfaces(v, [Surface.from_lists([[0, 1, 2, 3]]).rings])
    p = v[t]
    assert (np.abs(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2]) > 1e-9).all()


def test_winding_number_inside_outside():
    b = box(2, 2, 2)
    tris, _ = triangulate_surfaces(b.vertices, [f.rings for f in b.root.geometries[0].solids[0].shells[0].surfaces])
    w = winding_number(np.array([[1, 1, 1], [3, 1, 1]], float), b.vertices, tris)
    assert w == pytest.approx([1.0, 0.0], abs=1e-9)


def test_snap_map_merges_clusters():
    p = np.array([[0, 0, 0], [0.0005, 0, 0], [5, 5, 5]], float)
    assert snap_map(p, 0.001).tolist() == [0, 0, 2]
    assert snap_map(p, 0.0001).tolist() == [0, 1, 2]


def test_bbox_pairs_and_triangle_intersections():
    v = np.array([[0, 0, 0], [2, 0, 0], [0, 2, 0],          # flat triangle
                  [0.5, 0.5, -1], [0.5, 0.5, 1], [1.5, 0.5, 1],   # pierces it
                  [5, 5, 5], [6, 5, 5], [5, 6, 5]], float)   # far away
    tris = np.array([[0, 1, 2], [3, 4, 5], [6, 7, 8]])
    P = v[tris]
    pairs = bbox_pairs(P.min(1), P.max(1))
    assert pairs.tolist() == [[0, 1]]
    assert triangle_pairs_intersect(v, tris, pairs).tolist() == [True]
    # sharing an edge without folding: no intersection
    v2 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.5]], float)
    assert triangle_pairs_intersect(v2, np.array([[0, 1, 2], [1, 3, 2]]), np.array([[0, 1]])).tolist() == [False]


def test_601_between_a_composite_solid_part_and_a_solid_part():
    comp = _merge([box(2, 2, 2), box(2, 2, 2, origin=(2, 0, 0))], "CompositeSolid", id="c")
    solo = box(2, 2, 2, origin=(3, 1, 0))                       # overlaps the second member
    off = len(comp.vertices)
    sh = solo.root.geometries[0].solids[0].shells[0]
    moved = Shell(tuple(Surface.from_lists([r + off for r in s.rings]) for s in sh.surfaces))
    objs = (CityObject("b", "Building", (), children=("p1", "p2")),
            CityObject("p1", "BuildingPart", comp.root.geometries, parents=("b",)),
            CityObject("p2", "BuildingPart", (Geometry("Solid", "2", (Solid((moved,)),)),), parents=("b",)))
    b = Building("b", "Building", np.vstack([comp.vertices, solo.vertices]), objs)
    assert [d.location for d in validate_building(b)] == ["coid=p1|geom=0&&coid=p2|geom=0"]
    far = Building("b", "Building", np.vstack([comp.vertices, solo.vertices + [0, 5, 0]]), objs)
    assert codes(far) == set()


def test_bbox_pairs_in_blocks_equal_brute_force():
    rng = np.random.default_rng(0)
    lo = rng.random((400, 3)) * 10
    hi = lo + rng.random((400, 3))
    brute = np.argwhere(np.triu(np.all((lo[:, None] <= hi[None]) & (lo[None] <= hi[:, None]), axis=2), 1))
    for block in (50, 2_000_000):
        got = bbox_pairs(lo, hi, block=block)
        assert sorted(map(tuple, got.tolist())) == sorted(map(tuple, brute.tolist()))


def test_601_at_real_world_coordinates_and_in_batches():
    rd = np.array([85000.0, 447000.0, 0.0])
    touching = _with_parts([box(6, 5, 7, origin=rd), box(4, 5, 3, origin=rd + [6, 0, 0])], id="t")
    overlapping = _with_parts([box(6, 5, 7, origin=rd + [50, 0, 0]), box(4, 5, 3, origin=rd + [55.5, 1, 0])],
                              id="o")
    single = [{d.code for d in validate_building(b)} for b in (touching, overlapping)]
    assert single == [set(), {601}]
    batched = [{d.code for d in ds} for ds in validate_buildings([touching, overlapping])]
    assert batched == single


@pytest.mark.parametrize("code,polys", [
    (307, lambda: box_polygons(1, 1, 1)[:2] + [[box_polygons(1, 1, 1)[2][0][::-1]]]),
    (305, lambda: box_polygons(1, 1, 1)[:1] + box_polygons(1, 1, 1, origin=(5, 0, 0))[:1]),
    (306, lambda: [[p[0]] for p in building_polys_of(dented_box())]),
])
def test_composite_surface_rules(code, polys):
    b = building_from_polygons(polys(), "CompositeSurface", id="cs")
    assert codes(b) == {code}


def building_polys_of(b: Building):
    sh = b.root.geometries[0].solids[0].shells[0]
    return [[b.vertices[s.outer]] for s in sh.surfaces]
