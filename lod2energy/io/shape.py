"""The input-shape check at the readers' boundary: bounded reads, bounded JSON, well-formed CityObjects.

Every reader goes through this module before it interprets a value, so that input of the
wrong type, size or depth becomes one clear :class:`~lod2energy.errors.InputError` (901)
for its building or its file, and never a ``RecursionError``, ``OverflowError``,
``TypeError`` or ``MemoryError`` further down:

- :func:`check_input_file` refuses what is not a regular file (a FIFO, a device such as
  ``/dev/zero``, a socket: an endless stream cannot be read whole) and a file larger than
  :data:`MAX_INPUT_BYTES`; :func:`read_bounded` reads at most that many bytes, and
  :func:`iter_lines_bounded` at most :data:`MAX_LINE_BYTES` per line (a longer line is
  reported and skipped, the next lines are still read);
- :func:`parse_json` turns JSON that nests too deeply for the parser, integers too long to
  convert and duplicate object keys into errors (the first of repeated keys is kept and the
  repeated ones are listed);
- :func:`cityobject_problem` checks one CityObject: its ``type``, ``parents``,
  ``children``, ``geometry`` and ``attributes`` have the types CityJSON gives them, it nests
  at most :data:`MAX_DEPTH` levels, every number in it is finite and within float range,
  every string shorter than :data:`MAX_STRING`.

The limits can be raised with the environment variables ``LOD2ENERGY_MAX_INPUT_MB`` and
``LOD2ENERGY_MAX_LINE_MB``.
"""
from __future__ import annotations

import json
import math
import os
import stat
from itertools import chain
from collections.abc import Mapping
from typing import Any, Iterator

from lod2energy.errors import InputError


def _env_mb(name: str, default_mb: int) -> int:
    try:
        mb = float(os.environ.get(name, default_mb))
    except ValueError:
        mb = default_mb
    return max(int(mb * 2**20), 1)


#: Largest input file read (bytes); a larger one is refused with one line.
MAX_INPUT_BYTES = _env_mb("LOD2ENERGY_MAX_INPUT_MB", 2048)
#: Largest line of a CityJSONSeq file (bytes): one feature.
MAX_LINE_BYTES = _env_mb("LOD2ENERGY_MAX_LINE_MB", 256)
#: Deepest nesting of JSON arrays/objects inside one CityObject (a MultiSolid's boundaries
#: need 6 below the geometry; attributes rarely more than a few).
MAX_DEPTH = 48
#: Deepest nesting of the file-level members (metadata, extensions, appearance, templates).
MAX_HEADER_DEPTH = 64
#: Longest string value or key (characters).
MAX_STRING = 1 << 20
#: Largest magnitude of a number anywhere in a CityObject or header.
MAX_NUMBER = 1.7976931348623157e308
_CHUNK = 1 << 20


def check_input_file(path: str) -> int:
    """The size of ``path`` in bytes, or InputError (901) when it cannot be read as a bounded file.

    Refuses FIFOs, character and block devices and sockets (streams without an end: copy
    them to a file first) and files larger than :data:`MAX_INPUT_BYTES`.
    """
    try:
        st = os.stat(path)
    except OSError as e:
        raise InputError(f"cannot read {path}: {e.strerror}") from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError(f"cannot read {path}: Is a directory")
    if not stat.S_ISREG(st.st_mode):
        kind = ("a FIFO" if stat.S_ISFIFO(st.st_mode) else "a device" if stat.S_ISCHR(st.st_mode)
                or stat.S_ISBLK(st.st_mode) else "a socket" if stat.S_ISSOCK(st.st_mode) else "not a file")
        raise InputError(f"cannot read {path}: it is {kind}, not a regular file (a stream without "
                         f"an end cannot be read whole; copy it to a file first)")
    if st.st_size > MAX_INPUT_BYTES:
        raise InputError(f"cannot read {path}: {st.st_size / 2**20:.0f} MiB is more than the "
                         f"{MAX_INPUT_BYTES / 2**20:.0f} MiB an input may have (LOD2ENERGY_MAX_INPUT_MB)")
    return st.st_size


