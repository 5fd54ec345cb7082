"""The neighbour index of the second pass: compressed rows, the same neighbours as one query a building."""
from __future__ import annotations

import numpy as np
import pytest
from shapely import STRtree, box

from lod2energy.neighbours import neighbours_within


def _one_query_a_building(seqs, boxes, halo):
    """The index as it was built before: one STRtree query per building, a dict of sorted lists."""
    tree = STRtree([box(b[0], b[1], b[3], b[4]) for b in boxes])
    out = {}
    for i, (s, b) in enumerate(zip(seqs, boxes)):
        hits = tree.query(box(b[0] - halo, b[1] - halo, b[3] + halo, b[4] + halo))
        out[int(s)] = sorted(int(seqs[j]) for j in hits if j != i)
    return out


@pytest.mark.parametrize("halo, chunk", [(1.0, None), (1.0, 7), (25.0, 50), (0.0, 1)])
def test_neighbours_equal_one_query_a_building(halo, chunk):
    rng = np.random.default_rng(3)
    n = 600
    lo = np.c_[rng.random((n, 2)) * 300, np.zeros(n)]
    lo[::10, :2] = np.round(lo[::10, :2])          # some boxes exactly a halo apart, or touching
    size = np.c_[rng.random((n, 2)) * 12 + 1, rng.random(n) * 20 + 3]
    size[::10, :2] = 1.0
    boxes = np.c_[lo, lo + size]
    seqs = np.sort(rng.choice(10 * n, n, replace=False))   # ascending, with gaps (others, errors)
    want = _one_query_a_building(seqs, boxes, halo)
    got = neighbours_within(seqs, boxes, halo, chunk)
    assert len(got) == n
    assert {int(s): got.of(k) for k, s in enumerate(seqs)} == want
    assert sum(map(len, want.values())) > n // 2  # not a trivial index


def test_neighbours_of_nothing():
    got = neighbours_within([], np.zeros((0, 6)), 1.0)
    assert len(got) == 0
