"""Hand-offs to URBANopt (--urbanopt) and the City Energy Analyst (--cea), each checked by that
tool's own rules: every FeatureFile against URBANopt's published JSON schemas (vendored in
tests/data/urbanopt, as urbanopt-geojson-gem's ``GeoFile.from_file`` validates), the zone table
read back through pyogrio with CEA's column names and CEA's input checks."""
from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import numpy as np
import pytest
import shapely
from pyproj import CRS

from conftest import shared_path
from export_helpers import TEST_CRS, shifted, two_part_building
from factories import box, gabled_house
from lod2energy.cli import main
from lod2energy.exporters.cea import writer as cea
from lod2energy.exporters.handoff import facts
from lod2energy.exporters.registry import writer
from lod2energy.exporters.urbanopt import writer as urbanopt

pyogrio = pytest.importorskip("pyogrio")

SCHEMAS = Path(__file__).resolve().parent / "data" / "urbanopt"
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "3dbag_b2.city.json"
#: CEA 4's zone columns (cea/datamanagement/databases_verification.py, COLUMNS_ZONE_GEOMETRY and
#: COLUMNS_ZONE_TYPOLOGY) and use / construction types of its default database (CH).
CEA_GEOMETRY = ["name", "floors_bg", "floors_ag", "void_deck", "height_bg", "height_ag"]
CEA_TYPOLOGY = ["name", "year", "const_type", "use_type1", "use_type1r", "use_type2", "use_type2r", "use_type3",
                "use_type3r"]
CEA_USE_TYPES = {"MULTI_RES", "SINGLE_RES", "HOTEL", "OFFICE", "RETAIL", "FOODSTORE", "RESTAURANT", "INDUSTRIAL",
                 "SCHOOL", "HOSPITAL", "GYM", "SWIMMING", "SERVERROOM", "PARKING", "COOLROOM", "LAB", "MUSEUM",
                 "LIBRARY", "UNIVERSITY"}
CEA_CONST_TYPES = {f"STANDARD{k}" for k in range(1, 7)}


def _schema(name: str, strict: bool = False) -> dict:
    s = json.loads((SCHEMAS / name).read_text())
    if strict:  # every property we write must be one of URBANopt's
        s["additionalProperties"] = False
    return s


def urbanopt_errors(doc: dict) -> list[str]:
    """URBANopt's schema errors of a FeatureFile: the collection against ``geojson_schema.json``,
    ``project`` against ``site_properties.json``, each Building's properties against
    ``building_properties.json`` with no property outside it."""
    out = [f"collection: {e.message}" for e in jsonschema.Draft4Validator(_schema("geojson_schema.json")).iter_errors(doc)]
    if "project" in doc:
        v = jsonschema.Draft4Validator(_schema("site_properties.json"))
        out += [f"project: {e.message}" for e in v.iter_errors(doc["project"])]
    bv = jsonschema.Draft4Validator(_schema("building_properties.json", strict=True))
    for ft in doc.get("features", []):
        if (ft.get("properties") or {}).get("type") == "Building":
            out += [f"{ft['properties'].get('id')}: {e.message}" for e in bv.iter_errors(ft["properties"])]
    return out


def cea_errors(meta: dict, cols: dict, geoms) -> list[str]:
    """CEA's input checks of a zone table (databases_verification.py: verify_input_geometry_zone,
    verify_input_typology), restated."""
    out = []
    missing = [c for c in CEA_GEOMETRY + CEA_TYPOLOGY if c not in cols]
    if missing:
        return [f"columns missing: {missing}"]
    num = {k: np.asarray(v, dtype=float) for k, v in cols.items() if np.asarray(v).dtype.kind in "iuf"}
    if any((v < 0).any() for v in num.values()):
        out.append("negative values")
    if (num["floors_ag"] < 1).any() or (num["height_ag"] < 1.0).any() or (num["height_ag"] < num["floors_ag"]).any():
        out.append("less than one floor, 1 m, or 1 m a floor above ground")
    if any(g.geom_type != "Polygon" for g in geoms):
        out.append("not only Polygons")
    for c in CEA_GEOMETRY + CEA_TYPOLOGY:
        if any(x is None or (isinstance(x, float) and np.isnan(x)) for x in cols[c]):
            out.append(f"NA in {c}")
    names = list(cols["name"])
    if len(set(names)) != len(names):
        out.append("duplicated names")
    if (num["void_deck"] % 1 != 0).any() or (num["void_deck"] > num["floors_ag"]).any():
        out.append("void_deck not an integer below floors_ag")
    if not all(str(n)[:1].isalpha() for n in names):
        out.append("a name does not start with a letter")
    if not set(cols["use_type1"]) <= CEA_USE_TYPES or not set(cols["const_type"]) <= CEA_CONST_TYPES:
        out.append("use or construction type not in CEA's database")
    if not CRS.from_user_input(meta["crs"]).is_projected:
        out.append("not in a projected CRS")
    return out


