"""Export cost per stage (s per building): validate/repair/label against each writer and its self-check.

Usage (from the repository root)::

    python benchmarks/bench_export.py [TILE] [--limit N] [--out results.json] [--stages]
    python benchmarks/bench_export.py [TILE] --eplus N      # also EnergyPlus time per building

TILE defaults to ../shared/data/3dbag/tile901_trimmed.city.jsonl; ``--limit N`` keeps the first
N buildings (with their parts) of a CityJSON file, written to a temporary file first.

``--stages`` runs ``lod2energy export --idf --stl --cityjson`` in-process and times, with both
CPU (process) and wall seconds, each stage the pipeline calls: ``pipeline.prepare``
(validate, repair, label, U-values), each writer's ``write`` and, inside it, its
``self_check``; for the IDF self-check also its IDD pass (``read_checked_idf``) and the
enclosure emulation (``enclosure_defects``, counted wherever the writer calls it); for the
CityJSON self-check the interpreted schema validation (``_schema_errors``). CPU seconds are the
figure to compare on a shared machine. The timers wrap module attributes only where the code
under test has them, so the script also measures older trees (``PYTHONPATH=OLD_TREE``).

Without ``--stages`` it measures the IDF and STL writers directly (buildings/s, self-check
included) and, with ``--eplus N``, EnergyPlus on the first N buildings (annual run, Heino NL).
"""
from __future__ import annotations

import argparse
import functools
import json
import statistics
import sys
import tempfile
import time
from collections import defaultdict
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


def sample_tile(path: str, n: int, out_dir: str) -> str:
    """The first ``n`` Buildings of a CityJSON file (with their children), vertices re-indexed."""
    if path.endswith(".jsonl"):
        lines = Path(path).read_text(encoding="utf-8").splitlines()
        out = Path(out_dir) / f"sample{n}.city.jsonl"
        out.write_text("\n".join(lines[: n + 1]) + "\n", encoding="utf-8")
        return str(out)
    doc = json.loads(Path(path).read_text(encoding="utf-8"))
    cos = doc["CityObjects"]
    keep: dict = {}
    for k in [k for k, o in cos.items() if o.get("type") == "Building"][:n]:
        keep[k] = cos[k]
        for c in cos[k].get("children", []):
            keep[c] = cos[c]
    used: dict[int, int] = {}

    def remap(x):
        if isinstance(x, list):
            return [remap(y) for y in x]
        return used.setdefault(x, len(used))

    for o in keep.values():
        for g in o.get("geometry", []):
            g["boundaries"] = remap(g["boundaries"])
            g.pop("texture", None)
            g.pop("material", None)
    verts = [None] * len(used)
    for old, new in used.items():
        verts[new] = doc["vertices"][old]
    doc.update(CityObjects=keep, vertices=verts)
    doc.pop("appearance", None)
    out = Path(out_dir) / f"sample{n}.city.json"
    out.write_text(json.dumps(doc), encoding="utf-8")
    return str(out)


class Timers:
    """CPU and wall seconds and call counts per wrapped function."""

    def __init__(self):
        self.cpu = defaultdict(float)
        self.wall = defaultdict(float)
        self.calls = defaultdict(int)
        self._depth = defaultdict(int)

    def wrap(self, module, attr: str, label: str) -> None:
        f = getattr(module, attr, None)
        if f is None:
            return

        @functools.wraps(f)
        def timed(*a, **k):
            self._depth[label] += 1
            c0, w0 = time.process_time(), time.perf_counter()
            try:
                return f(*a, **k)
            finally:
                self._depth[label] -= 1
                if self._depth[label] == 0:  # recursion counted once
                    self.cpu[label] += time.process_time() - c0
                    self.wall[label] += time.perf_counter() - w0
                    self.calls[label] += 1

        setattr(module, attr, timed)


def _jobs1() -> list[str]:
    """``["-j", "1"]`` where the CLI has ``--jobs`` (in-process, so the timers see the work)."""
    import inspect

    from lod2energy import cli
    try:
        return ["-j", "1"] if '"--jobs"' in inspect.getsource(cli) else []
    except (OSError, TypeError):
        return []


