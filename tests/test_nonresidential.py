"""Non-residential constructions: IWU office U-values (TEASER) for German offices and, stated as
such, for the other non-residential uses; residential buildings keep TABULA."""
from __future__ import annotations

import csv
import io
import re
import subprocess
import sys
from argparse import Namespace
from dataclasses import replace
from importlib import resources

import pytest

from factories import box
from lod2energy import semantics as S
from lod2energy import thermal as T
from lod2energy.model import Building, frozen_mapping
from lod2energy.options import prepare_options
from lod2energy.thermal import uvalues as UV
from conftest import REPO, shared_path

DATA = resources.files("lod2energy.thermal") / "data"


def labelled(**attrs) -> Building:
    b = box(12.0, 10.0, 9.0)
    root = replace(b.root, attributes=frozen_mapping({**b.root.attributes, **attrs}))
    return S.label_building(replace(b, objects=(root,) + b.objects[1:]))


def csv_row(name: str, year: int, building_type: str | None = None) -> dict:
    """The row of a shipped table whose period holds ``year`` (read from the file itself)."""
    rows = list(csv.DictReader(io.StringIO((DATA / name).read_text(encoding="utf-8"))))
    hit = [r for r in rows if int(r["period_start"]) <= year <= int(r["period_end"])
           and r["country"] == "DE" and (building_type is None or r["building_type"] == building_type)]
    assert len(hit) == 1, hit
    return {e: float(hit[0][f"u_{e}"]) for e in UV.ELEMENTS}


@pytest.mark.parametrize("year", [1900, 1960, 1975, 1990, 2005])
def test_german_office_gets_iwu_u_values(year):
    b = labelled(function="31001_2020", yearOfConstruction=year)  # ALKIS Gebäudefunktion: Bürogebäude
    th = T.assign_u_values(b, T.ThermalOptions(country="DE")).provenance["thermal"]
    assert th["u_values"] == pytest.approx(csv_row("iwu_office_de.csv", year))
    assert th["table_sources"] == ["TEASER-IWU-OFFICE"]
    assert th["use"] == "office"
    assert th["typology"] in T.typology.BUILDING_TYPES  # the Energy extension's enum stays valid
    assert "IWU office" in th["constructions"] and "used for" not in th["constructions"]
    o, gi, g = S.envelope_objects(T.assign_u_values(b, T.ThermalOptions(country="DE")))[0]
    walls = {g.semantic_surfaces[s.semantic]["uValue"] for *_, s in g.iter_surfaces()
             if g.semantic_type(s) == "WallSurface"}
    assert len(walls) == 1 and walls.pop() == pytest.approx(th["u_values"]["wall"])


@pytest.mark.parametrize("year", [1900, 1960, 1990, 2005])
def test_german_residential_keeps_tabula(year):
    b = labelled(function="31001_1000", yearOfConstruction=year, storeysAboveGround=3)  # Wohngebäude
    th = T.assign_u_values(b, T.ThermalOptions(country="DE")).provenance["thermal"]
    assert th["u_values"] == pytest.approx(csv_row("tabula_de.csv", year, th["typology"]))
    assert th["table_sources"] == ["TEASER-TABULA-DE"]
    assert "use" not in th and "constructions" not in th
    office = T.assign_u_values(b, T.ThermalOptions(country="DE", use="office")).provenance["thermal"]
    assert office["u_values"] != th["u_values"]  # the two typologies differ for these periods


def test_other_non_residential_uses_get_the_office_rows_stated_as_such():
    b = labelled(function="31001_2050", yearOfConstruction=1975)  # ALKIS: Geschäftsgebäude (retail)
    th = T.assign_u_values(b, T.ThermalOptions(country="DE")).provenance["thermal"]
    assert th["use"] == "retail"
    assert th["u_values"] == pytest.approx(csv_row("iwu_office_de.csv", 1975))
    assert "used for retail" in th["constructions"]


def test_outside_the_iwu_periods_and_countries_the_residential_tables_stay():
    late = T.assign_u_values(labelled(function="office", yearOfConstruction=2020),
                             T.ThermalOptions(country="DE")).provenance["thermal"]
    assert "TEASER-IWU-OFFICE" not in late["table_sources"]
    assert re.search(r"no period for 2020", late["constructions"])
    nl = T.assign_u_values(labelled(function="office", yearOfConstruction=1975),
                           T.ThermalOptions(country="NL")).provenance["thermal"]
    res = T.assign_u_values(labelled(yearOfConstruction=1975), T.ThermalOptions(country="NL")).provenance["thermal"]
    assert nl["u_values"] == res["u_values"] and "no non-residential table for country NL" in nl["constructions"]


def test_use_option_reaches_the_thermal_stage():
    opts = prepare_options(Namespace(use="office", country="DE"))
    assert opts.thermal.use == "office"
    th = T.assign_u_values(labelled(yearOfConstruction=1975), opts.thermal).provenance["thermal"]
    assert th["table_sources"] == ["TEASER-IWU-OFFICE"]


def test_iwu_table_is_reproduced_by_its_derivation_script(tmp_path):
    teaser = shared_path("typology-teaser")
    out = tmp_path / "iwu.csv"
    subprocess.run([sys.executable, str(REPO / "scripts" / "derive_iwu_office.py"), str(teaser), "-o", str(out)],
                   check=True, capture_output=True)
    assert out.read_text(encoding="utf-8") == (DATA / "iwu_office_de.csv").read_text(encoding="utf-8")


def test_iwu_source_is_cited():
    sources = (DATA / "SOURCES.md").read_text(encoding="utf-8")
    cited = set(re.findall(r"^\| `([^`]+)` \|", sources, flags=re.M))
    assert {r.source for r in UV.builtin_nonres_rows()} <= cited
