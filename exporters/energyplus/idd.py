"""EnergyPlus's Input Data Dictionary (``Energy+.idd``) read once, and IDF text checked against it.

The IDD is parsed once per process (:func:`load_idd`) into frozen object and field
definitions; :func:`check_idf` tests a file the way EnergyPlus's input processor does before
it simulates:

- every object is a class of the IDD (case-insensitive), with no more fields than the IDD
  defines (extensible objects repeat their last ``\\extensible:N`` fields);
- ``\\required-field`` fields are given (or have a ``\\default``), ``\\unique-object`` classes
  appear at most once and ``\\required-object`` classes at least once;
- numeric fields are numbers (or ``autosize`` / ``autocalculate`` where the IDD allows them),
  integers where ``\\type integer``, within ``\\minimum``/``\\minimum>``/``\\maximum``/
  ``\\maximum<``; ``\\type choice`` fields hold one of their ``\\key`` values;
- the ``Version`` object matches the IDD's version (major.minor).

Field values are read as EnergyPlus reads them: ``!`` starts a comment, ``,`` separates
fields, ``;`` ends an object, surrounding blanks are dropped.
"""
from __future__ import annotations

import functools
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from lod2energy import cache


@dataclass(frozen=True)
class FieldDef:
    """One field of an IDD class.

    Attributes
    ----------
    name : str
        ``\\field`` text, e.g. "Vertex 1 X-coordinate".
    numeric : bool
        An ``N`` field (else ``A``).
    type : str
        ``\\type`` (alpha, choice, object-list, real, integer, node, external-list).
    required : bool
    keys : tuple of str
        ``\\key`` values, upper case.
    minimum, maximum : float or None
    min_exclusive, max_exclusive : bool
        ``\\minimum>`` / ``\\maximum<``.
    autosizable, autocalculatable : bool
    default : str or None
    """
    name: str
    numeric: bool
    type: str
    required: bool = False
    keys: tuple[str, ...] = ()
    minimum: float | None = None
    maximum: float | None = None
    min_exclusive: bool = False
    max_exclusive: bool = False
    autosizable: bool = False
    autocalculatable: bool = False
    default: str | None = None


@dataclass(frozen=True)
class ClassDef:
    """One IDD class (object type).

    Attributes
    ----------
    name : str
        As the IDD spells it ("BuildingSurface:Detailed").
    fields : tuple of FieldDef
    extensible : int
        ``\\extensible:N`` (0: not extensible).
    first_extensible : int
        Index of the ``\\begin-extensible`` field (``len(fields)`` when none).
    unique, required : bool
        ``\\unique-object``, ``\\required-object``.
    """
    name: str
    fields: tuple[FieldDef, ...]
    extensible: int = 0
    first_extensible: int = 0
    unique: bool = False
    required: bool = False

    def field(self, i: int) -> FieldDef | None:
        """Definition of field ``i`` (0-based, after the class name); extensible classes
        repeat their last ``extensible`` fields. None beyond a non-extensible class."""
        if i < len(self.fields):
            return self.fields[i]
        if not self.extensible:
            return None
        k0 = self.first_extensible
        return self.fields[k0 + (i - k0) % self.extensible]

    @functools.cached_property
    def field_index(self) -> dict[str, int]:
        """``{upper-case field name: index}``, built on first use and kept (the IDF self-check
        looks fields up tens of thousands of times a file); callers must not modify it."""
        return {f.name.upper(): i for i, f in enumerate(self.fields)}

    @functools.cached_property
    def plain_tail(self) -> int | None:
        """:func:`_plain_tail` of the class, found on first use and kept."""
        return _plain_tail(self)


@dataclass(frozen=True)
class Idd:
    """A parsed ``Energy+.idd``: ``version`` ("25.2.0") and ``classes`` by upper-case name."""
    version: str
    classes: dict

    def __hash__(self) -> int:  # frozen with a dict: hash by identity (one per process)
        return id(self)


@dataclass(frozen=True)
class IdfObject:
    """One object of an IDF file: its class as written, its field values, its first line."""
    cls: str
    fields: tuple[str, ...]
    line: int


_FIELD_ID = re.compile(r"^[AN]\d+$")


def _num(text: str) -> float | None:
    try:
        return float(text.strip().split()[0])
    except (ValueError, IndexError):
        return None


