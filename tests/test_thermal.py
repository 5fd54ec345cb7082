"""Typology choice and fallbacks, U-value tables and their sources, per-surface Energy ADE
quantities and the UA arithmetic on a box with known U-values."""
from __future__ import annotations

import math
import re
from dataclasses import replace
from importlib import resources

import pytest

from factories import box, gabled_house
from lod2energy import semantics as S
from lod2energy import thermal as T
from lod2energy.errors import ParameterError
from lod2energy.model import Building, frozen_mapping
from lod2energy.thermal import typology as TY
from lod2energy.thermal import uvalues as UV
from conftest import REPO, shared_path

KNOWN = dict(u_roof=0.2, u_wall=0.3, u_ground=0.4, u_window=1.5)


def with_attrs(b: Building, **attrs) -> Building:
    root = replace(b.root, attributes=frozen_mapping({**b.root.attributes, **attrs}))
    return replace(b, objects=(root,) + b.objects[1:])


def labelled_box(dx=10.0, dy=8.0, dz=6.0, **attrs) -> Building:
    return S.label_building(with_attrs(box(dx, dy, dz), **attrs))


# ----------------------------------------------------------------------------- UA arithmetic

@pytest.mark.parametrize("dx, dy, dz, wwr", [(10, 8, 6, 0.25), (4, 4, 3, 0.0), (20, 5, 12, 0.4)])
def test_ua_of_a_box_with_known_u_values(dx, dy, dz, wwr):
    b = T.assign_u_values(labelled_box(dx, dy, dz), T.ThermalOptions(wwr=wwr, **KNOWN))
    th = b.provenance["thermal"]
    a_roof = a_ground = dx * dy
    a_wall = 2 * (dx + dy) * dz
    expected = (0.2 * a_roof + a_wall * ((1 - wwr) * 0.3 + wwr * 1.5) + 0.4 * a_ground)
    assert th["areas"] == pytest.approx({"roof": a_roof, "wall": a_wall, "ground": a_ground})
    assert th["A_env"] == pytest.approx(a_roof + a_wall + a_ground)
    assert th["volume"] == pytest.approx(dx * dy * dz)
    assert th["UA"] == pytest.approx(expected, rel=1e-4)
    assert th["u_values"] == KNOWN_AS_DICT
    assert th["wwr"] == wwr


KNOWN_AS_DICT = {"roof": 0.2, "wall": 0.3, "ground": 0.4, "window": 1.5}


def test_per_surface_energy_ade_quantities():
    b = T.assign_u_values(labelled_box(10, 8, 6), T.ThermalOptions(**KNOWN))
    o, gi, g = S.envelope_objects(b)[0]
    got = {}
    for *_, s in g.iter_surfaces():
        e = g.semantic_surfaces[s.semantic]
        got.setdefault(e["type"], []).append(e)
    ground, roof = got["GroundSurface"][0], got["RoofSurface"][0]
    assert (ground["uValue"], ground["thermalBoundaryType"], ground["inclination"]) == (0.4, "ground", 180.0)
    assert (roof["uValue"], roof["thermalBoundaryType"], roof["inclination"]) == (0.2, "exterior", 0.0)
    walls = got["WallSurface"]
    assert all(w["uValue"] == 0.3 and w["inclination"] == 90.0 for w in walls)
    # box faces S, E, N, W: outward normals -y, +x, +y, -x
    assert [w["azimuth"] for w in walls] == [180.0, 90.0, 0.0, 270.0]
    assert [w["area"] for w in walls] == pytest.approx([60, 48, 60, 48])


def test_inclined_roof_azimuth_and_inclination():
    h = T.assign_u_values(S.label_building(gabled_house(10, 8, 6, 9)), T.ThermalOptions(**KNOWN))
    o, gi, g = S.envelope_objects(h)[0]
    roofs = [g.semantic_surfaces[s.semantic] for *_, s in g.iter_surfaces()
             if g.semantic_type(s) == "RoofSurface"]
    assert sorted(r["azimuth"] for r in roofs) == [0.0, 180.0]
    slope = math.degrees(math.atan2(3, 4))
    assert [r["inclination"] for r in roofs] == pytest.approx([slope, slope], abs=0.01)
    assert h.provenance["thermal"]["volume"] == pytest.approx(10 * 8 * 6 + 0.5 * 8 * 3 * 10)


