"""CRS names: EPSG codes from CityJSON, CityGML and AdV spellings."""
from __future__ import annotations

import doctest

import pytest

import lod2energy.crs
from lod2energy.crs import cityjson_reference_system, epsg_code


@pytest.mark.parametrize("name, code", [
    ("https://www.opengis.net/def/crs/EPSG/0/7415", 7415),
    ("http://www.opengis.net/def/crs/EPSG/0/28992", 28992),
    ("urn:ogc:def:crs:EPSG::25833", 25833),
    ("urn:ogc:def:crs:EPSG:6.12:31468", 31468),
    ("EPSG:3879", 3879),
    ("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837", 25832),
    ("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH*GCG2016", 25832),
    ("urn:adv:crs:ETRS89_UTM33*DE_DHHN92_NH", 25833),
    ("urn:adv:crs:DE_DHDN_3GK4*DE_DHN92_NH", 31468),
    ("urn:adv:crs:DE_DHDN_3GK3", 31467),
    (7415, 7415), ("4979", 4979),
    ("urn:adv:crs:Unknown", None), ("local grid", None), ("", None), (None, None),
])
def test_epsg_code(name, code):
    assert epsg_code(name) == code


def test_spelling_per_cityjson_version():
    adv = "urn:adv:crs:DE_DHDN_3GK4*DE_DHN92_NH"
    assert cityjson_reference_system(adv, "2.0") == "https://www.opengis.net/def/crs/EPSG/0/31468"
    assert cityjson_reference_system(adv, "1.1") == "https://www.opengis.net/def/crs/EPSG/0/31468"
    assert cityjson_reference_system(adv, "1.0") == "urn:ogc:def:crs:EPSG::31468"
    assert cityjson_reference_system("local grid") == "local grid"   # kept when not understood
    assert cityjson_reference_system(None) is None


def test_docstring_examples_run():
    assert doctest.testmod(lod2energy.crs).failed == 0
