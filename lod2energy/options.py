"""What an export computes and how it runs: :class:`ExportOptions` (with :class:`PrepareOptions`),
:class:`RunOptions`, and their completion from the input file (:func:`resolve`).

The options are frozen and picklable: they travel with every job to the workers.
"""
from __future__ import annotations

import csv
import io
import os
import re
from dataclasses import asdict, dataclass, field, replace
from importlib.resources import files
from typing import Any, Mapping

from lod2energy.cache import digest
from lod2energy.config import DEFAULT, Tolerances, tolerances
from lod2energy.errors import ParameterError
from lod2energy.model import CityModel
from lod2energy.thermal import ThermalOptions, country_from_crs
from lod2energy.thermal.attributes import load_attribute_map

#: Writers in the order they run and appear in the options.
FORMATS = ("cityjson", "idf", "stl", "cfd", "geojson", "gpkg", "urbanopt", "cea", "hbjson")
#: Writers that need the buildings' real positions (a site, latitude / longitude): refused for
#: a file with no CRS pyproj reads unless ``--crs`` gives one; the others take metres.
NEEDS_POSITIONS = ("idf", "geojson", "gpkg", "urbanopt", "cea")


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
    thermal: Any = field(default_factory=ThermalOptions)


# The writers' option classes come with their format packages (which import their writers):
# loaded when an ExportOptions is made, not when this module is (validate and repair read it).
def _idf_default():
    from lod2energy.exporters.energyplus.options import IdfOptions
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
    buildings : mapping, optional
        The ``--buildings`` table, ``{id: {column: value}}`` (:mod:`lod2energy.thermal.table`):
        each row is joined to its building before the thermal stage.
    ids : tuple of str, optional
        Only these buildings are exported and reported (``--ids``); the others within reach
        of a neighbour writer (party walls, shading) are still prepared as neighbours.
    region : lod2energy.exporters.cfd.region.Region, optional
        Only the buildings whose plan hull meets it (``--region``, ``--centre`` / ``--radius``),
        as with ``ids`` (both given: the buildings of both).
    crs : str or None
        The CRS of the input's coordinates (``--crs``, any form pyproj reads), replacing the
        file's.
    hard_timeout : float or None, s
        Limit of one building's first-pass job, enforced by the executor (CPU time of the
        worker, or ten times that of wall time; the worker is killed and replaced, the
        building reported ``timeout``). Default: the repair budget itself (``--timeout``,
        :func:`hard_budget`).
    """

    formats: tuple[str, ...] = ()
    prepare: PrepareOptions = field(default_factory=PrepareOptions)
    idf: Any = field(default_factory=_idf_default)
    stl: Any = field(default_factory=_stl_default)
    cityjson: Any = field(default_factory=_cityjson_default)
    hard_timeout: float | None = None
    cfd: Any = None
    html: bool = True
    buildings: Any = None
    ids: tuple[str, ...] | None = None
    region: Any = None
    crs: str | None = None

    def writer_options(self, name: str):
        # the footprints and the hand-offs (URBANopt, CEA, honeybee) carry the energy model's figures:
        # they take its options
        return {"idf": self.idf, "stl": self.stl, "cityjson": self.cityjson, "cfd": self.cfd,
                "geojson": self.idf, "gpkg": self.idf, "urbanopt": self.idf, "cea": self.idf, "hbjson": self.idf}[name]

    @property
    def job_timeout(self) -> float | None:
        if self.hard_timeout is not None:
            return self.hard_timeout if self.hard_timeout > 0 else None
        return hard_budget(self.prepare.timeout, margin=False)

    def fingerprint(self) -> dict:
        """JSON-ready summary of everything that changes the outputs (the journal header)."""
        th = self.prepare.thermal
        amap = getattr(th, "attribute_map", None)
        plain = replace(self, buildings=None, prepare=replace(self.prepare, thermal=replace(th, attribute_map=None))
                        if amap is not None else self.prepare)
        d = asdict(plain)
        d.pop("hard_timeout", None)
        if amap is not None:
            d["prepare"]["thermal"]["attribute_map"] = {"name": amap.name, "digest": digest(amap).hex()}
        d["buildings"] = (digest(sorted((k, sorted(v.items())) for k, v in self.buildings.items())).hex()
                          if self.buildings else None)
        if d.get("crs") is None:  # the file's own CRS: journals of earlier versions stay resumable
            d.pop("crs", None)
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


def hard_budget(timeout: float | None, margin: bool = True) -> float | None:
    """The executor's limit for one building's job (s); None without a budget.

    Parameters
    ----------
    timeout : float or None, s
        The budget (``--timeout``).
    margin : bool
        Add ``max(2 s, 20 %)`` for the steps the repair's ladder takes after its own deadline
        (``lod2energy repair``, whose job is the repair alone). ``export`` passes False: there
        ``--timeout S`` bounds the whole job of a building, which is stopped after ``S`` s of
        its worker's CPU time (or ``WALL_FACTOR * S`` s of wall time, see
        :mod:`lod2energy.run.executor`). The ladder works to a wall-clock deadline of the same
        ``S`` s, which on a loaded machine comes first; on an idle one a building whose repair
        runs to its deadline is stopped before its last stages and reported ``timeout``.
    """
    if not timeout or timeout <= 0:
        return None
    return float(timeout) + max(2.0, 0.2 * timeout) if margin else float(timeout)


def ladder_budget(timeout: float | None) -> float | None:
    """The repair ladder's own deadline inside an ``export`` job (s): ``timeout`` less
    ``max(1 s, 20 %)``, so that the cheap reconstructions it escalates to when the deadline
    passes (footprint extrusion, hull) can finish before the executor stops the job at
    ``timeout`` (:func:`hard_budget` without margin). None or 0 keeps the value as given."""
    if not timeout or timeout <= 0:
        return timeout
    return float(timeout) - max(1.0, 0.2 * float(timeout))


def prepare_options(a, tol: Tolerances = DEFAULT, crs: str | None = None) -> PrepareOptions:
    """:class:`PrepareOptions` from a namespace of CLI options (absent ones: defaults)."""
    kw = {"crs": crs, "lod": getattr(a, "lod", None)}
    for name in ("country", "u_table", "u_wall", "u_roof", "u_ground", "u_window", "wwr", "use"):
        v = getattr(a, name, None)
        if v is not None:
            kw[name] = v
    if getattr(a, "attribute_map", None) is not None:
        kw["attribute_map"] = load_attribute_map(a.attribute_map)
    timeout = getattr(a, "timeout", 30.0)
    return PrepareOptions(tol, getattr(a, "lod", None), 30.0 if timeout is None else float(timeout),
                          bool(getattr(a, "merge_parts", False)), ThermalOptions(**kw))


def default_weather(country: str | None) -> str | None:
    """The bundled EPW for ``country`` (only NL ships one), else None."""
    if (country or "").upper() != "NL":
        return None
    p = files("lod2energy") / "data" / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"
    return str(p) if p.is_file() else None


def resolve(options: ExportOptions, model: CityModel) -> ExportOptions:
    """``options`` completed from the file: the CRS for the typology, the weather for ``--run``.

    Raises
    ------
    ParameterError
        ``--run`` without a weather file where none ships, a missing weather file, or a
        weather folder without EPW files.
    """
    prep = options.prepare
    if getattr(prep.thermal, "crs", None) is None and model is not None and model.crs:
        prep = replace(prep, thermal=replace(prep.thermal, crs=model.crs))
    md = (model.metadata if model is not None else None) or {}
    ref = md.get("referenceDate") or md.get("creationDate") if isinstance(md, Mapping) else None
    if getattr(prep.thermal, "reference_date", None) is None and ref:
        prep = replace(prep, thermal=replace(prep.thermal, reference_date=str(ref)))
    idf = options.idf
    if "idf" in options.formats:
        weather = idf.weather
        if idf.run and weather is None:
            weather = default_weather(prep.thermal.country or country_from_crs(model.crs))
            if weather is None:
                raise ParameterError("--run needs --weather EPW (a weather file ships only for the Netherlands)")
        if weather is not None and not os.path.isfile(weather):
            if not os.path.isdir(weather):
                raise ParameterError(f"--weather {weather}: no such file or folder")
            if not any(n.lower().endswith(".epw") for n in os.listdir(weather)):
                raise ParameterError(f"--weather {weather}: no EPW file in the folder")
        if options.prepare.lod is not None and idf.lod is None:
            idf = replace(idf, lod=options.prepare.lod)
        idf = replace(idf, weather=weather)
    stl = options.stl
    if options.prepare.lod is not None and stl.lod is None:
        stl = replace(stl, lod=options.prepare.lod)
    return replace(options, prepare=prep, idf=idf, stl=stl)


def chosen_formats(a) -> tuple[str, ...]:
    """The writers ``export``'s parsed arguments choose (``--idf``, ``--stl``, ...), in :data:`FORMATS` order."""
    return tuple(f for f in FORMATS if getattr(a, f, False))


