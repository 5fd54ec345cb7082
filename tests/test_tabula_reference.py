"""The TABULA reference heating need (data/tabula_heat_need.csv), its derivation script and its
use in the plausibility benchmark's table."""
from __future__ import annotations

import csv
import io
import subprocess
import sys
from importlib import resources, util

import pytest

from conftest import REPO

DATA = resources.files("lod2energy.thermal") / "data"
HEAD = ("Code_BuildingVariant", "Year1_Building", "Year2_Building", "A_C_Ref", "Name_ClimateRegion",
        "HeatingDays", "q_h_nd")


def _module(path, name):
    spec = util.spec_from_file_location(name, path)
    mod = util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def shipped() -> list[dict]:
    return list(csv.DictReader(io.StringIO((DATA / "tabula_heat_need.csv").read_text(encoding="utf-8"))))


def test_derivation_keeps_only_generic_existing_state_rows(tmp_path):
    rows = [("DE.N.SFH.05.Gen.ReEx.001.001", "1958", "1968", "121,2", "Potsdam", "216", "265,3"),
            ("DE.N.SFH.05.Gen.ReEx.001.002", "1958", "1968", "121,2", "Potsdam", "216", "90,0"),  # refurbished
            ("DE.N.AB.05.HR.ReEx.001.001", "1958", "1968", "11448,8", "Potsdam", "216", "115,6"),  # high-rise
            ("DE.N.MFH.12.Gen.ReEx.001.001", "2016", "9999", "1305", "Potsdam", "216", "71,4"),
            ("AT.N.SFH.01.Gen.ReEx.001.001", "0", "1918", "100", "AT", "212", "250")]
    src = tmp_path / "tabula.csv"
    src.write_text(";".join(HEAD) + ";;\n" + "".join(";".join(r) + ";;\n" for r in rows), encoding="utf-8")
    out = tmp_path / "out.csv"
    out.write_text("country,building_type,period_start,period_end,tabula_code,heating_kwh_m2,reference_area_m2,"
                   "climate,heating_days,status,source\n"
                   "NL,terraced,1992,2005,NL.N.TH.04.Gen.ReEx.001.001,74.6,125.4,NL,212,transcribed,x\n")
    subprocess.run([sys.executable, str(REPO / "scripts" / "derive_tabula_heat_need.py"), str(src), "-o", str(out)],
                   check=True, capture_output=True)
    got = {r["tabula_code"]: r for r in csv.DictReader(out.open())}
    assert set(got) == {"DE.N.SFH.05.Gen.ReEx.001.001", "DE.N.MFH.12.Gen.ReEx.001.001", "NL.N.TH.04.Gen.ReEx.001.001"}
    sfh = got["DE.N.SFH.05.Gen.ReEx.001.001"]
    assert (sfh["building_type"], sfh["period_start"], sfh["heating_kwh_m2"], sfh["status"]) == (
        "single-family", "1958", "265.3", "derived")
    assert got["DE.N.MFH.12.Gen.ReEx.001.001"]["period_end"] == "2100"
    assert got["NL.N.TH.04.Gen.ReEx.001.001"]["status"] == "transcribed"


def test_german_reference_rows_have_the_periods_of_the_u_value_rows():
    """The TABULA DE heat need and the TABULA DE constructions describe the same type rows."""
    u_rows = {(r["building_type"], r["period_start"], r["period_end"])
              for r in csv.DictReader(io.StringIO((DATA / "tabula_de.csv").read_text(encoding="utf-8")))}
    de = [r for r in shipped() if r["country"] == "DE"]
    assert de
    missing = [r["tabula_code"] for r in de if (r["building_type"], r["period_start"], r["period_end"]) not in u_rows]
    assert not missing, missing
    assert all(0 < float(r["heating_kwh_m2"]) < 1000 and r["tabula_code"].endswith(".001.001") for r in shipped())


