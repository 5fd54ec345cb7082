"""Study inputs: attribute maps, the --buildings table, value sources and sentinels, --ids, --run-period."""
from __future__ import annotations

import csv
import json
from dataclasses import replace
from pathlib import Path

import pytest

from conftest import shared_path
from factories import box, gabled_house
from lod2energy.cli import main
from lod2energy.errors import ParameterError
from lod2energy.exporters.energyplus.options import parse_run_period
from lod2energy.semantics import label_building
from lod2energy.thermal import ThermalOptions, assign_u_values
from lod2energy.thermal.attributes import load_attribute_map, parse_map, profile, profiles
from lod2energy.thermal.facts import TABLE_KEY, year_fact, year_of
from lod2energy.thermal.table import parse_buildings
from lod2energy.thermal.use import building_use
from spine_inputs import row_of_boxes_seq

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "delft_subset.city.jsonl"


def _with(b=None, **attrs):
    b = b if b is not None else box()
    return replace(b, objects=(replace(b.root, attributes={**b.root.attributes, **attrs}),) + b.objects[1:])


def _thermal(b, **kw) -> dict:
    return dict(assign_u_values(label_building(b), ThermalOptions(country="NL", **kw)).provenance["thermal"])


# ----------------------------------------------------------------------------- attribute maps

def test_builtin_profiles_load_and_auto_holds_every_one():
    names = profiles()
    assert {"auto", "citygml", "3dbag", "alkis", "plateau", "osm"} <= set(names)
    auto = profile("auto")
    for n in names:
        for field, fm in profile(n).fields.items():
            assert set(fm.keys) <= set(auto.field(field).keys), (n, field)
    assert not auto.user  # built-in keys are "attribute", never "map"


@pytest.mark.parametrize("attrs,field,value", [
    ({"oorspronkelijkbouwjaar": 1931}, "year", 1931), ({"yearOfConstruction": "1975-01-01"}, "year", 1975),
    ({"Baujahr": 1988.0}, "year", 1988), ({"construction_year": "2001"}, "year", 2001),
    ({"function": "31001_2460"}, "use", "other"), ({"gebruiksdoel": "kantoorfunctie"}, "use", "office"),
    ({"usage": "411"}, "use", "residential"), ({"building": "Apartments"}, "use", "residential"),
    ({"function": "31001_2461"}, "conditioned", False), ({"building": "garage"}, "conditioned", False),
    ({"roofType": "1030"}, "roof_type", "gabled"),
])
def test_auto_profile_reads_the_producers_recognised_so_far(attrs, field, value):
    found = profile("auto").read(_with(**attrs), field, year_of if field == "year" else None)
    assert found is not None and found.value == value and found.key == next(iter(attrs))


def test_a_user_map_reads_renamed_attributes_with_source_map(tmp_path):
    p = tmp_path / "fi.toml"
    p.write_text('name = "helsinki"\n[year]\nkeys = ["Valmistunut"]\n[storeys]\nkeys = ["Kerroksia"]\n'
                 '[use]\nkeys = ["C_KAYTTARK"]\n[use.values]\n"011" = "residential"\n"151" = "office"\n',
                 encoding="utf-8")
    amap = load_attribute_map(p)
    assert amap.name == "helsinki"
    b = _with(box(dz=9.0), Valmistunut="1962", Kerroksia=3, C_KAYTTARK="151", yearOfConstruction=1900)
    th = _thermal(b, attribute_map=amap)
    f = th["facts"]
    assert (f["year"]["value"], f["year"]["source"], f["year"]["key"]) == (1962, "map", "Valmistunut")
    assert f["storeys"]["value"] == 3 and f["storeys"]["source"] == "map"
    assert f["use"]["value"] == "office" and f["use"]["source"] == "map" and f["use"]["raw"] == "151"
    assert th["attribute_map"] == "helsinki"
    # the built-in profiles still fill what the map leaves open (include = ["auto"] by default)
    assert _thermal(_with(box(), yearOfConstruction=1900), attribute_map=amap)["facts"]["year"]["source"] == "attribute"
    alone = parse_map('include = []\n[year]\nkeys = ["Valmistunut"]\n', "t", "t")
    assert _thermal(_with(box(), yearOfConstruction=1900), attribute_map=alone)["facts"]["year"]["value"] is None


