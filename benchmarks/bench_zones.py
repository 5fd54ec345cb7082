"""Benchmark: storey zoning of tall and many-part buildings, exported by the CLI at the default budget.

Usage: python benchmarks/bench_zones.py [--keep DIR]

Two synthetic buildings (``tests/factories.stepped_tower``: 40 storeys of 3 m with two
set-backs, attribute ``storeysAboveGround = 40``; ``tests/test_many_parts.many_parts``: 200
BuildingParts) are written as CityJSON and exported with ``lod2energy export --idf --stl -j 1``
(the default ``--timeout``). Printed per building: the export's wall time (s), whether the IDF
and STL passed their self-checks, the zones, the highest zone (m, from the IDF's surfaces),
the building's storeys, and the zones' volume against the shell's (report.csv).
"""
from __future__ import annotations

import argparse
import csv
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests"))

from factories import stepped_tower  # noqa: E402 - the tests' builders
from test_many_parts import many_parts  # noqa: E402


def tower_doc() -> dict:
    """The 40-storey tower as a CityJSON document (RD New, mm integers)."""
    b = stepped_tower()
    g = b.objects[0].geometries[0]
    types: list[str] = []
    faces, values = [], []
    for s in g.solids[0].shells[0].surfaces:
        faces.append([[int(i) for i in r] for r in s.rings])
        t = g.semantic_type(s)
        if t not in types:
            types.append(t)
        values.append(types.index(t))
    geom = {"type": "Solid", "lod": "2.2", "boundaries": [faces],
            "semantics": {"surfaces": [{"type": t} for t in types], "values": [values]}}
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [0.001] * 3, "translate": [85000.0, 446000.0, 0.0]},
            "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
            "CityObjects": {"tower": {"type": "Building", "attributes": {"storeysAboveGround": 40},
                                      "geometry": [geom]}},
            "vertices": [[round((x + 100) * 1000), round((y + 100) * 1000), round(z * 1000)] for x, y, z in b.vertices]}


def zone_heights(idf: Path) -> dict[str, float]:
    """Zone name -> height (m): the z-range of its surfaces' vertices."""
    body = re.sub(r"!.*", "", idf.read_text())
    lo: dict[str, float] = {}
    hi: dict[str, float] = {}
    for obj in body.split(";"):
        f = [x.strip() for x in obj.split(",")]
        if f[0] != "BuildingSurface:Detailed":
            continue
        z = np.array([float(x) for x in f[12:12 + 3 * int(f[11])]]).reshape(-1, 3)[:, 2]
        lo[f[4]] = min(lo.get(f[4], np.inf), float(z.min()))
        hi[f[4]] = max(hi.get(f[4], -np.inf), float(z.max()))
    return {k: hi[k] - lo[k] for k in lo}


def zone_volumes(idf: Path) -> list[float]:
    body = re.sub(r"!.*", "", idf.read_text())
    return [float(f[9]) for f in ([x.strip() for x in o.split(",")] for o in body.split(";")) if f[0] == "Zone"]


def run(name: str, doc: dict, work: Path) -> None:
    src = work / f"{name}.city.json"
    src.write_text(json.dumps(doc))
    out = work / name
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "lod2energy", "export", str(src), "-o", str(out), "--idf", "--stl",
                           "-j", "1", "-q", "--no-html"], capture_output=True, text=True)
    dt = time.perf_counter() - t0
    (row,) = list(csv.DictReader((out / "report.csv").open()))
    idfs = list(out.glob("*.idf"))
    heights = zone_heights(idfs[0]) if idfs else {}
    info = json.loads((out / "report.json").read_text())["buildings"][0]
    storeys = (info.get("thermal") or {}).get("storeys")
    vol = sum(zone_volumes(idfs[0])) if idfs else 0.0
    print(f"| {name} | {proc.returncode} | {dt:.1f} | {row.get('idf_ok')} | {row.get('stl_ok')} | {len(heights)} | "
          f"{max(heights.values(), default=0):.2f} | {storeys} | {vol:.1f} | {row.get('volume_m3')} | "
          f"{row.get('downgrades') or '-'} |")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--keep", default=None, help="write the inputs and outputs here (default: a temporary folder)")
    a = ap.parse_args(argv)
    work = Path(a.keep) if a.keep else Path(tempfile.mkdtemp(prefix="bench_zones_"))
    work.mkdir(parents=True, exist_ok=True)
    print("| building | exit | wall s | idf ok | stl ok | zones | highest zone m | storeys | "
          "zone volumes m3 | shell volume m3 | downgrades |")
    print("|---|---:|---:|---|---|---:|---:|---:|---:|---:|---|")
    run("tower40", tower_doc(), work)
    run("parts200", many_parts(solid=True)[0], work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
