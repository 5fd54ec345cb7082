"""Plausibility of the annual heating need: kWh per m2 of conditioned floor area by typology row.

Each building of the given tiles (the first ``--n`` per tile) goes through the main job's
stages (labels, U-values), is written with storey zones and its use's loads and simulated for a
year by EnergyPlus with the Heino (NL) weather file; the heating need per m2 of conditioned floor
area is grouped by the typology row its U-values came from (country, building type, period).
Unconditioned buildings (:func:`lod2energy.thermal.facts.conditioned_fact`: an unheated use, or
an annex under 20 m2 of floor area) are written without ideal loads and left out of the table.

Next to each row stands the value the typology source publishes for it: TABULA's calculated
energy need for heating ``q_h_nd`` of the national generic type in its existing state
(``lod2energy/thermal/data/tabula_heat_need.csv``, derived by
``scripts/derive_tabula_heat_need.py``; sources in ``data/SOURCES.md``), looked up per building
by country, building type and year of construction (or the assumed year). A row is split by
TABULA type when its buildings fall into several TABULA periods (the Dutch U-value rows after
1991 are Bouwbesluit periods, not TABULA's). Rows outside ``--band`` (default +-30%; TABULA
gives no band) of the reference are flagged; rows without a published value say so.
``--reference FILE`` replaces the shipped table (same columns).

``--rows FILE`` saves the per-building figures as JSON lines; ``--from-rows FILE`` builds the
table from them without simulating again.

Usage (from the repository root)::

    python benchmarks/bench_energy.py [TILE ...] [--n 4] [--reference REF.csv] [--band 0.3]
                                      [--rows ROWS.jsonl] [--out FILE.md]
    python benchmarks/bench_energy.py --from-rows ROWS.jsonl [--out FILE.md]
"""
from __future__ import annotations

import argparse
import csv
import json
import statistics
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
EPW = DATA / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"
REFERENCE = REPO / "lod2energy" / "thermal" / "data" / "tabula_heat_need.csv"


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
        if not isinstance(b, Building) or b.type != "Building" or not b.envelope():
            continue
        try:
            out.append(assign_u_values(label_building(b), ThermalOptions(crs=model.crs if model else None)))
        except Exception as e:  # noqa: BLE001 - a building the stages reject is reported and skipped
            print(f"{tile.name}: {b.id}: skipped ({type(e).__name__}: {e})", file=sys.stderr)
        if len(out) >= n:
            break
    return model, out


def _row(b) -> tuple:
    """(country, building type, period) of the U-value row; a non-residential building's use
    stands for the building type (no residential reference applies to it)."""
    t = b.provenance.get("thermal", {})
    btype = str(t.get("typology", "?")) if not t.get("use") else f"{t['use']} (non-residential)"
    return (str(t.get("country", "?")), btype, str(t.get("construction_period", "?")))


def _year(b) -> int:
    """The year the typology lookup used (the attribute's, else the assumed one)."""
    from lod2energy.thermal.typology import DEFAULT_YEAR

    y = b.provenance.get("thermal", {}).get("year_of_construction")
    return int(y) if y is not None else DEFAULT_YEAR


def measure(tiles, n: int, tmp: Path) -> list[dict]:
    from lod2energy.exporters import energyplus
    from lod2energy.thermal.facts import is_conditioned

    rows = []
    for t in tiles:
        model, bs = _prepared(Path(t), n)
        for b in bs:
            res = energyplus.writer.write([b], tmp / b.id.replace("/", "_"), energyplus.options.IdfOptions(run=True, weather=str(EPW),
                                                                               timesteps_per_hour=2),
                            crs=model.crs, frame=getattr(model, "frame", None))
            for r in res:
                rows.append({"tile": Path(t).name, "id": b.id, "row": _row(b), "year": _year(b), "ok": r.ok,
                             "conditioned": is_conditioned(b),
                             "use": r.stats.get("use"), "zones": r.stats.get("zones"),
                             "heating_kwh_m2": r.stats.get("heating_kwh_m2"),
                             "area": r.stats.get("conditioned_floor_area_m2")})
    return rows


def load_reference(path: str | Path | None = None) -> list[dict]:
    """Rows of a reference CSV (``country, building_type, period_start, period_end,
    heating_kwh_m2`` and optional ``tabula_code``, ``source``); default: the shipped TABULA table."""
    with open(path or REFERENCE, newline="", encoding="utf-8") as f:
        return [{**r, "period_start": int(r["period_start"]), "period_end": int(r["period_end"]),
                 "heating_kwh_m2": float(r["heating_kwh_m2"])} for r in csv.DictReader(f)]


def reference_for(ref: list[dict], country: str, building_type: str, year: int) -> dict | None:
    """The reference row of ``country`` and ``building_type`` whose period holds ``year``."""
    return next((r for r in ref if r["country"] == country and r["building_type"] == building_type
                 and r["period_start"] <= year <= r["period_end"]), None)


