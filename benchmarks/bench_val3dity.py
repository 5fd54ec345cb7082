"""`lod2energy validate` side by side with val3dity 2.6 on the same files, in one run.

Usage (from the repository root)::

    python benchmarks/bench_val3dity.py --val3dity PATH/TO/val3dity [--repeat 3]
                                        [--files denhaag,tile5908,...] [--out benchmarks/results/val3dity.md]

The val3dity binary comes from ``--val3dity`` or ``$VAL3DITY``; without one the script says so and
exits 0 (it is not part of the tests). val3dity is not shipped with lod2energy: build 2.6.x from
https://github.com/tudelft3d/val3dity (CGAL, Eigen, GEOS, Boost.Filesystem; ``cmake .. && make``).

Both tools run as subprocesses on the same file, each writing its JSON report, alternately, ``--repeat``
times; the best CPU time of each is kept. CPU seconds are those of the process and its children
(``resource.getrusage(RUSAGE_CHILDREN)`` before and after), the fair figure on a loaded machine;
wall seconds are upper bounds. lod2energy's figure includes the Python start-up and imports (given
separately in the ``import CPU s`` column) because a user pays them too. lod2energy runs with its
bytecode compiled, as an installed package is (``compileall``, ``PYTHONDONTWRITEBYTECODE`` cleared
for its runs): otherwise every run would also compile its ~60 modules from source, about 0.25 CPU s.

The 3DBAG tiles carry LoD 1.2, 1.3 and 2.2 of every BuildingPart. lod2energy validates the highest
LoD >= 2 (2.2); val3dity validates every geometry. So that both do the same work, each such file is
first copied with only its LoD 2.2 geometries (``lod22`` in the table); val3dity's time on the
original file is given too (``val3dity all LoDs``).
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
FILES = {
    "denhaag": "denhaag/DenHaag_01.city.json",
    "delfshaven": "val3dity-tests/rotterdam/3-20-DELFSHAVEN.city.json",
    "tile5908": "3dbag/tile5908_subset_ext.city.jsonl",
    "tile5870": "3dbag/tile5870_subset_ext.city.jsonl",
    "tile901": "3dbag/tile901_trimmed.city.jsonl",
    "delft": "3dbag/delft_subset.city.jsonl",
    "berlin": "citygml-real/berlin/3920_5818.gml",
}


IMPORTS = ("import lod2energy.cli, lod2energy.io, lod2energy.validate.report, lod2energy.validate.checks, "
           "shapely")
"""What a ``validate`` of a CityJSON file imports (its start-up, without the work). No scipy: the
validate path needs none since session 33 (GEOS's CDT, numpy close pairs and components); a
polygon GEOS does not take still loads scipy's Qhull, inside the work."""

START = "from lod2energy.run.blas_threads import one_blas_thread\none_blas_thread()\n" + IMPORTS
"""The start-up alone: one BLAS thread set before numpy loads (as :func:`lod2energy.cli.main`
does; otherwise OpenBLAS's spinning threads add CPU time), then the imports."""

CHILD = ("import resource, sys\n" + START + "\n"
         "r = resource.getrusage(resource.RUSAGE_SELF)\n"
         "start = r.ru_utime + r.ru_stime\n"
         "rc = lod2energy.cli.main(sys.argv[2:])\n"
         "with open(sys.argv[1], 'w') as f:\n"
         "    f.write(repr(start))\n"
         "sys.exit(rc)\n")
"""``lod2energy validate`` as the CLI runs it, writing the CPU s its start-up (interpreter and
imports) took to ``argv[1]``: the run's own split of start-up and work, not a separate estimate."""


def lod_only(src: Path, dst: Path, lod: str = "2.2") -> bool:
    """Copy a CityJSONSeq keeping, per CityObject, only its geometries of ``lod`` when it has them.

    Returns
    -------
    bool
        True when some geometry was dropped (the file had other LoDs too).
    """
    dropped = False
    with open(src, encoding="utf-8") as f, open(dst, "w", encoding="utf-8") as g:
        for line in f:
            if not line.strip():
                continue
            doc = json.loads(line)
            for co in doc.get("CityObjects", {}).values():
                geoms = co.get("geometry") or []
                keep = [x for x in geoms if str(x.get("lod")) == lod]
                if keep and len(keep) < len(geoms):
                    co["geometry"] = keep
                    dropped = True
            g.write(json.dumps(doc, separators=(",", ":")) + "\n")
    return dropped


def timed(cmd: list[str], env: dict | None = None, start_file: Path | None = None) -> dict:
    """Run ``cmd``; wall s, CPU s (user + system of the process tree) and the exit code, and with
    ``start_file`` (written by :data:`CHILD`) the CPU s of the run's start-up (``start``)."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    out = {"wall": wall, "cpu": cpu, "rc": p.returncode, "err": p.stderr.strip()[-300:]}
    if start_file is not None:
        try:
            out["start"] = float(start_file.read_text())
        except (OSError, ValueError):
            out["start"] = None
        start_file.unlink(missing_ok=True)
    return out


def compiled_env() -> dict:
    """The environment of the lod2energy runs: its bytecode compiled once (``__pycache__``, as pip
    installs it) and read from there, as with the third-party packages' own."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(REPO / "lod2energy")], env=env,
                   stdout=subprocess.DEVNULL, check=False)
    return env