@pytest.mark.parametrize("text,why", [
    ("[year\nkeys = 1", "not valid TOML"),
    ("[colour]\nkeys = ['x']", "unknown entries colour"),
    ("[use]\nkeys = ['x']\n[use.values]\na = 'palace'", "a use must be one of"),
    ("[conditioned]\nkeys = ['x']\n[conditioned.values]\na = 'maybe'", "true or false"),
    ("[use]\nkeys = ['x']\n[[use.rules]]\npattern = '('\nranges = []", "pattern"),
    ("[use]\nkeys = ['x']\n[[use.rules]]\npattern = '(\\d+)'\nranges = [[1, 'office']]", "[low, high, result]"),
    ("[year]\nkeys = 'a'\nfrom = 'b'", "unknown entries from"),
    ("include = ['nosuch']", "no built-in attribute profile"),
])
def test_a_bad_map_is_one_clear_error(text, why):
    with pytest.raises(ParameterError, match="map.toml") as e:
        parse_map(text, "map.toml", "map")
    assert why in str(e.value)


def test_a_bad_map_or_table_exits_2_and_writes_nothing(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[use]\nkeys = ['x']\n[use.values]\na = 'palace'\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["export", str(EXAMPLE), "-o", str(out), "--geojson", "-q", "--attribute-map", str(bad)]) == 2
    assert "palace" in capsys.readouterr().err and not out.exists()
    table = tmp_path / "b.csv"
    table.write_text("id,year\nx,1950\ny,19x0\n", encoding="utf-8")
    assert main(["export", str(EXAMPLE), "-o", str(out), "--geojson", "-q", "--buildings", str(table)]) == 2
    err = capsys.readouterr().err
    assert "line 3, column year" in err and "Traceback" not in err and not out.exists()


# ----------------------------------------------------------------------------- the table

def test_table_parses_and_names_line_and_column_of_a_bad_value():
    t = parse_buildings("id;year;use;conditioned;u_wall;wwr\na;1950;Office;no;0.4;\nb;;;;;0.3\n", "t.csv")
    assert dict(t["a"]) == {"year": 1950, "use": "office", "conditioned": False, "u_wall": 0.4}
    assert dict(t["b"]) == {"wwr": 0.3}
    for text, where in [("id,storeys\na,0\n", "line 2, column storeys"), ("id,u_roof\na,9\n", "column u_roof"),
                        ("id,use\na,palace\n", "column use"), ("id,year\na,1950\na,1960\n", "line 3, column id"),
                        ("id,colour\na,red\n", "unknown column"), ("year\n1950\n", "needs an 'id' column"),
                        ("id,wwr\na,1.0\n", "column wwr")]:
        with pytest.raises(ParameterError, match="t.csv") as e:
            parse_buildings(text, "t.csv")
        assert where in str(e.value), text


def test_a_table_row_wins_and_says_so():
    row = {"year": 1925, "storeys": 2, "use": "retail", "conditioned": False, "u_wall": 1.1, "wwr": 0.4}
    b = _with(box(dz=6.0), oorspronkelijkbouwjaar=1990, b3_bouwlagen=3).with_provenance(**{TABLE_KEY: row})
    th = _thermal(b, u_wall=0.3)
    f = th["facts"]
    for k, v in row.items():
        assert f[k]["value"] == v and f[k]["source"] == "table", k
    assert th["u_values"]["wall"] == 1.1 and th["wwr"] == 0.4 and th["year_of_construction"] == 1925
    assert f["u_roof"]["source"] == "default" and th["use"] == "retail"
    plain = _thermal(b.with_provenance(**{TABLE_KEY: None}), u_wall=0.3)["facts"]
    assert plain["year"]["value"] == 1990 and plain["u_wall"] == {"value": 0.3, "source": "option", "key": "u_wall"}


# ----------------------------------------------------------------------------- sentinels

