"""The spine of every command: the order of work per building, and the passes over a file.

Per building, one pure and picklable job (:func:`process_building`):
validate -> repair -> label -> U-values -> compliance and the final check -> the writers that
need only this building -> their self-checks; it returns the new building and a
:class:`~lod2energy.records.BuildingRecord`. :func:`export` runs that job over a file on an
executor (:mod:`lod2energy.executor`: in-process, a process pool or Dask) and then

1. the writers that need a building's neighbours (IDF party walls, ``--shading``, ``--run``),
   one building at a time with the neighbours found in a spatial index of the prepared
   buildings' boxes, on the same executor;
2. the writers of one file for all buildings (CityJSON, IDF / STL in dataset mode).

Prepared buildings are spooled to ``OUTDIR/.lod2energy/spool`` (one pickle each), so that the
parent holds records, not geometry. Every finished step is appended to the journal
(``OUTDIR/report.jsonl``, :mod:`lod2energy.journal`); ``report.json`` and ``report.csv`` are
assembled from it, in input order, so that every executor writes the same bytes.
"""
from __future__ import annotations

import csv
import os
import pickle
import signal
import sys
import threading
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any, Iterable, Iterator

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.errors import Lod2EnergyError, ParameterError
from lod2energy.model import Building, CityModel, FeatureError, frozen_mapping
from lod2energy.records import (CSV_FIELDS, _untimed, BuildingRecord, ComplianceRecord, ExportRecord, RepairRecord,
                                ThermalRecord)
from lod2energy.safe_write import UnsafeWriteError, atomic_write, check_target, write_bytes, write_json
from lod2energy.validate import checks as _checks
from lod2energy.validate.report import error_json

EXIT_OK, EXIT_INVALID, EXIT_UNUSABLE = 0, 1, 2
EXIT_SIGINT, EXIT_SIGTERM = 130, 143

#: Writers in the order they run and appear in the options.
FORMATS = ("cityjson", "idf", "stl", "cfd")


# ============================================================================ options

def _thermal_default():
    from lod2energy.thermal import ThermalOptions
    return ThermalOptions()


@dataclass(frozen=True)
class PrepareOptions:
    """Options of validate -> repair -> label -> U-values -> compliance.

    Parameters
    ----------
    tol : Tolerances
        The user's tolerances: validation, repair, the final check and every writer's check.
    lod : str, optional
        LoD of the energy envelope (default: each building's highest >= 2).
    timeout : float, s
        The repair's time budget per building (the ladder escalates when it is spent).
    merge_parts : bool
        Union overlapping BuildingParts (601).
    thermal : ThermalOptions
        Typology / U-value choices (country, tables, overrides, WWR).
    """

    tol: Tolerances = DEFAULT
    lod: str | None = None
    timeout: float = 30.0
    merge_parts: bool = False
    thermal: Any = field(default_factory=_thermal_default)


def _idf_default():
    from lod2energy.exporters.idf import IdfOptions
    return IdfOptions()


def _stl_default():
    from lod2energy.exporters.stl import StlOptions
    return StlOptions()


def _cityjson_default():
    from lod2energy.exporters.registry import CityJsonOptions
    return CityJsonOptions()


@dataclass(frozen=True)
class ExportOptions:
    """What ``lod2energy export`` computes and writes (picklable: it travels to the workers).

    Parameters
    ----------
    formats : tuple of str
        Writers to run, names of :mod:`lod2energy.exporters.registry` ("cityjson", "idf", "stl").
    prepare : PrepareOptions
    idf : IdfOptions
    stl : StlOptions
    cityjson : CityJsonOptions
    cfd : lod2energy.cfd.CfdOptions or None
        The OpenFOAM case (``--cfd``).
    html : bool
        Write ``report.html`` (the method's pictures) beside ``report.json``.
    hard_timeout : float or None, s
        Limit of one building's first-pass job, enforced by the executor (CPU time of the
        worker, or ten times that of wall time; the worker is killed and replaced, the
        building reported ``timeout``). Default: the repair budget plus ``max(2 s, 20 %)``.
    """

    formats: tuple[str, ...] = ()
    prepare: PrepareOptions = field(default_factory=PrepareOptions)
    idf: Any = field(default_factory=_idf_default)
    stl: Any = field(default_factory=_stl_default)
    cityjson: Any = field(default_factory=_cityjson_default)
    hard_timeout: float | None = None
    cfd: Any = None
    html: bool = True

    def writer_options(self, name: str):
        return {"idf": self.idf, "stl": self.stl, "cityjson": self.cityjson, "cfd": self.cfd}[name]

    @property
    def job_timeout(self) -> float | None:
        if self.hard_timeout is not None:
            return self.hard_timeout if self.hard_timeout > 0 else None
        return hard_budget(self.prepare.timeout)

    def fingerprint(self) -> dict:
        """JSON-ready summary of everything that changes the outputs (the journal header)."""
        d = asdict(self)
        d.pop("hard_timeout", None)
        return d


