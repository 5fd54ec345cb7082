"""The spool: prepared buildings kept on disk (``OUTDIR/.lod2energy/spool``, one pickle each)
so that the parent of an export holds records, not geometry, and what a resumed run may reuse.

Every pass after the first (the neighbour pass, the one-file writers, ``report.html``) reads
the buildings it needs back from here, one at a time and in input order.
"""
from __future__ import annotations

import os
import pickle
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Sequence

from lod2energy.model import Building
from lod2energy.options import ExportOptions
from lod2energy.records import BuildingRecord
from lod2energy.safe_write import write_bytes
from lod2energy.validate.memo import learn


@dataclass(frozen=True)
class Job:
    """What every worker needs besides its building: options, OUTDIR, the spool, the CRS, and
    the spooled buildings outside the selection (``--ids``, ``--region``) that serve only as
    neighbours of the one-file writers (their seqs)."""

    options: ExportOptions
    outdir: str
    spool: str
    crs: str | None = None
    frame: Any = None
    neighbours: tuple[int, ...] = ()


def spool_path(spool: str, seq: int) -> str:
    """The spool file of object ``seq`` (its index in the input)."""
    return os.path.join(spool, f"{seq:08d}.pkl")


def spool_building(job: Job, seq: int, b: Building) -> None:
    """Keep ``b`` (object ``seq`` of the input) in the spool of ``job``."""
    write_bytes(spool_path(job.spool, seq), pickle.dumps(b, protocol=pickle.HIGHEST_PROTOCOL),
                root=job.outdir, fsync=False)


def load_spooled(spool: str, seq: int) -> Building:
    """The building spooled as object ``seq``; the validation verdicts it carries are
    remembered in this process (:func:`lod2energy.validate.memo.learn`)."""
    with open(spool_path(spool, seq), "rb") as f:
        b = pickle.load(f)
    if isinstance(b, Building):
        learn(b)
    return b


class Spooled(Sequence):
    """Spooled buildings in the order of ``seqs``, read from the spool one at a time as they
    are iterated (again on each iteration): what the one-file writers stream.

    Parameters
    ----------
    spool : path
    seqs : sequence of int
        The objects, in the order the writer gets them.
    load : callable(Building, int) -> Building, optional
        Applied to each building (with its seq) as it is read.

    Attributes
    ----------
    heads : list of (str, str) or None
        ``(id, type)`` of every building, in order, once an iteration went through them all
        (so that the writer's records need not read the spool again).
    """

    def __init__(self, spool: str, seqs: Sequence[int], load: Callable[[Building, int], Building] | None = None):
        self.spool, self.seqs, self.load = spool, tuple(seqs), load
        self.heads: list[tuple[str, str]] | None = None

    def __len__(self) -> int:
        return len(self.seqs)

    def _get(self, seq: int) -> Building:
        b = load_spooled(self.spool, seq)
        return self.load(b, seq) if self.load is not None else b

    def __getitem__(self, i):
        if isinstance(i, slice):
            return Spooled(self.spool, self.seqs[i], self.load)
        return self._get(self.seqs[i])

    def __iter__(self) -> Iterator[Building]:
        heads = []
        for s in self.seqs:
            b = self._get(s)
            heads.append((str(b.id), b.type))
            yield b
        self.heads = heads


def reusable(p: BuildingRecord | None, b: Building, job: Job, per_building: list[str]) -> bool:
    """A journal record of a former run that stands (``--resume``): same object, done, spooled,
    the outputs of the per-building writers ``per_building`` intact on disk."""
    if p is None or p.id != str(b.id) or p.outcome != "done" or not os.path.isfile(spool_path(job.spool, p.seq)):
        return False
    if p.energy.geometry_ready:
        for fmt in per_building:
            e = p.export(fmt)
            if e is None or not e.intact():
                return False
    return all(e.intact() for e in p.exports)
