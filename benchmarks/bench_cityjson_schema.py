"""Time the CityJSON self-check's schema validation on a real file (not a test).

Each measure runs in a fresh interpreter (validators built there, as in a worker):

- ``schema first`` / ``schema again``: the schema shortcut of the self-check
  (``exporters.cityjson.schema._schema_valid_fast``) on the whole document, the first call
  (building the validator included) and a second one;
- ``self-check``: :func:`exporters.cityjson.check.self_check_document` on a copy of the file
  (schema, geometry and envelope checks), with the number of problems and a digest of their
  text, so that two versions of the code can be shown to give the same messages.

Usage::

    python benchmarks/bench_cityjson_schema.py [FILE] [--repeat 3]

Default file: ``../shared/data/val3dity-tests/rotterdam/3-20-DELFSHAVEN.city.json``.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DEFAULT = REPO.parent / "shared" / "data" / "val3dity-tests" / "rotterdam" / "3-20-DELFSHAVEN.city.json"

CHILD = r"""
import hashlib, json, sys, time
from lod2energy.exporters.cityjson import check, schema
from lod2energy.io.cityjson import normalise_version
path = sys.argv[1]
doc = json.load(open(path, encoding="utf-8"))
version = normalise_version(doc.get("version"))
out = {"objects": len(doc.get("CityObjects") or {}), "version": version}
t = time.process_time()
out["schema_valid"] = bool(schema._schema_valid_fast(version, doc))
out["schema first"] = time.process_time() - t
t = time.process_time()
schema._schema_valid_fast(version, doc)
out["schema again"] = time.process_time() - t
t = time.process_time()
problems = check.self_check_document(path)
out["self-check"] = time.process_time() - t
out["problems"] = len(problems)
out["digest"] = hashlib.sha256("\n".join(problems).encode()).hexdigest()[:16]
print(json.dumps(out))
"""


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file", nargs="?", default=str(DEFAULT))
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args(argv)
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    runs = []
    with tempfile.TemporaryDirectory() as d:
        copy = os.path.join(d, os.path.basename(a.file))  # the self-check keeps scratch files beside it
        shutil.copyfile(a.file, copy)
        for _ in range(a.repeat):
            res = subprocess.run([sys.executable, "-c", CHILD, copy], capture_output=True, text=True, env=env)
            if res.returncode:
                print(res.stderr, file=sys.stderr)
                return 1
            runs.append(json.loads(res.stdout.strip().splitlines()[-1]))
    first = runs[0]
    print(f"{Path(a.file).name}: CityJSON {first['version']}, {first['objects']} CityObjects, "
          f"schema valid: {first['schema_valid']}, self-check problems: {first['problems']} "
          f"(digest {first['digest']})")
    for key in ("schema first", "schema again", "self-check"):
        vals = [r[key] for r in runs]
        print(f"  {key:<13} median {statistics.median(vals):7.3f} CPU s  (min {min(vals):.3f}, max {max(vals):.3f})")
    if len({(r["problems"], r["digest"], r["schema_valid"]) for r in runs}) != 1:
        print("  the runs disagree", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
