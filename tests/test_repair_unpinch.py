"""Unpinch (part of stage 3): sheets touching at a non-manifold edge or vertex are separated."""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.config import DEFAULT
from lod2energy.polymesh import Face, PolyMesh, signed_volume, topology
from lod2energy.repair.pipeline import repair_building
from lod2energy.repair.unpinch import OFFSET, unpinch
from lod2energy.validate.closed import shell_defects

from test_repair import assert_energy_ready, building

BOX_F = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def _box_v(x0, y0, x1, y1, z1=6.0):
    return [(x0, y0, 0), (x1, y0, 0), (x1, y1, 0), (x0, y1, 0),
            (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]


def two_boxes(b_corner, share):
    """Box A [0,10]x[0,8]x[0,6] and box B from ``b_corner``, in ONE shell; ``share`` maps a
    vertex of B to the vertex of A it coincides with (same index)."""
    va = _box_v(0, 0, 10, 8)
    vb = _box_v(*b_corner)
    V = list(va)
    lut = {}
    for i, p in enumerate(vb):
        if i in share:
            lut[i] = share[i]
        else:
            lut[i] = len(V)
            V.append(p)
    faces = [list(f) for f in BOX_F] + [[lut[i] for i in f] for f in BOX_F]
    return V, faces


def courtyard_pinch():
    """A prism over four rectangles around a courtyard whose corner touches the outside at
    (10, 8): the vertical edge there carries four walls, yet the building is one piece."""
    rects = [[(0, 0), (10, 0), (10, 8), (4, 8), (0, 8)],            # A
             [(0, 8), (4, 8), (4, 16), (0, 16)],                      # D
             [(0, 16), (4, 16), (10, 16), (20, 16), (20, 20), (0, 20)],  # C
             [(10, 8), (20, 8), (20, 16), (10, 16)]]                  # B
    ring = [(0, 0), (10, 0), (10, 8), (4, 8), (4, 16), (10, 16), (10, 8), (20, 8), (20, 20), (0, 20)]
    index: dict = {}
    V: list = []

    def vid(x, y, z):
        k = (x, y, z)
        if k not in index:
            index[k] = len(V)
            V.append(k)
        return index[k]
    faces = []
    for r in rects:
        faces.append([vid(x, y, 6.0) for x, y in r])
        faces.append([vid(x, y, 0.0) for x, y in reversed(r)])
    walls = []
    for i in range(len(ring)):
        (x0, y0), (x1, y1) = ring[i], ring[(i + 1) % len(ring)]
        # boundary edges of the rectangles lie on the ring: split at their vertices
        pts = sorted({(x, y) for r in rects for x, y in r
                      if min(x0, x1) <= x <= max(x0, x1) and min(y0, y1) <= y <= max(y0, y1)
                      and (x - x0) * (y1 - y0) == (y - y0) * (x1 - x0)},
                     key=lambda p: abs(p[0] - x0) + abs(p[1] - y0))
        bottom = [vid(x, y, 0.0) for x, y in pts]
        top = [vid(x, y, 6.0) for x, y in pts]
        walls.append(bottom + top[::-1])
    return V, faces + walls


def edge_pinch():
    # B = [10,20]x[8,16]: it touches A along the vertical edge x=10, y=8 (four faces on it)
    return two_boxes((10, 8, 20, 16), {0: 2, 4: 6})


def vertex_pinch():
    # B = [10,20]x[8,16]x[6,12] would float; use B standing on the ground touching A's top
    # corner only: B = [10,20]x[8,16], height 6, shifted so that only A's corner (10,8,6) and
    # B's corner meet -> take B from z=6 to z=12
    va = _box_v(0, 0, 10, 8)
    vb = [(x, y, z + 6.0) for x, y, z in _box_v(10, 8, 20, 16)]
    V = list(va) + [p for i, p in enumerate(vb) if i != 0]
    lut = {0: 6}
    k = len(va)
    for i in range(1, 8):
        lut[i] = k
        k += 1
    faces = [list(f) for f in BOX_F] + [[lut[i] for i in f] for f in BOX_F]
    return V, faces


def mesh(V, faces):
    return PolyMesh(np.asarray(V, dtype=float), tuple(Face((tuple(f),)) for f in faces))


@pytest.mark.parametrize("make,bridge", [(edge_pinch, False), (courtyard_pinch, False), (vertex_pinch, False),
                                         (vertex_pinch, True)],
                         ids=["edge", "courtyard", "vertex", "vertex-bridge"])
def test_unpinch_makes_a_2manifold_and_moves_only_the_pinch(make, bridge):
    V, faces = make()
    m = mesh(V, faces)
    t = topology(m)
    assert t.nonmanifold or t.nm_vertices, "fixture must be pinched"
    u = unpinch(m, DEFAULT, bridge=bridge)
    assert u is not None
    tu = topology(u)
    assert not tu.nonmanifold and not tu.nm_vertices and not tu.boundary and not tu.misoriented
    moved = np.linalg.norm(u.vertices[: len(V)] - m.vertices, axis=1)
    assert moved.max() == pytest.approx(OFFSET, rel=1e-6)
    assert (moved > 0).sum() <= 2  # the pinch vertices, nothing else
    new = u.vertices[len(V):]
    assert len(new) >= 1
    # every copy sits OFFSET from the original pinch point
    pinch = [m.vertices[i] for i in range(len(V)) if moved[i] > 0]
    for p in new:
        assert min(np.linalg.norm(p - q) for q in pinch) == pytest.approx(OFFSET, rel=1e-6)
    assert signed_volume(u) == pytest.approx(signed_volume(m), rel=5e-3)  # corners moved 8 mm


def test_separated_sheets_do_not_touch():
    V, faces = courtyard_pinch()
    u = unpinch(mesh(V, faces), DEFAULT)
    assert shell_defects([u], DEFAULT) == [[]]


def test_unpinch_none_without_pinch():
    V, faces = _box_v(0, 0, 10, 8), BOX_F
    assert unpinch(mesh(V, faces), DEFAULT) is None


def test_ladder_fixes_pinch_locally():
    V, faces = courtyard_pinch()
    b = building(V, faces)
    r = repair_building(b)
    info = r.provenance["repair"]
    assert 303 in info["defects_before"]
    assert info["stage"] == "refill", info["geometries"][0]["log"]
    assert_energy_ready(r)
    assert info["iou"] >= 0.999
    assert info["mean_displacement"] <= OFFSET
    assert info["hausdorff"] <= 2 * OFFSET
