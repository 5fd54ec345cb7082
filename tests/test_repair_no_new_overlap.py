"""Repair never creates a BuildingPart overlap (601, issue 38 item 2): a repaired part that
overlaps its neighbour where the input did not, and cannot be separated from it, is a failed
candidate, refused with the reason."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import shared_path
from lod2energy.config import DEFAULT
from lod2energy.io import read
from lod2energy.model import Building, CityObject, Geometry, Shell, Solid, Surface
from lod2energy.repair import parts
from lod2energy.repair.pipeline import repair_building
from lod2energy.validate.checks import validate_building


def _prism(footprint, h: float, flip: int | None = None) -> list[list[tuple[float, float, float]]]:
    """Faces (rings of points) of a vertical prism over a counter-clockwise ``footprint``, m;
    ``flip``: index of a wall turned inside out (307)."""
    fp = [(float(x), float(y)) for x, y in footprint]
    faces = [[(x, y, 0.0) for x, y in reversed(fp)], [(x, y, h) for x, y in fp]]
    for i, (p, q) in enumerate(zip(fp, fp[1:] + fp[:1])):
        w = [(p[0], p[1], 0.0), (q[0], q[1], 0.0), (q[0], q[1], h), (p[0], p[1], h)]
        faces.append(w[::-1] if i == flip else w)
    return faces


def l_and_notch() -> Building:
    """Part ``L`` (an L-shaped 10 x 10 m prism, 6 m high, one wall flipped: invalid) and part
    ``notch`` (the 5 x 5 m box in the L's notch, sharing its two walls): no overlap. The convex
    hull of ``L`` fills the notch."""
    verts, index = [], {}

    def geom(faces):
        surfs = []
        for f in faces:
            ring = []
            for p in f:
                index.setdefault(p, len(verts))
                if index[p] == len(verts):
                    verts.append(p)
                ring.append(index[p])
            surfs.append(Surface.from_lists([ring]))
        return Geometry("Solid", "2", (Solid((Shell(tuple(surfs)),)),))

    ell = geom(_prism([(0, 0), (10, 0), (10, 10), (5, 10), (5, 5), (0, 5)], 6.0, flip=0))
    notch = geom(_prism([(0, 5), (5, 5), (5, 10), (0, 10)], 6.0))
    objs = (CityObject("B", "Building", (), {}, (), ("L", "notch")),
            CityObject("L", "BuildingPart", (ell,), {}, ("B",)),
            CityObject("notch", "BuildingPart", (notch,), {}, ("B",)))
    return Building("B", "Building", np.array(verts, dtype=float), objs)


def _n601(b: Building) -> int:
    return sum(code == 601 for _, code, _ in parts.check_parts_overlap([b], DEFAULT)[0])


def test_the_hull_of_a_part_would_overlap_its_neighbour():
    b = l_and_notch()
    assert _n601(b) == 0 and {d.code for d in validate_building(b)} == {307}
    rb = repair_building(b, DEFAULT, timeout=0.0)  # straight to the convex hull
    rec = rb.provenance["repair"]
    assert _n601(rb) == 0
    assert rec["parts_overlap"]["created"] and not rec["parts_overlap"]["left"]


def test_a_repair_making_an_overlap_it_cannot_undo_is_refused(monkeypatch):
    b = l_and_notch()
    monkeypatch.setattr(parts, "_snap_back", lambda m, other, *a, **k: None)
    monkeypatch.setattr(parts, "_clip_by", lambda m, other, *a, **k: None)
    rb = repair_building(b, DEFAULT, timeout=0.0)
    rec = rb.provenance["repair"]
    assert _n601(rb) == 0                                 # no overlap made by the repair
    assert rec["parts_overlap"]["left"]
    (ell,) = [e for e in rec["geometries"] if e["object"] == "L"]
    assert ell["stage"] == "irreparable" and "601" in ell["error"] and ell["iou"] is None
    assert rb.object_index["L"].geometries[0] == b.object_index["L"].geometries[0]
    assert rec["stage"] == "irreparable" and "601" in rec["error"]


@pytest.mark.parametrize("rel", [("citygml-real", "nrw", "LoD2_32_280_5657_1_NW.gml")])
def test_real_tile_no_building_gains_601(rel):
    _, feats = read(str(shared_path(*rel)))
    n = 0
    for b in feats:
        if not isinstance(b, Building) or sum(o.type == "BuildingPart" for o in b.objects) < 2:
            continue
        rb = repair_building(b, DEFAULT)
        if rb is b:
            continue
        n += 1
        assert _n601(rb) <= _n601(b), b.id
    assert n > 0
