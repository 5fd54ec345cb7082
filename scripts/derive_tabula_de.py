"""Derive the German TABULA U-value table (lod2energy/thermal/data/tabula_de.csv) from TEASER.

Source: RWTH-EBC/TEASER ``teaser/data/input/inputdata/TypeElements_TABULA_DE.json`` and
``MaterialTemplates.json`` (MIT; copy in ``../shared/data/typology-teaser``, see its
MANIFEST.md), which carry the TABULA DE (IWU) constructions as layers.

For each TABULA type (SFH, TH, MFH, AB), construction period and element (OuterWall,
Rooftop, GroundFloor, Window) of the *standard* (unrefurbished) state, variant 1:

    U = 1 / (R_si + sum(d_i / lambda_i) + R_se),
    R_si = 1 / (inner_convection + inner_radiation),
    R_se = 1 / (outer_convection + outer_radiation)  (0 for ground floors: no outer film)

If variant 1 lacks an element, variant 2 of the same period is used; if neither has it,
the nearest period of the same type (noted in the ``note`` column).

Usage: python scripts/derive_tabula_de.py [TEASER_DIR] [-o OUT.csv]
"""
from __future__ import annotations

import argparse
import csv
import json
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DEFAULT_DIR = REPO.parent / "shared" / "data" / "typology-teaser"
OUT = REPO / "lod2energy" / "thermal" / "data" / "tabula_de.csv"
ELEMENTS = {"roof": "Rooftop", "wall": "OuterWall", "ground": "GroundFloor", "window": "Window"}
TYPES = {"SFH": "single-family", "TH": "terraced", "MFH": "multi-family", "AB": "apartment-block"}


def u_value(elem: dict, materials: dict) -> float:
    def film(conv, rad):
        c = (conv or 0.0) + (rad or 0.0)
        return 1.0 / c if c > 0 else 0.0

    r = film(elem.get("inner_convection"), elem.get("inner_radiation"))
    r += film(elem.get("outer_convection"), elem.get("outer_radiation"))
    for k in sorted(elem["layer"], key=int):
        lay = elem["layer"][k]
        lam = materials[lay["material"]["material_id"]]["thermal_conduc"]
        r += lay["thickness"] / lam
    return 1.0 / r


def derive(src: Path) -> list[dict]:
    te = json.loads((src / "TypeElements_TABULA_DE.json").read_text())
    mats = json.loads((src / "MaterialTemplates.json").read_text())
    table: dict = {}
    for key, e in te.items():
        elem = key.split("_")[0]
        cd = e.get("construction_data", "")
        parts = cd.split("_")
        if not cd.startswith("tabula_de_standard_") or len(parts) != 5:
            continue
        variant, typ = parts[3], parts[4]
        period = tuple(e["building_age_group"])
        table[(typ, period, elem, variant)] = u_value(e, mats)
    rows = []
    for typ, tname in TYPES.items():
        periods = sorted({k[1] for k in table if k[0] == typ})
        for p in periods:
            row = {"country": "DE", "building_type": tname, "period_start": p[0], "period_end": p[1]}
            notes = []
            for col, elem in ELEMENTS.items():
                u = table.get((typ, p, elem, "1"))
                if u is None:
                    u = table.get((typ, p, elem, "2"))
                    if u is not None:
                        notes.append(f"{col}: variant 2")
                if u is None:
                    cands = [q for q in periods if (typ, q, elem, "1") in table]
                    q = min(cands, key=lambda q: abs(q[0] - p[0]))
                    u = table[(typ, q, elem, "1")]
                    notes.append(f"{col}: period {q[0]}-{q[1]}")
                row[f"u_{col}"] = round(u, 3)
            row["source"] = "TEASER-TABULA-DE"
            row["note"] = "; ".join(notes)
            rows.append(row)
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("src", nargs="?", default=str(DEFAULT_DIR))
    ap.add_argument("-o", "--out", default=str(OUT))
    a = ap.parse_args(argv)
    rows = derive(Path(a.src))
    with open(a.out, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    print(f"{len(rows)} rows -> {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
