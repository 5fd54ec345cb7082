"""The self-check of a written CityJSON file (:func:`self_check`); a document (``.json``) one building at a time.

A CityJSONSeq (``.jsonl``) is read whole; a document gets the same checks
(:func:`self_check_document`): the official schema of the file's version, the Energy extension's attributes, then every
energy building re-read (as :func:`lod2energy.io.cityjson.read` reads it) and checked with
val3dity's checks and the envelope checks. The file is read twice with a
:class:`~lod2energy.io.json_stream.Scanner` instead of being parsed whole, and what the check
holds does not grow with the file:

1. the head (every member but ``CityObjects`` and ``vertices``), a hash of each CityObject id
   (8 bytes) and the vertices, written to an unnamed scratch file beside the document (in
   memory only when no scratch file can be written);
2. each CityObject again: the schema and the extension on batches of CityObjects (a
   document with the file's head and those objects: the schema constrains every CityObject
   on its own, so this is the verdict on the whole document), and each run of consecutive
   CityObjects whose links stay inside it (as this package writes a building and its parts)
   grouped as the reader groups the whole document, each first-level object with its
   descendants built into a Building (its vertices read from the scratch file), checked,
   and dropped.

A document whose links leave such a run (a part written far from its parent, a link back to
an earlier object, an id used twice) is checked from every CityObject's links, read in a
third reading: the same verdict, with memory growing with the file.
"""
from __future__ import annotations

import array
import json
import errno
import os
import sys
import tempfile
from collections.abc import Mapping
from typing import Any, Iterator

import numpy as np

from lod2energy.config import DEFAULT
from lod2energy.errors import Lod2EnergyError
from lod2energy.exporters.cityjson.schema import (
    EXTENSION_NAME, MAX_PROBLEMS, _schema_errors, _schema_valid_fast, _validators,
    extension_problems, extension_schema, load_extension_beside,
)
from lod2energy.io import cityjson as cjio
from lod2energy.io import to_local_frame
from lod2energy.io.json_stream import Scanner, StreamError
from lod2energy.model import Building, FeatureError
from lod2energy.validate.closed import TOLERATED_CODES, envelope_problems
from lod2energy.validate.checks import validate_building
from lod2energy.validate.codes import name

#: CityObjects validated together (one small document each).
BATCH = 64
#: Surfaces (top-level boundary items) a batch may hold before it is validated: a large object
#: (a terrain TIN of 10,000s of triangles) is checked with the few before it, not with 63 more.
BATCH_SURFACES = 4096
#: Vertices converted to an array (and read back) at a time.
VERTEX_CHUNK = 1 << 16
#: CityObjects one run of linked objects may hold before every link of the document is read.
MAX_BLOCK = 4096


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


def _write_all(fd: int, data: bytes) -> None:
    """``data`` written whole to ``fd`` (unbuffered: a full disk raises here, not at a flush)."""
    view = memoryview(data)
    while view:
        n = os.write(fd, view)
        if n <= 0:
            raise OSError(errno.ENOSPC, "nothing written")
        view = view[n:]


