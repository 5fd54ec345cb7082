"""CPU of the export hot loops changed in session 22 (perf2) against the code they replaced.

Usage (from the repository root)::

    python benchmarks/bench_hot_loops.py

The references are the replaced implementations kept in ``tests/test_fast_paths_equivalence.py``;
the inputs are random rings at national-grid offsets (4-8 vertices, rounded as the IDF writes
them) and upright rectangular walls. Prints the best of 3 CPU times per call.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402
import shapely  # noqa: E402
import shapely.geometry as sg  # noqa: E402

import test_fast_paths_equivalence as T  # noqa: E402
from lod2energy.exporters.energyplus import render  # noqa: E402
from lod2energy.energy import conform
from lod2energy.energy.openings import window_for  # noqa: E402
from lod2energy.energy.pieces import Piece, _pieces_volume  # noqa: E402
from lod2energy import semantics  # noqa: E402


def cpu(f) -> float:
    """CPU seconds (process) of one call of ``f()``."""
    t = time.process_time()
    f()
    return time.process_time() - t


def main() -> None:
    rng = np.random.default_rng(0)
    rings = [np.round(rng.normal(size=(int(k), 3)) * 5 + [85000, 447000, 3], 4) for k in rng.integers(4, 9, 2000)]
    n = np.array([0.0, 0.0, 1.0])
    pieces = [Piece(q, "wall", "Outdoors", 1.0, k) for k, q in enumerate(rings)]
    walls = []
    for _ in range(300):
        w, h = rng.random(2) * 10 + 1
        walls.append(np.array([[0.0, 0, 0], [w, 0, 0], [w, 0, h], [0, 0, h]]) + [85000, 447000, 0])
    rows = [
        ("_ring_centroid", lambda: [semantics._ring_centroid(q - q[0], n) for q in rings],
         lambda: [T._ref_ring_centroid(q - q[0], n) for q in rings]),
        ("_pieces_volume", lambda: _pieces_volume(pieces), lambda: T._ref_pieces_volume(pieces)),
        ("upper_left_first", lambda: [render.upper_left_first(q) for q in rings],
         lambda: [T._ref_upper_left_first(q) for q in rings]),
        ("keep_corners", lambda: conform.keep_corners(pieces), lambda: T._ref_keep_corners(pieces)),
    ]
    for name, new, old in rows:
        o = min(cpu(old) for _ in range(3))
        nw = min(cpu(new) for _ in range(3))
        print(f"{name}: {o * 1e6 / len(rings):.1f} -> {nw * 1e6 / len(rings):.1f} us CPU per ring")

    def win_old():
        orig = shapely.box
        shapely.box = sg.box  # the bisection as before: shapely.geometry.box
        try:
            for p in walls:
                window_for(p, 0.3)
        finally:
            shapely.box = orig

    o = min(cpu(win_old) for _ in range(3))
    nw = min(cpu(lambda: [window_for(p, 0.3) for p in walls]) for _ in range(3))
    print(f"window_for: {o * 1e6 / len(walls):.0f} -> {nw * 1e6 / len(walls):.0f} us CPU per wall")


if __name__ == "__main__":
    main()
