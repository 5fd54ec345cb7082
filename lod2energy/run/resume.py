"""The run journal: one JSON line per finished step of an export (OUTDIR/report.jsonl).

The journal is what a run has done so far, appended as each building finishes (one
``write`` a line, so a killed process loses none; fsync'ed at most every
:data:`SYNC_INTERVAL` s and at the end, so a crash of the machine loses at most that much
work), so that an interrupted run leaves a truthful account and ``--resume`` can continue
from it. ``report.json`` and ``report.csv`` are assembled from it at the end.

Lines (each a JSON object with a ``kind``):

- ``{"kind": "header", "format": 1, "input": PATH, "input_size": N, "input_sha256": H,
  "options": {...}}`` - first line; a resume only trusts a journal whose header matches;
- ``{"kind": "building", ...}`` - a :meth:`BuildingRecord.to_json` after the first pass
  (validate ... per-building writers), for every input object in input order;
- ``{"kind": "context", "seq": I, "exports": [...]}`` - the writers that needed the
  building's neighbours (IDF party walls, shading, ``--run``), for building ``seq``;
- ``{"kind": "dataset", "seq": I, "exports": [...]}`` - a writer of one file for all
  buildings (CityJSON, GeoJSON, IDF / STL in dataset mode, the CFD case), for building ``seq``;
- ``{"kind": "terrain", "format": F, "path": P, "ok": B, "objects": N, "faces": T, "ids": [...]}`` -
  the input's terrain (``TINRelief`` objects) a one-file writer carried (the energy CityJSON);
- ``{"kind": "dataset_error", "code": C, "message": M}`` - a file-level problem;
- ``{"kind": "end", "interrupted": null | "SIGINT" | "SIGTERM"}`` - the run's last line.

A later line for the same ``seq`` and kind replaces an earlier one (a resumed run appends).
:func:`records_of` folds the lines of one run (from :attr:`Journal.run_start`) into the
buildings' final records: what ``report.json`` and ``report.csv`` are written from.
"""
from __future__ import annotations

import json
import os
import re
import time
from collections.abc import Mapping
from pathlib import Path
from typing import Any, Iterator

from lod2energy.run.record_store import RecordSequence
from lod2energy.records import BuildingRecord, ExportRecord, FileRecord
from lod2energy.safe_write import atomic_write, check_target, json_default

FORMAT = 1
JOURNAL_NAME = "report.jsonl"


def header(input_path: str, options: dict) -> dict:
    """The header line of a run on ``input_path`` with ``options`` (JSON-ready)."""
    fr = FileRecord.of(input_path)
    size, sha = (fr.size, fr.sha256) if fr is not None else (-1, "")
    return {"kind": "header", "format": FORMAT, "input": os.path.abspath(input_path), "input_size": size,
            "input_sha256": sha, "options": options}


def _dumps(obj: Any) -> str:
    return json.dumps(obj, ensure_ascii=False, default=json_default, allow_nan=True)


#: Longest time (s) between two fsyncs of the journal while lines are appended: an fsync a
#: line cost about 1 ms each of ~1,700 lines on Den Haag, in the parent that hands out jobs.
SYNC_INTERVAL = 1.0


class Journal:
    """Appends lines to OUTDIR/report.jsonl through the safe-write checks.

    Parameters
    ----------
    path : path
        The journal file.
    root : path
        OUTDIR (the journal must stay inside it).
    inputs : sequence of path
        The command's inputs (never written).
    head : dict
        The header line.
    resume : bool
        Keep the existing journal when its header equals ``head`` (its lines are then
        available from :meth:`previous`); otherwise the journal starts anew.
    """

    def __init__(self, path: str | os.PathLike, root, inputs, head: dict, resume: bool = False):
        self.path = Path(path)
        self.root, self.inputs = root, tuple(inputs)
        self._previous: list[dict] = []
        self.resumed = False
        if resume and self.path.is_file():
            lines = list(read_lines(self.path))
            if lines and lines[0].get("kind") == "header" and _same_header(lines[0], head):
                self._previous = [ln for ln in lines[1:] if ln.get("kind") != "end"]
                self.resumed = True
        if not self.resumed:
            with atomic_write(self.path, "w", root=root, inputs=inputs) as f:
                f.write(_dumps(head) + "\n")
        check_target(self.path, root, inputs)
        #: Byte offset of this run's first line (the lines before are the header and the
        #: runs this one resumes).
        self.run_start = self.path.stat().st_size
        flags = os.O_WRONLY | os.O_APPEND | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
        self._fd = os.open(self.path, flags)
        self._synced = float("-inf")  # the first line is fsync'ed at once

    def previous(self) -> list[dict]:
        """The lines of the journal this run resumes (empty for a new run)."""
        return self._previous

    def append(self, entry: dict, sync: bool = True) -> None:
        """One line, written whole (one ``write`` call on an ``O_APPEND`` file); with ``sync``,
        fsync'ed when the last fsync is :data:`SYNC_INTERVAL` s old or more."""
        data = (_dumps(entry) + "\n").encode("utf-8")
        os.write(self._fd, data)
        if sync and time.monotonic() - self._synced >= SYNC_INTERVAL:
            self.sync()

    def sync(self) -> None:
        """fsync what was appended."""
        if self._fd is not None:
            os.fsync(self._fd)
            self._synced = time.monotonic()

    def close(self) -> None:
        if self._fd is not None:
            self.sync()
            os.close(self._fd)
            self._fd = None


