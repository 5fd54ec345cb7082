"""Export throughput (buildings/s) of the IDF and STL exporters and EnergyPlus time per building.

Usage (from the repository root)::

    python benchmarks/bench_export.py [TILE] [--eplus N] [--timesteps 4] [--out results.json]

TILE defaults to ../shared/data/3dbag/tile901_trimmed.city.jsonl. Buildings are labelled and
given U-values first (lod2energy.semantics / lod2energy.thermal); that time is not counted.
IDF throughput includes the self-check (eppy re-read + closure check); STL throughput
includes the union of parts and the self-check. EnergyPlus is run on the first N buildings
(annual run, Heino NL weather) one at a time and surfaceCheck on every STL when installed.
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"


def energy_ready(b):
    try:
        from lod2energy.semantics import label_building
        from lod2energy.thermal import assign_u_values
        return assign_u_values(label_building(b))
    except Exception:
        return b


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tile", nargs="?", default=str(DATA / "3dbag" / "tile901_trimmed.city.jsonl"))
    ap.add_argument("--eplus", type=int, default=5, help="buildings to simulate (0: none)")
    ap.add_argument("--timesteps", type=int, default=4)
    ap.add_argument("--weather", default=str(DATA / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"))
    ap.add_argument("--out", default=None)
    a = ap.parse_args(argv)

    from lod2energy import energyplus, openfoam
    from lod2energy.exporters import idf, stl
    from lod2energy.io import read
    from lod2energy.model import Building

    _, it = read(a.tile)
    raw = [b for b in it if isinstance(b, Building) and b.type == "Building" and b.energy_objects()]
    t0 = time.perf_counter()
    bs = [energy_ready(b) for b in raw]
    t_label = time.perf_counter() - t0
    out: dict = {"tile": Path(a.tile).name, "buildings": len(bs), "label_seconds": round(t_label, 2)}
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        res = idf.write(bs, Path(tmp) / "idf", idf.IdfOptions())
        dt = time.perf_counter() - t0
        out["idf"] = {"seconds": round(dt, 2), "buildings_per_s": round(len(bs) / dt, 2),
                      "files": len(res), "self_check_ok": sum(r.ok for r in res),
                      "surfaces": sum(r.stats["surfaces"] for r in res)}
        t0 = time.perf_counter()
        res_s = stl.write(bs, Path(tmp) / "stl", stl.StlOptions())
        dt = time.perf_counter() - t0
        out["stl"] = {"seconds": round(dt, 2), "buildings_per_s": round(len(bs) / dt, 2),
                      "files": len(res_s), "self_check_ok": sum(r.ok for r in res_s)}
        if openfoam.surface_check_binary():
            t0 = time.perf_counter()
            ok = sum(openfoam.surface_check(r.path).ok for r in res_s)
            out["stl"]["surfaceCheck_ok"] = ok
            out["stl"]["surfaceCheck_seconds_per_file"] = round((time.perf_counter() - t0) / max(len(res_s), 1), 3)
        if a.eplus and energyplus.binary() and Path(a.weather).is_file():
            sample = bs[: a.eplus]
            t0 = time.perf_counter()
            rr = idf.write(sample, Path(tmp) / "run", idf.IdfOptions(run=True, timesteps_per_hour=a.timesteps),
                           weather=a.weather)
            secs = [r.stats.get("energyplus_seconds", 0.0) for r in rr]
            out["energyplus"] = {
                "buildings": len(rr), "timesteps_per_hour": a.timesteps,
                "seconds_per_building_median": round(statistics.median(secs), 2),
                "seconds_per_building_max": round(max(secs), 2),
                "ok": sum(r.ok for r in rr), "severe_errors": sum(r.severe_errors or 0 for r in rr),
                "not_enclosed": sum(len(r.not_enclosed or ()) for r in rr),
                "heating_kwh": [round(r.heating_kwh or 0) for r in rr],
                "wall_seconds": round(time.perf_counter() - t0, 1)}
    text = json.dumps(out, indent=1)
    print(text)
    if a.out:
        Path(a.out).write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