@pytest.mark.parametrize("value,ref,known", [
    (2099, "2020-01-01", None), (2019, "2020-01-01", 2019), (9999, None, None), (1000, None, None),
    (1001, None, 1001), ("0", None, None),
])
def test_sentinel_and_late_years_are_unknown_with_a_warning(value, ref, known):
    warnings = []
    f = year_fact(_with(yearOfConstruction=value), reference_date=ref, warnings=warnings)
    assert f.value == known
    assert (f.source == "default") == (known is None)
    assert bool(warnings) == (known is None)


def test_a_sentinel_falls_back_to_the_next_attribute_and_creation_date_bounds_the_year():
    f = year_fact(_with(yearOfConstruction=9999, oorspronkelijkbouwjaar=1968))
    assert f.value == 1968 and f.key == "oorspronkelijkbouwjaar"
    assert year_fact(_with(yearOfConstruction=2023, creationDate="2021-05-01")).value is None
    th = _thermal(_with(box(), yearOfConstruction=2099), reference_date="2020-06-30")
    assert th["year_of_construction"] is None and th["construction_period"].endswith("(assumed)")
    assert any("2099" in w["message"] and "referenceDate" in w["message"] for w in th["warnings"])


def test_plateau_9999_storeys_are_unknown():
    th = _thermal(_with(gabled_house(eaves=5.6, ridge=9.0), storeysAboveGround=9999, usage="411"))
    assert th["facts"]["storeys"]["source"] == "geometry" and th["facts"]["storeys"]["value"] == 3
    assert th["facts"]["use"]["value"] == "residential" and th["facts"]["use"]["scheme"] == "PLATEAU"
    assert [w["field"] for w in th["warnings"]] == ["storeys"]


# ----------------------------------------------------------------------------- a shared tile, renamed

RENAMED = {"oorspronkelijkbouwjaar": "Valmistunut", "b3_bouwlagen": "Kerroksia", "b3_h_dak_70p": "korkeus",
           "b3_h_maaiveld": "maanpinta", "b3_opp_scheidingsmuur": "yhteinen_seina"}
MAP = """name = "renamed"
include = []
[year]
keys = ["Valmistunut"]
[storeys]
keys = ["Kerroksia"]
[height]
keys = ["korkeus"]
ground = {korkeus = "maanpinta"}
[shared_wall]
keys = ["yhteinen_seina"]
[use]
keys = ["kaytto"]
[use.values]
asuinrakennus = "residential"
toimisto = "office"
"""


def test_a_tile_with_renamed_attributes_and_a_map_gives_the_same_study_inputs():
    from lod2energy import io
    from lod2energy.model import Building
    _, feats = io.read(str(shared_path("3dbag", "delft_subset.city.jsonl")))
    amap = parse_map(MAP, "renamed.toml", "renamed")
    uses = ["residential", "office"]
    n = 0
    for i, b in enumerate(f for f in feats if isinstance(f, Building) and f.is_building):
        use = uses[i % 2]
        orig = _with(b, gebruiksdoel="woonfunctie" if use == "residential" else "kantoorfunctie")
        objs = tuple(replace(o, attributes={RENAMED.get(k, k): v for k, v in o.attributes.items()})
                     for o in b.objects)
        ren = _with(replace(b, objects=objs), kaytto="asuinrakennus" if use == "residential" else "toimisto")
        assert "oorspronkelijkbouwjaar" not in ren.root.attributes
        a, r = _thermal(orig), _thermal(ren, attribute_map=amap)
        for k in ("year_of_construction", "storeys", "typology", "construction_period", "u_values", "UA"):
            assert a[k] == r[k], (b.id, k)
        for k in ("year", "storeys", "use"):
            assert a["facts"][k]["value"] == r["facts"][k]["value"], (b.id, k)
            assert r["facts"][k]["source"] == ("map" if a["facts"][k]["source"] == "attribute"
                                               else a["facts"][k]["source"]), (b.id, k)
        n += a["facts"]["year"]["source"] == "attribute" and a["facts"]["storeys"]["source"] == "attribute"
    assert n >= 3


# ----------------------------------------------------------------------------- the CLI

def _csv(path: Path) -> dict[str, dict]:
    with open(path, newline="", encoding="utf-8") as f:
        return {r["id"]: r for r in csv.DictReader(f)}


