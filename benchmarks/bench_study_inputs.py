"""Where each building's study inputs come from, per shared tile, with the default profile.

For every building of the given tiles, the thermal stage (:func:`lod2energy.thermal.assign_u_values`
on the labelled, unrepaired building, with the file's CRS and ``referenceDate`` as an export
takes them) records year, storeys, use and conditioned with their sources
(:mod:`lod2energy.thermal.facts`); this counts the sources, the sentinel warnings, the
buildings marked unconditioned, and the stage's CPU time per building.

Usage (from the repository root)::

    python benchmarks/bench_study_inputs.py [TILE ...] [--map FILE.toml] [--out FILE.md]
"""
from __future__ import annotations

import argparse
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
FIELDS = ("year", "storeys", "use", "conditioned")


def default_tiles() -> list[Path]:
    return [DATA / "3dbag" / "delft_subset.city.jsonl", DATA / "3dbag" / "tile5908_subset_ext.city.jsonl",
            DATA / "denhaag" / "DenHaag_01.city.json", DATA / "citygml-real" / "nrw" / "LoD2_32_280_5657_1_NW.gml",
            DATA / "citygml-real" / "berlin" / "3900_5819.gml", DATA / "citygml-real" / "munich" / "LOD2_4424_5482_solid.gml",
            DATA / "japan-plateau" / "japanese.city.json"]


def measure(tile: Path, amap) -> dict:
    from dataclasses import replace

    from lod2energy import io
    from lod2energy.model import Building
    from lod2energy.options import ExportOptions, resolve
    from lod2energy.semantics import label_building
    from lod2energy.thermal import assign_u_values

    model, feats = io.read(str(tile))
    opts = resolve(ExportOptions(), model).prepare.thermal
    if amap is not None:
        opts = replace(opts, attribute_map=amap)
    src = {f: Counter() for f in FIELDS}
    warned, uses = Counter(), Counter()
    n = failed = unconditioned = 0
    cpu = 0.0
    name = ""
    for b in feats:
        if not isinstance(b, Building) or not b.is_building:
            continue
        n += 1
        try:
            lb = label_building(b)
            t0 = time.process_time()
            th = assign_u_values(lb, opts).provenance["thermal"]
            cpu += time.process_time() - t0
        except Exception:  # noqa: BLE001 - counted: the export reports such a building itself
            failed += 1
            continue
        name = th["attribute_map"]
        for f in FIELDS:
            src[f][th["facts"][f]["source"]] += 1
        uses[th["facts"]["use"]["value"]] += 1
        unconditioned += th["facts"]["conditioned"]["value"] is False
        warned.update(w["field"] for w in th.get("warnings", ()))
    return {"tile": f"{tile.parent.name}/{tile.name}", "n": n, "failed": failed, "map": name, "src": src,
            "uses": uses, "unconditioned": unconditioned, "warned": warned, "ms": 1000 * cpu / max(n - failed, 1)}


def _cell(c: Counter) -> str:
    return ", ".join(f"{k} {v}" for k, v in c.most_common()) or "-"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*", type=Path)
    ap.add_argument("--map", default=None, help="--attribute-map (default: the auto profile)")
    ap.add_argument("--out", type=Path, default=REPO / "benchmarks" / "results" / "study_inputs.md")
    a = ap.parse_args(argv)
    from lod2energy.thermal.attributes import load_attribute_map
    amap = load_attribute_map(a.map) if a.map else None
    rows = [measure(t, amap) for t in (a.tiles or default_tiles()) if t.is_file()]
    commit = subprocess.run(["git", "-C", str(REPO), "log", "-1", "--format=%h %ad", "--date=short"],
                            capture_output=True, text=True).stdout.strip()
    lines = [f"# Study inputs by source ({commit})", "",
             f"`python benchmarks/bench_study_inputs.py{' --map ' + a.map if a.map else ''}`: per tile, where "
             "year, storeys, use and conditioned come from (thermal stage on the labelled, unrepaired "
             "buildings), the values taken as unknown (sentinels, implausible), the buildings marked "
             "unconditioned by their use code, and the stage's CPU time per building.", "",
             "| tile | buildings | map | year | storeys | use | conditioned | uses | unconditioned | unknown (warnings) | ms/building |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        failed = f" ({r['failed']} failed)" if r["failed"] else ""
        lines.append(f"| {r['tile']} | {r['n']}{failed} "
                     f"| {r['map']} | {_cell(r['src']['year'])} | {_cell(r['src']['storeys'])} | {_cell(r['src']['use'])} "
                     f"| {_cell(r['src']['conditioned'])} | {_cell(r['uses'])} | {r['unconditioned']} "
                     f"| {_cell(r['warned'])} | {r['ms']:.2f} |")
    text = "\n".join(lines) + "\n"
    a.out.write_text(text, encoding="utf-8")
    sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
