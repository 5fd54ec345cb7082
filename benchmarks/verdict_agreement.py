"""One verdict: ``validate``'s codes against the repair path's input codes, per building, on every
shared real tile; and BuildingPart overlaps (601) before and after the repair.

Usage: PYTHONPATH=$PWD python benchmarks/verdict_agreement.py [-o verdict.md] [--jobs 1]
[--timeout 30] [tile ...]

For every Building of every real tile under ``../shared/data`` (the val3dity and CityGML-QIE
unit-test files left out), the building is repaired as ``lod2energy repair`` / ``export`` do
(:func:`lod2energy.repair.pipeline.repair_building`) and, per geometry the ladder looked at, the
val3dity codes of its input record (``defects_before``, codes under 1000) are compared with the
codes :func:`lod2energy.validate.checks.validate_geometry` (``lod2energy validate``) finds.
Per tile: buildings, buildings that disagree, valid Solids (no val3dity code) the ladder
changed anyway - by a global stage (must never happen) or by a local one (only for the
project's energy codes: a sliver, vertices shared only once snapped) - and buildings with more
601 after the repair than before, with the 601 totals (the validator's BuildingPart check,
:func:`lod2energy.validate.solid.check_parts_overlap`, run on every building whatever its other
codes, as the ladder's own :func:`lod2energy.repair.parts.overlap_pairs` does).
Disagreeing buildings are listed under the table. Each tile runs in its own worker process.
"""
from __future__ import annotations

import argparse
import multiprocessing as mp
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared" / "data"
#: Folders of unit-test files and non-geometry data, not real tiles.
NOT_TILES = {"val3dity-tests", "citygml-qie-3dvalidation", "typology-teaser", "weather"}
SUFFIXES = (".json", ".jsonl", ".gml")


def real_tiles() -> list[str]:
    """Paths (relative to the shared data) of every real tile."""
    out = []
    for p in sorted(SHARED.rglob("*")):
        rel = p.relative_to(SHARED)
        if p.is_file() and p.suffix in SUFFIXES and rel.parts[0] not in NOT_TILES and len(rel.parts) > 1:
            out.append(str(rel))
    return out


def run_tile(args) -> dict:
    rel, timeout = args
    sys.path.insert(0, str(REPO))
    from lod2energy.config import DEFAULT
    from lod2energy.io import read
    from lod2energy.model import Building
    from lod2energy.repair.pipeline import LOCAL, repair_building
    from lod2energy.validate.checks import validate_geometry
    from lod2energy.validate.solid import check_parts_overlap

    def n601(x):
        return sum(d[1] == 601 for d in check_parts_overlap([x], DEFAULT)[0])

    t0 = time.perf_counter()
    _, it = read(str(SHARED / rel))
    ins = [b for b in it if isinstance(b, Building) and b.is_building]
    row = {"tile": rel, "buildings": len(ins), "disagree": 0, "replaced_valid": 0, "local_valid": 0,
           "more_601": 0, "601_before": 0, "601_after": 0, "examples": []}
    for b in ins:
        rb = repair_building(b, DEFAULT, timeout=timeout)
        geoms = {(o.id, gi): g for o in b.objects for gi, g in enumerate(o.geometries)}
        rec = rb.provenance.get("repair") or {}
        bad = []
        for e in rec.get("geometries", ()):
            g = geoms[(e["object"], e["geometry"])]
            want = sorted({d.code for d in validate_geometry(b.vertices, e["object"], e["geometry"], g, DEFAULT)})
            got = sorted(c for c in e["defects_before"] if c < 1000)
            if got != want:
                bad.append(f"{e['object']} geom {e['geometry']}: validate {want}, repair input {got}")
            if not want and g.type == "Solid" and e["stage"] != "valid":
                local = e["stage"] in LOCAL
                row["local_valid" if local else "replaced_valid"] += 1
                bad.append(f"{e['object']} geom {e['geometry']}: valid, {'changed' if local else 'replaced'} by "
                           f"stage {e['stage']} (input codes {e['defects_before']})")
        n0 = n601(b)
        n1 = n0 if rb is b else n601(rb)
        row["601_before"] += n0
        row["601_after"] += n1
        if n1 > n0:
            row["more_601"] += 1
            bad.append(f"601: {n0} before, {n1} after")
        if bad:
            row["disagree"] += any("validate" in x for x in bad)
            row["examples"].append(f"{b.id}: " + "; ".join(bad))
    row["seconds"] = time.perf_counter() - t0
    return row


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*", help="tiles (relative to ../shared/data); default: every real tile")
    ap.add_argument("-o", "--output", help="markdown file to write (default: stdout only)")
    ap.add_argument("--jobs", type=int, default=1, help="worker processes")
    ap.add_argument("--timeout", type=float, default=30.0, help="repair budget per building, s")
    a = ap.parse_args(argv)
    tiles = a.tiles or real_tiles()
    ctx = mp.get_context("spawn")
    with ctx.Pool(a.jobs, maxtasksperchild=1) as pool:
        rows = pool.map(run_tile, [(t, a.timeout) for t in tiles], chunksize=1)
    keys = ("buildings", "disagree", "replaced_valid", "local_valid", "more_601", "601_before", "601_after")
    lines = ["| tile | buildings | disagree | valid replaced (global) | valid changed (local) | more 601 after "
             "| 601 before | 601 after | s |", "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    tot = {k: 0 for k in keys}
    for r in rows:
        lines.append(f"| {r['tile']} | " + " | ".join(str(r[k]) for k in keys) + f" | {r['seconds']:.1f} |")
        for k in tot:
            tot[k] += r[k]
    lines.append("| **all** | " + " | ".join(str(tot[k]) for k in keys) + " | |")
    ex = [f"- {r['tile']}: {x}" for r in rows for x in r["examples"]]
    text = "\n".join(lines + ([""] + ex if ex else [])) + "\n"
    print(text)
    if a.output:
        Path(a.output).write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