#: A line that starts a class (its first value is not a field id such as ``A1`` / ``N12``):
#: where :func:`parse_idd` cuts the IDD into one text a class.
_CLASS_LINE = re.compile(r"^[ \t]*(?![AN]\d+[ \t]*[,;])([A-Za-z][^,;\\!\n]*?)[ \t]*[,;]", re.M)
#: A value line that is neither a class line (one name, then ``,`` or ``;``) nor field ids
#: only: an IDD :data:`_CLASS_LINE` may cut wrong (a class named after a field on its line, a
#: name without a separator...), read whole as before. Energy+.idd has none.
_ODD_LINE = re.compile(r"^[ \t]*(?!(?:[AN]\d+[ \t]*[,;][ \t]*)+(?:[\\!][^\n]*)?$)"
                       r"(?![A-Za-z][^,;\\!\n]*[,;][ \t]*(?:[\\!][^\n]*)?$)[^\s\\!]", re.M)
#: ``\unique-object`` / ``\required-object`` lines, and the first field line of a class.
_FLAG_LINE = re.compile(r"^[ \t]*\\(unique-object|required-object)(?=[ \t\r]|$)", re.M | re.I)
_FIELD_LINE = re.compile(r"^[ \t]*[AN]\d+[ \t]*[,;]", re.M)


def parse_idd(text: str) -> Idd:
    """Parse the text of an ``Energy+.idd``.

    The text is cut into one piece a class (:data:`_CLASS_LINE`); a class is read from its
    piece the first time it is asked for (:class:`_Classes`), as :func:`_read_classes` reads
    the whole text: a file uses a few dozen of the IDD's ~850 classes.
    """
    m = re.search(r"!IDD_Version\s+(\S+)", text)
    version = m.group(1) if m else ""
    if _ODD_LINE.search(text) is not None:
        whole = _read_classes(text)
        return Idd(version, _Classes(text, dict.fromkeys(whole, (0, 0)), whole))
    starts = [(c.start(), c.group(1).strip()) for c in _CLASS_LINE.finditer(text)]
    pieces: dict[str, tuple[int, int]] = {}
    for k, (at, name) in enumerate(starts):
        pieces[name.upper()] = (at, starts[k + 1][0] if k + 1 < len(starts) else len(text))
    return Idd(version, _Classes(text, pieces))


def _read_classes(text: str) -> dict[str, dict]:
    """Every class of an IDD text as read, by upper-case name (name, fields, attributes)."""
    as_read: dict[str, dict] = {}  # upper-case name -> the class as read (name, fields, attributes)
    cur: dict | None = None
    fld: dict | None = None

    def close_field():
        nonlocal fld
        if fld is not None and cur is not None:
            cur["fields"].append(fld)
        fld = None

    def close_class():
        nonlocal cur
        close_field()
        if cur is not None:
            as_read[cur["name"].upper()] = cur  # complete: the parser no longer holds it
        cur = None

    def attribute(attr: str):
        target = fld if fld is not None else cur
        if target is None:
            return
        key, _, value = attr.partition(" ")
        value = value.strip()
        low = key.lower()
        if fld is not None:
            if low == "field":
                fld["name"] = value
            elif low == "required-field":
                fld["required"] = True
            elif low == "type":
                fld["type"] = value.lower()
            elif low == "key":
                fld.setdefault("keys", []).append(value.upper())
            elif low in ("minimum", "minimum>"):
                fld["minimum"] = _num(value)
                fld["min_exclusive"] = low.endswith(">")
            elif low in ("maximum", "maximum<"):
                fld["maximum"] = _num(value)
                fld["max_exclusive"] = low.endswith("<")
            elif low == "autosizable":
                fld["autosizable"] = True
            elif low == "autocalculatable":
                fld["autocalculatable"] = True
            elif low == "default":
                fld["default"] = value
            elif low == "begin-extensible":
                fld["begin_ext"] = True
        else:
            if low.startswith("extensible:"):
                cur["extensible"] = int(re.match(r"\d+", low.split(":", 1)[1]).group(0))
            elif low == "unique-object":
                cur["unique"] = True
            elif low == "required-object":
                cur["required"] = True

    for raw in text.splitlines():
        line = raw.split("!", 1)[0].strip()
        if not line:
            continue
        if line.startswith("\\"):
            if line.lower().startswith("\\group"):
                continue
            attribute(line[1:])
            continue
        code, sep, attr = line.partition("\\")
        for tok in (t.strip() for t in re.split(r"[,;]", code)):
            if not tok:
                continue
            if _FIELD_ID.match(tok) and cur is not None:
                close_field()
                fld = {"name": tok, "numeric": tok[0] == "N"}
            else:
                close_class()
                cur = {"name": tok, "fields": []}
        if sep:
            attribute(attr)
    close_class()
    return as_read