def test_closure_surfaces_are_left_out_of_ua():
    from test_semantics import two_part_building

    b = T.assign_u_values(S.label_building(two_part_building()), T.ThermalOptions(wwr=0.0, **KNOWN))
    th = b.provenance["thermal"]
    assert th["areas"]["wall"] == pytest.approx(2 * (2 * 60 + 48))     # the two 48 m2 closures excluded
    assert th["volume"] == pytest.approx(2 * 480)
    closure = [g.semantic_surfaces[s.semantic] for _, _, g in S.envelope_objects(b)
               for *_, s in g.iter_surfaces() if g.semantic_type(s) == "ClosureSurface"]
    assert len(closure) == 2 and all(c["thermalBoundaryType"] == "interior" and c["uValue"] > 0 for c in closure)


def test_assign_u_values_does_not_mutate_input():
    b = labelled_box()
    entries = [dict(e) for e in b.objects[0].geometries[0].semantic_surfaces]
    T.assign_u_values(b, T.ThermalOptions(**KNOWN))
    assert [dict(e) for e in b.objects[0].geometries[0].semantic_surfaces] == entries


# ----------------------------------------------------------------------------- typology

@pytest.mark.parametrize("key, value, year", [
    ("yearOfConstruction", 1963, 1963), ("oorspronkelijkbouwjaar", 1994, 1994), ("b3_bouwjaar", 1931, 1931),
    ("bouwjaar", "1972", 1972), ("constructionYear", 2016.0, 2016), ("yearOfConstruction", "1965-03-01", 1965),
])
def test_year_of_construction_under_its_common_names(key, value, year):
    b = T.assign_u_values(labelled_box(**{key: value}), T.ThermalOptions(country="NL"))
    th = b.provenance["thermal"]
    assert th["year_of_construction"] == year
    assert th["sources"]["year"] == key
    start, end = (int(x) if x else None for x in th["construction_period"].split("-"))
    assert (start or 0) <= year <= (end or 9999)


@pytest.mark.parametrize("value", [None, "unknown", 0, 3000, True, float("nan")])
def test_missing_or_implausible_year_falls_back_to_default(value):
    b = T.assign_u_values(labelled_box(yearOfConstruction=value), T.ThermalOptions(country="NL"))
    th = b.provenance["thermal"]
    assert th["year_of_construction"] is None and th["sources"]["year"] == "default"
    assert th["construction_period"].endswith("(assumed)")
    start, end = th["construction_period"].split(" ")[0].split("-")
    assert int(start or 0) <= TY.DEFAULT_YEAR <= int(end or 9999)


@pytest.mark.parametrize("attrs, footprint, expected", [
    ({"storeysAboveGround": 2}, 80.0, "single-family"),
    ({"b3_bouwlagen": 2, "b3_opp_scheidingsmuur": 40.0}, 60.0, "terraced"),
    ({"storeysAboveGround": 4}, 80.0, "multi-family"),
    ({"storeysAboveGround": 2}, 900.0, "multi-family"),
    ({"storeysAboveGround": 9}, 400.0, "apartment-block"),
    ({"measuredHeight": 30.0}, 100.0, "apartment-block"),        # storeys from height / 3 m
    ({}, 50.0, "single-family"),                                   # storeys from the geometry height
])
def test_building_type_choice(attrs, footprint, expected):
    b = with_attrs(box(), **attrs)
    assert TY.classify(b, "NL", ground_area=footprint, z_extent=6.0).building_type == expected


def test_height_fallbacks():
    t = TY.classify(with_attrs(box(), b3_h_dak_70p=12.5, b3_h_maaiveld=0.5), "NL", 50.0, 3.0)
    assert t.height == pytest.approx(12.0) and t.storeys == 4
    t = TY.classify(box(), "NL", 50.0, 7.0)
    assert (t.height, t.sources["height"], t.storeys) == (7.0, "geometry", 2)


def test_attributes_of_building_parts_are_used():
    from test_semantics import two_part_building

    b = two_part_building()
    p1 = replace(b.objects[1], attributes=frozen_mapping({"oorspronkelijkbouwjaar": 1925}))
    b = replace(b, objects=(b.objects[0], p1, b.objects[2]))
    assert TY.classify(b, "NL").year == 1925


