"""Derive the TABULA reference heating need table (lod2energy/thermal/data/tabula_heat_need.csv).

TABULA / EPISCOPE (IEE projects TABULA and EPISCOPE, IWU Darmstadt, www.episcope.eu; data
CC BY 4.0) publishes for every national example building and state its calculated energy
need for heating ``q_h_nd`` (kWh per m2 of the TABULA reference area ``A_C_Ref`` and year,
TABULA common calculation method, national climate). The values are read from the TABULA
"tabula-calculator.xlsx" data as exported to CSV by FZJ-IEK3-VSA/HiSim
(``hisim/inputs/housing/data_raw/tabula_DE_complete.csv``, comma-separated, decimal point, or
``hisim/inputs/housing/data_processed/episcope-tabula.csv``, semicolon-separated, decimal
comma). One row per generic national type (``<CC>.N.<SFH|TH|MFH|AB>.<nn>.Gen``) in its
existing state (variant ``ReEx.001.001``): country, our building type, period, the TABULA
code, q_h_nd, A_C_Ref, the climate and heating days of the calculation.

Rows already in the output with ``status = transcribed`` (values read by hand from a file not
available as a whole) are kept and not overwritten unless the input has the same code.

Usage: python scripts/derive_tabula_heat_need.py TABULA.csv [...] [--countries DE NL] [-o OUT.csv]
"""
from __future__ import annotations

import argparse
import csv
import io
import re
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "lod2energy" / "thermal" / "data" / "tabula_heat_need.csv"
TYPES = {"SFH": "single-family", "TH": "terraced", "MFH": "multi-family", "AB": "apartment-block"}
FIELDS = ("country", "building_type", "period_start", "period_end", "tabula_code", "heating_kwh_m2",
          "reference_area_m2", "climate", "heating_days", "status", "source")
CODE = re.compile(r"^([A-Z]{2})\.N\.(SFH|TH|MFH|AB)\.(\d\d)\.Gen\.ReEx\.001\.001$")


def _number(s: str, comma: bool) -> float:
    s = (s or "").strip()
    return float(s.replace(",", ".") if comma else s)


def read_rows(path: Path, countries: set[str]) -> list[dict]:
    """The existing-state generic rows of one TABULA CSV export."""
    text = path.read_text(encoding="utf-8", errors="replace")
    head = text.split("\n", 1)[0]
    sep = ";" if head.count(";") > head.count(",") else ","
    comma = sep == ";"
    out = []
    for r in csv.DictReader(io.StringIO(text), delimiter=sep):
        m = CODE.match(r.get("Code_BuildingVariant") or "")
        if not m or m.group(1) not in countries:
            continue
        end = int(_number(r["Year2_Building"], comma))
        out.append({"country": m.group(1), "building_type": TYPES[m.group(2)],
                    "period_start": int(_number(r["Year1_Building"], comma)),
                    "period_end": 2100 if end >= 9999 else end, "tabula_code": m.group(0),
                    "heating_kwh_m2": round(_number(r["q_h_nd"], comma), 1),
                    "reference_area_m2": round(_number(r["A_C_Ref"], comma), 1),
                    "climate": r.get("Name_ClimateRegion", "").strip(),
                    "heating_days": int(_number(r["HeatingDays"], comma)),
                    "status": "derived", "source": f"TABULA q_h_nd via HiSim {path.name}"})
    return out


def merge(derived: list[dict], existing: list[dict]) -> list[dict]:
    """``derived`` plus the transcribed rows of ``existing`` whose code it lacks, sorted."""
    have = {r["tabula_code"] for r in derived}
    keep = [r for r in existing if r.get("status") == "transcribed" and r["tabula_code"] not in have]
    rows = derived + keep
    return sorted(rows, key=lambda r: (r["country"], r["building_type"], int(r["period_start"])))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("src", nargs="+")
    ap.add_argument("--countries", nargs="+", default=["DE", "NL"])
    ap.add_argument("-o", "--out", default=str(OUT))
    a = ap.parse_args(argv)
    derived = [r for p in a.src for r in read_rows(Path(p), set(a.countries))]
    out = Path(a.out)
    existing = list(csv.DictReader(out.open(encoding="utf-8"))) if out.is_file() else []
    rows = merge(derived, existing)
    with out.open("w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    print(f"{len(derived)} derived, {len(rows) - len(derived)} kept -> {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
