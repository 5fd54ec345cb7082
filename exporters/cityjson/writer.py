"""Energy-ADE-style CityJSON export of labelled buildings, with a self-check before a file counts.

What is written (through :mod:`lod2energy.io.cityjson`'s writer):

- the energy geometry of every building (the repaired, labelled LoD; other LoDs are left
  out unless ``keep_other_lods``), a semantic surface on every face carrying ``uValue``
  (W/(m2 K)), ``thermalBoundaryType`` (``sharedWallOrFloor`` for a face the written IDF makes a
  party wall, :func:`lod2energy.energy.figures.with_shared_boundaries`), ``area`` (m2),
  ``azimuth`` and ``inclination`` (deg);
- per building, ``+energy...`` attributes on the first-level Building (envelope area,
  volume, UA, typology, construction period, repair stage, energy compliance, ...), defined
  by the CityJSON Extension ``Energy`` shipped in ``lod2energy/data/extensions/<v>/`` and
  referenced under the document's ``"extensions"`` (relative URL ``energy.ext.json``; the
  extension file is copied next to the output);
- the input's terrain (``TINRelief`` city objects) as read, after the buildings, on the same
  grid (:mod:`lod2energy.exporters.cityjson.terrain`);
- CityJSON version: the input's by default, else ``version`` ("1.0", "1.1", "2.0").

Self-check (:func:`self_check`): re-parse the file, validate it against the official
CityJSON schema of its version (bundled copy in ``lod2energy/data/schemas/cityjson``, with
a ``referencing`` registry for the ``$ref`` between schema files), validate the
``+energy`` attributes against the Extension schema, then re-read it with
:func:`lod2energy.io.cityjson.read` and check every energy building's geometry: val3dity
checks (:func:`lod2energy.validate.checks.validate_building`), closed and outward (every
edge used exactly twice in opposite directions, positive volume), every face labelled with
an envelope type and a positive ``uValue``.

Files are written to a temporary name next to the target and moved into place only when
the self-check passes; a file that fails is kept as ``<path>.invalid`` (for inspection) and
``ExportResult.ok`` is False with the problems. Buildings that cannot pass (no thermal
data, or an energy geometry that is not closed / labelled) are left out beforehand and
listed in ``ExportResult.skipped`` when ``exclude_unready`` is True (default).
"""
from __future__ import annotations

import itertools
import os
from dataclasses import replace
from typing import Any, Iterable, Iterator, Sequence

from lod2energy import safe_write
from lod2energy.config import DEFAULT
from lod2energy.energy.figures import with_shared_boundaries
from lod2energy.errors import Lod2EnergyError
from lod2energy.run.memory import give_back
from lod2energy.io import cityjson as cjio, cityjson_write
from lod2energy.io.cityjson_grid import on_grid
from lod2energy.model import Building, CityModel, frozen_mapping
from lod2energy.semantics import strip_to_energy
from lod2energy.validate.closed import export_problem

from lod2energy.exporters.cityjson.check import self_check
from lod2energy.exporters.cityjson.schema import EXTENSION_FILE, extension_schema
from lod2energy.exporters.cityjson.terrain import is_terrain, n_faces, prepare_terrain, terrain_problem
from lod2energy.exporters.cityjson.version import fix_cityobject, fix_header, model_for
from lod2energy.exporters.registry import as_sequence, register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.exporters.run_results import result_attributes

INVALID_SUFFIX = ".invalid"
_STAGED = itertools.count()


# ----------------------------------------------------------------------------- preparing

def _energy_attributes(b: Building) -> dict[str, Any]:
    th = dict(b.provenance.get("thermal") or {})
    rep = dict(b.provenance.get("repair") or {})
    energy = b.provenance.get("energy")
    a: dict[str, Any] = {
        "+energyEnvelopeArea": float(th.get("A_env", 0.0)),
        "+energyVolume": float(th.get("volume", 0.0)),
        "+energyUA": float(th.get("UA", 0.0)),
        "+energyTypology": str(th.get("typology")),
        "+energyConstructionPeriod": str(th.get("construction_period")),
        "+energyYearOfConstruction": th.get("year_of_construction"),
        "+energyCountry": str(th.get("country")),
        "+energyUValues": dict(th.get("u_values") or {}),
        "+energyWindowToWallRatio": float(th.get("wwr", 0.0)),
        "+energyAreas": dict(th.get("areas") or {}),
        "+energyRepairStage": str(rep.get("stage", "none")),
    }
    if rep:  # without its timings: the file is byte-reproducible (they stay in report.json)
        a["+energyRepair"] = _untimed(cityjson_write._plain(rep))
    if energy is not None:
        a["+energyCompliance"] = cityjson_write._plain(energy)
    a.update(result_attributes(b))  # after export --run: the simulated demand and loads
    return a