def export_options(a) -> "ExportOptions":
    """:class:`ExportOptions` from the parsed ``export`` arguments (ParameterError for a bad one)."""
    from lod2energy.exporters.cfd.options import options_from_args, region_from_args
    from lod2energy.exporters.energyplus.options import IdfOptions, parse_run_period
    from lod2energy.exporters.registry import CityJsonOptions
    from lod2energy.exporters.stl import StlOptions

    formats = chosen_formats(a)
    if not formats:
        raise ParameterError("choose at least one of " + ", ".join(f"--{f}" for f in FORMATS))
    if a.wwr is not None and not (0.0 <= a.wwr < 1.0):
        raise ParameterError("--wwr must be in [0, 1)")
    for c in ("wall", "roof", "ground", "window"):
        v = getattr(a, f"u_{c}")
        if v is not None and not (v > 0 and v < 100):
            raise ParameterError(f"--u-{c} must be a positive U-value in W/(m2 K)")
    if getattr(a, "run_period", None) and not a.idf:
        raise ParameterError("--run-period is for the IDF (--idf, --run)")
    if a.jobs is not None and a.jobs < 0:
        raise ParameterError("--jobs must be >= 0 (0: all cores)")
    if not (a.timeout > 0) or a.timeout != a.timeout:
        raise ParameterError("--timeout must be a positive number of seconds")

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
    return ExportOptions(formats, prepare_options(a, tolerances(a)), idf,
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
            raise ParameterError(f"--ids {spec}: cannot read: {getattr(e, 'strerror', None) or 'not UTF-8 text'}") from None
        head = [c.strip() for c in re.split(r"[,;\t]", text.split("\n", 1)[0])]
        if "id" in head and len(head) > 1:
            delim = next(d for d in ",;\t" if d in text.split("\n", 1)[0])
            text = ",".join(r.get("id") or "" for r in csv.DictReader(io.StringIO(text), delimiter=delim))
    ids = tuple(dict.fromkeys(t.strip() for t in text.replace("\n", ",").replace("\r", ",").split(",")
                              if t.strip() and not t.strip().startswith("#")))
    if not ids:
        raise ParameterError(f"--ids {spec}: no id given")
    return ids
