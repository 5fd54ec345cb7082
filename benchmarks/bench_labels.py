"""Benchmark: area-weighted agreement of the labelling rules alone with the input's labels.

Runs over every CityJSON / CityJSONSeq file of the shared real tiles (``../shared/data``
relative to the repo root, or the folder given as the first argument) and prints, per
tile, the labelled area, the share on which the rules agree, and the largest confusions.
With ``--repair`` the buildings are first repaired (``lod2energy.repair.pipeline``) and
labelled with :func:`lod2energy.semantics.label_building`; agreement is then also reported
for the final labels against the input's own labels.

With ``--export DIR`` (implies ``--repair``) the labelled buildings also get U-values and
are exported with :mod:`lod2energy.exporters.cityjson.writer` in every CityJSON version
(``--versions``), and the self-check result is reported per tile and version, with the
number of exported surfaces, those labelled and those with a positive U-value (counted by
re-reading the exported file).

Usage: python benchmarks/bench_labels.py [DATA_DIR] [--repair] [--export DIR] [--json OUT]
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import replace
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared"
TILE_DIRS = ("3dbag", "rotterdam", "denhaag", "delft-3dfier-lod1", "france-roofer", "japan-plateau",
             "montreal", "swiss-building", "val3dity-tests/rotterdam")


def tiles(root: Path) -> list[Path]:
    out = []
    for d in TILE_DIRS:
        p = root / d
        if p.is_dir():
            out += sorted(x for x in p.iterdir() if x.suffix in (".json", ".jsonl"))
    return out


def rule_agreement(b) -> tuple[float, float]:
    """Area-weighted agreement of the rules alone with the input's own labels of building ``b``:
    ``(agree_area, total_area)``, m2, over the faces that carry an input label."""
    from lod2energy import semantics

    agree = total = 0.0
    for o, gi, g in semantics.envelope_objects(b, None):
        t = semantics.face_table(b.vertices, g)
        rl = semantics.rule_labels(t, semantics.DEFAULT_RULES)
        for i, s in enumerate(t.surfaces):
            st = semantics._known_type(g, s)
            if st is None:
                continue
            total += float(t.area[i])
            if st == rl[i]:
                agree += float(t.area[i])
    return agree, total


def label_confusion(b) -> dict[tuple[str, str], float]:
    """Area (m2) per (input label, rule label) pair of building ``b``."""
    from lod2energy import semantics

    out: dict[tuple[str, str], float] = {}
    for o, gi, g in semantics.envelope_objects(b, None):
        t = semantics.face_table(b.vertices, g)
        rl = semantics.rule_labels(t, semantics.DEFAULT_RULES)
        for i, s in enumerate(t.surfaces):
            st = semantics._known_type(g, s)
            if st is not None:
                out[(st, rl[i])] = out.get((st, rl[i]), 0.0) + float(t.area[i])
    return out


def run_tile(path: Path, repair: bool, export: str | None = None, versions=("1.0", "1.1", "2.0")) -> dict:
    from lod2energy.io import cityjson
    from lod2energy.model import Building
    from lod2energy import semantics

    model, feats = cityjson.read(str(path))
    if model is None:
        return {"tile": f"{path.parent.name}/{path.name}", "unreadable_file": [f.message for f in feats]}
    labelled = []
    agree = total = 0.0
    final_agree = final_total = final_without = final_far = 0.0
    conf: dict = {}
    n = n_err = n_rep = 0
    for f in feats:
        if not isinstance(f, Building):
            n_err += 1
            continue
        n += 1
        a, t = rule_agreement(f)
        agree += a
        total += t
        for k, v in label_confusion(f).items():
            conf[k] = conf.get(k, 0.0) + v
        if repair:
            from lod2energy.repair.pipeline import repair_building
            try:
                rb = repair_building(f, lod=f.default_lod())
                if isinstance(rb, tuple):
                    rb = rb[0]
            except Exception as e:  # benchmark: report and continue
                print(f"  repair failed on {f.id}: {e}", file=sys.stderr)
                continue
            n_rep += 1
            lb = semantics.label_building(rb, source=f)
            labelled.append(lb)
            fa, ft, fw, ff = final_label_agreement(f, lb)
            final_far += ff
            final_agree += fa
            final_total += ft
            final_without += fw
    top = sorted(((v, k) for k, v in conf.items() if k[0] != k[1]), reverse=True)[:3]
    exports = {}
    if export:
        exports = export_tile(path, model, labelled, export, versions)
    return {"tile": f"{path.parent.name}/{path.name}", "buildings": n, "unreadable": n_err,
            "labelled_area_m2": round(total, 1),
            "rule_agreement_pct": round(100 * agree / total, 2) if total else None,
            "top_confusions": [f"{k[0]}->{k[1]}: {v:.1f} m2" for v, k in top],
            **({"repaired": n_rep,
                "final_agreement_pct": round(100 * final_agree / final_total, 2) if final_total else None,
                "final_area_without_labelled_input_face_pct": round(100 * final_without / (final_total + final_without), 2)
                if final_total + final_without else None,
                "final_area_far_from_input_pct": round(100 * final_far / (final_total + final_without), 2)
                if final_total + final_without else None}
               if repair else {}), **({"exports": exports} if export else {})}


def export_tile(path: Path, model, labelled, outdir: str, versions) -> dict:
    """Export the labelled buildings in each version; self-check result and surface counts."""
    from lod2energy import thermal
    from lod2energy.exporters.cityjson import writer as X
    from lod2energy.io import cityjson
    from lod2energy.model import Building

    opts = thermal.ThermalOptions(crs=model.crs)
    ready = []
    for b in labelled:
        try:
            ready.append(thermal.assign_u_values(b, opts))
        except Exception as e:  # benchmark: report and continue
            print(f"  thermal failed on {b.id}: {e}", file=sys.stderr)
    out = {}
    for v in versions:
        target = Path(outdir) / f"{path.parent.name}__{path.name.split('.')[0]}.v{v.replace('.', '')}.city.json"
        t0 = time.time()
        r = X.write(str(target), model, ready, v)
        n_s = n_lab = n_u = 0
        if r.ok:
            _, feats = cityjson.read(r.path)
            for f in feats:
                if not isinstance(f, Building):
                    continue
                for o, gi, g in __import__("lod2energy.semantics", fromlist=["x"]).envelope_objects(f):
                    for *_, s in g.iter_surfaces():
                        n_s += 1
                        e = g.semantic_surfaces[s.semantic] if s.semantic is not None else {}
                        n_lab += e.get("type") is not None
                        n_u += isinstance(e.get("uValue"), (int, float)) and e.get("uValue") > 0
        out[v] = {"ok": r.ok, "buildings": len(r.building_ids), "skipped": len(r.skipped),
                  "skip_reasons": sorted({s[1].split(":")[-1].strip()[:60] for s in r.skipped})[:3],
                  "problems": list(r.problems[:3]), "surfaces": n_s, "labelled": n_lab,
                  "with_u": n_u, "seconds": round(time.time() - t0, 1), "notes": list(r.notes[:3])}
    return out


FAR = 2.0  # m


def final_label_agreement(source, labelled) -> tuple[float, float, float, float]:
    """Agreement of the final labels with the input's own labels, area-weighted.

    A face that came from an input face carries that face's label (``labelSource`` "input")
    and agrees by construction; every other output face (created by the repair) is compared
    with the input face of compatible normal (within 30 degrees) nearest to it, the look-up
    label transfer uses.

    Returns
    -------
    agree : float, m2
        Area of output faces labelled like their input face.
    comparable : float, m2
        Area of output faces that have such an input face (labelled).
    without_input : float, m2
        Area of output faces with no input face to compare with (no labelled input face of
        similar orientation; the rules label them).
    far : float, m2
        Area of output faces whose nearest compatible input face is more than
        ``FAR`` m away (a measure of how much the repair moved the envelope).
    """
    from lod2energy import semantics as S

    src = S._SourceFaces(source, None)
    near = replace(S.DEFAULT_RULES, transfer_max_dist=FAR)
    agree = comparable = without = far = 0.0
    for o, gi, g in S.envelope_objects(labelled):
        t = S.face_table(labelled.vertices, g)
        for i, s in enumerate(t.surfaces):
            if t.area[i] <= 0:
                continue
            if g.semantic_surfaces[s.semantic].get("labelSource") == "input":
                comparable += t.area[i]
                agree += t.area[i]
                continue
            hit = src.nearest(t.normal[i], t.centroid[i], S.DEFAULT_RULES)
            if hit is None:
                without += t.area[i]
                continue
            if src.nearest(t.normal[i], t.centroid[i], near) is None:
                far += t.area[i]
            comparable += t.area[i]
            if hit[0] == g.semantic_type(s):
                agree += t.area[i]
    return agree, comparable, without, far


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("data", nargs="?", default=str(SHARED / "data"))
    ap.add_argument("--repair", action="store_true")
    ap.add_argument("--json")
    ap.add_argument("--export")
    ap.add_argument("--versions", default="1.0,1.1,2.0")
    ap.add_argument("--only", help="comma-separated substrings of the tile paths to run")
    ap.add_argument("--skip", help="comma-separated substrings of tile paths to leave out")
    a = ap.parse_args(argv)
    if a.export:
        a.repair = True
    rows = []
    tot_a = tot_t = 0.0
    t0 = time.time()
    for p in tiles(Path(a.data)):
        if a.only and not any(x in str(p) for x in a.only.split(",")):
            continue
        if a.skip and any(x in str(p) for x in a.skip.split(",")):
            continue
        r = run_tile(p, a.repair, a.export, tuple(a.versions.split(",")))
        rows.append(r)
        if r.get("rule_agreement_pct") is not None:
            tot_a += r["rule_agreement_pct"] * r["labelled_area_m2"] / 100
            tot_t += r["labelled_area_m2"]
        print(json.dumps(r))
    summary = {"all_tiles_rule_agreement_pct": round(100 * tot_a / tot_t, 2) if tot_t else None,
               "labelled_area_m2": round(tot_t, 1), "seconds": round(time.time() - t0, 1)}
    print(json.dumps(summary))
    if a.json:
        Path(a.json).write_text(json.dumps({"tiles": rows, "summary": summary}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