@dataclass(frozen=True)
class RunOptions:
    """How an export runs (not what it computes: none of these change a file).

    Parameters
    ----------
    jobs : int or None
        Worker processes (None or 0: all cores; 1: in this process).
    dask : str or dask.distributed.Client, optional
        Run the jobs on this Dask cluster instead.
    resume : bool
        Continue the run whose journal is in OUTDIR: buildings whose outputs are complete,
        self-checked and unchanged on disk are not processed again.
    quiet : bool
        No progress bar, notes or table.
    """

    jobs: int | None = None
    dask: Any = None
    resume: bool = False
    quiet: bool = False


# ============================================================================ one building

def hard_budget(timeout: float | None) -> float | None:
    """The executor's limit for one building's job (s): the repair's ``timeout`` plus
    ``max(2 s, 20 %)`` for the stages after it; None without a budget."""
    return None if not timeout or timeout <= 0 else timeout + max(2.0, 0.2 * timeout)


def _codes(defects) -> list[int]:
    return sorted({d.code for d in defects})


def repair_one(b: Building, tol: Tolerances, timeout: float = 30.0, merge_parts: bool = False,
               lod: str | None = None) -> Building:
    """Repair a building by the ladder (identity for valid input and non-buildings)."""
    if not b.is_building:
        return b
    from lod2energy.repair.pipeline import repair_building
    return repair_building(b, tol=tol, timeout=timeout, merge_parts=merge_parts, lod=lod)


def _geometry_key(b: Building) -> bytes:
    """Digest of the geometry state of ``b``: vertices and polygon structure, not labels
    (what :func:`lod2energy.validate.checks.validate_building` looks at)."""
    import hashlib

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


def final_check(b: Building, defects, lod: str | None, tol: Tolerances = DEFAULT) -> str | None:
    """Why ``b`` may not be called compliant nor exported (None when it may).

    The acceptance check every writer applies (:func:`lod2energy.repair.accept.export_problem`:
    thermal data present, envelope closed, outward, labelled, with U-values, val3dity-valid at
    the energy LoD at the user's tolerances), judged on the output file's grid: the building
    as the CityJSON writer will write it. ``defects`` (of the final geometry at ``tol``) are
    reused when the grid leaves the geometry as it is.
    """
    from lod2energy.repair.accept import export_problem

    return export_problem(b, lod, tol, defects=defects)


def prepare_building(b: Building, options: PrepareOptions = PrepareOptions(), seq: int = 0
                     ) -> tuple[Building, BuildingRecord]:
    """validate -> repair -> label -> U-values -> compliance and the final check, for one building.

    Each geometry state is validated once: the input, the ladder's result (inside the
    repair), and the labelled result only when its geometry differs from the input's.

    Returns
    -------
    (Building, BuildingRecord)
        The labelled building with ``provenance["energy"]`` and its record.
    """
    from lod2energy.io.interior import without_interior
    from lod2energy.repair import repair_info
    from lod2energy.semantics import label_building
    from lod2energy.thermal import assign_u_values
    from lod2energy.validate.compliance import energy_compliance

    tol, lod = options.tol, options.lod
    b = without_interior(b)  # LoD3/4 interior detail is not envelope (counted in the repair record)
    before = _checks.validate_building(b, tol)
    rb = repair_one(b, tol, options.timeout, options.merge_parts, lod)
    if rb.provenance.get("repair") is not None:
        # the ladder's timings would make the files (``+energyRepair``) differ run to run
        rb = rb.with_provenance(repair=frozen_mapping(_untimed(rb.provenance["repair"])))
    extra = {}
    if b.provenance.get("interior_left_out"):
        extra["interior_left_out"] = dict(b.provenance["interior_left_out"])
    # BuildingParts that overlap in the input stay as they are (reported by the repair as
    # ``overlapping_parts``): clipping them for the energy model (repair.parts.clip_overlapping_parts)
    # left hairline faces that 13 of Den Haag's 844 buildings' STL/CityJSON self-checks refused,
    # so it is not applied until the clipped shells pass every writer
    repair = RepairRecord.from_info({**repair_info(rb), **extra})
    lb = label_building(rb, lod=lod, source=b)
    thermal_opts = options.thermal
    if lod is not None and getattr(thermal_opts, "lod", None) is None:
        thermal_opts = replace(thermal_opts, lod=lod)
    tb = assign_u_values(lb, thermal_opts)
    after = before if _geometry_key(tb) == _geometry_key(b) else _checks.validate_building(tb, tol)
    block = dict(energy_compliance(tb, after, lod=lod, tol=tol, assess_labels=True, assess_u_values=True))
    if repair.error:  # e.g. implausible coordinates: kept in the output, not simulated
        block.update(compliant=False, geometry_ready=False,
                     reasons=[f"repair: {repair.error}"] + list(block.get("reasons", [])))
    energy = ComplianceRecord.from_block(block)
    if energy.geometry_ready or energy.compliant:
        blod = lod if lod is not None else (tb.provenance.get("thermal") or {}).get("lod")
        why = final_check(tb, after, blod, tol)
        if why is not None:
            energy = energy.rejected(f"final check: {why}")
    # areas, volume and UA of implausible geometry (e.g. a vertex 2,000 km away) would only
    # pollute sums over the report's columns
    thermal = ThermalRecord() if repair.error else ThermalRecord.from_block(tb.provenance.get("thermal"))
    tb = tb.with_provenance(energy=frozen_mapping(energy.to_json()))
    bbox = None
    if len(tb.vertices):
        import numpy as np
        v = np.asarray(tb.vertices, dtype=float)
        fin = v[np.isfinite(v).all(axis=1)]
        if len(fin):
            bbox = tuple(float(x) for x in np.concatenate([fin.min(axis=0), fin.max(axis=0)]))
    rec = BuildingRecord(seq, str(b.id), b.type, "done", tuple(_codes(before)), tuple(_codes(after)),
                         repair, energy, thermal, (), "", bbox)
    if not energy.geometry_ready:
        rec = rec.with_message("not exported: " + "; ".join(energy.reasons))
    return tb, rec


