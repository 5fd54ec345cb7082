"""Inputs that are not a named file: standard input (``-``, ``/dev/stdin``), a file object, a
CityJSON document as a dict (or a CityJSONSeq as a list of dicts).

The readers and every later pass read their input by path (a writer or the HTML page reads it
again), so such an input is written once to a regular file with the suffix its content calls for
(:func:`materialise`) and read from there like any other.
"""
from __future__ import annotations

import json
import os
import sys
from collections.abc import Mapping

from lod2energy.errors import InputError
from lod2energy.io.shape import MAX_INPUT_BYTES

#: The names that mean standard input on the command line.
STDIN_NAMES = ("-", "/dev/stdin")


def is_stdin(path) -> bool:
    """True when ``path`` names standard input (``-`` or ``/dev/stdin``)."""
    return isinstance(path, str) and path in STDIN_NAMES


def read_stdin(stream=None) -> bytes:
    """The bytes of standard input (or ``stream``), at most :data:`MAX_INPUT_BYTES`; InputError beyond."""
    stream = sys.stdin if stream is None else stream
    data = _read_all(getattr(stream, "buffer", stream), "standard input")
    if not data.strip():
        raise InputError("standard input is empty")
    return data


def _read_all(f, what: str) -> bytes:
    data = f.read(MAX_INPUT_BYTES + 1)
    if isinstance(data, str):
        data = data.encode("utf-8")
    if len(data) > MAX_INPUT_BYTES:
        raise InputError(f"cannot read {what}: more than the {MAX_INPUT_BYTES / 2**20:.0f} MiB an input may "
                         f"have (LOD2ENERGY_MAX_INPUT_MB)")
    return data


def to_bytes(obj) -> bytes:
    """The bytes of ``obj``: a CityJSON dict, a list of dicts (a CityJSONSeq, the header first),
    ``bytes`` / ``str`` of a document, or a file object opened in text or binary mode."""
    if isinstance(obj, Mapping):
        return json.dumps(obj, separators=(",", ":")).encode("utf-8")
    if isinstance(obj, (list, tuple)) and obj and all(isinstance(d, Mapping) for d in obj):
        return b"".join(json.dumps(d, separators=(",", ":")).encode("utf-8") + b"\n" for d in obj)
    if isinstance(obj, (bytes, bytearray)):
        return bytes(obj)
    if isinstance(obj, str):
        return obj.encode("utf-8")
    if hasattr(obj, "read"):
        return _read_all(obj, getattr(obj, "name", None) or "the file object")
    raise InputError(f"cannot read a {type(obj).__name__}: give a path, a file object or a CityJSON dict")


def suffix_of(data: bytes) -> str:
    """``.city.jsonl`` for a CityJSONSeq (a first line that is a whole JSON object, then more
    lines), ``.gml`` for XML, ``.city.json`` otherwise."""
    head = data.lstrip()[:1]
    if head == b"<":
        return ".gml"
    first, _, rest = data.lstrip(b"\xef\xbb\xbf \t\r\n").partition(b"\n")
    if rest.strip():
        try:
            doc = json.loads(first)
        except ValueError:
            return ".city.json"
        if isinstance(doc, dict) and doc.get("type") == "CityJSON":
            return ".city.jsonl"
    return ".city.json"


def materialise(data: bytes, folder: str, name: str = "stdin") -> str:
    """Write ``data`` to ``folder/<name><suffix>`` (the suffix by :func:`suffix_of`) and return its path."""
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, f"{os.path.basename(name) or 'stdin'}{suffix_of(data)}")
    tmp = f"{path}.{os.getpid()}.part"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)
    return path
