"""The writers of one file for all buildings (the export's last pass): CityJSON, IDF / STL in
dataset mode, the CFD case."""
from __future__ import annotations

import os
import sys

from lod2energy.model import CityModel
from lod2energy.options import ExportOptions
from lod2energy.records import ExportRecord
from lod2energy.repair_file import with_repair_attributes
from lod2energy.reports import err
from lod2energy.spool import Job, Spooled, load_spooled

#: The one-file writers that take the buildings one at a time (a :class:`~lod2energy.spool.Spooled`
#: sequence); the others get a list.
STREAMED = ("cityjson", "geojson")


def stem_of(path: str) -> str:
    """File name of ``path`` without its (double) suffix."""
    base = os.path.basename(path)
    for suf in (".city.jsonl", ".city.json", ".jsonl", ".json", ".obj", ".off", ".poly"):
        if base.lower().endswith(suf):
            return base[: -len(suf)]
    return os.path.splitext(base)[0]


def dataset_pass(w, options: ExportOptions, job: Job, records: dict, others: list[int], model: CityModel,
                  input_path: str, quiet: bool, journal=None) -> None:
    """Writer ``w`` of one file for all buildings (CityJSON, IDF / STL in dataset mode, the CFD
    case): the buildings are loaded from the spool in input order; every record of ``records``
    (seq -> BuildingRecord) in the file gets the writer's export record, also appended to
    ``journal`` (a :class:`~lod2energy.journal.Journal`; a ``dataset`` line per building, and a
    ``terrain`` line when the file carries the input's terrain).

    Returns
    -------
    dict or None
        The terrain the file carries (format, path, ok, objects, faces, ids), else None.
    """
    wopts = options.writer_options(w.name)
    if w.name == "cityjson":
        seqs = [s for s, r in sorted(records.items()) if r.outcome == "done" and r.assessed]
        from lod2energy.exporters.run_results import with_run_results  # the IDF runs' figures
        energy = set(seqs)

        def load(b, s):
            return with_run_results(with_repair_attributes(b), records[s].export("idf")) if s in energy else b

        # read from the spool one at a time as the writer streams the file
        bs = Spooled(job.spool, seqs + sorted(others), load)
    else:
        seqs = [s for s, r in sorted(records.items()) if r.outcome == "done" and r.energy.geometry_ready]
        if w.name in STREAMED:
            bs = Spooled(job.spool, seqs)
        else:
            bs = [load_spooled(job.spool, s) for s in seqs]
            if w.name == "cfd":  # the file's terrain (TINRelief) is the case's ground
                bs += [load_spooled(job.spool, s) for s in sorted(others)]
    kw = {"records": [records[s] for s in seqs]} if getattr(w, "records", False) else {}
    try:
        pairs = w.write(w.prepare(bs, wopts), job.outdir, wopts, crs=job.crs, model=model, stem=stem_of(input_path),
                        tol=options.prepare.tol, frame=job.frame, **kw)
    except Exception as e:  # noqa: BLE001 - reported for every building of the file
        pairs = [((records[s].id,), ExportRecord(w.name, False, "", (f"{w.name.upper()} not written: "
                                                                      f"{type(e).__name__}: {e}",)))
                 for s in seqs]
        err(f"{w.name.upper()} export failed: {type(e).__name__}: {e}")
    for note in getattr(pairs, "notes", ()) or ():
        if not quiet:
            print(f"lod2energy: note: {note}", file=sys.stderr)
    terrain = getattr(pairs, "terrain", None)
    if terrain and journal is not None:  # the input's terrain the file carries, for the report
        journal.append({"kind": "terrain", **terrain}, sync=False)
    by_id: dict[str, list[int]] = {}
    for s in seqs:
        by_id.setdefault(records[s].id, []).append(s)
    bad = None
    for ids, er in pairs:
        for bid in ids:
            for s in by_id.get(bid, ()):
                records[s] = records[s].with_export(er)
                if journal is not None:
                    journal.append({"kind": "dataset", "seq": s, "exports": [er.journal()]}, sync=False)
        if not er.ok and bad is None:
            bad = er
    if journal is not None:
        journal.sync()
    if bad is not None:
        err(f"{w.name.upper()} export {bad.path} failed its self-check: {'; '.join(bad.problems[:3])}")
    return terrain or None
