"""The spool: prepared buildings kept on disk (``OUTDIR/.lod2energy/spool``, one pickle each)
so that the parent of an export holds records, not geometry, and what a resumed run may reuse.

Every pass after the first (the neighbour pass, the one-file writers, ``report.html``) reads
the buildings it needs back from here, one at a time and in input order.
"""
from __future__ import annotations

import os
import pickle
from dataclasses import dataclass
from typing import Any

from lod2energy.model import Building
from lod2energy.options import ExportOptions
from lod2energy.records import BuildingRecord
from lod2energy.safe_write import write_bytes


@dataclass(frozen=True)
class Job:
    """What every worker needs besides its building: options, OUTDIR, the spool, the CRS."""

    options: ExportOptions
    outdir: str
    spool: str
    crs: str | None = None
    frame: Any = None


def spool_path(spool: str, seq: int) -> str:
    """The spool file of object ``seq`` (its index in the input)."""
    return os.path.join(spool, f"{seq:08d}.pkl")


def spool_building(job: Job, seq: int, b: Building) -> None:
    """Keep ``b`` (object ``seq`` of the input) in the spool of ``job``."""
    write_bytes(spool_path(job.spool, seq), pickle.dumps(b, protocol=pickle.HIGHEST_PROTOCOL),
                root=job.outdir, fsync=False)


def load_spooled(spool: str, seq: int) -> Building:
    """The building spooled as object ``seq``."""
    with open(spool_path(spool, seq), "rb") as f:
        return pickle.load(f)


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
