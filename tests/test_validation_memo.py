"""The validation memory: a verdict is reused only for the very same geometry, never for another."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.io import read
import lod2energy.records  # noqa: F401 - makes Building picklable
from lod2energy.model import Building
from lod2energy import cache
from lod2energy.validate import checks, memo

from conftest import shared_path
from factories import box, flipped_wall, open_box


@pytest.fixture(autouse=True)
def _empty_memory():
    memo.forget()
    yield
    memo.forget()


def _count_validations(monkeypatch) -> list[int]:
    seen = []
    real = checks._validate_all

    def counting(bs, tol):
        seen.append(len(bs))
        return real(bs, tol)
    monkeypatch.setattr(checks, "_validate_all", counting)
    return seen


def test_the_same_geometry_is_validated_once_and_gets_the_same_verdict(monkeypatch):
    seen = _count_validations(monkeypatch)
    b = open_box()
    first = checks.validate_building(b, DEFAULT)
    again = checks.validate_building(b, DEFAULT)
    assert first and first == again
    assert seen == [1]
    # a copy with equal arrays is the same geometry
    twin = pickle.loads(pickle.dumps(b))
    assert checks.validate_building(twin, DEFAULT) == first and seen == [1]


def test_another_geometry_tolerance_or_id_is_validated_again(monkeypatch):
    seen = _count_validations(monkeypatch)
    b = box()
    assert checks.validate_building(b, DEFAULT) == []
    moved = b.vertices.copy()
    moved[0, 2] += 0.5  # one vertex moved: the face is no longer planar
    bent = Building(b.id, b.type, moved, b.objects, b.provenance)
    assert checks.validate_building(bent, DEFAULT) != []
    assert checks.validate_building(b, Tolerances(snap_tol=0.01)) == []
    assert seen == [1, 1, 1]
    flipped = flipped_wall()
    assert {d.code for d in checks.validate_building(flipped, DEFAULT)} and seen[-1] == 1


def test_verdicts_travel_with_a_spooled_building_and_are_used_only_for_its_geometry(monkeypatch):
    b = open_box()
    verdict = checks.validate_building(b, DEFAULT)
    carried = memo.carry(box(id="carrier"), [(b, verdict)], DEFAULT)
    blob = pickle.dumps(carried)
    memo.forget()  # another process
    seen = _count_validations(monkeypatch)
    memo.learn(pickle.loads(blob))
    assert checks.validate_building(b, DEFAULT) == verdict and seen == []
    assert checks.validate_building(box(), DEFAULT) == [] and seen == [1]


def test_the_memory_is_bounded(monkeypatch):
    monkeypatch.setattr(memo, "MAX_ENTRIES", 3)
    for dx in (1.0, 2.0, 3.0, 4.0, 5.0):
        checks.validate_building(box(dx=dx), DEFAULT)
    assert cache.sizes()[memo.BUILDINGS][0] == 3


def test_batched_validation_with_the_memory_equals_validation_without_it_on_a_real_tile():
    _, feats = read(str(shared_path("3dbag", "tile5908_subset_ext.city.jsonl")))
    bs = [f for f in feats if isinstance(f, Building)][:40]
    plain = checks._validate_all(bs, DEFAULT)
    half = checks.validate_buildings(bs[::2], DEFAULT)  # half of them remembered first
    mixed = checks.validate_buildings(bs, DEFAULT)
    assert mixed == plain and half == plain[::2]
    assert any(plain)  # the tile has invalid buildings: the verdicts compared are not all empty