def test_benchmark_table_puts_the_reference_next_to_the_median_and_flags_the_band():
    bench = _module(REPO / "benchmarks" / "bench_energy.py", "bench_energy")
    ref = bench.load_reference()
    r = next(x for x in ref if x["country"] == "DE" and x["building_type"] == "single-family")
    year = r["period_start"] + 1
    q = r["heating_kwh_m2"]
    row = ("DE", "single-family", f"{r['period_start']}-{r['period_end']}")
    rows = [{"row": row, "year": year, "ok": True, "heating_kwh_m2": q * 1.1},
            {"row": row, "year": year, "ok": True, "heating_kwh_m2": q * 1.2},
            {"row": ("DE", "office", "1969-1978"), "year": 1970, "ok": True, "heating_kwh_m2": 50.0}]
    text = bench.table(rows, ref, 0.3)
    line = next(x for x in text.splitlines() if r["tabula_code"] in x)
    assert f"{q:.1f}" in line and "| 1.15 |" in line and line.rstrip().endswith("| yes |")
    assert "no published value" in next(x for x in text.splitlines() if "office" in x)
    far = bench.table([{**rows[0], "heating_kwh_m2": q * 2}], ref, 0.3)
    assert "**no**" in far


TABULA_TYPE = {"SFH": "single-family", "TH": "terraced", "MFH": "multi-family", "AB": "apartment-block"}


def test_dutch_rows_are_generic_existing_state_types_with_the_periods_of_their_code():
    """Every hand-transcribed Dutch row: its code names its building type, TABULA period
    ``NL.nn`` has the same years in every type, periods follow each other without a gap, and
    within a type the need falls from period to period (older stock loses more)."""
    import re

    nl = [r for r in shipped() if r["country"] == "NL"]
    assert {r["building_type"] for r in nl} == set(TABULA_TYPE.values())
    by_period: dict = {}
    for r in nl:
        m = re.fullmatch(r"NL\.N\.(SFH|TH|MFH|AB)\.(\d\d)\.Gen\.ReEx\.001\.001", r["tabula_code"])
        assert m, r["tabula_code"]
        assert TABULA_TYPE[m.group(1)] == r["building_type"]
        assert r["status"] == "transcribed" and r["climate"] == "Netherlands" and r["heating_days"] == "212"
        assert float(r["reference_area_m2"]) > 0
        by_period.setdefault(m.group(2), set()).add((int(r["period_start"]), int(r["period_end"])))
    assert all(len(v) == 1 for v in by_period.values()), by_period
    spans = [next(iter(by_period[k])) for k in sorted(by_period)]
    assert all(b[0] == a[1] + 1 for a, b in zip(spans, spans[1:])), spans
    for t in TABULA_TYPE.values():
        q = [float(r["heating_kwh_m2"]) for r in sorted(nl, key=lambda r: int(r["period_start"]))
             if r["building_type"] == t]
        assert q == sorted(q, reverse=True), (t, q)


@pytest.mark.parametrize("building_type", sorted(TABULA_TYPE.values()))
def test_every_dutch_building_type_has_a_reference_up_to_2014(building_type):
    """The benchmark finds a TABULA row for every Dutch residential building of the typology
    built before 2015 (the multi-family and apartment rows also after)."""
    bench = _module(REPO / "benchmarks" / "bench_energy.py", "bench_energy")
    ref = bench.load_reference()
    last = 2100 if building_type in ("multi-family", "apartment-block") else 2014
    if building_type == "single-family":
        last = 2005  # NL.N.SFH.05 / .06 not transcribed
    missing = [y for y in range(1850, last + 1) if bench.reference_for(ref, "NL", building_type, y) is None]
    assert not missing, (missing[:3], missing[-3:])
    mfh = bench.reference_for(ref, "NL", "multi-family", 2011)
    assert mfh["tabula_code"] == "NL.N.MFH.05.Gen.ReEx.001.001" and mfh["heating_kwh_m2"] == 59.0
