"""The footprint layer (GeoJSON, exporters/geojson/) is one typed layer, and ``--gpkg`` writes
the same rows and values as a GeoPackage (exporters/gpkg/), read back by GDAL (pyogrio)."""
import json
import math
from pathlib import Path

import numpy as np
import pytest
import shapely
from shapely.geometry import shape

from conftest import REPO, shared_path
from lod2energy.cli import main
from lod2energy.exporters.geojson import writer as geojson
from lod2energy.exporters.gpkg import writer as gpkg

pyogrio = pytest.importorskip("pyogrio")

JSON_TYPES = {str: (str,), int: (int,), float: (float,), bool: (bool,)}
#: GDAL's type of a GeoJSON field inferred from its values (an integer field may be 32 or 64 bit).
GDAL_JSON_TYPES = {str: {("OFTString", "OFSTNone")}, float: {("OFTReal", "OFSTNone")},
                   int: {("OFTInteger", "OFSTNone"), ("OFTInteger64", "OFSTNone")},
                   bool: {("OFTInteger", "OFSTBoolean")}}


def _json_kind(v):
    return type(v) if not isinstance(v, bool) else bool


def _plain(v):
    if isinstance(v, np.generic):
        v = v.item()
    return None if isinstance(v, float) and math.isnan(v) else v


def _export(src: Path, out: Path) -> dict:
    rc = main(["export", str(src), "-o", str(out), "--idf", "--geojson", "--gpkg", "--no-html", "-q", "-j", "1"])
    assert rc in (0, 1)
    return {b["id"]: b for b in json.loads((out / "report.json").read_text())["buildings"]}


@pytest.mark.parametrize("src", ["example", "berlin"])
def test_geojson_is_one_typed_layer_and_the_gpkg_has_its_rows(tmp_path, src):
    path = (REPO / "examples" / "delft_subset.city.jsonl" if src == "example"
            else shared_path("citygml-real", "berlin", "3920_5820.gml"))
    report = _export(path, tmp_path / "out")
    (gj,) = (tmp_path / "out").glob(f"*{geojson.SUFFIX}")
    (gp,) = (tmp_path / "out").glob(f"*{gpkg.SUFFIX}")
    feats = json.loads(gj.read_text())["features"]
    assert feats and len(feats) == sum(1 for b in report.values() if "gpkg" in b.get("exports", {}))
    # every Feature: a MultiPolygon, the same keys, one JSON type per key (null allowed)
    kinds: dict[str, set] = {k: set() for k in geojson.FIELDS}
    for f in feats:
        assert f["geometry"]["type"] == "MultiPolygon"
        assert list(f["properties"]) == list(geojson.FIELDS)
        for k, v in f["properties"].items():
            if v is not None:
                kinds[k].add(_json_kind(v))
    for k, t in geojson.FIELDS.items():
        assert kinds[k] <= set(JSON_TYPES[t]), (k, kinds[k])
    # the figures are the report's
    for f in feats:
        p, b = f["properties"], report[f["id"]]
        assert (p["year"], p["year_source"], p["conditioned"], p["use"], p["storeys"]) == \
            (b["year"] if b["year"] != "" else None, b["year_source"], b["conditioned"], b["use"], b["storeys"])
        assert p["UA_W_per_K"] == b["UA_W_per_K"] and p["u_wall"] == b["thermal"]["u_values"]["wall"]
        assert p["height_m"] > 0 and p["floor_area_m2"] >= p["footprint_area_m2"] * 0.5 > 0
    # GDAL reads the GeoJSON as one layer whose fields have the declared types
    assert len(pyogrio.list_layers(gj)) == 1
    meta, _, wkb, values = pyogrio.raw.read(str(gj))
    assert list(meta["fields"]) == list(geojson.FIELDS) and meta["geometry_type"] == "MultiPolygon"
    for k, ot, st in zip(meta["fields"], meta["ogr_types"], meta["ogr_subtypes"]):
        if kinds[k]:
            assert (ot, st) in GDAL_JSON_TYPES[geojson.FIELDS[k]], (k, ot, st)
    # the GeoPackage: the same rows, values and geometries, the declared types
    assert gpkg.self_check(str(gp)) == []
    assert [list(x) for x in pyogrio.list_layers(gp)] == [[gp.name[:-len(gpkg.SUFFIX)], "MultiPolygon"]]
    meta, _, wkb, values = pyogrio.raw.read(str(gp))
    assert meta["crs"] == "EPSG:4326" and list(meta["fields"]) == list(geojson.FIELDS)
    assert [(ot, st) for ot, st in zip(meta["ogr_types"], meta["ogr_subtypes"])] == \
        [gpkg.OGR_TYPES[t] for t in geojson.FIELDS.values()]
    cols = dict(zip(meta["fields"], values))
    assert [str(i) for i in cols["id"]] == [f["id"] for f in feats]
    for i, f in enumerate(feats):
        for k, v in f["properties"].items():
            got = _plain(cols[k][i])
            assert (got is None and v is None) or got == v, (f["id"], k, got, v)
        assert shapely.equals_exact(shapely.from_wkb(wkb[i]), shape(f["geometry"]), tolerance=0)
    assert all(b["exports"]["gpkg"]["ok"] == b["exports"]["geojson"]["ok"] for b in report.values()
               if "gpkg" in b.get("exports", {}))


def _boxes(n: int = 2):
    from factories import box
    return [box(origin=(85000.0 + 30 * i, 447000.0, 0.0), id=f"b{i}") for i in range(n)]


