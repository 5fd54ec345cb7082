"""Storeys from attributes and from the geometry (lod2energy.thermal.storeys)."""
from dataclasses import replace

import pytest

from factories import box, gabled_house
from conftest import shared_path
from lod2energy.thermal.storeys import ATTIC_MIN_HEIGHT, roof_levels, storeys, storeys_above_eave


def _with_attrs(b, **attrs):
    root = replace(b.root, attributes={**b.root.attributes, **attrs})
    return replace(b, objects=(root,) + b.objects[1:])


def test_flat_box_storeys_from_height():
    s = storeys(box(dz=8.4))
    assert s.source == "geometry" and s.count == 3 and not s.attic
    assert s.storey_height == pytest.approx(2.8)


def test_office_storey_height_gives_fewer_storeys():
    assert storeys(box(dz=10.5), use="office").count == 3
    assert storeys(box(dz=10.5), use="residential").count == 4


def test_gabled_house_levels_and_attic():
    lv = roof_levels(gabled_house(eaves=5.6, ridge=9.0))
    assert lv.ground == pytest.approx(0) and lv.eave == pytest.approx(5.6) and lv.ridge == pytest.approx(9.0)
    assert lv.pitched
    s = storeys(gabled_house(eaves=5.6, ridge=9.0))
    assert s.attic and s.count == 3 and s.below_eave == 2
    low = storeys(gabled_house(eaves=5.6, ridge=5.6 + ATTIC_MIN_HEIGHT - 0.5))
    assert not low.attic and low.count == 2


@pytest.mark.parametrize("key,value,n", [("storeysAboveGround", 5, 5), ("b3_bouwlagen", "4", 4),
                                         ("building:levels", 2.0, 2)])
def test_attribute_wins(key, value, n):
    s = storeys(_with_attrs(box(dz=3.2 * n), **{key: value}))
    assert s.count == n and s.source == "attribute" and s.key == key
    assert s.storey_height == pytest.approx(3.2)


def test_storey_heights_attribute():
    s = storeys(_with_attrs(box(dz=7.0), storeyHeightsAboveGround="3.5 3.5"))
    assert s.count == 2 and s.heights == (3.5, 3.5) and s.source == "attribute"
    assert s.key == "storeyHeightsAboveGround"


@pytest.mark.parametrize("value,why", [(9999, "9999"), (5, "1.2 m"), (1, "12.0 m")])
def test_sentinel_or_implausible_storey_height_is_unknown(value, why):
    dz = 6.0 if value != 1 else 12.0
    warnings = []
    s = storeys(_with_attrs(box(dz=dz), storeysAboveGround=value), warnings=warnings)
    assert s.source == "geometry" and s.count == round(dz / 2.8)
    assert len(warnings) == 1 and warnings[0][0] == "storeys" and why in warnings[0][1]


def test_next_attribute_after_a_sentinel():
    s = storeys(_with_attrs(box(dz=6.0), storeysAboveGround=9999, b3_bouwlagen=2))
    assert s.count == 2 and s.key == "b3_bouwlagen"


@pytest.mark.parametrize("bad", [None, "", "abc", 0, -2, True, float("nan"), 1e6])
def test_bad_attribute_falls_back_to_geometry(bad):
    s = storeys(_with_attrs(box(dz=5.6), storeysAboveGround=bad))
    assert s.source == "geometry" and s.count == 2


def test_attribute_ignored_on_request():
    s = storeys(_with_attrs(box(dz=5.6), storeysAboveGround=7), use_attributes=False)
    assert s.source == "geometry" and s.count == 2


def test_3dbag_geometry_estimate_within_one_storey():
    from lod2energy import io
    from lod2energy.model import Building

    _, feats = io.read(str(shared_path("3dbag", "delft_subset.city.jsonl")))
    n = close = 0
    for b in feats:
        if isinstance(b, Building) and b.root.attributes.get("b3_bouwlagen") is not None:
            n += 1
            close += abs(storeys(b, use_attributes=False).count - int(b.root.attributes["b3_bouwlagen"])) <= 1
    assert n >= 3 and close / n >= 0.8


def test_set_back_tower_counts_the_storeys_above_its_podium():
    from factories import stepped_tower
    t = stepped_tower(sizes=(40.0, 28.0, 16.0), tops=(30.0, 75.0, 120.0))
    assert roof_levels(t).eave == pytest.approx(30.0)  # the podium's roof: the median roof level by area
    s = storeys(t, use="office")
    assert s.count == round(30 / 3.5) + round(90 / 3.5)
    a = storeys(_with_attrs(t, storeysAboveGround=40))
    assert a.count == 40 and a.storey_height == pytest.approx(3.0)


def test_storeys_above_eave():
    assert storeys_above_eave(2.5, 2.8, False) == 0 and storeys_above_eave(3.0, 2.8, True) == 1
    assert storeys_above_eave(6.0, 2.8, False) == 2 and storeys_above_eave(8.4, 2.8, True) == 1  # an attic, however high
