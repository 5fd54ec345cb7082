"""Acceptance by the real clients: OpenFOAM surfaceCheck on every exported STL, EnergyPlus on IDFs.

Runs the user's main job (``lod2energy export``: validate, repair, labels, U-values, export;
the IDF with the default ``--zoning storey``) on real tiles and hands every STL to
``surfaceCheck`` (closed, one orientation zone per part, no illegal triangle). With ``--idf``
the IDFs are also written and, with ``--run N``, the first N IDFs of each tile are simulated
by EnergyPlus (``--run 0``: all of them). Per IDF the check reads back:

- from ``eplusout.err``: the severe / fatal errors, every zone "not fully enclosed" and the
  surfaces it calls "upside down" (a Roof/Ceiling facing down, a Floor facing up);
- the zones of the IDF (``Zone`` objects) and their volumes as EnergyPlus uses them (the
  ``Zone Information`` rows of ``eplusout.eio``), and each zone's volume rebuilt from its
  own ``BuildingSurface:Detailed`` vertices (divergence theorem);
- the volume of the exported shell: the building's STL (the same repaired envelope, written
  for CFD), by the signed volume of its triangles.

An IDF passes when EnergyPlus completes with 0 severe errors, every zone is enclosed and
the zone volumes EnergyPlus reports sum to the STL's volume within ``--vol-tol`` (0.5%).
An EnergyPlus severe error on an IDF whose own self-check passed (``idf_ok`` in the
report) is flagged: the self-check must catch every surface EnergyPlus calls degenerate.

With ``--days D`` each IDF is simulated over its first D days only (a copy with the
RunPeriod shortened): EnergyPlus reads and checks the whole input (geometry, enclosure,
constructions) before the first day, so a one-day run checks every building in ~1 s.

Usage (from the repository root)::

    python benchmarks/client_check.py [TILE ...] [--idf] [--cityjson] [--run N] [--days D] [--jobs 2]
                                      [--export-jobs J] [--out FILE.md] [--jsonl FILE] [--keep DIR]
                                      [--keep-failures DIR]
    python benchmarks/client_check.py --table ROWS.jsonl [...] --out FILE.md

With ``--cityjson`` the energy CityJSON is written too, and each tile's row counts the
buildings called compliant against the buildings each writer accepted (``<writer>_ok`` in
``report.csv``, file present): the two must be equal (issue 19), every building on one side
only is listed with the report's reason.

Without TILE: every real CityJSON / CityJSONSeq file under ../shared/data and the real
CityGML tiles of ``citygml-real`` (not the val3dity / QIE conformance files, but the
Delfshaven tile kept among them). ``--jsonl`` appends one row per tile (with every IDF's
figures) so that tiles checked by separate runs make one table with ``--table``. Prints a
markdown table; exit code 1 when any file failed its client.
"""
from __future__ import annotations

import argparse
import csv
import json
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
SKIP_DIRS = {"val3dity-tests", "citygml-qie-3dvalidation", "typology-teaser", "weather"}
WEATHER = DATA / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"
VOL_TOL = 0.005


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


# --------------------------------------------------------------------------- reading back

def idf_objects(text: str) -> list[list[str]]:
    """The objects of an IDF text as lists of fields (class name first; comments dropped)."""
    body = "\n".join(line.split("!", 1)[0] for line in text.splitlines())
    return [[f.strip() for f in obj.split(",")] for obj in body.split(";") if obj.strip()]


def polygons_volume(polys) -> float:
    """Enclosed volume (m3) of closed outward polygons (divergence theorem)."""
    v = 0.0
    for q in polys:
        for k in range(1, len(q) - 1):
            v += float(np.dot(q[0], np.cross(q[k], q[k + 1]))) / 6.0
    return v


