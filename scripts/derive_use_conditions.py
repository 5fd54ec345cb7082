"""Derive the use-condition tables (lod2energy/thermal/data/use_conditions.csv, use_schedules.csv) from TEASER.

Source: RWTH-EBC/TEASER ``teaser/data/input/inputdata/UseConditions.json`` (PyPI wheel
``teaser`` 1.3.1, MIT; copy in ``../shared/data/typology-teaser``, see its MANIFEST.md), which
carries the DIN V 18599-10:2018 Table 4 / SIA 2024:2015 use profiles.

For each use type of :data:`lod2energy.thermal.use.USE_TYPES` one TEASER entry
(:data:`ENTRY`) gives:

- ``people_per_m2`` = ``persons`` (TEASER writes it as a fraction ``{"/": [1, m2 per person]}``);
  ``activity_w_per_person`` = ``activity_degree_persons`` (met) x 58.2 W/m2 x 1.8 m2 (body
  surface); ``sensible_fraction`` = ``fixed_heat_flow_rate_persons`` / that activity;
- ``lighting_w_per_m2`` = ``fixed_lighting_power``, ``equipment_w_per_m2`` = ``machines``;
- ``heating_setpoint`` = max of ``heating_profile`` (K -> C); ``heating_setback`` = the
  setpoint minus 4 K (DIN V 18599-10 reduced operation, Delta theta_i,NA = 4 K) in the hours the
  occupancy profile is 0; residential entries have no unoccupied hour and so no setback;
- ``cooling_setpoint`` 26 C and ``cooling_setback`` 30 C in unoccupied hours (TEASER's entries
  have ``with_cooling`` false and no cooling setpoint of their own: 26 C is the upper
  operative-temperature limit of EN 16798-1:2019 category II, stated as such in SOURCES.md);
- ``infiltration_ach`` = ``base_infiltration`` (1/h, always);
- ``ventilation_m3h_per_m2`` = ``max_ahu`` (m3/(h m2)) when above 0, else the occupancy x
  25.2 m3/(h person) (EN 16798-1 category II, 7 l/(s person)), run while occupied;
- schedules ``occupancy`` / ``lighting`` / ``equipment`` = the entry's 24 hourly profiles
  (``persons_profile``, ``lighting_profile``, ``machines_profile``), ``heating`` / ``cooling``
  the hourly setpoints (C). TEASER profiles are daily: the same every day of the year.

Usage: python scripts/derive_use_conditions.py [TEASER_DIR] [-o OUTDIR]
"""
from __future__ import annotations

import argparse
import csv
import json
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DEFAULT_DIR = REPO.parent / "shared" / "data" / "typology-teaser"
OUTDIR = REPO / "lod2energy" / "thermal" / "data"
#: TEASER entry used for each use type.
ENTRY = {
    "residential": "Living",
    "office": "Group Office (between 2 and 6 employees)",
    "retail": "Retail, department store",
    "education": "Class room (school), group room (kindergarden)",
    "health": "Bed room",
    "hospitality": "Hotel room",
    "industry": "Commercial and industrial Halls - medium work, standing activity",
    "other": "Further common rooms",
}
MET_W_PER_M2 = 58.2
BODY_M2 = 1.8
SETBACK_K = 4.0
COOLING_SETPOINT, COOLING_SETBACK = 26.0, 30.0
VENT_M3H_PER_PERSON = 25.2


def _persons(v) -> float:
    if isinstance(v, dict) and "/" in v:
        a, b = v["/"]
        return float(a) / float(b)
    return float(v)


def derive(src: Path) -> tuple[list[dict], list[dict]]:
    uc = json.loads((src / "UseConditions.json").read_text())
    rows, sched = [], []
    for use, name in ENTRY.items():
        e = uc[name]
        occ = [float(x) for x in e["persons_profile"][:24]]
        heat = max(float(x) for x in e["heating_profile"]) - 273.15
        unocc = [o <= 0.0 for o in occ]
        heat_h = [heat - SETBACK_K if u else heat for u in unocc]
        cool_h = [COOLING_SETBACK if u else COOLING_SETPOINT for u in unocc]
        ppl = _persons(e["persons"])
        activity = float(e["activity_degree_persons"]) * MET_W_PER_M2 * BODY_M2
        vent = float(e["max_ahu"]) if float(e["max_ahu"]) > 0 else ppl * VENT_M3H_PER_PERSON
        rows.append({
            "use": use, "teaser_entry": name, "people_per_m2": round(ppl, 5),
            "activity_w_per_person": round(activity, 2),
            "sensible_fraction": round(min(float(e["fixed_heat_flow_rate_persons"]) / activity, 1.0), 4),
            "lighting_w_per_m2": float(e["fixed_lighting_power"]), "equipment_w_per_m2": float(e["machines"]),
            "heating_setpoint": round(heat, 2), "heating_setback": round(min(heat_h), 2),
            "cooling_setpoint": COOLING_SETPOINT, "cooling_setback": max(cool_h),
            "infiltration_ach": float(e["base_infiltration"]), "ventilation_m3h_per_m2": round(vent, 4),
            "source": "TEASER-UC-DIN18599",
        })
        for sname, vals in (("occupancy", occ), ("lighting", e["lighting_profile"][:24]),
                            ("equipment", e["machines_profile"][:24]), ("heating", heat_h), ("cooling", cool_h)):
            sched.append({"use": use, "schedule": sname,
                          **{f"h{h:02d}": round(float(v), 3) for h, v in enumerate(vals)}})
    return rows, sched


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("src", nargs="?", default=str(DEFAULT_DIR))
    ap.add_argument("-o", "--outdir", default=str(OUTDIR))
    a = ap.parse_args(argv)
    rows, sched = derive(Path(a.src))
    out = Path(a.outdir)
    for name, table in (("use_conditions.csv", rows), ("use_schedules.csv", sched)):
        with open(out / name, "w", newline="", encoding="utf-8") as f:
            w = csv.DictWriter(f, fieldnames=list(table[0]), lineterminator="\n")
            w.writeheader()
            w.writerows(table)
        print(f"{out / name}: {len(table)} rows")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