@pytest.mark.parametrize("crs, country", [
    ("urn:ogc:def:crs:EPSG::7415", "NL"), ("https://www.opengis.net/def/crs/EPSG/0/28992", "NL"),
    ("EPSG:25832", "DE"), ("urn:ogc:def:crs:EPSG::2056", "CH"), ("EPSG:31287", "AT"), ("EPSG:3067", "FI"),
    ("EPSG:4326", None), (None, None),
])
def test_country_from_crs(crs, country):
    assert TY.country_from_crs(crs) == country


def test_country_choice_order():
    b = labelled_box(yearOfConstruction=1970)
    by_crs = T.assign_u_values(b, T.ThermalOptions(crs="EPSG:3067")).provenance["thermal"]
    explicit = T.assign_u_values(b, T.ThermalOptions(country="de", crs="EPSG:3067")).provenance["thermal"]
    generic = T.assign_u_values(b, T.ThermalOptions()).provenance["thermal"]
    assert (by_crs["country"], explicit["country"], generic["country"]) == ("FI", "DE", "*")
    assert "GENERIC" in generic["table_sources"]


# ----------------------------------------------------------------------------- tables

COUNTRIES = ("NL", "DE", "AT", "CH", "FI", "*")


@pytest.mark.parametrize("country", COUNTRIES)
@pytest.mark.parametrize("btype", TY.BUILDING_TYPES)
@pytest.mark.parametrize("year", [1900, 1955, 1975, 1995, 2012, 2023])
def test_every_country_type_and_period_has_all_u_values(country, btype, year):
    u, used = UV.lookup(country, btype, year, UV.builtin_rows())
    assert set(u) == set(UV.ELEMENTS)
    assert all(UV.U_RANGE[0] <= v <= UV.U_RANGE[1] for v in u.values())
    assert used and used[0].country == country


def test_newer_periods_are_not_worse_insulated_on_average():
    for c in COUNTRIES:
        old, _ = UV.lookup(c, "single-family", 1930, UV.builtin_rows())
        new, _ = UV.lookup(c, "single-family", 2020, UV.builtin_rows())
        assert sum(new.values()) < sum(old.values()), c


def test_every_table_source_is_cited():
    d = resources.files("lod2energy.thermal") / "data"
    sources = (d / "SOURCES.md").read_text(encoding="utf-8")
    cited = set(re.findall(r"^\| `([^`]+)` \|", sources, flags=re.M))
    used = {r.source for r in UV.builtin_rows()}
    assert used and used <= cited, used - cited


def test_de_table_is_reproduced_by_its_derivation_script(tmp_path):
    teaser = shared_path("typology-teaser")
    import subprocess
    import sys

    out = tmp_path / "de.csv"
    subprocess.run([sys.executable, str(REPO / "scripts" / "derive_tabula_de.py"), str(teaser), "-o", str(out)],
                   check=True, capture_output=True)
    shipped = (resources.files("lod2energy.thermal") / "data" / "tabula_de.csv").read_text(encoding="utf-8")
    assert out.read_text(encoding="utf-8") == shipped


def test_de_u_value_formula_on_one_layer():
    from importlib import util

    spec = util.spec_from_file_location("derive", REPO / "scripts" / "derive_tabula_de.py")
    mod = util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    elem = {"inner_convection": 2.7, "inner_radiation": 5.0, "outer_convection": 20.0, "outer_radiation": 5.0,
            "layer": {"0": {"thickness": 0.24, "material": {"material_id": "m"}}}}
    u = mod.u_value(elem, {"m": {"thermal_conduc": 0.8}})
    assert u == pytest.approx(1 / (1 / 7.7 + 0.24 / 0.8 + 1 / 25))


# ----------------------------------------------------------------------------- user tables and overrides

def test_user_table_takes_precedence_and_fills_gaps(tmp_path):
    p = tmp_path / "u.csv"
    p.write_text("country,building_type,period_start,period_end,u_roof,u_wall,u_ground,u_window,wwr\n"
                 "NL,,1960,1969,0.9,,1.1,,0.33\n")
    b = labelled_box(yearOfConstruction=1965)
    th = T.assign_u_values(b, T.ThermalOptions(country="NL", u_table=p)).provenance["thermal"]
    builtin, _ = UV.lookup("NL", "single-family", 1965, UV.builtin_rows())
    assert th["u_values"]["roof"] == 0.9 and th["u_values"]["ground"] == 1.1
    assert th["u_values"]["wall"] == builtin["wall"] and th["u_values"]["window"] == builtin["window"]
    assert th["wwr"] == 0.33
    other = T.assign_u_values(labelled_box(yearOfConstruction=1990),
                              T.ThermalOptions(country="NL", u_table=p)).provenance["thermal"]
    assert other["u_values"]["roof"] != 0.9


