"""The self-check of a written CityJSON document (``.json``), one building at a time.

The same checks as on the whole document (:func:`lod2energy.exporters.cityjson.self_check`):
the official schema of the file's version, the Energy extension's attributes, then every
energy building re-read (as :func:`lod2energy.io.cityjson.read` reads it) and checked with
val3dity's checks and the envelope checks. The file is read twice with a
:class:`~lod2energy.io.json_stream.Scanner` instead of being parsed whole:

1. the head (every member but ``CityObjects`` and ``vertices``), the links between the
   CityObjects (type, parents, children) and the vertices (a float array, 24 bytes a vertex);
2. each CityObject again: the schema and the extension on batches of CityObjects (a
   document with the file's head and those objects: the schema constrains every CityObject
   on its own, so this is the verdict on the whole document), and each first-level object
   with its descendants built into a Building, checked, and dropped.
"""
from __future__ import annotations

import sys
from typing import Any, Iterator, Mapping

import numpy as np

from lod2energy.errors import Lod2EnergyError
from lod2energy.io import cityjson as cjio
from lod2energy.io import shape
from lod2energy.io.json_stream import Scanner, StreamError
from lod2energy.model import Building, FeatureError

from .cityjson_schema import (
    EXTENSION_NAME, MAX_PROBLEMS, _schema_errors, _schema_valid_fast, _validators, _worth_compiling,
    extension_problems, extension_schema, load_extension_beside,
)

#: CityObjects validated together (one small document each).
BATCH = 64
#: Vertices converted to an array at a time.
VERTEX_CHUNK = 1 << 16


_ABSENT = object()


class _Link(Mapping):
    """What the grouping of CityObjects reads of one (``type``, ``parents``, ``children``), in
    ~60 bytes instead of a dict's ~200, the ids and types interned so that a child's
    ``parents`` and its parent's key share one string (13,504 buildings: ~40,000 of these)."""

    __slots__ = ("type", "parents", "children")
    _KEYS = ("type", "parents", "children")

    def __init__(self, type_=_ABSENT, parents=_ABSENT, children=_ABSENT):
        self.type, self.parents, self.children = type_, parents, children

    @classmethod
    def of(cls, co: Mapping) -> "_Link":
        def keep(k):
            x = co.get(k, _ABSENT)
            if k == "type" and type(x) is str:
                return sys.intern(x)
            if k != "type" and type(x) is list and all(type(i) is str for i in x):
                return [sys.intern(i) for i in x]
            return x
        return cls(*(keep(k) for k in cls._KEYS))

    def __getitem__(self, key):
        x = getattr(self, key, _ABSENT) if key in self._KEYS else _ABSENT
        if x is _ABSENT:
            raise KeyError(key)
        return x

    def __iter__(self):
        return (k for k in self._KEYS if getattr(self, k) is not _ABSENT)

    def __len__(self) -> int:
        return sum(1 for _ in self)


class _Pass1:
    """What the first reading keeps: the head, the CityObjects' links, the vertices."""

    def __init__(self):
        self.head: dict = {}
        self.links: dict[str, dict] = {}
        self.duplicates: list[str] = []
        self.raw: list[np.ndarray] = []
        self.bad_vertices: list[list] = []  # chunks that are not triples of integers (for the schema)
        self.vertices_member: Any = None  # the 'vertices' value when it is not an array

    def vertices(self, transform) -> np.ndarray:
        """All vertices, as the reader computes them (``v * scale + translate``); called once
        (the integer chunks are dropped as they are copied)."""
        if self.vertices_member is not None:
            return cjio._transform_vertices(self.vertices_member, transform, "document")
        if not self.raw:
            return np.zeros((0, 3))
        # filled chunk by chunk, each integer chunk dropped once copied: one float array at the peak
        v = np.empty((sum(len(a) for a in self.raw), 3), dtype=np.float64)
        o = 0
        for i, a in enumerate(self.raw):
            v[o:o + len(a)] = a
            o += len(a)
            self.raw[i] = None
        self.raw = []
        if transform:
            scale = np.asarray(transform["scale"], dtype=np.float64).reshape(3)
            translate = np.asarray(transform["translate"], dtype=np.float64).reshape(3)
            with np.errstate(over="ignore", invalid="ignore"):
                v *= scale  # the same two roundings as v * scale + translate
                v += translate
        return v


