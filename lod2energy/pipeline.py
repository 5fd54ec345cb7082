"""The spine of every command: the order of work per building, and the passes over a file.

Per building, one pure and picklable job (:func:`process_building`):
validate -> repair -> label -> U-values -> compliance and the final check -> the writers that
need only this building -> their self-checks; it returns the new building and a
:class:`~lod2energy.records.BuildingRecord`. :func:`export` runs that job over a file on an
executor (:mod:`lod2energy.run.executor`: in-process, a process pool or Dask) and then

1. the writers that need a building's neighbours (IDF party walls, ``--shading``, ``--run``),
   one building at a time with the neighbours found in a spatial index of the prepared
   buildings' boxes, on the same executor;
2. the writers of one file for all buildings (CityJSON, IDF / STL in dataset mode).

Prepared buildings are spooled to ``OUTDIR/.lod2energy/spool`` (one pickle each), so that the
parent holds records, not geometry. Every finished step is appended to the journal
(``OUTDIR/report.jsonl``, :mod:`lod2energy.run.resume`); ``report.json`` and ``report.csv`` are
assembled from it, in input order, so that every executor writes the same bytes.
"""
from __future__ import annotations

import importlib
import os
from array import array
from dataclasses import dataclass, replace
from functools import partial
from typing import Iterator, Sequence


from lod2energy.run.side_process import Beside
from lod2energy.crs import no_crs_reason
from lod2energy.dataset import BESIDE, CARRIERS, DatasetResult, beside_ok, dataset_apply, dataset_pass, write_beside
from lod2energy.errors import ParameterError
from lod2energy.run.executor import Failure, Overrun, ProcessPoolExecutor, make_executor
from lod2energy.exporters.registry import writers
from lod2energy.run.interrupt import EXIT_INVALID, EXIT_OK, EXIT_SIGINT, EXIT_UNUSABLE, Interrupted, Signals
from lod2energy.io import read
from lod2energy.io.source import is_stdin, materialise, read_stdin
from lod2energy.logs import log
from lod2energy.run.resume import JOURNAL_NAME, Journal, header, records_of
from lod2energy.model import Building, FeatureError
from lod2energy.neighbours import neighbours_within, spatial_order
from lod2energy.options import NEEDS_POSITIONS, ExportOptions, RunOptions, chosen_formats, export_options, resolve
from lod2energy.run.record_store import RecordStore
from lod2energy.records import BuildingRecord, ExportRecord
from lod2energy.prepare import prepare_building
from lod2energy.reports import (
    CsvRows, err, note_frame, print_export_summary, refuse_overwriting_inputs, warning_summary, weather_warnings,
    write_html_report,
    write_reports_from_journal,
)
from lod2energy.run.driver import Command, Run, progress
from lod2energy.safe_write import sweep_stale
from lod2energy.study import joined, report_unknown_ids, selection_reach, selector, study_entry
from lod2energy.run.spool import Job, load_spooled, reusable, spool_building
from lod2energy.viz.footprints import FootprintSpill, plan_footprint
from lod2energy.viz.report import warm_page


# ============================================================================ one building

def _attach(rec: BuildingRecord, fmt: str, pairs) -> BuildingRecord:
    for ids, er in pairs:
        if rec.id in ids or not ids:
            rec = rec.with_export(er)
    if rec.export(fmt) is None:
        rec = rec.with_export(ExportRecord(fmt, False, "", (f"{fmt.upper()} not written",)))
    return rec


def _written(w, b: Building, write) -> list:
    """``write()``'s (ids, ExportRecord) pairs; a writer that raises is one failed record for ``b``
    (a geometry the writer cannot take: reported for this building, the rest goes on)."""
    try:
        return write()
    except Exception as e:  # noqa: BLE001
        return [((b.id,), ExportRecord(w.name, False, "", (f"{w.name.upper()} not written: {type(e).__name__}: {e}",)))]


