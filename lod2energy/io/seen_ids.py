"""The ids a streaming reader has read, and where: what a city-sized file keeps per CityObject.

A CityJSONSeq or CityGML file read one feature at a time must still report a second CityObject
with an id already read (val3dity's 901 on the input) and say where the first came from. A dict
of every id string to a description string costs ~200 bytes a CityObject (the key, the value,
the entry): ~120 MB for Zurich's 145,865 buildings and their parts. :class:`SeenIds` keeps 16
bytes a slot instead: a 64-bit key of the id (BLAKE2b, the same in every process) and an integer
tag (the line or feature number) in an open-addressing table kept at most half full.

Two different ids with the same 64-bit key would be reported as one id read twice; for a
million ids the chance is about 3e-8.
"""
from __future__ import annotations

import hashlib
from array import array
from typing import Callable


def id_key(oid: str) -> int:
    """A stable 64-bit key of an id (never 0: 0 marks an empty slot)."""
    k = int.from_bytes(hashlib.blake2b(oid.encode("utf-8", "surrogatepass"), digest_size=8).digest(),
                       "little", signed=True)
    return k or 1


class SeenIds:
    """Ids read so far, each with the tag of where it was read (first one wins).

    Parameters
    ----------
    describe : callable
        ``describe(tag) -> str``: where the id of a tag was read (for the messages), e.g.
        ``lambda n: f"{path} line {n}"``.

    Notes
    -----
    ``oid in seen``, ``seen.add(oid, tag)``, ``seen.where(oid)``; :meth:`duplicate_id` names
    the report row of a repeated id (``"ID (duplicate)"``, ``"ID (duplicate 2)"``, ...), which
    keeps a count only for the ids that repeat.
    """

    def __init__(self, describe: Callable[[int], str] = str):
        self._describe = describe
        self._keys = array("q", bytes(8 * 1024))
        self._tags = array("q", bytes(8 * 1024))
        self._n = 0
        self._dups: dict[str, int] = {}

    def __len__(self) -> int:
        return self._n

    def _slot(self, k: int) -> int:
        keys = self._keys
        mask = len(keys) - 1
        i = k & mask
        while True:
            c = keys[i]
            if c == 0 or c == k:
                return i
            i = (i + 1) & mask

    def __contains__(self, oid: str) -> bool:
        k = id_key(oid)
        return self._keys[self._slot(k)] == k

    def add(self, oid: str, tag: int) -> None:
        """Remember ``oid`` as read at ``tag`` (an id already there keeps its first tag)."""
        k = id_key(oid)
        i = self._slot(k)
        if self._keys[i] == k:
            return
        self._keys[i] = k
        self._tags[i] = int(tag)
        self._n += 1
        if 2 * self._n > len(self._keys):
            self._grow()

    def where(self, oid: str) -> str:
        """Where ``oid`` was first read (``describe`` of its tag); KeyError if never."""
        k = id_key(oid)
        i = self._slot(k)
        if self._keys[i] != k:
            raise KeyError(oid)
        return self._describe(self._tags[i])

    def duplicate_id(self, oid: str) -> str:
        """A report id for one more CityObject ``oid`` that cannot collide with the first."""
        n = self._dups[oid] = self._dups.get(oid, 0) + 1
        return f"{oid} (duplicate)" if n == 1 else f"{oid} (duplicate {n})"

    def _grow(self) -> None:
        oldk, oldt = self._keys, self._tags
        size = 2 * len(oldk)
        keys = self._keys = array("q", bytes(8 * size))
        tags = self._tags = array("q", bytes(8 * size))
        mask = size - 1
        for j in range(len(oldk)):
            k = oldk[j]
            if k:
                i = k & mask
                while keys[i] != 0:
                    i = (i + 1) & mask
                keys[i] = k
                tags[i] = oldt[j]
