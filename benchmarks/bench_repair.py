"""Benchmark of the repair ladder on the shared real tiles; writes a markdown table.

Usage: python benchmarks/bench_repair.py [-o bench_repair.md] [--jobs 2] [--timeout 30] [tile ...]

Per tile: buildings, valid before/after (the project's validator, no error other than 601,
on every geometry of the building), energy-compliant before/after (also closed, outward, no
sliver: the repair criterion), stage histogram, mIoU / mAP_v (m) / mean Hausdorff (m) over
the repaired buildings, buildings per second, peak memory (max RSS of the worker, MB).
Each tile runs in its own worker process.
"""
from __future__ import annotations

import argparse
import multiprocessing as mp
import resource
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared" / "data"

TILES = [
    "denhaag/DenHaag_01.city.json",
    "val3dity-tests/rotterdam/3-20-DELFSHAVEN.city.json",
    "3dbag/3dbag_b2.city.json",
    "3dbag/9-444-728_sm.city.jsonl",
    "3dbag/delft_subset.city.jsonl",
    "3dbag/small.city.jsonl",
    "3dbag/tile5870_subset_ext.city.jsonl",
    "3dbag/tile5908_subset_ext.city.jsonl",
    "3dbag/tile901_trimmed.city.jsonl",
    "rotterdam/fme_csolid_buildings.json",
    "rotterdam/fme_csurface_buildings.json",
    "rotterdam/fme_msolid_buildings.json",
    "rotterdam/fme_msurface_buildings_semsrf_attributes.json",
    "rotterdam/fme_solid_buildings_metadata.json",
    "rotterdam/rotterdam_subset.json",
    "rotterdam/rotterdam_one.json",
    "rotterdam/Example_CityGML_Converted_Rotterdam.json",
    "rotterdam/euromast.json",
    "rotterdam/fme_solid_buildings_lod_empty.json",
    "rotterdam/fme_solid_buildings_lod_missing.json",
    "rotterdam/fme_solid_buildings_lod_null.json",
    "delft-3dfier-lod1/delft.json",
    "citygml-real/berlin/3900_5819.gml",
    "citygml-real/berlin/3920_5818.gml",
    "citygml-real/berlin/3920_5820.gml",
    "citygml-real/nrw/LoD2_32_280_5657_1_NW.gml",
    "citygml-real/munich/LOD2_4424_5482_solid.gml",
]


def run_tile(args) -> dict:
    rel, timeout = args
    sys.path.insert(0, str(REPO))
    from lod2energy.io import read
    from lod2energy.model import Building
    from lod2energy.repair.pipeline import dataset_table, repair_building
    from lod2energy.validate.checks import validate_building

    def v3_ok(b):
        return all(d.code == 601 for d in validate_building(b))

    _, it = read(str(SHARED / rel))
    ins = [b for b in it if isinstance(b, Building) and b.type == "Building"]
    t0 = time.perf_counter()
    outs = [repair_building(b, timeout=timeout) for b in ins]
    dt = time.perf_counter() - t0
    table = dataset_table(outs)
    table.update(tile=rel, seconds=dt, per_s=len(ins) / dt if dt > 0 else float("inf"),
                 v3_before=sum(v3_ok(b) for b in ins), v3_after=sum(v3_ok(b) for b in outs),
                 present=len(outs) == len(ins) and all(a.id == b.id for a, b in zip(ins, outs)),
                 max_rss_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
    return table


def _f(x, nd=3):
    return "-" if x is None else f"{x:.{nd}f}"


def markdown(rows: list[dict]) -> str:
    head = ("| tile | buildings | valid before | valid after | compliant before | compliant after | "
            "stages | mIoU | mAP_v (m) | Hausdorff (m) | bldg/s | peak MB |\n|" + "---|" * 12 + "\n")
    lines = []
    tot = {"n": 0, "vb": 0, "va": 0, "cb": 0, "ca": 0}
    for r in rows:
        n = r["total"]
        tot["n"] += n
        tot["vb"] += r["v3_before"]
        tot["va"] += r["v3_after"]
        tot["cb"] += r["compliant_before"]
        tot["ca"] += r["compliant_after"]
        st = ", ".join(f"{k} {v}" for k, v in r["stages"].items())
        lines.append(f"| {r['tile']} | {n} | {r['v3_before']} ({100 * r['v3_before'] / max(n, 1):.1f}%) | "
                     f"{r['v3_after']} ({100 * r['v3_after'] / max(n, 1):.1f}%) | {r['compliant_before']} | "
                     f"{r['compliant_after']} ({100 * r['compliant_after'] / max(n, 1):.1f}%) | {st} | "
                     f"{_f(r['miou'])} | {_f(r['map_v'])} | {_f(r['mean_hausdorff'], 2)} | "
                     f"{r['per_s']:.1f} | {r['max_rss_mb']:.0f} |")
    n = max(tot["n"], 1)
    w = [(r["n_measured"], r) for r in rows if r.get("n_measured")]
    k = sum(m for m, _ in w)

    def pooled(key):
        return sum(m * r[key] for m, r in w) / k if k else None
    lines.append(f"| **all** | {tot['n']} | {tot['vb']} ({100 * tot['vb'] / n:.1f}%) | "
                 f"{tot['va']} ({100 * tot['va'] / n:.1f}%) | {tot['cb']} | {tot['ca']} ({100 * tot['ca'] / n:.1f}%) "
                 f"| {k} repaired | {_f(pooled('miou'))} | {_f(pooled('map_v'))} | "
                 f"{_f(pooled('mean_hausdorff'), 2)} | | |")
    return head + "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*", default=TILES)
    ap.add_argument("-o", "--output", default="bench_repair.md")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=30.0)
    a = ap.parse_args(argv)
    tiles = [t for t in a.tiles if (SHARED / t).exists()]
    if not tiles:
        print("no shared tiles found under ../shared/data", file=sys.stderr)
        return 1
    with mp.get_context("spawn").Pool(a.jobs, maxtasksperchild=1) as pool:
        rows = pool.map(run_tile, [(t, a.timeout) for t in tiles], chunksize=1)
    md = markdown(rows)
    Path(a.output).write_text(md)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
