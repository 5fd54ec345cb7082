"""CityGML 3.0 reading: real 3.0 files read, repaired and exported as their 2.0 counterparts."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from lod2energy.cli import main
from lod2energy.io import read
from lod2energy.model import Building

HERE = Path(__file__).parent / "data"
#: (CityGML 2.0 file, its CityGML 3.0 conversion): tum-gis/citygml2-to-citygml3 (tests/data/README.md)
PAIRS = [("CityGML_v2.gml", "CityGML_v3.gml"),                     # lod2Solid + boundary surfaces
         ("Berlin_Moabit_1Bldg_v2.gml", "Berlin_Moabit_1Bldg_v3.gml")]  # thematic surfaces only


def buildings(path: Path) -> list[Building]:
    model, feats = read(str(path))
    assert model is not None
    out = list(feats)
    assert all(isinstance(b, Building) for b in out), out
    return out


def faces(b: Building) -> list[tuple[str, str | None, tuple]]:
    """Per polygon: geometry type, semantic type and its sorted rounded coordinates."""
    out = []
    for o in b.objects:
        for g in o.geometries:
            for _si, _hi, _fi, s in g.iter_surfaces():
                pts = tuple(sorted(tuple(np.round(b.vertices[i], 3)) for r in s.rings for i in r))
                out.append((g.type, g.lod, g.semantic_type(s), pts))
    return sorted(out)


@pytest.mark.parametrize("v2,v3", PAIRS)
def test_citygml3_reads_as_its_citygml2_counterpart(v2, v3):
    (a,), (b,) = buildings(HERE / v2), buildings(HERE / v3)
    assert a.id == b.id
    assert [(o.id, o.type) for o in a.objects] == [(o.id, o.type) for o in b.objects]
    fa, fb = faces(a), faces(b)
    assert len(fa) >= 6 and fa == fb
    assert {f[2] for f in fb} >= {"RoofSurface", "WallSurface", "GroundSurface"}
    for k in ("measuredHeight", "function", "roofType"):
        assert a.root.attributes.get(k) == b.root.attributes.get(k)


@pytest.mark.parametrize("v2,v3", PAIRS)
def test_citygml3_is_repaired_and_exported_as_its_citygml2_counterpart(tmp_path, v2, v3, capsys):
    results = []
    for name in (v2, v3):
        out = tmp_path / name
        rc = main(["export", str(HERE / name), "-o", str(out), "--idf", "--stl", "--cityjson", "-q"])
        capsys.readouterr()
        assert rc == 0
        (rep,) = json.loads((out / "report.json").read_text())["buildings"]
        results.append(rep)
    a, b = results
    assert a["exports"]["idf"]["ok"] and b["exports"]["idf"]["ok"]
    for key in ("stage", "iou"):
        assert a.get("repair", {}).get(key) == b.get("repair", {}).get(key)
    ta, tb = a["thermal"], b["thermal"]
    assert ta["country"] == tb["country"] == "DE"
    assert ta["typology"] == tb["typology"] and ta["construction_period"] == tb["construction_period"]
    for k in ("A_env", "volume", "UA"):
        assert ta[k] == pytest.approx(tb[k], rel=1e-9), k


def test_citygml3_openings_are_window_and_door_semantics(tmp_path):
    """A 3.0 wall with a ``con:fillingSurface`` WindowSurface: the window polygon is read as a
    "Window" semantic surface of the same geometry (as 2.0's ``bldg:opening/bldg:Window``)."""
    wall = "0 0 0 10 0 0 10 0 6 0 0 6 0 0 0"
    hole = "2 0 2 2 0 4 4 0 4 4 0 2 2 0 2"
    text = f"""<?xml version="1.0" encoding="UTF-8"?>
<CityModel xmlns="http://www.opengis.net/citygml/3.0" xmlns:con="http://www.opengis.net/citygml/construction/3.0"
 xmlns:bldg="http://www.opengis.net/citygml/building/3.0" xmlns:gml="http://www.opengis.net/gml/3.2">
<cityObjectMember><bldg:Building gml:id="B">
<boundary><con:WallSurface gml:id="w"><lod3MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon>
<gml:exterior><gml:LinearRing><gml:posList>{wall}</gml:posList></gml:LinearRing></gml:exterior>
<gml:interior><gml:LinearRing><gml:posList>{hole}</gml:posList></gml:LinearRing></gml:interior>
</gml:Polygon></gml:surfaceMember></gml:MultiSurface></lod3MultiSurface>
<con:fillingSurface><con:WindowSurface gml:id="win"><lod3MultiSurface><gml:MultiSurface><gml:surfaceMember>
<gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>{hole}</gml:posList></gml:LinearRing></gml:exterior>
</gml:Polygon></gml:surfaceMember></gml:MultiSurface></lod3MultiSurface></con:WindowSurface></con:fillingSurface>
</con:WallSurface></boundary>
<bldg:buildingPart><bldg:BuildingPart gml:id="P"/></bldg:buildingPart>
</bldg:Building></cityObjectMember></CityModel>"""
    p = tmp_path / "w3.gml"
    p.write_text(text)
    (b,) = buildings(p)
    assert [(o.id, o.type) for o in b.objects] == [("B", "Building"), ("P", "BuildingPart")]
    (g,) = b.root.geometries
    assert g.lod == "3" and sorted(g.semantic_type(s) for *_, s in g.iter_surfaces()) == ["WallSurface", "Window"]
