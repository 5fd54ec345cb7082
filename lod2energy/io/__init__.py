"""Readers and writers, chosen by file suffix (a small format registry, as meshio does)."""
from __future__ import annotations

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


def _register_builtin() -> None:
    from lod2energy.io import cityjson

    def _cj(path, **_):
        return cityjson.read(path)

    register_format("CityJSON", (".json", ".city.json"), _cj)
    register_format("CityJSONSeq", (".jsonl", ".city.jsonl", ".cjseq"), _cj)
    try:  # mesh readers (POLY/OBJ/OFF) live in lod2energy.io.mesh
        from lod2energy.io import mesh
        mesh.register(register_format)
    except ImportError:
        pass


_register_builtin()