def process_building(b: Building, options: ExportOptions, outdir: str, seq: int = 0,
                     crs: str | None = None, frame=None) -> tuple[Building, BuildingRecord]:
    """The whole job of one building: :func:`prepare_building`, then the chosen writers that
    need no other building (their self-checks included). Pure but for the files it writes
    into ``outdir``; picklable (a module-level function of picklable arguments)."""
    pb, rec = prepare_building(b, options.prepare, seq)
    if not rec.energy.geometry_ready:
        return pb, rec
    for w in writers(options.formats):
        wopts = options.writer_options(w.name)
        if w.scope(wopts) != "building":
            continue
        pairs = _written(w, pb, lambda: w.write(w.prepare([pb], wopts), outdir, wopts, crs=crs,
                                                tol=options.prepare.tol, frame=frame))
        rec = _attach(rec, w.name, pairs)
    return pb, rec


# ============================================================================ jobs (worker side)

@dataclass(frozen=True)
class Pass1:
    """The first pass's answer for one object: its record (None for a non-building object) and,
    when ``report.html`` is written, its plan footprint as read (``[(k, 2) float]``, m; drawn
    here in the worker, so that the page does not read and build the whole file again)."""

    record: BuildingRecord | None
    plan: list | None = None


def first_pass(task: tuple) -> Pass1:
    """Worker side of the first pass: ``(seq, kind, payload, job)`` -> :class:`Pass1`.

    ``kind`` is "building" (process and spool it), "other" (a non-building object: spool
    it), or "record" (a record already known: returned as it is).
    """
    seq, kind, payload, job = task
    if kind == "record":
        return Pass1(payload)
    if kind == "neighbour":
        pb, rec = prepare_building(payload, job.options.prepare, seq)
        if rec.energy.geometry_ready:
            spool_building(job, seq, pb)
        return Pass1(rec)
    plan = plan_footprint(payload) if job.options.html else None
    if kind == "other":
        spool_building(job, seq, payload)
        return Pass1(None, plan)
    pb, rec = process_building(payload, job.options, job.outdir, seq, job.crs, job.frame)
    spool_building(job, seq, pb)
    return Pass1(rec, plan)


def context_pass(task: tuple) -> list[ExportRecord]:
    """Worker side of the neighbour pass: ``(seq, neighbour seqs, job)`` -> export records
    of the writers with "context" scope for building ``seq``."""
    seq, near, job = task
    b = load_spooled(job.spool, seq)
    context = [load_spooled(job.spool, s) for s in near]
    out = []
    for w in writers(job.options.formats):
        wopts = job.options.writer_options(w.name)
        if w.scope(wopts) != "context":
            continue
        # the stage before the writer (prepare) runs with the writer's neighbours
        pairs = _written(w, b, lambda: w.write(w.prepare([b], wopts, context), job.outdir, wopts, crs=job.crs,
                                               context=context, tol=job.options.prepare.tol, frame=job.frame))
        rec = _attach(BuildingRecord(seq, b.id, b.type), w.name, pairs)
        out.append(rec.export(w.name))
    return out


# ============================================================================ the file


@dataclass(frozen=True)
class ExportOutcome:
    """What :func:`export` did: exit code, records in input order, the interruption if any."""

    exit_code: int
    #: In input order; a lazy sequence (:class:`~lod2energy.run.record_store.RecordSequence`) of an export.
    records: Sequence[BuildingRecord] = ()
    interrupted: str | None = None
    report: str = ""
    dataset_errors: tuple[str, ...] = ()
    #: The input's terrain (TINRelief objects) the one-file writers carried: one dict per file
    #: (format, path, ok, objects, faces, ids), as in ``report.json``'s ``terrain``.
    terrain: tuple[dict, ...] = ()


#: What every job imports, and each writer's own modules: :func:`warm` loads them in the parent.
_JOB_MODULES = ("lod2energy.repair.pipeline", "lod2energy.repair.accept", "lod2energy.semantics",
                "lod2energy.thermal.storeys", "lod2energy.thermal.use", "lod2energy.energy.zones.cut", "lod2energy.site",
                "lod2energy.polymesh", "scipy.spatial")
_WRITER_MODULES = {"idf": ("lod2energy.exporters.energyplus.writer", "lod2energy.exporters.energyplus.check"),
                   "stl": ("lod2energy.exporters.stl", "lod2energy.repair.parts"),
                   "cityjson": ("lod2energy.exporters.cityjson",), "geojson": ("lod2energy.exporters.geojson",),
                   "gpkg": ("lod2energy.exporters.gpkg",),
                   "urbanopt": ("lod2energy.exporters.urbanopt",), "cea": ("lod2energy.exporters.cea",),
                   "hbjson": ("lod2energy.exporters.hbjson",)}


