"""CityJSON 1.0 / 1.1 / 2.0 and CityJSONSeq writing: documents, features and files from the model.

Whatever the reader kept and the model does not interpret (attributes, other properties,
metadata, extensions, appearance, templates) is written back; vertices go on the file's
grid (:mod:`lod2energy.io.cityjson_grid`).
"""
from __future__ import annotations

import json
import os
import shutil
import tempfile
from collections.abc import Mapping
from types import MappingProxyType
from typing import Any, Callable, Iterable, Sequence

import numpy as np

from lod2energy import safe_write
from lod2energy.crs import cityjson_reference_system
from lod2energy.io.cityjson_grid import GEOGRAPHIC_SCALE, default_transform, file_coordinates, quantise
from lod2energy.io.seen_ids import SeenIds
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
    t = type(x)
    if t in _LEAF:  # the common leaves, decided by their exact type (no ABC check)
        return x
    if t is dict or t is MappingProxyType or isinstance(x, Mapping):
        return {k: _plain(v) for k, v in x.items()}
    if t is list or t is tuple or isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.generic):
        return x.item()
    return x


#: Exact types :func:`_plain` returns as they are: none is a Mapping, list, tuple or numpy
#: scalar (``np.float64`` is a float subclass, not one of these types).
_LEAF = frozenset({str, int, float, bool, type(None)})


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


def transform_for(model: CityModel, buildings: Iterable[Building]) -> dict:
    """The file's ``transform``: the model's, else a 1 mm grid (geographic: ~0.1 mm) from the
    smallest coordinates of ``buildings`` (iterated once, one building at a time)."""
    if model.transform:
        return _plain(model.transform)
    lo = None
    for b in buildings:
        if len(b.vertices):
            m = file_coordinates(np.asarray(b.vertices), model.frame).min(axis=0)
            lo = m if lo is None else np.minimum(lo, m)
    t = default_transform(lo.reshape(1, 3) if lo is not None else np.zeros((0, 3)))
    if getattr(model.frame, "geographic", False):  # degrees: ~0.1 mm horizontally, 1 mm in height
        t["scale"] = list(GEOGRAPHIC_SCALE)
    return t


def _dumps(x: Any) -> str:
    return json.dumps(x, separators=(",", ":"), ensure_ascii=False)


def write_document(f, model: CityModel, buildings: Iterable[Building], version: str | None = None, *,
                   fix_object: Callable[[dict], None] | None = None,
                   fix_header: Callable[[dict], None] | None = None, scratch_dir: str | None = None) -> None:
    """Write a whole CityJSON document into the text file ``f``, one building at a time.

    The bytes are those of ``json.dump(document, f, separators=(",", ":"), ensure_ascii=False)``
    (after ``fix_header`` / ``fix_object`` on the document's head and on each CityObject), but
    no more than one building is in memory: the CityObjects go to ``f`` as they come, the
    vertices to an anonymous scratch file (in ``scratch_dir``), appended after them.

    Parameters
    ----------
    f : text file
    model : CityModel
        With a ``transform`` (else ``buildings`` are iterated once more, for the grid).
    buildings : iterable of Building
    fix_object, fix_header : callable(dict), optional
        Change a CityObject's JSON / the document's head (everything but CityObjects and
        vertices) in place before it is written.

    Raises
    ------
    ValueError
        Two CityObjects with one id (a document cannot hold both).
    """
    version = version or model.version
    if not model.transform and not isinstance(buildings, Sequence):
        buildings = list(buildings)
    head = _header_json(model, version)
    transform = transform_for(model, buildings)
    head["transform"] = transform
    if fix_header is not None:
        fix_header(head)
    f.write(_dumps(head)[:-1] + ',"CityObjects":{')
    seen = SeenIds()  # 16 bytes a slot per id written, not the id strings (a city's document)
    n = 0
    with tempfile.TemporaryFile("w+", encoding="utf-8", dir=scratch_dir) as vf:
        for b in buildings:
            q = quantise(b.vertices, transform, model.frame)
            for o in b.objects:
                if o.id in seen:
                    raise ValueError(f"two CityObjects with id {o.id!r}")
                co = cityobject_json(o, n, version)
                if fix_object is not None:
                    fix_object(co)
                f.write(("," if len(seen) else "") + _dumps(o.id) + ":" + _dumps(co))
                seen.add(o.id, 0)
            if q:
                vf.write(("," if n else "") + _dumps(q)[1:-1])
                n += len(q)
        f.write('},"vertices":[')
        vf.seek(0)
        shutil.copyfileobj(vf, f)
    f.write("]}")


def feature_document(b: Building, transform: Mapping, version: str, frame=None) -> dict:
    """One CityJSONFeature (dict) for ``b`` (vertices moved back out of ``frame``)."""
    return {"type": "CityJSONFeature", "id": b.id,
            "CityObjects": {o.id: cityobject_json(o, 0, version) for o in b.objects},
            "vertices": quantise(b.vertices, transform, frame)}


def write(path: str, model: CityModel, buildings: Iterable[Building], version: str | None = None, *,
          root: str | None = None, inputs: Iterable[str] | None = None) -> None:
    """Write CityJSON (``.json``) or CityJSONSeq (``.jsonl``), chosen by the suffix.

    Written through :func:`lod2energy.safe_write.atomic_write`: inside ``root`` (default:
    the target's folder), never over one of ``inputs`` (default: the model's source file)
    or a link, and atomically (a full disk leaves no half file under ``path``).
    """

    version = version or model.version
    root = os.path.dirname(os.path.abspath(path)) if root is None else root
    if inputs is None:
        inputs = [model.source] if model.source and os.path.exists(str(model.source)) else []
    with safe_write.atomic_write(path, "w", root=root, inputs=inputs) as f:
        if is_cityjsonseq(path):
            if not model.transform:  # the grid from every building first
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
            write_document(f, model, buildings, version, scratch_dir=os.path.dirname(os.path.abspath(path)))
