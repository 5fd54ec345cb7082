"""Storeys estimated from the geometry alone against the storey attribute of real tiles.

For every building of the given tiles that has a storey count attribute (the 3DBAG's
``b3_bouwlagen``, CityGML ``storeysAboveGround``, ...), the count estimated from its LoD2
geometry with the attribute ignored (:func:`lod2energy.thermal.storeys.storeys` with
``use_attributes=False``, residential storey height) is compared with the attribute: the
share exact and within one storey, per attribute key, and the mean signed error; the last
two columns compare the storeys under the eave only (German ``storeysAboveGround`` counts
full storeys, "Vollgeschosse", and leaves a roof-space storey out; the 3DBAG counts it).

Usage (from the repository root)::

    python benchmarks/bench_storeys.py [TILE ...] [--out FILE.md]

Without TILE: the shared 3DBAG tiles (``../shared/data/3dbag/*.jsonl``) plus the real
CityGML / PLATEAU tiles that carry ``storeysAboveGround``.
"""
from __future__ import annotations

import argparse
import sys
from collections import defaultdict
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"


def default_tiles() -> list[Path]:
    return (sorted((DATA / "3dbag").glob("*.jsonl"))
            + [DATA / "citygml-real" / "munich" / "LOD2_4424_5482_solid.gml",
               DATA / "citygml-real" / "nrw" / "LoD2_32_280_5657_1_NW.gml",
               DATA / "japan-plateau" / "japanese.city.json"])


def measure(tiles) -> tuple[dict, list]:
    from lod2energy import io
    from lod2energy.model import Building
    from lod2energy.thermal.storeys import storeys, storeys_from_attributes

    stats: dict = defaultdict(lambda: {"n": 0, "exact": 0, "within1": 0, "err": 0.0, "exact_na": 0,
                                          "within1_na": 0})
    rows = []
    for t in tiles:
        if not Path(t).is_file():
            continue
        _, feats = io.read(str(t))
        for b in feats:
            if not isinstance(b, Building) or not b.is_building:
                continue
            n, key, _ = storeys_from_attributes(b)
            if n is None:
                continue
            est = storeys(b, use_attributes=False)
            if est.source != "geometry":
                continue
            d = est.count - n
            for k in (f"{Path(t).parent.name}: {key}", "all"):
                s = stats[k]
                s["n"] += 1
                s["exact"] += d == 0
                s["within1"] += abs(d) <= 1
                s["err"] += d
                s["exact_na"] += est.below_eave == n
                s["within1_na"] += abs(est.below_eave - n) <= 1
            rows.append((Path(t).name, b.id, key, n, est.count, est.attic))
    return stats, rows


def table(stats) -> str:
    lines = ["| tiles: attribute | buildings | exact | within 1 storey | mean error (storeys) "
             "| exact, attic not counted | within 1, attic not counted |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for k in sorted(stats, key=lambda k: (k == "all", k)):
        s = stats[k]
        lines.append(f"| {k} | {s['n']} | {100 * s['exact'] / s['n']:.0f}% | {100 * s['within1'] / s['n']:.0f}% "
                     f"| {s['err'] / s['n']:+.2f} | {100 * s['exact_na'] / s['n']:.0f}% "
                     f"| {100 * s['within1_na'] / s['n']:.0f}% |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*")
    ap.add_argument("--out", default=None)
    ap.add_argument("-v", action="store_true", help="print every building")
    a = ap.parse_args(argv)
    stats, rows = measure([Path(t) for t in a.tiles] or default_tiles())
    if a.v:
        for r in rows:
            print(*r, sep="\t")
    if not stats:
        print("no building with a storey attribute", file=sys.stderr)
        return 1
    text = table(stats)
    print(text)
    if a.out:
        from lod2energy.safe_write import write_text
        write_text(a.out, text + "\n", root=Path(a.out).resolve().parent)
    return 0


if __name__ == "__main__":
    sys.exit(main())