def _triples(chunk: list) -> bool:
    return all(type(r) is list and len(r) == 3 and type(r[0]) is int and type(r[1]) is int
               and type(r[2]) is int for r in chunk)


def _add_vertices(p: _Pass1, chunk: list) -> None:
    ok = _triples(chunk)
    try:
        a = np.array(chunk, dtype=np.int64) if ok else None
    except (OverflowError, ValueError, TypeError):
        a, ok = None, False
    if not ok:
        p.bad_vertices.append(chunk)
        a = cjio._vertices_row_by_row(chunk, "document")
    p.raw.append(a)


def _first_pass(path: str) -> _Pass1:
    p = _Pass1()
    with open(path, encoding="utf-8") as f:
        sc = Scanner(f)
        for key in sc.members():
            if key == "CityObjects" and sc.peek() == "{" and "CityObjects" not in p.head:
                p.head["CityObjects"] = {}
                for oid in sc.members():
                    co = sc.value()
                    if oid in p.links:
                        p.duplicates.append(oid)
                        continue
                    p.links[sys.intern(oid)] = _Link.of(co) if isinstance(co, Mapping) else co
            elif key == "vertices" and sc.peek() == "[" and "vertices" not in p.head:
                p.head["vertices"] = []
                chunk: list = []
                for _ in sc.items():
                    chunk.append(sc.value())
                    if len(chunk) >= VERTEX_CHUNK:
                        _add_vertices(p, chunk)
                        chunk = []
                if chunk:
                    _add_vertices(p, chunk)
            else:
                p.head[key] = sc.value()
                if key == "vertices":
                    p.vertices_member = p.head[key]
        sc.end()
    return p


def _cityobjects(path: str) -> Iterator[tuple[str, Any, bool]]:
    """``(id, CityObject, first)`` of the file's CityObjects member, in file order.

    Reading stops after that member: :func:`_first_pass` has read the whole file already (its
    JSON is sound), and what follows in an exported file is the vertices, which as Python lists
    would cost ~150 bytes each (13,504 buildings: ~60 MB held at the end of the check)."""
    seen: set[str] = set()
    with open(path, encoding="utf-8") as f:
        sc = Scanner(f)
        for key in sc.members():
            if key == "CityObjects" and sc.peek() == "{":
                for oid in sc.members():
                    co = sc.value()
                    yield oid, co, oid not in seen
                    seen.add(oid)
                return
            sc.value()


def _feature(root: str, ids: list[str], cos: Mapping, verts: np.ndarray, transform, templates,
             path: str) -> Building | FeatureError:
    """One group read as :func:`lod2energy.io.cityjson._features_of_document` reads it."""
    rtype = cos[root].get("type", "") if isinstance(cos[root], Mapping) else ""
    rtype = rtype if isinstance(rtype, str) else ""
    bad = next(((oid, p) for oid in ids if (p := shape.cityobject_problem(oid, cos[oid]))), None)
    if bad is not None:
        item: Building | FeatureError = FeatureError(root, 901, f"coid={bad[0]}: {bad[1]}", rtype)
    else:
        try:
            item = cjio.build_feature(root, ids, cos, verts)
        except Lod2EnergyError as e:
            item = FeatureError(root, getattr(e, "code", 901), str(e), rtype)
        except (TypeError, ValueError, KeyError, IndexError, OverflowError, RecursionError) as e:
            item = FeatureError(root, 901, f"coid={root}: unusable value ({type(e).__name__}: "
                                           f"{str(e).splitlines()[0][:120] if str(e) else ''})", rtype)
    if isinstance(item, FeatureError):
        if not item.message.isprintable() or len(item.message) > shape.MAX_MESSAGE:
            item = FeatureError(item.id, item.code, shape.one_line(item.message), item.type)
        return item
    if isinstance(transform, Mapping):
        item = item.with_provenance(file_transform={"scale": [float(x) for x in transform["scale"]],
                                                    "translate": [float(x) for x in transform["translate"]]})
    if isinstance(templates, Mapping) and any(g.type == "GeometryInstance" for o in item.objects for g in o.geometries):
        item = item.with_provenance(geometry_templates=templates)
    return item


