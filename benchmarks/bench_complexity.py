"""Benchmark: the CPU cost of one building against its number of BuildingParts.

Usage: python benchmarks/bench_complexity.py [-n 25 50 100 200] [--kind solid open] [--profile N]
       [-o complexity.md] [--formats idf stl cityjson]

A synthetic housing block of ``n`` parts (``tests/factories.py``: ``terraced_block``) is exported in this process with
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
sys.path.insert(0, str(REPO / "tests"))

from factories import terraced_block  # noqa: E402 - the synthetic block the tests export too

def export_block(n: int, kind: str, formats, workdir: Path, timeout: float = 1e6) -> tuple[float, dict]:
    """CPU s of ``lod2energy export`` of the ``n``-part block (in this process), and its report row."""
    from lod2energy.cli import main
    src = workdir / f"blk{n}_{kind}.city.json"
    src.write_text(json.dumps(terraced_block(n, kind)))
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
