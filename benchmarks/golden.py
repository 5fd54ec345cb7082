"""Fingerprints of every output of the main commands on the bundled example and shared real tiles.

A refactoring that must leave outputs byte-identical runs this before and after and compares:

    python benchmarks/golden.py record before.json            # at the old commit
    python benchmarks/golden.py record after.json             # at the new one
    python benchmarks/golden.py compare before.json after.json

Each case runs one command into its own folder; every file it wrote is hashed (sha256) after the
paths of the output folder, the repository and the shared data are replaced by tokens and, in JSON
reports, the keys that hold a measured time are left out (key order kept).
The spool (``.lod2energy/``) is run machinery, not output, and is left out; ``--skip-journal``
leaves out ``report.jsonl`` too. ``--quick`` runs only the cases that take seconds (the example,
the CFD case, validate); ``--only NAME`` one case.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "data"
EXAMPLE = ROOT / "examples" / "delft_subset.city.jsonl"
TILES = {
    "denhaag": SHARED / "denhaag" / "DenHaag_01.city.json",
    "delfshaven": SHARED / "val3dity-tests" / "rotterdam" / "3-20-DELFSHAVEN.city.json",
    "tile5908": SHARED / "3dbag" / "tile5908_subset_ext.city.jsonl",
}
ALL4 = ["--idf", "--stl", "--cityjson", "--geojson"]


def cases(quick: bool) -> list[tuple[str, list[str], bool]]:
    """(name, command arguments with OUT for the output, slow?)."""
    out = [
        ("example-export", ["export", str(EXAMPLE), "-o", "OUT", *ALL4, "-j", "2"], False),
        ("example-cfd", ["export", str(EXAMPLE), "-o", "OUT", "--cfd", "-j", "2"], False),
        ("example-repair", ["repair", str(EXAMPLE), "-o", "OUT/repaired.city.json", "--report",
                            "OUT/repair.json"], False),
    ]
    for name, path in TILES.items():
        out.append((f"{name}-validate", ["validate", str(path), "--report", "OUT/validate.json"], False))
    for name, path in TILES.items():
        out.append((f"{name}-export", ["export", str(path), "-o", "OUT", *ALL4, "-j", "2"], True))
    out.append(("tile5908-repair", ["repair", str(TILES["tile5908"]), "-o", "OUT/repaired.city.json",
                                    "--report", "OUT/repair.json", "-j", "2"], True))
    return [c for c in out if not (quick and c[2])]


#: Keys of JSON reports that hold a measured time (they differ run to run).
TIMING = re.compile(r"^(time|seconds.*|.*_seconds|elapsed.*|timings?)$")


def _untimed(x):
    if isinstance(x, dict):
        return {k: _untimed(v) for k, v in x.items() if not TIMING.match(k)}
    if isinstance(x, list):
        return [_untimed(v) for v in x]
    return x


def fingerprint(folder: Path, skip_journal: bool) -> dict[str, str]:
    """sha256 of every output file under ``folder``, with the output folder, the repository and the
    shared data's paths replaced by tokens and, in JSON reports, timing keys left out."""
    tokens = [(str(folder.resolve()), "OUTDIR"), (str(SHARED.resolve()), "SHARED"), (str(SHARED), "SHARED"),
              (str(ROOT), "REPO")]
    digests = {}
    for p in sorted(folder.rglob("*")):
        rel = p.relative_to(folder).as_posix()
        if not p.is_file() or rel.startswith(".lod2energy/") or (skip_journal and rel == "report.jsonl"):
            continue
        data = p.read_bytes()
        for old, new in tokens:
            data = data.replace(old.encode(), new.encode())
        if rel.endswith((".json", ".jsonl")) and not rel.endswith(".city.json"):
            try:
                lines = [json.loads(x) for x in data.splitlines() if x.strip()] if rel.endswith(".jsonl") \
                    else [json.loads(data)]
                data = "\n".join(json.dumps(_untimed(x)) for x in lines).encode()
            except ValueError:
                pass
        digests[rel] = hashlib.sha256(data).hexdigest()
    return digests


def record(target: str, quick: bool, only: str | None, skip_journal: bool) -> None:
    result = {}
    for name, args, _ in cases(quick):
        if only and name != only:
            continue
        with tempfile.TemporaryDirectory(prefix=f"golden-{name}-") as tmp:
            out = Path(tmp) / "out"
            out.mkdir()
            argv = [a.replace("OUT", str(out)) if a.startswith("OUT") else a for a in args]
            t0 = time.perf_counter()
            proc = subprocess.run([sys.executable, "-m", "lod2energy", *argv, "-q"], capture_output=True, text=True)
            files = fingerprint(out, skip_journal)
            result[name] = {"exit": proc.returncode, "files": files}
            print(f"{name}: exit {proc.returncode}, {len(files)} files, {time.perf_counter() - t0:.1f} s",
                  file=sys.stderr)
    Path(target).write_text(json.dumps(result, indent=1, sort_keys=True))


def compare(a: str, b: str) -> int:
    A, B = json.loads(Path(a).read_text()), json.loads(Path(b).read_text())
    bad = 0
    for name in sorted(set(A) | set(B)):
        if name not in A or name not in B:
            print(f"{name}: only in {'before' if name in A else 'after'}")
            continue
        fa, fb = A[name]["files"], B[name]["files"]
        if A[name]["exit"] != B[name]["exit"]:
            print(f"{name}: exit {A[name]['exit']} -> {B[name]['exit']}")
            bad += 1
        diff = sorted(k for k in set(fa) | set(fb) if fa.get(k) != fb.get(k))
        for k in diff:
            print(f"{name}: {k}: {'missing' if k not in fb else 'new' if k not in fa else 'differs'}")
        bad += len(diff)
        if not diff:
            print(f"{name}: {len(fa)} files identical")
    print("identical" if not bad else f"{bad} differences")
    return 1 if bad else 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("record", help="run the cases and write their fingerprints")
    r.add_argument("target")
    r.add_argument("--quick", action="store_true", help="only the cases that take seconds")
    r.add_argument("--only", help="one case by name")
    r.add_argument("--skip-journal", action="store_true", help="leave report.jsonl out")
    c = sub.add_parser("compare", help="compare two fingerprint files")
    c.add_argument("before")
    c.add_argument("after")
    a = ap.parse_args()
    if a.cmd == "record":
        record(a.target, a.quick, a.only, a.skip_journal)
        return 0
    return compare(a.before, a.after)


if __name__ == "__main__":
    sys.exit(main())
