"""CFD case export: a region of a city model as an OpenFOAM v1912 case ready to mesh and run.

Public API (wired into ``lod2energy export --cfd``):

- :class:`CfdOptions` and :func:`add_cli_arguments` / :func:`options_from_args` for the CLI;
- :func:`export_case` ``(buildings, model, outdir, options) -> CfdResult``.

See :mod:`lod2energy.exporters.cfd.domain` (guideline domain), :mod:`lod2energy.exporters.cfd.region` (region
selection), :mod:`lod2energy.exporters.cfd.surfaces` (united buildings, ground), :mod:`lod2energy.exporters.cfd.case`
(the case folder) and :mod:`lod2energy.exporters.cfd.mesh` (running and checking the mesh).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from lod2energy.errors import Lod2EnergyError, ParameterError

#: Default cell size (m) at the building surfaces.
DEFAULT_CELL_SIZE = 2.0
#: Carved volume must agree with the united surfaces' volume within this fraction.
VOLUME_TOLERANCE = 0.05


@dataclass(frozen=True)
class CfdOptions:
    """Options of :func:`export_case`.

    Parameters
    ----------
    region : (xmin, ymin, xmax, ymax) or None
        Rectangle in the input CRS (m).
    centre : (x, y) or None
        Circle centre in the input CRS; with ``radius``.
    radius : float or None, m
    wind_direction : float, deg
        Meteorological: the direction the wind comes from, clockwise from north.
    cell_size : float, m
        Cell size at the building surfaces.
    min_gap : float or None, m
        Gaps narrower than this are closed; None = ``cell_size``; 0 = none.
    mesh : bool
        Also run blockMesh, surfaceFeatureExtract, snappyHexMesh and checkMesh.
    iterations : int
        simpleFoam iterations written in controlDict.
    processors : int
        decomposeParDict subdomains.
    nice : int
        ``nice`` level of the meshing tools (0 = none).
    lod : str or None
        LoD used (default: highest).
    """

    region: tuple[float, float, float, float] | None = None
    centre: tuple[float, float] | None = None
    radius: float | None = None
    wind_direction: float = 270.0
    cell_size: float = DEFAULT_CELL_SIZE
    min_gap: float | None = None
    mesh: bool = False
    iterations: int = 1000
    processors: int = 2
    nice: int = 10
    lod: str | None = None

    def __post_init__(self):
        if not (isinstance(self.cell_size, (int, float)) and math.isfinite(self.cell_size) and self.cell_size > 0):
            raise ParameterError(f"--cell-size must be a positive number of metres, not {self.cell_size!r}")
        if self.min_gap is not None and not (math.isfinite(self.min_gap) and self.min_gap >= 0):
            raise ParameterError(f"--min-gap must be a non-negative number of metres, not {self.min_gap!r}")
        if not math.isfinite(self.wind_direction):
            raise ParameterError(f"--wind-direction must be finite, not {self.wind_direction!r}")
        from lod2energy.exporters.cfd.region import make_region
        make_region(self.region, self.centre, self.radius)  # raises on a bad region

    @property
    def gap(self) -> float:
        return self.cell_size if self.min_gap is None else float(self.min_gap)


@dataclass(frozen=True)
class CfdResult:
    """Outcome of :func:`export_case`.

    Parameters
    ----------
    ok : bool
        Surfaces passed surfaceCheck and (with ``mesh``) checkMesh said "Mesh OK" and the
        carved volume is within 5% of the united surfaces' volume.
    path : str
        The case folder (``OUTDIR/cfd``), "" when nothing was written.
    problems : tuple of str
    stats : mapping
        For report.json: buildings included/excluded/failed, domain, mesh plan, surface checks,
        times, and with ``mesh`` the checkMesh figures and volumes.
    building_ids : tuple of str
        Buildings in the case.
    """

    ok: bool
    path: str
    problems: tuple[str, ...] = ()
    stats: Mapping[str, Any] = field(default_factory=dict)
    building_ids: tuple[str, ...] = ()

    def to_dict(self) -> dict:
        return {"ok": self.ok, "path": self.path, "problems": list(self.problems), "stats": dict(self.stats),
                "building_ids": list(self.building_ids)}


def _floats(text: str, n: int, flag: str) -> tuple[float, ...]:
    try:
        vals = tuple(float(x) for x in str(text).split(","))
    except ValueError:
        raise ParameterError(f"{flag} needs {n} comma-separated numbers, not {text!r}") from None
    if len(vals) != n or not all(math.isfinite(v) for v in vals):
        raise ParameterError(f"{flag} needs {n} comma-separated finite numbers, not {text!r}")
    return vals


def add_cli_arguments(group) -> None:
    """Add ``--cfd --region --centre --radius --wind-direction --cell-size --min-gap --mesh``
    to an argparse parser or argument group."""
    group.add_argument("--cfd", action="store_true",
                       help="write an OpenFOAM v1912 case OUTDIR/cfd/ (domain by COST 732 / AIJ guidelines)")
    group.add_argument("--region", metavar="XMIN,YMIN,XMAX,YMAX", default=None,
                       help="CFD region rectangle in the input CRS (buildings cut by its edge are kept whole)")
    group.add_argument("--centre", metavar="X,Y", default=None, help="CFD region circle centre (input CRS)")
    group.add_argument("--radius", metavar="R", type=float, default=None, help="CFD region circle radius (m)")
    group.add_argument("--wind-direction", metavar="DEG", type=float, default=270.0,
                       help="wind direction in degrees, meteorological: where the wind comes FROM, clockwise "
                            "from north (default 270, westerly)")
    group.add_argument("--cell-size", metavar="M", type=float, default=DEFAULT_CELL_SIZE,
                       help=f"cell size at the buildings in m (default {DEFAULT_CELL_SIZE:g})")
    group.add_argument("--min-gap", metavar="M", type=float, default=None,
                       help="close gaps between buildings narrower than M metres (default: the cell size; 0: none)")
    group.add_argument("--mesh", action="store_true",
                       help="also run blockMesh, surfaceFeatureExtract, snappyHexMesh and checkMesh")


def options_from_args(args) -> CfdOptions:
    """:class:`CfdOptions` from parsed arguments (ParameterError on bad values)."""
    region = getattr(args, "region", None)
    centre = getattr(args, "centre", None)
    return CfdOptions(
        region=_floats(region, 4, "--region") if region is not None else None,
        centre=_floats(centre, 2, "--centre") if centre is not None else None,
        radius=getattr(args, "radius", None),
        wind_direction=float(getattr(args, "wind_direction", 270.0)),
        cell_size=float(getattr(args, "cell_size", DEFAULT_CELL_SIZE)),
        min_gap=getattr(args, "min_gap", None),
        mesh=bool(getattr(args, "mesh", False)),
        lod=getattr(args, "lod", None),
    )


def export_case(buildings, model, outdir: str | Path, options: CfdOptions | None = None) -> CfdResult:
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
    CfdResult
        Never raises for bad geometry: a building that cannot be triangulated is left out (listed
        in ``stats["buildings_failed"]``); a region without buildings gives ``ok=False``.
    """
    from lod2energy.exporters.cfd.case import build_case, write_case
    from lod2energy.exporters.cfd.region import make_region
    from lod2energy.exporters.cfd.terrain import tin_of

    options = options or CfdOptions()
    t0 = time.perf_counter()
    blist = list(buildings)
    region = make_region(options.region, options.centre, options.radius)
    crs = getattr(model, "crs", None)
    source = getattr(model, "source", "") or ""
    frame = getattr(model, "frame", None)
    frame_note = ("geographic input: coordinates are the local metric frame of report.json (local_frame)"
                  if frame is not None else "")
    tin = tin_of([b for b in blist if b.type == "TINRelief"])
    try:
        case = build_case(blist, region, options.wind_direction, options.cell_size, options.gap,
                          options.lod, terrain=tin)
    except (ParameterError, ValueError) as e:
        return CfdResult(False, "", (f"CFD case not written: {e}",), {"region": region.as_dict()})
    t_build = time.perf_counter() - t0
    try:
        cdir, checks, problems = write_case(case, outdir, source=source, crs=crs, iterations=options.iterations,
                                            processors=options.processors, frame_note=frame_note)
    except (Lod2EnergyError, ValueError, OSError) as e:
        return CfdResult(False, "", (f"CFD case not written: {type(e).__name__}: {e}",), {"region": region.as_dict()},
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
    return CfdResult(not fatal, str(cdir), tuple(problems), stats, case.included)


def mesh_and_check(cdir: Path, case, nice: int = 10, root=None) -> tuple[dict, list[str]]:
    """Run the meshing chain in ``cdir`` and compare the carved volume with the union's."""
    from lod2energy.safe_write import write_json
    from lod2energy.exporters.cfd.mesh import have_openfoam, run_mesh

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
