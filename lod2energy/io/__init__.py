"""Readers and writers, chosen by file suffix (a small format registry, as meshio does)."""
from __future__ import annotations

import itertools
import os
import re
from dataclasses import replace
from typing import Callable, Iterator

import numpy as np

from lod2energy import crs as crs_
from lod2energy.errors import InputError
from lod2energy.geodesy import LocalFrame, ScaledFrame
from lod2energy.io.shape import check_input_file
from lod2energy.logs import log
from lod2energy.model import Building, CityModel, FeatureError

Reader = Callable[..., "tuple[CityModel | None, Iterator[Building | FeatureError]]"]
_READERS: dict[str, tuple[str, Reader]] = {}


def register_format(name: str, suffixes: tuple[str, ...], reader: Reader) -> None:
    """Register ``reader(path, **options)`` for files ending in one of ``suffixes``."""
    for s in suffixes:
        _READERS[s.lower()] = (name, reader)


def format_of(path: str) -> str | None:
    """Name of the registered format of ``path`` (by its longest matching suffix), or None."""
    return _lookup(path, (None, None))[0]


def _lookup(path: str, default):
    p = path.lower()
    return next((_READERS[s] for s in sorted(_READERS, key=len, reverse=True) if p.endswith(s)), default)


def read(path: str, **options) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Read any supported file. Never raises for bad input: problems come as FeatureError.

    Options (mesh formats only): ``primitive`` ("Solid", "CompositeSurface",
    "MultiSurface"), ``inner_shells`` (list of POLY paths). Any format: ``only``, a container
    of first-level CityObject ids: only those features are given (the CityJSON readers pass
    over the others before building them; the others build and drop them). ``crs``: the CRS
    of the coordinates (any form pyproj reads, :func:`lod2energy.crs.spelled`), replacing the
    one the file names, if any.
    """
    if not isinstance(path, (str, os.PathLike)):  # a document, not a path: one line, not the document
        return None, iter([FeatureError(None, 903, f"lod2energy.io.read takes a path, not a {type(path).__name__}: "
                                                   "lod2energy.read takes a CityJSON dict or a file object")])
    path = os.fspath(path)
    try:  # the input-shape check starts here: a regular file of bounded size
        check_input_file(str(path))
    except InputError as e:
        return None, iter([FeatureError(None, e.code, str(e))])
    only = options.pop("only", None)
    crs = options.pop("crs", None)
    name, reader = _lookup(path, _READERS[".json"])  # unknown suffix: sniff JSON
    log.debug("%s: read as %s", path, name)
    if only is None:
        return to_local_frame(*with_crs(*reader(path, **options), crs))
    gate = _Only(only)
    model, feats = with_crs(*(reader(path, only=gate, **options) if getattr(reader, "takes_only", False) else
                              reader(path, **options)), crs)
    if model is not None and crs_.is_geographic(model.crs) and _frame_origin(model) is None:
        gate.every = True  # the local frame is taken at the first building: build them all
    model, feats = to_local_frame(model, feats)
    return model, (f for f in feats if isinstance(f, Building) and f.id in only)


class _Only:
    """The ids a reader builds (``read(..., only=)``); ``every`` set before the first feature is
    read makes it build every one (the frame of a geographic file may need the first)."""

    def __init__(self, ids):
        self.ids, self.every = ids, False

    def __contains__(self, oid) -> bool:
        return self.every or oid in self.ids


def _frame_origin(model: CityModel, translate: bool = False) -> "list[float] | None":
    """Centre of the file's geographicalExtent (or, with ``translate``, the transform's
    translation), in file coordinates."""
    md = model.metadata or {}
    ext = md.get("geographicalExtent") if hasattr(md, "get") else None
    try:
        if not translate and ext is not None and len(ext) == 6:
            return [(float(ext[i]) + float(ext[i + 3])) / 2 for i in range(3)]
        if translate and model.transform:
            return [float(x) for x in model.transform["translate"]]
    except (TypeError, ValueError, KeyError):
        pass
    return None


def with_crs(model: "CityModel | None", features, crs=None):
    """``model`` with its CRS replaced by ``crs`` (any form pyproj reads; the user's ``--crs``)."""
    if model is None or crs is None:
        return model, features
    md = dict(model.metadata or {})
    md.pop("crs", None)  # CityJSON 0.x / 1.0 "crs": {"epsg": ...}
    md["referenceSystem"] = crs_.spelled(crs)
    return replace(model, metadata=md), features


def to_local_frame(model: "CityModel | None", features: "Iterator[Building | FeatureError]"
                   ) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Buildings in metres: those of a file in a geographic CRS (degrees) moved into a local
    metric frame, those of a projected CRS in another linear unit (US survey feet, feet)
    scaled to metres (:class:`lod2energy.geodesy.ScaledFrame`, its factors pyproj's).

    The frame (:class:`lod2energy.geodesy.LocalFrame`, east-north-up in metres) is tangent
    at the centre of the file's ``geographicalExtent`` (else at the first building's first
    vertex, else at the ``transform`` translation), and stored as ``model.frame`` so that
    writers move vertices back. Its "up" is the ellipsoid normal at that point: a building
    5 km away stands 0.045 degrees off it (its shape, areas and volume are exact). Files in
    a projected CRS in metres, and files with no CRS pyproj reads, pass through unchanged; a
    CRS whose unit is not a length gives ``(None, [FeatureError 901])``.
    """
    info = crs_.crs_info(model.crs) if model is not None else None
    if info is None:
        return model, features
    if not info.geographic:
        return _scaled(model, features, info)
    features = iter(features)
    pending: list = []
    origin = _frame_origin(model)
    if origin is None:
        for f in features:
            pending.append(f)
            if isinstance(f, Building) and len(f.vertices):
                origin = [float(x) for x in f.vertices[0]]
                break
    if origin is None:
        origin = _frame_origin(model, translate=True)
    if origin is None or not all(np.isfinite(origin)):
        return model, itertools.chain(pending, features)
    lat_first = crs_.latitude_first(model.crs)
    if lat_first and abs(origin[0]) > 90 >= abs(origin[1]):
        lat_first = False  # written (lon, lat) although the EPSG CRS says (lat, lon)
    lat0, lon0 = (origin[0], origin[1]) if lat_first else (origin[1], origin[0])
    if not (abs(lat0) <= 90 and abs(lon0) <= 180):
        return model, itertools.chain(
            [FeatureError(None, 901, f"{model.source}: CRS {model.crs} is geographic but the coordinates "
                                     f"({origin[0]:g}, {origin[1]:g}) are not degrees")],
            pending, features)
    frame = LocalFrame(round(lat0, 7), round(lon0, 7), 0.0, lat_first)
    return _in_frame(model, itertools.chain(pending, features), frame)


def _scaled(model: CityModel, features, info):
    if info.unit_problem:
        return None, iter([FeatureError(None, 901, f"{model.source}: {info.unit_problem}")])
    if info.metric:
        return model, features
    return _in_frame(model, features, ScaledFrame(info.to_metre, info.vertical_to_metre, info.unit, info.vertical_unit))


def _in_frame(model: CityModel, features, frame):
    """``model`` in ``frame``, and its buildings' vertices turned into it one at a time."""
    def gen():
        for f in features:
            if isinstance(f, Building) and len(f.vertices):
                f = replace(f, vertices=frame.to_local(f.vertices)).with_provenance(file_frame=frame)
            yield f
    return replace(model, frame=frame), gen()


_TYPE_RE = re.compile(rb'"type"\s*:\s*"([^"]{1,40})"')


_DOC_TYPES = (b"CityJSON", b"CityJSONFeature", b"tu3djson", b"Feature", b"FeatureCollection")


def _json_document_type(path: str, head: int = 65536) -> str | None:
    """The first document-level ``"type"`` value in the head of a JSON file (no parsing).

    Tells tu3djson and JSON-FG (``"tu3djson"``, ``"Feature"``, ``"FeatureCollection"``)
    from CityJSON; other ``"type"`` values (CityObject types, media types of links) are
    skipped.
    """
    try:
        with open(path, "rb") as f:
            text = f.read(head)
    except OSError:
        return None
    for m in _TYPE_RE.finditer(text):
        if m.group(1) in _DOC_TYPES:
            return m.group(1).decode("ascii")
    return None


# the readers register themselves in this module's registry: imported once it exists
from lod2energy.io import citygml, cityjson, jsonfg, mesh, tu3djson  # noqa: E402


def _cityjson_family(path, only=None, **_):
    """CityJSON / CityJSONSeq, or tu3djson / JSON-FG told by the document's ``"type"``."""
    other = _json_document_type(path) if not cityjson.is_cityjsonseq(path) else None
    if other == "tu3djson":  # ``only`` is applied after these by :func:`read`
        return tu3djson.read(path)
    if other in ("Feature", "FeatureCollection"):
        return jsonfg.read(path)
    return cityjson.read(path, only=only)


_cityjson_family.takes_only = True
register_format("CityJSON", (".json", ".city.json"), _cityjson_family)
register_format("CityJSONSeq", (".jsonl", ".city.jsonl", ".cjseq"), _cityjson_family)
register_format("CityGML", (".gml", ".xml"), citygml.read)
mesh.register(register_format)
