"""One rule for every CRS question (issues 38.7, 39.1, 40.2).

- any CRS pyproj reads: geographic or projected, axis order and units from pyproj;
- coordinates in feet are converted to metres for every computation, written back in feet;
- a file without a CRS pyproj reads is refused for the outputs that need positions (exit 2,
  nothing written) unless ``--crs`` gives one; the others take metres and say so.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from pyproj import Transformer

from lod2energy.cli import main
from lod2energy.crs import crs_info, no_crs_reason, spelled
from lod2energy.errors import ParameterError
from lod2energy.geometry import signed_volume
from lod2energy.io import read
from lod2energy.site import distance_km

from cityjson_docs import box_doc, write
from conftest import shared_path

FT = 0.3048006096012192  # metres in one US survey foot


def run(args, capsys):
    rc = main(args)
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return rc, out, err


def site_location(idf: Path) -> tuple[float, float]:
    """(latitude, longitude) of the ``Site:Location`` of an IDF."""
    m = re.search(r"Site:Location,[^\n]*\n[^\n]*\n\s*(-?[0-9.]+),[^\n]*\n\s*(-?[0-9.]+),", idf.read_text())
    return float(m.group(1)), float(m.group(2))


def decoded(doc: dict) -> np.ndarray:
    t = doc["transform"]
    return np.asarray(doc["vertices"], float) * t["scale"] + t["translate"]


def encoded(doc: dict, xyz: np.ndarray, scale) -> dict:
    doc = dict(doc)
    lo = xyz.min(axis=0)
    doc["transform"] = {"scale": list(scale), "translate": lo.tolist()}
    doc["vertices"] = np.rint((xyz - lo) / scale).astype(np.int64).tolist()
    return doc


def shell_volume(b) -> float:
    """Volume (m3) of the first solid of a building read by :func:`lod2energy.io.read`."""
    tris = [(r[0], r[i], r[i + 1]) for _, _, g in b.envelope() for solid in g.solids
            for s in solid.shells[0].surfaces for r in [np.asarray(s.rings[0])] for i in range(1, len(r) - 1)]
    return signed_volume(np.asarray(b.vertices, float), np.asarray(tris, dtype=np.int64))


# ----------------------------------------------------------------------------- any CRS pyproj reads

@pytest.mark.parametrize("name, geographic, lat_first, north_first, to_metre", [
    ("EPSG:4171", True, True, False, 1.0),           # RGF93: not in any hand list
    ("EPSG:4674", True, True, False, 1.0),           # SIRGAS 2000
    ("urn:ogc:def:crs:OGC:1.3:CRS84", True, False, False, 1.0),
    ("https://www.opengis.net/def/crs/EPSG/0/6697", True, True, False, 1.0),
    ("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH*GCG2016", False, False, False, 1.0),
    ("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837", False, False, False, 1.0),
    ("EPSG:6677", False, False, True, 1.0),          # JGD2011 plane CS: north first
    ("EPSG:2263", False, False, False, FT),          # US survey feet
    ("EPSG:2227", False, False, False, FT),          # California zone 3 (ftUS)
])
def test_pyproj_decides_kind_axis_order_and_unit(name, geographic, lat_first, north_first, to_metre):
    info = crs_info(name)
    assert info is not None and info.placeable
    assert (info.geographic, info.lat_first, info.north_first) == (geographic, lat_first, north_first)
    assert info.to_metre == pytest.approx(to_metre, rel=1e-12)


@pytest.mark.parametrize("name", [None, "", "EPSG:999999", "local grid", "urn:adv:crs:Unknown"])
def test_a_crs_pyproj_cannot_read_counts_as_no_crs(name):
    assert crs_info(name) is None
    assert no_crs_reason(name)


def test_user_crs_is_spelled_for_cityjson_and_refused_when_unreadable():
    assert spelled("EPSG:2263") == "https://www.opengis.net/def/crs/EPSG/0/2263"
    assert spelled(28992) == "https://www.opengis.net/def/crs/EPSG/0/28992"
    # a PROJ string: its EPSG or OGC equivalent, with the same axis order (lon, lat: CRS84, not 4326)
    assert spelled("+proj=utm +zone=32 +datum=WGS84 +units=m") == "https://www.opengis.net/def/crs/EPSG/0/32632"
    assert spelled("+proj=longlat +datum=WGS84") == "https://www.opengis.net/def/crs/OGC/0/CRS84"
    with pytest.raises(ParameterError):
        spelled("EPSG:999999")


def _latlon_tile(tmp_path, code: int) -> str:
    """3dbag_b2 (EPSG:7415) reprojected with pyproj to ETRS89 latitude / longitude, tagged ``code``."""
    doc = json.loads(shared_path("3dbag", "3dbag_b2.city.json").read_text(encoding="utf-8"))
    xyz = decoded(doc)
    lat, lon = Transformer.from_crs("EPSG:28992", "EPSG:4258").transform(xyz[:, 0], xyz[:, 1])
    doc = encoded(doc, np.column_stack([lat, lon, xyz[:, 2]]), (1e-9, 1e-9, 0.001))
    doc["metadata"] = {"referenceSystem": f"https://www.opengis.net/def/crs/EPSG/0/{code}"}
    return write(tmp_path, doc, f"b2_{code}.city.json")


def test_a_tile_in_latlon_gives_the_same_verdicts_and_site_whatever_geographic_crs_it_is_tagged(tmp_path, capsys):
    verdicts, sites = {}, {}
    for code in (4258, 4171, 4674):
        path = _latlon_tile(tmp_path, code)
        rep = tmp_path / f"v{code}.json"
        rc, _, _ = run(["validate", path, "-q", "--report", str(rep)], capsys)
        r = json.loads(rep.read_text())
        verdicts[code] = (rc, [(f["id"], f["validity"], sorted(e["code"] for e in f["errors"]))
                               for f in r["features"]])
        out = tmp_path / f"o{code}"
        rc, _, err = run(["export", path, "-o", str(out), "--idf", "-q", "-j", "1"], capsys)
        idfs = sorted(out.glob("*.idf"))
        assert idfs, err
        sites[code] = [tuple(round(x, 4) for x in site_location(p)) for p in idfs]
    assert verdicts[4258][0] == 0 and all(v for _, v, _ in verdicts[4258][1])
    assert verdicts[4171] == verdicts[4258] == verdicts[4674]
    assert sites[4171] == sites[4258] == sites[4674]
    # the same place as the projected original (ETRS89 and WGS84 differ by < 1 m)
    xyz = decoded(json.loads(shared_path("3dbag", "3dbag_b2.city.json").read_text(encoding="utf-8")))
    c = (xyz.min(axis=0) + xyz.max(axis=0)) / 2
    lon, lat = Transformer.from_crs("EPSG:28992", "EPSG:4326", always_xy=True).transform(c[0], c[1])
    for la, lo in sites[4258]:
        assert distance_km(la, lo, lat, lon) < 0.2


# ----------------------------------------------------------------------------- linear units

def _feet_doc(h_ft: float = 342.8, crs: str = "https://www.opengis.net/def/crs/EPSG/0/2263") -> dict:
    """A 60 x 40 ft box ``h_ft`` tall in Manhattan, in EPSG:2263 (US survey feet)."""
    corners = np.array([[0, 0, 0], [60, 0, 0], [60, 40, 0], [0, 40, 0],
                        [0, 0, h_ft], [60, 0, h_ft], [60, 40, h_ft], [0, 40, h_ft]], float) + [987000.0, 212000.0, 0.0]
    doc = encoded(box_doc(), corners, (0.001, 0.001, 0.001))
    doc["metadata"] = {"referenceSystem": crs}
    return doc


def _metre_twin(h_ft: float = 342.8) -> dict:
    """The same box in metres (EPSG:32618, UTM 18N)."""
    corners = np.array([[0, 0, 0], [60, 0, 0], [60, 40, 0], [0, 40, 0],
                        [0, 0, h_ft], [60, 0, h_ft], [60, 40, h_ft], [0, 40, h_ft]], float) * FT + [585000.0, 4511000.0, 0]
    doc = encoded(box_doc(), corners, (0.0001, 0.0001, 0.0001))
    doc["metadata"] = {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/32618"}
    return doc


def test_feet_are_read_as_metres(tmp_path):
    _, feats = read(write(tmp_path, _feet_doc(), "ft.city.json"))
    ft = [f for f in feats][0]
    _, feats = read(write(tmp_path, _metre_twin(), "m.city.json"))
    m = [f for f in feats][0]
    height = float(np.ptp(ft.vertices[:, 2]))
    assert height == pytest.approx(342.8 * FT, abs=1e-3) and 104.4 < height < 104.6
    assert shell_volume(ft) == pytest.approx(shell_volume(m), rel=1e-5)  # the twin on a 0.1 mm grid
    assert shell_volume(ft) == pytest.approx(60 * 40 * 342.8 * FT ** 3, rel=1e-6)


def test_export_of_a_file_in_feet_works_in_metres_and_writes_feet_back(tmp_path, capsys):
    path = write(tmp_path, _feet_doc(h_ft=32.8), "ft.city.json")
    out = tmp_path / "o"
    rc, _, err = run(["export", path, "-o", str(out), "--cityjson", "--stl", "--idf", "-j", "1", "-q",
                      "--no-html"], capsys)
    assert rc == 0, err
    rep = json.loads((out / "report.json").read_text())
    assert rep["unit_conversion"]["unit"] == "US survey foot"
    assert rep["unit_conversion"]["to_metre"] == pytest.approx(FT)
    (b,) = rep["buildings"]
    assert b["repair"]["unit_conversion"]["to_metre"] == pytest.approx(FT)
    assert b["energy"]["volume"] == pytest.approx(60 * 40 * 32.8 * FT ** 3, rel=1e-3)
    # Site:Location from the feet, not from metres read as feet: Midtown Manhattan
    lat, lon = site_location(next(out.glob("*.idf")))
    assert distance_km(lat, lon, 40.7486, -73.9901) < 1.0
    doc = json.loads(next(out.glob("*.city.json")).read_text())
    z = decoded(doc)[:, 2]
    assert float(np.ptp(z)) == pytest.approx(32.8, abs=2e-3)   # the file's unit, as read
    import trimesh
    stl = trimesh.load(next(out.glob("*.stl")), force="mesh")
    assert float(np.ptp(stl.vertices[:, 2])) == pytest.approx(32.8 * FT, abs=2e-3)  # metres


def test_a_unit_that_is_not_a_length_is_refused(tmp_path, capsys):
    wkt = ('PROJCRS["odd",BASEGEOGCRS["WGS 84",DATUM["World Geodetic System 1984",ELLIPSOID["WGS 84",'
           '6378137,298.257223563]],UNIT["degree",0.0174532925199433]],CONVERSION["tm",METHOD["Transverse Mercator",'
           'ID["EPSG",9807]],PARAMETER["Latitude of natural origin",0],PARAMETER["Longitude of natural origin",9],'
           'PARAMETER["Scale factor at natural origin",0.9996],PARAMETER["False easting",500000],'
           'PARAMETER["False northing",0]],CS[Cartesian,2],AXIS["easting",east,ANGLEUNIT["degree",0.0174532925199433]],'
           'AXIS["northing",north,ANGLEUNIT["degree",0.0174532925199433]]]')
    info = crs_info(wkt)
    if info is None:
        pytest.skip("this PROJ does not read a projected CRS in degrees")
    assert info.unit_problem
    rc, _, err = run(["validate", write(tmp_path, box_doc()), "--crs", wkt, "-q"], capsys)
    assert rc == 2 and "not a length unit" in err


# ----------------------------------------------------------------------------- no CRS, --crs

def _without_crs_cityjson(tmp_path) -> str:
    doc = json.loads(shared_path("3dbag", "3dbag_b2.city.json").read_text(encoding="utf-8"))
    doc.get("metadata", {}).pop("referenceSystem", None)
    return write(tmp_path, doc, "nocrs.city.json")


def _without_crs_citygml(tmp_path) -> str:
    text = shared_path("citygml-real", "berlin", "3920_5820.gml").read_text(encoding="utf-8")
    p = tmp_path / "nocrs.gml"
    p.write_text(re.sub(r'\s+srsName="[^"]*"', "", text), encoding="utf-8")
    return str(p)


@pytest.mark.parametrize("make, crs, epsg", [(_without_crs_cityjson, "EPSG:7415", 28992),
                                              (_without_crs_citygml, "EPSG:25833", 25833)])
def test_a_file_without_crs_is_refused_for_idf_and_placed_by_crs(tmp_path, capsys, make, crs, epsg):
    path = make(tmp_path)
    epw = str(Path(__file__).resolve().parents[1] / "lod2energy" / "data" / "weather"
              / "NLD_OV_Heino.062780_TMYx.2007-2021.epw")
    for extra in ([], ["--weather", epw], ["--geojson"]):
        out = tmp_path / f"refused{len(extra)}"
        rc, _, err = run(["export", path, "-o", str(out), "--idf", "-q", *extra], capsys)
        assert rc == 2 and "no CRS" in err and "--crs" in err
        assert len([ln for ln in err.splitlines() if ln.strip()]) == 1
        assert not list(out.glob("**/*.idf"))
    # outputs that take metres: written, with one note
    out = tmp_path / "stl"
    rc, _, err = run(["export", path, "-o", str(out), "--stl", "-q", "-j", "1"], capsys)
    assert rc in (0, 1) and list(out.glob("*.stl"))
    assert err.count("taken as metres") == 1
    # with --crs: Site:Location within 1 km of the buildings
    out = tmp_path / "placed"
    rc, _, err = run(["export", path, "-o", str(out), "--idf", "-q", "-j", "1", "--crs", crs], capsys)
    idfs = sorted(out.glob("*.idf"))
    assert idfs, err
    _, feats = read(path)
    xyz = np.concatenate([f.vertices for f in feats if hasattr(f, "vertices") and len(f.vertices)])
    c = (xyz.min(axis=0) + xyz.max(axis=0)) / 2
    lon, lat = Transformer.from_crs(f"EPSG:{epsg}", "EPSG:4326", always_xy=True).transform(c[0], c[1])
    for p in idfs:
        assert distance_km(*site_location(p), lat, lon) < 1.0


def test_validate_and_repair_take_metres_and_say_so_once(tmp_path, capsys):
    doc = box_doc()
    del doc["metadata"]
    path = write(tmp_path, doc)
    rc, _, err = run(["validate", path, "-q"], capsys)
    assert rc == 0 and err.count("no CRS: coordinates are taken as metres") == 1
    rc, _, err = run(["repair", path, "-o", str(tmp_path / "r.city.json"), "-q"], capsys)
    assert rc == 0 and err.count("taken as metres") == 1
    rc, _, err = run(["validate", path, "-q", "--crs", "EPSG:7415"], capsys)
    assert rc == 0 and "metres" not in err


def test_crs_replaces_the_files_and_is_written_to_the_cityjson(tmp_path, capsys):
    path = write(tmp_path, box_doc())  # tagged EPSG:7415
    out = tmp_path / "o"
    rc, _, err = run(["export", path, "-o", str(out), "--cityjson", "-q", "-j", "1", "--crs", "EPSG:28992"], capsys)
    assert rc == 0, err
    doc = json.loads(next(out.glob("*.city.json")).read_text())
    assert doc["metadata"]["referenceSystem"] == "https://www.opengis.net/def/crs/EPSG/0/28992"


def test_an_unreadable_crs_option_is_a_usage_error(tmp_path, capsys):
    rc, _, err = run(["validate", write(tmp_path, box_doc()), "--crs", "EPSG:999999"], capsys)
    assert rc == 2 and "--crs" in err


def test_the_idf_writer_has_no_default_site(tmp_path):
    from lod2energy.exporters import energyplus
    from export_helpers import energy_ready
    from factories import box
    with pytest.raises(ParameterError, match="Site:Location"):
        energyplus.writer.write([energy_ready(box())], tmp_path)
    assert not list(tmp_path.glob("*.idf"))


# ----------------------------------------------------------------------------- --weather FOLDER

def _station(folder: Path, name: str, lat: float, lon: float) -> Path:
    """A copy of the shipped EPW whose LOCATION says station ``name`` at ``lat``, ``lon``."""
    lines = EPW.read_text(encoding="latin-1").splitlines(keepends=True)
    loc = lines[0].split(",")
    loc[1], loc[6], loc[7] = name, f"{lat:.4f}", f"{lon:.4f}"
    p = folder / f"{name}.epw"
    p.write_text(",".join(loc) + "".join(lines[1:]), encoding="latin-1")
    return p


EPW = Path(__file__).resolve().parents[1] / "lod2energy" / "data" / "weather" / "NLD_OV_Heino.062780_TMYx.2007-2021.epw"


def test_weather_folder_gives_each_building_the_nearest_station(tmp_path, capsys):
    folder = tmp_path / "epw"
    folder.mkdir()
    _station(folder, "Delft", 52.01, 4.36)      # the box of box_doc stands in Delft (RD 85000, 447000)
    _station(folder, "Madrid", 40.42, -3.70)
    (folder / "notes.txt").write_text("not a weather file")
    out = tmp_path / "o"
    rc, _, err = run(["export", write(tmp_path, box_doc()), "-o", str(out), "--idf", "-q", "-j", "1",
                      "--weather", str(folder), "--no-html"], capsys)
    assert rc == 0, err
    idf = json.loads((out / "report.json").read_text())["buildings"][0]["exports"]["idf"]
    assert idf["weather"]["station"].startswith("Delft") and idf["weather"]["distance_km"] < 5
    assert "warning: weather" not in err


def test_a_station_over_50_km_away_is_a_warning_on_the_console_and_in_report_html(tmp_path, capsys):
    folder = tmp_path / "epw"
    folder.mkdir()
    _station(folder, "Madrid", 40.42, -3.70)
    out = tmp_path / "o"
    rc, _, err = run(["export", write(tmp_path, box_doc()), "-o", str(out), "--idf", "-q", "-j", "1",
                      "--weather", str(folder)], capsys)
    assert rc == 0, err
    idf = json.loads((out / "report.json").read_text())["buildings"][0]["exports"]["idf"]
    assert idf["weather"]["distance_km"] > 1000
    assert err.count("warning: weather station Madrid") == 1 and "more than 50 km" in err
    html = (out / "report.html").read_text()
    assert 'id="weather-table"' in html and "more than 50 km" in html


def test_a_weather_folder_without_epw_is_refused(tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    rc, _, err = run(["export", write(tmp_path, box_doc()), "-o", str(tmp_path / "o"), "--idf", "-q",
                      "--weather", str(tmp_path / "empty")], capsys)
    assert rc == 2 and "no EPW" in err


def test_repair_of_a_file_in_feet_writes_feet_and_records_the_factor(tmp_path, capsys):
    path = write(tmp_path, _feet_doc(h_ft=32.8), "ft.city.json")
    rc, _, err = run(["repair", path, "-o", str(tmp_path / "r.city.json"), "--report", str(tmp_path / "r.json"),
                      "-q"], capsys)
    assert rc == 0, err
    assert err.count("US survey foot") >= 1
    z = decoded(json.loads((tmp_path / "r.city.json").read_text()))[:, 2]
    assert float(np.ptp(z)) == pytest.approx(32.8, abs=2e-3)
    assert json.loads((tmp_path / "r.json").read_text())["unit_conversion"]["to_metre"] == pytest.approx(FT)


def test_a_crs_pyproj_does_not_know_follows_the_no_crs_rule(tmp_path, capsys):
    doc = box_doc()
    doc["metadata"]["referenceSystem"] = "https://www.opengis.net/def/crs/EPSG/0/999999"
    path = write(tmp_path, doc)
    rc, _, err = run(["export", path, "-o", str(tmp_path / "o"), "--idf", "-q"], capsys)
    assert rc == 2 and "pyproj cannot read" in err and not (tmp_path / "o").exists()
    rc, _, err = run(["validate", path, "-q"], capsys)
    assert rc == 0 and err.count("taken as metres") == 1
    out = tmp_path / "placed"
    rc, _, err = run(["export", path, "-o", str(out), "--idf", "-q", "-j", "1", "--crs", "EPSG:7415",
                      "--no-html"], capsys)
    assert rc == 0, err
    lat, lon = site_location(next(out.glob("*.idf")))
    assert distance_km(lat, lon, 52.012, 4.359) < 1.0  # RD (85000, 447000): Delft