def read_bounded(path: str, limit: int | None = None) -> bytes:
    """The bytes of ``path``, at most ``limit`` (default :data:`MAX_INPUT_BYTES`); InputError otherwise.

    The file is checked by :func:`check_input_file` first; a file that grows while it is
    read is cut at the limit and refused.
    """
    limit = MAX_INPUT_BYTES if limit is None else limit
    check_input_file(path)
    try:
        with open(path, "rb") as f:
            data = f.read(limit + 1)
    except OSError as e:
        raise InputError(f"cannot read {path}: {e.strerror}") from None
    if len(data) > limit:
        raise InputError(f"cannot read {path}: more than the {limit / 2**20:.0f} MiB an input may have "
                         f"(LOD2ENERGY_MAX_INPUT_MB)")
    return data


class LineTooLong(InputError):
    """One line of a line-based file is longer than :data:`MAX_LINE_BYTES` (901); it was skipped."""


def iter_lines_bounded(f, limit: int | None = None) -> Iterator[bytes | LineTooLong]:
    """The lines of the binary file ``f``, each at most ``limit`` bytes (default :data:`MAX_LINE_BYTES`).

    A longer line is read on in chunks to its end without being kept, and yielded as a
    :class:`LineTooLong` in its place, so that the next lines are still read. The whole
    file is bounded by :data:`MAX_INPUT_BYTES` (then a LineTooLong ends the iteration).
    """
    limit = MAX_LINE_BYTES if limit is None else limit
    total = 0
    while True:
        line = f.readline(limit + 1)
        if not line:
            return
        total += len(line)
        if len(line) > limit and not line.endswith(b"\n"):
            skipped = len(line)
            while True:
                rest = f.readline(_CHUNK)
                skipped += len(rest)
                total += len(rest)
                if not rest or rest.endswith(b"\n") or total > MAX_INPUT_BYTES:
                    break
            yield LineTooLong(f"line longer than the {limit / 2**20:.0f} MiB a line may have "
                              f"(LOD2ENERGY_MAX_LINE_MB): {skipped} bytes skipped")
        else:
            yield line
        if total > MAX_INPUT_BYTES:
            yield LineTooLong(f"more than the {MAX_INPUT_BYTES / 2**20:.0f} MiB an input may have "
                              f"(LOD2ENERGY_MAX_INPUT_MB): the rest is not read")
            return


class _Keys:
    """``object_pairs_hook`` for :func:`json.loads` that keeps the first of repeated keys and lists them."""

    def __init__(self):
        self.repeated: list[tuple[dict, list[str]]] = []

    def __call__(self, pairs: list) -> dict:
        d = dict(pairs)
        if len(d) != len(pairs):
            d = {}
            rep = []
            for k, v in pairs:
                if k in d:
                    rep.append(k)
                else:
                    d[k] = v
            self.repeated.append((d, rep))
        return d

    def of(self, d: Any) -> list[str]:
        """The keys repeated in the object ``d`` (only the first was kept)."""
        for obj, rep in self.repeated:
            if obj is d:
                return rep
        return []


def parse_json(text: str, what: str) -> tuple[Any, _Keys]:
    """Parse JSON text; InputError (901) with one line for anything the parser cannot take.

    Returns
    -------
    (value, keys)
        ``keys.of(obj)`` lists the keys an object repeated (the first occurrence is kept).
    """
    keys = _Keys()
    try:
        return json.loads(text, object_pairs_hook=keys), keys
    except json.JSONDecodeError as e:
        raise InputError(f"{what} is not valid JSON: {e.msg} at line {e.lineno} column {e.colno}") from None
    except RecursionError:
        raise InputError(f"{what}: JSON nested too deeply to be read") from None
    except (ValueError, OverflowError) as e:  # e.g. an integer of more than 4300 digits
        raise InputError(f"{what} is not usable JSON: {str(e).splitlines()[0][:120]}") from None
    except MemoryError:
        raise InputError(f"{what}: too large to be parsed in the memory available") from None


#: Longest message of a reader's error (characters); long ids are cut in the middle.
MAX_MESSAGE = 400