def _untimed(x: Any) -> Any:
    """``x`` without the members that measure time (``seconds``...), which differ run to run."""
    if isinstance(x, dict):
        return {k: _untimed(v) for k, v in x.items() if "seconds" not in str(k)}
    if isinstance(x, list):
        return [_untimed(v) for v in x]
    return x


def _ready_problem(b: Building, lod: str | None, keep_other_lods: bool = False, tol=None,
                   transform=None, frame=None) -> str | None:
    """Why ``b`` cannot be exported as an energy building (None when it can): the pipeline's
    final check (:func:`lod2energy.validate.closed.export_problem`) on the file's grid
    ``transform`` (default: the building's own, :func:`lod2energy.io.cityjson_grid.building_grid`)."""
    return export_problem(b, lod, tol or DEFAULT, transform=transform, frame=frame, keep_other_lods=keep_other_lods)


def prepare_building(b: Building, lod: str | None = None, keep_other_lods: bool = False) -> Building:
    """The building as exported: energy LoD only, ``+energy`` attributes on the root."""
    lod = lod if lod is not None else (b.provenance.get("thermal") or {}).get("lod") or b.default_lod()
    b = with_shared_boundaries(b, (b.provenance.get("thermal") or {}).get("shared_faces") or {}, lod)
    b = strip_to_energy(b, lod, keep_other_lods)
    root = b.root
    attrs = dict(root.attributes)
    attrs.update(_energy_attributes(b))
    objs = (replace(root, attributes=frozen_mapping(attrs)),) + tuple(b.objects[1:])
    return replace(b, objects=objs)


# ----------------------------------------------------------------------------- writing

