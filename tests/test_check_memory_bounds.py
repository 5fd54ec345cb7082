"""The vectorised checks examine their candidates a chunk at a time (bounded memory however large
the batch), with the same answers as all at once."""
from __future__ import annotations

import numpy as np
import pytest

import lod2energy.validate.solid as S
from lod2energy.geometry.intersect import bbox_pairs, triangle_pairs_intersect
from lod2energy.io import read
from lod2energy.model import Building
from lod2energy.validate.solid import check_parts_overlap

from conftest import shared_path


def _soup(seed: int, n: int = 400):
    """``n`` random small triangles in a 10 m cube, some sharing vertices (a dense soup with
    every kind of pair: disjoint, crossing, sharing a vertex or an edge, coplanar)."""
    rng = np.random.default_rng(seed)
    V = rng.random((n, 3)) * 10.0
    V = np.vstack([V, np.round(V * 2) / 2])  # snapped copies: coplanar and touching cases
    T = rng.integers(0, len(V), size=(n, 3))
    T = T[(T[:, 0] != T[:, 1]) & (T[:, 1] != T[:, 2]) & (T[:, 0] != T[:, 2])]
    P = V[T]
    pairs = bbox_pairs(P.min(axis=1), P.max(axis=1), pad=0.5)
    return V, T, pairs


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_triangle_pairs_in_chunks_agree_with_all_at_once(seed):
    V, T, pairs = _soup(seed)
    assert len(pairs) > 1000
    whole = triangle_pairs_intersect(V, T, pairs, chunk=len(pairs))
    assert whole.any() and not whole.all()
    for chunk in (97, 1000):
        np.testing.assert_array_equal(triangle_pairs_intersect(V, T, pairs, chunk=chunk), whole)


def test_bbox_pairs_in_blocks_agree_with_one_block():
    rng = np.random.default_rng(5)
    lo = rng.random((3000, 3)) * 100
    hi = lo + rng.random((3000, 3)) * 8
    one = bbox_pairs(lo, hi, block=10 ** 9)
    assert len(one) > 1000
    for block in (1, 333, 4096):
        got = bbox_pairs(lo, hi, block=block)
        assert sorted(map(tuple, got.tolist())) == sorted(map(tuple, one.tolist()))


def test_parts_overlap_in_small_chunks_gives_the_same_verdicts(monkeypatch):
    """Den Haag's buildings with BuildingParts, their planes set against each other's points
    13 values at a time and all at once: the same 601 findings."""
    _, feats = read(str(shared_path("denhaag", "DenHaag_01.city.json")))
    parts = [f for f in feats if isinstance(f, Building) and len(f.objects) > 1][:120]
    assert len(parts) >= 50
    whole = check_parts_overlap(parts)
    monkeypatch.setattr(S, "PLANE_VALUES_CHUNK", 13)
    assert check_parts_overlap(parts) == whole


def test_triangle_pairs_memory_is_bounded_by_the_chunk():
    import tracemalloc
    V, T, pairs = _soup(0)

    def peak(chunk):
        tracemalloc.start()
        triangle_pairs_intersect(V, T, pairs, chunk=chunk)
        top = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        return top / 2 ** 20

    whole, chunked = peak(len(pairs)), peak(4096)
    assert whole > 20 and chunked < whole / 4, (whole, chunked)
