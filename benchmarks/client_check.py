"""Acceptance by the real clients: OpenFOAM surfaceCheck on every exported STL, EnergyPlus on IDFs.

Runs the user's main job (``lod2energy export``: validate, repair, labels, U-values, export)
on real tiles and hands every STL to ``surfaceCheck`` (closed, one orientation zone per part,
no illegal triangle). With ``--idf`` the IDFs are also written and, with ``--run N``, the
first N buildings of each tile are simulated by EnergyPlus (``--run 0``: all of them) and
their severe errors / "not fully enclosed" warnings counted from the ``.err`` files. With
``--days D`` each IDF is simulated over its first D days only (a copy with the RunPeriod
shortened): EnergyPlus reads and checks the whole input (geometry, enclosure, constructions)
before the first day, so a one-day run checks every building of a tile in ~1 s each instead
of ~40 s for the year.

Usage (from the repository root)::

    python benchmarks/client_check.py [TILE ...] [--idf] [--run N] [--days D] [--jobs 2]
                                      [--out FILE.md] [--keep DIR]

Without TILE: every real CityJSON / CityJSONSeq file under ../shared/data and the real
CityGML tiles of ``citygml-real`` (not the val3dity / QIE conformance files, but the
Delfshaven tile kept among them). Prints a markdown table; exit code 1 when any file failed its client.
"""
from __future__ import annotations

import argparse
import csv
import re
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
SKIP_DIRS = {"val3dity-tests", "citygml-qie-3dvalidation", "typology-teaser", "weather"}


def default_tiles() -> list[Path]:
    out = []
    for p in sorted(DATA.glob("*/*")) + sorted(DATA.glob("citygml-real/*/*.gml")):
        if p.parent.name in SKIP_DIRS or not p.name.endswith((".json", ".jsonl", ".gml")):
            continue
        out.append(p)
    # the whole Delfshaven tile sits with val3dity's files but is a real city tile
    out += sorted((DATA / "val3dity-tests" / "rotterdam").glob("*.json"))
    return out


def shortened(idf: Path, days: int, dest: Path) -> Path:
    """A copy of ``idf`` whose RunPeriod ends ``days`` days after 1 January."""
    import datetime as dt
    end = dt.date(2001, 1, 1) + dt.timedelta(days=max(1, days) - 1)
    text = idf.read_text(encoding="utf-8")
    text, n = re.subn(r"(RunPeriod,[^;]*?\n\s*1, 1, ,[^\n]*\n\s*)12, 31, ,",
                      rf"\g<1>{end.month}, {end.day}, ,", text, count=1)
    if n != 1:
        raise ValueError(f"{idf}: no annual RunPeriod to shorten")
    dest.mkdir(parents=True, exist_ok=True)
    out = dest / idf.name
    out.write_text(text, encoding="utf-8")
    return out


def check_tile(tile: Path, a, tmp: Path) -> dict:
    from lod2energy import openfoam

    out = tmp / tile.name.replace(".", "_")
    cmd = [sys.executable, "-m", "lod2energy", "export", str(tile), "-o", str(out), "--stl", "-q"]
    if a.idf:
        cmd.append("--idf")
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    dt = time.perf_counter() - t0
    row = {"tile": f"{tile.parent.name}/{tile.name}", "rc": proc.returncode, "seconds": round(dt, 1),
           "stl": 0, "stl_pass": 0, "stl_fail": [], "idf": 0, "idf_ok": 0, "eplus": 0, "eplus_ok": 0,
           "eplus_fail": []}
    report = out / "report.csv"
    rows = list(csv.DictReader(report.open())) if report.exists() else []
    row["buildings"] = len(rows)
    for stl in sorted(out.glob("*.stl")):
        row["stl"] += 1
        sc = openfoam.surface_check(stl)
        if sc.ok:
            row["stl_pass"] += 1
        else:
            row["stl_fail"].append(f"{stl.stem}: {'; '.join(sc.failures) or 'not closed'}")
    if a.idf:
        idfs = sorted(out.glob("*.idf"))
        row["idf"] = len(idfs)
        row["idf_ok"] = sum(r.get("idf_ok") == "True" for r in rows)
        if a.run is not None:
            from lod2energy.exporters import energyplus
            sel = idfs if a.run == 0 else idfs[: a.run]
            for f in sel:
                if a.days:
                    f = shortened(f, a.days, tmp / "short" / out.name)
                res = energyplus.run.run(f, weather=str(DATA / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"),
                                     outdir=tmp / "eplus" / out.name / f.stem)
                row["eplus"] += 1
                if res.ok:
                    row["eplus_ok"] += 1
                else:
                    row["eplus_fail"].append(f"{f.stem}: {'; '.join(res.problems())}")
    if a.keep:
        shutil.copytree(out, Path(a.keep) / out.name, dirs_exist_ok=True)
    return row


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*")
    ap.add_argument("--idf", action="store_true", help="also write IDFs")
    ap.add_argument("--run", type=int, default=None, help="simulate the first N IDFs per tile (0: all)")
    ap.add_argument("--days", type=int, default=None,
                    help="simulate only the first D days of the year (input checks are the same)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--keep", default=None, help="copy each tile's export folder here")
    ap.add_argument("--out", default=None, help="write the markdown table here too")
    a = ap.parse_args(argv)
    tiles = [Path(t) for t in a.tiles] or default_tiles()
    with tempfile.TemporaryDirectory(prefix="client_check_") as tmp:
        with ThreadPoolExecutor(a.jobs) as ex:
            rows = list(ex.map(lambda t: check_tile(t, a, Path(tmp)), tiles))
    lines = ["| tile | buildings | export rc | s | STL surfaceCheck pass | IDF self-check | EnergyPlus clean |",
             "|---|---|---|---|---|---|---|"]
    bad = False
    for r in rows:
        eplus = f"{r['eplus_ok']}/{r['eplus']}" if r["eplus"] else "-"
        idf = f"{r['idf_ok']}/{r['idf']}" if a.idf else "-"
        lines.append(f"| {r['tile']} | {r['buildings']} | {r['rc']} | {r['seconds']} | "
                     f"{r['stl_pass']}/{r['stl']} | {idf} | {eplus} |")
        bad |= r["stl_pass"] != r["stl"] or r["eplus_ok"] != r["eplus"]
    tot = sum(r["stl"] for r in rows), sum(r["stl_pass"] for r in rows)
    lines.append(f"| **all** | {sum(r['buildings'] for r in rows)} | | | {tot[1]}/{tot[0]} | | "
                 f"{sum(r['eplus_ok'] for r in rows)}/{sum(r['eplus'] for r in rows)} |")
    fails = [f"- {r['tile']}: {x}" for r in rows for x in r["stl_fail"] + r["eplus_fail"]]
    text = "\n".join(lines + ([""] + fails if fails else [])) + "\n"
    print(text)
    if a.out:
        Path(a.out).write_text(text, encoding="utf-8")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
