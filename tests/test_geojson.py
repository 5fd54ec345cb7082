"""GeoJSON footprints (exporters/geojson.py): WGS84, RFC 7946, read back by GDAL (pyogrio)."""
import json
import re
from pathlib import Path

import numpy as np
import pytest

from conftest import shared_path
from lod2energy.cli import main
from lod2energy.exporters.geojson import writer as geojson
from lod2energy.site import distance_km
from lod2energy.thermal.use import USE_TYPES

pyogrio = pytest.importorskip("pyogrio")


def _site_locations(outdir: Path) -> list[tuple[float, float]]:
    """(lat, lon) of every ``Site:Location`` the IDF writer put in ``outdir``."""
    out = []
    for p in outdir.glob("*.idf"):
        text = re.sub(r"!.*", "", p.read_text())
        i = text.find("Site:Location,")
        if i >= 0:
            fields = [f.strip() for f in text[i:text.index(";", i)].split(",")]
            out.append((float(fields[2]), float(fields[3])))
    return out


def _gdal_read(path: Path):
    """Features as GDAL reads them: (meta, field dict, shapely geometries)."""
    import shapely
    meta, _, wkb, fields = pyogrio.raw.read(str(path))
    cols = {name: list(vals) for name, vals in zip(meta["fields"], fields)}
    return meta, cols, [shapely.from_wkb(g) for g in wkb]


@pytest.mark.parametrize("parts", [("3dbag", "delft_subset.city.jsonl"),
                                   ("citygml-real", "berlin", "3920_5820.gml")])
def test_gdal_reads_footprints_in_wgs84_near_the_site(tmp_path, parts):
    src = shared_path(*parts)
    out = tmp_path / "out"
    rc = main(["export", str(src), "-o", str(out), "--geojson", "--idf", "--no-html", "-q", "-j", "1"])
    assert rc in (0, 1)
    report = json.loads((out / "report.json").read_text())
    exported = {b["id"]: b for b in report["buildings"] if b.get("exports", {}).get("geojson", {}).get("ok")}
    assert exported
    files = list(out.glob(f"*{geojson.SUFFIX}"))
    assert len(files) == 1 and geojson.self_check(str(files[0])) == []
    meta, cols, geoms = _gdal_read(files[0])
    assert meta["crs"] == "EPSG:4326"
    assert len(geoms) == len(exported) and set(cols["id"]) == set(exported)
    sites = _site_locations(out)
    assert sites
    for bid, g in zip(cols["id"], geoms):
        assert g.is_valid and g.area > 0 and g.geom_type in ("Polygon", "MultiPolygon")
        lon, lat = g.centroid.x, g.centroid.y  # lon/lat order (RFC 7946): lon is x
        assert min(distance_km(lat, lon, *s) for s in sites) < 1.0
    for i, bid in enumerate(cols["id"]):
        b = exported[bid]
        assert cols["repair_stage"][i] == b["repair_stage"]
        assert bool(cols["compliant"][i]) == bool(b["compliant"])
        assert cols["storeys"][i] >= 1 and cols["use"][i] in USE_TYPES
    # an input error-free building is reported valid, the others by the stage that mended them
    assert all((s == "valid") == bool(v) for s, v in zip(cols["repair_stage"], cols["input_valid"]))


def test_delft_footprint_matches_an_independent_rd_transform(tmp_path):
    """The footprint's vertices against RD -> WGS84 by the published approximation (about 1 m)."""
    from lod2energy import io
    from lod2energy.model import Building
    from test_site import _rd_to_wgs84

    model, feats = io.read(str(shared_path("3dbag", "delft_subset.city.jsonl")))
    bs = [b for b in feats if isinstance(b, Building) and b.is_building and len(b.vertices)][:3]
    for b in bs:
        g = geojson.footprint_geometry(b, model.crs)
        fp = geojson.footprint(b)
        ring = np.asarray(g["coordinates"][0] if g["type"] == "Polygon" else g["coordinates"][0][0])
        xy = np.asarray((fp.geoms[0] if hasattr(fp, "geoms") else fp).exterior.coords)
        ref = np.array([_rd_to_wgs84(x, y) for x, y in xy[:, :2]])  # (lat, lon)
        # the ring may be reversed for the winding: compare as sets of points
        dmin = [min(distance_km(lat, lon, rl, rn) for rl, rn in ref) * 1000 for lon, lat in ring]
        assert max(dmin) < 2.0, dmin


def test_footprint_of_an_overhang_is_the_projection_union():
    from export_helpers import parts_building
    from factories import box_polygons
    b = parts_building([box_polygons(10, 8, 3), box_polygons(14, 8, 3, origin=(0.0, 0.0, 3.0)),
                        box_polygons(4, 4, 3, origin=(20.0, 0.0, 0.0))], id="overhang")
    fp = geojson.footprint(b)
    assert fp.geom_type == "MultiPolygon"  # the detached third part is a polygon of its own
    assert fp.area == pytest.approx(14 * 8 + 16, rel=1e-3)


def test_self_check_refuses_clockwise_and_out_of_range(tmp_path):
    bad = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "id": "cw", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
            [[4.0, 52.0], [4.0, 52.001], [4.001, 52.001], [4.001, 52.0], [4.0, 52.0]]]}},
        {"type": "Feature", "id": "far", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
            [[190.0, 52.0], [191.0, 52.0], [191.0, 53.0], [190.0, 52.0]]]}}]}
    p = tmp_path / "bad.geojson"
    p.write_text(json.dumps(bad))
    problems = geojson.self_check(str(p), n_features=2)
    assert any("clockwise" in x for x in problems) and any("range" in x for x in problems)
