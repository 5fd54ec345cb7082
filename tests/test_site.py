"""The real site (lod2energy.site): Site:Location from the buildings' own coordinates."""
import numpy as np
import pytest

from conftest import shared_path
from lod2energy import io
from lod2energy.model import Building
from lod2energy.site import (MAX_WEATHER_KM, SiteError, distance_km, read_weather_header, site_of, time_zone,
                             weather_distance)


def _rd_to_wgs84(x: float, y: float) -> tuple[float, float]:
    """RD (EPSG:28992) to WGS84 by the published approximation of Schreutelkamp & Strang van
    Hees (2001, "Benaderingsformules voor de transformatie tussen RD- en WGS84-kaartcoordinaten",
    about 1 m): independent of pyproj."""
    dx, dy = (x - 155000.0) * 1e-5, (y - 463000.0) * 1e-5
    k = {(0, 1): 3235.65389, (2, 0): -32.58297, (0, 2): -0.24750, (2, 1): -0.84978, (0, 3): -0.06550,
         (2, 2): -0.01709, (1, 0): -0.00738, (4, 0): 0.00530, (2, 3): -0.00039, (4, 1): 0.00033, (1, 1): -0.00012}
    l_ = {(1, 0): 5260.52916, (1, 1): 105.94684, (1, 2): 2.45656, (3, 0): -0.81885, (1, 3): 0.05594,
          (3, 1): -0.05607, (0, 1): 0.01199, (3, 2): -0.00256, (1, 4): 0.00128, (0, 2): 0.00022,
          (2, 0): -0.00022, (5, 0): 0.00026}
    lat = 52.15517440 + sum(c * dx ** p * dy ** q for (p, q), c in k.items()) / 3600
    lon = 5.38720621 + sum(c * dx ** p * dy ** q for (p, q), c in l_.items()) / 3600
    return lat, lon


def _buildings(*parts):
    model, feats = io.read(str(shared_path(*parts)))
    model, feats = io.to_local_frame(model, feats)
    return model, [b for b in feats if isinstance(b, Building) and len(b.vertices)]


def test_dutch_tile_site_within_1km_of_each_building():
    model, bs = _buildings("3dbag", "delft_subset.city.jsonl")
    for b in bs:
        s = site_of(b.vertices, model.crs)
        c = (b.vertices.min(axis=0) + b.vertices.max(axis=0)) / 2
        ref = _rd_to_wgs84(c[0], c[1])
        assert distance_km(s.latitude, s.longitude, *ref) < 0.01  # the same point, two methods
        assert s.time_zone == 1.0 and -10 < s.elevation < 50


@pytest.mark.parametrize("parts,landmark,tz", [
    # Alexanderplatz, Berlin (52.5219 N, 13.4132 E); Kamiyacho station, Minato-ku (35.6629 N, 139.7449 E)
    (("citygml-real", "berlin", "3920_5820.gml"), (52.5219, 13.4132), 1.0),
    (("japan-plateau", "japanese.city.json"), (35.6629, 139.7449), 9.0),
])
def test_berlin_and_japanese_site_within_1km(parts, landmark, tz):
    model, bs = _buildings(*parts)
    assert bs
    for b in bs:
        s = site_of(b.vertices, model.crs, getattr(model, "frame", None))
        assert distance_km(s.latitude, s.longitude, *landmark) < 1.0
        assert s.time_zone == tz


def test_geographic_frame_round_trip():
    from lod2energy.geodesy import LocalFrame
    f = LocalFrame(48.137, 11.575, 0.0)
    pts = f.to_local(np.array([[48.137, 11.575, 520.0], [48.138, 11.576, 530.0]]))
    s = site_of(pts, "EPSG:4979", f)
    assert abs(s.latitude - 48.1375) < 1e-4 and abs(s.longitude - 11.5755) < 1e-4
    assert s.elevation == pytest.approx(520.0, abs=0.1)


def test_no_crs_is_a_clear_error():
    with pytest.raises(SiteError):
        site_of(np.zeros((3, 3)), None)
    with pytest.raises(SiteError):
        site_of(np.full((3, 3), np.nan), "EPSG:28992")


def test_time_zone_fallback_from_longitude():
    assert time_zone(-74.0) == -5.0 and time_zone(139.7, "JP") == 9.0 and time_zone(4.4, "NL") == 1.0


def test_weather_header_and_distance():
    epw = shared_path("weather", "NLD_OV_Heino.062780_TMYx.2007-2021.epw")
    w = read_weather_header(epw)
    assert abs(w.latitude - 52.43) < 0.05 and len(w.ground_temperatures) == 12
    assert w.ground_depth is not None and min(w.ground_temperatures) < max(w.ground_temperatures)
    model, bs = _buildings("3dbag", "delft_subset.city.jsonl")
    d, warn = weather_distance(site_of(bs[0].vertices, model.crs), w)
    assert d > MAX_WEATHER_KM and "km from the site" in warn
    near = site_of(np.array([[212000.0, 490000.0, 2.0]]), "EPSG:28992")  # near Heino
    d2, warn2 = weather_distance(near, w)
    assert d2 < MAX_WEATHER_KM and warn2 is None