def _class_def(cur: dict) -> ClassDef:
    """The :class:`ClassDef` of a class as :func:`parse_idd` read it."""
    fields = tuple(FieldDef(
        name=f["name"], numeric=f["numeric"],
        type=f.get("type") or ("real" if f["numeric"] else "alpha"),
        required=f.get("required", False), keys=tuple(f.get("keys", ())),
        minimum=f.get("minimum"), maximum=f.get("maximum"),
        min_exclusive=f.get("min_exclusive", False), max_exclusive=f.get("max_exclusive", False),
        autosizable=f.get("autosizable", False), autocalculatable=f.get("autocalculatable", False),
        default=f.get("default")) for f in cur["fields"])
    first = next((i for i, f in enumerate(cur["fields"]) if f.get("begin_ext")), len(fields))
    return ClassDef(cur["name"], fields, cur.get("extensible", 0), first,
                    cur.get("unique", False), cur.get("required", False))


class _Classes(Mapping):
    """``{upper-case class name: ClassDef}`` of a parsed IDD, each class read from its piece of
    the text and its :class:`ClassDef` built the first time it is asked for (what is built
    depends only on the class's own lines). ``whole``: every class already read (an IDD with a
    line :data:`_ODD_LINE` finds); a piece that does not read as exactly its one class makes
    the whole text be read, too."""

    def __init__(self, text: str, pieces: dict[str, tuple[int, int]], whole: dict[str, dict] | None = None):
        self._text, self._pieces = text, pieces
        self._all = whole  # the whole text read at once (the fallback)
        self._built: dict[str, ClassDef] = {}
        self._flags: list[tuple[str, bool, bool]] | None = None

    def _as_read(self, key: str) -> dict:
        if self._all is None:
            at, end = self._pieces[key]
            one = _read_classes(self._text[at:end])
            if len(one) == 1 and key in one:
                return one[key]
            self._all = _read_classes(self._text)
            if list(self._all) != list(self._pieces):
                self._pieces = dict.fromkeys(self._all, (0, 0))
        return self._all[key]

    def __getitem__(self, key: str) -> ClassDef:
        c = self._built.get(key)
        if c is None:
            c = self._built[key] = _class_def(self._as_read(key))
        return c

    def __iter__(self):
        return iter(self._pieces)

    def __len__(self) -> int:
        return len(self._pieces)

    def __contains__(self, key) -> bool:
        return key in self._pieces

    def get(self, key, default=None):
        """``Mapping.get`` without its exception round trip (the self-check asks once per object)."""
        c = self._built.get(key)
        if c is not None:
            return c
        return self[key] if key in self._pieces else default

    def flags(self) -> list[tuple[str, bool, bool]]:
        """``(name, unique, required)`` of the ``\\unique-object`` / ``\\required-object``
        classes, in IDD order, without reading any class: the flag lines of each piece before
        its first field (found once: the classes as read do not change)."""
        if self._flags is None:
            out = []
            for key, (at, end) in self._pieces.items():
                if self._all is not None:
                    c = self._all[key]
                    if c.get("unique") or c.get("required"):
                        out.append((c["name"], c.get("unique", False), c.get("required", False)))
                    continue
                first = _FIELD_LINE.search(self._text, at, end)
                head_end = first.start() if first is not None else end
                found = {f.group(1).lower() for f in _FLAG_LINE.finditer(self._text, at, head_end)}
                if found:
                    name = _CLASS_LINE.match(self._text, at).group(1).strip()
                    out.append((name, "unique-object" in found, "required-object" in found))
            self._flags = out
        return list(self._flags)


def _class_flags(idd: Idd) -> list[tuple[str, bool, bool]]:
    """``(name, unique, required)`` of the classes that are unique or required, in IDD order."""
    if isinstance(idd.classes, _Classes):
        return idd.classes.flags()
    return [(c.name, c.unique, c.required) for c in idd.classes.values() if c.unique or c.required]


@cache.memoize("idd.parsed", 4)
def load_idd(path: str) -> Idd:
    """The parsed IDD at ``path``, read once per process."""
    return parse_idd(Path(path).read_text(encoding="latin-1"))


_IDF_SEP = re.compile(r"([,;])")


