"""The one place where lod2energy remembers results across calls.

What belongs to one object is cached on the object (``functools.cached_property`` on the frozen
types of :mod:`lod2energy.model`). What must outlive one building - a neighbour's zone shells that
the next jobs ask for again, the triangles of a face that several stages triangulate, the
verdict of a geometry the repair validates again - is kept here, in named tables of this
process, each a least-recently-used map of bounded size keyed by the content it was made from
(a digest or the bytes of the input arrays), so that a key can never go stale.

    >>> from lod2energy import cache
    >>> cache.remember("demo", b"k", lambda: 42, size=4)
    42
    >>> cache.recall("demo", b"k")
    42
    >>> cache.clear("demo")

A worker process starts with empty tables (forked from a parent that has used them, it inherits
their entries, which are valid there too: keys are contents). Tests empty them with
:func:`clear`.
"""
from __future__ import annotations

import hashlib
import functools
from collections import OrderedDict
from typing import Any, Callable, Hashable, Sequence

import numpy as np

_TABLES: dict[str, "OrderedDict[Hashable, Any]"] = {}
_SIZES: dict[str, int] = {}
_MISSING = object()


def _table(name: str, size: int) -> "OrderedDict[Hashable, Any]":
    t = _TABLES.get(name)
    if t is None:
        t = _TABLES[name] = OrderedDict()
    _SIZES[name] = size
    return t


def recall(name: str, key: Hashable, default: Any = None) -> Any:
    """The value kept under ``key`` in table ``name`` (marked as recently used), else ``default``."""
    t = _TABLES.get(name)
    if t is None:
        return default
    value = t.get(key, _MISSING)
    if value is _MISSING:
        return default
    try:
        t.move_to_end(key)
    except KeyError:  # evicted meanwhile by another thread (the IDF writer's threads share tables)
        pass
    return value


def keep(name: str, key: Hashable, value: Any, size: int) -> Any:
    """Keep ``value`` under ``key`` in table ``name`` of at most ``size`` entries (the least
    recently used go first); returns ``value``."""
    t = _table(name, size)
    t[key] = value
    try:
        t.move_to_end(key)
        while len(t) > size:
            t.popitem(last=False)
    except KeyError:  # another thread changed the table meanwhile
        pass
    return value


def remember(name: str, key: Hashable, make: Callable[[], Any], size: int) -> Any:
    """``make()`` once per ``key`` in table ``name`` of at most ``size`` entries."""
    value = recall(name, key, _MISSING)
    if value is _MISSING:
        value = keep(name, key, make(), size)
    return value


def remember_each(name: str, keys: Sequence[Hashable | None], make: Callable[[list[int]], list], size: int) -> list:
    """One value per key of ``keys`` from table ``name``: the kept ones recalled, the others made
    together by ``make(indices)`` (a list of values, one per index) and kept; a None key is
    never kept."""
    out = [_MISSING if k is None else recall(name, k, _MISSING) for k in keys]
    todo = [i for i, v in enumerate(out) if v is _MISSING]
    if todo:
        for i, value in zip(todo, make(todo)):
            out[i] = value if keys[i] is None else keep(name, keys[i], value, size)
    return out


def digest(*parts: Any) -> bytes:
    """A 16-byte key of ``parts``: arrays by dtype, shape and bytes, bytes as they are, anything
    else by its ``repr``."""
    h = hashlib.blake2b(digest_size=16)
    for p in parts:
        if isinstance(p, np.ndarray):
            h.update(f"{p.dtype.str}{p.shape}".encode())
            h.update(np.ascontiguousarray(p).tobytes())
        elif isinstance(p, bytes):
            h.update(p)
        else:
            h.update(repr(p).encode("utf-8", "surrogatepass"))
        h.update(b"|")
    return h.digest()


def clear(name: str | None = None) -> None:
    """Empty table ``name``, or every table."""
    for n, t in _TABLES.items():
        if name is None or n == name:
            t.clear()


def sizes() -> dict[str, tuple[int, int]]:
    """``{table: (entries, bound)}`` of this process."""
    return {n: (len(t), _SIZES.get(n, 0)) for n, t in _TABLES.items()}


def memoize(name: str, size: int) -> Callable[[Callable], Callable]:
    """Decorator: a function of hashable arguments whose results are kept in table ``name``
    (the loaders of shipped data, schemas and the IDD: read once per process)."""

    def wrap(fn: Callable) -> Callable:
        @functools.wraps(fn)
        def memoized(*args, **kw):
            key = (args, tuple(sorted(kw.items()))) if kw else args
            return remember(name, key, lambda: fn(*args, **kw), size)

        memoized.cache_clear = lambda: clear(name)  # type: ignore[attr-defined]
        return memoized

    return wrap