def stage_table(tile: str) -> dict:
    """Run the export on ``tile`` with every stage timed."""
    from lod2energy import cli, pipeline
    from lod2energy.exporters import energyplus
    from lod2energy.energy import conform
    from lod2energy.energy.zones import storeys
    from lod2energy.exporters.cityjson import check as cityjson_check, writer as cityjson
    from lod2energy.exporters.stl import writer as stl

    from lod2energy.validate import checks

    t = Timers()
    t.wrap(pipeline, "prepare", "validate+repair+label")
    t.wrap(pipeline, "prepare_building", "validate+repair+label")
    # each name where its callers look it up: the IDF writer calls its self-check from writer.py
    for mod, name in ((energyplus.writer, "idf"), (stl, "stl"), (cityjson, "cityjson")):
        t.wrap(mod, "self_check", f"{name} self-check")
        t.wrap(mod, "write", f"{name} writer (with self-check)")
    t.wrap(energyplus.check, "read_checked_idf", "idf self-check: IDD parse+check")
    for mod in (conform, storeys, energyplus.check):
        t.wrap(mod, "enclosure_defects", "idf enclosure emulation (writer + self-check)")
    t.wrap(cityjson_check, "_schema_errors", "cityjson self-check: jsonschema")
    t.wrap(cityjson_check, "_schema_valid_fast", "cityjson self-check: schema (jsonschema-rs)")
    # later trees (the spine split): the IDF writer's parts and the other costs of a run
    t.wrap(energyplus.check, "check_closed_outward", "idf self-check: closed and outward shells")
    t.wrap(energyplus.writer, "render_idf", "idf writer: render_idf")
    t.wrap(energyplus.writer, "zone_pieces", "idf writer: zone_pieces")
    t.wrap(energyplus.writer, "_written_zones", "idf writer: _written_zones")
    t.wrap(checks, "validate_building", "validate_building (every caller)")
    t.wrap(pipeline, "write_html_report", "HTML report")
    with tempfile.TemporaryDirectory() as tmp:
        c0, w0 = time.process_time(), time.perf_counter()
        rc = cli.main(["export", tile, "-o", tmp, "--idf", "--stl", "--cityjson", "-q"] + _jobs1())
        cpu, wall = time.process_time() - c0, time.perf_counter() - w0
        report = json.loads((Path(tmp) / "report.json").read_text())
    rows = report.get("buildings") or report.get("features") or []
    n = max(t.calls["validate+repair+label"], 1)
    out = {"tile": Path(tile).name, "buildings": n, "exit_code": rc, "cpu_seconds": round(cpu, 2),
           "wall_seconds": round(wall, 2), "report_rows": len(rows), "stages": {}}
    for label in t.calls:
        out["stages"][label] = {"cpu_s": round(t.cpu[label], 3), "wall_s": round(t.wall[label], 3),
                                "calls": t.calls[label], "cpu_ms_per_building": round(1000 * t.cpu[label] / n, 1),
                                "share_of_cpu": round(t.cpu[label] / cpu, 3) if cpu else None}
    return out


def markdown(res: dict) -> str:
    lines = [f"**{res['tile']}**: {res['buildings']} buildings, {res['cpu_seconds']} s CPU "
             f"({res['wall_seconds']} s wall), {1000 * res['cpu_seconds'] / res['buildings']:.0f} ms CPU per building", "",
             "| stage | CPU ms / building | share of CPU | calls |", "|---|---:|---:|---:|"]
    for label, s in res["stages"].items():
        lines.append(f"| {label} | {s['cpu_ms_per_building']} | {100 * (s['share_of_cpu'] or 0):.1f}% | {s['calls']} |")
    return "\n".join(lines)


def writer_throughput(a) -> dict:
    from lod2energy.exporters.cfd import openfoam
    from lod2energy.exporters import energyplus
    from lod2energy.exporters.stl import writer as stl
    from lod2energy.io import read
    from lod2energy.model import Building

    _, it = read(a.tile)
    raw = [b for b in it if isinstance(b, Building) and b.type == "Building" and b.envelope()]
    t0 = time.perf_counter()
    bs = [energy_ready(b) for b in raw]
    t_label = time.perf_counter() - t0
    out: dict = {"tile": Path(a.tile).name, "buildings": len(bs), "label_seconds": round(t_label, 2)}
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        res = energyplus.writer.write(bs, Path(tmp) / "idf", energyplus.options.IdfOptions())
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
        if a.eplus and energyplus.run.binary() and Path(a.weather).is_file():
            sample = bs[: a.eplus]
            t0 = time.perf_counter()
            rr = energyplus.writer.write(sample, Path(tmp) / "run", energyplus.options.IdfOptions(run=True, timesteps_per_hour=a.timesteps),
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
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tile", nargs="?", default=str(DATA / "3dbag" / "tile901_trimmed.city.jsonl"))
    ap.add_argument("--limit", type=int, default=None, help="first N buildings only")
    ap.add_argument("--stages", action="store_true", help="per-stage CPU seconds of a full export")
    ap.add_argument("--eplus", type=int, default=0, help="buildings to simulate (0: none)")
    ap.add_argument("--timesteps", type=int, default=4)
    ap.add_argument("--weather", default=str(DATA / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"))
    ap.add_argument("--out", default=None)
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        if a.limit:
            a.tile = sample_tile(a.tile, a.limit, tmp)
        if a.stages:
            res = stage_table(a.tile)
            text = json.dumps(res, indent=1)
            print(markdown(res))
        else:
            res = writer_throughput(a)
            text = json.dumps(res, indent=1)
            print(text)
    if a.out:
        Path(a.out).write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