def test_a_one_part_footprint_is_a_multipolygon_and_unknowns_are_null(tmp_path):
    p = tmp_path / f"t{geojson.SUFFIX}"
    res = geojson.write(_boxes(), p, crs="EPSG:28992", root=tmp_path)
    assert res.ok, res.problems
    feats = json.loads(p.read_text())["features"]
    assert [f["geometry"]["type"] for f in feats] == ["MultiPolygon", "MultiPolygon"]
    assert len(feats[0]["geometry"]["coordinates"]) == 1
    props = feats[0]["properties"]
    assert list(props) == list(geojson.FIELDS)
    assert props["UA_W_per_K"] is None and props["heating_kwh"] is None and props["weather_station"] is None
    assert props["footprint_area_m2"] == pytest.approx(80.0, abs=0.01) and isinstance(props["storeys"], int)
    # the GeoPackage of a layer with columns null throughout still declares their types
    g = tmp_path / f"t{gpkg.SUFFIX}"
    res = gpkg.write(_boxes(), g, crs="EPSG:28992", root=tmp_path)
    assert res.ok, res.problems
    meta = pyogrio.read_info(str(g))
    assert meta["features"] == 2
    assert dict(zip(meta["fields"], meta["ogr_types"]))["heating_kwh"] == "OFTReal"


def test_typed_values():
    assert geojson.typed("year", np.int64(1994)) == 1994 and isinstance(geojson.typed("year", 1994.0), int)
    assert geojson.typed("UA_W_per_K", 3) == 3.0 and isinstance(geojson.typed("UA_W_per_K", 3), float)
    assert geojson.typed("heating_kwh", 1234.56) == 1235.0 and geojson.typed("heating_kwh_m2", 12.345) == 12.3
    assert geojson.typed("UA_W_per_K", float("nan")) is None and geojson.typed("year", "") is None
    assert geojson.typed("conditioned", np.bool_(False)) is False and geojson.typed("id", 7) == "7"


def test_self_checks_refuse_a_changed_type_or_a_missing_field(tmp_path):
    p = tmp_path / f"t{geojson.SUFFIX}"
    assert geojson.write(_boxes(), p, crs="EPSG:28992", root=tmp_path).ok
    fc = json.loads(p.read_text())
    fc["features"][0]["properties"]["storeys"] = 2.0
    del fc["features"][1]["properties"]["wwr"]
    p.write_text(json.dumps(fc))
    problems = geojson.self_check(str(p), n_features=2)
    assert any("'storeys'" in x for x in problems) and any("wwr" in x for x in problems)
    # a GeoPackage whose "storeys" is Real
    rows = [f["properties"] for f in fc["features"][:1]]
    values, masks = gpkg.columns(rows)
    k = list(geojson.FIELDS).index("storeys")
    values[k] = values[k].astype(np.float64)
    bad = tmp_path / "bad.gpkg"
    pyogrio.raw.write(str(bad), np.asarray(shapely.to_wkb([shape(fc["features"][0]["geometry"])]), dtype=object),
                      values, list(geojson.FIELDS), field_mask=masks, driver="GPKG", geometry_type="MultiPolygon",
                      crs="EPSG:4326")
    assert any("storeys" in x for x in gpkg.self_check(str(bad)))


def test_a_gpkg_that_fails_its_check_never_has_the_good_name(tmp_path, monkeypatch):
    g = tmp_path / f"t{gpkg.SUFFIX}"
    g.write_bytes(b"an older file")
    monkeypatch.setattr(gpkg, "self_check", lambda path, ids=None, rows=None: [f"{path}: broken"])
    res = gpkg.write(_boxes(), g, crs="EPSG:28992", root=tmp_path)
    assert not res.ok and res.path.endswith(".invalid") and not g.exists()
    assert (tmp_path / f"t{gpkg.SUFFIX}.invalid").exists()
    assert sorted(x.name for x in tmp_path.iterdir()) == [f"t{gpkg.SUFFIX}.invalid"]  # no temporary left


@pytest.mark.parametrize("formats", [("--geojson", "--gpkg"), ("--geojson",), ("--gpkg",)])
def test_the_layer_facts_are_computed_once_for_geojson_and_gpkg(tmp_path, monkeypatch, formats):
    """With --geojson and --gpkg each building's footprint facts are computed once (the
    GeoPackage keeps them, the GeoJSON takes them), the two files hold the same rows, and
    nothing is kept once the GeoJSON has taken them."""
    from lod2energy.exporters import handoff
    calls = []
    real = handoff.facts

    def counting(b, *a, **kw):
        calls.append(str(b.id))
        return real(b, *a, **kw)

    monkeypatch.setattr(handoff, "facts", counting)
    out = tmp_path / "out"
    assert main(["export", str(REPO / "examples" / "delft_subset.city.jsonl"), "-o", str(out), *formats,
                 "--no-html", "-q", "-j", "1"]) in (0, 1)
    assert calls and len(calls) == len(set(calls)), "facts computed more than once for a building"
    if len(formats) == 2:
        feats = json.loads(next(out.glob(f"*{geojson.SUFFIX}")).read_text())["features"]
        _, _, _, values = pyogrio.raw.read(str(next(out.glob(f"*{gpkg.SUFFIX}"))))
        cols = dict(zip(geojson.FIELDS, values))
        assert [f["id"] for f in feats] == [str(v) for v in cols["id"]]
        for k in ("storeys", "height_m", "floor_area_m2", "use"):
            assert [f["properties"][k] for f in feats] == [_plain(v) for v in cols[k]], k
        from lod2energy import cache
        assert cache.sizes().get(geojson.LAYER_TABLE, (0, 0))[0] == 0
