"""Attribute maps: which attribute of a producer gives a building's year, storeys, use, ...

A map is a TOML file (``--attribute-map FILE``) or a built-in profile
(``lod2energy/data/attribute_maps/<name>.toml``: ``citygml``, ``3dbag``, ``alkis``,
``plateau``, ``osm``, and ``auto``, all of them, the default). One table per field of
:data:`FIELDS`::

    name = "helsinki"               # named in the report (default: the file name)
    include = ["auto"]              # profiles read after this map's own keys ([] for none)

    [year]
    keys = ["Valmistunut"]          # attributes, first usable one wins (root object first)

    [use]
    keys = ["C_KAYTTARK"]
    split = ",;"                    # one value may list several codes: the first known wins
    [use.values]                    # code -> use type (lower-cased, spaces and - as _)
    "011" = "residential"
    [[use.rules]]                   # numeric codes by range, first matching range wins
    pattern = '^31001_(\\d{4})$'    # group 1 is the code
    ranges = [[1000, 1999, "residential"], [0, 9999, "other"]]

    [height]
    keys = ["h_abs"]
    ground = {h_abs = "h_ground"}   # an absolute height and the ground level it is measured from

``use`` values are one of :data:`lod2energy.config.USE_TYPES`; ``conditioned`` values are
booleans; other fields take the attribute's value as it is (``roof_type`` through its value
table when one is given). Fields: ``year``, ``storeys``, ``storey_heights`` (m, a list or a
whitespace-separated string), ``height`` (m above ground), ``footprint`` (m2),
``shared_wall`` (m2 of party walls), ``use``, ``conditioned``, ``roof_type``.
"""
from __future__ import annotations

import re
import sys
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any, Mapping

from lod2energy import cache
from lod2energy.config import USE_TYPES
from lod2energy.errors import ParameterError
from lod2energy.model import Building, frozen_mapping

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

FIELDS = ("year", "storeys", "storey_heights", "height", "footprint", "shared_wall", "use", "conditioned",
          "roof_type")
DEFAULT_PROFILE = "auto"
_TOP = {"name", "description", "include"} | set(FIELDS)
_FIELD_KEYS = {"keys", "values", "rules", "split", "scheme", "ground"}


def normalise(value: Any) -> str:
    """A value as table keys are compared: lower-cased, stripped, spaces and hyphens as ``_``."""
    return re.sub(r"[\s\-]+", "_", str(value).strip().lower())


@dataclass(frozen=True)
class Rule:
    """Numeric codes by range: ``pattern``'s group 1 (or the whole match) is the code."""

    pattern: str
    ranges: tuple[tuple[float, float, Any], ...]
    scheme: str

    def apply(self, s: str) -> Any:
        m = re.fullmatch(self.pattern, s)
        if not m:
            return None
        try:
            code = float(m.group(1) if m.groups() else m.group(0))
        except (TypeError, ValueError):
            return None
        return next((v for lo, hi, v in self.ranges if lo <= code <= hi), None)


@dataclass(frozen=True)
class FieldMap:
    """How one field is read: attribute keys in order, value tables, ground-level keys."""

    keys: tuple[str, ...] = ()
    values: Mapping[str, tuple[Any, str]] = field(default_factory=dict)  # normalised value -> (result, scheme)
    rules: tuple[Rule, ...] = ()
    split: str = ""
    scheme: str = ""
    ground: Mapping[str, str] = field(default_factory=dict)
    tabled: bool = False  # values of this field must come through a table (use)

    def translate(self, value: Any) -> tuple[Any, str] | None:
        """``(value, scheme)`` of one attribute value through the tables; None when unknown."""
        if value is None or (isinstance(value, bool) and self.tabled):
            return None
        if isinstance(value, (list, tuple)):
            return next((r for r in map(self.translate, value) if r is not None), None)
        s = str(value).strip()
        if not s:
            return None
        parts = [s] + ([p for p in re.split("[" + re.escape(self.split) + r"]\s*", s) if p] if self.split else [])
        for p in parts:
            key = normalise(p)
            if key in self.values:
                return self.values[key]
            for r in self.rules:
                v = r.apply(p.strip())
                if v is not None:
                    return v, r.scheme
        return None


