"""Plausibility of the annual heating need: kWh per m2 of conditioned floor area by typology row.

Each building of the given tiles (the first ``--n`` per tile) goes through the main job's
stages (labels, U-values), is written with storey zones and its use's loads and simulated for a
year by EnergyPlus with the Heino (NL) weather file; the heating need per m2 of conditioned floor
area is grouped by the typology row its U-values came from (country, building type, period).

A ``--reference FILE`` CSV (``country,building_type,period_start,period_end,heating_kwh_m2,source``)
adds the value the typology source publishes for that row and flags rows outside
``--band`` (default +-50%) of it. No reference values are shipped: the TEASER copy of TABULA
carries the constructions, not TABULA's calculated heating need, so the column stays empty
without a file.

Usage (from the repository root)::

    python benchmarks/bench_energy.py [TILE ...] [--n 4] [--reference REF.csv] [--out FILE.md]
"""
from __future__ import annotations

import argparse
import csv
import statistics
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
EPW = DATA / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"


def default_tiles() -> list[Path]:
    return [DATA / "3dbag" / "delft_subset.city.jsonl", DATA / "citygml-real" / "berlin" / "3920_5820.gml"]


def _prepared(tile: Path, n: int):
    from lod2energy import io
    from lod2energy.model import Building
    from lod2energy.semantics import label_building
    from lod2energy.thermal import ThermalOptions, assign_u_values

    model, feats = io.read(str(tile))
    model, feats = io.to_local_frame(model, feats)
    out = []
    for b in feats:
        if not isinstance(b, Building) or b.type != "Building" or not b.energy_objects():
            continue
        try:
            out.append(assign_u_values(label_building(b), ThermalOptions(crs=model.crs if model else None)))
        except Exception as e:  # noqa: BLE001 - a building the stages reject is reported and skipped
            print(f"{tile.name}: {b.id}: skipped ({type(e).__name__}: {e})", file=sys.stderr)
        if len(out) >= n:
            break
    return model, out


def _row(b) -> tuple:
    t = b.provenance.get("thermal", {})
    return (str(t.get("country", "?")), str(t.get("typology", "?")), str(t.get("construction_period", "?")))


def measure(tiles, n: int, tmp: Path) -> list[dict]:
    from lod2energy.exporters import energyplus

    rows = []
    for t in tiles:
        model, bs = _prepared(Path(t), n)
        for b in bs:
            res = energyplus.writer.write([b], tmp / b.id.replace("/", "_"), energyplus.options.IdfOptions(run=True, weather=str(EPW),
                                                                               timesteps_per_hour=2),
                            crs=model.crs, frame=getattr(model, "frame", None))
            for r in res:
                rows.append({"tile": Path(t).name, "id": b.id, "row": _row(b), "ok": r.ok,
                             "use": r.stats.get("use"), "zones": r.stats.get("zones"),
                             "heating_kwh_m2": r.stats.get("heating_kwh_m2"),
                             "area": r.stats.get("conditioned_floor_area_m2")})
    return rows


def _reference(path: str | None) -> dict:
    if not path:
        return {}
    ref = {}
    with open(path, newline="", encoding="utf-8") as f:
        for r in csv.DictReader(f):
            ref[(r["country"], r["building_type"], f"{r['period_start']}-{r['period_end']}")] = (
                float(r["heating_kwh_m2"]), r.get("source", ""))
    return ref


def table(rows: list[dict], ref: dict, band: float) -> str:
    by: dict = defaultdict(list)
    for r in rows:
        if r["ok"] and r["heating_kwh_m2"] is not None:
            by[r["row"]].append(r["heating_kwh_m2"])
    lines = ["| country | building type | period | buildings | heating need median (kWh/m2a) | min - max "
             "| reference (kWh/m2a) | within band |", "|---|---|---|---:|---:|---|---:|---|"]
    for key in sorted(by):
        v = by[key]
        med = statistics.median(v)
        rv = ref.get(key)
        inside = "" if rv is None else ("yes" if abs(med - rv[0]) <= band * rv[0] else "**no**")
        lines.append(f"| {key[0]} | {key[1]} | {key[2]} | {len(v)} | {med:.0f} | {min(v):.0f} - {max(v):.0f} "
                     f"| {'' if rv is None else f'{rv[0]:.0f} ({rv[1]})'} | {inside} |")
    failed = sum(1 for r in rows if not r["ok"])
    lines.append(f"\n{len(rows)} buildings, {failed} not simulated cleanly.")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*")
    ap.add_argument("--n", type=int, default=4, help="buildings per tile")
    ap.add_argument("--reference", default=None)
    ap.add_argument("--band", type=float, default=0.5)
    ap.add_argument("--out", default=None)
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="bench_energy_") as tmp:
        rows = measure([Path(t) for t in a.tiles] or default_tiles(), a.n, Path(tmp))
    text = table(rows, _reference(a.reference), a.band)
    print(text)
    if a.out:
        from lod2energy.safe_write import write_text
        write_text(a.out, text + "\n", root=Path(a.out).resolve().parent)
    return 0


if __name__ == "__main__":
    sys.exit(main())