def warm(options: ExportOptions) -> None:
    """Load here what every job of ``options`` loads (its modules; EnergyPlus's IDD for the
    IDF's self-check), before a process pool forks its workers from this process: they then
    share it instead of each loading its own (about 1.3 CPU s of imports and 1.1 s of IDD parse
    a worker). Modules that start threads (pymeshlab) are left to the workers."""
    for m in _JOB_MODULES + tuple(x for f in options.formats for x in _WRITER_MODULES.get(f, ())):
        importlib.import_module(m)
    if "idf" in options.formats:  # the writer's package, loaded by name as the others are
        importlib.import_module("lod2energy.exporters.energyplus.run").idd()


class _Export:
    """One export under way: what its passes share (the input, the journal, the records, the
    executor, the one-file writers' process beside pass 2) and the passes themselves
    (:data:`PASSES`), run in order by :func:`export`."""

    def __init__(self, input_path: str, out: str, options: ExportOptions, run: RunOptions, model, feats, executor):
        self.input_path, self.out, self.options, self.run, self.model, self.feats = (
            input_path, out, options, run, model, feats)
        self.inputs = (input_path,)
        spool = os.path.join(out, ".lod2energy", "spool")
        os.makedirs(spool, exist_ok=True)
        self.table = options.buildings or {}
        self.selection = frozenset(options.ids) if options.ids is not None else None
        self.selected = selector(self.selection, options.region)
        # the table's rows travel with their buildings, not with every job
        self.job = Job(replace(options, buildings=None), out, spool, model.crs, getattr(model, "frame", None))
        self.chosen = writers(options.formats)
        self.scope = {w.name: w.scope(options.writer_options(w.name)) for w in self.chosen}
        self.near_selected = selection_reach(input_path, self.selected, self.chosen, self.scope, options)
        self.input_ids: set[str] = set()  # the file's building ids (--buildings / --ids not in it are reported)
        self.study = study_entry(options)  # report.json's "study"
        self.neighbour_boxes: dict[int, tuple] = {}  # buildings outside --ids that serve as neighbours: their boxes
        self.journal = Journal(os.path.join(out, JOURNAL_NAME), out, self.inputs,
                               header(input_path, options.fingerprint()), resume=run.resume)
        self.csv_rows = CsvRows(os.path.join(out, "report.csv"), out, self.inputs)  # a row as each building finishes
        self.prev_b = RecordStore(scratch=spool)  # the journal's records of an earlier run (--resume)
        self.prev_c: dict[int, dict] = {}
        for ln in self.journal.previous():
            if ln.get("kind") == "building":
                self.prev_b[int(ln["seq"])] = BuildingRecord.from_json(ln)
            elif ln.get("kind") == "context":
                self.prev_c[int(ln["seq"])] = ln
        self.records = RecordStore(scratch=spool)  # seq -> record, on disk: the parent's memory stays flat
        self.others: list[int] = []  # the spooled non-building objects (written with the CityJSON)
        self.terrain: list[dict] = []  # the input's terrain the one-file writers carried
        self.reused: set[int] = set()  # the buildings whose records --resume took from the journal
        self.dataset_errors: list[str] = []
        self.unusable, self.interrupted, self.closing = False, None, []  # closing: the progress bars' close
        self.own, self.ex = executor is None, executor
        self.page_pool = None  # the process pool that renders report.html's pictures, kept open for it
        self.beside, self.side = None, []  # the one-file writers' process beside pass 2 (Beside), and its writers
        self.demoted = 0  # buildings no longer compliant after pass 2 (a file that failed its check): carriers again
        # the plan footprints of every object as read, in input order, for report.html; and of resumed
        # objects, drawn here (no job reads them)
        self.plans = FootprintSpill(out) if options.html else None
        self.resumed_plans: dict[int, tuple[str, list]] = {}

    def progress(self, desc: str, total: int | None = None):
        tick, close = progress(self.run.quiet, desc, total=total)
        self.closing.append(close)
        return tick, close

    def start_executor(self) -> None:
        """The executor (ours unless one was given), warmed before a process pool forks its workers."""
        if self.own:
            self.ex = make_executor(self.run.jobs, self.run.dask)
        if isinstance(self.ex, ProcessPoolExecutor):
            warm(self.options)  # before the workers are forked (at their first job): they share it
            # report.html's pictures are rendered by the pool when its workers are ours
            if self.options.html and self.own:
                self.page_pool = self.ex

    # ------------------------------------------------------------------------ pass 1
    def tasks(self) -> Iterator[tuple]:
        """The first pass's jobs, in input order: ``(seq, kind, payload, job)``."""
        for seq, item in enumerate(self.feats):
            if isinstance(item, FeatureError):
                if item.id is None:  # the file itself (e.g. an XML external entity)
                    self.dataset_errors.append(item.message)
                    self.journal.append({"kind": "dataset_error", "code": item.code, "message": item.message})
                    continue
                rec = BuildingRecord(seq, str(item.id), item.type or "unknown", "unreadable", (item.code,),
                                     message=item.message)
                yield (seq, "record", rec, self.job)
            elif not item.is_building:
                yield (seq, "other", item, self.job)
            else:
                item = joined(item, self.table, self.input_ids)
                if self.selected is not None and not self.selected(item):
                    if self.near_selected(item):
                        yield (seq, "neighbour", item, self.job)
                elif self.run.resume and reusable(prev := self.prev_b.get(seq), item, self.job, self.per_building):
                    self.reused.add(seq)
                    if self.plans is not None:
                        self.resumed_plans[seq] = (item.id, plan_footprint(item))
                    yield (seq, "record", prev, self.job)
                else:
                    yield (seq, "building", item, self.job)

    def pass_one(self) -> None:
        """Every object, in input order: prepared, written by the writers of scope "building", spooled."""
        self.per_building = [n for n, s in self.scope.items() if s == "building"]
        timeout = self.options.job_timeout
        tick, close = self.progress(os.path.basename(self.input_path))
        for task, res in self.ex.map(first_pass, self.tasks(), timeout):
            seq, kind, payload = task[0], task[1], task[2]
            tick()
            if kind == "neighbour":  # prepared and spooled for its neighbours, not reported
                r = res.record if isinstance(res, Pass1) else None
                if r is not None and r.outcome == "done" and r.energy.geometry_ready and r.bbox is not None:
                    self.neighbour_boxes[seq] = r.bbox
                continue
            if isinstance(res, Pass1):
                plan, res = res.plan, res.record
            else:  # the job did not finish: its object as read is drawn here
                plan = plan_footprint(payload) if self.plans is not None and kind != "record" else None
            if self.plans is not None:
                if kind == "record":
                    plan = self.resumed_plans.pop(seq, (None, None))[1]
                if plan is not None:
                    self.plans.add(str(payload.id), plan)
            if kind == "other":
                if not isinstance(res, (Overrun, Failure)):
                    self.others.append(seq)  # spooled: written with the CityJSON
                continue
            if isinstance(res, Overrun):  # not spooled: no later pass reads a building that is not "done"
                rec = BuildingRecord(seq, str(payload.id), payload.type, "timeout",
                                     message=f"timeout: not finished within {timeout:g} s "
                                     f"(--timeout); kept as read, not exported")
            elif isinstance(res, Failure):
                rec = BuildingRecord(seq, str(payload.id), payload.type, "failed",
                                     message=f"pipeline failed: {res.message}")
            else:
                rec = res
            if rec.outcome == "unreadable":  # the reader's message names the object itself
                err(f"{self.input_path}: {rec.message}")
            elif rec.outcome != "done":
                err(f"{self.input_path}: {rec.type} {rec.id}: {rec.message}")
            elif rec.repair.error:
                err(f"{self.input_path}: {rec.type} {rec.id}: {rec.repair.error}")
            for e in rec.exports:
                if not e.ok:
                    err(e.message(rec.id))
            self.records[seq] = rec
            self.journal.append({"kind": "building", **rec.to_json()})
            self.csv_rows.append(rec)
        close()
        self.study.update(report_unknown_ids(self.input_path, self.input_ids, self.table, self.selection))
        self.job = replace(self.job, neighbours=tuple(sorted(self.neighbour_boxes)))  # for the one-file writers
        # the one-file writers that need nothing of pass 2 run beside it, in a process of their own
        self.unusable = bool(self.dataset_errors) and not any(r.outcome == "done" for r in self.records.values())
        self.side = [w for w in self.chosen if self.scope[w.name] == "dataset" and w.name in BESIDE]
        if (self.side and not self.unusable and isinstance(self.ex, ProcessPoolExecutor)
                and beside_ok(self.options)):
            self.beside = Beside(write_beside, (tuple(self.side), self.options, self.job, self.records, self.others,
                                                self.model, self.input_path))

    # ------------------------------------------------------------------------ pass 2
    def pass_two(self) -> None:
        """The writers that need the neighbours (scope "context"), one building at a time."""
        ctx_writers = [w for w in self.chosen if self.scope[w.name] == "context"]
        if not ctx_writers:
            return
        options, job, timeout = self.options, self.job, self.options.job_timeout
        ready, ready_boxes = array("q"), array("d")  # 56 bytes a building, not a tuple of floats
        for s, r in self.records.in_order():
            if r.outcome == "done" and r.energy.geometry_ready and r.bbox is not None:
                ready.append(s)
                ready_boxes.extend(r.bbox)
        for s, bbox in sorted(self.neighbour_boxes.items()):
            ready.append(s)
            ready_boxes.extend(bbox)
        halo = max(w.halo(options.writer_options(w.name)) for w in ctx_writers)
        near = neighbours_within(ready, ready_boxes, halo)
        order = spatial_order(ready_boxes)  # near buildings one after the other: the same for every executor
        del ready_boxes
        names = [w.name for w in ctx_writers]

        def ctx_tasks():
            for k in order.tolist():
                s = ready[k]
                if s in self.neighbour_boxes:  # a neighbour only: nothing of its own is written
                    continue
                p = self.prev_c.get(s)
                if self.run.resume and s in self.reused and p is not None:
                    ers = [ExportRecord.from_journal(e) for e in p.get("exports", [])]
                    if {e.format for e in ers} >= set(names) and all(e.intact() for e in ers):
                        yield ("record", s, ers)
                        continue
                yield (s, near.of(k), job)

        # the same budget per job as pass 1: an overrun stops the worker (replaced), the rest goes on;
        # a worker left idle at the end loads what report.html's pictures need
        tail = None
        if self.page_pool is not None:
            tail = partial(warm_page, after=self.beside.proc.pid if self.beside is not None else None)
        run_idf = "idf" in names and getattr(options.writer_options("idf"), "run", False)
        tick, close = self.progress(f"{', '.join(names)}{' + EnergyPlus' if run_idf else ''}",
                                    total=len(ready) - len(self.neighbour_boxes))
        for task, res in self.ex.map(_context_or_record, ctx_tasks(), timeout, tail=tail):
            tick()
            seq = task[1] if task[0] == "record" else task[0]
            rec = self.records[seq]
            if isinstance(res, (Overrun, Failure)):
                msg = (res.message if isinstance(res, Failure) else
                       f"timeout: not finished within {timeout:g} s (--timeout)")
                res = [ExportRecord(n, False, "", (f"{n.upper()} not written: {msg}",)) for n in names]
            was = rec.energy.compliant
            for er in res:
                rec = rec.with_export(er)
                if not er.ok:
                    err(er.message(rec.id))
            if was and not rec.energy.compliant:
                self.demoted += 1  # the carriers written beside this pass say compliant
            self.records[seq] = rec
            self.journal.append({"kind": "context", "seq": seq, "exports": [e.journal() for e in res]})
        close()

    # ------------------------------------------------------------------------ pass 3
    def pass_three(self) -> None:
        """One file for all buildings (none for a file that could not be read; ``unusable`` is of
        pass 1, which alone sets the outcomes and the file's errors)."""
        if self.own and self.page_pool is None:
            self.ex.close()
        if self.demoted and self.beside is not None and self.beside.cancel():
            sweep_stale(self.out)  # its half-written files go; the carriers are written again below
        done_beside = _beside_results(self.beside, self.side) if not self.demoted else {}
        # the carriers last: they carry each building's compliance, which the others' checks decide
        for w in sorted(self.chosen, key=lambda w: w.name in CARRIERS):
            if self.scope[w.name] != "dataset" or self.unusable:
                continue
            if w.name in done_beside:
                carried = dataset_apply(done_beside[w.name], self.records, self.run.quiet, self.journal)
            else:
                if self.page_pool is not None:  # its idle workers' memory is not held while this one writes
                    self.page_pool.close()
                    self.page_pool = None
                carried = dataset_pass(w, self.options, self.job, self.records, self.others, self.model,
                                       self.input_path, self.run.quiet, self.journal)
            if carried:
                self.terrain.append(carried)

    # ------------------------------------------------------------------------ the reports
    def outcome(self) -> ExportOutcome:
        """report.json, report.csv, report.html from the journal; the exit code."""
        rows = self.records.ordered()
        self.csv_rows.close()
        journal, interrupted = self.journal, self.interrupted
        journal.sync()
        try:
            done = records_of(journal.path, journal.run_start)  # what the journal says was done: the report
            report = write_reports_from_journal(self.out, self.input_path, self.model, str(journal.path),
                                                journal.run_start, self.dataset_errors, interrupted, self.inputs,
                                                done, self.study)
            if self.options.html:
                mapper = partial(_results, self.page_pool) if self.page_pool is not None and not interrupted else None
                write_html_report(report, self.input_path, done, self.job.spool, self.out, self.options.prepare.tol,
                                  self.inputs, self.plans, mapper, crs=self.options.crs)
                self.plans.close()
        finally:
            if self.page_pool is not None:
                self.page_pool.close()
        journal.append({"kind": "end", "interrupted": interrupted[0] if interrupted else None})
        journal.close()
        errors, terrain = tuple(self.dataset_errors), tuple(self.terrain)
        if interrupted:
            err(f"interrupted by {interrupted[0]}: report.json has the {len(rows)} objects done so far; "
                f"run again with --resume to continue")
            return ExportOutcome(interrupted[1], rows, interrupted[0], report, errors, terrain)
        for m in self.dataset_errors:
            err(m)
        worst = EXIT_OK
        for r in rows:
            if (r.outcome != "done" or (r.assessed and not r.energy.geometry_ready)
                    or any(not e.ok for e in r.exports)):
                worst = EXIT_INVALID
        if self.dataset_errors:
            worst = EXIT_UNUSABLE
        return ExportOutcome(worst, rows, None, report, errors, terrain)