#: Line breaks of ``str.splitlines`` other than ``\n``: a text with none of them is read by
#: :func:`_parse_idf_plain`.
_ODD_BREAK = re.compile("[\r\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029]")
_COMMENT = re.compile(r"!.*")
_FIRST_PIECE = re.compile(r"[^\s,]")


def parse_idf(text: str) -> list[IdfObject]:
    """The objects of an IDF text, in order (comments removed, values stripped).

    A value may span lines (its pieces are joined, then stripped); an object's line is that
    of its first non-blank piece (or of its ``;``).
    """
    if _ODD_BREAK.search(text) is None:
        out = _parse_idf_plain(text)
        if out is not None:
            return out
    return _parse_idf_lines(text)


def _parse_idf_plain(text: str) -> list[IdfObject] | None:
    """:func:`parse_idf` of a text whose lines end in ``\n`` only, every value on one line and
    nothing but blanks and comments after the last ``;`` (what the writer writes), on the
    whole text at once; None for any other text.

    With comments removed (line breaks kept), each object is the text before a ``;`` and its
    values its ``,``-separated parts, stripped: a part's non-blank characters lie on one line,
    so the line reader's joined pieces are that line's part. Its line is that of the first
    character neither blank nor ``,`` (the first non-blank piece), or of the ``;``.
    """
    body = _COMMENT.sub("", text)
    chunks = body.split(";")
    if chunks.pop().strip():
        return None  # an object without its ";"
    out: list[IdfObject] = []
    pos = counted = 0
    line = 1
    find, count = _FIRST_PIECE.search, body.count
    for chunk in chunks:
        values = [v.strip() for v in chunk.split(",")]
        if "\n" in chunk:
            for v in values:
                if "\n" in v:
                    return None  # a value over several lines
        m = find(chunk)
        at = pos + (m.start() if m is not None else len(chunk))
        line += count("\n", counted, at)
        counted = at
        out.append(IdfObject(values[0], tuple(values[1:]), line))
        pos += len(chunk) + 1
    return out


def _parse_idf_lines(text: str) -> list[IdfObject]:
    """:func:`parse_idf` line by line (any text)."""
    out: list[IdfObject] = []
    values: list[str] = []
    start = None
    token: list[str] = []  # the pieces of the value being read (each with a non-blank character)
    split = _IDF_SEP.split
    for n, raw in enumerate(text.splitlines(), 1):
        line = raw.partition("!")[0]
        if not line or line.isspace():
            continue
        parts = split(line)
        if len(parts) == 1:  # no separator: a piece of a value that goes on
            if start is None:
                start = n
            token.append(line)
            continue
        for part in parts:
            if part == ",":
                values.append("".join(token).strip() if token else "")
                token = []
            elif part == ";":
                values.append("".join(token).strip() if token else "")
                token = []
                out.append(IdfObject(values[0], tuple(values[1:]), n if start is None else start))
                values, start = [], None
            elif part and not part.isspace():
                if start is None:
                    start = n
                token.append(part)
    if values or "".join(token).strip():
        out.append(IdfObject((values + ["".join(token).strip()])[0], tuple(values[1:]), start or 0))
    return out


def _field_problem(f: FieldDef, v: str) -> str | None:
    if f.numeric:
        low = v.lower()
        if low == "autosize" and f.autosizable or low == "autocalculate" and f.autocalculatable:
            return None
        try:
            x = float(v)
        except ValueError:
            return f"{v!r} is not a number"
        if not math.isfinite(x):
            return f"{v!r} is not a finite number"
        if f.type == "integer" and not x.is_integer():
            return f"{v!r} is not an integer"
        if f.minimum is not None and (x <= f.minimum if f.min_exclusive else x < f.minimum):
            return f"{v} is below the minimum {'>' if f.min_exclusive else ''}{f.minimum:g}"
        if f.maximum is not None and (x >= f.maximum if f.max_exclusive else x > f.maximum):
            return f"{v} is above the maximum {'<' if f.max_exclusive else ''}{f.maximum:g}"
        return None
    if f.type == "choice" and f.keys and v.upper() not in f.keys:
        return f"{v!r} is not one of {', '.join(f.keys[:6])}{', ...' if len(f.keys) > 6 else ''}"
    return None


def _plain_real(f: FieldDef) -> bool:
    """Is any finite number a valid value of field ``f`` (a real with no bounds), so that
    :func:`_field_problem` finds nothing in a value ``float`` reads as finite?"""
    return (f.numeric and f.type != "integer" and f.minimum is None and f.maximum is None)