def read_zone(path: Path):
    meta, _, wkb, values = pyogrio.raw.read(str(path))
    return meta, {k: list(v) for k, v in zip(meta["fields"], values)}, list(shapely.from_wkb(wkb))


# ----------------------------------------------------------------------------- tiny buildings

def test_facts_of_a_box_a_wing_and_an_attic():
    b = facts(box())  # 6 m flat roof: 2 storeys of 2.8 m
    assert (b.storeys, b.footprint_area, b.floor_area, b.height) == (2, pytest.approx(80), pytest.approx(160), 6.0)
    # a 6 m wing beside a 9 m part: the wing's two storeys and the part's three, not 3 x footprint
    w = facts(two_part_building())
    assert w.footprint_area == pytest.approx(128) and w.floor_area == pytest.approx(2 * 80 + 3 * 48)
    # the attic floor counts only when the attic is conditioned, as in the IDF
    cold, warm = facts(gabled_house()), facts(gabled_house(), attic_mode="conditioned")
    assert cold.attic and cold.floor_area == pytest.approx(160) and warm.floor_area == pytest.approx(240, rel=1e-3)
    assert cold.prism_height == pytest.approx(9.0)  # no thermal volume: the ridge


def test_urbanopt_file_of_tiny_buildings_passes_urbanopts_schema(tmp_path):
    bs = [shifted(box(id="b1")), shifted(gabled_house(id="h1"), (85030.0, 446000.0, 0.0))]
    res = urbanopt.write(bs, tmp_path / f"t{urbanopt.SUFFIX}", crs=TEST_CRS)
    assert res.ok, res.problems
    doc = json.loads(Path(res.path).read_text())
    assert urbanopt_errors(doc) == []
    by_id = {f["properties"]["id"]: f["properties"] for f in doc["features"]}
    assert set(by_id) == {"b1", "h1"}
    assert by_id["b1"]["floor_area"] == pytest.approx(160 * urbanopt.FT2, abs=0.1)
    assert by_id["h1"]["maximum_roof_height"] == pytest.approx(9.0 * urbanopt.FT, abs=0.01)
    assert by_id["h1"]["number_of_stories"] == 3 and by_id["h1"]["building_type"] == "Multifamily"
    assert 51.9 < doc["project"]["latitude"] < 52.1 and 4.2 < doc["project"]["longitude"] < 4.5


def test_the_schema_check_catches_what_urbanopt_refuses():
    """The control: the schema check fails on a feature URBANopt would refuse."""
    props = urbanopt.properties(facts(box()))
    good = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": props,
         "geometry": {"type": "Polygon", "coordinates": [[[4.0, 52.0], [4.001, 52.0], [4.001, 52.001], [4.0, 52.0]]]}}]}
    assert urbanopt_errors(good) == []
    for change in ({"building_type": "residential"}, {"floor_area": None}, {"number_of_stories": 2.5},
                   {"height": 6.0}):
        bad = json.loads(json.dumps(good))
        bad["features"][0]["properties"].update(change)
        bad["features"][0]["properties"] = {k: v for k, v in bad["features"][0]["properties"].items() if v is not None}
        assert urbanopt_errors(bad), change


def test_cea_table_of_tiny_buildings(tmp_path):
    bs = [shifted(box(id="1st")), shifted(two_part_building(id="wing"), (85030.0, 446000.0, 0.0)),
          shifted(box(dz=1.5, id="shed"), (85060.0, 446000.0, 0.0))]
    res = cea.write(bs, cea.scenario_path(tmp_path, "t"), crs=TEST_CRS)
    assert res.ok, res.problems
    meta, cols, geoms = read_zone(Path(res.path))
    assert cea_errors(meta, cols, geoms) == []
    assert cols["reference"] == ["1st", "wing"]  # the 1.5 m shed is below CEA's 2 m: left out with the reason
    assert dict(res.skipped)["shed"].startswith("CEA:")
    assert cols["name"][0].startswith("B") and cols["floors_ag"] == [2, 3]
    assert [round(g.area, 1) for g in geoms] == [pytest.approx(80, abs=0.5), pytest.approx(128, abs=0.5)]
    assert meta["crs"] == "EPSG:32631"  # the UTM zone of the RD test site


