"""Benchmark: the CPU cost of one building against its number of BuildingParts.

Usage: python benchmarks/bench_complexity.py [-n 25 50 100 200] [--kind solid open] [--profile N]
       [-o complexity.md] [--formats idf stl cityjson]

A synthetic housing block of ``n`` parts (:func:`block`) is exported in this process with
``lod2energy export X -o OUT --idf --stl --cityjson -j 1`` (no budget), and the CPU time of
the export (``time.process_time``) is reported per block, with the log-log slope of CPU against
``n`` (least squares over the sizes run): 1 is a cost that is the sum of the parts, 2 one that
grows with the pairs of parts. Two kinds of block: ``solid`` (every part a closed Solid) and
``open`` (every part a MultiSurface, every fourth one without its ground face, so that the repair
closes it). ``--profile N`` prints a cProfile of the ``N``-part block of each kind instead.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

#: Every this many parts, one reaches 5 cm into its eastern neighbour (a 601 overlap to clip).
OVERLAP_EVERY = 3
#: In an ``open`` block, every this many parts has no ground face.
OPEN_EVERY = 4


def block(n: int, kind: str = "solid", width: float = 6.0, depth: float = 9.0) -> dict:
    """A CityJSON document of one Building of ``n`` BuildingParts: a grid of terraced houses
    with gable roofs (ridge along y), of varying eave and ridge heights, sharing their side
    walls (in full or in part) and their gable ends.

    Parameters
    ----------
    n : int
        Number of parts.
    kind : {"solid", "open"}
        ``solid``: each part a closed Solid; ``open``: each a MultiSurface, every
        :data:`OPEN_EVERY` th one without its ground face.
    width, depth : float, m
        Footprint of a part (x, y).
    """
    cols = max(1, math.ceil(math.sqrt(n)))
    verts: list[list[int]] = []
    index: dict[tuple, int] = {}

    def vid(p):
        k = tuple(round(c * 1000) for c in p)
        if k not in index:
            index[k] = len(verts)
            verts.append(list(k))
        return index[k]

    cos: dict = {"blk": {"type": "Building", "children": []}}
    for k in range(n):
        i, j = k % cols, k // cols
        x0, y0 = i * width, j * depth
        x1, y1 = x0 + width, y0 + depth
        if k % OVERLAP_EVERY == OVERLAP_EVERY - 1 and i < cols - 1 and k + 1 < n:
            x1 += 0.05
        eave = 5.0 + ((i * 5 + j * 3) % 4) * 1.0
        ridge = eave + 2.0 + (k % 3) * 0.5
        xm = (x0 + x1) / 2
        g = [vid((x0, y0, 0)), vid((x0, y1, 0)), vid((x1, y1, 0)), vid((x1, y0, 0))]
        e = [vid((x0, y0, eave)), vid((x1, y0, eave)), vid((x1, y1, eave)), vid((x0, y1, eave))]
        r0, r1 = vid((xm, y0, ridge)), vid((xm, y1, ridge))
        faces = [[g],                                     # ground
                 [[e[0], r0, r1, e[3]]],                  # roof, west slope
                 [[e[1], e[2], r1, r0]],                  # roof, east slope
                 [[g[0], g[3], e[1], r0, e[0]]],          # south gable
                 [[g[2], g[1], e[3], r1, e[2]]],          # north gable
                 [[g[1], g[0], e[0], e[3]]],              # west wall
                 [[g[3], g[2], e[2], e[1]]]]              # east wall
        sem = [0, 1, 1, 2, 2, 2, 2]
        if kind == "open" and k % OPEN_EVERY == OPEN_EVERY - 1:
            faces, sem = faces[1:], sem[1:]
        semantics = {"surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface"}, {"type": "WallSurface"}],
                     "values": [sem] if kind == "solid" else sem}
        geom = ({"type": "Solid", "lod": "2.2", "boundaries": [faces], "semantics": semantics} if kind == "solid"
                else {"type": "MultiSurface", "lod": "2.2", "boundaries": faces, "semantics": semantics})
        pid = f"blk-p{k:03d}"
        cos[pid] = {"type": "BuildingPart", "parents": ["blk"], "geometry": [geom]}
        cos["blk"]["children"].append(pid)
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [0.001] * 3, "translate": [85000.0, 446000.0, 0.0]},
            "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
            "CityObjects": cos, "vertices": verts}


def export_block(n: int, kind: str, formats, workdir: Path, timeout: float = 1e6) -> tuple[float, dict]:
    """CPU s of ``lod2energy export`` of the ``n``-part block (in this process), and its report row."""
    from lod2energy.cli import main
    src = workdir / f"blk{n}_{kind}.city.json"
    src.write_text(json.dumps(block(n, kind)))
    out = workdir / f"out{n}_{kind}"
    argv = ["export", str(src), "-o", str(out), "-j", "1", "--timeout", str(timeout), "-q"]
    argv += [f"--{f}" for f in formats]
    t0 = time.process_time()
    main(argv)
    cpu = time.process_time() - t0
    (row,) = json.loads((out / "report.json").read_text())["buildings"]
    return cpu, row


def slope(ns, cpus) -> float:
    """Least-squares slope of log(cpu) against log(n)."""
    x = [math.log(v) for v in ns]
    y = [math.log(v) for v in cpus]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, nargs="+", default=[25, 50, 100, 200])
    ap.add_argument("--kind", nargs="+", default=["solid", "open"], choices=["solid", "open"])
    ap.add_argument("--formats", nargs="+", default=["idf", "stl", "cityjson"])
    ap.add_argument("--profile", type=int, metavar="N", help="cProfile the N-part block instead")
    ap.add_argument("--top", type=int, default=40, help="lines of the profile")
    ap.add_argument("-o", "--output")
    a = ap.parse_args(argv)
    lines = ["| kind | parts | CPU s | status | compliant |", "|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as tmp:
        if a.profile:
            import cProfile
            import pstats
            for kind in a.kind:
                prof = cProfile.Profile()
                prof.enable()
                cpu, row = export_block(a.profile, kind, a.formats, Path(tmp))
                prof.disable()
                print(f"== {kind}, {a.profile} parts: {cpu:.1f} CPU s, {row['status']}")
                pstats.Stats(prof).sort_stats("cumulative").print_stats(a.top)
                pstats.Stats(prof).sort_stats("tottime").print_stats(a.top)
            return 0
        summary = []
        export_block(2, "solid", a.formats, Path(tmp))  # the imports and first calls, not counted
        for kind in a.kind:
            cpus = []
            for n in a.n:
                cpu, row = export_block(n, kind, a.formats, Path(tmp))
                cpus.append(cpu)
                lines.append(f"| {kind} | {n} | {cpu:.1f} | {row['status']} | {row['energy']['compliant']} |")
                print(lines[-1], flush=True)
            if len(a.n) > 1:
                summary.append(f"{kind}: log-log slope of CPU against parts {slope(a.n, cpus):.2f}")
                print(summary[-1], flush=True)
    if a.output:
        from lod2energy.safe_write import write_text
        write_text(a.output, "\n".join(lines + [""] + summary) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