def _plain_tail(c: ClassDef) -> int | None:
    """Index of the first field from which every field of an extensible class (its repeated
    group included) is :func:`_plain_real` (vertex coordinates), or None."""
    if not c.extensible:
        return None
    k = len(c.fields)
    while k > 0 and _plain_real(c.fields[k - 1]):
        k -= 1
    return k if k <= c.first_extensible else None


#: The :mod:`lod2energy.cache` table of :func:`_object_problems` of objects without a coordinate
#: list, by class, IDD version and fields (an IDF repeats them from file to file: materials,
#: schedules, output requests), and its size.
OBJECT_PROBLEMS = "idd.object_problems"
OBJECT_PROBLEMS_KEPT = 4096


def _object_problems(idd: Idd, c: ClassDef, fields: tuple[str, ...]) -> tuple[str, ...]:
    """What :func:`check_idf` reports for one object of class ``c`` (each problem without its
    ``line N:`` prefix, in the order found; all of them)."""
    tail = c.plain_tail
    if tail is not None and len(fields) > tail:
        head, rest = fields[:tail], fields[tail:]
        try:  # the common case: every value of the coordinate list a finite number
            clean = all(map(math.isfinite, map(float, rest)))
        except ValueError:
            clean = False
        if clean:
            return _fields_problems(idd, c, fields, len(head))
        return _fields_problems(idd, c, fields, len(fields))
    key = (id(c), idd.version, fields)
    hit = cache.recall(OBJECT_PROBLEMS, key)
    if hit is not None and hit[0] is c:  # the entry holds its class: its id is not reused
        return hit[1]
    found = _fields_problems(idd, c, fields, len(fields))
    cache.keep(OBJECT_PROBLEMS, key, (c, found), OBJECT_PROBLEMS_KEPT)
    return found


def _fields_problems(idd: Idd, c: ClassDef, fields: tuple[str, ...], n_checked: int) -> tuple[str, ...]:
    """The problems of one object, its values checked one by one up to ``n_checked`` (those
    after it known to be fine)."""
    problems: list[str] = []
    if not c.extensible and len(fields) > len(c.fields):
        return (f"{c.name} has {len(fields)} fields, the IDD defines {len(c.fields)}",)
    if c.extensible and len(fields) > c.first_extensible and (len(fields) - c.first_extensible) % c.extensible:
        problems.append(f"{c.name} ends inside a group of {c.extensible} extensible fields")
    for i, f in enumerate(c.fields[:c.first_extensible]):
        v = fields[i] if i < len(fields) else ""
        if f.required and not v and f.default is None:
            problems.append(f"{c.name}: required field {f.name!r} is empty")
    for i in range(n_checked):
        v = fields[i]
        if not v:
            continue
        f = c.field(i)
        why = _field_problem(f, v)
        if why:
            problems.append(f"{c.name}, {f.name}: {why}")
    if c.name == "Version" and fields and idd.version:
        want = ".".join(idd.version.split(".")[:2])
        got = ".".join(fields[0].split(".")[:2])
        if got != want:
            problems.append(f"Version {fields[0]} but the IDD is {idd.version}")
    return tuple(problems)


def check_idf(objects: list[IdfObject], idd: Idd, max_problems: int = 20) -> list[str]:
    """Problems EnergyPlus's input processor would report for these objects (empty: none).

    Parameters
    ----------
    objects : list of IdfObject
        :func:`parse_idf` of the file.
    idd : Idd
    max_problems : int
        Stop after this many.
    """
    problems: list[str] = []
    seen: dict[str, int] = {}
    classes = idd.classes
    for o in objects:
        if len(problems) >= max_problems:
            break
        c = classes.get(o.cls.upper())
        if c is None:
            problems.append(f"line {o.line}: unknown object {o.cls!r}")
            continue
        seen[c.name] = seen.get(c.name, 0) + 1
        found = _object_problems(idd, c, o.fields)
        if found:
            for why in found:
                problems.append(f"line {o.line}: {why}")
                if len(problems) >= max_problems:
                    break
    for name, unique, required in _class_flags(idd):
        if unique and seen.get(name, 0) > 1:
            problems.append(f"{name} appears {seen[name]} times (a unique object)")
        if required and not seen.get(name):
            problems.append(f"required object {name} is missing")
    return problems[:max_problems]
