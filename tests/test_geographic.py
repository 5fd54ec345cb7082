"""City models in a geographic CRS (degrees): read into a local metric frame, written back."""
from __future__ import annotations

import doctest
import json

import numpy as np
import pytest

import lod2energy.geodesy
from lod2energy.crs import is_geographic, latitude_first
from lod2energy.geodesy import LocalFrame
from lod2energy.io import read
from lod2energy.validate.checks import validate_building

from cityjson_docs import BOX_FACES, BOX_SEMANTICS, box_doc, to_seq, write

TOKYO = LocalFrame(35.68, 139.76, 0.0)


def geographic_box_doc(frame=TOKYO, offset=(0.0, 0.0, 0.0), crs="https://www.opengis.net/def/crs/EPSG/0/6697",
                       n=1) -> dict:
    """``n`` 10 x 8 x 6 m boxes 30 m apart, corners given in degrees (PLATEAU's lat, lon, h)."""
    doc = box_doc()
    verts, cos = [], {}
    for k in range(n):
        corners = np.array([[0, 0, 0], [10, 0, 0], [10, 8, 0], [0, 8, 0], [0, 0, 6], [10, 0, 6], [10, 8, 6], [0, 8, 6]],
                           float) + offset + [30.0 * k, 0, 0]
        base = len(verts)
        verts.extend(frame.to_geodetic(corners).tolist())
        cos[f"b{k + 1}"] = {"type": "Building", "geometry": [{
            "type": "Solid", "lod": "2.2", "boundaries": [[[[base + i for i in r] for r in f] for f in BOX_FACES]],
            "semantics": BOX_SEMANTICS}]}
    doc["CityObjects"] = cos
    doc["transform"] = {"scale": [1e-10, 1e-10, 1e-6], "translate": [35.6, 139.7, 0.0]}
    s, t = np.array(doc["transform"]["scale"]), np.array(doc["transform"]["translate"])
    doc["vertices"] = np.rint((np.array(verts) - t) / s).astype(np.int64).tolist()
    doc["metadata"] = {"referenceSystem": crs}
    return doc


def test_docstring_examples_run():
    assert doctest.testmod(lod2energy.geodesy).failed == 0


@pytest.mark.parametrize("crs, geographic, lat_first", [
    ("https://www.opengis.net/def/crs/EPSG/0/6697", True, True),
    ("urn:ogc:def:crs:EPSG::4326", True, True),
    ("urn:ogc:def:crs:OGC:1.3:CRS84", True, False),
    ("https://www.opengis.net/def/crs/EPSG/0/7415", False, True),
    ("https://www.opengis.net/def/crs/EPSG/0/6677", False, True),   # JGD2011 plane rectangular IX
    (None, False, True),
])
def test_geographic_crs_names(crs, geographic, lat_first):
    assert is_geographic(crs) is geographic
    assert latitude_first(crs) is lat_first


@pytest.mark.parametrize("lat, lon", [(35.68, 139.76), (52.0, 4.36), (-33.9, 151.2), (64.1, -21.9)])
def test_round_trip_keeps_distances(lat, lon):
    f = LocalFrame(lat, lon, 40.0)
    rng = np.random.default_rng(0)
    enu = rng.uniform(-3000, 3000, (50, 3)) * [1, 1, 0.05]
    g = f.to_geodetic(enu)
    np.testing.assert_allclose(f.to_local(g), enu, atol=1e-6)
    d = np.linalg.norm(enu[:, None] - enu[None], axis=2)
    from lod2energy.geodesy import geodetic_to_ecef
    e = geodetic_to_ecef(g[:, 0], g[:, 1], g[:, 2])
    np.testing.assert_allclose(np.linalg.norm(e[:, None] - e[None], axis=2), d, atol=1e-6)


def test_geographic_file_is_read_in_metres_and_valid(tmp_path):
    model, feats = read(write(tmp_path, geographic_box_doc(offset=(500.0, -200.0, 3.0))))
    (b,) = list(feats)
    assert model.frame is not None and model.frame.lat_first
    v = b.vertices
    edges = [np.linalg.norm(v[i] - v[j]) for i, j in ((0, 1), (1, 2), (0, 4))]
    np.testing.assert_allclose(edges, [10, 8, 6], atol=2e-4)      # metres, not 1e-4 degrees
    up = np.cross(v[1] - v[0], v[2] - v[1])
    assert up[2] / np.linalg.norm(up) > 0.999999                  # the frame's origin is near the data
    assert validate_building(b) == []


def test_lon_lat_order_is_recognised(tmp_path):
    doc = geographic_box_doc(crs="urn:ogc:def:crs:OGC:1.3:CRS84")
    s, t = np.array(doc["transform"]["scale"]), np.array(doc["transform"]["translate"])
    deg = np.array(doc["vertices"]) * s + t
    doc["transform"] = {"scale": [1e-10, 1e-10, 1e-6], "translate": [139.7, 35.6, 0.0]}
    doc["vertices"] = np.rint((deg[:, [1, 0, 2]] - [139.7, 35.6, 0.0]) / s).astype(np.int64).tolist()
    model, feats = read(write(tmp_path, doc))
    (b,) = list(feats)
    assert not model.frame.lat_first
    v = b.vertices
    np.testing.assert_allclose([np.linalg.norm(v[i] - v[j]) for i, j in ((0, 1), (1, 2), (0, 4))], [10, 8, 6],
                               atol=2e-4)


def test_export_writes_degrees_back_and_metres_to_the_simulation_files(tmp_path, capsys):
    from lod2energy.cli import main
    src = write(tmp_path, None, "geo.city.jsonl", to_seq(geographic_box_doc(n=2)))
    out = tmp_path / "out"
    rc = main(["export", src, "-o", str(out), "--idf", "--stl", "--cityjson", "-q"])
    assert rc == 0, capsys.readouterr().err
    doc = json.loads((out / "geo.energy.city.json").read_text())
    assert doc["metadata"]["referenceSystem"].endswith("/6697")
    s, t = np.array(doc["transform"]["scale"]), np.array(doc["transform"]["translate"])
    got = np.array(doc["vertices"]) * s + t
    ins = [json.loads(ln) for ln in to_seq(geographic_box_doc(n=2)).splitlines()]
    s0, t0 = np.array(ins[0]["transform"]["scale"]), np.array(ins[0]["transform"]["translate"])
    want = np.vstack([np.array(f["vertices"]) * s0 + t0 for f in ins[1:]])
    for p in want:                                               # every input corner is written back
        assert np.abs(got - p).max(axis=1).min() < 2e-9          # degrees (~0.2 mm)
    idf_text = (out / "b1.idf").read_text()
    from lod2energy.exporters import energyplus
    assert energyplus.check.self_check(out / "b1.idf") == []
    assert "BuildingSurface:Detailed" in idf_text
    report = json.loads((out / "report.json").read_text())
    areas = {r["id"]: r["A_env_m2"] for r in report["buildings"]}
    assert areas["b1"] == pytest.approx(2 * 80 + 2 * 60 + 2 * 48, rel=1e-3)   # m2, not square degrees
