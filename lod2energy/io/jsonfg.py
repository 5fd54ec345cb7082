"""Reader for OGC JSON-FG documents with 3D solids (``place`` of type Polyhedron/MultiPolyhedron).

Each Feature becomes a :class:`Building` of type "GenericCityObject" (id: the feature's
``id``, else its position). Rings are GeoJSON-style closed rings; the repeated last point
is dropped. A ring that is not closed is reported as 103 (RING_NOT_CLOSED) and kept as
given. A Feature without a 3D ``place`` (plain GeoJSON, 2D geometry) cannot be validated:
it is reported as 904 (FORMAT_NOT_SUPPORTED), as val3dity does.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Iterator

import numpy as np

from lod2energy.io.cityjson import read_json
from lod2energy.errors import InputError
from lod2energy.model import Building, CityModel, CityObject, FeatureError, Geometry, Shell, Solid, Surface

PLACE_TYPES = {"Polyhedron": "Solid", "MultiPolyhedron": "MultiSolid"}


class _Builder:
    def __init__(self, fid: str):
        self.fid = fid
        self.points: list[list[float]] = []
        self.errors: list[tuple[int, str, str]] = []

    def ring(self, r: Any, where: str) -> list[int]:
        if not isinstance(r, list) or not all(isinstance(p, list) and len(p) >= 3 for p in r):
            raise InputError(f"coid={self.fid}|{where}: a ring must be an array of [x, y, z] positions")
        try:
            pts = [[float(p[0]), float(p[1]), float(p[2])] for p in r]
        except (TypeError, ValueError):
            raise InputError(f"coid={self.fid}|{where}: non-numeric coordinates") from None
        if len(pts) >= 2 and pts[0] == pts[-1]:
            pts = pts[:-1]
        else:
            self.errors.append((103, f"coid={self.fid}|{where}", "First-last must be the same for JSON-FG rings"))
        start = len(self.points)
        self.points.extend(pts)
        return list(range(start, start + len(pts)))

    def shell(self, sh: Any, where: str) -> Shell:
        if not isinstance(sh, list):
            raise InputError(f"coid={self.fid}|{where}: a shell must be an array of polygons")
        faces = []
        for fi, poly in enumerate(sh):
            if not isinstance(poly, list):
                raise InputError(f"coid={self.fid}|{where}|face={fi}: a polygon must be an array of rings")
            faces.append(Surface.from_lists([self.ring(r, f"{where}|face={fi}") for r in poly]))
        return Shell(tuple(faces))

    def solid(self, so: Any, where: str) -> Solid:
        if not isinstance(so, list):
            raise InputError(f"coid={self.fid}|{where}: a polyhedron must be an array of shells")
        return Solid(tuple(self.shell(sh, f"{where}|shell={hi}") for hi, sh in enumerate(so)))


def _feature(f: Mapping[str, Any], counter: int) -> Building:
    fid = f.get("id", counter)
    fid = str(fid)
    place = f.get("place")
    ptype = place.get("type") if isinstance(place, Mapping) else None
    if ptype not in PLACE_TYPES:
        raise _NoSolid(fid)
    b = _Builder(fid)
    coords = place.get("coordinates")
    if not isinstance(coords, list):
        raise InputError(f"coid={fid}: 'place' has no 'coordinates' array")
    if ptype == "Polyhedron":
        geom = Geometry("Solid", None, (b.solid(coords, "geom=0"),))
    else:
        geom = Geometry("MultiSolid", None, tuple(b.solid(so, f"geom=0|solid={si}") for si, so in enumerate(coords)))
    verts = np.asarray(b.points, dtype=np.float64).reshape(-1, 3)
    if verts.size and not np.isfinite(verts).all():
        raise InputError(f"coid={fid}: non-finite coordinates")
    if len(verts):  # JSON-FG repeats coordinates: share identical vertices, as CityJSON does
        verts, inverse = np.unique(verts, axis=0, return_inverse=True)
        lut = np.asarray(inverse, dtype=np.intp).reshape(-1)
        geom = Geometry(geom.type, None, tuple(
            Solid(tuple(Shell(tuple(Surface(tuple(lut[r] for r in s.rings)) for s in sh.surfaces))
                        for sh in so.shells)) for so in geom.solids))
    prov = {"source_format": "JSON-FG"}
    if b.errors:
        prov["input_errors"] = tuple(b.errors)
    obj = CityObject(fid, "GenericCityObject", (geom,))
    return Building(fid, "GenericCityObject", verts, (obj,), prov)


class _NoSolid(Exception):
    def __init__(self, fid: str):
        self.fid = fid


def read_document(doc: Mapping[str, Any], path: str) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Features of a parsed JSON-FG document (a Feature or a FeatureCollection)."""
    if doc.get("type") == "Feature":
        feats = [doc]
    else:
        feats = doc.get("features")
        if not isinstance(feats, list):
            return None, iter([FeatureError(None, 904, f"{path}: 'type' is 'FeatureCollection', not 'CityJSON', "
                                                       "and it has no 'features' array")])
    model = CityModel(version="JSON-FG", source=path, format="JSON-FG")

    def gen():
        for i, f in enumerate(feats):
            if not isinstance(f, Mapping):
                yield FeatureError(str(i), 901, f"{path}: feature {i} is not an object")
                continue
            try:
                yield _feature(f, i)
            except _NoSolid as e:
                yield FeatureError(e.fid, 904, f"{path}: feature {e.fid} has no 3D 'place' "
                                              "(Polyhedron/MultiPolyhedron): nothing to validate")
            except InputError as e:
                yield FeatureError(str(f.get("id", i)), e.code, str(e))
    return model, gen()


def read(path: str, **_) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Read a JSON-FG file."""
    try:
        doc = read_json(path)
    except InputError as e:
        return None, iter([FeatureError(None, e.code, str(e))])
    if not isinstance(doc, Mapping) or doc.get("type") not in ("Feature", "FeatureCollection"):
        return None, iter([FeatureError(None, 904, f"{path}: not a JSON-FG Feature/FeatureCollection")])
    return read_document(doc, path)
