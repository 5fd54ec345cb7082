"""Many :class:`~lod2energy.records.BuildingRecord` objects of one file, kept compactly by the export's
parent for its later passes and the report (:class:`RecordStore`), and read back in order
(:class:`RecordSequence`).
"""
from __future__ import annotations

import os
import pickle
import tempfile
import zlib
from collections.abc import Mapping, MutableMapping, Sequence

from lod2energy.records import BuildingRecord


class RecordStore(MutableMapping):
    """``seq -> BuildingRecord`` for a whole file, each record kept as compressed pickle bytes.

    The export's parent keeps one record per building of the file for its later passes and the
    report. As objects a record costs about 10 KB (its detail mappings); kept as a pickle
    compressed at zlib level 1 it costs about 1.4 KB (measured on Den Haag). With ``scratch``
    (a folder: the export's spool) the bytes go to an unnamed file there and memory keeps one
    integer a record (its offset and length), so the parent's memory stays flat as the file
    grows (13,504 buildings: about 19 MB of records on disk, 1.5 MB in memory). A record is
    rebuilt on every read (about 0.1 ms): read it once per pass, and use :meth:`in_order` /
    :meth:`ordered` rather than ``sorted(items())``, which would hold them all at once.

    Parameters
    ----------
    items : mapping of int to BuildingRecord, optional
    scratch : str, optional
        Folder of the unnamed scratch file (removed by the system when the store is closed or
        its process ends); default: the bytes stay in memory. Only the process that created the
        store writes that file: a forked process (the one-file writers beside pass 2) reads it,
        and what it stores itself stays in its memory. A write that fails (a full disk) keeps
        that record in memory: nothing is lost.
    """

    __slots__ = ("_d", "_f", "_end", "_pid")

    def __init__(self, items: Mapping[int, BuildingRecord] | None = None, scratch: str | None = None):
        # seq -> bytes (in memory) or int (offset << 32 | length in the scratch file)
        self._d: dict[int, bytes | int] = {}
        self._f = tempfile.TemporaryFile(dir=scratch) if scratch is not None else None
        self._end = 0
        self._pid = os.getpid()
        for k, v in (items or {}).items():
            self[k] = v

    def _bytes(self, seq: int) -> bytes:
        v = self._d[seq]
        if isinstance(v, int):
            off, n = v >> 32, v & 0xFFFFFFFF
            v = os.pread(self._f.fileno(), n, off)
            if len(v) != n:
                raise OSError(f"record {seq}: scratch file is short ({len(v)} of {n} bytes)")
        return v

    def __getitem__(self, seq: int) -> BuildingRecord:
        return pickle.loads(zlib.decompress(self._bytes(seq)))

    def __setitem__(self, seq: int, rec: BuildingRecord) -> None:
        b = zlib.compress(pickle.dumps(rec, protocol=pickle.HIGHEST_PROTOCOL), 1)
        if self._f is not None and os.getpid() == self._pid and len(b) <= 0xFFFFFFFF:
            try:
                done = 0
                while done < len(b):
                    done += os.pwrite(self._f.fileno(), b[done:], self._end + done)
            except OSError:  # a full disk: this record stays in memory
                pass
            else:
                self._d[seq] = (self._end << 32) | len(b)
                self._end += len(b)
                return
        self._d[seq] = b

    def __delitem__(self, seq: int) -> None:
        del self._d[seq]

    def __iter__(self):
        return iter(self._d)

    def __len__(self) -> int:
        return len(self._d)

    def __contains__(self, seq) -> bool:
        return seq in self._d

    def __reduce__(self):  # pickled (a spawned process): the bytes themselves, in memory
        return _store_of_bytes, ({k: self._bytes(k) for k in self._d},)

    def close(self) -> None:
        """Remove the scratch file (the store is empty afterwards)."""
        self._d.clear()
        if self._f is not None:
            self._f.close()
            self._f = None

    def in_order(self):
        """``(seq, record)`` in input order, one record rebuilt at a time."""
        for s in sorted(self._d):
            yield s, self[s]

    def ordered(self, seqs=None) -> "RecordSequence":
        """The records of ``seqs`` (default: all, in input order) as a lazy sequence."""
        return RecordSequence(self, sorted(self._d) if seqs is None else list(seqs))


def _store_of_bytes(d: dict[int, bytes]) -> RecordStore:
    st = RecordStore()
    st._d.update(d)
    return st


class RecordSequence(Sequence):
    """The records of a :class:`RecordStore` at some seqs, rebuilt when indexed or iterated."""

    __slots__ = ("_store", "_seqs")

    def __init__(self, store: RecordStore, seqs: list[int]):
        self._store, self._seqs = store, seqs

    def __getitem__(self, i):
        if isinstance(i, slice):
            return RecordSequence(self._store, self._seqs[i])
        return self._store[self._seqs[i]]

    def __len__(self) -> int:
        return len(self._seqs)

    def __iter__(self):
        for s in self._seqs:
            yield self._store[s]

    def __eq__(self, other) -> bool:
        if not isinstance(other, Sequence) or len(other) != len(self):
            return NotImplemented if not isinstance(other, Sequence) else False
        return all(a == b for a, b in zip(self, other))

    __hash__ = None

    def __repr__(self) -> str:
        return f"RecordSequence({len(self)} records)"
