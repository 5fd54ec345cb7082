"""The spine: one per-building job, typed records, validation counted, outputs never over inputs."""
from __future__ import annotations

import collections
import json
import pickle
from pathlib import Path

import pytest

from lod2energy.cli import main
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.options import ExportOptions, PrepareOptions
from lod2energy.pipeline import process_building
from lod2energy.prepare import prepare_building
from lod2energy.records import BuildingRecord
from lod2energy.validate import checks

from cityjson_docs import box_doc, to_seq, write
from factories import box, open_box

REPO = Path(__file__).resolve().parents[1]
DELFT = REPO / "examples" / "delft_subset.city.jsonl"


def run(args, capsys):
    rc = main(args)
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return rc, out, err


@pytest.fixture
def validate_calls(monkeypatch):
    """Every building handed to the validator (the batch function every path goes through)."""
    calls: list[str] = []
    orig = checks.validate_buildings

    def counting(buildings, tol=DEFAULT):
        buildings = list(buildings)
        calls.extend(b.id for b in buildings)
        return orig(buildings, tol)

    monkeypatch.setattr(checks, "validate_buildings", counting)
    return calls


# ----------------------------------------------------------------------------- one job, typed records

def test_process_building_is_pure_picklable_and_returns_a_typed_record(tmp_path):
    from lod2energy.exporters.registry import CityJsonOptions  # noqa: F401 - registry loads
    from lod2energy.validate.memo import geometry_key
    b = box(id="bx")
    before = (geometry_key(b), dict(b.provenance), [dict(o.attributes) for o in b.objects],
              [g.semantic_surfaces for o in b.objects for g in o.geometries])
    opts = ExportOptions(formats=("stl",))
    pb, rec = process_building(b, pickle.loads(pickle.dumps(opts)), str(tmp_path), seq=3)
    assert (geometry_key(b), dict(b.provenance), [dict(o.attributes) for o in b.objects],
            [g.semantic_surfaces for o in b.objects for g in o.geometries]) == before  # input unchanged
    assert isinstance(rec, BuildingRecord) and rec.seq == 3 and rec.outcome == "done"
    assert rec.energy.compliant and rec.energy.geometry_ready and rec.repair.stage == "valid"
    (e,) = rec.exports
    assert e.format == "stl" and e.ok and Path(e.path).is_file() and e.files[0].intact()
    assert BuildingRecord.from_json(json.loads(json.dumps(rec.to_json()))) == rec
    assert pickle.loads(pickle.dumps(pb)).id == "bx"


def test_a_valid_geometry_is_validated_once_in_prepare(validate_calls):
    prepare_building(box(id="v"), PrepareOptions())
    assert validate_calls == ["v"]


def test_a_repaired_geometry_is_validated_as_input_and_after_the_ladder(validate_calls):
    _, rec = prepare_building(open_box(id="o"), PrepareOptions())
    assert rec.repair.stage not in ("", "valid") and rec.energy.geometry_ready
    assert len(validate_calls) <= 3  # input, the ladder's result, the labelled result


def test_export_validates_each_building_at_most_three_times(tmp_path, capsys, validate_calls):
    # input, the CityJSON writer's check of the building on the file's grid, its re-read
    # (212 calls for the 52 buildings of tile901 before the spine; 161 now)
    # (report.html validates the input of each building it draws once more, for the defects'
    # face locations: at most 16 panels, counted separately below)
    rc, _, _ = run(["export", str(DELFT), "-o", str(tmp_path / "o"), "--cityjson", "--idf", "--stl",
                    "-q", "-j", "1", "--no-html"], capsys)
    assert rc == 0
    c = collections.Counter(validate_calls)
    assert len(c) == 10 and max(c.values()) <= 3
    validate_calls.clear()
    rc, _, _ = run(["export", str(DELFT), "-o", str(tmp_path / "h"), "--stl", "-q", "-j", "1"], capsys)
    assert rc == 0 and (tmp_path / "h" / "report.html").is_file()
    assert max(collections.Counter(validate_calls).values()) <= 2  # the job's once, the page's once


def test_report_keeps_its_columns_and_adds_outcome(tmp_path, capsys):
    out = tmp_path / "o"
    rc, _, _ = run(["export", str(DELFT), "-o", str(out), "--stl", "-q", "-j", "1"], capsys)
    assert rc == 0
    head = (out / "report.csv").read_text().splitlines()[0].split(",")
    for col in ("id", "type", "input_errors", "repair_stage", "iou", "compliant", "UA_W_per_K", "stl_ok",
                "message"):
        assert col in head
    assert head[-1] == "outcome"
    rep = json.loads((out / "report.json").read_text())
    b = rep["buildings"][0]
    assert set(b) >= {"repair", "energy", "thermal", "exports", "outcome"} and b["exports"]["stl"]["ok"]
    lines = [json.loads(ln) for ln in (out / "report.jsonl").read_text().splitlines()]
    assert lines[0]["kind"] == "header" and lines[-1] == {"kind": "end", "interrupted": None}
    assert sum(ln["kind"] == "building" for ln in lines) == 10


# ----------------------------------------------------------------------------- issue 19.2: one final check

def _warped_roof_doc(dz: float) -> dict:
    doc = box_doc()
    v = [list(p) for p in doc["vertices"]]
    v[6][2] += int(dz * 1000)  # one roof corner up: the roof is not planar by ~dz/2
    doc["vertices"] = v
    return doc


