"""Validation verdicts remembered by geometry, so that nothing validates the same geometry twice.

A verdict (the list of :class:`~lod2energy.validate.defect.Defect` of
:func:`lod2energy.validate.checks.validate_building`) is keyed by :func:`geometry_key`: a digest
of everything the checks read (the vertex array bit for bit, every ring's vertex indices, the
object ids and types, each geometry's type, LoD and raw input, the reader's input errors) and of
the tolerances. Two buildings with the same key are the same input to the checks, so the
verdict of one is the verdict of the other; a building with a ``GeometryInstance`` (whose
template lives outside the key) is never remembered.

Verdicts travel between processes with the building: :func:`carry` puts the verdicts of the
states a job validated (input, final) in ``provenance["validated"]``, and :func:`learn` (called
for every building read back from the export's spool) adds them to this process's memory. A
stale entry there is harmless: it is only used when its key matches.

The memory of a process is a bounded LRU (:data:`MAX_ENTRIES`), so it never grows with the file.
"""
from __future__ import annotations

import hashlib
from collections import OrderedDict
from typing import Iterable, Sequence

from lod2energy.validate.defect import Defect

#: Verdicts kept per process (least recently used dropped first).
MAX_ENTRIES = 4096
_MEMORY: "OrderedDict[bytes, tuple[Defect, ...]]" = OrderedDict()
#: Verdicts of single geometries (:func:`entry_key`): the repair asks again about the
#: geometries the whole-building validation just checked.
_ENTRIES: "OrderedDict[bytes, tuple[Defect, ...]]" = OrderedDict()


def geometry_key(b) -> bytes:
    """Digest (16 bytes) of the geometry state of ``b``: vertices and polygon structure, not
    labels (what :func:`lod2energy.validate.checks.validate_building` looks at)."""
    import numpy as np
    h = hashlib.blake2b(digest_size=16)
    h.update(np.ascontiguousarray(b.vertices, dtype=float).tobytes())
    h.update(repr(tuple(b.provenance.get("input_errors", ()) or ())).encode())
    for o in b.objects:
        h.update(f"|o{o.id}|{o.type}".encode("utf-8", "surrogatepass"))
        for g in o.geometries:
            h.update(f"|g{g.type}|{g.lod}".encode())
            if g.raw is not None:
                h.update(repr(g.raw).encode("utf-8", "surrogatepass"))
            for so in g.solids:
                h.update(b"|S")
                for sh in so.shells:
                    h.update(b"|H")
                    for sf in sh.surfaces:
                        h.update(b"|F")
                        for r in sf.rings:
                            h.update(np.ascontiguousarray(r, dtype=np.int64).tobytes() + b";")
    return h.digest()


def entry_key(vertices, coid: str, gi: int, g, tol) -> bytes:
    """Digest of one geometry's input to the geometry-level checks (levels 1xx-5xx of
    :func:`lod2energy.validate.checks.validate_geometries`): the vertex array bit for bit (with
    its dtype and shape), the object id and geometry index (they are in the locations), the
    geometry's type, LoD and raw input, every ring's vertex indices with the solid / shell /
    surface / ring structure, and the tolerances."""
    import numpy as np
    h = hashlib.blake2b(digest_size=16)
    v = np.asarray(vertices)
    h.update(f"{v.dtype.str}{v.shape}|o{coid}|g{gi}|{g.type}|{g.lod}|".encode("utf-8", "surrogatepass"))
    h.update(np.ascontiguousarray(v).tobytes())
    if g.raw is not None:
        h.update(repr(g.raw).encode("utf-8", "surrogatepass"))
    shape, rings = [len(g.solids)], []
    for so in g.solids:
        shape.append(len(so.shells))
        for sh in so.shells:
            shape.append(len(sh.surfaces))
            for sf in sh.surfaces:
                shape.append(len(sf.rings))
                for r in sf.rings:
                    shape.append(len(r))
                    rings.append(r)
    h.update(np.asarray(shape, dtype=np.int64).tobytes() + b"|")
    if rings:
        h.update(np.ascontiguousarray(np.concatenate(rings), dtype=np.int64).tobytes())
    h.update(repr(tol).encode())
    return h.digest()


def recall_entry(key: bytes) -> list[Defect] | None:
    """The remembered defects of the geometry of :func:`entry_key` ``key`` (a new list), or None."""
    found = _ENTRIES.get(key)
    if found is None:
        return None
    _ENTRIES.move_to_end(key)
    return list(found)


def remember_entry(key: bytes, defects: Iterable[Defect]) -> None:
    """Keep the defects of the geometry of :func:`entry_key` ``key``."""
    _ENTRIES[key] = tuple(defects)
    _ENTRIES.move_to_end(key)
    while len(_ENTRIES) > MAX_ENTRIES:
        _ENTRIES.popitem(last=False)


def verdict_key(b, tol) -> bytes | None:
    """Key of the verdict of ``b`` at tolerances ``tol`` (None: not to be remembered)."""
    if any(g.type == "GeometryInstance" for o in b.objects for g in o.geometries):
        return None
    return geometry_key(b) + hashlib.blake2b(repr(tol).encode(), digest_size=8).digest()


def recall(key: bytes | None) -> list[Defect] | None:
    """The remembered verdict of ``key`` (a new list), or None."""
    if key is None:
        return None
    found = _MEMORY.get(key)
    if found is None:
        return None
    _MEMORY.move_to_end(key)
    return list(found)


def remember(key: bytes | None, defects: Iterable[Defect]) -> None:
    """Keep the verdict ``defects`` of ``key``."""
    if key is None:
        return
    _MEMORY[key] = tuple(defects)
    _MEMORY.move_to_end(key)
    while len(_MEMORY) > MAX_ENTRIES:
        _MEMORY.popitem(last=False)


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
        if k not in _MEMORY:
            remember(k, defects)


def forget() -> None:
    """Empty this process's memory, building and geometry verdicts (tests, benchmarks)."""
    _MEMORY.clear()
    _ENTRIES.clear()
