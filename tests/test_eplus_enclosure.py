"""EnergyPlus's zone enclosure test, emulated (lod2energy.energy.enclosure), and what the IDF
writer does with a zone that fails it (slivers, vertex merges, simpler envelopes).

The emulation's verdicts are compared with EnergyPlus itself in test_energyplus_run.py.
"""
from __future__ import annotations

import numpy as np
import pytest

from export_helpers import energy_ready, write_idf
from factories import box, box_polygons, building_from_polygons, BOX_SEMANTICS

from lod2energy import energy
import lod2energy.energy.surfaces  # noqa: F401 - energy.surfaces
import lod2energy.energy.pieces  # noqa: F401 - energy.pieces
import lod2energy.energy.enclosure  # noqa: F401 - energy.enclosure
import lod2energy.energy.conform  # noqa: F401 - energy.conform
from lod2energy.exporters import energyplus

from lod2energy.energy.zones import shells as zones
from lod2energy.geometry.polygons import polygon_area3d
from lod2energy.validate.closed import check_closed_outward
from lod2energy.energy.enclosure import (_edges_not_two, enclosure_defects, snap_polygons,
                                       unique_vertices)
from lod2energy.energy import fallback as zone_fallback
from lod2energy.energy import model as energy_model


def _box() -> list[np.ndarray]:
    return [np.asarray(p[0], dtype=float) for p in box_polygons()]


def sliver_ground_box(w: float) -> list[np.ndarray]:
    """A closed 10 x 8 x 6 m box whose ground is cut into a quad and a 10 m long triangle
    ``w`` wide at its end; the east wall carries the triangle's corner on its bottom edge."""
    P = _box()
    quad = np.array([[0, 0, 0], [0, 8, 0], [10, 8, 0], [10, w, 0]], dtype=float)
    tri = np.array([[0, 0, 0], [10, w, 0], [10, 0, 0]], dtype=float)
    east = np.array([[10, 0, 0], [10, w, 0], [10, 8, 0], [10, 8, 6], [10, 0, 6]], dtype=float)
    return [quad, tri, P[1], P[2], east, P[4], P[5]]


def test_closed_box_is_enclosed():
    assert enclosure_defects(_box()) == []
    assert len(unique_vertices(_box())) == 8


def test_missing_face_is_not_enclosed():
    bad = enclosure_defects(_box()[:-1])
    assert len(bad) == 4 and all(e.count == 1 for e in bad)


def test_t_junction_is_enclosed_in_the_second_count():
    # the south wall cut in two at x = 5: ground and roof keep the whole edge
    P = _box()
    south = [np.array([[0, 0, 0], [5, 0, 0], [5, 0, 6], [0, 0, 6]], float),
             np.array([[5, 0, 0], [10, 0, 0], [10, 0, 6], [5, 0, 6]], float)]
    polys = [P[0], P[1]] + south + P[3:]
    assert _edges_not_two(polys, 0.0127)          # the first count fails ...
    assert enclosure_defects(polys) == []         # ... EnergyPlus inserts (5, 0, z) and passes


@pytest.mark.parametrize("shift,enclosed", [(0.008, True), (0.012, True), (0.02, False)])
def test_corners_merge_within_half_an_inch_per_axis(shift, enclosed):
    # one roof corner moved in x only in the roof polygon: EnergyPlus merges it with the
    # walls' corner when |dx| < 0.0127 m
    P = _box()
    roof = P[1].copy()
    roof[2, 0] += shift
    assert (enclosure_defects([P[0], roof] + P[2:]) == []) is enclosed


@pytest.mark.parametrize("w,enclosed", [(0.005, False), (0.01, False), (0.02, True)])
def test_sliver_pieces_narrower_than_the_tolerance_fail(w, enclosed):
    polys = sliver_ground_box(w)
    assert check_closed_outward(polys) == []       # a closed, outward 2-manifold ...
    assert (enclosure_defects(polys) == []) is enclosed   # ... that EnergyPlus may reject


def test_snap_drops_slivers_and_folds():
    polys = sliver_ground_box(0.004)
    out = snap_polygons(polys, merge=False)
    assert 1 not in [i for i, _ in out]            # the 4 mm sliver triangle is gone
    assert enclosure_defects([q for _, q in out]) == []
    # a polygon and its reverse (a fold) cancel
    P = _box()
    fold = np.array([[2, 2, 6], [3, 2, 6], [3, 3, 6]], float)
    out = snap_polygons(P + [fold, fold[::-1]], merge=False)
    assert len(out) == 6