def table(rows: list[dict], ref: list[dict], band: float, min_area: float = 0.0) -> str:
    """Markdown table: per typology row (and TABULA type) the median heating need and the reference
    (buildings under ``min_area`` m2 of conditioned floor area left out and counted)."""
    by: dict = defaultdict(list)
    refs: dict = {}
    small = unheated = 0
    for r in rows:
        if r.get("conditioned") is False:  # unheated (its use, or an annex under the threshold): no need
            unheated += 1
        elif r["ok"] and r["heating_kwh_m2"] is not None and (r.get("area") or 0.0) < min_area:
            small += 1
        elif r["ok"] and r["heating_kwh_m2"] is not None:
            key = tuple(r["row"])
            rv = reference_for(ref, key[0], key[1], int(r.get("year") or 0))
            code = (rv.get("tabula_code") or "reference") if rv else ""
            by[key + (code,)].append(r["heating_kwh_m2"])
            refs[key + (code,)] = rv
    lines = ["| country | building type | period (U-values) | TABULA type | buildings | heating need median "
             "(kWh/m2a) | min - max | TABULA q_h_nd (kWh/m2a) | median / reference | within +-"
             f"{100 * band:.0f}% |", "|---|---|---|---|---:|---:|---|---:|---:|---|"]
    for key in sorted(by):
        v = by[key]
        med = statistics.median(v)
        rv = refs[key]
        if rv is None:
            refcol, ratio, inside = "no published value", "", ""
        else:
            refcol, ratio = f"{rv['heating_kwh_m2']:.1f}", f"{med / rv['heating_kwh_m2']:.2f}"
            inside = "yes" if abs(med - rv["heating_kwh_m2"]) <= band * rv["heating_kwh_m2"] else "**no**"
        lines.append(f"| {key[0]} | {key[1]} | {key[2]} | {key[3] or '-'} | {len(v)} | {med:.0f} | "
                     f"{min(v):.0f} - {max(v):.0f} | {refcol} | {ratio} | {inside} |")
    failed = sum(1 for r in rows if not r["ok"])
    lines.append(f"\n{len(rows)} buildings, {failed} not simulated cleanly, {unheated} unconditioned left out"
                 + (f", {small} under {min_area:g} m2 of floor area left out." if min_area else "."))
    return "\n".join(lines)


def building_table(rows: list[dict], ref: list[dict]) -> str:
    """Markdown table of every building: its year, use, zones, floor area, heating need and reference."""
    lines = ["| tile | building | year | use | zones | floor area (m2) | heating need (kWh/m2a) | TABULA type "
             "| q_h_nd (kWh/m2a) | ratio |", "|---|---|---:|---|---:|---:|---:|---|---:|---:|"]
    for r in sorted(rows, key=lambda r: (tuple(r["row"]), r.get("year") or 0, r["id"])):
        key = tuple(r["row"])
        rv = reference_for(ref, key[0], key[1], int(r.get("year") or 0))
        h, area = r.get("heating_kwh_m2"), r.get("area")
        hs = "" if h is None else f"{h:.0f}"
        code, q = (rv.get("tabula_code") or "reference", f"{rv['heating_kwh_m2']:.1f}") if rv else ("-", "")
        ratio = f"{h / rv['heating_kwh_m2']:.2f}" if rv and h is not None else ""
        area_s = "" if area is None else f"{area:.0f}"
        lines.append(f"| {r['tile']} | `{r['id']}` | {r.get('year', '')} | {r.get('use') or ''} | "
                     f"{r.get('zones') or ''} | {area_s} | {hs} | {code} | {q} | {ratio} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tiles", nargs="*")
    ap.add_argument("--n", type=int, default=4, help="buildings per tile")
    ap.add_argument("--reference", default=None, help="reference CSV (default: the shipped TABULA table)")
    ap.add_argument("--band", type=float, default=0.3, help="relative band around the reference (0.3)")
    ap.add_argument("--min-area", type=float, default=0.0,
                    help="also give the table without buildings under this floor area (m2)")
    ap.add_argument("--rows", default=None, help="write the per-building figures here (JSON lines)")
    ap.add_argument("--from-rows", default=None, help="build the table from these figures only")
    ap.add_argument("--out", default=None)
    a = ap.parse_args(argv)
    if a.from_rows:
        rows = [json.loads(x) for x in Path(a.from_rows).read_text().splitlines() if x.strip()]
    else:
        with tempfile.TemporaryDirectory(prefix="bench_energy_") as tmp:
            rows = measure([Path(t) for t in a.tiles] or default_tiles(), a.n, Path(tmp))
        if a.rows:
            Path(a.rows).write_text("".join(json.dumps(r) + "\n" for r in rows))
    ref = load_reference(a.reference)
    text = table(rows, ref, a.band)
    if a.min_area:
        text += f"\n\nWithout buildings under {a.min_area:g} m2 of conditioned floor area:\n\n" + table(
            rows, ref, a.band, a.min_area)
    text += "\n\nPer building:\n\n" + building_table(rows, ref)
    print(text)
    if a.out:
        from lod2energy.safe_write import write_text
        write_text(a.out, text + "\n", root=Path(a.out).resolve().parent)
    return 0


if __name__ == "__main__":
    sys.exit(main())
