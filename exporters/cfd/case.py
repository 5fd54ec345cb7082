"""Writing an OpenFOAM v1912 case folder (``OUTDIR/cfd/``) for a region of a city model.

:func:`build_case` computes everything (bodies, union, ground, domain, mesh levels) without
writing; :func:`write_case` renders the jinja2 templates of ``templates/cfd/`` and writes the
STL surfaces, the sidecar ``case.json`` and the README through :mod:`lod2energy.safe_write`.
"""
from __future__ import annotations

import math
import os
import shutil
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path

import jinja2
import numpy as np

import lod2energy.templates as tpl
from lod2energy.energy.zones.shells import local_origin
from lod2energy.errors import ParameterError
from lod2energy.exporters.cfd.domain import Domain, from_wind_frame, frontal_area, size_domain
from lod2energy.exporters.cfd.openfoam import surface_check, surface_check_binary
from lod2energy.exporters.cfd.region import Region, select
from lod2energy.exporters.cfd.surfaces import (
    BuildingBody, SINK, SOLIDS, UnitedSurface, _to_manifold, building_body, flat_ground, smallest_feature, stl_text,
    unite,
)
from lod2energy.exporters.cfd.terrain import height_function, local_tin, solid_under, terrain_grid, volume_under
from lod2energy.exporters.stl.writer import self_check
from lod2energy.safe_write import write_checked, write_json, write_text

#: Neutral ABL inlet: reference speed (m/s) at the WMO reference height (m), roughness (m).
UREF, ZREF, Z0 = 10.0, 10.0, 0.1
KAPPA, CMU = 0.41, 0.09
#: Most refinement levels above the background mesh.
MAX_LEVEL = 4


@dataclass(frozen=True)
class MeshPlan:
    """Background cell size and snappyHexMesh refinement levels.

    Parameters
    ----------
    background_cell : float, m
        blockMesh cell size: ``cell_size * 2**surface_level``, about H_max.
    surface_level : int
        Level at the building surfaces (cells of ``cell_size``).
    feature_level : int
        Level at feature edges and at cells of high curvature: as many more (0 to 2) as it
        takes to put two cells across the smallest building dimension.
    region_level : int
        Level inside a box around the buildings (``surface_level - 1``).
    cells : (3,) int
        blockMesh cells along the wind, across, up.
    smallest_feature : float, m
    """
    background_cell: float
    surface_level: int
    feature_level: int
    region_level: int
    cells: tuple[int, int, int]
    smallest_feature: float

    @property
    def surface_cell(self) -> float:
        return self.background_cell / 2 ** self.surface_level

    @property
    def feature_cell(self) -> float:
        return self.background_cell / 2 ** self.feature_level

    def as_dict(self) -> dict:
        return {"background_cell_m": self.background_cell, "surface_level": self.surface_level,
                "feature_level": self.feature_level, "region_level": self.region_level,
                "surface_cell_m": self.surface_cell, "feature_cell_m": self.feature_cell,
                "blockmesh_cells": list(self.cells), "smallest_feature_m": round(self.smallest_feature, 3)}


def plan_mesh(domain: Domain, cell_size: float, smallest: float) -> MeshPlan:
    """Refinement levels from ``cell_size`` (m, at the buildings) and the smallest feature (m)."""
    if not (cell_size > 0 and math.isfinite(cell_size)):
        raise ParameterError(f"--cell-size must be a positive number of metres, not {cell_size!r}")
    level = int(min(MAX_LEVEL, max(0, round(math.log2(max(domain.h_max / cell_size, 1.0))))))
    # at least two cells across the smallest building dimension (at most two more levels)
    extra = 0
    if math.isfinite(smallest) and smallest > 0:
        extra = int(min(2, max(0, math.ceil(math.log2(2 * cell_size / smallest)))))
    feature = min(level + extra, MAX_LEVEL + 1)
    h0 = cell_size * 2 ** level
    lx, ly, lz = domain.size
    cells = tuple(max(1, int(math.ceil(L / h0 - 1e-9))) for L in (lx, ly, lz))
    return MeshPlan(float(h0), level, feature, max(level - 1, 0), cells, float(smallest))


