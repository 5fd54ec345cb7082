"""What a command tells its user: report.json / report.csv / report.html, the summary table,
the lines on stderr (errors, notes, the progress bar).
"""
from __future__ import annotations

import csv
import io
import json
import os
from collections import Counter
from typing import TYPE_CHECKING, Iterable, Sequence

from lod2energy import crs as crs_
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.io.json_stream import Scanner
from lod2energy.run.resume import records_of, terrain_of
from lod2energy.logs import log
from lod2energy.model import CityModel
from lod2energy.options import FORMATS
from lod2energy.energy.downgrades import KINDS
from lod2energy.records import CSV_FIELDS, BuildingRecord
from lod2energy.safe_write import atomic_write, check_target, json_default
from lod2energy.site import MAX_WEATHER_KM
from lod2energy.run.spool import load_spooled, spool_path
from lod2energy.viz.data import iter_rows
from lod2energy.viz.report import write_report_for_files
from lod2energy.viz.warnings import WarningTally, warning_lines

if TYPE_CHECKING:
    from lod2energy.run.resume import JournalRecords


def err(msg: str) -> None:
    """One error of a building or file, on the package's logger (the CLI prints ``lod2energy: error: ...``)."""
    log.error("%s", msg)


def frame_entry(model: CityModel | None) -> dict:
    """Report entry for an input not in metres: the local metric frame a geographic file's
    buildings were validated, repaired and exported in (IDF / STL offsets are in this frame),
    or the conversion of a file in feet to metres."""
    frame = getattr(model, "frame", None)
    if frame is None:
        return {}
    return {"local_frame" if frame.geographic else "unit_conversion": frame.as_dict()}


def note_frame(path: str, model: CityModel | None, metres_note: bool = True) -> None:
    """One note (logged at INFO) when an input is processed in a local metric frame (geographic CRS),
    converted to metres (a CRS in feet) or, with ``metres_note``, taken as metres (no CRS
    pyproj reads)."""
    f = getattr(model, "frame", None)
    if f is not None and f.geographic:
        log.info(f"{path}: CRS {model.crs} is geographic (degrees); buildings are checked and "
              f"exported in a local east-north-up frame in metres at lat {f.lat0:.7f}, lon {f.lon0:.7f} "
              "(report.json: local_frame); CityJSON is written back in degrees")
    elif f is not None:
        log.info(f"{path}: CRS {model.crs} is in {f.unit} (heights in {f.vertical_unit}); "
              f"coordinates are converted to metres (x {f.to_metre:.10g}) for every check and export in "
              "metres (report.json: unit_conversion); CityJSON is written back in the file's unit")
    elif metres_note and model is not None and crs_.metres_note(path, model.crs):
        log.info(crs_.metres_note(path, model.crs))


def refuse_overwriting_inputs(outputs: Iterable[str], inputs: Iterable[str]) -> None:
    """:class:`UnsafeWriteError` when an output path is one of the inputs (also via a link)."""
    inputs = [p for p in inputs if p]
    for out in outputs:
        if out:
            check_target(out, None, inputs)


class CsvRows:
    """``OUTDIR/report.csv`` as the run goes: the header first, then one row appended as each
    building finishes (one ``write`` on an ``O_APPEND`` file, as the journal's lines), so that
    an interrupted or killed run leaves a CSV of what it finished. :func:`write_reports`
    replaces it at the end with the final rows (the writers of later passes add columns).

    Parameters
    ----------
    path : path
        report.csv.
    root, inputs :
        See :func:`lod2energy.safe_write.check_target`.
    """

    def __init__(self, path: str | os.PathLike, root, inputs=()):
        with atomic_write(path, "w", root=root, inputs=inputs, newline="", fsync=False) as f:
            csv.DictWriter(f, fieldnames=CSV_FIELDS, extrasaction="ignore").writeheader()
        check_target(path, root, inputs)
        flags = os.O_WRONLY | os.O_APPEND | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
        self._fd: int | None = os.open(path, flags)

    def append(self, rec: BuildingRecord) -> None:
        """The row of ``rec``, as :func:`write_reports` writes it."""
        if self._fd is None:
            return
        buf = io.StringIO(newline="")
        csv.DictWriter(buf, fieldnames=CSV_FIELDS, extrasaction="ignore").writerow(rec.row())
        os.write(self._fd, buf.getvalue().encode("utf-8"))

    def close(self) -> None:
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None


#: Stands for the buildings' list in the report's head (a NUL cannot be in a path nor an id).
_ROWS = "\x00lod2energy: buildings\x00"


def _dump(obj) -> str:
    return json.dumps(obj, indent=1, ensure_ascii=False, default=json_default)