def prepare(b: Building, tol: Tolerances, a=None, source_model: CityModel | None = None
            ) -> tuple[Building, BuildingRecord]:
    """:func:`prepare_building` with options from an argparse namespace (``lod``, ``timeout``,
    ``merge_parts``, thermal flags; missing ones take their defaults)."""
    return prepare_building(b, prepare_options(a, tol, getattr(source_model, "crs", None)))


def prepare_options(a, tol: Tolerances = DEFAULT, crs: str | None = None) -> PrepareOptions:
    """:class:`PrepareOptions` from a namespace of CLI options (absent ones: defaults)."""
    from lod2energy.thermal import ThermalOptions
    kw = {"crs": crs, "lod": getattr(a, "lod", None)}
    for name in ("country", "u_table", "u_wall", "u_roof", "u_ground", "u_window", "wwr"):
        v = getattr(a, name, None)
        if v is not None:
            kw[name] = v
    timeout = getattr(a, "timeout", 30.0)
    return PrepareOptions(tol, getattr(a, "lod", None), 30.0 if timeout is None else float(timeout),
                          bool(getattr(a, "merge_parts", False)), ThermalOptions(**kw))


def _attach(rec: BuildingRecord, fmt: str, pairs) -> BuildingRecord:
    for ids, er in pairs:
        if rec.id in ids or not ids:
            rec = rec.with_export(er)
    if rec.export(fmt) is None:
        rec = rec.with_export(ExportRecord(fmt, False, "", (f"{fmt.upper()} not written",)))
    return rec


def process_building(b: Building, options: ExportOptions, outdir: str, seq: int = 0,
                     crs: str | None = None, frame=None) -> tuple[Building, BuildingRecord]:
    """The whole job of one building: :func:`prepare_building`, then the chosen writers that
    need no other building (their self-checks included). Pure but for the files it writes
    into ``outdir``; picklable (a module-level function of picklable arguments)."""
    from lod2energy.exporters.registry import writers
    pb, rec = prepare_building(b, options.prepare, seq)
    if not rec.energy.geometry_ready:
        return pb, rec
    for w in writers(options.formats):
        wopts = options.writer_options(w.name)
        if w.scope(wopts) != "building":
            continue
        try:
            pairs = w.write([pb], outdir, wopts, crs=crs, tol=options.prepare.tol, frame=frame)
        except Exception as e:  # noqa: BLE001 - a geometry the writer cannot take
            pairs = [((pb.id,), ExportRecord(w.name, False, "", (f"{w.name.upper()} not written: "
                                                                 f"{type(e).__name__}: {e}",)))]
        rec = _attach(rec, w.name, pairs)
    return pb, rec


# ============================================================================ jobs (worker side)

@dataclass(frozen=True)
class Job:
    """What every worker needs besides its building: options, OUTDIR, the spool, the CRS."""

    options: ExportOptions
    outdir: str
    spool: str
    crs: str | None = None
    frame: Any = None


def spool_path(spool: str, seq: int) -> str:
    return os.path.join(spool, f"{seq:08d}.pkl")


def _spool(job: Job, seq: int, b: Building) -> None:
    write_bytes(spool_path(job.spool, seq), pickle.dumps(b, protocol=pickle.HIGHEST_PROTOCOL),
                root=job.outdir, fsync=False)


def load_spooled(spool: str, seq: int) -> Building:
    with open(spool_path(spool, seq), "rb") as f:
        return pickle.load(f)


def first_pass(task: tuple) -> BuildingRecord | None:
    """Worker side of the first pass: ``(seq, kind, payload, job)`` -> record.

    ``kind`` is "building" (process and spool it), "other" (a non-building object: spool
    it), or "record" (a record already known: returned as it is).
    """
    seq, kind, payload, job = task
    if kind == "record":
        return payload
    if kind == "other":
        _spool(job, seq, payload)
        return None
    pb, rec = process_building(payload, job.options, job.outdir, seq, job.crs, job.frame)
    _spool(job, seq, pb)
    return rec


def context_pass(task: tuple) -> list[ExportRecord]:
    """Worker side of the neighbour pass: ``(seq, neighbour seqs, job)`` -> export records
    of the writers with "context" scope for building ``seq``."""
    from lod2energy.exporters.registry import writers
    seq, near, job = task
    b = load_spooled(job.spool, seq)
    context = [load_spooled(job.spool, s) for s in near]
    out = []
    for w in writers(job.options.formats):
        wopts = job.options.writer_options(w.name)
        if w.scope(wopts) != "context":
            continue
        try:
            pairs = w.write([b], job.outdir, wopts, crs=job.crs, context=context, tol=job.options.prepare.tol,
                            frame=job.frame)
        except Exception as e:  # noqa: BLE001 - reported for this building, the rest goes on
            pairs = [((b.id,), ExportRecord(w.name, False, "", (f"{w.name.upper()} not written: "
                                                                f"{type(e).__name__}: {e}",)))]
        rec = _attach(BuildingRecord(seq, b.id, b.type), w.name, pairs)
        out.append(rec.export(w.name))
    return out