class _Vertices:
    """The document's vertices, kept in an unnamed scratch file beside the document (24 bytes a
    vertex on disk, none in memory) and gathered a feature at a time, as ``v * scale +
    translate`` with the same two roundings the reader makes on the whole array.

    Behaves as the vertex array :func:`lod2energy.io.cityjson.build_feature` indexes: ``len``
    and ``[used]`` (sorted, unique row indices). Without a scratch file (it cannot be made, or
    the disk fills) the vertices stay in memory, as one array.
    """

    def __init__(self, scratch_dir: str | None):
        self.n = 0
        self._mem: list[np.ndarray] | None = None
        self._array: np.ndarray | None = None
        self._scale = self._translate = None
        try:
            self._f = tempfile.TemporaryFile(dir=scratch_dir, buffering=0)
        except OSError:
            self._f, self._mem = None, []

    def append(self, a: np.ndarray) -> None:
        a = np.ascontiguousarray(a, dtype=np.float64).reshape(-1, 3)  # the cast an assignment makes
        if self._f is not None:
            try:
                _write_all(self._f.fileno(), a.tobytes())
            except OSError:  # a full disk: what is written comes back to memory
                self._mem = [self._read(0, self.n)]
                self._f.close()
                self._f = None
        if self._f is None:
            self._mem.append(a)
        self.n += len(a)

    def finish(self, transform) -> "_Vertices":
        """Set the document's ``transform`` (None: the values are the coordinates)."""
        if transform:
            self._scale = np.asarray(transform["scale"], dtype=np.float64).reshape(3)
            self._translate = np.asarray(transform["translate"], dtype=np.float64).reshape(3)
        if self._f is None:
            v = np.concatenate(self._mem) if self._mem else np.zeros((0, 3))
            self._mem = None
            self._array = self._transformed(v)
        return self

    def _transformed(self, v: np.ndarray) -> np.ndarray:
        if self._scale is not None:
            with np.errstate(over="ignore", invalid="ignore"):
                v *= self._scale  # the same two roundings as v * scale + translate
                v += self._translate
        return v

    def _read(self, start: int, stop: int) -> np.ndarray:
        data = os.pread(self._f.fileno(), (stop - start) * 24, start * 24)
        return np.frombuffer(data, dtype=np.float64).reshape(-1, 3).copy()

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, used: np.ndarray) -> np.ndarray:
        if self._array is not None:
            return self._array[used]
        used = np.asarray(used, dtype=np.intp)
        out = np.empty((len(used), 3), dtype=np.float64)
        i = 0
        last = int(used[-1]) + 1 if len(used) else 0
        while i < len(used):  # a feature's rows are nearly always one short run: one read
            lo = int(used[i])
            hi = min(lo + VERTEX_CHUNK, last)  # no further than the feature's last row
            j = int(np.searchsorted(used, hi, side="left"))
            out[i:j] = self._read(lo, hi)[used[i:j] - lo]
            i = j
        return self._transformed(out)

    def close(self) -> None:
        if self._f is not None:
            self._f.close()
            self._f = None


class _Pass1:
    """What the first reading keeps: the head, a hash of each CityObject id (8 bytes), the
    vertices (in a scratch file)."""

    def __init__(self, scratch_dir: str | None = None):
        self.head: dict = {}
        self.ids: np.ndarray = np.zeros(0, dtype=np.int64)  # sorted hashes of the ids
        self.repeated = False  # two ids may be equal (their hashes are): the links decide
        self.verts = _Vertices(scratch_dir)
        self.bad_vertices: list[list] = []  # chunks that are not triples of integers (for the schema)
        self.vertices_member: Any = None  # the 'vertices' value when it is not an array

    def vertices(self, transform):
        """The vertex array :func:`lod2energy.io.cityjson.build_feature` indexes."""
        if self.vertices_member is not None:
            self.verts.close()
            return cjio._transform_vertices(self.vertices_member, transform, "document")
        return self.verts.finish(transform)

    def may_exist(self, oid: str) -> bool:
        """False only for an id the document surely has no CityObject of."""
        h = hash(oid)
        k = int(np.searchsorted(self.ids, h))
        return k < len(self.ids) and int(self.ids[k]) == h


def _surfaces(co: Any) -> int:
    """Top-level boundary items of a CityObject's geometries (its weight in a schema batch;
    1 for whatever is not shaped as a CityObject)."""
    try:
        return max(1, sum(len(g["boundaries"]) for g in co.get("geometry") or ()
                          if isinstance(g, Mapping) and isinstance(g.get("boundaries"), list)))
    except (AttributeError, TypeError):
        return 1


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
    p.verts.append(a)


def _first_pass(path: str, scratch_dir: str | None = None) -> _Pass1:
    p = _Pass1(scratch_dir)
    hashes = array.array("q")
    with open(path, encoding="utf-8") as f:
        sc = Scanner(f)
        for key in sc.members():
            if key == "CityObjects" and sc.peek() == "{" and "CityObjects" not in p.head:
                p.head["CityObjects"] = {}
                for oid in sc.members():
                    sc.value()
                    hashes.append(hash(oid))
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
    p.ids = np.unique(np.frombuffer(hashes, dtype=np.int64)) if len(hashes) else p.ids
    p.repeated = len(p.ids) < len(hashes)
    return p


def _links_pass(path: str) -> tuple[dict[str, _Link], list[str]]:
    """Every CityObject's links (and the repeated ids), for a document whose groups are not
    local (see ``local_features`` in :func:`_check`): the reader's grouping needs them all at once."""
    links: dict[str, Any] = {}
    duplicates: list[str] = []
    for oid, co, first in _cityobjects(path):
        if not first:
            duplicates.append(oid)
            continue
        links[sys.intern(oid)] = _Link.of(co) if isinstance(co, Mapping) else co
    return links, duplicates


class _NotLocal(Exception):
    """The document's groups are not runs of consecutive CityObjects: read every link."""