@dataclass(frozen=True)
class Found:
    """One value read from a building's attributes.

    Attributes
    ----------
    value : Any
        After the field's value table, if any.
    key : str
        The attribute read.
    raw : Any
        The attribute's value as given.
    scheme : str
        The value table's name ("" without one).
    """

    value: Any
    key: str
    raw: Any
    scheme: str = ""


@dataclass(frozen=True)
class AttributeMap:
    """A parsed attribute map (picklable; it travels with the options to the workers).

    Attributes
    ----------
    name : str
        Named in the report.
    fields : mapping
        Field name -> :class:`FieldMap`, includes merged in.
    user : frozenset of str
        Attribute keys given by a user's map (values read through them have source ``map``;
        those of the built-in profiles ``attribute``).
    """

    name: str
    fields: Mapping[str, FieldMap]
    user: frozenset = frozenset()

    def field(self, name: str) -> FieldMap:
        return self.fields.get(name) or FieldMap(tabled=name == "use")

    def source(self, key: str) -> str:
        """``"map"`` for a key of the user's map, ``"attribute"`` for one of a built-in profile."""
        return "map" if key in self.user else "attribute"

    def read(self, b: Building, name: str, parse=None) -> Found | None:
        """The first usable value of field ``name`` on ``b`` (root object first, then its parts).

        Parameters
        ----------
        parse : callable, optional
            Value -> parsed value or None (unusable, the next key is tried); applied after the
            field's tables. Fields that need a table (``use``) take only values a
            table knows; the others keep an untabled value as it is.
        """
        fm = self.field(name)
        for o in b.objects:
            for k in fm.keys:
                if k not in o.attributes:
                    continue
                raw = o.attributes[k]
                t = fm.translate(raw) if (fm.values or fm.rules) else None
                if t is None and fm.tabled:
                    continue
                v, scheme = t if t is not None else (raw, "")
                if parse is not None:
                    v = parse(v)
                if v is None:
                    continue
                return Found(v, k, raw, scheme)
        return None


def _check_field(name: str, d: Any, where: str) -> FieldMap:
    if not isinstance(d, Mapping):
        raise ParameterError(f"{where}: [{name}] must be a table")
    bad = set(d) - _FIELD_KEYS
    if bad:
        raise ParameterError(f"{where}: [{name}] has unknown entries {', '.join(sorted(bad))} "
                             f"(known: {', '.join(sorted(_FIELD_KEYS))})")
    keys = d.get("keys", [])
    if isinstance(keys, str):
        keys = [keys]
    if not isinstance(keys, list) or not all(isinstance(k, str) and k for k in keys):
        raise ParameterError(f"{where}: [{name}] keys must be a list of attribute names")
    values = d.get("values", {})
    if not isinstance(values, Mapping):
        raise ParameterError(f"{where}: [{name}.values] must be a table of value = result")
    for k, v in values.items():
        _check_result(name, v, f"{where}: [{name}.values] {k!r}")
    rules = []
    for i, r in enumerate(d.get("rules", []) or []):
        w = f"{where}: [[{name}.rules]] #{i + 1}"
        if not isinstance(r, Mapping) or not isinstance(r.get("pattern"), str):
            raise ParameterError(f"{w} needs a pattern (a regular expression)")
        try:
            re.compile(r["pattern"])
        except re.error as e:
            raise ParameterError(f"{w}: pattern {r['pattern']!r}: {e}") from None
        ranges = []
        for rg in r.get("ranges", []):
            if not (isinstance(rg, list) and len(rg) == 3 and all(
                    isinstance(x, (int, float)) and not isinstance(x, bool) for x in rg[:2])):
                raise ParameterError(f"{w}: each range is [low, high, result], got {rg!r}")
            _check_result(name, rg[2], w)
            ranges.append((float(rg[0]), float(rg[1]), rg[2]))
        rules.append(Rule(r["pattern"], tuple(ranges), str(r.get("scheme") or d.get("scheme") or where)))
    ground = d.get("ground", {})
    if not isinstance(ground, Mapping) or not all(isinstance(v, str) for v in ground.values()):
        raise ParameterError(f"{where}: [{name}] ground must be a table of height key = ground level key")
    scheme = str(d.get("scheme") or where)
    return FieldMap(tuple(keys), frozen_mapping({normalise(k): (v, scheme) for k, v in values.items()}),
                    tuple(rules), str(d.get("split", "")), scheme, frozen_mapping(dict(ground)),
                    name == "use")


