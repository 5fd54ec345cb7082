"""Compliant vs written: the energy CityJSON holds every building its writer's check (the one
final check, :func:`lod2energy.repair.accept.export_problem`) accepts, each with its compliance
block; a building whose val3dity-valid geometry keeps a sliver face (1003, which the repair
could not collapse) is written with ``compliant: false`` and gets no IDF/STL. So the number of
buildings the file calls compliant is the number the pipeline calls compliant."""
from __future__ import annotations

import dataclasses
import json

from test_repair import building
from lod2energy.config import DEFAULT
from lod2energy.model import CityModel
from lod2energy.options import PrepareOptions
from lod2energy.pipeline import final_check, prepare_building
from lod2energy.validate.checks import validate_building

#: The user's sliver tolerance: faces up to 0.3 m2 are slivers (val3dity does not mind them).
TOL = dataclasses.replace(DEFAULT, sliver_area=0.3)


def chamfered(dx: float = 0.0, bid: str = "chamfered"):
    """A 10 x 8 x 6 m box whose top corner (10, 8, 6) is cut off by a 0.22 m2 triangle."""
    v = [(0, 0, 0), (10, 0, 0), (10, 8, 0), (0, 8, 0), (0, 0, 6), (10, 0, 6), (0, 8, 6),
         (9.5, 8, 6), (10, 7.5, 6), (10, 8, 5.5)]
    v = [(x + dx, y, z) for x, y, z in v]
    f = [[0, 3, 2, 1], [4, 5, 8, 7, 6], [0, 1, 5, 4], [1, 2, 9, 8, 5], [2, 3, 6, 7, 9], [3, 0, 4, 6], [7, 8, 9]]
    return building(v, f, semantics=[0, 1, 2, 2, 2, 2, 2], bid=bid)


def plain_box(dx: float = 30.0, bid: str = "box"):
    v = [(0, 0, 0), (10, 0, 0), (10, 8, 0), (0, 8, 0), (0, 0, 6), (10, 0, 6), (10, 8, 6), (0, 8, 6)]
    v = [(x + dx, y, z) for x, y, z in v]
    f = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return building(v, f, semantics=[0, 1, 2, 2, 2, 2], bid=bid)


def test_a_valid_building_with_a_kept_sliver_is_written_as_not_compliant(tmp_path):
    from lod2energy.exporters import cityjson
    opts = dataclasses.replace(PrepareOptions(), tol=TOL)
    prepared = [prepare_building(b, opts) for b in (chamfered(), plain_box())]
    (sl, sl_rec), (ok, ok_rec) = prepared
    assert validate_building(chamfered(), TOL) == []
    # the pipeline: not compliant, not geometry-ready (no IDF/STL) because of the sliver ...
    assert not sl_rec.energy.compliant and not sl_rec.energy.geometry_ready
    assert any("sliver" in r for r in sl_rec.energy.reasons)
    assert 1003 in sl_rec.repair.detail["defects_after"]
    assert ok_rec.energy.compliant
    # ... while its geometry passes the writers' check: written, with its status
    assert final_check(sl, validate_building(sl, TOL), None, TOL) is None
    res = cityjson.write(str(tmp_path / "e.city.json"), CityModel(), [sl, ok], tol=TOL)
    assert res.ok and not res.skipped and set(res.building_ids) == {"chamfered", "box"}
    doc = json.loads((tmp_path / "e.city.json").read_text())
    flags = {k: o["attributes"]["+energyCompliance"]["compliant"] for k, o in doc["CityObjects"].items()
             if not o.get("parents")}
    assert flags == {"chamfered": False, "box": True}
    assert sum(flags.values()) == sum(r.energy.compliant for _, r in prepared)
