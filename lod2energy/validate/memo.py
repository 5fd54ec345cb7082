"""Validation verdicts remembered by geometry, so that nothing validates the same geometry twice.

A verdict (the list of :class:`~lod2energy.validate.codes.Defect` of
:func:`lod2energy.validate.checks.validate_building`, or of one geometry) is kept in
:mod:`lod2energy.cache` under a digest of everything the checks read: the vertex array bit for
bit, every ring's vertex indices with the solid / shell / surface structure, the object ids and
types, each geometry's type, LoD and raw input, the reader's input errors, and the tolerances.
A building with a ``GeometryInstance`` (whose template lives outside the key) is never remembered.

Verdicts travel between processes with the building: :func:`carry` puts the verdicts of the
states a job validated (input, final) in ``provenance["validated"]``, and :func:`learn` (called
for every building read back from the export's spool) keeps them in this process. A stale entry
is harmless: it is only used when its key matches.
"""
from __future__ import annotations

import hashlib
from typing import Sequence

import numpy as np

from lod2energy import cache
from lod2energy.validate.codes import Defect

#: Verdicts kept per process in each table (least recently used dropped first).
MAX_ENTRIES = 4096
#: The tables: whole buildings (:func:`verdict_key`) and single geometries (:func:`entry_key`).
BUILDINGS, GEOMETRIES = "validate.buildings", "validate.geometries"


def _structure(g) -> list:
    """The parts of a geometry's key: type, LoD, raw input, and its rings with their structure."""
    shape, rings = [len(g.solids)], []
    for so in g.solids:
        shape.append(len(so.shells))
        for sh in so.shells:
            shape.append(len(sh.surfaces))
            for sf in sh.surfaces:
                shape.append(len(sf.rings))
                shape.extend(len(r) for r in sf.rings)
                rings.extend(sf.rings)
    flat = np.concatenate(rings).astype(np.int64, copy=False) if rings else np.zeros(0, np.int64)
    return [g.type, g.lod, g.raw, np.asarray(shape, dtype=np.int64), flat]


def geometry_key(b) -> bytes:
    """Digest (16 bytes) of the geometry state of ``b``: vertices and polygon structure, not
    labels (what :func:`lod2energy.validate.checks.validate_building` looks at)."""
    parts = [np.asarray(b.vertices, dtype=float), tuple(b.provenance.get("input_errors", ()) or ())]
    for o in b.objects:
        parts += [o.id, o.type, len(o.geometries)]
        for g in o.geometries:
            parts += _structure(g)
    return cache.digest(*parts)


def entry_key(vertices, coid: str, gi: int, g, tol) -> bytes:
    """Digest of one geometry's input to the geometry-level checks (levels 1xx-5xx of
    :func:`lod2energy.validate.checks.validate_geometry`), tolerances included."""
    return cache.digest(np.asarray(vertices), coid, gi, *_structure(g), tol)


def shell_keys(items: Sequence[tuple[np.ndarray, object]], *extra) -> list[bytes]:
    """Digest of each ``(vertices (n, 3), Shell)`` pair and ``extra`` (tolerances): the whole
    vertex array (digested once per array) and the shell's rings with their structure."""
    arrays: dict[int, bytes] = {}
    tail = cache.digest(*extra)
    keys = []
    for v, sh in items:
        vk = arrays.get(id(v))
        if vk is None:
            vk = arrays[id(v)] = cache.digest(np.asarray(v), tail)
        rings = [r for s in sh.surfaces for r in s.rings]
        shape = [len(sh.surfaces)] + [len(s.rings) for s in sh.surfaces] + [len(r) for r in rings]
        h = hashlib.blake2b(vk, digest_size=16)
        h.update(np.asarray(shape, dtype=np.int64).tobytes())
        if rings:
            h.update(np.concatenate(rings).astype(np.int64, copy=False).tobytes())
        keys.append(h.digest())
    return keys


def verdict_key(b, tol) -> bytes | None:
    """Key of the verdict of ``b`` at tolerances ``tol`` (None: not to be remembered)."""
    if any(g.type == "GeometryInstance" for o in b.objects for g in o.geometries):
        return None
    return cache.digest(geometry_key(b), tol)


def remembered(table: str, items: list, keys: list, compute) -> list[list[Defect]]:
    """``compute(items)`` (one list of defects per item) through table ``table``: the items whose
    key is kept get that verdict (a new list); the others are computed together and kept."""
    found = cache.remember_each(table, keys, lambda todo: [tuple(d) for d in compute([items[i] for i in todo])],
                                MAX_ENTRIES)
    return [list(f) for f in found]


def recall(key: bytes | None) -> list[Defect] | None:
    """The remembered verdict of building key ``key`` (a new list), or None."""
    found = None if key is None else cache.recall(BUILDINGS, key)
    return None if found is None else list(found)


def carry(b, states: Sequence[tuple[object, Sequence[Defect]]], tol):
    """``b`` with the verdicts of ``states`` (``[(building, defects)]``, validated at ``tol``) in
    ``provenance["validated"]``, for the processes that read it back (:func:`learn`)."""
    entries = []
    for s, defects in states:
        k = verdict_key(s, tol)
        if k is not None and all(k != e[0] for e in entries):
            entries.append((k, tuple(defects)))
    return b.with_provenance(validated=tuple(entries))


def learn(b) -> None:
    """Remember the verdicts ``b`` carries (:func:`carry`)."""
    for k, defects in b.provenance.get("validated", ()) or ():
        if cache.recall(BUILDINGS, k) is None:
            cache.keep(BUILDINGS, k, tuple(defects), MAX_ENTRIES)


def forget() -> None:
    """Empty this process's memory, building and geometry verdicts (tests, benchmarks)."""
    cache.clear(BUILDINGS)
    cache.clear(GEOMETRIES)