def write(path: str, model: CityModel, buildings: Iterable[Building], version: str | None = None, *,
          lod: str | None = None, keep_other_lods: bool = False, exclude_unready: bool = True,
          tol=None) -> ExportResult:
    """Write an Energy-ADE-style CityJSON (``.json``) or CityJSONSeq (``.jsonl``) file.

    Parameters
    ----------
    path : str
        Target file.
    model : CityModel
        File-level data of the input (metadata, transform, extensions, version).
    buildings : iterable of Building
        Output of label + U-value stages (``provenance["thermal"]`` present). Terrain
        features (``TINRelief``, :mod:`lod2energy.exporters.cityjson.terrain`) among them are
        written as they were read and listed in ``ExportResult.terrain``; other
        non-buildings are left out (``skipped``).
    version : str, optional
        "1.0", "1.1" or "2.0"; default: the input's version.
    lod : str, optional
        Energy LoD (default: each building's own).
    keep_other_lods : bool
        Keep the geometries at other LoDs too (they are then also self-checked).
    exclude_unready : bool
        Leave out (and list in ``skipped``) buildings without thermal data or whose energy
        geometry is not closed / labelled; otherwise they are written and fail the check.
    tol : Tolerances, optional
        The user's tolerances, for the acceptance check and the self-check (default: val3dity's).

    Returns
    -------
    ExportResult
    """
    try:
        version = cjio.normalise_version(version or model.version)
    except Lod2EnergyError as e:
        return ExportResult((), path, False, (str(e),), version=str(version))
    if cityjson_write.is_cityjsonseq(path) and version == "1.0":
        return ExportResult((), path, False, ("CityJSONSeq needs CityJSON 1.1 or 2.0",), version=version)
    skipped: list[tuple[str, str]] = []
    written: list[str] = []
    terrain: list[tuple[str, int]] = []
    if not isinstance(buildings, Sequence):
        buildings = list(buildings)
    m, notes = model_for(model, version)
    transform = cityjson_write.transform_for(m, buildings)  # iterates the buildings only without a transform
    if not m.transform:
        m = replace(m, transform=frozen_mapping(transform))

    def prepared() -> Iterator[Building]:
        # one building at a time: a lazy sequence (the export's spool) is never all in memory
        for b in buildings:
            if is_terrain(b):  # the input's terrain, carried as read (one object: bounded memory)
                why = terrain_problem(b)
                if why is not None:
                    skipped.append((b.id, why))
                    continue
                terrain.append((b.id, n_faces(b)))
                yield prepare_terrain(b)
                continue
            blod = lod if lod is not None else (b.provenance.get("thermal") or {}).get("lod")
            # checked as it will be read back: coordinates on the file's grid (a repaired vertex
            # off the grid moves by up to scale/2, which can tip a face over a tolerance)
            b = on_grid(b, transform, m.frame)
            why = _ready_problem(b, blod, keep_other_lods, tol, transform, m.frame) if exclude_unready else None
            if why is not None:
                skipped.append((b.id, why))
                continue
            written.append(b.id)
            yield prepare_building(b, blod, keep_other_lods)
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    base = os.path.basename(path)
    # staged under a name unique per process and call, with the suffix the self-check reads
    tmp = os.path.join(folder, f".{base}.{os.getpid()}.{next(_STAGED)}.tmp"
                       + (".jsonl" if cityjson_write.is_cityjsonseq(path) else ".json"))
    ext_path = os.path.join(folder, EXTENSION_FILE)
    inputs = [model.source] if model.source and os.path.exists(str(model.source)) else []
    try:
        safe_write.write_json(ext_path, extension_schema(version), root=folder, inputs=inputs)
        if cityjson_write.is_cityjsonseq(path):
            cityjson_write.write(tmp, m, prepared(), version, root=folder, inputs=inputs)
        else:
            with safe_write.atomic_write(tmp, "w", root=folder, inputs=inputs) as f:
                cityjson_write.write_document(f, m, prepared(), version, fix_object=lambda co: fix_cityobject(co, version),
                                    fix_header=lambda d: fix_header(d, version), scratch_dir=folder)
    except (OSError, ValueError, TypeError, Lod2EnergyError) as e:
        _remove(tmp)
        ids = tuple(written)
        why = e.strerror if isinstance(e, OSError) and e.strerror else e
        return ExportResult(ids, path, False, (f"cannot write {path}: {why}",), version=version,
                            skipped=tuple(skipped), terrain=tuple(terrain))
    ids = tuple(written)
    give_back()  # the written buildings' pages, before the self-check reads the file again
    try:
        problems = self_check(tmp, extension=extension_schema(version), tol=tol)
        target = path + INVALID_SUFFIX if problems else path
        safe_write.check_target(target, folder, inputs)
        os.replace(tmp, target)
        _remove(path if problems else path + INVALID_SUFFIX)  # never leave an older file that looks like this run's
    except OSError as e:
        _remove(tmp)
        return ExportResult(ids, path, False, (f"cannot write {path}: {e.strerror or e}",), version=version,
                            skipped=tuple(skipped), terrain=tuple(terrain))
    if problems:
        return ExportResult(ids, target, False,
                            tuple(problems) + (f"failed its self-check: kept as {base}{INVALID_SUFFIX}",),
                            version=version, skipped=tuple(skipped), sidecars=(ext_path,), notes=tuple(notes),
                            terrain=tuple(terrain))
    return ExportResult(ids, path, True, (), version=version, skipped=tuple(skipped), sidecars=(ext_path,),
                        notes=tuple(notes), terrain=tuple(terrain))


def _remove(p: str) -> None:
    try:
        os.remove(p)
    except FileNotFoundError:
        pass


def _write(buildings, outdir, options, *, model=None, stem="out", tol=None, **_):
    """One CityJSON for all ``buildings``: a record for each Building, written or left out; the
    input's terrain (TINRelief) it carries and other objects left out get none."""
    buildings = as_sequence(buildings)
    res = write(os.path.join(str(outdir), f"{stem}.energy.city.json"), model, buildings,
                version=options.version if options is not None else None, tol=tol)
    heads = getattr(buildings, "heads", None) or [(b.id, b.type) for b in buildings]
    out = {str(t[0]) for t in res.terrain} | {bid for bid, _ in res.skipped}
    return [replace(res, given=tuple(bid for bid, btype in heads if btype == "Building" or bid not in out))]


# after the IDF: the CityJSON carries the results of its EnergyPlus runs (exporters.run_results)
register_writer("cityjson", _write, self_check, scope="dataset")
