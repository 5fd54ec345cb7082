"""Tiny CityJSON documents built in code (shared by the I/O, graph and CLI tests)."""
from __future__ import annotations

import copy
import json

BOX_VERTICES = [[0, 0, 0], [10, 0, 0], [10, 8, 0], [0, 8, 0],
                [0, 0, 6], [10, 0, 6], [10, 8, 6], [0, 8, 6]]
# outward (counter-clockwise seen from outside)
BOX_FACES = [[[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]]]
BOX_SEMANTICS = {"surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface"}, {"type": "WallSurface"}],
                 "values": [[0, 1, 2, 2, 2, 2]]}


def box_doc(version: str = "2.0", faces=None, vertices=None, semantics=True, lod="2.2",
            gtype="Solid", extra_objects=None) -> dict:
    faces = copy.deepcopy(BOX_FACES if faces is None else faces)
    geom = {"type": gtype, "lod": lod}
    if gtype == "Solid":
        geom["boundaries"] = [faces]
    else:
        geom["boundaries"] = faces
    if semantics and gtype == "Solid" and faces == BOX_FACES:
        geom["semantics"] = copy.deepcopy(BOX_SEMANTICS)
    doc = {"type": "CityJSON", "version": version,
           "transform": {"scale": [0.001, 0.001, 0.001], "translate": [85000.0, 447000.0, 0.0]},
           "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
           "CityObjects": {"b1": {"type": "Building", "attributes": {"yearOfConstruction": 1975, "note": "x"},
                                  "geometry": [geom]}},
           "vertices": [[int(x * 1000), int(y * 1000), int(z * 1000)] for x, y, z in (vertices or BOX_VERTICES)]}
    if extra_objects:
        doc["CityObjects"].update(extra_objects)
    return doc


def parts_doc() -> dict:
    """A Building without geometry whose two BuildingParts are the same box."""
    part = box_doc()["CityObjects"]["b1"]
    doc = box_doc()
    doc["CityObjects"]["b1"]["geometry"] = []
    doc["CityObjects"]["b1"]["children"] = ["p1", "p2"]
    doc["CityObjects"]["p1"] = {**part, "type": "BuildingPart", "parents": ["b1"]}
    doc["CityObjects"]["p2"] = {**part, "type": "BuildingPart", "parents": ["b1"]}
    return doc


def write(tmp_path, doc, name="b.city.json", text=None) -> str:
    p = tmp_path / name
    p.write_text(text if text is not None else json.dumps(doc), encoding="utf-8")
    return str(p)


def to_seq(doc: dict) -> str:
    """CityJSONSeq text of a CityJSON document with one feature per first-level object."""
    header = {k: v for k, v in doc.items() if k not in ("CityObjects", "vertices")}
    header["CityObjects"] = {}
    header["vertices"] = []
    lines = [json.dumps(header)]
    for oid, co in doc["CityObjects"].items():
        if co.get("parents"):
            continue
        lines.append(json.dumps({"type": "CityJSONFeature", "id": oid, "CityObjects": {oid: co},
                                 "vertices": doc["vertices"]}))
    return "\n".join(lines) + "\n"