def test_a_buildings_table_changes_exactly_the_buildings_and_fields_it_names(tmp_path, capsys):
    base = tmp_path / "base"
    assert main(["export", str(EXAMPLE), "-o", str(base), "--geojson", "-q", "-j", "1"]) in (0, 1)
    before = _csv(base / "report.csv")
    ids = sorted(before)
    table = tmp_path / "buildings.csv"
    table.write_text(f"id,year,use,storeys\n{ids[0]},1925,,\n{ids[1]},,office,2\nnot-in-the-file,1960,,\n",
                     encoding="utf-8")
    out = tmp_path / "out"
    assert main(["export", str(EXAMPLE), "-o", str(out), "--geojson", "-q", "-j", "1",
                 "--buildings", str(table)]) in (0, 1)
    assert "--buildings: 1 of 3 ids are not buildings" in capsys.readouterr().err
    study = json.loads((out / "report.json").read_text())["study"]
    assert study == {"attribute_map": "auto", "buildings_table": {"rows": 3},
                     "buildings_table_not_in_input": ["not-in-the-file"]}
    after = _csv(out / "report.csv")
    assert after[ids[0]]["year"] == "1925" and after[ids[0]]["year_source"] == "table"
    assert after[ids[1]]["use"] == "office" and after[ids[1]]["use_source"] == "table"
    assert after[ids[1]]["storeys"] == "2" and after[ids[1]]["storeys_source"] == "table"
    changed = {(i, k) for i in ids for k in before[i] if before[i][k] != after[i][k]}
    fields = {"year", "year_source", "use", "use_source", "storeys", "storeys_source", "typology",
              "construction_period", "UA_W_per_K"}
    assert {i for i, _ in changed} <= {ids[0], ids[1]}
    assert {k for _, k in changed} <= fields
    assert (ids[0], "year") in changed and (ids[1], "use") in changed


def test_ids_write_only_the_selection_and_party_walls_with_others_stay_adiabatic(tmp_path, capsys):
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=5)
    full = tmp_path / "full"
    assert main(["export", src, "-o", str(full), "--idf", "-q", "-j", "1"]) == 0
    out = tmp_path / "sel"
    assert main(["export", src, "-o", str(out), "--idf", "-q", "-j", "1", "--ids", "b2,b9",
                 "--run-period", "01-01:01-31"]) == 0
    assert "--ids: 1 of 2 ids are not buildings" in capsys.readouterr().err
    assert sorted(p.name for p in out.glob("*.idf")) == ["b2.idf"]
    rep = json.loads((out / "report.json").read_text())
    assert [b["id"] for b in rep["buildings"]] == ["b2"]
    assert rep["study"]["ids"] == 2 and rep["study"]["ids_not_in_input"] == ["b9"]
    assert list(_csv(out / "report.csv")) == ["b2"]
    idf = (out / "b2.idf").read_text()
    assert idf.count("Adiabatic") == (full / "b2.idf").read_text().count("Adiabatic") >= 2
    period = idf.split("RunPeriod,")[1].split(";")[0]
    assert "Period, " in period and "Annual" not in period and "  1, 31, ," in period
    assert "12, 31, ," in (full / "b2.idf").read_text()
    # one IDF for the selection: its party walls with the unselected neighbours stay adiabatic too
    one = tmp_path / "dataset"
    assert main(["export", src, "-o", str(one), "--idf", "--idf-mode", "dataset", "--cityjson", "-q", "-j", "1",
                 "--ids", "b2"]) == 0
    written = list(one.glob("*.idf"))
    assert len(written) == 1 and written[0].read_text().count("Adiabatic") == idf.count("Adiabatic")
    city = json.loads(next(one.glob("*.city.json")).read_text())
    assert list(city["CityObjects"]) == ["b2"]


