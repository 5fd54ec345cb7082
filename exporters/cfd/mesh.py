"""Running OpenFOAM's meshing chain on a case folder and reading checkMesh's verdict.

blockMesh -> surfaceFeatureExtract -> snappyHexMesh -overwrite -> checkMesh, each in the case
folder with ``WM_PROJECT_DIR`` set (Debian's ``openfoam`` package: ``/usr/share/openfoam``),
optionally under ``nice``; each tool's output is kept in ``log.<tool>``.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import time
from dataclasses import dataclass, field
from pathlib import Path

from lod2energy.exporters.cfd.openfoam import DEFAULT_PROJECT_DIR
from lod2energy.safe_write import write_text

#: The meshing chain, in order.
MESH_TOOLS = (("blockMesh",), ("surfaceFeatureExtract",), ("snappyHexMesh", "-overwrite"), ("checkMesh",))


def foam_env() -> dict:
    env = dict(os.environ)
    env.setdefault("WM_PROJECT_DIR", DEFAULT_PROJECT_DIR)
    return env


def have_openfoam() -> bool:
    """True when blockMesh, surfaceFeatureExtract, snappyHexMesh and checkMesh are on PATH."""
    return all(shutil.which(t[0]) for t in MESH_TOOLS)


@dataclass(frozen=True)
class CheckMesh:
    """Parsed ``checkMesh`` output.

    Parameters
    ----------
    ok : bool
        checkMesh printed "Mesh OK.".
    cells, faces, points : int or None
    max_non_orthogonality, avg_non_orthogonality : float or None, deg
    max_skewness : float or None
    total_volume : float or None, m3
        Sum of the cell volumes.
    failed_checks : int or None
        "Failed N mesh checks".
    patches : dict
        Patch name -> number of faces.
    """

    ok: bool
    cells: int | None = None
    faces: int | None = None
    points: int | None = None
    max_non_orthogonality: float | None = None
    avg_non_orthogonality: float | None = None
    max_skewness: float | None = None
    total_volume: float | None = None
    failed_checks: int | None = None
    patches: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        return {k: getattr(self, k) for k in self.__dataclass_fields__}


def _num(pat: str, text: str, kind=float):
    m = re.search(pat, text, re.M)
    return kind(m.group(1)) if m else None


def parse_check_mesh(text: str) -> CheckMesh:
    """Parse the text printed by ``checkMesh``."""
    ok = bool(re.search(r"^\s*Mesh OK\.", text, re.M))
    patches = {}
    block = re.search(r"Checking patch topology for multiply connected surfaces\.\.\.\n(.*?)\n\n", text, re.S)
    if block:
        for line in block.group(1).splitlines()[1:]:
            w = line.split()
            if len(w) >= 2 and w[1].isdigit():
                patches[w[0]] = int(w[1])
    return CheckMesh(
        ok,
        _num(r"^\s*cells:\s+(\d+)", text, int),
        _num(r"^\s*faces:\s+(\d+)", text, int),
        _num(r"^\s*points:\s+(\d+)", text, int),
        _num(r"Mesh non-orthogonality Max:\s*([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)", text),
        _num(r"Mesh non-orthogonality Max:\s*[-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?\s+average:\s*([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)", text),
        _num(r"Max skewness = ([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)", text),
        _num(r"Total volume = ([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)", text),
        _num(r"Failed (\d+) mesh checks", text, int),
        patches,
    )


@dataclass(frozen=True)
class MeshRun:
    """Outcome of the meshing chain.

    Parameters
    ----------
    ok : bool
        Every tool exited 0 and checkMesh said "Mesh OK".
    check : CheckMesh or None
    seconds : dict
        Tool -> wall time (s).
    problems : tuple of str
    """

    ok: bool
    check: CheckMesh | None
    seconds: dict
    problems: tuple[str, ...] = ()


def run_tool(case: Path, argv: tuple[str, ...], nice: int = 0, timeout: float = 3600) -> tuple[int, str, float]:
    """Run one OpenFOAM tool in ``case``; its output is written to ``case/log.<tool>``.

    Returns
    -------
    (return code, output text, seconds)
    """
    cmd = list(argv)
    if nice and shutil.which("nice"):
        cmd = ["nice", "-n", str(int(nice))] + cmd
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, cwd=case, env=foam_env(), capture_output=True, text=True, timeout=timeout)
        rc, text = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired as e:
        rc, text = -1, f"{argv[0]} timed out after {timeout:g} s\n{e.stdout or ''}"
    except FileNotFoundError:
        rc, text = -1, f"{argv[0]} not found (apt-get install openfoam)"
    dt = time.perf_counter() - t0
    write_text(case / f"log.{argv[0]}", text, root=case, fsync=False)
    return rc, text, dt


def run_mesh(case: str | Path, nice: int = 10, timeout: float = 3600) -> MeshRun:
    """blockMesh, surfaceFeatureExtract, snappyHexMesh -overwrite and checkMesh in ``case``."""
    case = Path(case)
    seconds, problems = {}, []
    check = None
    for argv in MESH_TOOLS:
        rc, text, dt = run_tool(case, argv, nice=nice, timeout=timeout)
        seconds[argv[0]] = round(dt, 2)
        if argv[0] == "checkMesh":
            check = parse_check_mesh(text)
            if not check.ok:
                problems.append(f"checkMesh: {check.failed_checks or '?'} failed mesh check(s)")
        if rc != 0 or "FOAM FATAL" in text:
            fatal = [ln.strip() for ln in text.splitlines() if ln.strip()][-3:]
            problems.append(f"{argv[0]} failed (exit {rc}): {' '.join(fatal)[:300]}")
            break
    return MeshRun(not problems and check is not None and check.ok, check, seconds, tuple(problems))


def residuals(log_text: str) -> dict[str, list[float]]:
    """Initial residuals per field and iteration from a simpleFoam log."""
    out: dict[str, list[float]] = {}
    for m in re.finditer(r"Solving for (\w+), Initial residual = ([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?|-?nan|-?inf)", log_text):
        out.setdefault(m.group(1), []).append(float(m.group(2)))
    return out


def restore_initial_fields(case: str | Path) -> None:
    """Copy ``0.orig/`` to ``0/`` (as the Allrun script does) through :mod:`lod2energy.safe_write`."""
    case = Path(case)
    src = case / "0.orig"
    for p in sorted(src.rglob("*")):
        if p.is_file() and not p.is_symlink():
            write_text(case / "0" / p.relative_to(src), p.read_text(encoding="utf-8"), root=case, fsync=False)


@dataclass(frozen=True)
class SolverRun:
    """Outcome of a simpleFoam run.

    Parameters
    ----------
    ok : bool
        simpleFoam exited 0 and printed "End".
    iterations : int
        Iterations run (time steps).
    residuals : dict
        Field -> initial residual per solve.
    seconds : float
    problems : tuple of str
    """

    ok: bool
    iterations: int
    residuals: dict
    seconds: float
    problems: tuple[str, ...] = ()


def run_solver(case: str | Path, nice: int = 10, timeout: float = 3600) -> SolverRun:
    """Restore ``0/`` from ``0.orig/`` and run simpleFoam in ``case`` (``log.simpleFoam``)."""
    case = Path(case)
    restore_initial_fields(case)
    rc, text, dt = run_tool(case, ("simpleFoam",), nice=nice, timeout=timeout)
    problems = []
    if rc != 0 or "FOAM FATAL" in text:
        problems.append(f"simpleFoam failed (exit {rc}): {' '.join(text.splitlines()[-3:])[:300]}")
    ended = bool(re.search(r"^End\s*$", text, re.M))
    its = len(re.findall(r"^Time = \S+", text, re.M))
    return SolverRun(rc == 0 and ended and not problems, its, residuals(text), round(dt, 2), tuple(problems))
