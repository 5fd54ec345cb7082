"""The CFD case with the real client: OpenFOAM v1912 meshes it (checkMesh "Mesh OK") and simpleFoam runs it."""
from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pytest

from lod2energy.exporters.cfd.mesh import have_openfoam, parse_check_mesh, residuals, run_solver
from lod2energy.exporters.cfd.openfoam import surface_check

REPO = Path(__file__).resolve().parents[1]
DELFT = REPO / "examples" / "delft_subset.city.jsonl"
#: Two buildings of the bundled Delft subset (a 40 m circle), coarse cells.
DELFT_ARGS = ["--centre", "84640,446740", "--radius", "40", "--cell-size", "3", "--wind-direction", "250"]

needs_openfoam = pytest.mark.skipif(not have_openfoam(), reason="OpenFOAM (blockMesh, snappyHexMesh) not installed")


def _case(tmp_path: Path, *extra: str) -> dict:
    from lod2energy.cfd.__main__ import main
    out = tmp_path / "out"
    rc = main([str(DELFT), "-o", str(out), *DELFT_ARGS, *extra])
    report = json.loads((out / "cfd_report.json").read_text())
    report["rc"] = rc
    return report


def test_case_folder_is_complete(tmp_path):
    """Without --mesh: every dictionary, field, surface, Allrun and sidecar is there."""
    rep = _case(tmp_path)
    case = Path(rep["path"])
    for rel in ("system/blockMeshDict", "system/surfaceFeatureExtractDict", "system/snappyHexMeshDict",
                "system/controlDict", "system/fvSchemes", "system/fvSolution", "system/decomposeParDict",
                "constant/transportProperties", "constant/turbulenceProperties", "0.orig/U", "0.orig/p",
                "0.orig/k", "0.orig/epsilon", "0.orig/nut", "0.orig/include/ABLConditions", "Allrun",
                "README.md", "case.json", "constant/triSurface/buildings.stl", "constant/triSurface/ground.stl"):
        assert (case / rel).is_file(), rel
    assert (case / "Allrun").stat().st_mode & 0o111
    side = json.loads((case / "case.json").read_text())
    assert side["buildings_included"] == rep["building_ids"] and len(side["buildings_included"]) == 2
    assert len(side["buildings_excluded"]) == 8
    assert side["crs"].endswith("7415") and len(side["offset"]) == 3
    u = (case / "0.orig" / "U").read_text()
    assert "atmBoundaryLayerInletVelocity" in u
    assert "nutkAtmRoughWallFunction" in (case / "0.orig" / "nut").read_text()
    assert "atmBoundaryLayerInletEpsilon" in (case / "0.orig" / "epsilon").read_text()
    readme = (case / "README.md").read_text()
    for s in ("5 H_max", "15 H_max", "6 H_max", "3%", "Franke", "Tominaga", "meteorological"):
        assert s in readme
    stl = (case / "constant/triSurface/buildings.stl").read_text()
    assert "solid roof" in stl and "solid wall" in stl
    assert rep["ok"] and rep["rc"] == 0


@pytest.mark.external
@needs_openfoam
def test_surfaces_pass_surface_check(tmp_path):
    rep = _case(tmp_path)
    sc = surface_check(Path(rep["path"]) / "constant/triSurface/buildings.stl")
    assert sc.ok and sc.closed and set(sc.regions) >= {"roof", "wall"}


@pytest.mark.external
@needs_openfoam
def test_delft_district_meshes_and_checkmesh_says_ok(tmp_path):
    """blockMesh, surfaceFeatureExtract, snappyHexMesh, checkMesh on two Delft buildings: "Mesh OK",
    and the volume carved out of the mesh within 5% of the united surfaces' volume."""
    rep = _case(tmp_path, "--mesh")
    m = rep["stats"]["mesh"]
    assert m["check_mesh_ok"] is True, rep["problems"]
    log = (Path(rep["path"]) / "log.checkMesh").read_text()
    assert parse_check_mesh(log).ok
    assert m["cells"] > 1000 and m["max_non_orthogonality"] < 70 and m["max_skewness"] < 4
    assert m["patches"].get("buildings_roof", 0) > 0 and m["patches"].get("buildings_wall", 0) > 0
    assert m["patches"].get("ground", 0) > 0 and m["patches"].get("inlet", 0) > 0
    assert abs(m["carved_volume_error"]) < 0.05
    assert rep["ok"]


@pytest.mark.slow
@pytest.mark.external
@needs_openfoam
def test_simplefoam_runs_20_iterations_without_diverging(tmp_path):
    rep = _case(tmp_path, "--mesh", "--iterations", "20")
    assert rep["stats"]["mesh"]["check_mesh_ok"]
    run = run_solver(rep["path"])
    assert run.ok, run.problems
    assert run.iterations == 20
    for field in ("Ux", "Uy", "Uz", "p", "k", "epsilon"):
        r = run.residuals[field]
        assert r and all(math.isfinite(x) for x in r), field
        # not growing: the last residuals stay below the first ones (and far from blowing up)
        assert max(r[-3:]) <= max(r[:3]) and max(r) < 10, (field, r[:3], r[-3:])


def test_check_mesh_parser_reads_failures():
    text = ("    cells:            1234\n    Mesh non-orthogonality Max: 75.5 average: 10.2\n"
            " ***Max skewness = 5.3, 2 highly skew faces detected\n"
            "    Min volume = 1e-3. Max volume = 2. Total volume = 12345.5.  Cell volumes OK.\n"
            "\nFailed 1 mesh checks.\n")
    c = parse_check_mesh(text)
    assert not c.ok and c.cells == 1234 and c.max_non_orthogonality == 75.5 and c.max_skewness == 5.3
    assert c.total_volume == 12345.5 and c.failed_checks == 1
    assert residuals("Solving for Ux, Initial residual = 1e-3, Final\nSolving for Ux, Initial residual = nan,")["Ux"][0] == 1e-3