#: The passes of an export, in order (:class:`_Export`).
PASSES = (_Export.pass_one, _Export.pass_two, _Export.pass_three)


def export(input_path: str, outdir: str, options: ExportOptions, run: RunOptions = RunOptions(),
           executor=None) -> ExportOutcome:
    """``lod2energy export``: every building of ``input_path`` through the spine, into ``outdir``.

    Parameters
    ----------
    input_path : str
    outdir : str
        Created if missing; every file is written inside it (through :mod:`lod2energy.safe_write`).
    options : ExportOptions
    run : RunOptions
        Executor (``jobs``, ``dask``), ``resume``, ``quiet``.
    executor : Executor, optional
        Use this one (e.g. a :class:`~lod2energy.run.executor.DaskExecutor` over your Client);
        it is not closed here.

    Returns
    -------
    ExportOutcome
        Exit code 0 (all exported and self-checked), 1 (some building not), 2 (unusable
        input), 130 / 143 (interrupted by SIGINT / SIGTERM; the report has what was done).
    """
    inputs = (input_path,)
    refuse_overwriting_inputs([os.path.join(outdir, n) for n in ("report.json", "report.csv", "report.jsonl")],
                              inputs)
    if os.path.exists(outdir) and not os.path.isdir(outdir):
        refuse_overwriting_inputs([outdir], inputs)
        raise ParameterError(f"-o {outdir}: exists and is not a folder")
    model, feats = read(input_path, crs=options.crs)
    if model is None:
        msgs = []
        for fe in feats:
            err(fe.message)
            msgs.append(fe.message)
        return ExportOutcome(EXIT_UNUSABLE, dataset_errors=tuple(msgs))
    placed = [f for f in options.formats if f in NEEDS_POSITIONS]
    why = no_crs_reason(model.crs) if placed else None
    if why:
        what = " and ".join([f"--{f}" for f in placed] + (["--run"] if "idf" in placed and options.idf.run else []))
        raise ParameterError(f"{input_path}: {why}: {what} needs the buildings' real positions; "
                             "give the file's CRS with --crs (nothing written)")
    note_frame(input_path, model, metres_note=True)
    options = resolve(options, model)
    os.makedirs(outdir, exist_ok=True)
    out = os.path.abspath(outdir)
    sweep_stale(out)  # temporaries of a run that was killed mid-write
    st = _Export(input_path, out, options, run, model, feats, executor)
    ours = None  # our executor while passes 1 and 2 use it: stopped at once if they are interrupted
    try:
        with Signals():
            try:
                st.start_executor()
                ours = st.ex if st.own else None
                for one_pass in PASSES:
                    if one_pass is _Export.pass_three:
                        ours = None
                    one_pass(st)
            except BaseException:
                if ours is not None:
                    ours.close(kill=True)  # interrupted: workers stop now, not after their job
                raise
    except KeyboardInterrupt:
        st.interrupted = ("SIGINT", EXIT_SIGINT)
    except Interrupted as e:
        st.interrupted = (e.name, e.code)
    finally:
        for close in st.closing:
            close()
        stopped = st.beside is not None and st.beside.cancel()  # interrupted: its file is not finished
        if stopped or st.interrupted:
            sweep_stale(out)  # the temporaries of the processes stopped mid-write go
    return st.outcome()


