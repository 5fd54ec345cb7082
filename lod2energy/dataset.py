"""The writers of one file for all buildings (the export's last pass): CityJSON, IDF / STL in
dataset mode, the CFD case."""
from __future__ import annotations

import os
from dataclasses import dataclass

from lod2energy.energy.figures import model_figures
from lod2energy.exporters.run_results import with_run_results
from lod2energy.logs import log
from lod2energy.model import CityModel, frozen_mapping
from lod2energy.options import ExportOptions
from lod2energy.run.record_store import RecordStore
from lod2energy.records import NOT_COMPLIANT, ExportRecord
from lod2energy.repair_file import with_repair_attributes
from lod2energy.reports import err
from lod2energy.run.spool import Job, Spooled, load_spooled

#: The one-file writers that take the buildings one at a time (a :class:`~lod2energy.run.spool.Spooled`
#: sequence); the others get a list.
STREAMED = ("cityjson", "geojson", "gpkg", "urbanopt", "cea")
#: The one-file writers that carry a building whatever its compliance (the city model, the GIS
#: layer, each with the building's compliance status): a building in their file that is not
#: energy-compliant is not *accepted* as an energy model, so that every writer accepts exactly
#: the buildings called compliant (issue 19); its record says it is in the file, and why not.
CARRIERS = ("cityjson", "geojson", "gpkg")


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


@dataclass(frozen=True)
class DatasetResult:
    """What one writer of one file did (:func:`dataset_write`), before the records have it.

    ``pairs``: ``[(building ids, ExportRecord)]``; ``notes``: the writer's notes;
    ``seqs``: the records the file is for;
    ``terrain``: the input's terrain the file carries (format, path, ok, objects, faces, ids)
    or None; ``error``: the line to print when the writer failed as a whole, else None.
    """

    name: str
    seqs: tuple[int, ...] = ()
    pairs: tuple = ()
    notes: tuple[str, ...] = ()
    terrain: dict | None = None
    error: str | None = None


#: The one-file writers that may run beside the neighbour pass (:class:`lod2energy.run.side_process.Beside`):
#: they read nothing the neighbour pass writes, unless the IDFs are simulated (``--run``: the
#: CityJSON and GeoJSON carry the run's figures).
BESIDE = ("cityjson", "geojson", "gpkg")


def beside_ok(options: ExportOptions) -> bool:
    """True when the one-file writers :data:`BESIDE` need nothing of the neighbour pass: no
    IDF is written (the CityJSON and GeoJSON carry the written model's areas and UA, and a
    run's figures)."""
    return "idf" not in options.formats


def dataset_write(w, options: ExportOptions, job: Job, records: RecordStore, others: list[int], model: CityModel,
                  input_path: str) -> DatasetResult:
    """Writer ``w`` of one file for all buildings (CityJSON, IDF / STL in dataset mode, the CFD
    case), the buildings loaded from the spool in input order. Writes the file; changes no record
    (:func:`dataset_apply` does)."""
    wopts = options.writer_options(w.name)
    if w.name == "cityjson":
        seqs = [s for s, r in records.in_order() if r.outcome == "done" and r.assessed]
        energy = set(seqs)

        def load(b, s):
            if s not in energy:
                return b
            rec = records[s]
            if rec.energy.compliant is False and (b.provenance.get("energy") or {}).get("compliant"):
                # a writer before this one did not write it: the file says what the record says
                b = b.with_provenance(energy=frozen_mapping(rec.energy.to_json()))
            if rec.thermal.detail.get("figures_source") and b.provenance.get("thermal"):
                b = b.with_provenance(thermal=frozen_mapping(
                    model_figures(b.provenance["thermal"], rec.thermal.detail)))
            return with_run_results(with_repair_attributes(b), rec.export("idf"))

        # read from the spool one at a time as the writer streams the file
        bs = Spooled(job.spool, seqs + sorted(others), load)
    else:
        seqs = [s for s, r in records.in_order() if r.outcome == "done" and r.energy.geometry_ready]
        if w.name in STREAMED:
            bs = Spooled(job.spool, seqs)
        else:
            bs = [load_spooled(job.spool, s) for s in seqs]
            if w.name == "cfd":  # the file's terrain (TINRelief) is the case's ground
                bs += [load_spooled(job.spool, s) for s in sorted(others)]
    kw = {"records": records.ordered(seqs)} if getattr(w, "records", False) else {}
    if job.neighbours and w.name != "cityjson" and w.halo(wopts) > 0:  # party walls with unselected buildings
        kw["context"] = [load_spooled(job.spool, s) for s in job.neighbours]
    try:
        prepared = w.prepare(bs, wopts, kw["context"]) if "context" in kw else w.prepare(bs, wopts)
        pairs = w.write(prepared, job.outdir, wopts, crs=job.crs, model=model, stem=stem_of(input_path),
                        tol=options.prepare.tol, frame=job.frame, **kw)
    except Exception as e:  # noqa: BLE001 - reported for every building of the file
        why = f"{type(e).__name__}: {e}"
        return DatasetResult(w.name, tuple(seqs), tuple(((r.id,), ExportRecord(w.name, False, "", (
            f"{w.name.upper()} not written: {why}",))) for r in records.ordered(seqs)),
            error=f"{w.name.upper()} export failed: {why}")
    return DatasetResult(w.name, tuple(seqs), tuple(pairs), tuple(getattr(pairs, "notes", ()) or ()),
                         getattr(pairs, "terrain", None) or None)