def test_minimal_user_table_applies_everywhere(tmp_path):
    p = tmp_path / "u.csv"
    p.write_text("u_roof,u_wall,u_ground,u_window\n0.11,0.12,0.13,0.9\n")
    th = T.assign_u_values(labelled_box(), T.ThermalOptions(country="FI", u_table=str(p))).provenance["thermal"]
    assert th["u_values"] == {"roof": 0.11, "wall": 0.12, "ground": 0.13, "window": 0.9}


@pytest.mark.parametrize("text, fragment", [
    ("a,b\n1,2\n", "header"),
    ("u_wall\nabc\n", "not a number"),
    ("u_wall\n-0.3\n", "positive"),
    ("country,period_start,u_wall\nNL,nineteen,0.3\n", "not a year"),
])
def test_bad_user_table_is_a_one_line_parameter_error(tmp_path, text, fragment):
    p = tmp_path / "u.csv"
    p.write_text(text)
    with pytest.raises(ParameterError) as e:
        T.assign_u_values(labelled_box(), T.ThermalOptions(u_table=p))
    assert fragment in str(e.value) and "\n" not in str(e.value) and e.value.code == 903


def test_missing_user_table_file(tmp_path):
    with pytest.raises(ParameterError, match="cannot read"):
        T.assign_u_values(labelled_box(), T.ThermalOptions(u_table=tmp_path / "nope.csv"))


def test_per_class_overrides_win():
    b = labelled_box(yearOfConstruction=1930)
    th = T.assign_u_values(b, T.ThermalOptions(country="NL", u_wall=0.35, overrides={"roof": 0.25})
                           ).provenance["thermal"]
    base, _ = UV.lookup("NL", "single-family", 1930, UV.builtin_rows())
    assert th["u_values"]["wall"] == 0.35 and th["u_values"]["roof"] == 0.25
    assert th["u_values"]["ground"] == base["ground"]


@pytest.mark.parametrize("kw", [dict(u_wall=0), dict(u_roof=-1.0), dict(u_window=float("inf")),
                                dict(overrides={"door": 1.0}), dict(wwr=1.5), dict(u_ground=True)])
def test_bad_options_are_parameter_errors(kw):
    with pytest.raises(ParameterError):
        T.ThermalOptions(**kw)


def test_check_u_values():
    b = labelled_box()
    assert [d.code for d in T.check_u_values(b)] == [1201] * 6
    ok = T.assign_u_values(b, T.ThermalOptions(**KNOWN))
    assert T.check_u_values(ok) == []
    silly = T.assign_u_values(b, T.ThermalOptions(u_wall=50.0, u_roof=0.2, u_ground=0.3, u_window=1.0))
    assert [d.code for d in T.check_u_values(silly)] == [1202] * 4


# ----------------------------------------------------------------------------- real tile

def test_real_tile_thermal_summary_is_consistent():
    from lod2energy.io import cityjson

    model, feats = cityjson.read(str(shared_path("3dbag", "small.city.jsonl")))
    for f in feats:
        b = T.assign_u_values(S.label_building(f), T.ThermalOptions(crs=model.crs))
        th = b.provenance["thermal"]
        assert th["country"] == "NL" and th["sources"]["year"] == "oorspronkelijkbouwjaar"
        u, a, w = th["u_values"], th["areas"], th["wwr"]
        ua = u["roof"] * a["roof"] + a["wall"] * ((1 - w) * u["wall"] + w * u["window"]) + u["ground"] * a["ground"]
        assert th["UA"] == pytest.approx(ua, rel=1e-3)
        surf = sum(g.semantic_surfaces[s.semantic]["area"] for _, _, g in S.envelope_objects(b)
                   for *_, s in g.iter_surfaces())
        assert th["A_env"] == pytest.approx(surf, rel=1e-3)
        vol = f.root.attributes.get("b3_volume_lod22")
        if vol:
            assert th["volume"] == pytest.approx(vol, rel=0.01)
        assert T.check_u_values(b) == []