def test_near_collinear_chain_is_not_cut_into_slivers():
    # an L-shaped floor whose long side has corners 0.3 mm and 2 mm off its line:
    # earcut + Hertel-Mehlhorn would cut triangles a few mm wide along it
    ring = np.array([[0, 0, 0], [0, 6, 0], [4, 6, 0], [4, 3, 0], [12, 3.0003, 0], [16, 3.002, 0],
                     [20, 3, 0], [20, 0, 0]], dtype=float)[::-1]
    n = np.array([0, 0, -1.0])
    pieces = energy.pieces._pieces_from_points(ring, [len(ring)], n, ring.mean(axis=0))
    assert sum(polygon_area3d(p) for p in pieces) == pytest.approx(polygon_area3d(ring), rel=1e-9)
    used = {tuple(np.round(x, 6)) for p in pieces for x in p}
    assert used == {tuple(np.round(x, 6)) for x in ring}   # every corner kept (no T-junction)
    for p in pieces:
        q, k = p, len(p)
        # no piece has a vertex EnergyPlus would put on another of its edges
        assert not any(energy.conform._on_segment(q[i], q[(i + 1) % k], q[j])
                       for i in range(k) for j in range(k) if j not in (i, (i + 1) % k))


def test_writer_fixes_a_sliver_zone(tmp_path):
    # the 1 cm sliver box as a building: the written IDF passes the emulated test
    b = energy_ready(building_from_polygons([[p] for p in sliver_ground_box(0.01)], "Solid",
                                            ["GroundSurface", "GroundSurface"] + BOX_SEMANTICS[1:], id="sliver"))
    res = write_idf([b], tmp_path, energyplus.options.IdfOptions())
    assert res[0].ok, res[0].problems
    assert energyplus.check.self_check(res[0].path) == []


def test_fallback_block_keeps_footprint_height_and_u_values():
    b = energy_ready(box())
    z = zones.zone_shells(b, np.zeros(3))[0]
    nz = zone_fallback.block_zone(z)
    assert nz is not None and "LoD1 block" in nz.warnings[-1]
    pieces = energy.surfaces.zone_pieces(nz, 0, {}, False)
    pts = [p.points for p in pieces]
    assert check_closed_outward(pts) == [] and enclosure_defects(pts) == []
    area = {k: sum(polygon_area3d(p.points) for p in pieces if p.kind == k) for k in ("roof", "wall", "ground")}
    assert area["roof"] == pytest.approx(80.0) and area["ground"] == pytest.approx(80.0)
    assert area["wall"] == pytest.approx(2 * (10 + 8) * 6.0)
    u = {f.kind: f.u_value for f in z.faces}
    assert {f.kind: f.u_value for f in nz.faces} == u


def test_zone_that_fails_gets_a_simpler_envelope(monkeypatch):
    # a zone whose written pieces the emulation rejects is replaced by the first fallback
    # envelope that passes, with a warning saying so
    b = energy_ready(box())
    z = zones.zone_shells(b, np.zeros(3))[0]
    pieces = energy.surfaces.zone_pieces(z, 0, {}, False)
    original = {id(p.points) for p in pieces}
    real = energy.enclosure.enclosure_defects

    def reject_original(polys, *a, **k):
        return ["x"] if {id(p) for p in polys} == original else real(polys, *a, **k)
    monkeypatch.setattr(energy_model, "enclosure_defects", reject_original)
    nz, np_, how = energy_model.enclosable(z, 0, pieces)
    assert "fails EnergyPlus's enclosure test" in nz.warnings[-1] and how in ("roof_zone", "block_zone")
    assert real([p.points for p in np_]) == []
    assert energy_model.enclosable(z, 0, np_) is None        # pieces that pass are kept as they are


def test_cleared_zone_moves_a_near_miss_off_the_edge():
    # a corner 7 mm from an edge it is not on (two walls drawn a few mm apart): EnergyPlus
    # would insert it into that edge; it moves 1.6 cm clear, nothing else moves
    from lod2energy.energy.zones.shells import ZoneFace, ZoneShell

    V = np.array([[0, 0, 0], [10, 0, 0], [10, 1, 0], [5, 0.007, 0], [6, 1, 0], [5, 1, 0]], dtype=float)
    faces = (ZoneFace(((0, 1, 2),), "ground", None, 0.3, 0), ZoneFace(((3, 4, 5),), "ground", None, 0.3, 1))
    z = ZoneShell("b", "b", V, faces, 2.8, 0.0)
    nz = zone_fallback.cleared_zone(z)
    assert nz is not None and "moved" in nz.warnings[-1]
    assert np.linalg.norm(nz.vertices[3] - [5, 0, 0]) == pytest.approx(zone_fallback.CLEARANCE)
    assert nz.vertices[3][1] > 0.007                    # away from the edge, on its own side
    assert np.array_equal(np.delete(nz.vertices, 3, axis=0), np.delete(V, 3, axis=0))
    assert zone_fallback.cleared_zone(nz) is None       # nothing left to clear


def _stepped_wall(lean: float) -> np.ndarray:
    """A 10 m wall whose bottom edge has a 0.5 m step up at x = 5 m, leaning ``lean`` m over 3 m."""
    return np.array([[0, 0, 0], [5, 0, 0.5], [10, 0, 0], [10, lean, 3], [0, lean, 3]], float)


def test_energyplus_finds_collinear_points_in_its_projection_plane():
    from lod2energy.energy.enclosure import eplus_collinear, eplus_vertices
    # 0.04 degrees off vertical: EnergyPlus projects on XY, where the step's corner is collinear
    assert eplus_collinear([_stepped_wall(0.002)])[0] == [1]
    assert len(eplus_vertices([_stepped_wall(0.002)])[0]) == 4
    # exactly vertical: projected on XZ, the corner is a corner
    assert eplus_collinear([_stepped_wall(0.0)])[0] == []
    # a point on a straight edge is dropped in either case
    straight = np.array([[0, 0, 0], [5, 0, 0], [10, 0, 0], [10, 0, 3], [0, 0, 3]], float)
    assert eplus_collinear([straight])[0] == [1]


