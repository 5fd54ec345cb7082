"""City scale: buildings/s per core, speed-up from 1 to 2 workers and peak memory of the process tree.

Usage (from the repository root)::

    python benchmarks/bench_scale.py [--sizes 845,3380,13520] [--jobs 1,2]
                                     [--commands validate,export-stl,export-all,export-run]
                                     [--run-sample 5] [--dask] [--out benchmarks/results/scale.md]

Builds CityJSONSeq files by tiling translated copies of
``../shared/data/denhaag/DenHaag_01.city.json`` (845 objects a copy: 844 Buildings with their
BuildingParts and one TINRelief; 4 copies = 3,380, 16 = 13,520) side by side with a 50 m gap,
then runs each command as a subprocess (``lod2energy validate`` / ``lod2energy export ... -j N``)
and samples the resident memory of the whole process tree (the command and its workers,
psutil, every 0.1 s). ``buildings/s per core`` is objects / wall time / workers. ``export-run``
runs EnergyPlus (``--run``) on the first ``--run-sample`` buildings only. ``--dask`` adds a
row on a ``dask.distributed`` LocalCluster of 2 worker processes (through the Python API).
Timings depend on the machine's load: the table says what ran beside it.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
SOURCE = DATA / "denhaag" / "DenHaag_01.city.json"

COMMANDS = {
    "validate": ["validate", "{src}", "-q"],
    "export-stl": ["export", "{src}", "-o", "{out}", "--stl", "-q", "-j", "{jobs}"],
    "export-all": ["export", "{src}", "-o", "{out}", "--idf", "--stl", "--cityjson", "-q", "-j", "{jobs}"],
    "export-run": ["export", "{src}", "-o", "{out}", "--idf", "--run", "-q", "-j", "{jobs}"],
}


# ----------------------------------------------------------------------------- input

def _indices(boundaries, out: set) -> None:
    if isinstance(boundaries, int):
        out.add(boundaries)
    elif isinstance(boundaries, list):
        for b in boundaries:
            _indices(b, out)


def _remap(boundaries, m: dict):
    if isinstance(boundaries, int):
        return m[boundaries]
    return [_remap(b, m) for b in boundaries]


def features(doc: dict) -> list[dict]:
    """One CityJSONFeature (with its own vertex list) per first-level CityObject."""
    cos = doc["CityObjects"]
    out = []
    for oid, co in cos.items():
        if co.get("parents"):
            continue
        members = [oid] + [c for c in co.get("children", []) if c in cos]
        used: set[int] = set()
        for m in members:
            for g in cos[m].get("geometry", []):
                _indices(g.get("boundaries"), used)
        order = sorted(used)
        remap = {old: new for new, old in enumerate(order)}
        objs = {}
        for m in members:
            c = json.loads(json.dumps(cos[m]))
            for g in c.get("geometry", []):
                g["boundaries"] = _remap(g["boundaries"], remap)
            objs[m] = c
        out.append({"type": "CityJSONFeature", "id": oid, "CityObjects": objs,
                    "vertices": [doc["vertices"][i] for i in order]})
    return out


def tiled_seq(n_copies: int, path: Path) -> int:
    """Write ``n_copies`` translated copies of Den Haag as CityJSONSeq; returns the object count."""
    doc = json.loads(SOURCE.read_text(encoding="utf-8"))
    scale = doc["transform"]["scale"]
    v = doc["vertices"]
    span = [(max(p[i] for p in v) - min(p[i] for p in v)) * scale[i] + 50.0 for i in range(2)]
    feats = features(doc)
    header = {"type": "CityJSON", "version": doc["version"], "transform": doc["transform"],
              "metadata": doc.get("metadata", {}), "CityObjects": {}, "vertices": []}
    side = max(1, round(n_copies ** 0.5))
    count = 0
    with open(path, "w", encoding="utf-8") as f:
        f.write(json.dumps(header) + "\n")
        for k in range(n_copies):
            dx = round((k % side) * span[0] / scale[0])
            dy = round((k // side) * span[1] / scale[1])
            for feat in feats:
                ids = {oid: (oid if k == 0 else f"{oid}-t{k}") for oid in feat["CityObjects"]}
                objs = {}
                for oid, co in feat["CityObjects"].items():
                    co = dict(co)
                    if "children" in co:
                        co["children"] = [ids.get(c, c) for c in co["children"]]
                    if "parents" in co:
                        co["parents"] = [ids.get(c, c) for c in co["parents"]]
                    objs[ids[oid]] = co
                line = {"type": "CityJSONFeature", "id": ids[feat["id"]], "CityObjects": objs,
                        "vertices": [[p[0] + dx, p[1] + dy, p[2]] for p in feat["vertices"]]}
                f.write(json.dumps(line, separators=(",", ":")) + "\n")
                count += 1
    return count


def sample_seq(src: Path, n: int, path: Path) -> None:
    lines = src.read_text(encoding="utf-8").splitlines()
    path.write_text("\n".join(lines[: n + 1]) + "\n", encoding="utf-8")


# ----------------------------------------------------------------------------- measuring

def _tree_rss(p) -> int:
    import psutil
    total = 0
    try:
        procs = [p] + p.children(recursive=True)
    except psutil.Error:
        return 0
    for q in procs:
        try:
            total += q.memory_info().rss
        except psutil.Error:
            pass
    return total


def measure(cmd: list[str]) -> dict:
    """Wall time (s), exit code and peak RSS (MB) of the process tree of ``cmd``."""
    import psutil
    import resource
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    ps = psutil.Process(proc.pid)
    peak = 0
    stop = threading.Event()

    def sample():
        nonlocal peak
        while not stop.is_set():
            peak = max(peak, _tree_rss(ps))
            time.sleep(0.1)

    th = threading.Thread(target=sample, daemon=True)
    th.start()
    _, err = proc.communicate()
    stop.set()
    th.join()
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (ru1.ru_utime - ru0.ru_utime) + (ru1.ru_stime - ru0.ru_stime)
    return {"seconds": time.perf_counter() - t0, "cpu_s": cpu, "rc": proc.returncode, "peak_mb": peak / 2**20,
            "stderr": err.strip().splitlines()[-1:] if err.strip() else []}


def measure_dask(src: Path, out: Path, fmt: list[str]) -> dict:
    """``export`` through the Python API on a LocalCluster of 2 worker processes."""
    import psutil
    from dask.distributed import Client, LocalCluster

    from lod2energy.cli import build_parser, export_options
    from lod2energy.executor import DaskExecutor
    from lod2energy.options import RunOptions
    from lod2energy.pipeline import export

    a = build_parser().parse_args(["export", str(src), "-o", str(out), *fmt])
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        me = psutil.Process()
        peak = 0
        stop = threading.Event()

        def sample():
            nonlocal peak
            while not stop.is_set():
                peak = max(peak, _tree_rss(me))
                time.sleep(0.1)

        th = threading.Thread(target=sample, daemon=True)
        th.start()
        t0 = time.perf_counter()
        res = export(str(src), str(out), export_options(a), RunOptions(quiet=True), executor=DaskExecutor(client))
        dt = time.perf_counter() - t0
        stop.set()
        th.join()
    return {"seconds": dt, "cpu_s": None, "rc": res.exit_code, "peak_mb": peak / 2**20, "stderr": []}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="845", help="objects per file, multiples of 845 (default 845)")
    ap.add_argument("--jobs", default="1,2")
    ap.add_argument("--commands", default="validate,export-stl,export-all")
    ap.add_argument("--run-sample", type=int, default=5, help="buildings for export-run (EnergyPlus)")
    ap.add_argument("--all-sample", type=int, default=0,
                    help="export-all on the first N objects only (0: the whole file)")
    ap.add_argument("--dask", action="store_true", help="add a Dask LocalCluster row (export-stl)")
    ap.add_argument("--out", default=str(REPO / "benchmarks" / "results" / "scale.md"))
    a = ap.parse_args(argv)
    if not SOURCE.exists():
        print(f"missing {SOURCE}", file=sys.stderr)
        return 2
    exe = [sys.executable, "-m", "lod2energy"]
    sizes = [int(s) for s in a.sizes.split(",")]
    jobs = [int(j) for j in a.jobs.split(",")]
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench_scale_") as tmp:
        tmp = Path(tmp)
        for size in sizes:
            src = tmp / f"denhaag_x{size}.city.jsonl"
            n = tiled_seq(max(1, round(size / 845)), src)
            for cmd_name in a.commands.split(","):
                cmd_src, n_cmd = src, n
                sample = a.run_sample if cmd_name == "export-run" else (
                    a.all_sample if cmd_name == "export-all" else 0)
                if sample:
                    cmd_src = tmp / f"sample_{sample}.city.jsonl"
                    sample_seq(src, sample, cmd_src)
                    n_cmd = sample
                for j in (jobs if cmd_name.startswith("export") else [1]):
                    out = tmp / "out"
                    shutil.rmtree(out, ignore_errors=True)
                    cmd = exe + [x.format(src=cmd_src, out=out, jobs=j) for x in COMMANDS[cmd_name]]
                    r = measure(cmd)
                    rows.append({"objects": n_cmd, "command": cmd_name, "workers": j, **r})
                    print(json.dumps(rows[-1]), flush=True)
            if a.dask:
                out = tmp / "out"
                shutil.rmtree(out, ignore_errors=True)
                r = measure_dask(src, out, ["--stl", "-q"])
                rows.append({"objects": n, "command": "export-stl (Dask LocalCluster)", "workers": 2, **r})
                print(json.dumps(rows[-1]), flush=True)
    write_table(rows, Path(a.out))
    return 0


def write_table(rows: list[dict], path: Path) -> None:
    base = {(r["objects"], r["command"]): r["seconds"] for r in rows if r["workers"] == 1}
    lines = ["# City scale (`benchmarks/bench_scale.py`)", "",
             f"Tiled copies of `../shared/data/denhaag/DenHaag_01.city.json` as CityJSONSeq; "
             f"{os.cpu_count()} cores, shared with other work while it ran (figures are lower bounds).", "",
             "`objects/CPU-s` is objects per CPU-second of the whole process tree (the fair per-core "
             "rate on a loaded machine); `objects/s per worker` is objects / wall time / workers.", "",
             "| objects | command | workers | wall s | CPU s | objects/CPU-s | objects/s per worker | "
             "speed-up vs 1 (wall) | peak RSS MB (tree) | exit |",
             "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        rate = r["objects"] / r["seconds"] / r["workers"] if r["seconds"] else 0.0
        cpu = r.get("cpu_s")
        per_cpu = f"{r['objects'] / cpu:.1f}" if cpu else ""
        b = base.get((r["objects"], r["command"].split(" (")[0]))
        sp = f"{b / r['seconds']:.2f}x" if b and r["workers"] > 1 else ""
        lines.append(f"| {r['objects']:,} | {r['command']} | {r['workers']} | {r['seconds']:.1f} | "
                     f"{'' if cpu is None else f'{cpu:.1f}'} | {per_cpu} | {rate:.1f} | "
                     f"{sp} | {r['peak_mb']:.0f} | {r['rc']} |")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"table: {path}")


if __name__ == "__main__":
    sys.exit(main())