def test_ids_from_a_file(tmp_path):
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=3, touching=False)
    ids = tmp_path / "ids.txt"
    ids.write_text("# the study\nb0\nb2\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["export", src, "-o", str(out), "--idf", "-q", "-j", "1", "--ids", f"@{ids}"]) == 0
    assert sorted(p.name for p in out.glob("*.idf")) == ["b0.idf", "b2.idf"]
    from lod2energy.options import parse_ids
    table = tmp_path / "b.csv"
    table.write_text("year;id\n1950;b1\n;b3\n", encoding="utf-8")
    assert parse_ids(f"@{table}") == ("b1", "b3") and parse_ids(" b4, b5 ,b4") == ("b4", "b5")


@pytest.mark.parametrize("text,ok", [("01-01:01-31", (1, 1, 1, 31)), ("2-29:3-1", (2, 29, 3, 1)),
                                     ("12-31:01-01", None), ("02-30:03-01", None), ("jan:feb", None)])
def test_run_period(text, ok):
    if ok is None:
        with pytest.raises(ParameterError, match="--run-period"):
            parse_run_period(text)
    else:
        assert parse_run_period(text) == ok


def test_use_is_read_once_and_reused_from_the_prepared_building():
    b = _with(box(), function="31001_2020")
    tb = assign_u_values(label_building(b), ThermalOptions(country="DE"))
    assert building_use(tb).type == "office" and building_use(tb).source == "attribute"
    # the prepared building keeps the use it was given even if read with another map
    assert building_use(tb, amap=parse_map("include = []", "t", "t")).type == "office"


def test_every_writer_takes_the_recorded_use_and_a_table_row_beats_the_use_option(tmp_path):
    """The energy model's zones (IDF, HBJSON) take the use the thermal stage recorded (report.json's),
    made with the attribute map; a --buildings row wins over --use, as for its other columns."""
    from lod2energy.thermal.use import recorded_use
    tb = assign_u_values(label_building(_with(box(), C_KAYTTARK="151")),
                         ThermalOptions(country="NL", attribute_map=parse_map(
                             '[use]\nkeys = ["C_KAYTTARK"]\n[use.values]\n"151" = "office"\n', "m", "m")))
    assert recorded_use(tb).type == "office" and recorded_use(tb).source == "map"
    assert recorded_use(tb, "retail").type == "office"  # what the thermal stage recorded wins
    row = _with(box()).with_provenance(**{TABLE_KEY: {"use": "health"}})
    assert building_use(row, "retail").type == "health" and building_use(row, "retail").source == "table"
    table = tmp_path / "b.csv"
    first = json.loads(EXAMPLE.read_text().splitlines()[1])
    bid = next(k for k, v in first["CityObjects"].items() if v["type"] == "Building")
    table.write_text(f"id,use\n{bid},retail\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["export", str(EXAMPLE), "-o", str(out), "--hbjson", "--no-html", "-q", "-j", "1", "--use", "office",
                 "--buildings", str(table)]) in (0, 1)
    report = {r["id"]: r for r in json.loads((out / "report.json").read_text())["buildings"]}
    assert report[bid]["thermal"]["facts"]["use"]["value"] == "retail"
    for path in out.glob("*.hbjson"):
        doc = json.loads(path.read_text())
        b = doc["user_data"]["building"]
        assert {r["user_data"]["use"] for r in doc["rooms"]} == {report[b]["thermal"]["facts"]["use"]["value"]}, b
    assert (out / f"{bid}.hbjson").exists()


def test_region_selects_for_every_output(tmp_path):
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=5)
    out = tmp_path / "out"
    # the row runs along x from 85000 in 10 m steps: this rectangle meets b1 and b2 only
    assert main(["export", src, "-o", str(out), "--idf", "--geojson", "-q", "-j", "1",
                 "--region", "85012,446990,85025,447020"]) == 0
    assert sorted(p.name for p in out.glob("*.idf")) == ["b1.idf", "b2.idf"]
    gj = json.loads(next(out.glob("*.geojson")).read_text())
    assert sorted(f["properties"]["id"] for f in gj["features"]) == ["b1", "b2"]
    assert all(t.count("Adiabatic") >= 2 for t in (p.read_text() for p in out.glob("*.idf")))


