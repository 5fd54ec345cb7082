"""Building use from attributes and the shipped use conditions (lod2energy.thermal.use)."""
import csv
from dataclasses import replace

import pytest

from factories import box
from lod2energy.errors import ParameterError
from lod2energy.thermal.use import DATA, USE_TYPES, building_use, use_conditions


def _with(**attrs):
    b = box()
    return replace(b, objects=(replace(b.root, attributes=attrs),))


@pytest.mark.parametrize("attrs,use", [
    ({"function": "31001_1010"}, "residential"), ({"function": "31001_2020"}, "office"),
    ({"function": "31001_2071"}, "hospitality"), ({"function": "31001_3021"}, "education"),
    ({"function": "31001_3051"}, "health"), ({"function": "31001_2111"}, "industry"),
    ({"function": "1120"}, "office"), ({"function": "1000"}, "residential"),
    ({"usage": "401"}, "office"), ({"usage": "412"}, "residential"), ({"usage": "402"}, "retail"),
    ({"gebruiksdoel": ["winkelfunctie", "woonfunctie"]}, "retail"),
    ({"gebruiksdoel": "kantoorfunctie,woonfunctie"}, "office"),
    ({"gebruiksdoel": "sportfunctie"}, "other"),
    ({"building": "apartments"}, "residential"), ({"building": "school"}, "education"),
    ({"building": "warehouse"}, "industry"), ({"building": "hotel"}, "hospitality"),
    ({}, "residential"), ({"function": ""}, "residential"), ({"function": None}, "residential"),
])
def test_use_from_attributes(attrs, use):
    u = building_use(_with(**attrs))
    assert u.type == use
    assert u.source == ("default" if not any(attrs.values()) else u.source)


def test_override_wins_and_is_checked():
    assert building_use(_with(function="31001_1010"), "Office").type == "office"
    with pytest.raises(ParameterError):
        building_use(box(), "spaceport")


@pytest.mark.parametrize("use", USE_TYPES)
def test_every_use_has_loads_schedules_and_setpoints(use):
    c = use_conditions(use)
    assert c.people_per_m2 > 0 and c.lighting_w_per_m2 > 0 and c.equipment_w_per_m2 > 0
    assert 0 < c.sensible_fraction <= 1 and c.activity_w_per_person > 50
    assert 15 <= c.heating_setback <= c.heating_setpoint <= 24 < c.cooling_setpoint <= c.cooling_setback
    assert c.infiltration_ach > 0 and c.ventilation_m3h_per_m2 > 0
    assert set(c.schedules) == {"occupancy", "lighting", "equipment", "heating", "cooling"}
    assert all(len(v) == 24 for v in c.schedules.values())
    assert all(0 <= x <= 1 for k in ("occupancy", "lighting", "equipment") for x in c.schedules[k])
    assert max(c.schedules["heating"]) == pytest.approx(c.heating_setpoint)


def test_tables_match_their_derivation():
    import importlib.util
    from pathlib import Path
    src = Path(__file__).resolve().parents[1] / "scripts" / "derive_use_conditions.py"
    spec = importlib.util.spec_from_file_location("derive_uc", src)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    if not (mod.DEFAULT_DIR / "UseConditions.json").is_file():
        pytest.skip("TEASER use conditions not available")
    rows, _ = mod.derive(mod.DEFAULT_DIR)
    shipped = list(csv.DictReader(open(DATA / "use_conditions.csv", encoding="utf-8")))
    assert [r["use"] for r in shipped] == [r["use"] for r in rows]
    for a, b in zip(shipped, rows):
        assert float(a["people_per_m2"]) == pytest.approx(b["people_per_m2"])
        assert float(a["lighting_w_per_m2"]) == pytest.approx(b["lighting_w_per_m2"])
    sources = (DATA / "SOURCES.md").read_text(encoding="utf-8")
    for r in rows:
        assert r["teaser_entry"] in sources