def test_keep_corners_fans_a_piece_energyplus_would_strip():
    from lod2energy.energy.enclosure import eplus_vertices
    wall = _stepped_wall(0.002)
    piece = energy.pieces.Piece(wall, "wall", "Outdoors", 1.0, 0)
    out = energy.conform.keep_corners([piece])
    assert len(out) == 5 and all(len(p.points) == 3 for p in out)
    assert all(len(eplus_vertices([p.points])[0]) == 3 for p in out)
    assert sum(polygon_area3d(p.points) for p in out) == pytest.approx(polygon_area3d(wall))
    # every corner of the wall is still written
    corners = np.vstack([p.points for p in out])
    assert all(np.min(np.linalg.norm(corners - w, axis=1)) < 1e-9 for w in wall)
    # a piece EnergyPlus keeps whole is left alone
    plain = energy.pieces.Piece(_stepped_wall(0.0), "wall", "Outdoors", 1.0, 0)
    assert energy.conform.keep_corners([plain]) == [plain]


def test_energyplus_drops_a_spike_in_its_projection_plane():
    """A 4 cm wall of a 3 cm column (real Delfshaven case): projected on XY it doubles back
    at its last vertex, which EnergyPlus removes as collinear (the sine of the turn is 0)."""
    from lod2energy.energy.enclosure import eplus_collinear
    wall = np.array([[1.745, 7.698, 6.8552], [1.7326, 7.698, 6.8307], [1.745, 7.7156, 6.8153],
                     [1.745, 7.728, 6.8343]])
    assert eplus_collinear([wall])[0] == [3]
    # a vertical edge projects to a point on XY: its ends have no turn there and are kept
    # (a real Delfshaven wall; EnergyPlus removed none of its vertices)
    vertical = np.array([[13.026, 23.851, 4.825], [20.599, 5.663, 0.0], [11.8, 26.798, 0.0],
                         [11.8, 26.798, 4.825]])
    assert eplus_collinear([vertical])[0] == []
    piece = energy.pieces.Piece(wall, "wall", "Outdoors", 1.0, 0)
    assert all(len(p.points) == 3 for p in energy.conform.keep_corners([piece]))


def test_pieces_are_checked_as_written():
    """Every piece leaves zone_pieces rounded to the written precision: the emulated tests
    see the coordinates EnergyPlus reads."""
    b = energy_ready(box(10.00004, 8.00007, 6.00002))
    zs = zones.zone_shells(b, np.zeros(3), None)
    pcs = energy.surfaces.zone_pieces(zs[0], 0, {}, True)
    assert pcs and all(np.array_equal(p.points, np.round(p.points, energy.pieces.WRITE_DECIMALS)) for p in pcs)
    assert any(np.any(np.abs(p.points - 10.00004) < 1e-3) for p in pcs)


def test_triangle_collinear_in_projection_is_degenerate_for_energyplus():
    """A near-vertical sliver triangle (real Delfshaven wall): EnergyPlus projects it on XY,
    finds a vertex collinear and, with 3 sides only, calls it degenerate (a severe error).
    The writer fans it; the self-check flags such a surface."""
    from lod2energy.energy.enclosure import eplus_collinear, eplus_degenerate
    tri = np.array([[4.207, 18.371, 9.367], [7.1675, 31.623, 0.0], [4.209, 18.38, 0.0]])
    assert eplus_collinear([tri])[0] == [1]
    assert eplus_degenerate([tri])[0]
    assert not eplus_degenerate([np.array([[0, 0, 0], [1, 0, 0], [0, 0, 1.0]])])[0]
    out = energy.conform.keep_corners([energy.pieces.Piece(tri, "wall", "Outdoors", 1.0, 0)])
    assert out and not any(eplus_degenerate([p.points])[0] for p in out)


def test_out_of_plane_piece_is_written_as_triangles():
    """A roof quad with one corner 4 cm up (1 cm off its Newell plane; EnergyPlus reports 1 cm
    "out of line" as a severe error) becomes planar triangles."""
    quad = np.array([[0, 0, 10.0], [8, 0, 10.0], [8, 6, 10.04], [0, 6, 10.0]])
    out = energy.conform.keep_corners([energy.pieces.Piece(quad, "roof", "Outdoors", 1.0, 0)])
    assert len(out) == 4 and all(len(p.points) == 3 for p in out)
    assert sum(polygon_area3d(p.points) for p in out) == pytest.approx(polygon_area3d(quad), rel=1e-3)
    flat = energy.pieces.Piece(np.array([[0, 0, 10.0], [8, 0, 10.0], [8, 6, 10.0], [0, 6, 10.0]]), "roof", "Outdoors", 1.0, 0)
    assert energy.conform.keep_corners([flat]) == [flat]
