"""Reader for tu3djson (TU Delft's minimal 3D JSON: features with their own vertices).

A tu3djson document is ``{"type": "tu3djson", "features": [{"geometry": {"type",
"boundaries", "vertices"}}, ...]}``. Each feature becomes a :class:`Building` of type
"GenericCityObject" whose id is its position ("0", "1", ...), as val3dity names them.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any, Iterator

import numpy as np

from lod2energy.errors import InputError
from lod2energy.io.cityjson import _Collector, _parse_geometry, read_json
from lod2energy.model import Building, CityModel, CityObject, FeatureError


def read_document(doc: Mapping[str, Any], path: str) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Features of a parsed tu3djson document."""
    feats = doc.get("features")
    if not isinstance(feats, list):
        return None, iter([FeatureError(None, 901, f"{path}: tu3djson without a 'features' array")])
    model = CityModel(version="tu3djson", source=path, format="tu3djson")

    def gen():
        for i, f in enumerate(feats):
            fid = str(i)
            try:
                yield _feature(fid, f)
            except InputError as e:
                yield FeatureError(fid, e.code, str(e), "GenericCityObject")
    return model, gen()


def _feature(fid: str, f: Any) -> Building:

    if not isinstance(f, Mapping) or not isinstance(f.get("geometry"), Mapping):
        raise InputError(f"feature {fid}: no 'geometry' object")
    g = dict(f["geometry"])
    try:
        verts = np.asarray(g.pop("vertices", []), dtype=np.float64).reshape(-1, 3)
    except (ValueError, TypeError):
        raise InputError(f"feature {fid}: 'vertices' must be an array of [x, y, z] numbers") from None
    if verts.size and not np.isfinite(verts).all():
        raise InputError(f"feature {fid}: non-finite coordinates")
    g.setdefault("lod", "0")
    geom = _parse_geometry(g, _Collector(len(verts)), f"coid={fid}|geom=0")
    geom = replace(geom, lod=None) if "lod" not in f["geometry"] else geom
    obj = CityObject(fid, "GenericCityObject", (geom,))
    return Building(fid, "GenericCityObject", verts, (obj,), {"source_format": "tu3djson"})


def read(path: str, **_) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Read a tu3djson file."""
    try:
        doc = read_json(path)
    except InputError as e:
        return None, iter([FeatureError(None, e.code, str(e))])
    if not isinstance(doc, Mapping) or doc.get("type") != "tu3djson":
        return None, iter([FeatureError(None, 904, f"{path}: not a tu3djson document")])
    return read_document(doc, path)