@dataclass(frozen=True)
class Case:
    """Everything a case folder holds, before writing.

    Parameters
    ----------
    offset : (3,) float, m
        map coordinate = case coordinate + offset.
    region : Region
    included, excluded : tuple of str
        Building ids in the case / left out by the region.
    failed : tuple of (str, str)
        Buildings of the region that could not be triangulated (id, reason): left out.
    united : UnitedSurface
    ground_level : float, m
        Local z of the domain floor.
    domain : Domain
    mesh : MeshPlan
    ground : (vertices (n, 3), triangles (t, 3))
        The ground surface.
    terrain : bool
        The ground is the file's TIN (not flat).
    fluid_volume_without_buildings : float, m3
        What the mesh would fill without buildings: the box, less the volume under the terrain.
    terrain_level : int
        Refinement level of the terrain surface.
    """
    offset: tuple[float, float, float]
    region: Region
    included: tuple[str, ...]
    excluded: tuple[str, ...]
    failed: tuple[tuple[str, str], ...]
    united: UnitedSurface
    ground_level: float
    domain: Domain
    mesh: MeshPlan
    ground: tuple
    terrain: bool = False
    min_gap: float = 0.0
    notes: tuple[str, ...] = field(default_factory=tuple)
    fluid_volume_without_buildings: float = 0.0
    terrain_level: int = 0


def build_case(buildings, region: Region, wind_direction: float, cell_size: float, min_gap: float,
               lod: str | None = None, terrain=None) -> Case:
    """Bodies, union, domain and mesh plan for the buildings of ``region``.

    Parameters
    ----------
    buildings : list of Building
        Prepared (repaired, labelled) buildings; non-buildings are ignored.
    terrain : (vertices (n, 3), triangles (t, 3)) or None
        A TIN in map coordinates (see :func:`lod2energy.exporters.cfd.terrain.tin_of`); None: flat ground.

    Raises
    ------
    ParameterError
        No building of the region could be used.
    """
    blist = [b for b in buildings if b.is_building]
    inside, excluded = select(blist, region)
    if not inside:
        raise ParameterError(f"no building in the region ({region.as_dict()}): nothing to mesh")
    offset = np.asarray(local_origin(inside), dtype=np.float64)
    bodies: list[BuildingBody] = []
    failed = []
    for b in inside:
        try:
            bodies.append(building_body(b, offset, lod))
        except Exception as e:  # noqa: BLE001 - one building's geometry never stops the case
            failed.append((b.id, f"{type(e).__name__}: {e}"))
    if not bodies:
        raise ParameterError("no building of the region has a closed solid: " +
                             "; ".join(f"{i}: {m}" for i, m in failed[:3]))
    tin = None
    if terrain is not None:
        tin = local_tin(terrain, offset)
    ground_level = float(min(bd.base for bd in bodies))
    notes = []
    small = smallest_feature(bodies, ground_level)
    h_max = float(max(bd.top for bd in bodies) - ground_level)
    if tin is None:
        united = unite(bodies, ground_level, min_gap)
        domain, mesh = _size(united, h_max, ground_level, wind_direction, cell_size, small)
        return Case(tuple(float(x) for x in offset), region, tuple(bd.id for bd in bodies), tuple(excluded),
                    tuple(failed), united, ground_level, domain, mesh, flat_ground(domain.corners()), False,
                    float(min_gap), tuple(notes), domain.volume, 0)
    height = height_function(tin)
    # the domain is sized on the buildings as for flat ground; the box then reaches down under
    # the terrain, and the terrain grid is sampled along the background mesh's lines
    united0 = unite(bodies, ground_level, min_gap)
    domain0, plan0 = _size(united0, h_max, ground_level, wind_direction, cell_size, small)
    tlevel = max(0, plan0.surface_level - 2)
    gv, gt, inner = terrain_grid(domain0, plan0.cells, tlevel, height)
    zt = float(gv[:, 2].min())
    floor = min(zt, ground_level) - 0.5 * plan0.background_cell
    sink_to = min(zt, ground_level) - SINK
    united = unite(bodies, ground_level, min_gap, sink_to=sink_to) if sink_to < ground_level - SINK else united0
    domain = replace(domain0, floor=float(floor))
    mesh = plan_mesh(domain, cell_size, small)
    under = solid_under(gv, gt, min(floor, sink_to) - 1.0)
    bodies_above = (_to_manifold(united.vertices, united.triangles) - under).volume()
    fluid = domain.volume - volume_under(gv, gt[inner], floor)
    united = replace(united, volume_above_ground=float(bodies_above))
    notes.append(f"terrain: TINRelief resampled on a {domain.size[0] / (plan0.cells[0] * 2 ** tlevel):.2f} m grid "
                 f"(z {zt:.2f}..{float(gv[:, 2].max()):.2f} m local)")
    return Case(tuple(float(x) for x in offset), region, tuple(bd.id for bd in bodies), tuple(excluded),
                tuple(failed), united, ground_level, domain, mesh, (gv, gt), True, float(min_gap), tuple(notes),
                float(fluid), tlevel)


