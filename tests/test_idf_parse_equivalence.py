"""The fast IDF reader (:func:`lod2energy.exporters.energyplus.idd.parse_idf`) gives the same objects as the
line-by-line reader it replaced, kept here as the reference: on IDF text as the writer
writes it, and on random text of separators, comments, blanks and line breaks (values that
span lines, objects with no ``;``, empty fields, a ``;`` alone on its line)."""
from __future__ import annotations

import random
import re

import pytest

from lod2energy.exporters.energyplus.idd import IdfObject, parse_idf


def _ref_parse_idf(text: str) -> list[IdfObject]:
    out: list[IdfObject] = []
    values: list[str] = []
    start = None
    token: list[str] = []
    for n, raw in enumerate(text.splitlines(), 1):
        line = raw.split("!", 1)[0]
        if not line.strip():
            continue
        for part in re.split(r"([,;])", line):
            if part == ",":
                values.append("".join(token).strip())
                token = []
            elif part == ";":
                values.append("".join(token).strip())
                token = []
                if start is None:
                    start = n
                out.append(IdfObject(values[0], tuple(values[1:]), start))
                values, start = [], None
            elif part.strip():
                if start is None:
                    start = n
                token.append(part)
    if values or "".join(token).strip():
        out.append(IdfObject((values + ["".join(token).strip()])[0], tuple(values[1:]), start or 0))
    return out


_WRITTEN = """!- Written by lod2energy
Version, 25.2;

Building,
  B 1,     !- Name
  0,                       !- North Axis {deg}
  City;           !- Terrain
BuildingSurface:Detailed,
  Wall 1,                  !- Name
  , , ,
  4,                       !- Number of Vertices
  1.000, 2.000, 3.000,     !- X,Y,Z 1 {m}
  1.000
  , 2.000, 3.000,
  1.0e+00,2,3,
  4, 5,
  6
;
Output:Variable,*,Zone Mean Air Temperature,Hourly;
"""


def test_written_idf_text():
    assert parse_idf(_WRITTEN) == _ref_parse_idf(_WRITTEN)
    assert [o.cls for o in parse_idf(_WRITTEN)][-1] == "Output:Variable"


@pytest.mark.parametrize("seed", range(40))
def test_random_text(seed):
    rng = random.Random(seed)
    alphabet = [",", ";", "!", "\n", "\r\n", "\r", " ", "\t", "a", "B", "1.5", "-", "\x0c", "\u2028", "  x y "]
    for _ in range(50):
        text = "".join(rng.choice(alphabet) for _ in range(rng.randint(0, 80)))
        assert parse_idf(text) == _ref_parse_idf(text), repr(text)


@pytest.mark.parametrize("seed", range(40))
def test_random_text_with_newlines_only(seed):
    # the whole-text reader (lod2energy.exporters.energyplus.idd._parse_idf_plain) takes these unless a value
    # spans lines or the text ends inside an object
    from lod2energy.exporters.energyplus.idd import _parse_idf_plain

    rng = random.Random(1000 + seed)
    alphabet = [",", ";", ";", "!", "\n", "\n", " ", "\t", "a", "B", "1.5", "-", "  x y ", "Wall 1", "\u00a0"]
    plain = 0
    for _ in range(80):
        text = "".join(rng.choice(alphabet) for _ in range(rng.randint(0, 60)))
        exp = _ref_parse_idf(text)
        assert parse_idf(text) == exp, repr(text)
        fast = _parse_idf_plain(text)
        assert fast is None or fast == exp, repr(text)
        plain += fast is not None
    assert plain > 3


def test_written_idf_text_read_whole():
    from lod2energy.exporters.energyplus.idd import _parse_idf_plain

    assert _parse_idf_plain(_WRITTEN) == _ref_parse_idf(_WRITTEN)
    text = _WRITTEN.replace("Zone Mean Air", "Zone\n  Mean Air")  # a value over two lines
    assert _parse_idf_plain(text) is None  # falls back to the line reader
    assert parse_idf(text) == _ref_parse_idf(text)
    assert _parse_idf_plain(_WRITTEN + "Timestep, 4") is None  # no ";" at the end