# ============================================================================ the file

class Interrupted(BaseException):
    """SIGTERM (or SIGINT) arrived: finish the report with what is done."""

    def __init__(self, name: str, code: int):
        super().__init__(name)
        self.name, self.code = name, code


@dataclass(frozen=True)
class ExportOutcome:
    """What :func:`export` did: exit code, records in input order, the interruption if any."""

    exit_code: int
    records: tuple[BuildingRecord, ...] = ()
    interrupted: str | None = None
    report: str = ""
    dataset_errors: tuple[str, ...] = ()


def _err(msg: str) -> None:
    print(f"lod2energy: error: {msg}", file=sys.stderr)


def _progress(quiet: bool, desc: str):
    if quiet:
        return lambda: None, lambda: None
    from tqdm import tqdm
    bar = tqdm(desc=desc, unit=" buildings", file=sys.stderr, disable=None, leave=False)
    return (lambda: bar.update(1)), bar.close


def frame_entry(model: CityModel | None) -> dict:
    """Report entry for a geographic input: the local metric frame its buildings were
    validated, repaired and exported in (IDF / STL offsets are in this frame)."""
    frame = getattr(model, "frame", None)
    return {"local_frame": frame.as_dict()} if frame is not None else {}


def note_frame(path: str, model: CityModel | None) -> None:
    """One line on stderr when a geographic input is processed in a local metric frame."""
    f = getattr(model, "frame", None)
    if f is not None:
        print(f"lod2energy: note: {path}: CRS {model.crs} is geographic (degrees); buildings are checked and "
              f"exported in a local east-north-up frame in metres at lat {f.lat0:.7f}, lon {f.lon0:.7f} "
              "(report.json: local_frame); CityJSON is written back in degrees", file=sys.stderr)


def default_weather(country: str | None) -> str | None:
    """The bundled EPW for ``country`` (only NL ships one), else None."""
    if (country or "").upper() != "NL":
        return None
    from importlib.resources import files
    p = files("lod2energy") / "data" / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"
    return str(p) if p.is_file() else None


def resolve(options: ExportOptions, model: CityModel) -> ExportOptions:
    """``options`` completed from the file: the CRS for the typology, the weather for ``--run``.

    Raises
    ------
    ParameterError
        ``--run`` without a weather file where none ships, or a missing weather file.
    """
    from lod2energy.thermal import country_from_crs
    prep = options.prepare
    if getattr(prep.thermal, "crs", None) is None and model is not None and model.crs:
        prep = replace(prep, thermal=replace(prep.thermal, crs=model.crs))
    idf = options.idf
    if "idf" in options.formats:
        weather = idf.weather
        if idf.run and weather is None:
            weather = default_weather(prep.thermal.country or country_from_crs(model.crs))
            if weather is None:
                raise ParameterError("--run needs --weather EPW (a weather file ships only for the Netherlands)")
        if weather is not None and not os.path.isfile(weather):
            raise ParameterError(f"--weather {weather}: no such file")
        if options.prepare.lod is not None and idf.lod is None:
            idf = replace(idf, lod=options.prepare.lod)
        idf = replace(idf, weather=weather)
    stl = options.stl
    if options.prepare.lod is not None and stl.lod is None:
        stl = replace(stl, lod=options.prepare.lod)
    return replace(options, prepare=prep, idf=idf, stl=stl)


def stem_of(path: str) -> str:
    """File name of ``path`` without its (double) suffix."""
    base = os.path.basename(path)
    for suf in (".city.jsonl", ".city.json", ".jsonl", ".json", ".obj", ".off", ".poly"):
        if base.lower().endswith(suf):
            return base[: -len(suf)]
    return os.path.splitext(base)[0]


_stem = stem_of


def _repair_attributes(b: Building) -> Building:
    """``b`` with its repair record as flat attributes of the root CityObject."""
    from lod2energy.repair import repair_attributes
    if not b.is_building:
        return b
    attrs = dict(b.root.attributes)
    attrs.update({k: v for k, v in repair_attributes(b).items() if v is not None})
    root = replace(b.root, attributes=frozen_mapping(attrs))
    return replace(b, objects=(root,) + b.objects[1:])


def refuse_overwriting_inputs(outputs: Iterable[str], inputs: Iterable[str]) -> None:
    """:class:`UnsafeWriteError` when an output path is one of the inputs (also via a link)."""
    inputs = [p for p in inputs if p]
    for out in outputs:
        if out:
            check_target(out, None, inputs)



class _Signals:
    """While active (main thread only), SIGTERM raises :class:`Interrupted` and SIGINT
    :class:`KeyboardInterrupt`; the previous handlers come back on exit."""

    def __enter__(self):
        self._old = None
        if threading.current_thread() is threading.main_thread():
            def term(signum, frame):
                raise Interrupted("SIGTERM", EXIT_SIGTERM)
            self._old = signal.signal(signal.SIGTERM, term)
        return self

    def __exit__(self, *exc):
        if self._old is not None:
            signal.signal(signal.SIGTERM, self._old)
        return False


