"""The ``roofs`` stage: a building rebuilt as the union of prisms under its roof faces."""
from __future__ import annotations

import numpy as np
import pytest

from factories import gabled_house
from lod2energy.config import DEFAULT
from lod2energy.repair._mesh import Face, PolyMesh, signed_volume
from lod2energy.repair.footprint import extrude_roofs, ground_level
from lod2energy.repair.pipeline import STAGES, GLOBAL, is_repaired, mesh_of_geometry, roof_model


def house_mesh():
    b = gabled_house()
    return mesh_of_geometry(b.vertices, b.root.geometries[0])


def test_gabled_house_rebuilt_exactly():
    m = house_mesh()
    r = extrude_roofs(m)
    assert r is not None
    # 10 x 8 x 6 box plus the roof prism 10 x 8 x 3 / 2
    assert signed_volume(r) == pytest.approx(10 * 8 * 6 + 10 * 8 * 3 / 2, rel=1e-6)
    assert is_repaired(roof_model(m, "2", DEFAULT), "2", DEFAULT)


def test_crossing_basement_walls_are_cut_at_the_ground():
    """A house whose ground face sits at z=0 while two walls reach down to z=-2 (as in
    3DBAG tiles): the walls cross the ground face (306); the roof model starts at the
    ground level and keeps the roofs."""
    m = house_mesh()
    V = m.vertices.copy()
    extra = np.array([[0, 0, -2.0], [10, 0, -2.0]])
    V2 = np.vstack([V, extra])
    n = len(V)
    faces = list(m.faces)
    # the south wall (ground corners 0,1 in the factory's order) now goes down to z=-2
    south = [i for i, f in enumerate(faces) if np.allclose(V[list(f.outer)][:, 1], 0)]
    assert south
    f = faces[south[0]]
    ring = [i for i in f.outer]
    low = [k for k, i in enumerate(ring) if V[i, 2] == 0]
    ring2 = list(ring)
    ring2[low[0]] = n + (0 if V[ring[low[0]], 0] == 0 else 1)
    ring2[low[1]] = n + (0 if V[ring[low[1]], 0] == 0 else 1)
    faces[south[0]] = Face((tuple(ring2),), f.source, f.semantic)
    bad = PolyMesh(V2, tuple(faces))
    assert ground_level(bad) == pytest.approx(0.0, abs=1e-9)
    r = extrude_roofs(bad)
    assert r is not None
    used = np.unique([i for f in r.faces for ring in f.rings for i in ring])
    assert r.vertices[used, 2].min() == pytest.approx(0.0, abs=1e-6)
    assert signed_volume(r) == pytest.approx(10 * 8 * 6 + 10 * 8 * 3 / 2, rel=1e-6)  # nothing below z=0
    # on this tiny house the two buried corners are 2 of 12 vertices, 2 m away: on average
    # the input is more than ROOF_MODEL_MAX_DISPLACEMENT from the model, which is refused
    assert roof_model(bad, "2", DEFAULT) is None


def test_roofs_is_a_global_stage_before_alpha():
    assert "roofs" in GLOBAL
    assert STAGES.index("refill") < STAGES.index("roofs") < STAGES.index("alphashape")


def test_no_roof_no_model():
    m = house_mesh()
    walls_only = m.with_faces([f for f in m.faces if abs(np.ptp(m.vertices[list(f.outer)][:, 2])) > 1])
    # the roofs and the ground are gone: only the walls are left, nothing to extrude
    assert extrude_roofs(walls_only.with_faces([f for f in walls_only.faces
                                                if np.ptp(m.vertices[list(f.outer)][:, 0]) < 1e-9
                                                or np.ptp(m.vertices[list(f.outer)][:, 1]) < 1e-9])) is None