def _check_result(name: str, v: Any, where: str) -> None:
    if name == "use" and (not isinstance(v, str) or v not in USE_TYPES):
        raise ParameterError(f"{where}: a use must be one of {', '.join(USE_TYPES)}, got {v!r}")
    if name == "conditioned" and not isinstance(v, bool):
        raise ParameterError(f"{where}: conditioned values must be true or false, got {v!r}")


def _merge(a: FieldMap, b: FieldMap) -> FieldMap:
    """``a`` read first, then what ``b`` adds."""
    keys = a.keys + tuple(k for k in b.keys if k not in a.keys)
    values = dict(b.values)
    values.update(a.values)
    return FieldMap(keys, frozen_mapping(values), a.rules + b.rules, a.split or b.split, a.scheme or b.scheme,
                    frozen_mapping({**b.ground, **a.ground}), a.tabled or b.tabled)


def parse_map(text: str, where: str, default_name: str, seen: tuple[str, ...] = (),
              builtin: bool = False) -> AttributeMap:
    """An :class:`AttributeMap` from TOML text (ParameterError naming ``where`` on any problem)."""
    try:
        d = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise ParameterError(f"{where}: not valid TOML: {e}") from None
    bad = set(d) - _TOP
    if bad:
        raise ParameterError(f"{where}: unknown entries {', '.join(sorted(bad))} "
                             f"(fields: {', '.join(FIELDS)}; also name, description, include)")
    fields = {n: _check_field(n, d[n], where) for n in FIELDS if n in d}
    user = frozenset() if builtin else frozenset(k for f in fields.values() for k in f.keys)
    include = d.get("include", [] if builtin else [DEFAULT_PROFILE])
    if isinstance(include, str):
        include = [include]
    if not isinstance(include, list):
        raise ParameterError(f"{where}: include must be a list of profile names")
    for inc in include:
        if inc in seen:
            raise ParameterError(f"{where}: profile {inc!r} includes itself")
        try:
            other = profile(str(inc), seen + (default_name,))
        except ParameterError as e:
            raise ParameterError(f"{where}: include: {e}") from None
        for n, fm in other.fields.items():
            fields[n] = _merge(fields[n], fm) if n in fields else fm
    return AttributeMap(str(d.get("name") or default_name), frozen_mapping(fields), user)


def profiles() -> tuple[str, ...]:
    """Names of the built-in profiles."""
    d = resources.files("lod2energy") / "data" / "attribute_maps"
    return tuple(sorted(p.name[:-5] for p in d.iterdir() if p.name.endswith(".toml")))


def profile(name: str, seen: tuple[str, ...] = ()) -> AttributeMap:
    """A built-in profile by name (read once per process)."""
    def read():
        p = resources.files("lod2energy") / "data" / "attribute_maps" / f"{name}.toml"
        if not p.is_file():
            raise ParameterError(f"no built-in attribute profile {name!r} (known: {', '.join(profiles())})")
        return parse_map(p.read_text(encoding="utf-8"), f"attribute profile {name}", name, seen, builtin=True)
    return cache.remember("thermal.attribute-maps", name, read, 16)


def load_attribute_map(spec: str | Path | None) -> AttributeMap:
    """The map of ``--attribute-map``: a TOML file, or the name of a built-in profile; None: ``auto``."""
    if spec is None:
        return profile(DEFAULT_PROFILE)
    p = Path(spec)
    if not p.suffix and not p.exists():
        if str(spec) in profiles():
            return profile(str(spec))
        raise ParameterError(f"--attribute-map {spec}: no such file nor built-in profile "
                             f"(profiles: {', '.join(profiles())})")
    try:
        text = p.read_text(encoding="utf-8-sig")
    except OSError as e:
        raise ParameterError(f"--attribute-map {spec}: cannot read: {e.strerror}") from None
    except UnicodeDecodeError:
        raise ParameterError(f"--attribute-map {spec}: not a UTF-8 text file") from None
    return parse_map(text, f"--attribute-map {spec}", p.stem)