def self_check_document(path: str, extension: Mapping | None = None, tol=None) -> list[str]:
    """Problems of an exported CityJSON document (empty: the file is OK), read one
    CityObject at a time; see :func:`lod2energy.exporters.cityjson.self_check`."""
    from lod2energy.config import DEFAULT
    from lod2energy.exporters.cityjson import TOLERATED_CODES, envelope_problems
    from lod2energy.io import to_local_frame
    from lod2energy.validate.checks import validate_building
    from lod2energy.validate.codes import name

    tol = tol or DEFAULT
    try:
        p = _first_pass(path)
    except (OSError, UnicodeDecodeError) as e:
        return [f"cannot read {path}: {e}"]
    except StreamError as e:
        return [f"{path} is not valid JSON: {e.msg} at line {e.lineno}"]
    head = p.head
    try:
        version = cjio.normalise_version(head.get("version"))
    except Lod2EnergyError as e:
        return [f"{path}: {e}"]
    schemas = _validators(version)
    skeleton = {**head}
    if "CityObjects" in skeleton:
        skeleton["CityObjects"] = {}
    problems: list[str] = []
    fast = _worth_compiling(version, len(p.links) + len(p.duplicates))
    if not (fast and _schema_valid_fast(version, skeleton)):
        problems += _schema_errors(schemas, skeleton, "document")
    for chunk in p.bad_vertices:
        problems += _schema_errors(schemas, {**skeleton, "vertices": chunk}, "document (a block of vertices)")
    if extension is None:
        extension = load_extension_beside(path, head)
        if extension is None and EXTENSION_NAME in (head.get("extensions") or {}):
            extension = extension_schema(version)
    referenced = extension is not None and EXTENSION_NAME in (head.get("extensions") or {})
    if extension is not None and not referenced:  # the one line saying so
        problems += extension_problems(skeleton, extension, "document")

    def batch_problems(batch: dict) -> list[str]:
        doc = {**skeleton, "CityObjects": batch}
        out = [] if (fast and _schema_valid_fast(version, doc)) else _schema_errors(schemas, doc, "document")
        return out + (extension_problems(doc, extension, "document") if referenced else [])

    # the reader's groups: each first-level object with its descendants
    links, dups = p.links, p.duplicates
    groups = cjio._feature_ids(links)
    group_of = {oid: gi for gi, g in enumerate(groups) for oid in g}
    left = [len(g) for g in groups]
    model = None
    if head.get("type") != "CityJSON":
        problems.append(f"re-read: {path}: 'type' is {str(head.get('type'))[:40]!r}, not 'CityJSON'")
    else:
        try:
            model = cjio._header_of(head, path, "CityJSON")
        except Lod2EnergyError as e:
            problems.append(f"re-read: {e}")
    verts = p.vertices(model.transform) if model is not None else None
    del p
    templates = head.get("geometry-templates")

    def features() -> Iterator[Building | FeatureError]:
        for oid in dict.fromkeys(dups):
            yield FeatureError(oid, 901, f"coid={oid}: {path} has more than one CityObject with this id; the first "
                                         f"is read, the others are not")
        pending: dict[str, Any] = {}
        batch: dict = {}
        for oid, co, first in _cityobjects(path):
            if first:
                batch[oid] = co
            else:  # the schema sees every one
                problems.extend(batch_problems({oid: co}))
            if len(batch) >= BATCH:
                problems.extend(batch_problems(batch))
                batch = {}
            gi = group_of.get(oid) if first else None
            if gi is None or model is None:
                continue
            pending[oid] = co
            left[gi] -= 1
            if left[gi] == 0:
                g = groups[gi]
                yield _feature(g[0], g, {k: pending.pop(k) for k in g}, verts, model.transform, templates, path)
        if batch:
            problems.extend(batch_problems(batch))
        if model is not None:
            yield from cjio._orphan_errors(links, groups, path)

    feats: Iterator = features()
    if model is not None:
        model, feats = to_local_frame(model, feats)  # a geographic file is checked in metres
    geometry: list[str] = []
    for f in feats:
        if len(geometry) > MAX_PROBLEMS:
            continue  # the schema of every CityObject is still checked
        if not isinstance(f, Building):
            geometry.append(f"re-read: {f.message}")
            continue
        if not any(k.startswith("+energy") for k in f.root.attributes):
            continue
        for d in validate_building(f, tol):
            if d.code in TOLERATED_CODES:
                continue
            geometry.append(f"{d.location}: {d.code} {name(d.code)} {d.info}".rstrip())
        geometry += envelope_problems(f)
    if problems:  # the schema's and the extension's problems come first, as on the whole document
        return problems[:MAX_PROBLEMS]
    return geometry[:MAX_PROBLEMS]