def idf_zones(path: Path) -> dict[str, dict]:
    """``{zone name (upper): {"volume_field": m3 or None, "volume_geometry": m3, "surfaces": n}}``
    from the IDF's ``Zone`` and ``BuildingSurface:Detailed`` objects."""
    zones: dict[str, dict] = {}
    polys: dict[str, list] = {}
    for o in idf_objects(path.read_text(encoding="utf-8", errors="replace")):
        cls = o[0].upper()
        if cls == "ZONE":
            vol = o[9] if len(o) > 9 else ""
            try:
                v = float(vol)
            except ValueError:
                v = None
            zones[o[1].upper()] = {"volume_field": v, "volume_geometry": 0.0, "surfaces": 0}
        elif cls == "BUILDINGSURFACE:DETAILED":
            try:
                n = int(o[11]) if o[11] else (len(o) - 12) // 3
                pts = np.array([float(x) for x in o[12:12 + 3 * n]]).reshape(n, 3)
            except (ValueError, IndexError):
                continue
            polys.setdefault(o[4].upper(), []).append(pts)
    for z, ps in polys.items():
        d = zones.setdefault(z, {"volume_field": None, "volume_geometry": 0.0, "surfaces": 0})
        d["volume_geometry"] = polygons_volume(ps)
        d["surfaces"] = len(ps)
    return zones


def eio_volumes(path: Path) -> dict[str, float]:
    """``{zone name (upper): volume m3}`` from the ``Zone Information`` rows of ``eplusout.eio``."""
    if not path.is_file():
        return {}
    col, out = None, {}
    for line in path.read_text(errors="replace").splitlines():
        f = [x.strip() for x in line.split(",")]
        if f[0] == "! <Zone Information>":
            col = next((i for i, x in enumerate(f) if x.startswith("Volume")), None)
        elif f[0] == "Zone Information" and col is not None and len(f) > col:
            try:
                out[f[1].upper()] = float(f[col])
            except ValueError:
                pass
    return out


def stl_volume(path: Path) -> float | None:
    """Signed volume (m3) of the triangles of an STL (all its solids)."""
    from lod2energy.exporters.stl.writer import read_stl

    if not path.is_file():
        return None
    tris, _, _ = read_stl(path)
    if not len(tris):
        return None
    t = tris - tris.reshape(-1, 3).mean(axis=0)
    return float(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6.0)


def check_idf(f: Path, a, tmp: Path, out: Path, idf_ok: bool | None) -> dict:
    """Run EnergyPlus on one IDF and compare its zones with the exported shell."""
    from lod2energy.exporters import energyplus

    zones = idf_zones(f)
    run_f = shortened(f, a.days, tmp / "short" / out.name) if a.days else f
    res = energyplus.run.run(run_f, weather=str(WEATHER), outdir=tmp / "eplus" / out.name / f.stem)
    eio = eio_volumes(Path(res.outdir) / "eplusout.eio")
    shell = stl_volume(out / (f.stem + ".stl"))
    not_enc = set(z.upper() for z in res.err.not_enclosed)
    n_unknown = sum(1 for z in res.err.not_enclosed if z == "?")
    enclosed = max(0, len(zones) - len(not_enc - {"?"}) - n_unknown) if res.err.completed else 0
    vol_eplus = sum(eio.get(z, 0.0) for z in zones) if eio else None
    vol_geom = sum(d["volume_geometry"] for d in zones.values())
    err_file = Path(res.outdir) / "eplusout.err"
    upside = err_file.read_text(errors="replace").count("upside down") if err_file.is_file() else 0
    rec = {"id": f.stem, "zones": len(zones), "enclosed": enclosed, "upside_down": upside,
           "severe": len(res.err.severe), "fatal": res.err.fatal, "completed": res.err.completed,
           "first_severe": res.err.severe[0][:240] if res.err.severe else "",
           "not_enclosed": sorted(res.err.not_enclosed), "vol_eplus": vol_eplus, "vol_geometry": vol_geom,
           "vol_shell": shell, "idf_ok": idf_ok, "eplus_s": round(res.seconds, 2)}
    ref = shell if shell else None
    rec["vol_err"] = (None if ref is None or vol_eplus is None else abs(vol_eplus - ref) / ref)
    rec["vol_ok"] = rec["vol_err"] is not None and rec["vol_err"] <= a.vol_tol
    rec["clean"] = res.ok
    reasons = []
    if not res.err.completed or res.err.fatal:
        reasons.append(f"EnergyPlus did not complete (rc {res.returncode})")
    if res.err.severe:
        reasons.append(f"{len(res.err.severe)} severe: {res.err.severe[0][:160]}")
        if idf_ok:
            reasons.append("the self-check passed it (issue 19 item 5)")
    if res.err.not_enclosed:
        reasons.append(f"not enclosed: {', '.join(res.err.not_enclosed)[:160]}")
    if upside:
        reasons.append(f"{upside} surface(s) upside down")
    if not rec["vol_ok"]:
        if ref is None:
            reasons.append("no STL volume to compare")
        elif vol_eplus is None:
            reasons.append("no Zone Information volumes in eplusout.eio")
        else:
            reasons.append(f"zone volumes {vol_eplus:.2f} m3 (geometry {vol_geom:.2f}) vs shell "
                           f"{ref:.2f} m3: {100 * rec['vol_err']:.2f}%")
    rec["reasons"] = reasons
    rec["ok"] = not reasons
    if reasons and a.keep_failures:
        dest = Path(a.keep_failures) / out.name
        dest.mkdir(parents=True, exist_ok=True)
        shutil.copy2(f, dest / f.name)
        stl = out / (f.stem + ".stl")
        if stl.is_file():
            shutil.copy2(stl, dest / stl.name)
        err = Path(res.outdir) / "eplusout.err"
        if err.is_file():
            shutil.copy2(err, dest / (f.stem + ".err"))
    return rec