def _cityobjects(path: str, repeated: bool = True) -> Iterator[tuple[str, Any, bool]]:
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
                    if not repeated:  # no id twice (the first reading's hashes say so): no set of them
                        yield oid, co, True
                        continue
                    yield oid, co, oid not in seen
                    seen.add(oid)
                return
            sc.value()


def self_check_document(path: str, extension: Mapping | None = None, tol=None) -> list[str]:
    """Problems of an exported CityJSON document (empty: the file is OK), read one
    CityObject at a time; see :func:`lod2energy.exporters.cityjson.writer.self_check`."""
    try:
        p = _first_pass(path, os.path.dirname(os.path.abspath(path)))
    except (OSError, UnicodeDecodeError) as e:
        return [f"cannot read {path}: {e}"]
    except StreamError as e:
        return [f"{path} is not valid JSON: {e.msg} at line {e.lineno}"]
    try:
        return _check(path, p, extension, tol)
    finally:
        p.verts.close()


def _check(path: str, p: _Pass1, extension: Mapping | None, tol) -> list[str]:
    tol = tol or DEFAULT
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
    if not _schema_valid_fast(version, skeleton):
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
        out = [] if _schema_valid_fast(version, doc) else _schema_errors(schemas, doc, "document")
        return out + (extension_problems(doc, extension, "document") if referenced else [])

    model = None
    if head.get("type") != "CityJSON":
        problems.append(f"re-read: {path}: 'type' is {str(head.get('type'))[:40]!r}, not 'CityJSON'")
    else:
        try:
            model = cjio._header_of(head, path, "CityJSON")
        except Lod2EnergyError as e:
            problems.append(f"re-read: {e}")
    verts = p.vertices(model.transform) if model is not None else None
    templates = head.get("geometry-templates")

    def group(g: list[str], cos: Mapping) -> Building | FeatureError:
        return cjio.finished(cjio.group_feature(g[0], g, cos, verts), model.transform, templates)

    def schema_checked(out: list[str], repeated: bool) -> Iterator[tuple[str, Any, bool]]:
        """:func:`_cityobjects`, each CityObject also seen by the schema (in batches; a repeated
        id alone), its problems added to ``out``."""
        batch: dict = {}
        weight = 0
        for oid, co, first in _cityobjects(path, repeated):
            if first:
                batch[oid] = co
                weight += _surfaces(co)
            else:
                out.extend(batch_problems({oid: co}))
            if len(batch) >= BATCH or weight >= BATCH_SURFACES:
                out.extend(batch_problems(batch))
                batch, weight = {}, 0
            yield oid, co, first
        if batch:
            out.extend(batch_problems(batch))

    def local_features(out: list[str]) -> Iterator[Building | FeatureError]:
        """The reader's groups when each is a run of consecutive CityObjects whose links stay
        inside the run (as this package writes them): a run at a time in memory."""
        block: dict[str, Any] = {}
        wanted: set[str] = set()
        orphans: list[FeatureError] = []
        for oid, co, _ in schema_checked(out, repeated=False):
            if model is None:
                continue
            block[oid] = co
            wanted.discard(oid)
            wanted.update(x for x in cjio._links(co, "parents") + cjio._links(co, "children")
                          if x not in block and p.may_exist(x))
            if wanted:
                if len(block) > MAX_BLOCK:
                    raise _NotLocal
                continue
            # no CityObject before or after the run links into it: its groups are the reader's
            groups = cjio._feature_ids(block)
            at = {k: i for i, k in enumerate(block)}
            for g in sorted(groups, key=lambda g: max(at[k] for k in g)):  # in the order they complete
                yield group(g, block)
            orphans.extend(cjio._orphan_errors(block, groups, path))
            block = {}
        if block:
            raise _NotLocal  # a link to an id the document has before the run
        yield from orphans

    def all_features(out: list[str]) -> Iterator[Building | FeatureError]:
        """The reader's groups from every CityObject's links (any document)."""
        links, dups = _links_pass(path)
        groups = cjio._feature_ids(links)
        group_of = {oid: gi for gi, g in enumerate(groups) for oid in g}
        left = [len(g) for g in groups]
        for oid in dict.fromkeys(dups):
            yield FeatureError(oid, 901, f"coid={oid}: {path} has more than one CityObject with this id; the first "
                                         f"is read, the others are not")
        pending: dict[str, Any] = {}
        for oid, co, first in schema_checked(out, repeated=True):
            gi = group_of.get(oid) if first else None
            if gi is None or model is None:
                continue
            pending[oid] = co
            left[gi] -= 1
            if left[gi] == 0:
                g = groups[gi]
                yield group(g, {k: pending.pop(k) for k in g})
        if model is not None:
            yield from cjio._orphan_errors(links, groups, path)

    def checked(features) -> tuple[list[str], list[str]]:
        out: list[str] = []
        feats: Iterator = features(out)
        if model is not None:
            _, feats = to_local_frame(model, feats)  # a geographic file is checked in metres
        geometry: list[str] = []
        for f in feats:
            if len(geometry) <= MAX_PROBLEMS:  # the schema of every CityObject is still checked
                geometry += feature_problems(f, tol)
        return out, geometry

    try:
        if p.repeated:
            raise _NotLocal
        more, geometry = checked(local_features)
    except _NotLocal:
        more, geometry = checked(all_features)
    problems += more
    if problems:  # the schema's and the extension's problems come first, as on the whole document
        return problems[:MAX_PROBLEMS]
    return geometry[:MAX_PROBLEMS]


