"""The slowest buildings of a file: CPU s of each building's preparation (validate, repair ladder,
labels, compliance, final check), one building after the other in one process.

Usage: python benchmarks/bench_slowest.py FILE [FILE ...] [--top 5] [--timeout 30]

Prints, per file, the ``--top`` slowest buildings (CPU s, the repair stage of each geometry
that needed one) and the sum over the file. CPU s are the process's own plus its finished
children's (the alpha wrap runs in a forked child). ``--timeout`` is the export's budget
(``--timeout``): the ladder gets ``lod2energy.options.ladder_budget`` of it, as in ``export``.
A building's CPU s over the budget would be a timeout in ``export`` (its job is stopped there).
"""
from __future__ import annotations

import argparse
import resource
import time
from pathlib import Path


def _cpu() -> float:
    s, c = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return s.ru_utime + s.ru_stime + c.ru_utime + c.ru_stime


def _stages(b) -> str:
    rep = b.provenance.get("repair") or {}
    out = [f"{g['lod']}:{g['stage']}" for g in rep.get("geometries", ()) if g.get("stage") != "valid"]
    return " ".join(out) or "valid"


def run(path: Path, timeout: float) -> list[tuple[float, str, str]]:
    from lod2energy.io import read
    from lod2energy.options import PrepareOptions
    from lod2energy.prepare import prepare_building

    _, features = read(str(path))
    rows = []
    for b in features:
        if not hasattr(b, "objects"):
            continue
        t = _cpu()
        rb, _ = prepare_building(b, PrepareOptions(timeout=timeout))
        rows.append((_cpu() - t, b.id, _stages(rb)))
    return rows


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="+", type=Path)
    ap.add_argument("--top", type=int, default=5)
    ap.add_argument("--timeout", type=float, default=30.0)
    a = ap.parse_args(argv)
    for f in a.files:
        t0 = time.monotonic()
        rows = sorted(run(f, a.timeout), reverse=True)
        total = sum(r[0] for r in rows)
        print(f"## {f.name}: {len(rows)} buildings, {total:.1f} CPU s, {time.monotonic() - t0:.1f} wall s, "
              f"{sum(r[0] > a.timeout for r in rows)} over {a.timeout:g} CPU s")
        for cpu, bid, stages in rows[:a.top]:
            print(f"| {bid} | {cpu:.2f} | {stages} |")


if __name__ == "__main__":
    main()