def _beside_results(beside, writers) -> dict:
    """Writer name -> :class:`~lod2energy.dataset.DatasetResult` of the :class:`Beside` process
    (empty without one); a process that failed as a whole is a failed result for each writer."""
    if beside is None:
        return {}
    res = beside.result()
    if isinstance(res, Failure):  # every writer of the process, as dataset_write reports a failed writer
        return {w.name: DatasetResult(w.name, error=f"{w.name.upper()} export failed: {res.message}") for w in writers}
    return {r.name: r for r in res}


def _results(pool, fn, jobs) -> list:
    """``fn`` over ``jobs`` on ``pool``, the results in order."""
    return [res for _, res in pool.map(fn, jobs)]


def _context_or_record(task):
    if task[0] == "record":
        return task[2]
    return context_pass(task)


# ============================================================================ the command

def export_file(run: Run) -> None:
    """The export of ``IN`` into ``OUTDIR`` (``-``: standard input, written to
    ``OUTDIR/.lod2energy/input/stdin.city.json[l]`` and read from there). The run's ``made``:
    ``options`` (:class:`~lod2energy.options.ExportOptions`), ``outcome`` (:class:`ExportOutcome`)."""
    a = run.args
    opts = run.made["options"] = export_options(a)
    path = a.input
    if is_stdin(path):
        if os.path.exists(a.output) and not os.path.isdir(a.output):
            raise ParameterError(f"-o {a.output}: exists and is not a folder")
        path = materialise(read_stdin(), os.path.join(a.output, ".lod2energy", "input"))
    res = run.made["outcome"] = export(path, a.output, opts, RunOptions(a.jobs, a.dask, a.resume, a.quiet))
    run.code = res.exit_code


def print_summary(run: Run) -> None:
    """The table of what was written (none with ``-q``), the weather stations' warnings and the
    warnings by kind (warnings stay with ``-q``)."""
    res, opts = run.made["outcome"], run.made["options"]
    if not run.args.quiet and res.records and res.exit_code in (EXIT_OK, EXIT_INVALID):
        print_export_summary(res.records, opts.formats, run.args.output, res.terrain)
    if res.records and "idf" in opts.formats:
        for line in weather_warnings(res.records):
            log.warning("%s", line)
    for line in warning_summary(res.records):
        log.warning("%s", line)


EXPORT = Command("export", (export_file, print_summary), writers=chosen_formats)