def overview(report: Path) -> tuple[int, int]:
    """(Buildings, valid Buildings) from a val3dity-shaped JSON report."""
    try:
        d = json.loads(report.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return (0, 0)
    for fo in d.get("features_overview", []):
        if fo.get("type") == "Building":
            return (int(fo.get("total", 0)), int(fo.get("valid", 0)))
    return (0, 0)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--val3dity", default=os.environ.get("VAL3DITY"), help="val3dity binary (default $VAL3DITY)")
    ap.add_argument("--repeat", type=int, default=3, help="runs per tool and file; the best CPU time is kept")
    ap.add_argument("--files", default=",".join(FILES), help="comma list of: " + ", ".join(FILES))
    ap.add_argument("--out", default=str(REPO / "benchmarks" / "results" / "val3dity.md"))
    ap.add_argument("--data", default=str(DATA), help="the shared data folder (default ../shared/data)")
    a = ap.parse_args(argv)
    v3 = a.val3dity and shutil.which(a.val3dity)
    if not v3:
        print("no val3dity binary: pass --val3dity PATH or set $VAL3DITY (skipped)", file=sys.stderr)
        return 0
    ver = subprocess.run([v3, "--version"], capture_output=True, text=True).stdout.strip().splitlines()
    l2e = [sys.executable, "-c", CHILD]
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench_val3dity_") as tmp:
        tmp = Path(tmp)
        env = compiled_env()
        imp = min(timed([sys.executable, "-c", START], env)["cpu"]
                  for _ in range(a.repeat))
        start_file = tmp / "start"
        for key in a.files.split(","):
            src = Path(a.data) / FILES[key]
            if not src.exists():
                print(f"missing {src}", file=sys.stderr)
                continue
            same, full = src, None
            if src.suffix == ".jsonl":
                cand = tmp / (src.name.replace(".city.jsonl", "") + "_lod22.city.jsonl")
                if lod_only(src, cand):
                    same, full = cand, src
            best = {"l2e": None, "v3": None, "v3full": None}
            for _ in range(a.repeat):
                runs = {"l2e": l2e + [str(start_file), "validate", str(same), "-q", "--report", str(tmp / "l2e.json")],
                        "v3": [v3, str(same), "-r", str(tmp / "v3.json")]}
                if full is not None:
                    runs["v3full"] = [v3, str(full), "-r", str(tmp / "v3full.json")]
                for k, cmd in runs.items():
                    r = timed(cmd, env, start_file) if k == "l2e" else timed(cmd)
                    if best[k] is None or r["cpu"] < best[k]["cpu"]:
                        best[k] = r
            n_l, ok_l = overview(tmp / "l2e.json")
            n_v, ok_v = overview(tmp / "v3.json")
            row = {"file": FILES[key] + (" (lod22)" if full else ""), "buildings": n_l or n_v,
                   "valid_l2e": ok_l, "valid_v3": ok_v, "buildings_v3": n_v,
                   "l2e": best["l2e"], "v3": best["v3"], "v3full": best["v3full"],
                   "load": os.getloadavg()[0]}
            rows.append(row)
            print(json.dumps({k: v for k, v in row.items()}), flush=True)
    version = "val3dity " + ver[0].split("version:")[-1].strip() if ver else "val3dity"
    write_table(rows, Path(a.out), version, imp, a.repeat)
    return 0


def write_table(rows: list[dict], path: Path, version: str, imp: float, repeat: int) -> None:
    lines = [f"## {time.strftime('%Y-%m-%d', time.gmtime())}: `bench_val3dity.py --repeat {repeat}`", "",
             f"{version}, built from the 2.6.0 tag with `-O2` (its CMakeLists' default); both tools on the "
             f"same file in the same run, best CPU time of {repeat}; {os.cpu_count()} cores shared with "
             "other work (load average in the table).", "",
             f"lod2energy's CPU s include the Python start-up and imports (numpy, shapely, the validation "
             f"modules; bytecode compiled): {imp:.2f} CPU s alone (best of {repeat}). "
             "`start-up` is that part of the best run itself (measured inside it, before the CLI's work); "
             "`work` is the rest: reading, checks, report.", "",
             "| file | buildings | valid (lod2energy / val3dity) | lod2energy CPU s | of it start-up / work | "
             "lod2energy wall s | val3dity CPU s | val3dity wall s | lod2energy bldg/CPU-s | val3dity bldg/CPU-s | "
             "val3dity CPU / lod2energy CPU | val3dity CPU / lod2energy work | val3dity all LoDs CPU s | load avg |",
             "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        l, v, f = r["l2e"], r["v3"], r["v3full"]
        n = r["buildings"]
        start = l.get("start")
        split, per_work = "", ""
        if start is not None:
            work = max(l["cpu"] - start, 1e-3)
            split, per_work = f"{start:.2f} / {work:.2f}", f"{v['cpu'] / work:.2f}x"
        lines.append(
            f"| {r['file']} | {n} | {r['valid_l2e']} / {r['valid_v3']} | {l['cpu']:.2f} | {split} | {l['wall']:.2f} | "
            f"{v['cpu']:.2f} | {v['wall']:.2f} | {n / l['cpu']:.0f} | {n / v['cpu']:.0f} | "
            f"{v['cpu'] / l['cpu']:.2f}x | {per_work} | {'' if f is None else '%.2f' % f['cpu']} | {r['load']:.1f} |")
    lines += ["", "A ratio >= 1.00x means lod2energy is no slower than val3dity on that file."]
    path.parent.mkdir(parents=True, exist_ok=True)
    title = "# `lod2energy validate` and val3dity side by side (`benchmarks/bench_val3dity.py`)"
    old = path.read_text(encoding="utf-8") if path.exists() else title + "\n"
    head, _, rest = old.partition("\n")  # the newest section first, under the title; older ones kept
    path.write_text("\n".join([head if head.startswith("# ") else title, ""] + lines) + "\n"
                    + (rest if head.startswith("# ") else old), encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
