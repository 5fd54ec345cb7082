"""The repair's volume check: a hollow result (under a quarter of the input's convex hull, the
input not itself thin) goes further up the ladder or is reported."""
from __future__ import annotations

import numpy as np
import pytest

from factories import box_polygons, building_from_polygons
from lod2energy.repair import pipeline
from lod2energy.polymesh import Face, PolyMesh, signed_volume
from lod2energy.repair.plausible import hollow
from lod2energy.repair.pipeline import mesh_of_geometry, repair_building

T = 0.2  # wall thickness of the skin, m


def rev(poly):
    return [np.asarray(poly[0], float)[::-1]]


def skin() -> list:
    """A double-sided skin: the four walls of a 10 x 8 x 6 m box modelled on both sides
    (outer faces out, inner faces 0.2 m inside, facing in), no roof, no ground."""
    outer = box_polygons(10, 8, 6)[2:]
    inner = [rev(p) for p in box_polygons(10 - 2 * T, 8 - 2 * T, 6, (T, T, 0))[2:]]
    return outer + inner


def mesh(polys) -> PolyMesh:
    verts, faces, index = [], [], {}
    for k, poly in enumerate(polys):
        rings = []
        for ring in poly:
            r = []
            for p in np.asarray(ring, float):
                key = tuple(p)
                if key not in index:
                    index[key] = len(verts)
                    verts.append(p)
                r.append(index[key])
            rings.append(tuple(r))
        faces.append(Face(tuple(rings), k, None))
    return PolyMesh(np.array(verts), tuple(faces))


def cup() -> PolyMesh:
    """What wrapping the skin from both sides gives: a thin-walled open-topped body (the box
    minus a 9.6 x 7.6 x 5.8 m cavity open at the top), a valid closed solid of 56.8 m3."""
    o = box_polygons(10, 8, 6)
    i = box_polygons(10 - 2 * T, 8 - 2 * T, 6 - T, (T, T, T))
    rim = [o[1][0], np.asarray(i[1][0])[::-1]]                  # the top, with the cavity as hole
    return mesh([o[0]] + [rim] + o[2:] + [rev(p) for p in i[2:]] + [rev(i[0])])


def test_a_thin_walled_body_is_hollow_for_a_skin_and_a_box_is_not():
    m_in = mesh(skin())
    c = cup()
    assert signed_volume(c) == pytest.approx(480 - 9.6 * 7.6 * 5.8)
    assert "hollow" in hollow(m_in, c)
    assert hollow(m_in, mesh(box_polygons(10, 8, 6))) is None


def test_thin_inputs_and_concave_closed_inputs_are_not_hollow():
    slab = mesh(box_polygons(10, 0.1, 6))                       # a free-standing wall
    assert hollow(slab, slab) is None
    assert hollow(mesh(skin()), cup(), input_volume=60.0) is None   # the input is that small itself


def test_a_hollow_ladder_result_escalates_up_the_ladder(monkeypatch):
    b = building_from_polygons(skin(), "MultiSurface", id="skin")
    monkeypatch.setattr(pipeline, "ladder", lambda m, lod, tol, deadline: ("refill", cup(), ["refill: ok"]))
    rb = repair_building(b, timeout=20)
    r = rb.provenance["repair"]
    (g,) = [g for o in rb.objects for g in o.geometries]
    v = signed_volume(mesh_of_geometry(rb.vertices, g))
    assert r["stage"] in ("roofs", "alphashape", "footprint", "hull")
    assert v >= 0.25 * 480
    log = " ".join(r["geometries"][0]["log"])
    assert "refill: hollow result: 56.83 m3" in log and f"escalated to {r['stage']}" in log


def test_a_result_that_is_not_hollow_is_kept(monkeypatch):
    b = building_from_polygons(skin(), "MultiSurface", id="skin")
    box = mesh(box_polygons(10, 8, 6))
    monkeypatch.setattr(pipeline, "ladder", lambda m, lod, tol, deadline: ("refill", box, ["refill: ok"]))
    r = repair_building(b, timeout=20).provenance["repair"]
    assert r["stage"] == "refill" and "hollow" not in " ".join(r["geometries"][0]["log"])
