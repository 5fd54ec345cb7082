"""Command line: exit codes, report shape, bad input without tracebacks."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest

from lod2energy.cli import main

from cityjson_docs import box_doc, to_seq, write


def run(args, capsys):
    rc = main(args)
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return rc, out, err


def test_valid_file_exits_0_and_writes_a_val3dity_shaped_report(tmp_path, capsys):
    rep = tmp_path / "r.json"
    rc, out, _ = run(["validate", write(tmp_path, box_doc()), "--report", str(rep)], capsys)
    assert rc == 0 and "b.city.json" in out
    r = json.loads(rep.read_text())
    assert r["type"] == "val3dity_report" and r["validity"] is True and r["dataset_errors"] == []
    assert r["parameters"]["snap_tol"] == 0.001 and r["parameters"]["planarity_n_tol"] == 20.0
    (f,) = r["features"]
    assert (f["id"], f["type"], f["validity"], f["errors"]) == ("b1", "Building", True, [])
    e = f["energy"]
    assert e["closed_2manifold"] and e["outward_normals"] and e["no_degenerate_faces"]
    assert e["labelled"] is None and e["u_values"] is None and e["compliant"] is False
    assert (e["N_b"], e["N_nm"], e["status"]) == (0, 0, "watertight")
    assert f["graph"]["faces"] == 6
    assert r["features_overview"] == [{"type": "Building", "total": 1, "valid": 1}]


def test_broken_building_exits_1_and_the_rest_is_validated(tmp_path, capsys):
    bad = json.loads(json.dumps(box_doc()["CityObjects"]["b1"]))
    bad["geometry"][0]["boundaries"][0][0][0][0] = 77
    doc = box_doc(extra_objects={"bad": bad})
    rep = tmp_path / "r.json"
    rc, _, _ = run(["validate", "-q", write(tmp_path, doc), "--report", str(rep)], capsys)
    assert rc == 1
    r = json.loads(rep.read_text())
    v = {f["id"]: f for f in r["features"]}
    assert v["b1"]["validity"] is True
    assert v["bad"]["validity"] is False and v["bad"]["errors"][0]["code"] == 901


def test_broken_seq_line_keeps_the_other_features(tmp_path, capsys):
    doc = box_doc(extra_objects={"b2": box_doc()["CityObjects"]["b1"]})
    lines = to_seq(doc).splitlines()
    lines.insert(2, "{not json")
    p = write(tmp_path, None, "s.city.jsonl", "\n".join(lines))
    rep = tmp_path / "r.json"
    rc, _, _ = run(["validate", "-q", p, "--report", str(rep)], capsys)
    r = json.loads(rep.read_text())
    assert rc == 1 and [f["id"] for f in r["features"]] == ["b1", "line 3", "b2"]


@pytest.mark.parametrize("text", ["", "{", '{"type": "CityJSON", "version": "0.9", "CityObjects": {}}'])
def test_unusable_file_exits_2_with_one_line(tmp_path, capsys, text):
    rc, _, err = run(["validate", "-q", write(tmp_path, None, "x.city.json", text)], capsys)
    assert rc == 2 and err.count("lod2energy: error:") == 1


def test_missing_file_and_usage_errors_exit_2(tmp_path, capsys):
    rc, _, err = run(["validate", "-q", str(tmp_path / "nope.json")], capsys)
    assert rc == 2 and "cannot read" in err
    with pytest.raises(SystemExit) as e:
        main(["validate"])
    assert e.value.code == 2
    rc, _, err = run(["validate", "-q", "--snap-tol", "nan", write(tmp_path, box_doc())], capsys)
    assert rc == 2 and "--snap-tol" in err
    rc, _, err = run(["export", write(tmp_path, box_doc()), "-o", str(tmp_path / "o")], capsys)
    assert rc == 2 and "--idf" in err


def test_help_documents_exit_codes():
    out = subprocess.run([sys.executable, "-m", "lod2energy", "validate", "--help"],
                         capture_output=True, text=True, check=True).stdout
    assert "exit codes" in out and "unusable input" in out and "--snap-tol" in out


def test_cli_report_agrees_with_val3dity_on_a_real_tile(tmp_path, capsys):
    from pathlib import Path
    shared = Path(__file__).resolve().parents[2] / "shared"
    ref_path = shared / "reference" / "3dbag_tile5908_subset_ext.city.jsonl.report.json"
    if not ref_path.exists():
        pytest.skip("../shared not present")
    ref = json.loads(ref_path.read_text())
    rep = tmp_path / "r.json"
    rc, _, _ = run(["validate", "-q", str(shared / ref["input_file"]), "--report", str(rep)], capsys)
    ours = {f["id"]: sorted({e["code"] for e in f["errors"]}) for f in json.loads(rep.read_text())["features"]}
    theirs = {f["id"]: sorted({e["code"] for e in f["errors"]}) for f in ref["features"]}
    assert rc == 1 and set(ours) == set(theirs)
    same = sum(ours[k] == theirs[k] for k in theirs)
    assert same / len(theirs) >= 0.95


@pytest.mark.parametrize("suffix", ["out.city.json", "out.city.jsonl"])
def test_repair_command_closes_an_open_box_and_keeps_other_objects(tmp_path, capsys, suffix):
    from cityjson_docs import BOX_FACES
    doc = box_doc(faces=BOX_FACES[:1] + BOX_FACES[2:], gtype="MultiSurface", semantics=False)
    doc["CityObjects"]["tree"] = {"type": "SolitaryVegetationObject", "attributes": {"h": 3}}
    out, rep = tmp_path / suffix, tmp_path / "r.json"
    rc, _, _ = run(["repair", "-q", write(tmp_path, doc), "-o", str(out), "--report", str(rep)], capsys)
    assert rc == 0
    r = json.loads(rep.read_text())
    (b,) = r["buildings"]
    assert b["id"] == "b1" and b["stage"] not in ("valid", "irreparable") and b["defects_after"] == []
    assert r["summary"]["valid_after"] == 1
    rc, _, _ = run(["validate", "-q", str(out)], capsys)
    assert rc == 0
    from lod2energy.io import read
    _, feats = read(str(out))
    got = {f.id: f for f in feats}
    assert set(got) == {"b1", "tree"}
    g = got["b1"].root.geometries[0]
    assert g.type == "Solid" and got["b1"].root.attributes["repair_stage"] == b["stage"]


def test_repair_refuses_an_output_it_cannot_write(tmp_path, capsys):
    out = tmp_path / "out.gml"
    rc, _, err = run(["repair", "-q", write(tmp_path, box_doc()), "-o", str(out)], capsys)
    assert rc == 2 and "out.gml" in err and not out.exists()


def test_repaired_file_spells_the_crs_as_its_version_wants(tmp_path, capsys):
    doc = box_doc()
    doc.setdefault("metadata", {})["referenceSystem"] = "urn:ogc:def:crs:EPSG::25833"
    out = tmp_path / "out.city.json"
    rc, _, _ = run(["repair", "-q", write(tmp_path, doc), "-o", str(out)], capsys)
    assert rc == 0
    assert json.loads(out.read_text())["metadata"]["referenceSystem"] == "https://www.opengis.net/def/crs/EPSG/0/25833"


def test_export_runs_the_whole_pipeline_on_the_bundled_example(tmp_path, capsys):
    import csv
    from pathlib import Path
    example = Path(__file__).resolve().parents[1] / "examples" / "3dbag_b2.city.json"
    out = tmp_path / "out"
    rc, stdout, _ = run(["export", str(example), "-o", str(out), "--idf", "--stl", "--cityjson"], capsys)
    assert rc == 0 and "report:" in stdout
    rows = list(csv.DictReader((out / "report.csv").open()))
    assert len(rows) == 2
    for r in rows:
        assert r["compliant"] == "True" and r["idf_ok"] == r["stl_ok"] == r["cityjson_ok"] == "True"
        assert float(r["UA_W_per_K"]) > 0 and float(r["A_env_m2"]) > 0
        assert (out / f"{r['id']}.idf").exists() and (out / f"{r['id']}.stl").exists()
    rep = json.loads((out / "report.json").read_text())
    assert all(b["energy"]["labelled"] is True and b["energy"]["u_values"] is True for b in rep["buildings"])
    assert (out / "3dbag_b2.energy.city.json").exists()


def test_export_run_without_weather_outside_nl_is_a_usage_error(tmp_path, capsys):
    doc = box_doc()
    doc["metadata"]["referenceSystem"] = "https://www.opengis.net/def/crs/EPSG/0/2056"
    rc, _, err = run(["export", write(tmp_path, doc), "-o", str(tmp_path / "o"), "--idf", "--run"], capsys)
    assert rc == 2 and "--weather" in err
