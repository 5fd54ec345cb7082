"""CPU cost of the repair's fidelity metrics (IoU, mAP_v, Hausdorff) against faces per building.

Usage: python benchmarks/bench_fidelity.py [tile] [-o fidelity.md] [--cache calls.pkl] [--timeout 30]

Repairs every building of the tile (default: the shared 3DBAG LoD2.2 tile5908) once, recording
each call of :func:`lod2energy.repair.metrics.fidelity` with its arguments and the CPU seconds
of the whole repair; then replays every call twice, timed in CPU seconds: with the spatial index
(as shipped) and with every point measured against every triangle (the reference, as before
the index), the point-triangle distances also timed alone. It checks that both give the same values bit for bit and reports, per building,
fidelity CPU against input faces: totals, median, p95, the log-log slope, and the share of the
repair's CPU.
"""
from __future__ import annotations

import argparse
import math
import pickle
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared" / "data"
DEFAULT_TILE = SHARED / "3dbag" / "tile5908_subset_ext.city.jsonl"


def record(tile: Path, timeout: float) -> list[dict]:
    """Per building: id, input faces, repair CPU s, and the fidelity calls' arguments."""
    from lod2energy.io import read
    from lod2energy.model import Building
    from lod2energy.repair import pipeline

    calls: list = []
    orig = pipeline.fidelity

    spent = [0.0]

    def spy(*args, **kw):
        calls.append((args, kw))
        t0 = time.process_time()
        try:
            return orig(*args, **kw)
        finally:
            spent[0] += time.process_time() - t0

    pipeline.fidelity = spy
    rows = []
    try:
        _, it = read(str(tile))
        for b in it:
            if not isinstance(b, Building) or b.type != "Building":
                continue
            calls.clear()
            spent[0] = 0.0
            t0 = time.process_time()
            pipeline.repair_building(b, timeout=timeout)
            rows.append({"id": b.id, "repair_s": time.process_time() - t0, "fidelity_s": spent[0],
                         "calls": list(calls)})
    finally:
        pipeline.fidelity = orig
    return rows


def replay(rows: list[dict], indexed: bool) -> tuple[list[float], list[float], list[list[dict]]]:
    """Per building: CPU s of the fidelity calls, of their point-triangle distances, and the
    results; indexed or every pair measured."""
    from lod2energy.repair import metrics

    keep, ptd = metrics._ALL_PAIRS_MAX, metrics.point_triangle_distance
    dist = [0.0]

    def timed(*args, **kw):
        t0 = time.process_time()
        try:
            return ptd(*args, **kw)
        finally:
            dist[0] += time.process_time() - t0
    metrics._ALL_PAIRS_MAX = keep if indexed else math.inf
    metrics.point_triangle_distance = timed
    secs, dsecs, results = [], [], []
    try:
        for r in rows:
            dist[0] = 0.0
            t0 = time.process_time()
            res = [metrics.fidelity(*a, **kw) for a, kw in r["calls"]]
            secs.append(time.process_time() - t0)
            dsecs.append(dist[0])
            results.append(res)
    finally:
        metrics._ALL_PAIRS_MAX, metrics.point_triangle_distance = keep, ptd
    return secs, dsecs, results


def slope(x, y) -> float:
    """Least-squares slope of log y against log x over the points with both > 0."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    ok = (x > 0) & (y > 0)
    return float(np.polyfit(np.log(x[ok]), np.log(y[ok]), 1)[0]) if ok.sum() >= 2 else float("nan")


def same(a: dict, b: dict) -> bool:
    """Every value equal bit for bit (NaN equal to NaN)."""
    return a.keys() == b.keys() and all(
        np.asarray(a[k]).tobytes() == np.asarray(b[k]).tobytes() for k in a)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tile", nargs="?", default=str(DEFAULT_TILE))
    ap.add_argument("-o", "--output", default="fidelity.md")
    ap.add_argument("--cache", help="pickle of the recorded calls: read if present, else written")
    ap.add_argument("--timeout", type=float, default=30.0, help="repair budget per building, s")
    a = ap.parse_args(argv)
    sys.path.insert(0, str(REPO))
    if a.cache and Path(a.cache).exists():
        rows = pickle.loads(Path(a.cache).read_bytes())
    else:
        if not Path(a.tile).exists():
            print(f"no tile {a.tile}", file=sys.stderr)
            return 1
        rows = record(Path(a.tile), a.timeout)
        if a.cache:
            Path(a.cache).write_bytes(pickle.dumps(rows))
    rows = [r for r in rows if r["calls"]]
    faces = [sum(args[0].n_faces for args, _ in r["calls"]) for r in rows]
    ref_s, ref_d, ref_res = replay(rows, indexed=False)
    new_s, new_d, new_res = replay(rows, indexed=True)
    identical = all(same(x, y) for rx, ry in zip(ref_res, new_res) for x, y in zip(rx, ry))
    repair = sum(r["repair_s"] for r in rows)
    # the repair's own CPU: as recorded, less the fidelity metrics it ran
    work = repair - sum(r["fidelity_s"] for r in rows)

    def line(name, s):
        s = np.asarray(s)
        return (f"| {name} | {s.sum():.2f} | {1000 * np.median(s):.1f} | {1000 * np.percentile(s, 95):.1f} | "
                f"{1000 * s.max():.0f} | {slope(faces, s):.2f} | {100 * s.sum() / work:.1f}% |")
    md = "\n".join([
        f"Tile: `{Path(a.tile).name}`; {len(rows)} buildings with a fidelity call "
        f"({sum(len(r['calls']) for r in rows)} calls), input faces per building {min(faces)}-{max(faces)} "
        f"(median {int(np.median(faces))}); repair CPU as recorded {repair:.1f} s, {work:.1f} s of it the repair's own work (without the metrics).",
        "",
        "| fidelity metrics | CPU s | median ms | p95 ms | max ms | log-log slope vs faces | of the repair's CPU |",
        "|---|---|---|---|---|---|---|",
        line("all pairs (before)", ref_s),
        line("k-d tree (after)", new_s),
        line("of which distances, before", ref_d),
        line("of which distances, after", new_d),
        "",
        f"Speed-up {sum(ref_s) / max(sum(new_s), 1e-9):.1f}x; every value (IoU, mean displacement both ways, "
        f"Hausdorff, closure) bit-identical: {'yes' if identical else 'NO'}.",
    ]) + "\n"
    Path(a.output).write_text(md)
    print(md)
    return 0 if identical else 2


if __name__ == "__main__":
    sys.exit(main())