def write_reports(out: str, input_path: str, model, rows: Iterable[BuildingRecord], dataset_errors: list[str],
                   interrupted, inputs, terrain: Sequence[dict] = (), study: dict | None = None) -> str:
    """report.json and report.csv from the records, in input order (no timing in them).

    Both are written one building at a time: ``report.json`` is the bytes of ``json.dump(doc,
    indent=1)`` of the whole report, without the report as one object in memory.

    Parameters
    ----------
    rows : iterable of BuildingRecord
        In input order; iterated once (both files are written side by side).
    terrain : sequence of dict
        The input's terrain the one-file writers carried (format, path, ok, objects, faces,
        ids): ``report.json``'s ``terrain``, left out when there is none.
    study : dict, optional
        The study's inputs (attribute map, ``--buildings`` table, selection): ``report.json``'s
        ``study``.
    """
    doc = {"input_file": input_path, "output_dir": out, **frame_entry(model)}
    if study:
        doc["study"] = dict(study)
    if terrain:
        doc["terrain"] = [dict(t) for t in terrain]
    doc["buildings"] = _ROWS
    if dataset_errors:
        doc["dataset_errors"] = [{"code": 901, "info": m} for m in dataset_errors]
    if interrupted:
        doc["interrupted"] = interrupted[0]
    head, tail = _dump(doc).split(_dump(_ROWS), 1)
    path = os.path.join(out, "report.json")
    with atomic_write(path, "w", root=out, inputs=inputs) as f, \
            atomic_write(os.path.join(out, "report.csv"), "w", root=out, inputs=inputs, newline="") as fc:
        w = csv.DictWriter(fc, fieldnames=CSV_FIELDS, extrasaction="ignore")
        w.writeheader()
        f.write(head + "[")
        n = 0
        for r in rows:  # each record once: it may be rebuilt from the journal as it is read
            f.write(("," if n else "") + "\n  " + _dump(r.report_entry()).replace("\n", "\n  "))
            w.writerow(r.row())
            n += 1
        f.write(("\n ]" if n else "]") + tail)
    return path


def write_reports_from_journal(out: str, input_path: str, model, journal_path: str, start: int,
                               dataset_errors: list[str], interrupted, inputs, recs=None,
                               study: dict | None = None) -> str:
    """:func:`write_reports` from this run's lines of the journal (:func:`lod2energy.run.resume.records_of`
    from byte ``start``, or ``recs`` when given): what the journal says was done is what the
    report says."""
    recs = recs if recs is not None else records_of(journal_path, start)
    return write_reports(out, input_path, model, recs.ordered(), dataset_errors, interrupted, inputs,
                         terrain_of(journal_path, start), study)


def json_ready(doc):
    """``doc`` as it reads back from JSON (numpy values, tuples and mappings made plain)."""
    return json.loads(json.dumps(doc, default=json_default))


class _ReportBuildings:
    """The ``buildings`` of a ``report.json``, parsed one at a time on each iteration (the
    page reads them twice; as one list of dicts they cost ~25 KB a building)."""

    def __init__(self, path: str):
        self.path = path

    def __iter__(self):
        with open(self.path, encoding="utf-8") as f:
            sc = Scanner(f)
            for key in sc.members():
                if key == "buildings" and sc.peek() == "[":
                    for _ in sc.items():
                        yield sc.value()
                    return
                sc.value()


def report_lazily(path: str) -> dict:
    """``report.json`` as ``json.load`` gives it, but its ``buildings`` a :class:`_ReportBuildings`."""
    doc: dict = {}
    with open(path, encoding="utf-8") as f:
        sc = Scanner(f)
        for key in sc.members():
            if key == "buildings" and sc.peek() == "[":
                for _ in sc.items():
                    sc.value()
                doc[key] = _ReportBuildings(path)
            else:
                doc[key] = sc.value()
        sc.end()
    return doc