def compliance(rows: list[dict], out: Path, a) -> dict:
    """Issue 19's count: buildings called compliant against what each writer accepted.

    From the export's ``report.csv``: the buildings with ``compliant`` True, and per writer
    asked for (STL always, IDF with ``--idf``, CityJSON with ``--cityjson``) the buildings
    whose ``<writer>_ok`` is True (and as many files as those). ``mismatch`` lists every building
    on one side only (compliant but not accepted by a writer, or accepted but not compliant),
    with the report's message (why it was not written).
    """
    compliant = {r["id"] for r in rows if r.get("compliant") == "True"}
    writers = ["stl"] + (["idf"] if a.idf else []) + (["cityjson"] if a.cityjson else [])
    files = {"stl": len(list(out.glob("*.stl"))), "idf": len(list(out.glob("*.idf")))}
    res = {"compliant": len(compliant), "mismatch": []}
    for w in writers:
        ok = {r["id"] for r in rows if r.get(f"{w}_ok") == "True"}
        res[w] = len(ok)
        for i in sorted(compliant ^ ok):
            r = next(x for x in rows if x["id"] == i)
            res["mismatch"].append(f"{i}: compliant {r.get('compliant')}, {w}_ok {r.get(f'{w}_ok')}, "
                                   f"{r.get('outcome', '')}: {r.get('message', '')[:200]}")
        # every accepted per-building file is there (file names are the ids made safe, so count them)
        if w in files and files[w] < len(ok):
            res["mismatch"].append(f"{len(ok)} buildings with {w}_ok True but {files[w]} {w} files")
    return res


