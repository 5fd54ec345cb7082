"""Writer registry: every export format the pipeline can write, found by its name.

As the reader registry of :mod:`lod2energy.io` maps suffixes to readers, this maps a format
name ("idf", "stl", "cityjson", "cfd", "geojson", "gpkg", "urbanopt", "cea", "hbjson") to its
writer. Each format is a package of
:mod:`lod2energy.exporters` whose ``writer`` module registers its writer when it is imported
(meshio's way); :func:`writers` imports the modules of :data:`FORMATS`.

A format's ``write(buildings, outdir, options, *, crs, context, model, stem, tol, frame)``
returns a list of :class:`~lod2energy.exporters.result.ExportResult`; the registry wraps it
in one uniform adapter returning the ``(building ids, ExportRecord)`` pairs of the buildings
(:class:`WriteResults`), and says in which pass of the pipeline it runs (:attr:`Writer.scope`):

- ``"building"``: one building at a time, nothing else needed (STL in building mode);
- ``"context"``: one building at a time with its neighbours (IDF in building mode: party walls
  and ``--shading``);
- ``"dataset"``: one file for all buildings (IDF / STL in dataset mode, CityJSON, GeoJSON, GPKG, CFD).
"""
from __future__ import annotations

import importlib
import os
from dataclasses import dataclass
from functools import partial
from typing import Any, Callable, Iterable, Sequence

from lod2energy.exporters.result import ExportResult
from lod2energy.exporters.run_results import record_results
from lod2energy.records import LEFT_OUT, ExportRecord, FileRecord

#: The modules that register a writer when imported.
FORMATS = tuple(f"lod2energy.exporters.{m}.writer" for m in ("energyplus", "stl", "cityjson", "cfd", "geojson",
                                                                         "gpkg", "urbanopt", "cea", "hbjson"))
#: The order the writers run in: the CityJSON and the footprints carry the results of the IDF's
#: EnergyPlus runs.
_ORDER = ("idf", "stl", "cityjson", "cfd", "gpkg", "geojson", "urbanopt", "cea", "hbjson")


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
        neighbours (the IDF's energy model, :func:`lod2energy.energy.model.with_energy_model`);
        it records what it did in the buildings. Default: the buildings as they are.
    """

    name: str
    write: Callable[..., list]
    self_check: Callable[..., list]
    scope: Callable[[Any], str]
    halo: Callable[[Any], float] = lambda options: 0.0
    records: bool = False
    prepare: Callable[..., Sequence] = None  # type: ignore[assignment] - set in __post_init__

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
                    prepare: Callable[..., Sequence] | None = None) -> Writer:
    """Register (or replace) the writer of format ``name``; returns it.

    ``write`` returns a list of :class:`ExportResult`; the registered :attr:`Writer.write`
    returns their records (:func:`records_of`).
    """
    sc = scope if callable(scope) else (lambda options, _s=scope: _s)
    ha = halo if callable(halo) else (lambda options, _h=float(halo): _h)
    w = Writer(name, partial(_write, name, write), self_check, sc, ha, bool(records), prepare)
    _WRITERS[name] = w
    return w


def _load() -> None:
    for m in FORMATS:
        importlib.import_module(m)


def writer(name: str) -> Writer:
    """The registered writer of ``name`` (KeyError when there is none)."""
    _load()
    return _WRITERS[name]


def writers(names: Iterable[str] | None = None) -> list[Writer]:
    """Registered writers in the order they run (only ``names`` when given)."""
    _load()
    wanted = set(_WRITERS if names is None else names)
    rank = {n: i for i, n in enumerate(_ORDER)}
    return sorted((w for n, w in _WRITERS.items() if n in wanted), key=lambda w: rank.get(w.name, len(rank)))


def as_sequence(buildings) -> Sequence:
    """``buildings`` as a sequence: a Sequence (the spool) as it is, streamed, never all in memory."""
    return buildings if isinstance(buildings, Sequence) else list(buildings)


# ----------------------------------------------------------------------------- records

#: ExportResult fields copied into the records' ``extra`` when set.
_RESULT_EXTRA = ("offset", "heating_kwh", "cooling_kwh", "severe_errors", "not_enclosed", "warnings")


class WriteResults(list):
    """The ``(building ids, ExportRecord)`` pairs of one write, with the writer's notes for the user
    and, for a file that carries the input's terrain, ``terrain``: a dict (format, path, ok,
    objects, faces, ids) for the report (None otherwise)."""

    def __init__(self, items=(), notes: tuple[str, ...] = (), terrain: dict | None = None):
        super().__init__(items)
        self.notes = notes
        self.terrain = terrain


def _write(fmt: str, write: Callable[..., list], *args, **kwargs) -> WriteResults:
    return records_of(fmt, write(*args, **kwargs))


def _files(*paths: str) -> tuple[FileRecord, ...]:
    out = []
    for p in paths:
        if p and os.path.isfile(p):
            fr = FileRecord.of(p)
            if fr is not None:
                out.append(fr)
    return tuple(out)


def records_of(fmt: str, results: Sequence[ExportResult]) -> WriteResults:
    """The ``(building ids, ExportRecord)`` pairs of a writer's results, in order.

    A file written for many given buildings, some left out (:attr:`ExportResult.given`), gives
    each given building its own record (the first three problems; a left-out one its reason);
    a file of several buildings with run figures gives each its own figures.
    """
    out, notes, terrain = [], (), None
    for res in results:
        path = str(res.path)
        files = _files(path, *res.sidecars) if res.ok else ()
        notes += tuple(res.notes)
        if res.terrain:
            terrain = {"format": fmt, "path": path, "ok": res.ok, "objects": len(res.terrain),
                       "faces": sum(int(t[1]) for t in res.terrain), "ids": [str(t[0]) for t in res.terrain]}
        if res.given is not None:
            left = dict(res.skipped)
            for bid in res.given:
                if bid in left:
                    out.append(((bid,), ExportRecord(fmt, False, path.removesuffix(".invalid"),
                                                      (f"{LEFT_OUT}{left[bid]}",))))
                else:
                    out.append(((bid,), ExportRecord(fmt, res.ok, path, tuple(res.problems)[:3], {}, files)))
            continue
        extra = dict(res.record)
        for k in _RESULT_EXTRA:
            v = getattr(res, k)
            if v is not None and v != ():
                extra[k] = list(v) if isinstance(v, tuple) else v
        ids, problems, stats = tuple(res.building_ids), tuple(res.problems), res.stats
        if stats.get("downgrades"):  # building id -> the energy model's downgrades (records.Downgrade)
            extra["downgrades"] = {str(k): list(v) for k, v in stats["downgrades"].items()}
        if stats.get("envelope"):  # building id -> areas by boundary and UA of the written model
            extra["envelope"] = {str(k): dict(v) for k, v in stats["envelope"].items()}
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
    return WriteResults(out, notes, terrain)


@dataclass(frozen=True)
class CityJsonOptions:
    """Options of the CityJSON writer (``version``: "1.0", "1.1", "2.0" or None for the input's)."""

    version: str | None = None
