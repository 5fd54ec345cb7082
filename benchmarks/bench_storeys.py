"""Storeys estimated from the geometry alone against the storey attribute of real tiles.

For every building of the given tiles that has a storey count attribute (the 3DBAG's
``b3_bouwlagen``, CityGML ``storeysAboveGround``, ...), the count estimated from its LoD2
geometry with the attribute ignored (:func:`lod2energy.thermal.storeys.storeys` with
``use_attributes=False``, residential storey height) is compared with the attribute: the
share exact and within one storey, per attribute key, and the mean signed error; the last
two columns compare the storeys under the eave only (German ``storeysAboveGround`` counts
full storeys, "Vollgeschosse", and leaves a roof-space storey out; the 3DBAG counts it).

With ``--zones``: the storeys report.json gives each building against the storey zones its
IDF has. Each tile is exported (``lod2energy export TILE --idf --no-html -j 1``); a building's
storey zones are counted from the zone comments of its IDF (``!- zone NAME: "ID_S2"``: the
zones ``ID_S1 .. ID_Sn`` and ``ID_Attic`` cut from Building/BuildingPart ``ID``, a zone
named ``ID`` alone is one storey zone), the largest count over its Building/BuildingParts.
A building whose count differs from its ``storeys`` (the ``facts.storeys`` of report.json) is
"explained" when its record carries a downgrade that says why (``whole_zone``: a zone kept
whole; ``storeys_merged``: storey cuts dropped, a zone over two storeys), else "unexplained".

Usage (from the repository root)::

    python benchmarks/bench_storeys.py [TILE ...] [--out FILE.md]
    python benchmarks/bench_storeys.py --zones [TILE ...] [-v]

Without TILE: the shared 3DBAG tiles (``../shared/data/3dbag/*.jsonl``) plus the real
CityGML / PLATEAU tiles that carry ``storeysAboveGround``; with ``--zones``, DenHaag_01,
Delfshaven, tile5908 and a Munich tile (:func:`zone_tiles`).
"""
from __future__ import annotations

import argparse
import json
import re
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"


def default_tiles() -> list[Path]:
    return (sorted((DATA / "3dbag").glob("*.jsonl"))
            + [DATA / "citygml-real" / "munich" / "LOD2_4424_5482_solid.gml",
               DATA / "citygml-real" / "nrw" / "LoD2_32_280_5657_1_NW.gml",
               DATA / "japan-plateau" / "japanese.city.json"])


def zone_tiles() -> list[Path]:
    return [DATA / "denhaag" / "DenHaag_01.city.json", DATA / "val3dity-tests" / "rotterdam" / "3-20-DELFSHAVEN.city.json",
            DATA / "3dbag" / "tile5908_subset_ext.city.jsonl", DATA / "citygml-real" / "munich" / "LOD2_4424_5482_solid.gml"]


_ZONE = re.compile(r"^!- zone [^:]*: (\".*\")\s*$")
_STOREY = re.compile(r"^(.*)_(S(\d+)|Attic)$")
#: Downgrades that say why a building's zones are not its storeys.
EXPLAINING = ("whole_zone", "storeys_merged")


def idf_storey_zones(path: Path) -> int:
    """Storey zones of a building's IDF: the largest number of zones cut from one of its
    Building/BuildingParts (see the module docstring)."""
    per: dict[str, int] = defaultdict(int)
    with open(path, encoding="ascii", errors="replace") as f:
        for line in f:
            m = _ZONE.match(line)
            if m:
                oid = json.loads(m.group(1))
                s = _STOREY.match(oid)
                per[s.group(1) if s else oid] += 1
    return max(per.values(), default=0)


def measure_zones(tile: Path, keep: Path | None = None) -> tuple[dict, list]:
    """Export ``tile`` and compare each building's report storeys with its IDF's storey zones:
    ``({buildings, differ, explained, unexplained}, rows of the differing ones)``."""
    from lod2energy.cli import main as cli

    out = Path(keep) if keep else Path(tempfile.mkdtemp(prefix="bench_storeys_"))
    cli(["export", str(tile), "-o", str(out), "--idf", "--no-html", "-q", "-j", "1"])
    report = json.loads((out / "report.json").read_text())
    n = {"buildings": 0, "differ": 0, "explained": 0, "unexplained": 0}
    rows = []
    for b in report["buildings"]:
        idf = (b.get("exports") or {}).get("idf") or {}
        st = ((b.get("thermal") or {}).get("facts") or {}).get("storeys") or {}
        if not idf.get("ok") or not idf.get("path") or st.get("value") is None:
            continue
        n["buildings"] += 1
        zones = idf_storey_zones(out / idf["path"])  # an absolute path stays itself
        if zones == int(st["value"]):
            continue
        n["differ"] += 1
        kinds = sorted({d["kind"] for d in b.get("energy_downgrades") or () if d["kind"] in EXPLAINING})
        n["explained" if kinds else "unexplained"] += 1
        rows.append((tile.name, b["id"], st["value"], st.get("source"), zones, ",".join(kinds) or "-"))
    return n, rows


def zones_table(results: dict) -> str:
    lines = ["| tile | buildings with an IDF | storeys != IDF storey zones | explained by a downgrade | unexplained |",
             "|---|---:|---:|---:|---:|"]
    for t, n in results.items():
        lines.append(f"| {t} | {n['buildings']} | {n['differ']} | {n['explained']} | {n['unexplained']} |")
    return "\n".join(lines)


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
    ap.add_argument("--zones", action="store_true", help="report storeys against the IDF's storey zones")
    a = ap.parse_args(argv)
    if a.zones:
        results, rows = {}, []
        for t in [Path(t) for t in a.tiles] or zone_tiles():
            if t.is_file():
                results[t.name], r = measure_zones(t)
                rows += r
        if a.v:
            for r in rows:
                print(*r, sep="\t")
        print(zones_table(results))
        return 0
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
