"""CityJSON 1.0 / 1.1 / 2.0 and CityJSONSeq reading, feature by feature (writing: :mod:`.cityjson_write`).

Reading splits a CityJSON file into features (a first-level CityObject with all its
descendants, as CityJSONSeq does) with feature-local vertices, so every building is
processed on its own. Whatever the model does not interpret (attributes, other
properties, metadata, extensions, appearance, templates) is kept and written back.

Bad input never raises out of :func:`read`: a file-level problem or a broken feature is
yielded as a :class:`~lod2energy.model.FeatureError` and the other features go on.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any, Container, Iterator

import numpy as np

from lod2energy.errors import FormatNotSupportedError, InputError
from lod2energy.io import shape
from lod2energy.io.seen_ids import SeenIds
from lod2energy.io.cityjson_write import is_cityjsonseq
from lod2energy.model import (
    MULTISOLID_TYPES, SOLID_TYPES, SURFACE_TYPES, Building, CityModel, CityObject, FeatureError,
    Geometry, Shell, Solid, Surface, frozen_mapping,
)

SUPPORTED_VERSIONS = ("1.0", "1.1", "2.0")
#: Larger coordinates (m) cannot be a building on Earth in a projected CRS; float64 keeps
#: 1e-4 m only up to about 1e11, so such input is refused per building.
MAX_COORDINATE = 1e9
_GEOM_TYPES = SOLID_TYPES + MULTISOLID_TYPES + SURFACE_TYPES + (
    "MultiPoint", "MultiLineString", "GeometryInstance")


def normalise_version(v: Any) -> str:
    """"1.0.3" -> "1.0"; raises FormatNotSupportedError for versions we cannot read."""
    s = str(v) if v is not None else ""
    parts = s.split(".")
    short = ".".join(parts[:2]) if len(parts) >= 2 else s
    if short not in SUPPORTED_VERSIONS:
        raise FormatNotSupportedError(
            f"CityJSON version {s!r} is not supported (supported: {', '.join(SUPPORTED_VERSIONS)})")
    return short


def _load_json_text(text: str, what: str) -> Any:
    return shape.parse_json(text, what)[0]


def _read_text(path: str) -> str:
    data = shape.read_bounded(path)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        raise InputError(f"{path} is not UTF-8 text (byte {e.start})") from None


def read_json(path: str) -> Any:
    """Parse a JSON file (UTF-8, BOM allowed); InputError (901) with one line on failure."""
    return _load_json_text(_read_text(path), path)


def _transform_vertices(verts: Any, transform: Mapping | None, what: str) -> np.ndarray:
    if verts is None:
        raise InputError(f"{what} has no 'vertices'")
    if not isinstance(verts, list):
        raise InputError(f"{what}: 'vertices' is not an array")
    if len(verts) == 0:
        return np.zeros((0, 3))
    try:
        v = np.array(verts)
    except (ValueError, TypeError, OverflowError):
        v = None
    if v is None or v.dtype.kind not in "iuf" or v.ndim != 2 or v.shape[1] != 3:
        v = _vertices_row_by_row(verts, what)
    v = v.astype(np.float64)
    if transform:
        try:
            scale = np.asarray(transform["scale"], dtype=np.float64).reshape(3)
            translate = np.asarray(transform["translate"], dtype=np.float64).reshape(3)
        except (KeyError, ValueError, TypeError, OverflowError):
            raise InputError(f"{what}: 'transform' needs 'scale' and 'translate' of 3 numbers") from None
        with np.errstate(over="ignore", invalid="ignore"):
            v = v * scale + translate
    return v


def _vertices_row_by_row(verts: list, what: str) -> np.ndarray:
    """Vertices read one by one: a row that is not three finite numbers becomes NaN, so that
    only the buildings using it get an error (the others are read)."""
    def num(x):
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            return math.nan
        try:
            return float(x)
        except OverflowError:
            return math.nan
    rows = [[num(c) for c in r] if isinstance(r, list) and len(r) == 3 else [math.nan] * 3 for r in verts]
    return np.array(rows, dtype=np.float64).reshape(-1, 3)


def _lod_string(lod: Any) -> str | None:
    if lod is None:
        return None
    if isinstance(lod, bool):
        return None
    if isinstance(lod, (int, float)):
        if isinstance(lod, float) and not math.isfinite(lod):
            return None
        return str(int(lod)) if float(lod).is_integer() and not isinstance(lod, float) else str(lod)
    s = str(lod).strip()
    try:
        float(s)
    except ValueError:
        return None
    return s


_INT = {int}
"""The exact type of a vertex index :meth:`_Collector.ring` takes without looking at each."""


class _Collector:
    """Collects the vertex indices a feature uses, then remaps them to 0..n-1."""

    def __init__(self, n_vertices: int):
        self.n = n_vertices
        self.used: list[int] = []
        self.issues: list[tuple[int, str, str]] = []

    def ring(self, ring: Any, where: str) -> list[int]:
        if not isinstance(ring, list):
            raise InputError(f"{where}: a ring must be an array of vertex indices")
        if set(map(type, ring)) <= _INT and (not ring or (min(ring) >= 0 and max(ring) < self.n)):
            self.used.extend(ring)  # plain in-range ints (nearly always): the loop below finds nothing
            return ring
        for i in ring:
            if not isinstance(i, int) or isinstance(i, bool):
                raise InputError(f"{where}: vertex index {i!r} is not an integer")
            if i < 0 or i >= self.n:
                raise InputError(f"{where}: vertex index {i} out of range (file has {self.n} vertices)")
        self.used.extend(ring)
        return ring


def _semantic_values(sem: Mapping | None, gtype: str) -> tuple[tuple, Any]:
    if not sem or not isinstance(sem, Mapping):
        return (), None
    surfaces = sem.get("surfaces")
    values = sem.get("values")
    if not isinstance(surfaces, list):
        return (), None
    return tuple(frozen_mapping(s) if isinstance(s, Mapping) else frozen_mapping({"type": str(s)})
                 for s in surfaces), values


def _sem_at(values: Any, *idx: int) -> int | None:
    v = values
    for i in idx:
        if not isinstance(v, list) or i >= len(v):
            return None
        v = v[i]
    return v if isinstance(v, int) and not isinstance(v, bool) else None


def _parse_surfaces(surfs: Any, col: _Collector, where: str, values: Any, prefix: tuple,
                    arrays: bool = True) -> tuple[Surface, ...]:
    if not isinstance(surfs, list):
        raise InputError(f"{where}: expected an array of surfaces")
    out = []
    for fi, s in enumerate(surfs):
        if not isinstance(s, list):
            raise InputError(f"{where}|face={fi}: a surface must be an array of rings")
        rings = [col.ring(r, f"{where}|face={fi}") for r in s]
        out.append(Surface.from_lists(rings, _sem_at(values, *prefix, fi)) if arrays
                   else Surface(tuple(rings), _sem_at(values, *prefix, fi)))
    return tuple(out)


def _parse_geometry(g: Any, col: _Collector, where: str, arrays: bool = True) -> Geometry:
    """The :class:`Geometry` of CityJSON geometry ``g``; its rings' vertex indices go through ``col``.

    With ``arrays=False`` the rings stay the file's lists of ints, for :func:`_remap_geometry`
    to turn into arrays once (the reader's path: no ring array is built twice, issue 13).
    """
    if not isinstance(g, Mapping):
        raise InputError(f"{where}: geometry is not an object")
    gtype = g.get("type")
    if gtype not in _GEOM_TYPES:
        raise InputError(f"{where}: unknown geometry type {gtype!r}")
    if gtype == "GeometryInstance":
        b = g.get("boundaries")
        if not isinstance(b, list) or len(b) != 1:
            raise InputError(f"{where}: GeometryInstance needs 'boundaries' with one vertex index")
        col.ring(b, where)
        return Geometry(gtype, None, raw=frozen_mapping(g))
    lod = _lod_string(g.get("lod"))
    if lod is None:  # reported for this building; the geometry is still validated
        what = "has no 'lod'" if "lod" not in g else f"has 'lod' {g.get('lod')!r}, not a level of detail"
        col.issues.append((901, where, f"geometry {what}"))
    b = g.get("boundaries")
    if b is None:
        raise InputError(f"{where}: geometry has no 'boundaries'")
    if not isinstance(b, list):
        raise InputError(f"{where}: 'boundaries' is not an array")
    if gtype in ("MultiPoint", "MultiLineString"):
        if gtype == "MultiPoint":
            col.ring(b, where)
        else:
            for r in b:
                col.ring(r, where)
        return Geometry(gtype, lod, raw=frozen_mapping(g))
    sem_surfaces, values = _semantic_values(g.get("semantics"), gtype)
    if gtype in SURFACE_TYPES:
        shell = Shell(_parse_surfaces(b, col, where, values, (), arrays))
        solids = (Solid((shell,)),)
    elif gtype == "Solid":
        shells = []
        for hi, sh in enumerate(b):
            shells.append(Shell(_parse_surfaces(sh, col, f"{where}|shell={hi}", values, (hi,), arrays)))
        solids = (Solid(tuple(shells)),)
    else:
        solids_l = []
        for si, so in enumerate(b):
            if not isinstance(so, list):
                raise InputError(f"{where}|solid={si}: a solid must be an array of shells")
            shells = []
            for hi, sh in enumerate(so):
                shells.append(Shell(_parse_surfaces(sh, col, f"{where}|solid={si}|shell={hi}", values, (si, hi),
                                                    arrays)))
            solids_l.append(Solid(tuple(shells)))
        solids = tuple(solids_l)
    extra = {k: v for k, v in g.items() if k in ("texture", "material")}
    return Geometry(gtype, lod, solids, sem_surfaces, extra=frozen_mapping(extra))


class _Local:
    """The local index of a file vertex among a feature's sorted, unique ``used`` ones:
    ``lut[i]`` (an index or a sequence of them, each in ``used``) by binary search, so that a
    feature of a document with millions of vertices costs its own size, not a table of them all."""

    __slots__ = ("used",)

    def __init__(self, used: np.ndarray):
        self.used = used

    def __getitem__(self, idx):
        return np.searchsorted(self.used, idx)


def _remap_geometry(g: Geometry, lut: "_Local") -> Geometry:
    if g.raw is not None:
        raw = dict(g.raw)
        raw["boundaries"] = _remap_nested(raw["boundaries"], lut)
        return Geometry(g.type, g.lod, (), g.semantic_surfaces, frozen_mapping(raw))
    solids = tuple(Solid(tuple(Shell(tuple(Surface(tuple(lut[r] for r in s.rings), s.semantic)
                                             for s in sh.surfaces)) for sh in so.shells))
                   for so in g.solids)
    for so in solids:
        for sh in so.shells:
            for s in sh.surfaces:
                for r in s.rings:
                    r.setflags(write=False)
    return Geometry(g.type, g.lod, solids, g.semantic_surfaces, extra=g.extra)


def _remap_nested(x: Any, lut: "_Local") -> Any:
    if isinstance(x, list):
        return [_remap_nested(i, lut) for i in x]
    return int(lut[x])


def _links(co: Any, key: str) -> list[str]:
    """The ids of ``co[key]`` ("parents" / "children"), empty when it is not an array of strings."""
    v = co.get(key) if isinstance(co, Mapping) else None
    return [x for x in v if isinstance(x, str)] if isinstance(v, list) else []


def _feature_ids(cos: Mapping[str, Any]) -> list[list[str]]:
    """Group CityObject ids into features: each first-level object with its descendants.

    An object that is no first-level object's descendant (its ``parents``/``children``
    form a cycle or disagree) is in no group: see :func:`_orphan_errors`.
    """
    groups = []
    for oid, co in cos.items():
        parents = _links(co, "parents")
        if parents and any(p in cos for p in parents):
            continue
        members = [oid]
        seen = {oid}
        stack = [oid]
        while stack:
            for ch in _links(cos.get(stack.pop()), "children"):
                if ch in cos and ch not in seen:
                    seen.add(ch)
                    members.append(ch)
                    stack.append(ch)
        groups.append(members)
    return groups


def _orphan_errors(cos: Mapping[str, Any], groups: list[list[str]], what: str) -> Iterator[FeatureError]:
    """One FeatureError per set of linked CityObjects that no feature holds (nothing vanishes)."""
    placed = {oid for g in groups for oid in g}
    left = [oid for oid in cos if oid not in placed]
    done: set[str] = set()
    for oid in left:
        if oid in done:
            continue
        comp, stack = [], [oid]  # the orphans linked to this one
        done.add(oid)
        while stack:
            cur = stack.pop()
            comp.append(cur)
            for nb in _links(cos.get(cur), "parents") + _links(cos.get(cur), "children"):
                if nb in cos and nb not in placed and nb not in done:
                    done.add(nb)
                    stack.append(nb)
        path, cur = [], oid  # follow the parents until one repeats
        while cur is not None and cur not in path:
            path.append(cur)
            cur = next((p for p in _links(cos.get(cur), "parents") if p in cos), None)
        if cur is not None and cur in path:
            cyc = path[path.index(cur):] + [cur]
            why = f"its 'parents' form a cycle ({' -> '.join(cyc)})"
        else:
            why = f"its parent {path[1] if len(path) > 1 else '?'} does not list it among its 'children'"
        others = f"; with {', '.join(c for c in comp if c != oid)}" if len(comp) > 1 else ""
        co = cos.get(oid)
        rtype = co.get("type") if isinstance(co, Mapping) and isinstance(co.get("type"), str) else ""
        yield FeatureError(oid, 901, f"coid={oid}: {why}, so it belongs to no first-level CityObject and is "
                                     f"not read{others}", rtype)


def build_feature(root_id: str, ids: list[str], cos: Mapping[str, Any], vertices: np.ndarray) -> Building:
    """Turn the CityObjects ``ids`` (root first) into a :class:`Building` with local vertices.

    Raises
    ------
    InputError
        For a broken geometry, a vertex index out of range or a non-finite coordinate.
    """
    col = _Collector(len(vertices))
    objs = []
    for oid in ids:
        co = cos[oid]
        if not isinstance(co, Mapping):
            raise InputError(f"coid={oid}: CityObject is not a JSON object")
        otype = co.get("type")
        if not isinstance(otype, str):
            raise InputError(f"coid={oid}: CityObject has no 'type'")
        geoms_raw = co.get("geometry") or []
        if not isinstance(geoms_raw, list):
            raise InputError(f"coid={oid}: 'geometry' is not an array")
        geoms = tuple(_parse_geometry(g, col, f"coid={oid}|geom={gi}", arrays=False)
                      for gi, g in enumerate(geoms_raw))
        extra = {k: v for k, v in co.items()
                 if k not in ("type", "geometry", "attributes", "parents", "children")}
        objs.append(CityObject(oid, otype, geoms, frozen_mapping(co.get("attributes") or {}),
                               tuple(co.get("parents") or ()), tuple(co.get("children") or ()),
                               frozen_mapping(extra)))
    used = np.unique(np.asarray(col.used, dtype=np.intp)) if col.used else np.zeros(0, np.intp)
    local = vertices[used] if len(used) else np.zeros((0, 3))
    if local.size and not np.isfinite(local).all():
        bad = used[~np.isfinite(local).all(axis=1)][:3].tolist()
        raise InputError(f"coid={root_id}: non-finite (NaN/inf) or non-numeric coordinates at vertex {bad}")
    if local.size and np.abs(local).max() > MAX_COORDINATE:
        raise InputError(f"coid={root_id}: coordinates beyond {MAX_COORDINATE:.0e} m "
                         f"(max |c| = {np.abs(local).max():.3g}); is the CRS projected and metric?")
    lut = _Local(used)
    objs = [CityObject(o.id, o.type, tuple(_remap_geometry(g, lut) for g in o.geometries),
                       o.attributes, o.parents, o.children, o.extra) for o in objs]
    prov = frozen_mapping({"input_errors": tuple(col.issues)}) if col.issues else frozen_mapping({})
    return Building(root_id, objs[0].type, local, tuple(objs), prov)


def _header_from(doc: Mapping[str, Any], path: str, fmt: str) -> CityModel:
    version = normalise_version(doc.get("version"))
    known = {"type", "version", "CityObjects", "vertices", "transform", "metadata", "extensions",
             "appearance", "geometry-templates"}
    return CityModel(
        version=version,
        transform=frozen_mapping(doc["transform"]) if isinstance(doc.get("transform"), Mapping) else None,
        metadata=frozen_mapping(doc.get("metadata") if isinstance(doc.get("metadata"), Mapping) else {}),
        extensions=frozen_mapping(doc.get("extensions") if isinstance(doc.get("extensions"), Mapping) else {}),
        appearance=doc.get("appearance"),
        geometry_templates=doc.get("geometry-templates"),
        extra=frozen_mapping({k: v for k, v in doc.items() if k not in known}),
        source=path, format=fmt,
    )


def _features_of_document(doc: Mapping[str, Any], transform: Mapping | None,
                          what: str, templates: Any = None, keys: Any = None,
                          seen: SeenIds | None = None, tag: int = 0,
                          only: "Container[str] | None" = None) -> Iterator[Building | FeatureError]:
    if templates is None:
        templates = doc.get("geometry-templates")
    for item in _features_of_document_raw(doc, transform, what, keys, seen, tag, only):
        yield finished(item, transform, templates)


def finished(item: Building | FeatureError, transform: Mapping | None, templates: Any) -> Building | FeatureError:
    """A feature as :func:`read` gives it: an error's message on one line, a building with the
    file's grid and, when it has instances, the file's geometry templates."""
    if isinstance(item, FeatureError):
        if not item.message.isprintable() or len(item.message) > shape.MAX_MESSAGE:
            # one line, whatever the ids hold (a newline, a control character)
            item = FeatureError(item.id, item.code, shape.one_line(item.message), item.type)
        return item
    if isinstance(transform, Mapping):
        # the grid a writer keeps: the final check judges the building on it
        item = item.with_provenance(file_transform={"scale": [float(x) for x in transform["scale"]],
                                                    "translate": [float(x) for x in transform["translate"]]})
    if isinstance(templates, Mapping) and any(g.type == "GeometryInstance" for o in item.objects for g in o.geometries):
        # instances are validated on their template (lod2energy.validate.checks.check_instance)
        item = item.with_provenance(geometry_templates=templates)
    return item


def group_feature(root: str, ids: list[str], cos: Mapping[str, Any], vertices: np.ndarray) -> Building | FeatureError:
    """The feature of first-level CityObject ``root`` and its descendants ``ids`` (root
    first): the Building, or a FeatureError for it."""
    rtype = cos[root].get("type", "") if isinstance(cos[root], Mapping) else ""
    rtype = rtype if isinstance(rtype, str) else ""
    bad = next(((oid, p) for oid in ids if (p := shape.cityobject_problem(oid, cos[oid]))), None)
    if bad is not None:
        return FeatureError(root, 901, f"coid={bad[0]}: {bad[1]}", rtype)
    try:
        return build_feature(root, ids, cos, vertices)
    except InputError as e:
        return FeatureError(root, e.code, str(e), rtype)
    except (TypeError, ValueError, KeyError, IndexError, OverflowError, RecursionError) as e:
        return FeatureError(root, 901, f"coid={root}: unusable value ({type(e).__name__}: "
                                       f"{str(e).splitlines()[0][:120] if str(e) else ''})", rtype)


def _features_of_document_raw(doc: Mapping[str, Any], transform: Mapping | None,
                              what: str, keys: Any = None,
                              seen: SeenIds | None = None, tag: int = 0,
                              only: "Container[str] | None" = None) -> Iterator[Building | FeatureError]:
    """The features of one CityJSON document or CityJSONFeature.

    ``keys`` (from :func:`lod2energy.io.shape.parse_json`) tells the ids the document
    repeated; ``seen`` holds the ids of earlier lines of a CityJSONSeq and where they were
    (this document's are added with ``tag``), so that a second CityObject with an id already
    read is reported, not read over the first. With ``only``, a feature whose first-level id
    is not in it is passed over before it is built (its ids still count as read).
    """
    cos = doc.get("CityObjects")
    if not isinstance(cos, Mapping):
        yield FeatureError(None, 901, f"{what} has no 'CityObjects' object")
        return
    seen = SeenIds(lambda _: what) if seen is None else seen
    for oid in (keys.of(cos) if keys is not None else ()):
        yield FeatureError(seen.duplicate_id(oid), 901,
                           f"coid={oid}: {what} has more than one CityObject with this id; the first is read, "
                           f"the others are not")
    try:
        verts = _transform_vertices(doc.get("vertices"), transform, what)
    except InputError as e:
        yield FeatureError(None, 901, str(e))
        return
    groups = _feature_ids(cos)
    for ids in groups:
        root = ids[0]
        rtype = cos[root].get("type", "") if isinstance(cos[root], Mapping) else ""
        rtype = rtype if isinstance(rtype, str) else ""
        again = next((oid for oid in ids if oid in seen), None)
        if again is not None:
            yield FeatureError(seen.duplicate_id(root), 901,
                               f"coid={again}: this id was already read ({seen.where(again)}); the first is kept, "
                               f"this one ({what}) is not read", rtype)
            continue
        for oid in ids:
            seen.add(oid, tag)
        if only is not None and root not in only:
            continue
        yield group_feature(root, ids, cos, verts)
    yield from _orphan_errors(cos, groups, what)


def read(path: str, only: "Container[str] | None" = None) -> tuple[CityModel | None, Iterator[Building | FeatureError]]:
    """Open a CityJSON or CityJSONSeq file.

    Parameters
    ----------
    path : str
    only : container of str, optional
        First-level CityObject ids: the features of the others are passed over before they are
        checked and built (a page that needs a few buildings of a large file).

    Returns
    -------
    model : CityModel or None
        File-level data; None when the file cannot be used at all (then the iterator
        yields one file-level :class:`FeatureError`).
    features : iterator of Building or FeatureError
        Streamed: CityJSONSeq is read line by line.
    """
    if is_cityjsonseq(path):
        return _read_seq(path, only)
    try:
        doc, keys = shape.parse_json(_read_text(path), path)
        if not isinstance(doc, Mapping):
            raise InputError(f"{path}: the JSON root is not an object")
        if doc.get("type") != "CityJSON":
            raise FormatNotSupportedError(f"{path}: 'type' is {str(doc.get('type'))[:40]!r}, not 'CityJSON'")
        model = _header_of(doc, path, "CityJSON")
    except InputError as e:
        return None, iter([FeatureError(None, e.code, str(e))])
    return model, _features_of_document(doc, model.transform, path, keys=keys, only=only)


def _header_of(doc: Mapping[str, Any], path: str, fmt: str, what: str | None = None) -> CityModel:
    """:func:`_header_from` after the shape check of the file-level members (InputError)."""
    problem = shape.header_problem(doc)
    if problem:
        raise InputError(f"{what or path}: {problem}")
    return _header_from(doc, path, fmt)


def _read_seq(path: str, only: "Container[str] | None" = None):
    try:
        shape.check_input_file(path)
        f = open(path, "rb")
    except InputError as e:
        return None, iter([FeatureError(None, 901, str(e))])
    except OSError as e:
        return None, iter([FeatureError(None, 901, f"cannot read {path}: {e.strerror}")])
    lines = shape.iter_lines_bounded(f)
    first = next(lines, b"")
    try:
        if isinstance(first, InputError):
            raise InputError(f"{path} line 1: {first}")
        try:
            text = first.decode("utf-8-sig")
        except UnicodeDecodeError:
            raise InputError(f"{path}: first line is not UTF-8") from None
        if not text.strip():
            raise InputError(f"{path} is empty")
        doc = _load_json_text(text, f"{path} line 1")
        if not isinstance(doc, Mapping) or doc.get("type") != "CityJSON":
            raise InputError(f"{path} line 1: the first line of a CityJSONSeq must be a 'CityJSON' object")
        model = _header_of(doc, path, "CityJSONSeq", f"{path} line 1")
        if model.transform is None:
            raise InputError(f"{path} line 1: CityJSONSeq needs a 'transform' in its first line")
    except InputError as e:
        f.close()
        return None, iter([FeatureError(None, e.code, str(e))])

    def gen():
        seen = SeenIds(lambda n: f"{path} line {n}")
        with f:
            for lineno, raw in enumerate(lines, start=2):
                if isinstance(raw, InputError):
                    yield FeatureError(f"line {lineno}", 901, f"{path} line {lineno}: {raw}")
                    continue
                if not raw.strip():
                    continue
                try:
                    line, keys = shape.parse_json(raw.decode("utf-8"), f"{path} line {lineno}")
                except UnicodeDecodeError as e:
                    yield FeatureError(f"line {lineno}", 901, f"{path} line {lineno} is not UTF-8 text (byte {e.start})")
                    continue
                except InputError as e:
                    yield FeatureError(f"line {lineno}", 901, str(e))
                    continue
                if not isinstance(line, Mapping) or line.get("type") != "CityJSONFeature":
                    yield FeatureError(f"line {lineno}", 901, f"{path} line {lineno}: not a CityJSONFeature")
                    continue
                yield from _features_of_document(line, model.transform, f"{path} line {lineno}",
                                                 model.geometry_templates, keys, seen, lineno, only)
    return model, gen()