def _neighbours(records: list[BuildingRecord], halo: float) -> dict[int, list[int]]:
    """For each record, the seqs of the other records whose box comes within ``halo`` (m)
    of its own, in input order (a spatial index over the boxes' plan views)."""
    import numpy as np
    from shapely import STRtree, box
    if not records:
        return {}
    boxes = [box(r.bbox[0], r.bbox[1], r.bbox[3], r.bbox[4]) for r in records]
    tree = STRtree(boxes)
    seqs = np.array([r.seq for r in records])
    out = {}
    for i, r in enumerate(records):
        q = box(r.bbox[0] - halo, r.bbox[1] - halo, r.bbox[3] + halo, r.bbox[4] + halo)
        hits = tree.query(q)
        out[r.seq] = sorted(int(seqs[j]) for j in hits if j != i)
    return out


def _reusable(p: BuildingRecord | None, b: Building, job: Job, per_building: list[str]) -> bool:
    """A journal record of a former run that stands: same object, done, its outputs intact."""
    if p is None or p.id != str(b.id) or p.outcome != "done" or not os.path.isfile(spool_path(job.spool, p.seq)):
        return False
    if p.energy.geometry_ready:
        for fmt in per_building:
            e = p.export(fmt)
            if e is None or not e.intact():
                return False
    return all(e.intact() for e in p.exports)


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
        Use this one (e.g. a :class:`~lod2energy.executor.DaskExecutor` over your Client);
        it is not closed here.

    Returns
    -------
    ExportOutcome
        Exit code 0 (all exported and self-checked), 1 (some building not), 2 (unusable
        input), 130 / 143 (interrupted by SIGINT / SIGTERM; the report has what was done).
    """
    from lod2energy.executor import Failure, Overrun, make_executor
    from lod2energy.exporters.registry import writers
    from lod2energy.io import read
    from lod2energy.journal import JOURNAL_NAME, Journal, header

    inputs = (input_path,)
    refuse_overwriting_inputs([os.path.join(outdir, n) for n in ("report.json", "report.csv", "report.jsonl")],
                              inputs)
    if os.path.exists(outdir) and not os.path.isdir(outdir):
        refuse_overwriting_inputs([outdir], inputs)
        raise ParameterError(f"-o {outdir}: exists and is not a folder")
    model, feats = read(input_path)
    if model is None:
        msgs = []
        for fe in feats:
            _err(fe.message)
            msgs.append(fe.message)
        return ExportOutcome(EXIT_UNUSABLE, dataset_errors=tuple(msgs))
    note_frame(input_path, model)
    options = resolve(options, model)
    os.makedirs(outdir, exist_ok=True)
    out = os.path.abspath(outdir)
    from lod2energy.safe_write import sweep_stale
    sweep_stale(out)  # temporaries of a run that was killed mid-write
    spool = os.path.join(out, ".lod2energy", "spool")
    os.makedirs(spool, exist_ok=True)
    job = Job(options, out, spool, model.crs, getattr(model, "frame", None))
    chosen = writers(options.formats)
    scope = {w.name: w.scope(options.writer_options(w.name)) for w in chosen}
    per_building = [n for n, s in scope.items() if s == "building"]
    journal = Journal(os.path.join(out, JOURNAL_NAME), out, inputs,
                      header(input_path, options.fingerprint()), resume=run.resume)
    prev_b: dict[int, BuildingRecord] = {}
    prev_c: dict[int, dict] = {}
    for ln in journal.previous():
        if ln.get("kind") == "building":
            prev_b[int(ln["seq"])] = BuildingRecord.from_json(ln)
        elif ln.get("kind") == "context":
            prev_c[int(ln["seq"])] = ln
    records: dict[int, BuildingRecord] = {}
    others: list[int] = []
    reused: set[int] = set()
    dataset_errors: list[str] = []
    interrupted = None
    own = executor is None
    tick, close_bar = _progress(run.quiet, os.path.basename(input_path))
    timeout = options.job_timeout
    try:
        with _Signals():
            ex = make_executor(run.jobs, run.dask) if own else executor
            try:
                # ---- pass 1: every object, in input order
                def tasks() -> Iterator[tuple]:
                    for seq, item in enumerate(feats):
                        if isinstance(item, FeatureError):
                            if item.id is None:  # the file itself (e.g. an XML external entity)
                                dataset_errors.append(item.message)
                                journal.append({"kind": "dataset_error", "code": item.code,
                                                "message": item.message})
                                continue
                            rec = BuildingRecord(seq, str(item.id), item.type or "unknown", "unreadable",
                                                 (item.code,), message=item.message)
                            yield (seq, "record", rec, job)
                        elif not item.is_building:
                            yield (seq, "other", item, job)
                        elif run.resume and _reusable(prev_b.get(seq), item, job, per_building):
                            reused.add(seq)
                            yield (seq, "record", prev_b[seq], job)
                        else:
                            yield (seq, "building", item, job)

                for task, res in ex.map(first_pass, tasks(), timeout):
                    seq, kind, payload = task[0], task[1], task[2]
                    tick()
                    if kind == "other":
                        if not isinstance(res, (Overrun, Failure)):
                            others.append(seq)  # spooled: written with the CityJSON
                        continue
                    if isinstance(res, (Overrun, Failure)):
                        b = payload
                        if isinstance(res, Overrun):
                            rec = BuildingRecord(seq, str(b.id), b.type, "timeout",
                                                 message=f"timeout: not finished within {timeout:g} s "
                                                 f"(--timeout); kept as read, not exported")
                        else:
                            rec = BuildingRecord(seq, str(b.id), b.type, "failed",
                                                 message=f"pipeline failed: {res.message}")
                        _spool(job, seq, b)
                    else:
                        rec = res
                    if rec.outcome == "unreadable":  # the reader's message names the object itself
                        _err(f"{input_path}: {rec.message}")
                    elif rec.outcome != "done":
                        _err(f"{input_path}: {rec.type} {rec.id}: {rec.message}")
                    elif rec.repair.error:
                        _err(f"{input_path}: {rec.type} {rec.id}: {rec.repair.error}")
                    for e in rec.exports:
                        if not e.ok:
                            _err(f"{e.format.upper()} export {e.path or rec.id} failed its self-check: "
                                 f"{'; '.join(e.problems[:3])}")
                    records[seq] = rec
                    journal.append({"kind": "building", **rec.to_json()})
                close_bar()

                # ---- pass 2: writers that need the neighbours, one building at a time
                ctx_writers = [w for w in chosen if scope[w.name] == "context"]
                if ctx_writers:
                    ready = [r for _, r in sorted(records.items())
                             if r.outcome == "done" and r.energy.geometry_ready and r.bbox is not None]
                    halo = max(w.halo(options.writer_options(w.name)) for w in ctx_writers)
                    near = _neighbours(ready, halo)
                    names = [w.name for w in ctx_writers]

                    def ctx_tasks():
                        for r in ready:
                            p = prev_c.get(r.seq)
                            if run.resume and r.seq in reused and p is not None:
                                ers = [ExportRecord.from_journal(e) for e in p.get("exports", [])]
                                if {e.format for e in ers} >= set(names) and all(e.intact() for e in ers):
                                    yield ("record", r.seq, ers)
                                    continue
                            yield (r.seq, near[r.seq], job)

                    for task, res in ex.map(_context_or_record, ctx_tasks(), None):
                        seq = task[1] if task[0] == "record" else task[0]
                        rec = records[seq]
                        if isinstance(res, (Overrun, Failure)):
                            msg = res.message if isinstance(res, Failure) else f"timeout after {res.seconds} s"
                            res = [ExportRecord(n, False, "", (f"{n.upper()} not written: {msg}",)) for n in names]
                        for er in res:
                            rec = rec.with_export(er)
                            if not er.ok:
                                _err(f"{er.format.upper()} export {er.path or rec.id} failed its self-check: "
                                     f"{'; '.join(er.problems[:3])}")
                        records[seq] = rec
                        journal.append({"kind": "context", "seq": seq, "exports": [e.journal() for e in res]})
            except BaseException:
                if own:
                    ex.close(kill=True)  # interrupted: workers stop now, not after their job
                raise
            else:
                if own:
                    ex.close()

            # ---- pass 3: one file for all buildings (none for a file that could not be read)
            unusable = bool(dataset_errors) and not any(r.outcome == "done" for r in records.values())
            for w in chosen:
                if scope[w.name] != "dataset" or unusable:
                    continue
                _dataset_pass(w, options, job, records, others, model, input_path, run.quiet)
    except KeyboardInterrupt:
        interrupted = ("SIGINT", EXIT_SIGINT)
    except Interrupted as e:
        interrupted = (e.name, e.code)
    finally:
        close_bar()
    rows = [records[s] for s in sorted(records)]
    report = _write_reports(out, input_path, model, rows, dataset_errors, interrupted, inputs)
    if options.html:
        write_html_report(report, input_path, records, job.spool, out, options.prepare.tol, inputs)
    journal.append({"kind": "end", "interrupted": interrupted[0] if interrupted else None})
    journal.close()
    if interrupted:
        print(f"lod2energy: error: interrupted by {interrupted[0]}: report.json has the {len(rows)} objects done so far; "
              f"run again with --resume to continue", file=sys.stderr)
        return ExportOutcome(interrupted[1], tuple(rows), interrupted[0], report, tuple(dataset_errors))
    for m in dataset_errors:
        _err(m)
    worst = EXIT_OK
    for r in rows:
        if (r.outcome != "done" or (r.assessed and not r.energy.geometry_ready)
                or any(not e.ok for e in r.exports)):
            worst = EXIT_INVALID
    if dataset_errors:
        worst = EXIT_UNUSABLE
    return ExportOutcome(worst, tuple(rows), None, report, tuple(dataset_errors))


def _context_or_record(task):
    if task[0] == "record":
        return task[2]
    return context_pass(task)


def _dataset_pass(w, options: ExportOptions, job: Job, records: dict, others: list[int], model: CityModel,
                  input_path: str, quiet: bool) -> None:
    """One file for all buildings: loaded from the spool in input order."""
    wopts = options.writer_options(w.name)
    if w.name == "cityjson":
        seqs = [s for s, r in sorted(records.items()) if r.outcome == "done" and r.assessed]
        from lod2energy.exporters.run_results import with_run_results  # the IDF runs' figures
        bs = [with_run_results(_repair_attributes(load_spooled(job.spool, s)), records[s].export("idf"))
              for s in seqs]
        bs += [load_spooled(job.spool, s) for s in sorted(others)]
    else:
        seqs = [s for s, r in sorted(records.items()) if r.outcome == "done" and r.energy.geometry_ready]
        bs = [load_spooled(job.spool, s) for s in seqs]
        if w.name == "cfd":  # the file's terrain (TINRelief) is the case's ground
            bs += [load_spooled(job.spool, s) for s in sorted(others)]
    try:
        pairs = w.write(bs, job.outdir, wopts, crs=job.crs, model=model, stem=stem_of(input_path),
                        tol=options.prepare.tol, frame=job.frame)
    except Exception as e:  # noqa: BLE001 - reported for every building of the file
        pairs = [((records[s].id,), ExportRecord(w.name, False, "", (f"{w.name.upper()} not written: "
                                                                      f"{type(e).__name__}: {e}",)))
                 for s in seqs]
        _err(f"{w.name.upper()} export failed: {type(e).__name__}: {e}")
    for note in getattr(pairs, "notes", ()) or ():
        if not quiet:
            print(f"lod2energy: note: {note}", file=sys.stderr)
    by_id: dict[str, list[int]] = {}
    for s in seqs:
        by_id.setdefault(records[s].id, []).append(s)
    bad = None
    for ids, er in pairs:
        for bid in ids:
            for s in by_id.get(bid, ()):
                records[s] = records[s].with_export(er)
        if not er.ok and bad is None:
            bad = er
    if bad is not None:
        _err(f"{w.name.upper()} export {bad.path} failed its self-check: {'; '.join(bad.problems[:3])}")


def _write_reports(out: str, input_path: str, model, rows: list[BuildingRecord], dataset_errors: list[str],
                   interrupted, inputs) -> str:
    """report.json and report.csv from the records, in input order (no timing in them)."""
    doc = {"input_file": input_path, "output_dir": out, **frame_entry(model),
           "buildings": [r.report_entry() for r in rows]}
    if dataset_errors:
        doc["dataset_errors"] = [{"code": 901, "info": m} for m in dataset_errors]
    if interrupted:
        doc["interrupted"] = interrupted[0]
    path = os.path.join(out, "report.json")
    write_json(path, doc, root=out, inputs=inputs)
    with atomic_write(os.path.join(out, "report.csv"), "w", root=out, inputs=inputs, newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_FIELDS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r.row())
    return path


def json_ready(doc):
    """``doc`` as it reads back from JSON (numpy values, tuples and mappings made plain)."""
    import json
    from lod2energy.safe_write import json_default
    return json.loads(json.dumps(doc, default=json_default))


def write_html_report(report_path: str, input_path: str, records: dict, spool: str, out: str,
                      tol: Tolerances = DEFAULT, inputs=()) -> str:
    """``OUTDIR/report.html`` (:mod:`lod2energy.viz`) from the report, the input buildings and the
    prepared ones of the spool; a page that cannot be written costs one line, never the export."""
    import json
    try:
        from lod2energy.viz.report import panel_ids, read_buildings, write_report_html
        from lod2energy.viz import data as viz_data
        with open(report_path, encoding="utf-8") as f:
            doc = json.load(f)
        src = read_buildings(input_path) if os.path.isfile(input_path) else {}
        ids, _ = panel_ids(viz_data.rows(doc))
        wanted = set(ids)
        outputs = {}
        for s, r in sorted(records.items()):
            if r.id in wanted and r.outcome == "done" and os.path.exists(spool_path(spool, s)):
                outputs[r.id] = load_spooled(spool, s)
        path = os.path.join(out, "report.html")
        write_report_html(doc, path, inputs=src, outputs=outputs, tol=tol, root=out, input_files=list(inputs))
        return path
    except Exception as e:  # noqa: BLE001 - the page is a view of the report, not an output to check
        _err(f"report.html not written: {type(e).__name__}: {e}")
        return ""


def print_export_summary(records: Iterable[BuildingRecord], formats: Iterable[str], outdir: str) -> None:
    """The table ``lod2energy export`` prints."""
    formats = [f for f in FORMATS if f in set(formats)]
    b = [r for r in records if r.type == "Building" or r.assessed]
    n = len(b)
    comp = sum(bool(r.energy.compliant) for r in b)
    print(f"{'buildings':>9} {'compliant':>9} {'repaired':>8}  " + "  ".join(f"{f} ok" for f in formats))
    rep = sum(1 for r in b if r.repair.stage not in ("", "valid", "none", "irreparable"))
    cells = [f"{sum(bool(r.export(f) and r.export(f).ok) for r in b)}/{n}" for f in formats]
    timeouts = sum(r.outcome == "timeout" for r in b)
    print(f"{n:>9} {comp:>9} {rep:>8}  " + "  ".join(f"{c:>8}" for c in cells)
          + (f"  ({timeouts} timeout)" if timeouts else ""))
    print(f"report: {os.path.join(outdir, 'report.json')} and report.csv")


# ============================================================================ repair

#: Output suffixes of ``lod2energy repair`` (the writer picks CityJSON or CityJSONSeq by them).
REPAIR_SUFFIXES = (".json", ".jsonl", ".cjseq")


def _repair_job(task):
    from lod2energy.repair import repair_features
    b, tol, timeout, merge_parts, lod = task
    return next(iter(repair_features([b], tol, timeout, merge_parts, lod)))


def _repaired(feats, tol: Tolerances, timeout: float, merge_parts: bool, lod, jobs: int | None):
    """``repair_features`` on an executor that holds each building to its time budget: a building
    still running ``max(2 s, 20 %)`` past ``timeout`` is stopped and kept as read, reported
    ``timeout`` (the ladder's own deadline is cooperative and cannot interrupt one long step)."""
    from lod2energy.executor import Failure, Overrun, make_executor

    limit = hard_budget(timeout)
    with make_executor(1 if jobs is None else jobs, None) as ex:
        def tasks():
            for f in feats:
                yield (f, tol, timeout, merge_parts, lod)
        for task, res in ex.map(_repair_job, tasks(), limit):
            b = task[0]
            if isinstance(res, (Overrun, Failure)):
                why = f"timeout after {res.seconds:.0f} s" if isinstance(res, Overrun) else res.message
                stage = "timeout" if isinstance(res, Overrun) else "irreparable"
                res = b.with_provenance(repair={"stage": stage, "error": f"{stage}: {why}; kept as read",
                                                "iou": None, "mean_displacement": None, "hausdorff": None,
                                                "defects_before": [], "defects_after": [999]})
            yield res


def _print_repair_summary(table: dict) -> None:
    keys = ("total", "valid_before", "valid_after", "compliant_before", "compliant_after", "local_repairs",
            "global_repairs", "left", "miou", "map_v")
    print("  ".join(f"{k}={table[k]:.3g}" if isinstance(table.get(k), float) else f"{k}={table.get(k)}"
                    for k in keys if k in table))
    print("stages: " + ", ".join(f"{k}: {v}" for k, v in (table.get("stages") or {}).items()))


def repair_file(a, tol: Tolerances) -> int:
    """``lod2energy repair IN -o OUT``: every CityObject kept, defective buildings replaced by solids."""
    from lod2energy.io import cityjson, read
    from lod2energy.repair import dataset_table, repair_features, repair_info

    if not a.output.lower().endswith(REPAIR_SUFFIXES):
        _err(f"repair writes CityJSON (.json, .city.json) or CityJSONSeq (.jsonl, .city.jsonl): "
             f"cannot write {a.output!r}")
        return EXIT_UNUSABLE
    refuse_overwriting_inputs([a.output, getattr(a, "report", None)], [a.input])
    if a.report and os.path.abspath(a.report) == os.path.abspath(a.output):
        raise UnsafeWriteError(f"--report {a.report} is the output file")
    model, feats = read(a.input)
    if model is None:
        for fe in feats:
            _err(fe.message)
        return EXIT_UNUSABLE
    note_frame(a.input, model)
    out_b: list[Building] = []
    records: list[dict] = []
    lost: list[dict] = []
    html_inputs: dict = {}
    if getattr(a, "html", None):
        from lod2energy.viz.report import keep
        check_target(a.html, None, [a.input, a.output])
        feats = keep(feats, html_inputs)
    tick, close = _progress(a.quiet, os.path.basename(a.input))
    worst = EXIT_OK
    try:
        for item in _repaired(feats, tol, a.timeout, a.merge_parts, a.lod, getattr(a, "jobs", None)):
            tick()
            if isinstance(item, FeatureError):
                _err(f"{a.input}: {item.message}")
                if item.id is None:
                    worst = EXIT_UNUSABLE
                lost.append({"id": item.id, "type": item.type, "errors": [error_json(item.code, "", item.message)]})
                worst = max(worst, EXIT_INVALID)
                continue
            if item.is_building:
                rep = {"id": item.id, **{k: v for k, v in repair_info(item).items() if k != "geometries"}}
                records.append(rep)
                if rep.get("error"):
                    _err(f"{a.input}: {item.type} {item.id}: {rep['error']}")
                after = rep.get("defects_after") or []
                if rep.get("stage") == "irreparable" or any(c != 601 for c in after):
                    worst = max(worst, EXIT_INVALID)
            out_b.append(_repair_attributes(item))
    finally:
        close()
    out_dir = os.path.dirname(os.path.abspath(a.output))
    os.makedirs(out_dir, exist_ok=True)
    check_target(a.output, None, [a.input])
    cityjson.write(a.output, model, out_b)
    table = dataset_table(out_b)
    doc = {"input_file": a.input, "output_file": a.output, **frame_entry(model),
           "summary": table, "buildings": records, "unreadable": lost}
    if a.report:
        write_json(a.report, doc, inputs=[a.input, a.output])
    if getattr(a, "html", None):
        try:
            from lod2energy.viz.report import write_report_html
            write_report_html(json_ready(doc), a.html, inputs=html_inputs, outputs={b.id: b for b in out_b},
                              tol=tol, input_files=[a.input, a.output])
        except Exception as e:  # noqa: BLE001 - the page is a view of the report
            _err(f"{a.html} not written: {type(e).__name__}: {e}")
    if not a.quiet:
        _print_repair_summary(table)
    return worst