def dataset_apply(res: DatasetResult, records: RecordStore, quiet: bool, journal=None) -> dict | None:
    """Give every record of ``records`` (seq -> BuildingRecord) in the file of ``res`` the
    writer's export record, also appended to ``journal`` (a :class:`~lod2energy.run.resume.Journal`;
    a ``dataset`` line per building, and a ``terrain`` line when the file carries the input's
    terrain); print the writer's notes and its first failure.

    Returns
    -------
    dict or None
        The terrain the file carries (format, path, ok, objects, faces, ids), else None.
    """
    name = res.name
    if res.error is not None:
        err(res.error)
    for note in res.notes:
        if not quiet:
            log.info("%s", note)
    if res.terrain and journal is not None:  # the input's terrain the file carries, for the report
        journal.append({"kind": "terrain", **res.terrain}, sync=False)
    by_id: dict[str, list[int]] = {}
    for s, r in zip(res.seqs, records.ordered(res.seqs)):
        by_id.setdefault(r.id, []).append(s)
    bad, refused = None, []
    for ids, er in res.pairs:
        for bid in ids:
            for s in by_id.get(bid, ()):
                rec = records[s]
                es = accepted_only_if_compliant(er, rec)
                records[s] = rec.with_export(es)
                if journal is not None:
                    journal.append({"kind": "dataset", "seq": s, "exports": [es.journal()]}, sync=False)
                if es.refused:
                    refused.append((bid, es.problems[0]))
                elif not es.ok and bad is None:
                    bad = (bid, es)
    for s in res.seqs:  # a compliant building the file left out without a word: not written
        rec = records[s]
        if rec.export(name) is None and rec.energy.compliant:
            es = ExportRecord(name, False, "", (f"{name.upper()} not written: not in the file",))
            records[s] = rec.with_export(es)
            if journal is not None:
                journal.append({"kind": "dataset", "seq": s, "exports": [es.journal()]}, sync=False)
            if bad is None:
                bad = (rec.id, es)
    if journal is not None:
        journal.sync()
    if refused and not quiet:
        bid, why = refused[0]
        log.info(f"{name.upper()}: {len(refused)} of {len(by_id)} buildings not accepted as "
              f"energy models (see report.csv), e.g. {bid}: {why}")
    if bad is not None:
        err(bad[1].message(bad[0]))
    return res.terrain or None


def dataset_pass(w, options: ExportOptions, job: Job, records: RecordStore, others: list[int], model: CityModel,
                 input_path: str, quiet: bool, journal=None) -> dict | None:
    """:func:`dataset_write` then :func:`dataset_apply`: writer ``w``'s file and its records."""
    return dataset_apply(dataset_write(w, options, job, records, others, model, input_path), records, quiet,
                         journal)


def write_beside(task: tuple) -> tuple[DatasetResult, ...]:
    """The job of a :class:`lod2energy.run.side_process.Beside` process: ``(writers, options, job,
    records, others, model, input_path)`` -> one :class:`DatasetResult` per writer, in order."""
    ws, options, job, records, others, model, input_path = task
    return tuple(dataset_write(w, options, job, records, others, model, input_path) for w in ws)
