"""The readers' one-pass checks of number lists answer as the item-by-item loops they skip.

``io.shape._plain_numbers`` (the leaves of the JSON shape walk) and ``_Collector.ring`` (vertex
indices of a CityJSON ring) take lists of exact ints / floats in one C pass; on anything else
they fall back to the loop. The references below are the loops as they were, compared on random
lists holding bools, None, strings, int subclasses, huge integers, inf, NaN and values that
overflow a sum.
"""
from __future__ import annotations

import enum
import math

import numpy as np
import pytest

from lod2energy.errors import InputError
from lod2energy.io import cityjson, shape


def _ref_plain_numbers(v):
    for x in v:
        t = type(x)
        if t is int:
            if x > shape.MAX_NUMBER or x < -shape.MAX_NUMBER:
                return False
        elif t is float:
            if x - x != 0.0:
                return False
        else:
            return False
    return True


class _Small(enum.IntEnum):
    ONE = 1


_ODD = [True, False, None, "3", [1], {}, _Small.ONE, math.inf, -math.inf, math.nan, 10 ** 400, -10 ** 400,
        1.7e308, -1.7e308, 0.0, -0.0, 2 ** 63, 5e-324]


def _lists(seed: int, count: int):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        n = int(rng.integers(0, 12))
        kind = int(rng.integers(0, 3))
        if kind == 0:
            v = [int(x) for x in rng.integers(-50, 50, n)]
        else:
            v = [float(x) for x in rng.standard_normal(n) * 10.0 ** float(rng.uniform(-5, 307))]
        if n and rng.random() < 0.5:
            v[int(rng.integers(0, n))] = _ODD[int(rng.integers(0, len(_ODD)))]
        if n and kind == 2 and rng.random() < 0.5:  # ints and floats mixed
            v[int(rng.integers(0, n))] = int(rng.integers(-9, 9))
        yield v


@pytest.mark.parametrize("seed", range(4))
def test_plain_numbers_is_the_loop(seed):
    seen = set()
    for v in _lists(seed, 3000):
        got = shape._plain_numbers(v)
        assert got is _ref_plain_numbers(v), v
        seen.add(got)
    assert seen == {True, False}


def test_plain_numbers_overflowing_sum_falls_back():
    v = [1.7e308, 1.7e308]  # each finite, their sum inf: the loop decides (True)
    assert shape._plain_numbers(v) is True
    assert shape._plain_numbers([1.0, math.nan]) is False
    assert shape._plain_numbers([math.inf, -math.inf]) is False
    assert shape._plain_numbers([]) is True


def _ref_ring(col, ring, where):
    if not isinstance(ring, list):
        raise InputError(f"{where}: a ring must be an array of vertex indices")
    for i in ring:
        if not isinstance(i, int) or isinstance(i, bool):
            raise InputError(f"{where}: vertex index {i!r} is not an integer")
        if i < 0 or i >= col.n:
            raise InputError(f"{where}: vertex index {i} out of range (file has {col.n} vertices)")
    col.used.extend(ring)
    return ring


def _ring_outcome(f, col, ring):
    try:
        return f(col, ring, "o|g=0"), list(col.used)
    except InputError as e:
        return str(e), list(col.used)


@pytest.mark.parametrize("seed", range(4))
def test_collector_ring_is_the_loop(seed):
    rng = np.random.default_rng(seed)
    odd = [True, 1.0, None, "1", -1, 20, 19, 0, _Small.ONE, 10 ** 30]
    errors = 0
    for _ in range(3000):
        ring = [int(x) for x in rng.integers(0, 20, int(rng.integers(0, 8)))]
        if ring and rng.random() < 0.4:
            ring[int(rng.integers(0, len(ring)))] = odd[int(rng.integers(0, len(odd)))]
        got = _ring_outcome(cityjson._Collector.ring, cityjson._Collector(20), ring)
        want = _ring_outcome(_ref_ring, cityjson._Collector(20), ring)
        assert got == want, ring
        errors += isinstance(got[0], str)
    assert 200 < errors < 2800
    assert _ring_outcome(cityjson._Collector.ring, cityjson._Collector(5), (1, 2))[0].endswith(
        "a ring must be an array of vertex indices")
