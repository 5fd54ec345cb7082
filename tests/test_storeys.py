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


# --- one plan: the report's storeys are the IDF's storey zones, or a recorded downgrade says why

def _storey_zones_of(path) -> int:
    """Storey zones of an IDF: the most zones cut from one Building/BuildingPart (the zone
    comments ``!- zone NAME: "ID_S2"`` / ``"ID_Attic"``; a zone named ``ID`` alone is one)."""
    import json
    import re
    from collections import Counter
    per: Counter = Counter()
    for line in open(path, encoding="ascii"):
        m = re.match(r'^!- zone [^:]*: (".*")\s*$', line)
        if m:
            oid = json.loads(m.group(1))
            per[re.sub(r"_(S\d+|Attic)$", "", oid)] += 1
    return max(per.values(), default=0)


def _written(b, tmp_path, **opts):
    """``(storeys fact, storey zones of its IDF, downgrade kinds)`` of ``b`` exported alone."""
    from export_helpers import energy_ready, shifted
    from lod2energy.exporters import energyplus
    ready = energy_ready(shifted(b))
    res = energyplus.writer.write([ready], tmp_path, energyplus.options.IdfOptions(**opts), crs="EPSG:28992")[0]
    assert res.ok, res.problems
    fact = ready.provenance["thermal"]["facts"]["storeys"]
    kinds = {d["kind"] for d in res.stats.get("downgrades", {}).get(ready.id, ())}
    assert res.stats["storeys"] == fact["value"]  # the IDF's record reads the same plan
    return fact, _storey_zones_of(res.path), kinds


def _agrees(fact, zones, kinds) -> bool:
    return zones == fact["value"] or bool(kinds & {"whole_zone", "storeys_merged"})


def test_three_storey_house_with_a_pitched_roof_is_three_storeys_and_an_attic(tmp_path):
    fact, zones, kinds = _written(gabled_house(eaves=8.4, ridge=12.0, id="house"), tmp_path)
    assert fact == {"value": 4, "source": "geometry"} and zones == 4 and not kinds


def test_set_back_tower_report_storeys_are_its_zones(tmp_path):
    from factories import stepped_tower
    t = stepped_tower(sizes=(40.0, 28.0, 16.0), tops=(30.0, 75.0, 120.0))
    fact, zones, kinds = _written(t, tmp_path)
    assert fact["source"] == "geometry" and fact["value"] >= 38
    assert _agrees(fact, zones, kinds)
    a_fact, a_zones, a_kinds = _written(_with_attrs(t, storeysAboveGround=40), tmp_path / "attr")
    assert a_fact["value"] == 40 and a_fact["source"] == "attribute"
    assert _agrees(a_fact, a_zones, a_kinds)


def test_9999_storeys_is_unknown_and_the_geometry_decides(tmp_path):
    b = _with_attrs(box(dz=8.4), storeysAboveGround=9999)
    fact, zones, kinds = _written(b, tmp_path)
    assert fact == {"value": 3, "source": "geometry"} and zones == 3 and not kinds


def test_a_dropped_storey_cut_is_a_recorded_downgrade(tmp_path, monkeypatch):
    """A cut that cannot be made leaves a zone over two storeys: ``storeys_merged`` says so."""
    from lod2energy.energy.zones import cut
    real = cut.storey_cuts

    def first_cut_dropped(*a, **k):
        cuts, attic = real(*a, **k)
        return cuts[1:], attic
    monkeypatch.setattr(cut, "storey_cuts", first_cut_dropped)
    fact, zones, kinds = _written(box(dz=8.4), tmp_path)
    assert fact["value"] == 3 and zones == 2 and kinds == {"storeys_merged"}


def test_building_storeys_are_its_tallest_part(tmp_path):
    from export_helpers import parts_building
    from factories import box_polygons
    b = parts_building([box_polygons(30, 30, 5.6), box_polygons(10, 10, 14.0, (30, 0, 0))])
    s = storeys(b)
    assert s.count == 5 and sorted(p.count for p in s.parts) == [2, 5]
    fact, zones, kinds = _written(b, tmp_path, wwr=0.0)
    assert fact["value"] == 5 and zones == 5 and not kinds


def test_typology_reads_the_plan():
    from lod2energy.thermal.facts import Fact
    from lod2energy.thermal.typology import classify
    b = gabled_house(eaves=8.4, ridge=12.0)  # 3 storeys and an attic: 4, as report.json says
    t = classify(b, ground_area=80.0, z_extent=12.0, storeys=Fact(4, "geometry"))
    assert t.storeys == 4 and t.building_type == "multi-family" and t.sources["storeys"] == "geometry"
