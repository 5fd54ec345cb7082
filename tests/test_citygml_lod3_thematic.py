"""LoD3 CityGML whose ``lod3Solid`` is unusable (an xlink to a degenerate polygon) while its
thematic LoD3 surfaces carry the real shell: the thematic surfaces are used, as for LoD2
(issue 38 item 9)."""
from __future__ import annotations

import json

import numpy as np

from lod2energy.cli import main
from lod2energy.io import read
from lod2energy.model import Building

# a 10 x 8 x 6 m box in EPSG:25833 (Berlin), faces counter-clockwise seen from outside
CORNERS = np.array([[0, 0, 0], [10, 0, 0], [10, 8, 0], [0, 8, 0],
                    [0, 0, 6], [10, 0, 6], [10, 8, 6], [0, 8, 6]], float) + [390000.0, 5819000.0, 34.0]
FACES = {"ground": ("GroundSurface", [0, 3, 2, 1]), "roof": ("RoofSurface", [4, 5, 6, 7]),
         "south": ("WallSurface", [0, 1, 5, 4]), "east": ("WallSurface", [1, 2, 6, 5]),
         "north": ("WallSurface", [2, 3, 7, 6]), "west": ("WallSurface", [3, 0, 4, 7])}
#: three collinear points along the south wall's foot: a polygon with no area
DEGENERATE = "390000 5819000 34 390010 5819000 34 390005 5819000 34 390000 5819000 34"


def _polygon(pid: str, text: str) -> str:
    return (f'<gml:Polygon gml:id="{pid}"><gml:exterior><gml:LinearRing><gml:posList srsDimension="3">{text}'
            "</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon>")


def _ring(corners) -> str:
    return " ".join(f"{c:.3f}" for i in list(corners) + [corners[0]] for c in CORNERS[i])


def lod3_tile(solid_refs: list[str]) -> str:
    """A CityGML 2.0 tile of one LoD3 building: an ``lod3Solid`` of xlinks to ``solid_refs`` and
    six thematic surfaces with ``lod3MultiSurface`` (the south wall also holds the degenerate polygon)."""
    members = "".join(f'<gml:surfaceMember xlink:href="#{r}"/>' for r in solid_refs)
    body = (f"<bldg:lod3Solid><gml:Solid><gml:exterior><gml:CompositeSurface>{members}</gml:CompositeSurface>"
            "</gml:exterior></gml:Solid></bldg:lod3Solid>")
    for name, (kind, corners) in FACES.items():
        polys = _polygon(f"p_{name}", _ring(corners)) + (_polygon("degen", DEGENERATE) if name == "south" else "")
        body += (f'<bldg:boundedBy><bldg:{kind} gml:id="ts_{name}"><bldg:lod3MultiSurface><gml:MultiSurface>'
                 + "".join(f"<gml:surfaceMember>{p}</gml:surfaceMember>" for p in polys.split("</gml:Polygon>")[:-1]
                           for p in [p + "</gml:Polygon>"])
                 + f"</gml:MultiSurface></bldg:lod3MultiSurface></bldg:{kind}></bldg:boundedBy>")
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<CityModel xmlns="http://www.opengis.net/citygml/2.0" '
            'xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:gml="http://www.opengis.net/gml" '
            'xmlns:xlink="http://www.w3.org/1999/xlink"><gml:boundedBy><gml:Envelope '
            'srsName="urn:ogc:def:crs:EPSG::25833" srsDimension="3"><gml:lowerCorner>0 0 0</gml:lowerCorner>'
            '<gml:upperCorner>1 1 1</gml:upperCorner></gml:Envelope></gml:boundedBy>'
            f'<cityObjectMember><bldg:Building gml:id="B1">{body}</bldg:Building></cityObjectMember></CityModel>\n')


def _one(path) -> Building:
    _, feats = read(str(path))
    (b,) = [f for f in feats if isinstance(f, Building)]
    return b


def test_a_solid_of_one_degenerate_polygon_gives_way_to_the_thematic_lod3_surfaces(tmp_path):
    p = tmp_path / "lod3.gml"
    p.write_text(lod3_tile(["degen"]), encoding="utf-8")
    b = _one(p)
    (g,) = b.root.geometries
    assert (g.type, g.lod, g.n_surfaces) == ("MultiSurface", "3", 6)   # the degenerate polygon left out
    assert sorted(g.semantic_type(s) for *_, s in g.iter_surfaces()) == \
        ["GroundSurface", "RoofSurface"] + ["WallSurface"] * 4
    (why,) = b.provenance["geometry_replaced"]
    assert "lod3 Solid unusable" in why and "thematic LoD3" in why


def test_a_usable_lod3_solid_is_kept(tmp_path):
    p = tmp_path / "lod3.gml"
    p.write_text(lod3_tile([f"p_{n}" for n in FACES]), encoding="utf-8")
    b = _one(p)
    assert [(g.type, g.lod, g.n_surfaces) for g in b.root.geometries][0] == ("Solid", "3", 6)
    assert "geometry_replaced" not in b.provenance


def test_the_building_is_exported_from_its_thematic_surfaces(tmp_path, capsys):
    p = tmp_path / "lod3.gml"
    p.write_text(lod3_tile(["degen"]), encoding="utf-8")
    out = tmp_path / "o"
    rc = main(["export", str(p), "-o", str(out), "--idf", "--cityjson", "-q", "-j", "1", "--no-html"])
    err = capsys.readouterr().err
    (r,) = json.loads((out / "report.json").read_text())["buildings"]
    assert rc == 0, err
    assert r["energy"]["compliant"] and r["energy"]["volume"] == 480.0
    assert r["exports"]["idf"]["ok"] and r["exports"]["cityjson"]["ok"]
    assert "lod3 Solid unusable" in r["repair"]["geometry_replaced"][0]