def write_html_report(report_path: str, input_path: str, records: JournalRecords, spool: str, out: str,
                      tol: Tolerances = DEFAULT, inputs=(), footprints=None, mapper=None, crs=None) -> str:
    """``OUTDIR/report.html`` (:mod:`lod2energy.viz`) from the report, the input buildings and the
    prepared ones of the spool (``records``: the report's, :func:`lod2energy.run.resume.records_of`);
    a page that cannot be written costs one line, never the export.
    ``footprints``: the plan footprints of every object of the input, in input order (a
    :class:`~lod2energy.viz.footprints.FootprintSpill`; without it the input is read again);
    ``mapper``: renders the page's pictures (e.g. on the export's process pool,
    :func:`lod2energy.viz.report.write_report_html`); ``crs``: the user's ``--crs``, for the input
    read again."""
    try:
        def outputs(ids, _inputs) -> dict:  # the panels' prepared buildings, from the spool
            out_b = {}
            for s in records.seqs_of(ids):
                r = records[s]
                if r.outcome == "done" and os.path.exists(spool_path(spool, s)):
                    out_b[r.id] = load_spooled(spool, s)
            return out_b
        path = os.path.join(out, "report.html")
        write_report_for_files(report_lazily(report_path), path, [input_path], tol=tol, outputs=outputs, root=out,
                               input_files=list(inputs), footprints=footprints, mapper=mapper,
                               read_options={"crs": crs} if crs else None)
        return path
    except Exception as e:  # noqa: BLE001 - the page is a view of the report, not an output to check
        err(f"report.html not written: {type(e).__name__}: {e}")
        return ""


def weather_warnings(records: Iterable[BuildingRecord]) -> list[str]:
    """One line per weather station farther than :data:`lod2energy.site.MAX_WEATHER_KM` from
    the buildings it serves (their IDF records' ``weather``)."""
    far: dict[str, list[float]] = {}
    for r in records:
        e = r.export("idf")
        w = (e.extra.get("weather") if e is not None else None) or {}
        d = w.get("distance_km")
        if d is not None and d > MAX_WEATHER_KM:
            far.setdefault(f"{w.get('station')} ({w.get('file')})", []).append(float(d))
    return [f"weather station {k} is {min(v):.0f}-{max(v):.0f} km from {len(v)} building(s): more than "
            f"{MAX_WEATHER_KM:.0f} km, its climate may not be theirs" for k, v in sorted(far.items())]


def warning_summary(records: Iterable[BuildingRecord]) -> list[str]:
    """The console's warnings by kind (:func:`lod2energy.viz.warnings.warning_lines`): the rows
    of report.html's "Warnings by kind" table, read from the same report.json entries (the
    study's own warnings are logged when they arise)."""
    tally = WarningTally()
    for row in iter_rows({"buildings": (r.report_entry() for r in records)}):
        tally.add(row.id, row.warnings)
    return warning_lines(tally.table())


def print_export_summary(records: Iterable[BuildingRecord], formats: Iterable[str], outdir: str,
                         terrain: Iterable[dict] = ()) -> None:
    """The table ``lod2energy export`` prints, then a line for each file that carries the
    input's terrain (``terrain``: :attr:`lod2energy.pipeline.ExportOutcome.terrain`)."""
    formats = [f for f in FORMATS if f in set(formats)]
    n = comp = rep = timeouts = 0
    down: dict[str, int] = {}
    ok = dict.fromkeys(formats, 0)
    sources: dict[str, Counter] = {f: Counter() for f in ("year", "storeys", "use")}
    maps: Counter = Counter()
    for r in records:  # one pass: ``records`` may rebuild each record as it is read
        if not (r.type == "Building" or r.assessed):
            continue
        n += 1
        facts = r.thermal.detail.get("facts") or {}
        for f, c in sources.items():
            if f in facts:
                c[facts[f].get("source", "")] += 1
        if r.thermal.detail.get("attribute_map"):
            maps[r.thermal.detail["attribute_map"]] += 1
        comp += bool(r.energy.compliant)
        rep += r.repair.stage not in ("", "valid", "none", "irreparable")
        timeouts += r.outcome == "timeout"
        for kind in {d.kind for d in r.downgrades}:
            down[kind] = down.get(kind, 0) + 1
        for f in formats:
            ok[f] += bool(r.export(f) and r.export(f).ok)
    print(f"{'buildings':>9} {'compliant':>9} {'repaired':>8}  " + "  ".join(f"{f} ok" for f in formats))
    cells = [f"{ok[f]}/{n}" for f in formats]
    print(f"{n:>9} {comp:>9} {rep:>8}  " + "  ".join(f"{c:>8}" for c in cells)
          + (f"  ({timeouts} timeout)" if timeouts else ""))
    if maps:
        print(f"attribute map: {', '.join(sorted(maps))}; " + "; ".join(
            f"{f} from " + ", ".join(f"{k} {v}" for k, v in c.most_common()) for f, c in sources.items() if c))
    if down:
        print("energy model downgraded: " + ", ".join(f"{k} {down[k]}" for k in KINDS if k in down)
              + " building(s) (report.csv: downgrades)")
    for t in terrain:
        print(f"terrain: {t['objects']} TINRelief object(s), {t['faces']} faces, carried into {t['path']}")
    print(f"report: {os.path.join(outdir, 'report.json')} and report.csv")