def test_plateau_tile_with_sentinels_reports_them_unknown(tmp_path, capsys):
    doc = json.loads(shared_path("japan-plateau", "japanese.city.json").read_text(encoding="utf-8"))
    doc.setdefault("metadata", {})["referenceDate"] = "2020-01-01"
    ids = [k for k, o in doc["CityObjects"].items() if "storeysAboveGround" in (o.get("attributes") or {})]
    assert len(ids) >= 2
    doc["CityObjects"][ids[0]]["attributes"]["storeysAboveGround"] = 9999
    doc["CityObjects"][ids[1]]["attributes"]["yearOfConstruction"] = 2099
    src = tmp_path / "plateau.city.json"
    src.write_text(json.dumps(doc), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["export", str(src), "-o", str(out), "--geojson", "-j", "1"]) in (0, 1)
    captured = capsys.readouterr()
    assert (f"1 building(s): storeys: a sentinel or implausible value taken as unknown, e.g. {ids[0]}" in captured.err
            and f"1 building(s): year: a sentinel or implausible value taken as unknown, e.g. {ids[1]}" in captured.err)
    rows = _csv(out / "report.csv")
    assert rows[ids[0]]["storeys_source"] in ("geometry", "default")
    assert rows[ids[1]]["year"] == "" and rows[ids[1]]["year_source"] == "default"
    assert rows[ids[1]]["construction_period"].endswith("(assumed)")
    assert rows[ids[0]]["use"] == "office" and rows[ids[0]]["use_source"] == "attribute"


def test_renamed_tile_through_the_cli_gives_the_same_report(tmp_path):
    lines = EXAMPLE.read_text(encoding="utf-8").splitlines()
    out_lines = [lines[0]]
    for ln in lines[1:]:
        if not ln.strip():
            continue
        d = json.loads(ln)
        for o in d["CityObjects"].values():
            o["attributes"] = {RENAMED.get(k, k): v for k, v in (o.get("attributes") or {}).items()}
        out_lines.append(json.dumps(d))
    src = tmp_path / "renamed.city.jsonl"
    src.write_text("\n".join(out_lines) + "\n", encoding="utf-8")
    amap = tmp_path / "renamed.toml"
    amap.write_text(MAP, encoding="utf-8")
    a, b = tmp_path / "a", tmp_path / "b"
    assert main(["export", str(EXAMPLE), "-o", str(a), "--geojson", "-q", "-j", "1"]) in (0, 1)
    assert main(["export", str(src), "-o", str(b), "--geojson", "-q", "-j", "1", "--attribute-map", str(amap)]) in (0, 1)
    ra, rb = _csv(a / "report.csv"), _csv(b / "report.csv")
    assert sorted(ra) == sorted(rb) and len(ra) == 10
    for i in ra:
        for k in ("year", "storeys", "use", "typology", "construction_period", "UA_W_per_K"):
            assert ra[i][k] == rb[i][k], (i, k)
        assert ra[i]["year_source"] == "attribute" and rb[i]["year_source"] == "map"
    assert sum(r["storeys_source"] == "map" for r in rb.values()) >= 3
    assert json.loads((b / "report.json").read_text())["buildings"][0]["thermal"]["attribute_map"] == "renamed"


def test_only_buildings_in_reach_of_the_selection_are_prepared_as_neighbours(tmp_path):
    from lod2energy import io
    from lod2energy.exporters.registry import writers
    from lod2energy.options import ExportOptions
    from lod2energy.study import selection_reach, selector
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=5)  # touching boxes, 10 m apart
    _, feats = io.read(src)
    bs = {b.id: b for b in feats}
    chosen = writers(("idf",))
    for opts, near_ids in ((ExportOptions(formats=("idf",), ids=("b0",)), {"b1"}),
                           (ExportOptions(formats=("idf",), ids=("b2",)), {"b1", "b3"})):
        scope = {w.name: w.scope(opts.writer_options(w.name)) for w in chosen}
        near = selection_reach(src, selector(frozenset(opts.ids), None), chosen, scope, opts)
        assert {i for i, b in bs.items() if i not in opts.ids and near(b)} == near_ids
    # no neighbour writer (STL): nothing outside the selection is prepared
    stl = writers(("stl",))
    opts = ExportOptions(formats=("stl",), ids=("b2",))
    near = selection_reach(src, selector(frozenset(opts.ids), None), stl,
                            {w.name: w.scope(opts.writer_options(w.name)) for w in stl}, opts)
    assert not any(near(b) for b in bs.values())
