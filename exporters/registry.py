"""Writer registry: every export format the pipeline can write, found by its name.

As the reader registry of :mod:`lod2energy.io` maps suffixes to readers, this maps a format
name ("idf", "stl", "cityjson") to its writer and self-check. The pipeline iterates the
registry; a new format is one :func:`register_writer` call.

Each writer keeps its module's call shape ``write(buildings, outdir, options, ..., crs=...)``;
the registry wraps it in one uniform adapter::

    write(buildings, outdir, options, *, crs=None, context=(), model=None, stem="out", tol=None)
        -> list of (building ids, ExportRecord)

and says in which pass of the pipeline it runs (:attr:`Writer.scope`):

- ``"building"``: one building at a time, nothing else needed (STL in building mode);
- ``"context"``: one building at a time with its neighbours (IDF in building mode: party walls
  and ``--shading``);
- ``"dataset"``: one file for all buildings (IDF / STL in dataset mode, CityJSON).
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Callable, Iterable, Sequence

from lod2energy.records import LEFT_OUT, ExportRecord, FileRecord


@dataclass(frozen=True)
class Writer:
    """One registered export format.

    Parameters
    ----------
    name : str
        Format name, the CLI flag without dashes ("idf").
    write : callable
        The uniform adapter (see the module docstring).
    self_check : callable(path) -> list of str
        The format's self-check (empty list: the file is good).
    scope : callable(options) -> {"building", "context", "dataset"}
        The pass the writer runs in, for its options.
    halo : callable(options) -> float, m
        How far around a building its neighbours matter (``"context"`` scope).
    records : bool
        The writer also takes ``records=`` (the buildings' :class:`BuildingRecord` s, with
        the other writers' results) in the ``"dataset"`` pass.
    prepare : callable(buildings, options, context=()) -> sequence of Building
        The stage that runs just before this writer, in the same pass and with the same
        neighbours (the IDF's energy model, :mod:`lod2energy.energy.model`); it records
        what it did in the buildings' provenance. Default: the buildings as they are.
    """

    name: str
    write: Callable[..., list]
    self_check: Callable[..., list]
    scope: Callable[[Any], str]
    halo: Callable[[Any], float] = lambda options: 0.0
    records: bool = False
    prepare: Callable[..., list] = None  # type: ignore[assignment] - set in __post_init__

    def __post_init__(self):
        if self.prepare is None:
            object.__setattr__(self, "prepare", _as_given)


_WRITERS: dict[str, Writer] = {}


def _as_given(buildings, options, context=()):
    """No stage before the writer: the buildings as they are (the same sequence, so that a
    streamed one - the spool read one building at a time - stays streamed)."""
    return buildings


def register_writer(name: str, write: Callable[..., list], self_check: Callable[..., list], *,
                    scope: Callable[[Any], str] | str = "building",
                    halo: Callable[[Any], float] | float = 0.0, records: bool = False,
                    prepare: Callable[..., list] | None = None) -> Writer:
    """Register (or replace) the writer of format ``name``; returns it."""
    sc = scope if callable(scope) else (lambda options, _s=scope: _s)
    ha = halo if callable(halo) else (lambda options, _h=float(halo): _h)
    w = Writer(name, write, self_check, sc, ha, bool(records), prepare)
    _WRITERS[name] = w
    return w


def writer(name: str) -> Writer:
    """The registered writer of ``name`` (KeyError when there is none)."""
    return _WRITERS[name]


def writers(names: Iterable[str] | None = None) -> list[Writer]:
    """Registered writers, in registration order (only ``names`` when given)."""
    if names is None:
        return list(_WRITERS.values())
    wanted = set(names)
    return [w for n, w in _WRITERS.items() if n in wanted]


# ----------------------------------------------------------------------------- adapters

_RESULT_EXTRA = ("offset", "heating_kwh", "cooling_kwh", "severe_errors", "not_enclosed", "warnings")


def _files(*paths: str) -> tuple[FileRecord, ...]:
    out = []
    for p in paths:
        if p and os.path.isfile(p):
            fr = FileRecord.of(p)
            if fr is not None:
                out.append(fr)
    return tuple(out)


def _records(fmt: str, results: Sequence, sidecars: Callable[[str], Sequence[str]] = lambda p: ()) -> list:
    from lod2energy.exporters.run_results import record_results
    out = []
    for res in results:
        extra = {}
        for k in _RESULT_EXTRA:
            v = getattr(res, k, None)
            if v is not None and v != ():
                extra[k] = list(v) if isinstance(v, tuple) else v
        path = str(res.path)
        files = _files(path, *sidecars(path)) if res.ok else ()
        ids = tuple(getattr(res, "building_ids", ()) or ())
        problems = tuple(getattr(res, "problems", ()) or ())
        stats = getattr(res, "stats", None) or {}
        if stats.get("input_windows") or stats.get("input_doors"):  # LoD3: the input's own, in the file
            extra["openings"] = {"Window": int(stats.get("input_windows") or 0), "Door": int(stats.get("input_doors") or 0)}
        # a run's figures are stored once, as ``results``; the report's flat figures and per-zone
        # list are derived from them (lod2energy.records.run_figures)
        totals = {str(k): v for k, v in (stats.get("building_results") or {}).items()}
        if len(ids) > 1 and totals:  # one file of many buildings: each gets its own figures
            for bid in ids:
                d = totals.get(str(bid)) or {}
                own = {**extra, "heating_kwh": d.get("heating_kwh"), "cooling_kwh": d.get("cooling_kwh"),
                       "results": record_results(stats, bid)}
                out.append(((bid,), ExportRecord(fmt, bool(res.ok), path, problems, own, files)))
            continue
        if len(ids) == 1 and str(ids[0]) in totals:
            extra["results"] = record_results(stats, ids[0])
        out.append((ids, ExportRecord(fmt, bool(res.ok), path, problems, extra, files)))
    return WriteResults(out)


def _idf_scope(options) -> str:
    return "dataset" if getattr(options, "mode", "building") == "dataset" else "context"


def _idf_halo(options) -> float:
    # party walls are faces within a few cm of each other; shading reaches shading_radius
    return float(options.shading_radius) if getattr(options, "shading", False) else 1.0


def _prepare_idf(buildings, options, context=()):
    """The energy model stage before the IDF writer (:func:`lod2energy.energy.model.with_energy_model`)."""
    from lod2energy.energy.model import with_energy_model
    return with_energy_model(buildings, options, context)


def _write_idf(buildings, outdir, options, *, crs=None, context=(), model=None, stem="out", tol=None, frame=None):
    from lod2energy.exporters.energyplus.writer import write
    return _records("idf", write(buildings, outdir, options, crs=crs, context=context, frame=frame))


def _stl_sidecar(path: str) -> list[str]:
    return [path[:-4] + ".json"] if path.endswith(".stl") else []


def _write_stl(buildings, outdir, options, *, crs=None, context=(), model=None, stem="out", tol=None, frame=None):
    from lod2energy.exporters.stl import writer as stl
    from lod2energy.repair.parts import input_parts  # the union of the input parts (issue 19)
    buildings = [input_parts(b) for b in buildings]
    return _records("stl", stl.write(buildings, outdir, options, crs=crs), _stl_sidecar)


def _write_cityjson(buildings, outdir, options, *, crs=None, context=(), model=None, stem="out", tol=None,
                    frame=None):
    """One Energy-ADE CityJSON for all ``buildings``: a record for each, ok or left out; the
    input's terrain (TINRelief) it carries gets no record but the results' ``terrain``."""
    from lod2energy.exporters.cityjson import writer as cityjson
    if not isinstance(buildings, Sequence):
        buildings = list(buildings)  # a Sequence (the spool) is streamed, never all in memory
    path = os.path.join(str(outdir), f"{stem}.energy.city.json")
    res = cityjson.write(path, model, buildings, version=getattr(options, "version", None), tol=tol)
    ok = bool(getattr(res, "ok", False))
    skipped = dict(getattr(res, "skipped", ()) or ())
    files = _files(str(res.path), getattr(res, "extension_path", "") or "") if ok else ()
    terrain = tuple(getattr(res, "terrain", ()) or ())
    carried = {str(t[0]) for t in terrain}
    out = []
    for bid, btype in getattr(buildings, "heads", None) or [(b.id, b.type) for b in buildings]:
        if (bid in skipped or bid in carried) and btype != "Building":
            continue  # terrain, vegetation ...: not part of the energy model, never a failure
        if bid in skipped:
            out.append(((bid,), ExportRecord("cityjson", False, path, (f"{LEFT_OUT}{skipped[bid]}",))))
        else:
            out.append(((bid,), ExportRecord("cityjson", ok, str(res.path),
                                              tuple(getattr(res, "problems", ()) or ())[:3], {}, files)))
    notes = tuple(getattr(res, "notes", ()) or ())
    summary = None
    if terrain:
        faces = sum(int(t[1]) for t in terrain)
        summary = {"format": "cityjson", "path": str(res.path), "ok": ok, "objects": len(terrain),
                   "faces": faces, "ids": [str(t[0]) for t in terrain]}
    return WriteResults(out, notes, summary)


class WriteResults(list):
    """The ``(building ids, ExportRecord)`` pairs of one write, with the writer's notes for the user
    and, for a file that carries the input's terrain, ``terrain``: a dict (format, path, ok,
    objects, faces, ids) for the report (None otherwise)."""

    def __init__(self, items=(), notes: tuple[str, ...] = (), terrain: dict | None = None):
        super().__init__(items)
        self.notes = notes
        self.terrain = terrain


@dataclass(frozen=True)
class CityJsonOptions:
    """Options of the CityJSON writer (``version``: "1.0", "1.1", "2.0" or None for the input's)."""

    version: str | None = None


def _cityjson_check(path: str, tol=None) -> list[str]:
    from lod2energy.exporters.cityjson import writer as cityjson
    return cityjson.self_check(path, tol=tol)


def _idf_check(path: str) -> list[str]:
    from lod2energy.exporters.energyplus.check import self_check
    return self_check(path)


def _stl_check(path: str) -> list[str]:
    from lod2energy.exporters.stl import writer as stl
    return stl.self_check(path)


def _write_cfd(buildings, outdir, options, *, crs=None, context=(), model=None, stem="out", tol=None, frame=None):
    """The OpenFOAM case ``OUTDIR/cfd`` of the region's buildings (:func:`lod2energy.exporters.cfd.export_case`):
    one record for every building in the case; ``buildings`` may hold a TINRelief (the ground)."""
    from lod2energy.exporters.cfd import export_case
    res = export_case(list(buildings), model, outdir, options)
    rec = ExportRecord("cfd", bool(res.ok), str(res.path), tuple(res.problems), {"cfd": dict(res.stats)})
    return WriteResults([(tuple(res.building_ids), rec)])


def _cfd_check(path: str) -> list[str]:
    """Nothing to add: :func:`lod2energy.exporters.cfd.export_case` runs surfaceCheck (and checkMesh) itself."""
    return []


register_writer("idf", _write_idf, _idf_check, scope=_idf_scope, halo=_idf_halo, prepare=_prepare_idf)
register_writer("stl", _write_stl, _stl_check,
                scope=lambda options: "dataset" if getattr(options, "mode", "building") == "dataset" else "building")
# after the IDF: the CityJSON carries the results of its EnergyPlus runs (exporters.run_results)
register_writer("cityjson", _write_cityjson, _cityjson_check, scope="dataset")
register_writer("cfd", _write_cfd, _cfd_check, scope="dataset")


def _write_geojson(buildings, outdir, options, *, crs=None, context=(), model=None, stem="out", tol=None,
                   frame=None, records=None):
    """``OUTDIR/<stem>.footprints.geojson``: the footprints (WGS84) with the buildings' records;
    ``options`` are the IDF options (``use``, ``lod``, ``run``: the figures of the energy model)."""
    from lod2energy.exporters.geojson import writer as geojson
    path = os.path.join(str(outdir), f"{stem}{geojson.SUFFIX}")
    res = geojson.write(buildings, path, crs=crs, frame=frame, records=records, use=getattr(options, "use", None),
                        lod=getattr(options, "lod", None), run=bool(getattr(options, "run", False)), root=outdir)
    files = _files(res.path) if res.ok else ()
    out = []
    left = dict(res.left_out or {})
    for bid, _ in res.seen:  # the buildings the writer was given, in order (it streams them)
        if bid in left:
            out.append(((bid,), ExportRecord("geojson", False, res.path, (f"{LEFT_OUT}{left[bid]}",))))
        else:
            out.append(((bid,), ExportRecord("geojson", res.ok, res.path, tuple(res.problems)[:3], {}, files)))
    return WriteResults(out)


def _geojson_check(path: str) -> list[str]:
    from lod2energy.exporters.geojson import writer as geojson
    return geojson.self_check(path)


# after "idf": the footprints carry the run figures of the IDF pass
register_writer("geojson", _write_geojson, _geojson_check, scope="dataset", records=True)