def _size(united, h_max, ground_level, wind_direction, cell_size, small):
    above = united.vertices[:, 2] > ground_level
    fa = frontal_area(united.vertices, united.triangles, wind_direction, ground_level)
    xy = united.vertices[above][:, :2] if above.any() else united.vertices[:, :2]
    domain = size_domain(xy, h_max, ground_level, wind_direction, fa)
    return domain, plan_mesh(domain, cell_size, small)


def _env():
    folder = Path(tpl.__file__).resolve().parent / "cfd"
    return jinja2.Environment(loader=jinja2.FileSystemLoader(str(folder)), undefined=jinja2.StrictUndefined,
                              autoescape=False, keep_trailing_newline=True)


def location_in_mesh(domain: Domain, plan: MeshPlan) -> np.ndarray:
    """A point in the air: 1.2345 background cells in from the inlet, off-centre laterally,
    above half height; never on a cell face of any refinement level."""
    h = plan.background_cell
    u = domain.x_min + 1.2345 * h
    v = 0.5 * (domain.y_min + domain.y_max) + 0.2345 * h
    z = domain.z_min + 0.5 * (domain.z_max - domain.z_min) + 0.3456 * h / 2
    z = min(z, domain.z_max - 0.3 * h)
    xy = from_wind_frame(np.array([[u, v]]), np.asarray(domain.centre), domain.wind_direction)[0]
    return np.array([xy[0], xy[1], z])


def _surface_check(path: Path):
    """surfaceCheck on ``path`` whatever its suffix (write_checked stages files as ``.staged``)."""
    with tempfile.TemporaryDirectory(prefix="cfd_surface_") as tmp:
        local = Path(tmp) / "surface.stl"
        shutil.copyfile(path, local)
        return surface_check(local)


def _ground_check(path: Path) -> list[str]:
    """surfaceCheck on an open ground sheet: no illegal triangle, one part, one normal zone."""
    if surface_check_binary() is None:
        return []
    sc = _surface_check(path)
    problems = [f for f in sc.failures if "not closed" not in f.lower()]
    if sc.returncode != 0:
        problems.append(f"surfaceCheck exit {sc.returncode}")
    if sc.illegal_triangles:
        problems.append(f"{sc.illegal_triangles} illegal triangle(s)")
    if sc.parts not in (None, 1):
        problems.append(f"{sc.parts} unconnected parts")
    return problems


def _buildings_check(expected_bodies: int):
    def check(path: Path) -> list[str]:
        if surface_check_binary() is None:  # without OpenFOAM: the STL exporter's own re-read check
            return self_check(path)
        sc = _surface_check(path)
        problems = list(sc.failures)
        if not sc.closed:
            problems.append("surfaceCheck: surface is not closed")
        if sc.illegal_triangles:
            problems.append(f"surfaceCheck: {sc.illegal_triangles} illegal triangle(s)")
        if sc.returncode != 0:
            problems.append(f"surfaceCheck exit {sc.returncode}")
        if sc.parts is not None and sc.parts != expected_bodies:
            problems.append(f"surfaceCheck: {sc.parts} parts, the union has {expected_bodies} bodies")
        return problems
    return check


