"""CFD case generation and meshing time on three shared districts (OpenFOAM v1912).

Usage (from the repository root)::

    nice -n 10 python benchmarks/bench_cfd.py [--cell-size 2] [--out benchmarks/results/cfd.md]

Districts: the bundled Delft subset (whole file), a block of Den Haag tile 01 (its TINRelief as
the ground) and a block of the Berlin CityGML tile 3920_5818, picked with --centre/--radius.
For each: ``python -m lod2energy.exporters.cfd IN -o OUT --centre X,Y --radius R --cell-size C --mesh``
in a temporary folder. "prepare" is reading + validate/repair/label of the region's buildings,
"case" the surfaces, domain and dictionaries (with surfaceCheck on every surface), "mesh" the
meshing chain (blockMesh, surfaceFeatureExtract, snappyHexMesh, checkMesh). A row passes
when checkMesh says "Mesh OK" and the carved volume is within 5% of the united surfaces'.
"""
from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"

DISTRICTS = [
    ("Delft subset (bundled)", REPO / "examples" / "delft_subset.city.jsonl", []),
    ("Den Haag 01 block (TIN)", DATA / "denhaag" / "DenHaag_01.city.json", ["--centre", "78690,457885", "--radius", "50"]),
    ("Berlin 3920_5818 block", DATA / "citygml-real" / "berlin" / "3920_5818.gml",
     ["--centre", "392207,5818515", "--radius", "70"]),
]


def run(path: Path, extra: list[str], cell: float, out: Path) -> dict:
    from lod2energy.cfd.__main__ import main
    t0 = time.perf_counter()
    rc = main([str(path), "-o", str(out), "--cell-size", str(cell), "--mesh", *extra])
    wall = time.perf_counter() - t0
    rep = json.loads((out / "cfd_report.json").read_text())
    st, m = rep["stats"], rep["stats"].get("mesh", {})
    return {"rc": rc, "ok": rep["ok"], "wall_s": round(wall, 1), "prepare_s": rep.get("seconds_prepare"),
            "case_s": st.get("seconds_case"), "mesh_s": m.get("seconds_total"),
            "snappy_s": (m.get("seconds") or {}).get("snappyHexMesh"),
            "buildings": st.get("buildings_included"), "bodies": st.get("united_bodies"),
            "ground": st.get("ground"), "h_max": st["domain"]["h_max_m"],
            "blockage": st["domain"]["blockage_ratio"], "cells": m.get("cells"),
            "mesh_ok": m.get("check_mesh_ok"), "non_ortho": m.get("max_non_orthogonality"),
            "skewness": m.get("max_skewness"), "carved_m3": m.get("carved_volume_m3"),
            "united_m3": m.get("united_volume_m3"), "volume_error": m.get("carved_volume_error"),
            "problems": rep["problems"]}


def table(rows: list[tuple[str, dict]], cell: float) -> str:
    head = ("| district | buildings (bodies) | ground | H_max m | blockage | prepare s | case s | mesh s "
            "(snappy) | cells | max non-ortho | max skew | checkMesh | carved / united m3 | error |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    lines = []
    for name, r in rows:
        err = r["volume_error"]
        lines.append(
            f"| {name} | {r['buildings']} ({r['bodies']}) | {r['ground']} | {r['h_max']:.1f} | "
            f"{100 * r['blockage']:.2f}% | {r['prepare_s']} | {r['case_s']} | {r['mesh_s']} ({r['snappy_s']}) | "
            f"{r['cells']} | {r['non_ortho']} | {r['skewness']} | {'Mesh OK' if r['mesh_ok'] else 'FAILED'} | "
            f"{r['carved_m3']} / {r['united_m3']} | {100 * err:+.2f}% |" if err is not None else
            f"| {name} | {r['buildings']} | {r['ground']} | | | | | | | | | FAILED | | {r['problems'][:2]} |")
    return (f"# CFD case benchmark (OpenFOAM v1912, --cell-size {cell:g} m)\n\n"
            "Measured by `benchmarks/bench_cfd.py` on a 2-core machine shared with other jobs "
            "(load average 10-20 during the run; tools under `nice -n 10`; wall-clock seconds, so the "
            "mesh times are upper bounds).\n\n" + head + "\n".join(lines) + "\n\n"
            "- prepare: reading the file and validate/repair/label of the region's buildings; case: "
            "union, domain, dictionaries, surfaceCheck on both surfaces; mesh: blockMesh + "
            "surfaceFeatureExtract + snappyHexMesh + checkMesh.\n"
            "- carved = domain volume (less the volume under the terrain for a TIN ground) minus "
            "checkMesh's total cell volume; united = volume of the united building surfaces above "
            "the ground (manifold3d).\n"
            "- wind 270 deg (westerly), buildings at level `surface_level` (cell size), feature edges "
            "up to two levels finer (two cells across the smallest building dimension), no layers.\n")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cell-size", type=float, default=2.0)
    ap.add_argument("--out", default=str(REPO / "benchmarks" / "results" / "cfd.md"))
    ap.add_argument("--only", default=None, help="run only districts whose name contains this")
    ap.add_argument("--from-log", default=None, help="tabulate the output of an earlier run instead")
    a = ap.parse_args(argv)
    rows = []
    if a.from_log:  # re-tabulate the JSON lines printed by an earlier run
        for line in Path(a.from_log).read_text().splitlines():
            name, sep, rest = line.partition(" {")
            if sep and any(name == d[0] for d in DISTRICTS):
                rows.append((name, json.loads("{" + rest)))
        return _write(rows, a)
    with tempfile.TemporaryDirectory(prefix="bench_cfd_") as tmp:
        for i, (name, path, extra) in enumerate(DISTRICTS):
            if a.only and a.only.lower() not in name.lower():
                continue
            if not path.exists():
                print(f"skip {name}: {path} missing", file=sys.stderr)
                continue
            r = run(path, extra, a.cell_size, Path(tmp) / f"d{i}")
            print(name, json.dumps(r), flush=True)
            rows.append((name, r))
    return _write(rows, a)


def _write(rows, a) -> int:
    text = table(rows, a.cell_size)
    from lod2energy.safe_write import write_text
    out = Path(a.out)
    write_text(out, text, root=out.parent)
    print(text)
    return 0 if all(r["mesh_ok"] and r["volume_error"] is not None and abs(r["volume_error"]) < 0.05
                    for _, r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