def one_line(msg: str, limit: int = MAX_MESSAGE) -> str:
    """``msg`` with every non-printable character (newline, control) escaped, at most ``limit`` long."""
    if not msg.isprintable():
        msg = "".join(c if c.isprintable() else repr(c)[1:-1] for c in msg)
    if len(msg) > limit:
        msg = msg[: limit * 2 // 3] + " ... " + msg[-(limit // 3 - 5):]
    return msg


def _kind(x: Any) -> str:
    if x is None:
        return "null"
    if isinstance(x, bool):
        return "a boolean"
    if isinstance(x, (int, float)):
        return f"the number {x!r}" if len(repr(x)) < 30 else "a number"
    if isinstance(x, str):
        return f"the string {x[:30]!r}"
    if isinstance(x, list):
        return "an array"
    if isinstance(x, Mapping):
        return "an object"
    return type(x).__name__


_INT, _FLOAT = {int}, {float}


def _plain_numbers(v: list) -> bool:
    """Is every item of ``v`` a plain ``int`` within :data:`MAX_NUMBER` or a finite ``float``?

    One pass without the walk's stack (the leaves of boundaries and semantic values are
    such lists). False on anything else - bools, subclasses, None, containers, an integer
    out of range, inf or NaN - and the caller walks the list item by item as before, so the
    verdict and its message are the same either way.
    """
    kinds = set(map(type, v))
    if kinds == _INT:  # the common cases in one C pass each: the loop below gives the same answer
        return max(v) <= MAX_NUMBER and min(v) >= -MAX_NUMBER
    if kinds == _FLOAT:
        s = sum(v)  # finite only when every item is; inf/NaN (or an overflow): the loop decides
        if s - s == 0.0:
            return True
    for x in v:
        t = type(x)
        if t is int:
            if x > MAX_NUMBER or x < -MAX_NUMBER:
                return False
        elif t is float:
            if x - x != 0.0:  # inf - inf and nan - nan are NaN
                return False
        else:
            return False
    return True


_LEAF_TYPES = frozenset({int, float, str, bool, type(None)})


def _sound(value: Any, max_depth: int) -> bool:
    """True when :func:`value_problem` has nothing to report on ``value``; False when it may have.

    Level by level over the parser's plain types (``dict``, ``list``, ``str``, ``int``, ``float``,
    ``bool``, ``None``), each level in a few C passes: ``chain`` flattens a level of lists,
    ``max`` / ``min`` bound its integers, ``sum`` tells its floats finite. Anything else (a
    subclass, a level too deep, a number or string out of range) answers False and the walk
    decides, so a verdict and its message are always the walk's (issue 13: the 3DBAG boundaries'
    thousands of rings went through the walk's stack one by one).
    """
    level, d = [value], 0
    while level:
        kinds = set(map(type, level))
        if list in kinds or dict in kinds:
            if d >= max_depth:
                return False
            if kinds == {list}:
                level = list(chain.from_iterable(level))
                d += 1
                continue
        elif not kinds <= _LEAF_TYPES:
            return False
        nxt = []
        for t in kinds:
            items = level if len(kinds) == 1 else [v for v in level if type(v) is t]
            if t is list:
                nxt.extend(chain.from_iterable(items))
            elif t is dict:
                for v in items:
                    for k in v:
                        if type(k) is not str or len(k) > MAX_STRING:
                            return False
                    nxt.extend(v.values())
            elif t is int:
                if max(items) > MAX_NUMBER or min(items) < -MAX_NUMBER:
                    return False
            elif t is float:
                total = sum(items)  # finite only when every item is (an overflow: the walk decides)
                if total - total != 0.0:
                    return False
            elif t is str:
                if max(map(len, items)) > MAX_STRING:
                    return False
            elif t not in _LEAF_TYPES:
                return False
        level, d = nxt, d + 1
    return True


def value_problem(value: Any, max_depth: int = MAX_DEPTH) -> str | None:
    """What is wrong in a JSON value as a whole (depth, non-finite numbers, huge strings), or None.

    Walks iteratively (no recursion), so it answers for any depth the parser produced; a value
    :func:`_sound` clears in bulk is not walked.
    """
    if _sound(value, max_depth):
        return None
    stack: list[tuple[Any, int, str]] = [(value, 0, "")]
    while stack:
        v, d, where = stack.pop()
        if isinstance(v, list):
            if d >= max_depth:
                return f"nested more than {max_depth} levels deep{where and ' in ' + where}"
            if not _plain_numbers(v):  # a list of sound numbers has nothing to report
                stack.extend((x, d + 1, where) for x in v)
        elif isinstance(v, Mapping):
            if d >= max_depth:
                return f"nested more than {max_depth} levels deep{where and ' in ' + where}"
            for k, x in v.items():
                if len(k) > MAX_STRING:
                    return f"a key of {len(k)} characters"
                stack.append((x, d + 1, where or repr(k[:40])))
        elif isinstance(v, float):
            if not math.isfinite(v):
                return f"a number out of range ({v!r}){where and ' in ' + where}"
        elif isinstance(v, int) and not isinstance(v, bool):
            if abs(v) > MAX_NUMBER:
                return f"an integer out of range ({len(str(abs(v)))} digits){where and ' in ' + where}"
        elif isinstance(v, str):
            if len(v) > MAX_STRING:
                return f"a string of {len(v)} characters{where and ' in ' + where}"
    return None


def _ids_problem(co: Mapping, key: str) -> str | None:
    v = co.get(key)
    if v is None:
        return None
    if not isinstance(v, list):
        return f"'{key}' must be an array of CityObject ids, not {_kind(v)}"
    for x in v:
        if not isinstance(x, str):
            return f"'{key}' must be an array of CityObject ids, not hold {_kind(x)}"
    return None


def cityobject_problem(oid: Any, co: Any) -> str | None:
    """What is wrong with the shape of one CityObject (one line, without its id), or None.

    Checks the members every reader and writer relies on; the geometry's own structure
    (boundaries, semantics, vertex indices) is checked where it is parsed.
    """
    if not isinstance(oid, str) or not oid:
        return f"a CityObject id must be a non-empty string, not {_kind(oid)}"
    if len(oid) > 4096:
        return f"a CityObject id of {len(oid)} characters"
    if not isinstance(co, Mapping):
        return f"CityObject is {_kind(co)}, not a JSON object"
    t = co.get("type")
    if not isinstance(t, str) or not t:
        return "CityObject has no 'type'" if t is None else f"'type' must be a string, not {_kind(t)}"
    for key in ("parents", "children"):
        p = _ids_problem(co, key)
        if p:
            return p
    g = co.get("geometry")
    if g is not None and not isinstance(g, list):
        return f"'geometry' must be an array, not {_kind(g)}"
    for gi, geom in enumerate(g or ()):
        if not isinstance(geom, Mapping):
            return f"geometry {gi} is {_kind(geom)}, not a JSON object"
        sem = geom.get("semantics")
        if sem is not None:
            if not isinstance(sem, Mapping):
                return f"geometry {gi}: 'semantics' must be an object, not {_kind(sem)}"
            surfs = sem.get("surfaces")
            if surfs is not None and not isinstance(surfs, list):
                return f"geometry {gi}: semantic 'surfaces' must be an array, not {_kind(surfs)}"
            vals = sem.get("values")
            if vals is not None and not isinstance(vals, list):
                return f"geometry {gi}: semantic 'values' must be an array, not {_kind(vals)}"
            stack = list(vals or ())
            while stack:
                x = stack.pop()
                if isinstance(x, list):
                    stack.extend(x)
                elif x is not None and (isinstance(x, bool) or not isinstance(x, int)
                                        or not 0 <= x < len(surfs or ())):
                    return f"geometry {gi}: semantic 'values' hold {_kind(x)}, not an index of 'surfaces'"
            for si, s in enumerate(surfs or ()):
                if not isinstance(s, Mapping):
                    return f"geometry {gi}: semantic surface {si} is {_kind(s)}, not an object"
                if not isinstance(s.get("type"), str):
                    return f"geometry {gi}: semantic surface {si} has 'type' {_kind(s.get('type'))}, not a string"
                for key in ("parent", "children"):
                    x = s.get(key)
                    if x is not None and not (isinstance(x, int) and not isinstance(x, bool)) and not (
                            key == "children" and isinstance(x, list)):
                        return f"geometry {gi}: semantic surface {si} has '{key}' {_kind(x)}"
    a = co.get("attributes")
    if a is not None and not isinstance(a, Mapping):
        return f"'attributes' must be an object, not {_kind(a)}"
    return value_problem(co)


def header_problem(doc: Mapping) -> str | None:
    """What is wrong with the file-level members of a CityJSON document (not its CityObjects/vertices)."""
    for key in ("metadata", "extensions", "appearance", "geometry-templates"):
        v = doc.get(key)
        if v is not None and not isinstance(v, Mapping):
            return f"'{key}' must be an object, not {_kind(v)}"
    t = doc.get("transform")
    if t is not None:
        if not isinstance(t, Mapping):
            return f"'transform' must be an object, not {_kind(t)}"
        for key in ("scale", "translate"):
            v = t.get(key)
            if not (isinstance(v, list) and len(v) == 3 and all(
                    isinstance(x, (int, float)) and not isinstance(x, bool) for x in v)):
                return f"'transform' needs '{key}' of 3 numbers, not {_kind(v)}"
    rest = {k: v for k, v in doc.items() if k not in ("CityObjects", "vertices")}
    return value_problem(rest, MAX_HEADER_DEPTH)