def self_check(path: str, extension: Mapping | None = None, tol=None) -> list[str]:
    """Problems of an exported file (empty list: the file is OK).

    Parameters
    ----------
    path : str
        CityJSON (``.json``) or CityJSONSeq (``.jsonl``) file.
    extension : mapping, optional
        Energy extension schema to check ``+energy`` attributes against (default: the
        file referenced under ``extensions``, looked up next to ``path``, else the shipped one).
    tol : Tolerances, optional
        For the val3dity checks.

    Returns
    -------
    list of str
        One line per problem (schema errors with their JSON path, then geometry problems
        with val3dity-style locations).
    """
    tol = tol or DEFAULT
    if not cjio.is_cityjsonseq(path):  # a document: read one CityObject at a time
        return self_check_document(path, extension, tol)
    problems: list[str] = []
    try:
        with open(path, "rb") as f:
            raw = f.read().decode("utf-8")
    except (OSError, UnicodeDecodeError) as e:
        return [f"cannot read {path}: {e}"]
    docs: list[tuple[str, Any]] = []
    try:
        if cjio.is_cityjsonseq(path):
            lines = [ln for ln in raw.splitlines() if ln.strip()]
            docs = [(f"line {i + 1}", json.loads(ln)) for i, ln in enumerate(lines)]
        else:
            docs = [("document", json.loads(raw))]
    except json.JSONDecodeError as e:
        return [f"{path} is not valid JSON: {e.msg} at line {e.lineno}"]
    if not docs or not isinstance(docs[0][1], dict):
        return [f"{path}: no CityJSON object"]
    head = docs[0][1]
    try:
        version = cjio.normalise_version(head.get("version"))
    except Lod2EnergyError as e:
        return [f"{path}: {e}"]
    schemas = _validators(version)
    # a document jsonschema-rs accepts has no schema error: the interpreted validators (slow,
    # with the messages) only see the documents it rejects
    if not _schema_valid_fast(version, head):
        problems += _schema_errors(schemas, head, docs[0][0])
    for what, d in docs[1:]:
        if schemas.feature is None:
            problems.append(f"{what}: CityJSONFeature needs CityJSON 1.1 or later")
            break
        if not _schema_valid_fast(version, d, feature=True):
            problems += _schema_errors(schemas, d, what, feature=True)
        if len(problems) > MAX_PROBLEMS:
            break
    if extension is None:
        extension = load_extension_beside(path, head)
        if extension is None and EXTENSION_NAME in (head.get("extensions") or {}):
            extension = extension_schema(version)
    for what, d in docs[1:] if len(docs) > 1 else docs:
        if len(docs) > 1:
            d = {**d, "extensions": head.get("extensions")}
        problems += extension_problems(d, extension, what)
    if problems:
        return problems[:MAX_PROBLEMS]
    model, feats = to_local_frame(*cjio.read(path))  # a geographic file is checked in metres
    for f in feats:
        problems += feature_problems(f, tol)
        if len(problems) > MAX_PROBLEMS:
            break
    return problems[:MAX_PROBLEMS]


def feature_problems(f: Building | FeatureError, tol) -> list[str]:
    """What the self-check finds in one re-read feature: its reading error, or for an energy
    building (``+energy`` attributes) val3dity's defects (but the tolerated ones) and the
    envelope's problems."""
    if not isinstance(f, Building):
        return [f"re-read: {f.message}"]
    if not any(k.startswith("+energy") for k in f.root.attributes):
        return []
    out = [f"{d.location}: {d.code} {name(d.code)} {d.info}".rstrip()
           for d in validate_building(f, tol) if d.code not in TOLERATED_CODES]
    return out + envelope_problems(f)
