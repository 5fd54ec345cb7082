"""The warnings of ``lod2energy export`` grouped by kind on the console: each kind once with its
count and an example building, the grouping of report.html's "Warnings by kind" table
(lod2energy.viz.warnings.WarningTally); none on a clean run; kept with ``-q`` (warnings stay).
"""
from __future__ import annotations

import copy
import json
from collections import Counter

import pytest

import cityjson_docs as docs
from lod2energy.cli import main
from lod2energy.viz.warnings import WarningTally, warning_lines

SENTINEL = "a sentinel or implausible value taken as unknown"


def _row(x0: float, attributes: dict) -> tuple[dict, list]:
    """A 10 x 8 x 6 m box at ``x0`` (its CityObject and its vertices, indexed from 0)."""
    obj = copy.deepcopy(docs.box_doc()["CityObjects"]["b1"])
    obj["attributes"] = attributes
    return obj, [[x + x0, y, z] for x, y, z in docs.BOX_VERTICES]


def _doc(attributes: dict[str, dict]) -> dict:
    """Boxes 30 m apart, one per id, with the given attributes."""
    doc = docs.box_doc()
    doc["CityObjects"], vertices = {}, []
    for i, (bid, attrs) in enumerate(attributes.items()):
        obj, vs = _row(30.0 * i, attrs)
        n = len(vertices)
        obj["geometry"][0]["boundaries"] = [[[[v + n for v in ring] for ring in face] for face in shell]
                                            for shell in obj["geometry"][0]["boundaries"]]
        doc["CityObjects"][bid] = obj
        vertices += vs
    doc["vertices"] = [[int(round(x * 1000)), int(round(y * 1000)), int(round(z * 1000))] for x, y, z in vertices]
    return doc


WARNED = {"a": {"yearOfConstruction": 2099},
          "b": {"yearOfConstruction": 9999, "storeysAboveGround": 9999},
          "c": {"yearOfConstruction": 1975}}


def _warning_lines(err: str) -> list[str]:
    return [ln.removeprefix("lod2energy: warning: ") for ln in err.splitlines()
            if ln.startswith("lod2energy: warning: ") and " building(s): " in ln]


@pytest.mark.parametrize("quiet", [False, True])
def test_a_run_with_warnings_prints_each_kind_once_with_its_count(tmp_path, capsys, quiet):
    src = docs.write(tmp_path, _doc(WARNED))
    out = tmp_path / "out"
    assert main(["export", src, "-o", str(out), "--idf", "--no-html", "-j", "1", *(["-q"] if quiet else [])]) == 0
    captured = capsys.readouterr()
    lines = _warning_lines(captured.err)
    entries = json.loads((out / "report.json").read_text())["buildings"]
    want: Counter = Counter()  # straight from report.json's fields
    first: dict = {}
    for b in entries:
        for f in dict.fromkeys(w["field"] for w in b["thermal"].get("warnings") or ()):
            want[f"{f}: {SENTINEL}"] += 1
            first.setdefault(f"{f}: {SENTINEL}", b["id"])
    assert want == {f"year: {SENTINEL}": 2, f"storeys: {SENTINEL}": 1}
    shown = {}
    for ln in lines:
        count, rest = ln.split(" building(s): ", 1)
        kind, example = rest.rsplit(", e.g. ", 1)
        assert kind not in shown  # each kind once
        shown[kind] = int(count)
        assert example == first[kind]
    assert shown == dict(want)
    assert lines[0].startswith("2 building(s): year:")  # the most frequent first
    assert ("buildings" in captured.out) is not quiet  # -q drops the table, not the warnings


def test_a_clean_run_prints_no_warning_block(tmp_path, capsys):
    src = docs.write(tmp_path, _doc({"c": {"yearOfConstruction": 1975}}))
    assert main(["export", src, "-o", str(tmp_path / "out"), "--idf", "--no-html", "-j", "1"]) == 0
    captured = capsys.readouterr()
    assert "buildings" in captured.out
    assert _warning_lines(captured.err) == [] and "lod2energy: warning:" not in captured.err


def test_the_console_and_the_page_group_alike():
    tally = WarningTally()
    tally.add("a", ("year: x", "energy model downgraded (whole_zone)"))
    tally.add("b", ("year: x",))
    tally.add("c", ())
    table = tally.table({"--buildings ids not in the input": 3})
    assert table == [{"kind": "--buildings ids not in the input", "count": 3, "example": None},
                     {"kind": "year: x", "count": 2, "example": "a"},
                     {"kind": "energy model downgraded (whole_zone)", "count": 1, "example": "a"}]
    assert warning_lines(table) == ["3: --buildings ids not in the input", "2 building(s): year: x, e.g. a",
                                    "1 building(s): energy model downgraded (whole_zone), e.g. a"]
    assert warning_lines(WarningTally().table()) == []


@pytest.mark.parametrize("entry, kind", [
    ({"ok": False, "path": "", "problems": ["IDF not written: timeout: not finished within 3 s"]}, "not written"),
    ({"ok": False, "path": "a.idf", "problems": ["IDF not written: the energy model failed"]}, "not written"),
    ({"ok": False, "path": "a.idf", "problems": ["1 severe: zone not enclosed"]}, "failed its self-check"),
    ({"ok": False, "path": "x.city.json", "problems": ["in the file, not energy-compliant: a sliver"]},
     "left out (not energy-compliant)"),
], ids=["timeout", "no-file", "self-check", "refused"])
def test_an_export_not_ok_is_counted_by_why(entry, kind):
    """A timeout is not reported as a failed self-check (the user reads why no file was written)."""
    fmt = "cityjson" if "city.json" in entry["path"] else "idf"
    tally = WarningTally()
    tally.add_entry({"id": "a", "exports": {fmt: entry}})
    assert [w["kind"] for w in tally.table()] == [f"{fmt}: {kind}"]
