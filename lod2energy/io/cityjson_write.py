"""CityJSON 1.0 / 1.1 / 2.0 and CityJSONSeq writing: documents, features and files from the model.

Whatever the reader kept and the model does not interpret (attributes, other properties,
metadata, extensions, appearance, templates) is written back; vertices go on the file's
grid (:mod:`lod2energy.io.cityjson_grid`).
"""
from __future__ import annotations

import json
import os
from typing import Any, Iterable, Mapping

import numpy as np

from lod2energy.crs import cityjson_reference_system
from lod2energy.io.cityjson_grid import GEOGRAPHIC_SCALE, default_transform, file_coordinates
from lod2energy.io.cityjson_grid import quantise as _quantise
from lod2energy.model import SURFACE_TYPES, Building, CityModel, CityObject, Geometry, Shell, Solid, Surface


def is_cityjsonseq(path: str) -> bool:
    p = path.lower()
    return p.endswith(".jsonl") or p.endswith(".cjseq") or p.endswith(".city.jsonl")




def _lod_json(lod: str | None, version: str):
    if version != "1.0" or lod is None:
        return lod
    return float(lod) if "." in lod else int(lod)  # CityJSON 1.0 has numeric LoDs


def _geometry_json(g: Geometry, offset: int, version: str = "2.0") -> dict:
    if g.raw is not None:
        d = _plain(g.raw)
        d["boundaries"] = _offset_nested(d["boundaries"], offset)
        if "lod" in d and d["lod"] is not None:
            d["lod"] = _lod_json(str(d["lod"]), version)
        return d

    def surf(s: Surface):
        return [(r + offset).tolist() for r in s.rings]

    out: dict[str, Any] = {"type": g.type, "lod": _lod_json(g.lod, version)}
    if g.type in SURFACE_TYPES:
        shell = g.solids[0].shells[0] if g.solids else Shell(())
        out["boundaries"] = [surf(s) for s in shell.surfaces]
        values: Any = [s.semantic for s in shell.surfaces]
    elif g.type == "Solid":
        so = g.solids[0] if g.solids else Solid(())
        out["boundaries"] = [[surf(s) for s in sh.surfaces] for sh in so.shells]
        values = [[s.semantic for s in sh.surfaces] for sh in so.shells]
    else:
        out["boundaries"] = [[[surf(s) for s in sh.surfaces] for sh in so.shells] for so in g.solids]
        values = [[[s.semantic for s in sh.surfaces] for sh in so.shells] for so in g.solids]
    if g.semantic_surfaces:
        out["semantics"] = {"surfaces": _plain(g.semantic_surfaces), "values": values}
    out.update(_plain(g.extra))
    return out


def _offset_nested(x: Any, offset: int) -> Any:
    if isinstance(x, list):
        return [_offset_nested(i, offset) for i in x]
    return int(x) + offset


def _plain(x: Any) -> Any:
    """Deep-convert mapping proxies (and tuples) into JSON-serialisable objects."""
    if isinstance(x, Mapping):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.generic):
        return x.item()
    return x


def cityobject_json(o: CityObject, offset: int, version: str) -> dict:
    d: dict[str, Any] = {"type": o.type}
    if o.attributes:
        d["attributes"] = _plain(o.attributes)
    d.update(_plain(o.extra))
    if o.parents:
        d["parents"] = list(o.parents)
    if o.children:
        d["children"] = list(o.children)
    geoms = [_geometry_json(g, offset, version) for g in o.geometries]
    if geoms or version != "1.0":
        d["geometry"] = geoms
    else:
        d["geometry"] = []
    return d


def _header_json(model: CityModel, version: str) -> dict:
    d: dict[str, Any] = {"type": "CityJSON", "version": version}
    d.update(_plain(model.extra))
    if model.metadata:
        d["metadata"] = _plain(model.metadata)
        if d["metadata"].get("referenceSystem"):  # the spelling the written version's schema wants
            d["metadata"]["referenceSystem"] = cityjson_reference_system(d["metadata"]["referenceSystem"], version)
    if model.extensions:
        d["extensions"] = _plain(model.extensions)
    if model.appearance:
        d["appearance"] = _plain(model.appearance)
    if model.geometry_templates:
        d["geometry-templates"] = _plain(model.geometry_templates)
    return d


def transform_for(model: CityModel, buildings: list[Building]) -> dict:
    if model.transform:
        return _plain(model.transform)
    allv = [b.vertices for b in buildings if len(b.vertices)]
    t = default_transform(file_coordinates(np.vstack(allv), model.frame) if allv else np.zeros((0, 3)))
    if model.frame is not None:  # degrees: ~0.1 mm horizontally, 1 mm in height
        t["scale"] = list(GEOGRAPHIC_SCALE)
    return t


def to_document(model: CityModel, buildings: Iterable[Building], version: str | None = None) -> dict:
    """A whole CityJSON document (dict) from the model and its features."""
    version = version or model.version
    buildings = list(buildings)
    doc = _header_json(model, version)
    transform = transform_for(model, buildings)
    doc["transform"] = transform
    cos: dict[str, Any] = {}
    verts: list = []
    for b in buildings:
        off = len(verts)
        verts.extend(_quantise(b.vertices, transform, model.frame))
        for o in b.objects:
            cos[o.id] = cityobject_json(o, off, version)
    doc["CityObjects"] = cos
    doc["vertices"] = verts
    return doc


def feature_document(b: Building, transform: Mapping, version: str, frame=None) -> dict:
    """One CityJSONFeature (dict) for ``b`` (vertices moved back out of ``frame``)."""
    return {"type": "CityJSONFeature", "id": b.id,
            "CityObjects": {o.id: cityobject_json(o, 0, version) for o in b.objects},
            "vertices": _quantise(b.vertices, transform, frame)}


def write(path: str, model: CityModel, buildings: Iterable[Building], version: str | None = None, *,
          root: str | None = None, inputs: Iterable[str] | None = None) -> None:
    """Write CityJSON (``.json``) or CityJSONSeq (``.jsonl``), chosen by the suffix.

    Written through :func:`lod2energy.safe_write.atomic_write`: inside ``root`` (default:
    the target's folder), never over one of ``inputs`` (default: the model's source file)
    or a link, and atomically (a full disk leaves no half file under ``path``).
    """
    from lod2energy import safe_write

    version = version or model.version
    root = os.path.dirname(os.path.abspath(path)) if root is None else root
    if inputs is None:
        inputs = [model.source] if model.source and os.path.exists(str(model.source)) else []
    with safe_write.atomic_write(path, "w", root=root, inputs=inputs) as f:
        if is_cityjsonseq(path):
            buildings = list(buildings)
            header = _header_json(model, version)
            transform = transform_for(model, buildings)
            header["transform"] = transform
            header["CityObjects"] = {}
            header["vertices"] = []
            f.write(json.dumps(header, separators=(",", ":"), ensure_ascii=False) + "\n")
            for b in buildings:
                f.write(json.dumps(feature_document(b, transform, version, model.frame), separators=(",", ":"),
                                   ensure_ascii=False) + "\n")
        else:
            doc = to_document(model, buildings, version)
            json.dump(doc, f, separators=(",", ":"), ensure_ascii=False)


#: The former private name.
_transform_for = transform_for
