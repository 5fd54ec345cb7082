"""The per-building table of ``--buildings FILE.csv``: the user's year, storeys, use, ... by id.

Columns: ``id`` (required: the CityObject id of the building) and any of :data:`COLUMNS`.
An empty cell means "not given" (the attributes and defaults apply). Values:

- ``year``: an integer, 1001 to this year;
- ``storeys``: an integer, 1-200;
- ``use``: one of :data:`lod2energy.config.USE_TYPES`;
- ``conditioned``: true / false (also yes / no, 1 / 0);
- ``u_wall``, ``u_roof``, ``u_ground``, ``u_window``: W/(m2 K), 0.05-6;
- ``wwr``: window-to-wall ratio, 0 to < 1.

A row's values win over the attributes and over the options for every building (``--use``,
``--u-wall``, ``--wwr``): the table is the more specific. Any problem (unknown column,
repeated id, bad value) is one :class:`~lod2energy.errors.ParameterError` naming the line and
column.
"""
from __future__ import annotations

import csv
import datetime
import io
import math
from pathlib import Path
from typing import Any, Mapping

from lod2energy.config import USE_TYPES
from lod2energy.errors import ParameterError
from lod2energy.model import frozen_mapping
from lod2energy.thermal.facts import boolean

COLUMNS = ("year", "storeys", "use", "conditioned", "u_wall", "u_roof", "u_ground", "u_window", "wwr")
U_RANGE = (0.05, 6.0)  # W/(m2 K), as the U-value check (lod2energy.thermal.uvalues.U_RANGE)


def _value(col: str, text: str) -> Any:
    """The parsed cell, or a ValueError saying what is expected."""
    if col == "year":
        y = _int(text)
        latest = datetime.date.today().year
        if not 1000 < y <= latest:
            raise ValueError(f"a year of construction is 1001-{latest}")
        return y
    if col == "storeys":
        n = _int(text)
        if not 1 <= n <= 200:
            raise ValueError("storeys are 1-200")
        return n
    if col == "use":
        u = text.strip().lower()
        if u not in USE_TYPES:
            raise ValueError(f"a use is one of {', '.join(USE_TYPES)}")
        return u
    if col == "conditioned":
        v = boolean(text)
        if v is None:
            raise ValueError("conditioned is true or false")
        return v
    x = float(text)
    if not math.isfinite(x):
        raise ValueError("not a finite number")
    if col == "wwr":
        if not 0.0 <= x < 1.0:
            raise ValueError("a window-to-wall ratio is 0 to < 1")
        return x
    if not U_RANGE[0] <= x <= U_RANGE[1]:
        raise ValueError(f"a U-value is {U_RANGE[0]}-{U_RANGE[1]} W/(m2 K)")
    return x


def _int(text: str) -> int:
    x = float(text)
    if not math.isfinite(x) or x != int(x):
        raise ValueError("not a whole number")
    return int(x)


def parse_buildings(text: str, where: str) -> dict[str, Mapping[str, Any]]:
    """``{id: {column: value}}`` of a ``--buildings`` CSV text (see the module docstring)."""
    sample = text[:4096]
    try:
        dialect = csv.Sniffer().sniff(sample, delimiters=",;\t") if sample.strip() else csv.excel
    except csv.Error:
        dialect = csv.excel
    reader = csv.DictReader(io.StringIO(text), dialect=dialect)
    fields = [f.strip() for f in (reader.fieldnames or [])]
    if "id" not in fields:
        raise ParameterError(f"{where}: needs an 'id' column (and any of {', '.join(COLUMNS)})")
    unknown = [f for f in fields if f not in COLUMNS and f != "id"]
    if unknown:
        raise ParameterError(f"{where}: unknown column(s) {', '.join(map(repr, unknown))} "
                             f"(known: id, {', '.join(COLUMNS)})")
    out: dict[str, Mapping[str, Any]] = {}
    for line, r in enumerate(reader, start=2):
        r = {(k or "").strip(): v for k, v in r.items()}
        if None in r or "" in r and r[""]:
            raise ParameterError(f"{where} line {line}: more cells than columns")
        bid = (r.get("id") or "").strip()
        if not bid:
            if any((v or "").strip() for v in r.values()):
                raise ParameterError(f"{where} line {line}, column id: empty")
            continue
        if bid in out:
            raise ParameterError(f"{where} line {line}, column id: {bid!r} is given twice")
        row = {}
        for col in COLUMNS:
            text = (r.get(col) or "").strip()
            if not text:
                continue
            try:
                row[col] = _value(col, text)
            except ValueError as e:
                msg = str(e) if not str(e).startswith("could not convert") else "not a number"
                raise ParameterError(f"{where} line {line}, column {col}: {text!r}: {msg}") from None
        out[bid] = frozen_mapping(row)
    return out


def load_buildings(path: str | Path) -> dict[str, Mapping[str, Any]]:
    """The table of ``--buildings`` (ParameterError with one line on any problem)."""
    try:
        text = Path(path).read_text(encoding="utf-8-sig")
    except OSError as e:
        raise ParameterError(f"--buildings {path}: cannot read: {e.strerror}") from None
    except UnicodeDecodeError:
        raise ParameterError(f"--buildings {path}: not a UTF-8 text file") from None
    return parse_buildings(text, f"--buildings {path}")