def write_case(case: Case, outdir: str | Path, *, source: str = "", crs: str | None = None,
               iterations: int = 1000, processors: int = 2, check_surfaces: bool = True,
               frame_note: str = "") -> tuple[Path, dict, list[str]]:
    """Write the case folder ``outdir/cfd``.

    Returns
    -------
    (case folder, surface check results {file: problems}, problems)
    """
    root = Path(outdir)
    cdir = root / "cfd"
    env = _env()
    d = case.domain
    off = np.asarray(case.offset)
    plan = case.mesh
    loc = location_in_mesh(d, plan)
    if case.terrain:
        zt = height_function(case.ground)(loc[None, :2])[0]
        if loc[2] < zt + plan.background_cell:
            raise ParameterError("the terrain rises above the domain's mid-height: no point in the air found")
    u = case.united
    near = max(plan.background_cell, 0.5 * d.h_max)
    ustar = KAPPA * UREF / math.log((ZREF + Z0) / Z0)
    fd = d.flow_dir
    ctx = dict(
        corners=d.corners().tolist(), cells=plan.cells, flow_dir=fd, wind_direction=d.wind_direction,
        offset=[round(float(x), 4) for x in off], background_cell=plan.background_cell,
        surface_level=plan.surface_level, feature_level=plan.feature_level, region_level=plan.region_level,
        surface_cell=plan.surface_cell, feature_cell=plan.feature_cell, smallest_feature=plan.smallest_feature,
        terrain=case.terrain, ground_level_refinement=case.terrain_level, near_distance=near,
        max_local_cells=2_000_000, max_global_cells=20_000_000, location_in_mesh=loc.tolist(),
        iterations=int(iterations), write_interval=max(1, int(iterations)), processors=int(processors),
        cmu=CMU, uref=UREF, zref=ZREF, z0=Z0, z_ground=case.ground_level,
        u_init=[UREF * fd[0], UREF * fd[1]], k_init=ustar ** 2 / math.sqrt(CMU),
        epsilon_init=ustar ** 3 / (KAPPA * (ZREF + Z0)), location="",
    )
    files = {
        "system/blockMeshDict": "blockMeshDict.j2", "system/surfaceFeatureExtractDict": "surfaceFeatureExtractDict.j2",
        "system/snappyHexMeshDict": "snappyHexMeshDict.j2", "system/controlDict": "controlDict.j2",
        "system/fvSchemes": "fvSchemes.j2", "system/fvSolution": "fvSolution.j2",
        "system/decomposeParDict": "decomposeParDict.j2",
        "constant/transportProperties": "transportProperties.j2",
        "constant/turbulenceProperties": "turbulenceProperties.j2",
        "0.orig/U": "U.j2", "0.orig/p": "p.j2", "0.orig/k": "k.j2", "0.orig/epsilon": "epsilon.j2",
        "0.orig/nut": "nut.j2", "0.orig/include/ABLConditions": "ABLConditions.j2", "Allrun": "Allrun.j2",
    }
    for rel, tname in files.items():
        write_text(cdir / rel, env.get_template(tname).render(**ctx), root=root, inputs=[source] if source else ())
    os.chmod(cdir / "Allrun", 0o755)
    problems: list[str] = []
    checks: dict = {}
    tri = cdir / "constant" / "triSurface"
    text_b = stl_text(u.vertices, u.triangles, u.codes, SOLIDS)
    gv, gt = case.ground
    text_g = stl_text(np.asarray(gv), np.asarray(gt), np.zeros(len(gt), dtype=np.intp),
                      ("terrain" if case.terrain else "ground",))
    for name, text, check in (("buildings.stl", text_b, _buildings_check(u.bodies)), ("ground.stl", text_g, _ground_check)):
        if check_surfaces:
            path, probs = write_checked(tri / name, lambda f, s=text: f.write(s), check, root=root)
        else:
            write_text(tri / name, text, root=root)
            path, probs = str(tri / name), []
        checks[name] = {"path": path, "ok": not probs, "problems": probs}
        problems.extend(f"{name}: {p}" for p in probs)
    sidecar = case_json(case, source, crs)
    sidecar["surface_checks"] = checks
    write_json(cdir / "case.json", sidecar, root=root)
    dd = d.as_dict()
    readme = env.get_template("README.md.j2").render(
        title=Path(source).name if source else "lod2energy", source=Path(source).name if source else "",
        crs=crs or "unknown", frame_note=frame_note, region_text=_region_text(case.region),
        n_included=len(case.included), n_excluded=len(case.excluded), offset=ctx["offset"], d=dd,
        bodies=u.bodies, sink=SINK, min_gap=sidecar["min_gap_m"], gap_fills=u.gap_fills,
        gap_fill_area=u.gap_fill_area, ground_text=_ground_text(case), mesh=plan, terrain=case.terrain,
        abl={"uref": UREF, "zref": ZREF, "z0": Z0, "cmu": CMU})
    write_text(cdir / "README.md", readme, root=root)
    return cdir, checks, problems


