"""The geometry-level validation memory: the same answer as checking afresh, never a stale one."""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.config import DEFAULT, Tolerances
from lod2energy import cache
from lod2energy.validate import checks, memo

from factories import box, flipped_wall, open_box


@pytest.fixture(autouse=True)
def _empty_memory():
    memo.forget()
    yield
    memo.forget()


def _geoms(b):
    return [(o.id, gi, g) for o in b.objects for gi, g in enumerate(o.geometries) if g.is_polygonal]


@pytest.mark.parametrize("make", [box, open_box, flipped_wall])
def test_remembered_answer_equals_a_fresh_check(make):
    b = make()
    for coid, gi, g in _geoms(b):
        fresh = checks._validate_entries([(b.vertices, coid, gi, g)], DEFAULT)[0]
        assert checks.validate_geometry(b.vertices, coid, gi, g, DEFAULT) == fresh
        assert checks.validate_geometry(b.vertices, coid, gi, g, DEFAULT) == fresh  # from memory


def test_moved_vertices_are_checked_again():
    b = box()
    (coid, gi, g), = _geoms(b)[:1]
    v = np.array(b.vertices, dtype=float)
    assert checks.validate_geometry(v, coid, gi, g, DEFAULT) == []
    # the same geometry over other coordinates (a new array: the polygon checks' own cache in
    # lod2energy.validate.polygon is keyed by the array's identity), one vertex moved
    moved = v.copy()
    moved[0, 2] += 0.5
    assert {d.code for d in checks.validate_geometry(moved, coid, gi, g, DEFAULT)}
    assert checks.validate_geometry(v, coid, gi, g, DEFAULT) == []


def test_other_id_index_or_tolerance_is_not_the_remembered_geometry():
    b = open_box()
    (coid, gi, g), = _geoms(b)[:1]
    first = checks.validate_geometry(b.vertices, coid, gi, g, DEFAULT)
    assert first
    other = checks.validate_geometry(b.vertices, "other-id", gi + 1, g, DEFAULT)
    assert [d.code for d in other] == [d.code for d in first]
    assert all("other-id" in d.location and f"geom={gi + 1}" in d.location for d in other)
    loose = Tolerances(snap_tol=0.01)
    assert checks.validate_geometry(b.vertices, coid, gi, g, loose) == \
        checks._validate_entries([(b.vertices, coid, gi, g)], loose)[0]
    assert memo.entry_key(b.vertices, coid, gi, g, DEFAULT) != memo.entry_key(b.vertices, coid, gi, g, loose)


def test_memory_is_bounded(monkeypatch):
    monkeypatch.setattr(memo, "MAX_ENTRIES", 3)
    b = box()
    (coid, gi, g), = _geoms(b)[:1]
    for k in range(10):
        checks.validate_geometry(b.vertices + k, coid, gi, g, DEFAULT)
        assert cache.sizes()[memo.GEOMETRIES][0] <= 3
