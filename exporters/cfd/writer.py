"""The CFD writer: :func:`export_case` writes (and with ``--mesh`` meshes and checks) the OpenFOAM case."""
from __future__ import annotations

import time
from pathlib import Path
from typing import Any

from lod2energy.errors import Lod2EnergyError, ParameterError
from lod2energy.exporters.cfd.case import build_case, write_case
from lod2energy.exporters.cfd.mesh import have_openfoam, run_mesh
from lod2energy.exporters.cfd.options import CfdOptions
from lod2energy.exporters.cfd.region import make_region
from lod2energy.exporters.cfd.terrain import tin_of
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.safe_write import write_json

#: Carved volume must agree with the united surfaces' volume within this fraction.
VOLUME_TOLERANCE = 0.05


def _result(ok: bool, path: str, problems: tuple, stats: dict, ids=()) -> ExportResult:
    return ExportResult(tuple(ids), path, ok, tuple(problems), None, stats=stats, record={"cfd": dict(stats)})


def export_case(buildings, model, outdir: str | Path, options: CfdOptions | None = None) -> ExportResult:
    """Write (and with ``options.mesh`` mesh and check) the OpenFOAM case ``outdir/cfd``.

    Parameters
    ----------
    buildings : iterable of Building
        Prepared buildings (validated, repaired, labelled: ``pipeline.prepare``); features of
        type ``TINRelief`` among them are used as the terrain, other non-buildings are ignored.
    model : CityModel or None
        For the CRS and the source path.
    outdir : path
        OUTDIR; the case goes to ``outdir/cfd``.
    options : CfdOptions

    Returns
    -------
    ExportResult
        ``ok``: the surfaces passed surfaceCheck and (with ``mesh``) checkMesh said "Mesh OK" and
        the carved volume is within 5% of the united surfaces' volume; ``path``: the case folder
        ("" when nothing was written); ``stats`` (also the records' ``cfd``): buildings
        included / excluded / failed, domain, mesh plan, surface checks, times, and with ``mesh``
        the checkMesh figures and volumes; ``building_ids``: the buildings in the case. Never raises for bad geometry: a building that cannot be triangulated is left out (listed
        in ``stats["buildings_failed"]``); a region without buildings gives ``ok=False``.
    """
    options = options or CfdOptions()
    t0 = time.perf_counter()
    blist = list(buildings)
    region = make_region(options.region, options.centre, options.radius)
    crs = getattr(model, "crs", None)
    source = getattr(model, "source", "") or ""
    frame = getattr(model, "frame", None)
    frame_note = ("" if frame is None else
                  "geographic input: coordinates are the local metric frame of report.json (local_frame)"
                  if frame.geographic else
                  f"input in {frame.unit}: coordinates converted to metres (report.json: unit_conversion)")
    tin = tin_of([b for b in blist if b.type == "TINRelief"])
    try:
        case = build_case(blist, region, options.wind_direction, options.cell_size, options.gap,
                          options.lod, terrain=tin)
    except (ParameterError, ValueError) as e:
        return _result(False, "", (f"CFD case not written: {e}",), {"region": region.as_dict()})
    t_build = time.perf_counter() - t0
    try:
        cdir, checks, problems = write_case(case, outdir, source=source, crs=crs, iterations=options.iterations,
                                            processors=options.processors, frame_note=frame_note)
    except (Lod2EnergyError, ValueError, OSError) as e:
        return _result(False, "", (f"CFD case not written: {type(e).__name__}: {e}",), {"region": region.as_dict()},
                       case.included)
    t_write = time.perf_counter() - t0 - t_build
    stats: dict[str, Any] = {
        "region": region.as_dict(),
        "buildings_included": len(case.included), "buildings_excluded": len(case.excluded),
        "buildings_failed": [{"id": i, "reason": m} for i, m in case.failed],
        "ground": "terrain" if case.terrain else "flat",
        "domain": {k: v for k, v in case.domain.as_dict().items() if k != "corners"},
        "mesh_plan": case.mesh.as_dict(),
        "united_bodies": case.united.bodies,
        "united_volume_m3": round(case.united.volume_above_ground, 3),
        "surface_checks": {k: v["ok"] for k, v in checks.items()},
        "seconds_case": round(t_build + t_write, 2),
    }
    problems = list(problems)
    for i, m in case.failed:
        problems.append(f"building {i} left out: {m}")
    if options.mesh:
        mesh_stats, mesh_problems = mesh_and_check(cdir, case, options.nice, root=outdir)
        stats["mesh"] = mesh_stats
        problems.extend(mesh_problems)
    fatal = [p for p in problems if not p.startswith("building ")]
    return _result(not fatal, str(cdir), tuple(problems), stats, case.included)


def mesh_and_check(cdir: Path, case, nice: int = 10, root=None) -> tuple[dict, list[str]]:
    """Run the meshing chain in ``cdir`` and compare the carved volume with the union's."""
    if not have_openfoam():
        return {"ran": False}, ["--mesh: OpenFOAM (blockMesh, snappyHexMesh, checkMesh) not found: apt-get install openfoam"]
    run = run_mesh(cdir, nice=nice)
    problems = list(run.problems)
    st: dict[str, Any] = {"ran": True, "ok": run.ok, "seconds": run.seconds,
                          "seconds_total": round(sum(run.seconds.values()), 2)}
    chk = run.check
    if chk is not None:
        st.update(check_mesh_ok=chk.ok, cells=chk.cells, max_non_orthogonality=chk.max_non_orthogonality,
                  max_skewness=chk.max_skewness, failed_checks=chk.failed_checks, patches=chk.patches,
                  mesh_volume_m3=chk.total_volume)
        if chk.total_volume is not None and case.united.volume_above_ground > 0:
            box = fluid_box_volume(case)
            carved = box - chk.total_volume
            rel = (carved - case.united.volume_above_ground) / case.united.volume_above_ground
            st.update(domain_volume_m3=round(box, 3), carved_volume_m3=round(carved, 3),
                      united_volume_m3=round(case.united.volume_above_ground, 3), carved_volume_error=round(rel, 5))
            if abs(rel) > VOLUME_TOLERANCE:
                problems.append(f"carved volume {carved:.1f} m3 differs from the united surfaces' "
                                f"{case.united.volume_above_ground:.1f} m3 by {100 * rel:+.1f}% (limit 5%)")
    write_json(cdir / "mesh.json", st, root=root if root is not None else cdir.parent)
    return st, problems


def fluid_box_volume(case) -> float:
    """Volume (m3) the mesh would fill without buildings: the domain box (above the terrain)."""
    return case.fluid_volume_without_buildings or case.domain.volume


def _write(buildings, outdir, options, *, model=None, **_):
    """The case ``OUTDIR/cfd`` of the region's buildings: one record for every building in the
    case; ``buildings`` may hold a TINRelief (the ground)."""
    return [export_case(list(buildings), model, outdir, options)]


# export_case runs surfaceCheck (and checkMesh) itself: nothing left to check
register_writer("cfd", _write, lambda path: [], scope="dataset")