def test_cea_self_check_refuses_what_cea_refuses(tmp_path):
    res = cea.write([shifted(box(id="b"))], cea.scenario_path(tmp_path, "t"), crs=TEST_CRS)
    assert res.ok and cea.self_check(res.path, n_rows=1) == []
    meta, cols, geoms = read_zone(Path(res.path))
    cols["floors_ag"] = [np.int32(9)]  # 9 floors in 6 m: CEA refuses less than 1 m a floor
    bad = tmp_path / "bad.shp"
    pyogrio.raw.write(str(bad), np.array([shapely.to_wkb(g) for g in geoms], dtype=object),
                      [np.asarray(cols[k]) for k in meta["fields"]], list(meta["fields"]), crs=meta["crs"],
                      geometry_type="Polygon", driver="ESRI Shapefile")
    assert cea.self_check(str(bad)) and cea_errors(*read_zone(bad))


def test_registered_and_refused_without_a_crs(tmp_path):
    assert writer("urbanopt").scope(None) == "dataset" and writer("cea").scope(None) == "dataset"
    src = tmp_path / "nocrs.city.json"
    doc = json.loads(EXAMPLE.read_text())
    doc.get("metadata", {}).pop("referenceSystem", None)
    src.write_text(json.dumps(doc))
    for flag in ("--urbanopt", "--cea"):
        out = tmp_path / flag.strip("-")
        assert main(["export", str(src), "-o", str(out), flag, "--no-html", "-q", "-j", "1"]) == 2
        assert not out.exists() or not any(out.rglob("*.shp")) and not any(out.rglob("*.geojson"))


# ----------------------------------------------------------------------------- real tiles

@pytest.fixture(scope="module", params=["example", "delft", "berlin"])
def exported(request, tmp_path_factory):
    """One export with --urbanopt --cea --idf: (OUTDIR, report.json)."""
    src = {"example": lambda: EXAMPLE,
           "delft": lambda: shared_path("3dbag", "delft_subset.city.jsonl"),
           "berlin": lambda: shared_path("citygml-real", "berlin", "3920_5820.gml")}[request.param]()
    out = tmp_path_factory.mktemp(request.param)
    rc = main(["export", str(src), "-o", str(out), "--urbanopt", "--cea", "--idf", "--no-html", "-q", "-j", "1"])
    assert rc in (0, 1)
    return out, json.loads((out / "report.json").read_text())


def _exported(report: dict, fmt: str) -> dict:
    return {b["id"]: b for b in report["buildings"] if b.get("exports", {}).get(fmt, {}).get("ok")}


def test_every_urbanopt_featurefile_validates_against_urbanopts_schema(exported):
    out, report = exported
    ok = _exported(report, "urbanopt")
    assert ok
    [path] = list(out.glob(f"*{urbanopt.SUFFIX}"))
    doc = json.loads(path.read_text())
    assert urbanopt_errors(doc) == []
    ids = [f["properties"]["id"] for f in doc["features"]]
    assert len(ids) == len(set(ids)) and set(ids) == set(ok)
    for f in doc["features"]:
        p, b = f["properties"], ok[f["properties"]["id"]]
        assert p["number_of_stories"] == b["storeys"]  # the storeys the IDF zones, not an extrusion's
        assert p["floor_area"] >= 0.99 * p["footprint_area"] > 0
        assert p["maximum_roof_height"] > 0 and p.get("year_built", b["year"]) == b["year"]


def test_cea_zone_table_reads_back_with_ceas_columns_one_row_per_building(exported):
    out, report = exported
    ok = _exported(report, "cea")
    assert ok
    [path] = list(out.glob("*.cea/inputs/building-geometry/zone.shp"))
    meta, cols, geoms = read_zone(path)
    assert cea_errors(meta, cols, geoms) == []
    assert len(cols["reference"]) == len(set(cols["reference"])) and set(cols["reference"]) == set(ok)
    for bid, fl in zip(cols["reference"], cols["floors_ag"]):
        assert fl == ok[bid]["storeys"]
    # every building the CEA table leaves out says why
    for b in report["buildings"]:
        e = b.get("exports", {}).get("cea")
        if e is not None and not e["ok"]:
            assert e["problems"]


def test_cea_leaves_out_an_id_no_shapefile_field_holds(tmp_path):
    long_id = "é" * 200  # 400 bytes in UTF-8
    bs = [shifted(box(id=long_id)), shifted(box(id="short"), (85030.0, 446000.0, 0.0))]
    res = cea.write(bs, cea.scenario_path(tmp_path, "t"), crs=TEST_CRS)
    assert res.ok and res.building_ids == ("short",) and "254 bytes" in dict(res.skipped)[long_id]
    assert read_zone(Path(res.path))[1]["reference"] == ["short"]