def _region_text(r: Region) -> str:
    if r.kind == "box":
        return "rectangle x {:g}..{:g}, y {:g}..{:g} (input CRS)".format(r.bounds[0], r.bounds[2], r.bounds[1], r.bounds[3])
    if r.kind == "circle":
        return "circle centre ({:g}, {:g}) radius {:g} (input CRS)".format(*r.bounds)
    return "the whole file"


def _ground_text(case: Case) -> str:
    if case.terrain:
        return ("the file's own terrain (TINRelief), resampled on a grid along the background mesh lines "
                "over the whole domain and meshed by snappyHexMesh as the patch `terrain`; the blockMesh "
                f"floor (patch `ground`) lies under it at z = {case.domain.bottom:.3f} m and is cut away")
    return (f"flat at the terrain level z = {case.ground_level:.3f} m (local; the lowest ground of the "
            "region's buildings); it is the blockMesh floor, patch `ground` (the STL is for viewing)")


def case_json(case: Case, source: str, crs: str | None) -> dict:
    """The sidecar ``case.json``."""
    u = case.united
    return {
        "source": Path(source).name if source else "",
        "crs": crs,
        "units": "m",
        "offset": list(case.offset),
        "offset_meaning": "map coordinate = case coordinate + offset",
        "region": case.region.as_dict(),
        "buildings_included": list(case.included),
        "buildings_excluded": list(case.excluded),
        "buildings_failed": [{"id": i, "reason": m} for i, m in case.failed],
        "ground": {"kind": "terrain" if case.terrain else "flat", "level_local_m": case.ground_level,
                   "level_map_m": case.ground_level + case.offset[2]},
        "domain": case.domain.as_dict(),
        "domain_volume_m3": case.domain.volume,
        "fluid_volume_without_buildings_m3": case.fluid_volume_without_buildings,
        "notes": list(case.notes),
        "mesh_plan": case.mesh.as_dict(),
        "united": {"bodies": u.bodies, "triangles": int(len(u.triangles)),
                   "volume_above_ground_m3": round(u.volume_above_ground, 3),
                   "gap_fills": u.gap_fills, "gap_fill_area_m2": round(u.gap_fill_area, 3),
                   "patches": {n: int((u.codes == i).sum()) for i, n in enumerate(SOLIDS)},
                   "warnings": list(u.warnings)},
        "min_gap_m": case.min_gap,
        "guidelines": {"upstream": "5 H_max", "lateral": "5 H_max", "downstream": "15 H_max",
                       "top": "6 H_max above the ground (5 H_max above the tallest building)",
                       "blockage_ratio": "< 3%",
                       "references": ["Franke et al. 2007, COST Action 732 best practice guideline",
                                      "Tominaga et al. 2008, AIJ guidelines, J. Wind Eng. Ind. Aerodyn. 96:1749-1761"]},
    }