def check_tile(tile: Path, a, tmp: Path) -> dict:
    from lod2energy.exporters.cfd import openfoam

    out = tmp / tile.name.replace(".", "_")
    cmd = [sys.executable, "-m", "lod2energy", "export", str(tile), "-o", str(out), "--stl", "-q"]
    if a.idf:
        cmd.append("--idf")
    if a.cityjson:
        cmd.append("--cityjson")
    if a.export_jobs is not None:
        cmd += ["-j", str(a.export_jobs)]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    dt = time.perf_counter() - t0
    row = {"tile": f"{tile.parent.name}/{tile.name}", "rc": proc.returncode, "seconds": round(dt, 1),
           "stl": 0, "stl_pass": 0, "stl_fail": [], "idf": 0, "idf_ok": 0, "idfs": []}
    report = out / "report.csv"
    rows = list(csv.DictReader(report.open())) if report.exists() else []
    row["buildings"] = len(rows)
    row["compliance"] = compliance(rows, out, a)
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
        ok_ids = {r["id"] for r in rows if r.get("idf_ok") == "True"}
        row["idf_ok"] = len(ok_ids)
        if a.run is not None:
            sel = idfs if a.run == 0 else idfs[: a.run]
            for f in sel:
                row["idfs"].append(check_idf(f, a, tmp, out, f.stem in ok_ids))
    if a.keep:
        shutil.copytree(out, Path(a.keep) / out.name, dirs_exist_ok=True)
    shutil.rmtree(out, ignore_errors=True)
    shutil.rmtree(tmp / "eplus" / out.name, ignore_errors=True)
    return row


