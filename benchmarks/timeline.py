"""How busy each process of a run is, second by second: where a parallel run waits.

Usage (from the repository root)::

    python benchmarks/timeline.py [--step 0.1] [--out timeline.json] -- lod2energy export FILE --idf -j 2 -o OUT -q

Runs the command and samples its process tree with psutil every ``--step`` s: each process's
CPU seconds (user + system) since the last sample. Prints, per whole second of wall time,
the cores busy in all (``busy``) and in each process (the run's own process first, then its
children by start), and a summary: wall s, CPU s, the mean cores busy, and the seconds in
which fewer than ``--low`` cores were busy (where the speed-up of ``-j N`` is lost: serial
phases, barriers, a process waiting for another). Not a test; figures go to
``benchmarks/results/scale.md``.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time


def sample(cmd: list[str], step: float) -> tuple[float, list[tuple[float, dict[int, float]]], dict[int, float]]:
    """Run ``cmd``; return its wall seconds, the samples ``(t, {pid: cpu s})`` and each pid's start time."""
    import psutil
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd)
    root = psutil.Process(proc.pid)
    samples: list[tuple[float, dict[int, float]]] = []
    started: dict[int, float] = {}
    last: dict[int, float] = {}
    while proc.poll() is None:
        now = time.monotonic() - t0
        cpu: dict[int, float] = {}
        try:
            procs = [root] + root.children(recursive=True)
        except psutil.Error:
            procs = []
        for p in procs:
            try:
                c = p.cpu_times()
                cpu[p.pid] = c.user + c.system
                started.setdefault(p.pid, now)
            except psutil.Error:
                pass
        last.update(cpu)
        samples.append((now, dict(last)))
        time.sleep(step)
    return time.monotonic() - t0, samples, started


def per_second(samples, started) -> tuple[list[int], list[list[float]]]:
    """CPU seconds used in each whole second, per pid (in start order)."""
    pids = sorted(started, key=lambda p: (started[p], p))
    if not samples:
        return pids, []
    n = int(samples[-1][0]) + 1
    rows = [[0.0] * len(pids) for _ in range(n)]
    prev = {p: 0.0 for p in pids}
    for t, cpu in samples:
        sec = min(int(t), n - 1)
        for k, p in enumerate(pids):
            v = cpu.get(p, prev[p])
            rows[sec][k] += max(0.0, v - prev[p])
            prev[p] = v
    return pids, rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--step", type=float, default=0.1, help="sampling interval, s (default 0.1)")
    ap.add_argument("--low", type=float, default=1.5, help="'low' seconds: fewer cores busy than this (default 1.5)")
    ap.add_argument("--out", help="write the per-second table as JSON here")
    ap.add_argument("cmd", nargs=argparse.REMAINDER, help="-- then the command")
    a = ap.parse_args(argv)
    cmd = a.cmd[1:] if a.cmd[:1] == ["--"] else a.cmd
    if not cmd:
        ap.error("give the command after --")
    wall, samples, started = sample(cmd, a.step)
    pids, rows = per_second(samples, started)
    print("sec  busy  " + "  ".join(f"p{k}" for k in range(len(pids))))
    for s, r in enumerate(rows):
        print(f"{s:3d}  {sum(r):4.2f}  " + "  ".join(f"{v:4.2f}" for v in r))
    total = sum(map(sum, rows))
    low = [s for s, r in enumerate(rows[:-1]) if sum(r) < a.low]
    print(f"wall {wall:.1f} s, CPU {total:.1f} s, mean busy {total / max(wall, 1e-9):.2f} cores, "
          f"{len(low)} s below {a.low:g} cores busy: {low}")
    if a.out:
        with open(a.out, "w") as f:
            json.dump({"cmd": cmd, "wall_s": wall, "pids": pids, "per_second": rows}, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
