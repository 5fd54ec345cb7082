"""The writers of one file for all buildings (the export's last pass): CityJSON, IDF / STL in
dataset mode, the CFD case."""
from __future__ import annotations

import os
import sys

from lod2energy.model import CityModel
from lod2energy.options import ExportOptions
from lod2energy.records import NOT_COMPLIANT, ExportRecord
from lod2energy.repair_file import with_repair_attributes
from lod2energy.reports import err
from lod2energy.spool import Job, Spooled, load_spooled

#: The one-file writers that take the buildings one at a time (a :class:`~lod2energy.spool.Spooled`
#: sequence); the others get a list.
STREAMED = ("cityjson", "geojson")
#: The one-file writers that carry a building whatever its compliance (the city model, the GIS
#: layer, each with the building's compliance status): a building in their file that is not
#: energy-compliant is not *accepted* as an energy model, so that every writer accepts exactly
#: the buildings called compliant (issue 19); its record says it is in the file, and why not.
CARRIERS = ("cityjson", "geojson")


def accepted_only_if_compliant(er: ExportRecord, rec) -> ExportRecord:
    """The record of carrier ``er.format`` for the building of ``rec`` (a BuildingRecord): ok
    only when the building is energy-compliant; one in the file that is not gets ``ok`` False and
    the final check's first reason (:data:`lod2energy.records.NOT_COMPLIANT`)."""
    if not er.ok or er.format not in CARRIERS or rec.energy.compliant:
        return er
    why = (rec.energy.reasons or ("not energy-compliant",))[0]
    return ExportRecord(er.format, False, er.path, (f"{NOT_COMPLIANT}{why}",), er.extra, er.files)


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
    bad, refused = None, []
    for ids, er in pairs:
        for bid in ids:
            for s in by_id.get(bid, ()):
                es = accepted_only_if_compliant(er, records[s])
                records[s] = records[s].with_export(es)
                if journal is not None:
                    journal.append({"kind": "dataset", "seq": s, "exports": [es.journal()]}, sync=False)
                if es.refused:
                    refused.append((bid, es.problems[0]))
                elif not es.ok and bad is None:
                    bad = (bid, es)
    if journal is not None:
        journal.sync()
    if refused and not quiet:
        bid, why = refused[0]
        print(f"lod2energy: note: {w.name.upper()}: {len(refused)} of {len(by_id)} buildings not accepted as "
              f"energy models (see report.csv), e.g. {bid}: {why}", file=sys.stderr)
    if bad is not None:
        err(bad[1].message(bad[0]))
    return terrain or None
