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


# ----------------------------------------------------------------------------- value_problem's bulk pass

def _ref_value_problem(value, max_depth=shape.MAX_DEPTH):
    """``io.shape.value_problem`` as it was before its bulk pass (the walk alone)."""
    from collections.abc import Mapping
    stack = [(value, 0, "")]
    while stack:
        v, d, where = stack.pop()
        if isinstance(v, list):
            if d >= max_depth:
                return f"nested more than {max_depth} levels deep{where and ' in ' + where}"
            if not _ref_plain_numbers(v):
                stack.extend((x, d + 1, where) for x in v)
        elif isinstance(v, Mapping):
            if d >= max_depth:
                return f"nested more than {max_depth} levels deep{where and ' in ' + where}"
            for k, x in v.items():
                if len(k) > shape.MAX_STRING:
                    return f"a key of {len(k)} characters"
                stack.append((x, d + 1, where or repr(k[:40])))
        elif isinstance(v, float):
            if not math.isfinite(v):
                return f"a number out of range ({v!r}){where and ' in ' + where}"
        elif isinstance(v, int) and not isinstance(v, bool):
            if abs(v) > shape.MAX_NUMBER:
                return f"an integer out of range ({len(str(abs(v)))} digits){where and ' in ' + where}"
        elif isinstance(v, str):
            if len(v) > shape.MAX_STRING:
                return f"a string of {len(v)} characters{where and ' in ' + where}"
    return None


def _values(rng, depth: int):
    """A random JSON-like value: CityObject-like dicts, nested boundaries, odd leaves."""
    r = rng.random()
    if depth <= 0 or r < 0.25:
        k = int(rng.integers(0, 8))
        if k == 0:
            return int(rng.integers(-10, 10))
        if k == 1:
            return float(rng.standard_normal() * 10.0 ** float(rng.uniform(-5, 308)))
        if k == 2:
            return "s" * int(rng.integers(0, 4))
        if k == 3:
            return None
        if k == 4:
            return bool(rng.integers(0, 2))
        return _ODD[int(rng.integers(0, len(_ODD)))] if rng.random() < 0.3 else int(rng.integers(0, 100))
    if r < 0.55:
        return {f"k{i}": _values(rng, depth - 1) for i in range(int(rng.integers(0, 4)))}
    n = int(rng.integers(0, 5))
    if rng.random() < 0.4:  # a ring of indices
        return [int(x) for x in rng.integers(0, 1000, n)]
    return [_values(rng, depth - 1) for _ in range(n)]


@pytest.mark.parametrize("seed", range(6))
def test_value_problem_is_the_walk(seed):
    rng = np.random.default_rng(seed)
    found = {None: 0, "problem": 0}
    for _ in range(400):
        v = _values(rng, int(rng.integers(0, 7)))
        for depth in (3, 5, shape.MAX_DEPTH):
            want = _ref_value_problem(v, depth)
            assert shape.value_problem(v, depth) == want, (v, depth)
            found["problem" if want else None] += 1
    assert found[None] > 100 and found["problem"] > 50  # both outcomes were compared


def test_value_problem_edge_cases():
    deep = [1]
    for _ in range(60):
        deep = [deep]
    cases = [deep, {"a": deep}, [[]] * 3, {"x" * (shape.MAX_STRING + 1): 1}, {1: 2}, ["x" * (shape.MAX_STRING + 1)],
             [1.5e308, 1.5e308], [[1.5e308], [1.5e308]], [10 ** 400], [[1, 2], [3, -10 ** 400]], [[0.5, math.nan]],
             {"a": {"b": [math.inf]}}, [True, [False]], (1, 2), [(1, 2)], [_Small.ONE], {"a": _Small.ONE},
             [[1, 2, 3], [4.5, 6.5]], {"boundaries": [[[0, 1, 2]], [[2, 3, 4]]], "lod": "2.2"}]
    for v in cases:
        for depth in (2, 4, shape.MAX_DEPTH):
            try:
                want = _ref_value_problem(v, depth)
            except TypeError:  # a non-string key: both raise
                with pytest.raises(TypeError):
                    shape.value_problem(v, depth)
                continue
            assert shape.value_problem(v, depth) == want, (v, depth)


def test_sound_clears_real_cityobjects():
    """The bulk pass answers alone for sound CityObjects (else it would save nothing)."""
    co = {"type": "Building", "attributes": {"h": 3.5, "n": 4, "ok": True, "s": "x"},
          "geometry": [{"type": "Solid", "lod": "2.2", "boundaries": [[[[0, 1, 2, 3]], [[3, 2, 1, 0]]]],
                        "semantics": {"surfaces": [{"type": "RoofSurface"}], "values": [[0, None]]}}]}
    assert shape._sound(co, shape.MAX_DEPTH)
    assert not shape._sound(co, 3)
    assert not shape._sound({"a": [math.nan]}, shape.MAX_DEPTH)


# ----------------------------------------------------------------------------- rings built once

def _ring_dump(geometries):
    out = []
    for g in geometries:
        out.append((g.type, g.lod, None if g.raw is None else repr(dict(g.raw)), repr(g.semantic_surfaces)))
        for so in g.solids:
            for sh in so.shells:
                for s in sh.surfaces:
                    out.append(s.semantic)
                    out.extend((r.dtype.str, r.shape, r.flags.writeable, r.tobytes()) for r in s.rings)
    return out


@pytest.mark.parametrize("seed", range(4))
def test_reader_builds_each_ring_once_with_the_same_arrays(seed):
    """``build_feature`` parses rings as lists and makes each array once in the remap: the
    same arrays (values, dtype, read-only) as parsing to arrays and remapping those."""
    rng = np.random.default_rng(seed)
    nv = 60
    verts = rng.uniform(0, 10, (nv, 3))

    def ring():
        return [int(x) for x in rng.choice(nv, int(rng.integers(0, 6)), replace=False)]

    def surfaces():
        return [[ring() for _ in range(int(rng.integers(1, 3)))] for _ in range(int(rng.integers(0, 5)))]

    geoms = [{"type": "MultiSurface", "lod": "2", "boundaries": surfaces(),
              "semantics": {"surfaces": [{"type": "RoofSurface"}], "values": [0, None, 0]}},
             {"type": "Solid", "lod": 2.2, "boundaries": [surfaces(), surfaces()]},
             {"type": "CompositeSolid", "lod": "2.2", "boundaries": [[surfaces()], [surfaces()]],
              "semantics": {"surfaces": [{"type": "WallSurface"}], "values": [[[0, 0]], [[None]]]}},
             {"type": "MultiPoint", "lod": "1", "boundaries": ring()},
             {"type": "MultiLineString", "lod": "1", "boundaries": [ring(), ring()]}]
    cos = {"b": {"type": "Building", "geometry": geoms}}
    got = cityjson.build_feature("b", ["b"], cos, verts)
    col = cityjson._Collector(nv)
    parsed = [cityjson._parse_geometry(g, col, f"coid=b|geom={i}") for i, g in enumerate(geoms)]
    used = np.unique(np.asarray(col.used, dtype=np.intp))
    lut = np.full(nv, -1, dtype=np.intp)
    lut[used] = np.arange(len(used))
    want = [cityjson._remap_geometry(g, lut) for g in parsed]
    assert _ring_dump(got.root.geometries) == _ring_dump(want)
    assert np.array_equal(got.vertices, verts[used])
    assert sum(isinstance(x, tuple) and x[0] == np.dtype(np.intp).str for x in _ring_dump(want)) > 5
