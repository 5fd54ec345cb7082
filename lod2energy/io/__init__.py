"""Readers and writers, chosen by file suffix (a small format registry, as meshio does)."""
from __future__ import annotations

import re
from typing import Callable, Iterator

from lod2energy.model import Building, CityModel, FeatureError

Reader = Callable[..., "tuple[CityModel | None, Iterator[Building | FeatureError]]"]
_READERS: dict[str, tuple[str, Reader]] = {}


def register_format(name: str, suffixes: tuple[str, ...], reader: Reader) -> None:
    """Register ``reader(path, **options)`` for files ending in one of ``suffixes``."""
    for s in suffixes:
        _READERS[s.lower()] = (name, reader)


def format_of(path: str) -> str | None:
    p = path.lower()
    for s in sorted(_READERS, key=len, reverse=True):
        if p.endswith(s):
            return _READERS[s][0]
    return None


def read(path: str, **options) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Read any supported file. Never raises for bad input: problems come as FeatureError.

    Options (mesh formats only): ``primitive`` ("Solid", "CompositeSurface",
    "MultiSurface"), ``inner_shells`` (list of POLY paths).
    """
    p = path.lower()
    for s in sorted(_READERS, key=len, reverse=True):
        if p.endswith(s):
            return _READERS[s][1](path, **options)
    # unknown suffix: sniff JSON
    return _READERS[".json"][1](path, **options)


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


def _register_builtin() -> None:
    from lod2energy.io import cityjson

    def _cj(path, **_):
        other = _json_document_type(path) if not cityjson.is_cityjsonseq(path) else None
        if other == "tu3djson":
            from lod2energy.io import tu3djson
            return tu3djson.read(path)
        if other in ("Feature", "FeatureCollection"):
            from lod2energy.io import jsonfg
            return jsonfg.read(path)
        return cityjson.read(path)

    register_format("CityJSON", (".json", ".city.json"), _cj)
    register_format("CityJSONSeq", (".jsonl", ".city.jsonl", ".cjseq"), _cj)
    from lod2energy.io import citygml
    register_format("CityGML", (".gml", ".xml"), citygml.read)
    try:  # mesh readers (POLY/OBJ/OFF) live in lod2energy.io.mesh
        from lod2energy.io import mesh
        mesh.register(register_format)
    except ImportError:
        pass


_register_builtin()