def _same_header(a: dict, b: dict) -> bool:
    keys = ("format", "input", "input_size", "input_sha256", "options")
    return json.loads(_dumps({k: a.get(k) for k in keys})) == json.loads(_dumps({k: b.get(k) for k in keys}))


def records_of(path: str | os.PathLike, start: int = 0) -> "JournalRecords":
    """The buildings' records as the journal's lines from byte ``start`` on tell them.

    Each ``building`` line is a record (a later one for the same ``seq`` replaces it); the
    ``context`` and ``dataset`` lines that follow add their writers' export records, in
    the order they were appended (as :meth:`BuildingRecord.with_export` did in the run).

    Parameters
    ----------
    path : path
        The journal.
    start : int
        Byte offset to read from (:attr:`Journal.run_start`: this run's lines only).

    Returns
    -------
    JournalRecords
        ``seq`` -> record (insertion order: as the building lines came, not sorted), each
        record built from its lines when it is read.
    """
    return JournalRecords(path, start)


#: The start this code writes every building / context / dataset line with (``_dumps`` keeps
#: the keys' order): kind and seq without decoding the line.
_HEAD = re.compile(rb'\{"kind": "(building|context|dataset)", "seq": (\d+)[,}]')


_BUILDING_ID = re.compile(rb'\{"kind": "building", "seq": \d+, "id": ("(?:[^"\\]|\\.)*")')


class JournalRecords(Mapping):
    """``seq -> BuildingRecord`` of a journal's lines (:func:`records_of`), each record built
    when it is read from the lines that tell it (its last ``building`` line, then the
    ``context`` and ``dataset`` lines that came after it, in order).

    Indexing keeps the byte offset and length of each line and nothing else, so that memory
    stays small however long the file; a line is read and decoded on each access (about
    0.1 ms): read each record once (:meth:`in_order`, :meth:`ordered`).
    """

    def __init__(self, path: str | os.PathLike, start: int = 0):
        self.path = str(path)
        self._lines: dict[int, list[int]] = {}  # seq -> (offset << 32 | length) of its lines
        with open(self.path, "rb") as f:
            f.seek(start)
            off = start
            for raw in f:
                n = len(raw)
                m = _HEAD.match(raw)
                if m is not None and raw.endswith(b"\n"):
                    kind, seq = m.group(1), int(m.group(2))
                else:  # another writer's key order, or a torn last line: decoded here
                    try:
                        d = json.loads(raw)
                    except (json.JSONDecodeError, UnicodeDecodeError):
                        d = None
                    kind = str(d.get("kind")).encode() if isinstance(d, dict) else b""
                    seq = int(d["seq"]) if kind in (b"building", b"context", b"dataset") else -1
                if kind == b"building":
                    self._lines[seq] = [(off << 32) | n]  # a later building line replaces the record
                elif seq in self._lines and kind in (b"context", b"dataset"):
                    self._lines[seq].append((off << 32) | n)
                off += n

    def _read(self, v: int, f) -> dict:
        f.seek(v >> 32)
        return json.loads(f.read(v & 0xFFFFFFFF))

    def __getitem__(self, seq: int):
        lines = self._lines[seq]
        with open(self.path, "rb") as f:
            rec = BuildingRecord.from_json(self._read(lines[0], f))
            for v in lines[1:]:
                for e in self._read(v, f).get("exports") or ():
                    rec = rec.with_export(ExportRecord.from_journal(e))
        return rec

    def __iter__(self):
        return iter(self._lines)

    def __len__(self) -> int:
        return len(self._lines)

    def __contains__(self, seq) -> bool:
        return seq in self._lines

    def seqs_of(self, ids) -> list[int]:
        """The seqs, in input order, of the records whose building id is in ``ids`` (read from
        the start of each record's building line, not from the whole record)."""
        wanted, out = {str(i) for i in ids}, []
        with open(self.path, "rb") as f:
            for s in sorted(self._lines):
                f.seek(self._lines[s][0] >> 32)
                head = f.read(min(self._lines[s][0] & 0xFFFFFFFF, 4096))
                m = _BUILDING_ID.match(head)
                try:
                    ident = json.loads(m.group(1)) if m is not None else self[s].id
                except json.JSONDecodeError:
                    ident = self[s].id
                if ident in wanted:
                    out.append(s)
        return out

    def in_order(self):
        """``(seq, record)`` in input order, one record built at a time."""
        for s in sorted(self._lines):
            yield s, self[s]

    def ordered(self, seqs=None):
        """The records of ``seqs`` (default: all, in input order) as a lazy sequence."""
        return RecordSequence(self, sorted(self._lines) if seqs is None else list(seqs))


def read_lines(path: str | os.PathLike, start: int = 0) -> Iterator[dict]:
    """The journal's JSON object lines from byte ``start`` on (a torn last line skipped)."""
    with open(path, "rb") as f:
        f.seek(start)
        for raw in f:
            try:
                d = json.loads(raw)
            except (json.JSONDecodeError, UnicodeDecodeError):
                continue  # a torn last line (a crash while appending), or a blank one
            if isinstance(d, dict):
                yield d


def terrain_of(path: str | os.PathLike, start: int = 0) -> list[dict]:
    """The ``terrain`` lines from byte ``start`` on (this run's), without their ``kind``: one
    per format, a later line replacing an earlier one, in the order the formats first came."""
    out: dict[str, dict] = {}
    for d in read_lines(path, start):
        if d.get("kind") == "terrain":
            out[str(d.get("format"))] = {k: v for k, v in d.items() if k != "kind"}
    return list(out.values())