def table(rows: list[dict], run: bool) -> tuple[str, bool]:
    """The markdown table of the tile rows and whether any tile failed."""
    lines = ["| tile | buildings | export rc | s | STL surfaceCheck | IDF self-check | IDFs run | "
             "E+ clean (0 severe) | zones | zones enclosed | volume within 0.5% |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    bad = False
    tot = dict.fromkeys(("b", "stl", "stlp", "idf", "idfok", "run", "clean", "z", "ze", "v"), 0)
    for r in rows:
        ii = r.get("idfs", [])
        n, clean = len(ii), sum(1 for x in ii if x["severe"] == 0 and x["completed"] and not x["fatal"])
        z, ze, v = sum(x["zones"] for x in ii), sum(x["enclosed"] for x in ii), sum(x["vol_ok"] for x in ii)
        lines.append(f"| {r['tile']} | {r['buildings']} | {r['rc']} | {r['seconds']} | {r['stl_pass']}/{r['stl']} | "
                     f"{r['idf_ok']}/{r['idf']} | {n} | {clean}/{n} | {z} | {ze}/{z} | {v}/{n} |")
        bad |= "error" in r or r["stl_pass"] != r["stl"] or any(not x["ok"] for x in ii) or (run and n != r["idf"])
        for k, val in zip(tot, (r["buildings"], r["stl"], r["stl_pass"], r["idf"], r["idf_ok"], n, clean, z, ze, v)):
            tot[k] += val
    lines.append(f"| **all** | {tot['b']} | | | {tot['stlp']}/{tot['stl']} | {tot['idfok']}/{tot['idf']} | "
                 f"{tot['run']} | {tot['clean']}/{tot['run']} | {tot['z']} | {tot['ze']}/{tot['z']} | "
                 f"{tot['v']}/{tot['run']} |")
    up = [x.get("upside_down", 0) for r in rows for x in r.get("idfs", [])]
    if up:
        lines += ["", f"EnergyPlus 'upside down' warnings: {sum(up)} in {sum(1 for u in up if u)} of {len(up)} IDFs."]
    fails = [f"- {r['tile']}: the check itself failed: {r['error']}" for r in rows if "error" in r]
    fails += [f"- {r['tile']}: STL {x}" for r in rows for x in r["stl_fail"]]
    fails += [f"- {r['tile']}: `{x['id']}` ({x['zones']} zones): {'; '.join(x['reasons'])}"
              for r in rows for x in r.get("idfs", []) if not x["ok"]]
    comp = [r for r in rows if r.get("compliance")]
    if comp:
        ws = [w for w in ("idf", "stl", "cityjson") if any(w in r["compliance"] for r in comp)]
        lines += ["", "Buildings called compliant against the buildings each writer accepted (issue 19):", "",
                  "| tile | buildings | compliant | " + " | ".join(f"{w} accepted" for w in ws) + " | equal |",
                  "|---|---:|---:|" + "---:|" * len(ws) + "---|"]
        for r in comp:
            c = r["compliance"]
            eq = not c["mismatch"] and all(c.get(w) == c["compliant"] for w in ws)
            bad |= not eq
            lines.append(f"| {r['tile']} | {r['buildings']} | {c['compliant']} | "
                         + " | ".join(str(c.get(w, "")) for w in ws) + f" | {'yes' if eq else '**no**'} |")
            fails += [f"- {r['tile']}: compliant vs accepted: {m}" for m in c["mismatch"]]
        n_eq = sum(1 for r in comp if not r["compliance"]["mismatch"])
        lines.append(f"| **all** | {sum(r['buildings'] for r in comp)} | "
                     f"{sum(r['compliance']['compliant'] for r in comp)} | "
                     + " | ".join(str(sum(r['compliance'].get(w, 0) for r in comp)) for w in ws)
                     + f" | {n_eq}/{len(comp)} tiles |")
    errs = [x["vol_err"] for r in rows for x in r.get("idfs", []) if x["vol_err"] is not None]
    if errs:
        lines += ["", f"Zone volumes (EnergyPlus eio) against the STL shell: max deviation "
                      f"{100 * max(errs):.3f}%, mean {100 * float(np.mean(errs)):.4f}% over {len(errs)} IDFs."]
    return "\n".join(lines + ([""] + ["Failures:", ""] + fails if fails else [])) + "\n", bad


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*")
    ap.add_argument("--idf", action="store_true", help="also write IDFs")
    ap.add_argument("--cityjson", action="store_true",
                    help="also write the energy CityJSON (for the compliant-vs-accepted count)")
    ap.add_argument("--run", type=int, default=None, help="simulate the first N IDFs per tile (0: all)")
    ap.add_argument("--days", type=int, default=None,
                    help="simulate only the first D days of the year (input checks are the same)")
    ap.add_argument("--jobs", type=int, default=2, help="tiles checked at once")
    ap.add_argument("--export-jobs", type=int, default=None, help="the export's own -j (default: its default)")
    ap.add_argument("--vol-tol", type=float, default=VOL_TOL, help="relative volume tolerance (0.005)")
    ap.add_argument("--keep", default=None, help="copy each tile's export folder here")
    ap.add_argument("--keep-failures", default=None, help="copy each failing IDF, its STL and .err here")
    ap.add_argument("--jsonl", default=None, help="append one JSON row per tile here")
    ap.add_argument("--table", nargs="*", default=None, help="only build the table from these --jsonl files")
    ap.add_argument("--out", default=None, help="write the markdown table here too")
    a = ap.parse_args(argv)
    if a.table is not None:
        rows = [json.loads(line) for f in a.table for line in Path(f).read_text().splitlines() if line.strip()]
        wall = cpu = None
    else:
        tiles = [Path(t) for t in a.tiles] or default_tiles()
        t0 = time.perf_counter()
        with tempfile.TemporaryDirectory(prefix="client_check_") as tmp:
            lock = threading.Lock()

            def one(t):
                try:
                    r = check_tile(t, a, Path(tmp))
                except Exception as e:  # noqa: BLE001 - one tile's crash is its row, the others go on
                    r = {"tile": f"{t.parent.name}/{t.name}", "rc": -1, "seconds": 0, "buildings": 0,
                         "error": f"{type(e).__name__}: {e}",
                         "stl": 0, "stl_pass": 0, "stl_fail": [], "idf": 0, "idf_ok": 0, "idfs": []}
                if a.jsonl:  # as each tile finishes, one whole line at a time (tiles run in threads)
                    with lock, open(a.jsonl, "a", encoding="utf-8") as fh:
                        fh.write(json.dumps(r) + "\n")
                        fh.flush()
                return r
            with ThreadPoolExecutor(a.jobs) as ex:
                rows = list(ex.map(one, tiles))
        wall = time.perf_counter() - t0
        ru = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = ru.ru_utime + ru.ru_stime
    text, bad = table(rows, a.run is not None or a.table is not None)
    if wall is not None:
        text += f"\nWall {wall:.0f} s, CPU {cpu:.0f} s (children: export + surfaceCheck + EnergyPlus).\n"
    print(text)
    if a.out:
        Path(a.out).write_text(text, encoding="utf-8")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
