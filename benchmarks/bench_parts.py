"""Benchmark: BuildingPart overlaps (val3dity 601) before and after repair, per building.

Usage: python benchmarks/bench_parts.py [-o parts.md] [--overlap-tol -1] [--timeout 30] [--clip] [--all] [tile ...]

For every building of a tile with at least two geometries (Solid, CompositeSolid, MultiSurface
or CompositeSurface) among its Building and BuildingParts (one LoD), the 601 errors (pairs of overlapping solids, lod2energy's val3dity 601
at the given overlap tolerance, checked whatever the lower levels say) of the input and of the
repaired building are counted. Reported per tile: buildings with parts, buildings repaired,
601 pairs before / after, buildings with more 601 pairs after than before (the figure that must
be 0), buildings whose new overlaps the repair resolved (``parts_overlap`` records), seconds.
With ``--clip`` "after" is the building the writers get: the repair, then the preparation
stage that separates input overlaps (:func:`lod2energy.repair.parts.clip_overlapping_parts`);
three more columns count the buildings it separated, the volume it took off (m3) and the
buildings with a pair it could not separate (left, reported). Parts given as surfaces have no
601 before (val3dity tests solids only); once repaired into solids they are counted after, so a
repair that makes MultiSurface parts overlap shows as "more after".

``--all``: every shared real tile (the tiles of ``client_check.py``) and the conformance files
above; a tile without parts is a row of zeros.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared" / "data"
sys.path.insert(0, str(REPO))

TILES = [
    "denhaag/DenHaag_01.city.json",
    "citygml-real/nrw/LoD2_32_280_5657_1_NW.gml",
    "3dbag/tile5908_subset_ext.city.jsonl",
    "val3dity-tests/gml/DenHaag_1BwBP.gml",
    "val3dity-tests/gml/dh_1.gml",
    "val3dity-tests/test_cjseq/denhaag_random_5.city.jsonl",
    "val3dity-tests/test_cjseq/notransform.city.jsonl",
    "val3dity-tests/test_geometry_specific/601.json",
    "val3dity-tests/test_geometry_specific/601_1.json",
    "rotterdam/rotterdam_subset.json",
    "rotterdam/fme_solid_buildings_metadata.json",
    "citygml-real/munich/LOD2_4424_5482_solid.gml",
    "citygml-real/berlin/3920_5818.gml",
]


def n_solids(b, lod) -> int:
    return sum(1 for o in b.envelope_objects for g in o.geometries
               if g.lod == lod and g.type in ("Solid", "CompositeSolid") and g.solids)


def n_parts(b, lod) -> int:
    """Geometries at ``lod`` among the Building and its parts that could be (or become) solids."""
    return sum(1 for o in b.envelope_objects for g in o.geometries
               if g.lod == lod and g.type in ("Solid", "CompositeSolid", "MultiSurface", "CompositeSurface"))


def all_tiles() -> list[Path]:
    """Every shared real tile (as ``client_check.py`` finds them) and the conformance files of TILES."""
    sys.path.insert(0, str(REPO / "benchmarks"))
    from client_check import default_tiles
    real = default_tiles()
    return real + [SHARED / t for t in TILES if SHARED / t not in real]


def bench_tile(path: Path, tol, timeout: float, clip: bool = False) -> dict:
    from lod2energy.io import read
    from lod2energy.model import Building
    from lod2energy.repair.parts import clip_overlapping_parts
    from lod2energy.repair.pipeline import repair_building
    from lod2energy.validate.solid import check_parts_overlap

    model, feats = read(str(path))
    row = {"tile": str(path.relative_to(SHARED)) if SHARED in path.parents else str(path),
           "with_parts": 0, "repaired": 0, "before": 0, "after": 0, "worse": 0, "resolved": 0,
           "worse_ids": [], "clipped": 0, "removed_m3": 0.0, "kept": 0}
    if model is None:
        return row
    t0 = time.monotonic()
    for b in feats:
        if not isinstance(b, Building) or not b.is_building:
            continue
        lod = b.default_lod()
        if n_parts(b, lod) < 2:
            continue
        row["with_parts"] += 1
        before = len(check_parts_overlap([b], tol)[0]) if n_solids(b, lod) >= 2 else 0
        rb = repair_building(b, tol=tol, timeout=timeout, lod=lod)
        if rb is not b:
            row["repaired"] += 1
        if clip:
            rb, crec = clip_overlapping_parts(rb, tol, lod)
            row["clipped"] += int(bool(crec.get("clipped") or crec.get("united")))
            row["kept"] += int(bool(crec.get("left")))
            row["removed_m3"] += crec.get("volume_removed_m3", 0.0)
        after = len(check_parts_overlap([rb], tol)[0]) if n_solids(rb, lod) >= 2 else 0
        row["before"] += before
        row["after"] += after
        if after > before:
            row["worse"] += 1
            row["worse_ids"].append(b.id)
        rec = (rb.provenance.get("repair") or {}).get("parts_overlap") or {}
        row["resolved"] += int(bool(rec.get("resolved")))
    row["seconds"] = round(time.monotonic() - t0, 1)
    return row


def main(argv=None) -> int:
    from lod2energy.config import Tolerances
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*")
    ap.add_argument("-o", "--output")
    ap.add_argument("--overlap-tol", type=float, default=-1.0)
    ap.add_argument("--timeout", type=float, default=30.0)
    ap.add_argument("--clip", action="store_true", help="after = repair + clip_overlapping_parts")
    ap.add_argument("--all", action="store_true", help="every shared real tile and the conformance files")
    a = ap.parse_args(argv)
    tol = Tolerances(overlap_tol=a.overlap_tol)
    paths = all_tiles() if a.all else [Path(t) if Path(t).exists() else SHARED / t for t in (a.tiles or TILES)]
    lines = [f"601 (BuildingParts overlap, overlap_tol {a.overlap_tol}) before / after repair", "",
             "| tile | buildings with parts | repaired | 601 before | 601 after | buildings with more 601 after "
             "| new overlaps resolved | s |" + (" separated (clip) | m3 taken off | with a pair left |" if a.clip else ""),
             "|---|---|---|---|---|---|---|---|" + ("---|---|---|" if a.clip else "")]
    if a.clip:
        lines[0] += ", after = repair + clip_overlapping_parts"
    tot = {k: 0 for k in ("with_parts", "repaired", "before", "after", "worse", "resolved", "clipped", "kept")}
    tot["removed_m3"], tot["seconds"], n_tiles = 0.0, 0.0, 0
    for p in paths:
        if not p.exists():
            continue
        try:
            r = bench_tile(p, tol, a.timeout, a.clip)
        except Exception as e:  # noqa: BLE001 - an unreadable tile is its row, the others go on
            lines.append(f"| {p.relative_to(SHARED) if SHARED in p.parents else p} | not read: "
                         f"{type(e).__name__}: {str(e)[:80]} |")
            print(lines[-1], flush=True)
            continue
        n_tiles += 1
        for k in tot:
            tot[k] += r.get(k, 0)
        lines.append(f"| {r['tile']} | {r['with_parts']} | {r['repaired']} | {r['before']} | {r['after']} | "
                     f"{r['worse']}{' (' + ', '.join(r['worse_ids'][:5]) + ')' if r['worse'] else ''} | "
                     f"{r['resolved']} | {r.get('seconds', 0)} |"
                     + (f" {r['clipped']} | {r['removed_m3']:.2f} | {r['kept']} |" if a.clip else ""))
        print(lines[-1], flush=True)
    lines.append(f"| **all {n_tiles} tiles** | {tot['with_parts']} | {tot['repaired']} | {tot['before']} | "
                 f"{tot['after']} | {tot['worse']} | {tot['resolved']} | {tot['seconds']:.0f} |"
                 + (f" {tot['clipped']} | {tot['removed_m3']:.2f} | {tot['kept']} |" if a.clip else ""))
    print(lines[-1], flush=True)
    if a.output:
        from lod2energy.safe_write import write_text
        write_text(a.output, "\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
