"""What a 100,000-face building costs under ``--timeout 5``, and that the others of its file are exported.

Usage (from the repository root)::

    python benchmarks/bench_timeout.py [--jobs 1,2] [--timeout 5] [--formats idf,stl,cityjson]
                                       [--out benchmarks/results/timeout.md]

Writes a CityJSONSeq with the 10 Delft buildings of ``examples/delft_subset.city.jsonl`` and one
more Building beside them: a UV sphere of radius 10 m with 225 stacks and 224 slices (100,352
triangles), one triangle removed so that the shell is open and the repair has work to do. Runs
``lod2energy export`` on it with ``--timeout 5`` and, as the baseline, on the same file without the
sphere; the sphere's cost is the difference (wall s and CPU s of the process tree, measured as in
``bench_scale.py``). The issue's bar: <= 10 s in total for that building, reported ``timeout``,
the other buildings exported.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_scale import measure  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
DELFT = REPO / "examples" / "delft_subset.city.jsonl"


def sphere(centre: tuple[float, float, float], radius: float = 10.0, stacks: int = 225, slices: int = 224
           ) -> tuple[list[list[float]], list[list[int]]]:
    """A closed UV sphere, outward-oriented triangles.

    Returns
    -------
    vertices : (n, 3) float, m
    triangles : (2 * slices * (stacks - 1), 3) int
    """
    cx, cy, cz = centre
    v = [[cx, cy, cz + radius]]
    for i in range(1, stacks):
        th = math.pi * i / stacks
        for j in range(slices):
            ph = 2 * math.pi * j / slices
            v.append([cx + radius * math.sin(th) * math.cos(ph), cy + radius * math.sin(th) * math.sin(ph),
                      cz + radius * math.cos(th)])
    v.append([cx, cy, cz - radius])
    south = len(v) - 1

    def ring(i, j):  # vertex of ring i (1..stacks-1), slice j
        return 1 + (i - 1) * slices + j % slices

    t = [[0, ring(1, j), ring(1, j + 1)] for j in range(slices)]
    for i in range(1, stacks - 1):
        for j in range(slices):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1)
            t += [[a, c, d], [a, d, b]]
    t += [[south, ring(stacks - 1, j + 1), ring(stacks - 1, j)] for j in range(slices)]
    return v, t


def build_file(path: Path, with_sphere: bool) -> tuple[int, int]:
    """Write the Delft buildings (+ the sphere); returns (buildings, faces of the sphere)."""
    lines = [ln for ln in DELFT.read_text(encoding="utf-8").splitlines() if ln.strip()]
    header = json.loads(lines[0])
    s, tr = header["transform"]["scale"], header["transform"]["translate"]
    feats = [json.loads(ln) for ln in lines[1:]]
    xs = [p[0] for f in feats for p in f["vertices"]]
    ys = [p[1] for f in feats for p in f["vertices"]]
    zs = [p[2] for f in feats for p in f["vertices"]]
    centre = (max(xs) * s[0] + tr[0] + 40.0, (min(ys) + max(ys)) / 2 * s[1] + tr[1], min(zs) * s[2] + tr[2] + 10.0)
    out = list(lines)
    n_faces = 0
    if with_sphere:
        v, t = sphere(centre)
        del t[len(t) // 2]  # an open shell
        n_faces = len(t)
        iv = [[round((p[k] - tr[k]) / s[k]) for k in range(3)] for p in v]
        feat = {"type": "CityJSONFeature", "id": "sphere", "vertices": iv,
                "CityObjects": {"sphere": {"type": "Building", "attributes": {},
                                           "geometry": [{"type": "Solid", "lod": "2.2",
                                                         "boundaries": [[[tri] for tri in t]]}]}}}
        out.append(json.dumps(feat, separators=(",", ":")))
    path.write_text("\n".join(out) + "\n", encoding="utf-8")
    return len(feats) + with_sphere, n_faces


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jobs", default="1,2")
    ap.add_argument("--timeout", default="5")
    ap.add_argument("--formats", default="idf,stl,cityjson")
    ap.add_argument("--out", default=str(REPO / "benchmarks" / "results" / "timeout.md"))
    a = ap.parse_args(argv)
    fmt = [f"--{x}" for x in a.formats.split(",")]
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench_timeout_") as tmp:
        tmp = Path(tmp)
        big, base = tmp / "with_sphere.city.jsonl", tmp / "delft.city.jsonl"
        n_big, faces = build_file(big, True)
        n_base, _ = build_file(base, False)
        for j in a.jobs.split(","):
            res = {}
            for name, src in (("baseline", base), ("with sphere", big)):
                out = tmp / "out"
                shutil.rmtree(out, ignore_errors=True)
                cmd = [sys.executable, "-m", "lod2energy", "export", str(src), "-o", str(out), *fmt,
                       "--timeout", a.timeout, "-q", "-j", j]
                r = measure(cmd)
                rep = json.loads((out / "report.json").read_text(encoding="utf-8"))["buildings"]
                r["outcomes"] = {b["id"]: b.get("outcome") for b in rep}
                r["message"] = next((b.get("message", "") for b in rep if b["id"] == "sphere"), "")
                res[name] = r
                print(json.dumps({"jobs": j, "run": name, **r}), flush=True)
            b, w = res["baseline"], res["with sphere"]
            others = [k for k in w["outcomes"] if k != "sphere"]
            rows.append(f"| {j} | {faces:,} | {w['outcomes'].get('sphere')} | "
                        f"{sum(w['outcomes'][k] == 'done' for k in others)} of {len(others)} | "
                        f"{w['wall_s']:.1f} | {w['cpu_s']:.1f} | {b['wall_s']:.1f} | {b['cpu_s']:.1f} | "
                        f"{w['wall_s'] - b['wall_s']:.1f} | {w['cpu_s'] - b['cpu_s']:.1f} | {w['peak_mb']:.0f} | "
                        f"{w['load'][0]:.1f} -> {w['load'][1]:.1f} | {w['rc']} | {w['message'][:60]} |")
    lines = ["# A 100,000-face building under `--timeout " + a.timeout + "` (`benchmarks/bench_timeout.py`)", "",
             f"`export {' '.join(fmt)} --timeout {a.timeout}` on the 10 Delft buildings of "
             "`examples/delft_subset.city.jsonl` plus an open UV sphere of "
             f"{faces:,} triangles; baseline: the same file without the sphere. {os.cpu_count()} cores "
             "shared with other work (load average in the table): wall times are upper bounds.", "",
             "| jobs | sphere faces | sphere outcome | others done | wall s | CPU s | baseline wall s | "
             "baseline CPU s | sphere's extra wall s | sphere's extra CPU s | peak RSS MB | load avg | exit | "
             "message |",
             "|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---|", *rows]
    Path(a.out).parent.mkdir(parents=True, exist_ok=True)
    Path(a.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
