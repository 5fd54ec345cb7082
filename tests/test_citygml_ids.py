"""CityGML gml:id uniqueness: a repeated id is a per-building error, the rest of the file is read."""
from __future__ import annotations

from test_citygml import box_body, building, city_model, polygon, read_all, thematic, write
from lod2energy.model import Building, FeatureError
from lod2energy.validate.checks import validate_building


def test_second_feature_with_an_id_already_read_is_an_error_and_the_rest_goes_on(tmp_path):
    text = city_model(building("A", box_body("p")), building("A", box_body("q")), building("C", box_body("r")))
    _, feats = read_all(write(tmp_path, text))
    first, second, third = feats
    assert isinstance(first, Building) and first.id == "A" and validate_building(first) == []
    assert isinstance(second, FeatureError)
    assert second.code == 901 and second.id == "A (duplicate)" and second.type == "Building"
    assert "coid=A" in second.message and "already read" in second.message
    assert isinstance(third, Building) and third.id == "C" and validate_building(third) == []


def test_a_building_part_reusing_an_earlier_building_id_is_an_error(tmp_path):
    part = building("A", box_body("q"), tag="BuildingPart")
    second = building("B", f"<bldg:consistsOfBuildingPart>{part}</bldg:consistsOfBuildingPart>")
    _, feats = read_all(write(tmp_path, city_model(building("A", box_body("p")), second)))
    assert isinstance(feats[0], Building)
    assert isinstance(feats[1], FeatureError) and feats[1].id == "B (duplicate)" and "'A'" in feats[1].message


def test_two_polygons_with_one_id_in_a_building_is_an_error_for_that_building(tmp_path):
    # the roof's polygon carries the id of the ground's: the Solid's xlink to it is ambiguous
    body = box_body("p").replace('gml:id="p_roof"', 'gml:id="p_ground"')
    text = city_model(building("BAD", body), building("OK", box_body("q")))
    _, feats = read_all(write(tmp_path, text))
    bad, ok = feats
    assert isinstance(bad, FeatureError) and (bad.id, bad.code) == ("BAD", 901)
    assert "'p_ground'" in bad.message and "2 surfaces" in bad.message
    assert isinstance(ok, Building) and validate_building(ok) == []


def test_distinct_polygon_ids_are_not_an_error(tmp_path):
    extra = thematic("roof", [polygon("p_extra", [4, 5, 6, 7])])
    _, feats = read_all(write(tmp_path, city_model(building("A", box_body("p") + extra))))
    assert isinstance(feats[0], Building)
