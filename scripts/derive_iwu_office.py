"""Derive the German non-residential (IWU office) U-value table
(lod2energy/thermal/data/iwu_office_de.csv) from TEASER.

Source: RWTH-EBC/TEASER ``teaser/data/input/inputdata/TypeElements_IWU.json`` and
``MaterialTemplates.json`` (MIT; copy in ``../shared/data/typology-teaser``, see its
MANIFEST.md): the layered constructions TEASER's office archetype
(``teaser/logic/archetypebuildings/bmvbs/office.py``, after BMVBS 2010 and IWU) loads by
year of construction. As that archetype does by default, the script takes the *heavy*
construction (``construction_data = iwu_heavy``) of OuterWall, Rooftop and GroundFloor, and
the window ``"Kunststofffenster, Isolierverglasung"``, per construction period:

    U = 1 / (R_si + sum(d_i / lambda_i) + R_se)

with TEASER's film coefficients (the same arithmetic as ``scripts/derive_tabula_de.py``).
One row per period of the opaque elements; the window row is the one whose period holds
that period (its periods are coarser: 0-1978, 1979-1983, 1984-1994, 1995-2015).

Usage: python scripts/derive_iwu_office.py [TEASER_DIR] [--construction heavy|light] [-o OUT.csv]
"""
from __future__ import annotations

import argparse
import csv
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from derive_tabula_de import DEFAULT_DIR, u_value  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "lod2energy" / "thermal" / "data" / "iwu_office_de.csv"
OPAQUE = {"roof": "Rooftop", "wall": "OuterWall", "ground": "GroundFloor"}
WINDOW = "Kunststofffenster, Isolierverglasung"  # TEASER office.py: the window every office gets


def derive(src: Path, construction: str = "heavy") -> list[dict]:
    """Rows ``{country, building_type, period_start, period_end, u_roof, u_wall, u_ground,
    u_window, source, note}`` (U in W/(m2 K)), oldest period first."""
    te = json.loads((src / "TypeElements_IWU.json").read_text())
    mats = json.loads((src / "MaterialTemplates.json").read_text())
    opaque: dict = {}
    windows: dict = {}
    for key, e in te.items():
        elem, cd, period = key.split("_")[0], e.get("construction_data", ""), tuple(e["building_age_group"])
        if elem == "Window" and cd == WINDOW:
            windows[period] = u_value(e, mats)
        elif elem in OPAQUE.values() and cd == f"iwu_{construction}":
            opaque[(elem, period)] = u_value(e, mats)
    rows = []
    for p in sorted({p for _, p in opaque}):
        row = {"country": "DE", "building_type": "office", "period_start": p[0], "period_end": p[1]}
        for col, elem in OPAQUE.items():
            row[f"u_{col}"] = round(opaque[(elem, p)], 3)
        wp = next(q for q in windows if q[0] <= p[0] and p[1] <= q[1])
        row["u_window"] = round(windows[wp], 3)
        row["source"] = "TEASER-IWU-OFFICE"
        row["note"] = f"iwu_{construction}; window {WINDOW} {wp[0]}-{wp[1]}"
        rows.append(row)
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("src", nargs="?", default=str(DEFAULT_DIR))
    ap.add_argument("--construction", choices=("heavy", "light"), default="heavy")
    ap.add_argument("-o", "--out", default=str(OUT))
    a = ap.parse_args(argv)
    rows = derive(Path(a.src), a.construction)
    with open(a.out, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    print(f"{len(rows)} rows -> {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