def test_compliant_means_every_writer_accepts_it_at_the_users_tolerances(tmp_path, capsys):
    src = write(tmp_path, _warped_roof_doc(0.03))
    out = tmp_path / "o"
    # at a lenient tolerance the warped roof is valid: compliant, and the CityJSON writer
    # (checking at the same tolerance) keeps it
    rc, _, _ = run(["export", src, "-o", str(out), "--cityjson", "--stl", "--planarity-d2p-tol", "0.05",
                    "--planarity-n-tol", "30", "-q", "-j", "1"], capsys)
    rows = json.loads((out / "report.json").read_text())["buildings"]
    for r in rows:
        assert bool(r["compliant"]) == bool(r["cityjson_ok"]) == bool(r["stl_ok"]), r
    assert rows[0]["compliant"] is True and rc == 0


def test_final_check_rejects_what_the_writers_would(tmp_path):
    from lod2energy.prepare import final_check
    from lod2energy.validate.codes import Defect
    pb, rec = prepare_building(box(id="fc"), PrepareOptions())
    assert final_check(pb, [], None) is None
    bad = Defect(203, "coid=fc|geom=0|shell=0|face=1", "non planar")
    assert "203" in final_check(pb, [bad], None)
    assert final_check(box(id="raw"), [], None).startswith("no thermal data")


# ----------------------------------------------------------------------------- issue 15: outputs, inputs

def test_validate_report_over_its_input_is_refused(tmp_path, capsys):
    src = write(tmp_path, box_doc())
    before = Path(src).read_bytes()
    rc, _, err = run(["validate", src, "--report", src, "-q"], capsys)
    assert rc == 2 and "input" in err and Path(src).read_bytes() == before


def test_repair_output_over_its_input_is_refused(tmp_path, capsys):
    src = write(tmp_path, box_doc())
    before = Path(src).read_bytes()
    rc, _, err = run(["repair", src, "-o", src, "-q"], capsys)
    assert rc == 2 and Path(src).read_bytes() == before
    rc, _, err = run(["repair", src, "-o", str(tmp_path / "r.city.json"), "--report", src, "-q"], capsys)
    assert rc == 2 and Path(src).read_bytes() == before


def test_export_into_a_folder_holding_the_input_never_writes_over_it(tmp_path, capsys):
    out = tmp_path / "o"
    out.mkdir()
    src = write(out, box_doc(), name="report.json")  # the input has the report's name
    before = Path(src).read_bytes()
    rc, _, err = run(["export", src, "-o", str(out), "--stl", "-q", "-j", "1"], capsys)
    assert rc == 2 and Path(src).read_bytes() == before and "input" in err
    rc, _, _ = run(["export", src, "-o", src, "--stl", "-q"], capsys)
    assert rc == 2 and Path(src).read_bytes() == before


XXE = """<?xml version="1.0" encoding="UTF-8"?>
<!DOCTYPE foo [<!ENTITY xxe SYSTEM "file:///etc/hostname">]>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0"
  xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:gml="http://www.opengis.net/gml">
  <gml:name>&xxe;</gml:name>
  <core:cityObjectMember><bldg:Building gml:id="b1"/></core:cityObjectMember>
</core:CityModel>
"""


def test_external_entity_gets_exit_2_from_export_as_from_validate(tmp_path, capsys):
    src = write(tmp_path, None, "x.gml", XXE)
    rc, _, _ = run(["validate", src, "-q"], capsys)
    assert rc == 2
    out = tmp_path / "o"
    rc, _, err = run(["export", src, "-o", str(out), "--cityjson", "-q", "-j", "1"], capsys)
    assert rc == 2 and err.strip()
    if (out / "report.json").exists():
        rep = json.loads((out / "report.json").read_text())
        assert all(b["id"] not in (None, "None") for b in rep["buildings"])


def test_every_input_object_is_a_row_with_its_problem(tmp_path, capsys):
    doc = box_doc(extra_objects={"b2": box_doc()["CityObjects"]["b1"]})
    lines = to_seq(doc).splitlines()
    lines.insert(2, "{not json")
    src = write(tmp_path, None, "s.city.jsonl", "\n".join(lines))
    out = tmp_path / "o"
    rc, _, _ = run(["export", src, "-o", str(out), "--stl", "-q", "-j", "2"], capsys)
    assert rc == 1
    rows = json.loads((out / "report.json").read_text())["buildings"]
    assert [r["id"] for r in rows] == ["b1", "line 3", "b2"]
    assert rows[1]["outcome"] == "unreadable" and rows[1]["input_errors"] == "901" and rows[1]["message"]


# ----------------------------------------------------------------------------- the journal

def test_journal_skips_a_torn_line_and_starts_anew_for_other_options(tmp_path):
    from lod2energy.run.resume import Journal, header, read_lines
    src = write(tmp_path, box_doc())
    out = tmp_path / "o"
    out.mkdir()
    j = Journal(out / "report.jsonl", out, [src], header(src, {"a": 1}))
    j.append({"kind": "building", "seq": 0})
    j.close()
    with open(out / "report.jsonl", "a") as f:
        f.write('{"kind": "build')  # a crash while appending
    again = Journal(out / "report.jsonl", out, [src], header(src, {"a": 1}), resume=True)
    assert again.resumed and again.previous() == [{"kind": "building", "seq": 0}]
    again.close()
    other = Journal(out / "report.jsonl", out, [src], header(src, {"a": 2}), resume=True)
    assert not other.resumed and other.previous() == []
    other.close()
    assert [ln["kind"] for ln in read_lines(out / "report.jsonl")] == ["header"]


def test_journal_never_follows_a_link_out_of_outdir(tmp_path):
    from lod2energy.run.resume import Journal, header
    from lod2energy.safe_write import UnsafeWriteError
    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    out = tmp_path / "o"
    out.mkdir()
    (out / "report.jsonl").symlink_to(victim)
    with pytest.raises(UnsafeWriteError):
        Journal(out / "report.jsonl", out, [], header(str(victim), {}))
    assert victim.read_text() == "keep"
