"""The IDF self-check flags every surface EnergyPlus calls degenerate (issue 19, item 5).

EnergyPlus (``GetVertices`` in SurfaceGeometry.cc) drops a vertex closer than 1 cm to its
neighbour while the surface keeps more than three sides, and calls a surface with a
coincident pair left at three sides "degenerate" (``GetSurfaceData: There are N degenerate
surfaces``, a severe error); ``CheckConvexity`` then removes collinear vertices, never below
three. These tests write surfaces built to sit at those limits (short edges, chains of
sub-centimetre steps, near-collinear vertices, slivers), run EnergyPlus on them and compare
its verdict with the self-check's.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from export_helpers import EPW, energy_ready, write_idf
from factories import box
from lod2energy.exporters import energyplus
from lod2energy.energy.enclosure import eplus_degenerate

pytestmark = pytest.mark.skipif(energyplus.run.binary() is None, reason="EnergyPlus not installed")


def near_degenerate(rng) -> np.ndarray:
    """A planar polygon (m) near EnergyPlus's limits, in a coordinate plane, 20 m off the box."""
    k = int(rng.choice([3, 4, 5]))
    pts = (np.array([[0, 0], [3, 0], [1.5, 2]], float) if k == 3 else
           np.array([[0, 0], [3, 0], [3, 2], [0, 2], [1.5, 3]][:k], float))
    r = rng.random()
    if r < 0.4:      # one or two edges a few millimetres long
        for _ in range(int(rng.integers(1, 3))):
            i = int(rng.integers(len(pts)))
            d, a = rng.uniform(0.004, 0.016), rng.uniform(0, 2 * np.pi)
            pts = np.insert(pts, i + 1, pts[i] + d * np.array([np.cos(a), np.sin(a)]), axis=0)
    elif r < 0.7:    # a chain of sub-centimetre steps
        i = int(rng.integers(len(pts)))
        d = rng.uniform(0.004, 0.009)
        u = pts[(i + 1) % len(pts)] - pts[i]
        u /= np.linalg.norm(u)
        for s in range(int(rng.integers(2, 4))):
            pts = np.insert(pts, i + 1 + s, pts[i] + (s + 1) * d * u + rng.uniform(-0.003, 0.003, 2), axis=0)
    else:            # a near-collinear vertex, sometimes on a sliver
        i = int(rng.integers(len(pts)))
        j = (i + 1) % len(pts)
        m = 0.5 * (pts[i] + pts[j]) + np.array([0, rng.uniform(-1, 1) * 10 ** rng.uniform(-7, -2)])
        pts = np.insert(pts, i + 1, m, axis=0)
        if rng.random() < 0.5:
            pts = pts * np.array([1, rng.uniform(0.001, 0.01)])
    a, b = [(0, 1), (0, 2), (1, 2)][int(rng.integers(3))]
    P = np.zeros((len(pts), 3))
    P[:, a], P[:, b] = pts[:, 0], pts[:, 1]
    P[:, 3 - a - b] = rng.uniform(0, 5)
    return np.round(P + np.array([20.0, 20.0, 0.0]), 4)   # as written (4 decimals)


def _eplus_degenerate_names(err: str) -> set[str]:
    out = set()
    for block in re.split(r"\n\s*\*\* (?:Warning|Severe)", err):
        m = re.search(r"GetVertices:.*?Surface=\"?([A-Za-z0-9_]+)", block)
        if m and "degenerate surface" in block:
            out.add(m.group(1).upper())
    return out


def test_self_check_flags_every_surface_energyplus_calls_degenerate(tmp_path):
    base = write_idf([energy_ready(box())], tmp_path / "base", energyplus.options.IdfOptions())[0]
    assert base.ok, base.problems
    text = Path(base.path).read_text()
    zone = re.search(r"^Zone, ([^,]+),", text, re.M).group(1)
    cons = re.search(r"(Wall_Outdoors_[A-Za-z0-9_]+),\s+!- Construction Name", text).group(1)
    rng = np.random.default_rng(19)
    cands = [near_degenerate(rng) for _ in range(250)]
    extra = [f"BuildingSurface:Detailed, T{n}, Wall, {cons}, {zone}, , Outdoors, , SunExposed, WindExposed, "
             f"autocalculate, {len(P)}, " + ", ".join(f"{x:.4f}" for x in P.ravel()) + ";"
             for n, P in enumerate(cands)]
    path = tmp_path / "near_degenerate.idf"
    path.write_text(text + "\n" + "\n".join(extra) + "\n")
    rr = energyplus.run.run(path, str(EPW), tmp_path / "out", timeout=600)
    err = (tmp_path / "out" / "eplusout.err").read_text(errors="replace")
    theirs = _eplus_degenerate_names(err)
    m = re.search(r"There are (\d+) degenerate surfaces", err)
    assert m and int(m.group(1)) == len(theirs) > 0      # the constructions reach EnergyPlus's limit
    flagged = {re.match(r"surface (\S+): degenerate", p).group(1).upper()
               for p in energyplus.check.self_check(path) if re.match(r"surface \S+: degenerate", p)}
    assert theirs <= flagged, sorted(theirs - flagged)
    # and the self-check does not call many more degenerate than EnergyPlus does
    assert len(flagged - theirs) <= max(3, len(theirs) // 2), sorted(flagged - theirs)
    assert rr.err.severe


def test_a_sliver_triangle_8_mm_wide_is_degenerate_for_both(tmp_path):
    tri = np.array([[10, 0.008, 0.0], [10, 0, 0], [0, 0, 0]])
    assert eplus_degenerate([tri])[0]
    base = write_idf([energy_ready(box())], tmp_path / "base", energyplus.options.IdfOptions())[0]
    text = Path(base.path).read_text()
    zone = re.search(r"^Zone, ([^,]+),", text, re.M).group(1)
    cons = re.search(r"(Wall_Outdoors_[A-Za-z0-9_]+),\s+!- Construction Name", text).group(1)
    path = tmp_path / "sliver.idf"
    path.write_text(text + f"\nBuildingSurface:Detailed, SLIVER, Floor, {cons}, {zone}, , Outdoors, , NoSun, NoWind, "
                    "autocalculate, 3, " + ", ".join(f"{x:.4f}" for x in tri.ravel()) + ";\n")
    energyplus.run.run(path, str(EPW), tmp_path / "out", timeout=600)
    err = (tmp_path / "out" / "eplusout.err").read_text(errors="replace")
    assert _eplus_degenerate_names(err) == {"SLIVER"}
    assert any(p.startswith("surface SLIVER: degenerate") for p in energyplus.check.self_check(path))
