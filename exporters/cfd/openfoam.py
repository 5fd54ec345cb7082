"""Run OpenFOAM's ``surfaceCheck`` on an STL and parse its verdict.

The Debian/Ubuntu package ``openfoam`` (OpenFOAM v1912 on Debian 12) installs the
utilities in ``/usr/bin`` and its configuration in ``/usr/share/openfoam``;
``surfaceCheck`` only needs ``WM_PROJECT_DIR`` pointing there and no case folder (it is
run in a temporary folder anyway, because it writes helper files when it finds problems).

A surface passes when surfaceCheck says "Surface is closed", finds no illegal triangle,
prints no ``***`` failure line, and counts one normal-orientation zone per connected part.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

DEFAULT_PROJECT_DIR = "/usr/share/openfoam"


def surface_check_binary() -> Path | None:
    """Path of ``surfaceCheck``, or None when OpenFOAM is not installed."""
    found = shutil.which("surfaceCheck")
    if found:
        return Path(found)
    for d in (os.environ.get("FOAM_APPBIN"), "/usr/bin", "/usr/lib/openfoam/openfoam/platforms/linux64GccDPInt32Opt/bin"):
        if d and (Path(d) / "surfaceCheck").is_file():
            return Path(d) / "surfaceCheck"
    return None


@dataclass(frozen=True)
class SurfaceCheck:
    """Parsed ``surfaceCheck`` output.

    Parameters
    ----------
    closed : bool
        "Surface is closed. All edges connected to two faces."
    illegal_triangles : int
    zones : int or None
        "Number of zones (connected area with consistent normal)".
    parts : int or None
        "Number of unconnected parts".
    regions : dict
        Region (patch) name -> triangle count.
    failures : tuple of str
        Lines starting with ``***`` and other failure statements.
    returncode : int
    output : str
    """

    closed: bool
    illegal_triangles: int
    zones: int | None
    parts: int | None
    regions: dict
    failures: tuple[str, ...]
    returncode: int
    output: str

    @property
    def ok(self) -> bool:
        return self.returncode == 0 and self.closed and self.illegal_triangles == 0 and not self.failures


def parse_surface_check(text: str, returncode: int = 0) -> SurfaceCheck:
    """Parse the text printed by ``surfaceCheck``."""
    closed = "Surface is closed" in text
    m = re.search(r"Surface has (\d+) illegal triangles", text)
    illegal = int(m.group(1)) if m else 0
    m = re.search(r"Number of zones \(connected area with consistent normal\)\s*:\s*(\d+)", text)
    zones = int(m.group(1)) if m else None
    m = re.search(r"Number of unconnected parts\s*:\s*(\d+)", text)
    parts = int(m.group(1)) if m else None
    regions = {}
    block = re.search(r"Region\s+Size\n-+\s+-+\n(.*?)\n\n", text, re.S)
    if block:
        for line in block.group(1).splitlines():
            w = line.split()
            if len(w) == 2 and w[1].isdigit():
                regions[w[0]] = int(w[1])
    failures = [ln.strip() for ln in text.splitlines() if ln.strip().startswith("***")]
    for pat in ("Surface is not closed", "FOAM FATAL"):
        failures.extend(ln.strip() for ln in text.splitlines() if pat in ln and ln.strip() not in failures)
    # surfaceCheck prints "More than one normal orientation" whenever zones > 1; that is only a
    # failure when a connected part holds more than one orientation zone
    if zones is not None and parts is not None and zones > parts:
        failures.append(f"{zones} normal-orientation zones for {parts} connected part(s)")
    return SurfaceCheck(closed, illegal, zones, parts, regions, tuple(failures), returncode, text)


def surface_check(stl: str | Path, timeout: float = 300) -> SurfaceCheck:
    """Run ``surfaceCheck`` on ``stl`` in a temporary folder.

    Raises
    ------
    FileNotFoundError
        OpenFOAM's surfaceCheck is not installed.
    """
    exe = surface_check_binary()
    if exe is None:
        raise FileNotFoundError("OpenFOAM surfaceCheck not found: apt-get install openfoam")
    env = dict(os.environ)
    env.setdefault("WM_PROJECT_DIR", DEFAULT_PROJECT_DIR)
    stl = Path(stl).resolve()
    with tempfile.TemporaryDirectory(prefix="surfaceCheck_") as tmp:
        local = Path(tmp) / ("surface" + stl.suffix.lower())
        shutil.copyfile(stl, local)
        try:
            proc = subprocess.run([str(exe), local.name], cwd=tmp, env=env, capture_output=True,
                                  text=True, timeout=timeout)
            text, rc = proc.stdout + proc.stderr, proc.returncode
        except subprocess.TimeoutExpired:
            text, rc = "surfaceCheck timed out", -1
    return parse_surface_check(text, rc)
