"""The Python API on data (lod2energy.read of a dict, a file object, standard input) and the
named logger: the same reports and files as the CLI."""
from __future__ import annotations

import json
import logging
import subprocess
import sys
from pathlib import Path

import pytest

import lod2energy
from lod2energy import api
from lod2energy.cli import main
from lod2energy.errors import InputError, ParameterError
from lod2energy.io.source import suffix_of

from cityjson_docs import box_doc, to_seq, write
from conftest import shared_path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "3dbag_b2.city.json"
SEQ = ROOT / "examples" / "delft_subset.city.jsonl"


def tree(folder: Path) -> dict[str, bytes]:
    """The outputs of an export, by name (the reports, the journal and the work folder left out:
    they name the input's path and the run's time)."""
    return {p.name: p.read_bytes() for p in folder.iterdir()
            if p.is_file() and not p.name.startswith("report.")}


def cli(args: list[str], stdin: bytes | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "lod2energy", *args], input=stdin, capture_output=True,
                          cwd=ROOT, env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})


def test_read_of_a_dict_exports_the_same_files_as_the_cli(tmp_path):
    # the notebook: a CityJSON document in memory, read, exported
    doc = json.loads(EXAMPLE.read_text())
    data = lod2energy.read(doc, name="3dbag_b2")
    assert [b.id for b in data.buildings] == [k for k, o in doc["CityObjects"].items() if not o.get("parents")]
    outcome = lod2energy.export(data, tmp_path / "api", idf=True, stl=True, cityjson=True, jobs=1)
    assert main(["export", str(EXAMPLE), "-o", str(tmp_path / "cli"), "--idf", "--stl", "--cityjson",
                 "-j", "1", "-q"]) == outcome.exit_code == 0
    got, want = tree(tmp_path / "api"), tree(tmp_path / "cli")
    assert sorted(got) == sorted(want) and any(n.endswith(".idf") for n in got)
    assert got == want
    assert [r.id for r in outcome.records] == [
        r["id"] for r in json.loads((tmp_path / "cli" / "report.json").read_text())["buildings"]]
    assert doc == json.loads(EXAMPLE.read_text())  # the caller's dict is not changed
    # the STL's sidecars are named for the STL: no "<id>.json" to be taken for a city model
    sidecars = [n for n in got if n.endswith(".json") and not n.endswith((".city.json", ".ext.json"))]
    assert sidecars and all(n.endswith(".stl.json") and n[:-5] in got for n in sidecars)


def test_read_of_a_file_object_and_a_list_of_dicts_validates_as_the_path():
    want = lod2energy.read(SEQ).validate()
    lines = [json.loads(ln) for ln in SEQ.read_text().splitlines() if ln.strip()]
    with open(SEQ, "rb") as f:
        from_file = lod2energy.read(f).validate()
    from_list = api.validate(lines)
    for got in (from_file, from_list):
        assert got["exit_code"] == want["exit_code"] == 0
        assert [(f["id"], f["validity"]) for f in got["features"]] == [(f["id"], f["validity"]) for f in want["features"]]
    assert len(want["features"]) == len(lines) - 1


def test_validate_and_repair_return_the_reports_the_cli_writes(tmp_path):
    data = lod2energy.read(box_doc())
    rep = data.validate(planarity_d2p_tol=0.02)
    assert rep["exit_code"] == 0 and rep["parameters"]["planarity_d2p_tol"] == 0.02
    assert main(["validate", write(tmp_path, box_doc()), "--report", str(tmp_path / "r.json"), "-q"]) == 0
    cli_rep = json.loads((tmp_path / "r.json").read_text())
    assert [f["errors"] for f in rep["features"]] == [f["errors"] for f in cli_rep["features"]]
    rr = data.repair(tmp_path / "o.city.json", jobs=1)
    assert rr["exit_code"] == 0 and rr["summary"]["total"] == 1 and (tmp_path / "o.city.json").exists()


def test_citygml_through_a_file_object_validates_as_the_path():
    path = shared_path("citygml-real", "munich", "LOD2_4424_5482_solid.gml")
    want = lod2energy.read(path).validate()
    with open(path, "rb") as f:
        got = lod2energy.read(f, name="munich").validate()
    assert len(got["features"]) == len(want["features"]) > 10
    assert [(f["id"], f["errors"]) for f in got["features"]] == [(f["id"], f["errors"]) for f in want["features"]]


def test_api_refuses_unknown_options_and_objects(tmp_path):
    with pytest.raises(TypeError, match="nope"):
        lod2energy.read(box_doc()).validate(nope=1)
    with pytest.raises(InputError, match="int"):
        lod2energy.read(3)
    with pytest.raises(ParameterError, match="--wwr"):
        lod2energy.export(box_doc(), tmp_path / "o", idf=True, wwr=2.0)
    # the reader of paths says what it takes, in one line, not the document
    model, feats = lod2energy.io.read(box_doc())
    (fe,) = list(feats)
    assert model is None and "lod2energy.read" in fe.message and "CityObjects" not in fe.message


def test_import_is_light_and_the_api_loads_on_access():
    code = ("import sys, lod2energy; a = 'lod2energy.api' in sys.modules; lod2energy.read; "
            "print(a, 'lod2energy.api' in sys.modules, 'numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         env={"PYTHONPATH": str(ROOT)}).stdout.split()
    assert out == ["False", "True", "True"]
    with pytest.raises(AttributeError):
        lod2energy.nothing_of_that_name  # noqa: B018


def test_suffix_of_a_stream():
    assert suffix_of(json.dumps(box_doc()).encode()) == ".city.json"
    assert suffix_of(to_seq(box_doc()).encode()) == ".city.jsonl"
    assert suffix_of(b"  <CityModel/>") == ".gml"


# ---------------------------------------------------------------------------- standard input

def test_cityjsonseq_on_stdin_with_the_report_on_stdout():
    p = cli(["validate", "-", "--report", "-"], stdin=SEQ.read_bytes())
    assert p.returncode == 0, p.stderr
    rep = json.loads(p.stdout)  # stdout carries the JSON alone
    assert rep["type"] == "val3dity_report" and rep["input_file"] == "-" and len(rep["features"]) == 10
    err = p.stderr.decode()
    assert "features" in err and "valid" in err  # the table went to stderr


@pytest.mark.parametrize("name", ["-", "/dev/stdin"])
def test_cityjson_on_stdin_validates_as_the_file(tmp_path, name):
    p = cli(["validate", name, "--report", str(tmp_path / "r.json"), "-q"], stdin=EXAMPLE.read_bytes())
    assert p.returncode == 0 and p.stdout == b"", p.stderr
    want = cli(["validate", str(EXAMPLE), "--report", "-", "-q"])
    got, ref = json.loads((tmp_path / "r.json").read_text()), json.loads(want.stdout)
    assert got["features"] == ref["features"] and got["input_file"] == name


def test_stdin_is_read_once_and_empty_stdin_is_refused():
    p = cli(["validate", "-", "-"], stdin=SEQ.read_bytes())
    assert p.returncode == 2 and b"only once" in p.stderr and b"Traceback" not in p.stderr
    p = cli(["validate", "-"], stdin=b"")
    assert p.returncode == 2 and b"standard input is empty" in p.stderr and b"Traceback" not in p.stderr


def test_view_of_stdin_writes_the_page_of_the_file(tmp_path):
    p = cli(["view", "-", "-o", str(tmp_path / "in"), "--no-open", "-q"], stdin=SEQ.read_bytes())
    assert p.returncode == 0 and b"Traceback" not in p.stderr, p.stderr
    q = cli(["view", str(SEQ), "-o", str(tmp_path / "file"), "--no-open", "-q"])
    got, want = Path(p.stdout.decode().strip()), Path(q.stdout.decode().strip())
    assert got.parent == tmp_path / "in" and got.name == want.name and got.stat().st_size > 1000
    p = cli(["view", "-", "-o", str(tmp_path / "in"), "--no-open"], stdin=b"")
    assert p.returncode == 2 and b"standard input is empty" in p.stderr and b"Traceback" not in p.stderr


def test_export_and_repair_of_stdin(tmp_path):
    p = cli(["export", "-", "-o", str(tmp_path / "e"), "--idf", "--stl", "-j", "1", "-q"], stdin=SEQ.read_bytes())
    assert p.returncode == 0, p.stderr
    main(["export", str(SEQ), "-o", str(tmp_path / "f"), "--idf", "--stl", "-j", "1", "-q"])
    assert tree(tmp_path / "e") == tree(tmp_path / "f")
    assert (tmp_path / "e" / ".lod2energy" / "input" / "stdin.city.jsonl").read_bytes() == SEQ.read_bytes()
    p = cli(["repair", "-", "-o", str(tmp_path / "r.city.jsonl"), "--report", "-", "-j", "1"],
            stdin=SEQ.read_bytes())
    assert p.returncode == 0, p.stderr
    rep = json.loads(p.stdout)
    assert rep["input_file"] == "-" and rep["summary"]["total"] == 10 and b"stages:" in p.stderr


# ---------------------------------------------------------------------------- logging

def test_errors_go_to_the_named_logger_and_the_cli_keeps_its_lines(tmp_path, capsys, caplog):
    missing = str(tmp_path / "nope.city.json")
    with caplog.at_level(logging.INFO, logger="lod2energy"):
        out = lod2energy.export(missing, tmp_path / "o", idf=True)
    assert out.exit_code == 2
    assert any(r.name == "lod2energy" and r.levelno == logging.ERROR and "nope.city.json" in r.getMessage()
               for r in caplog.records)
    assert main(["export", missing, "-o", str(tmp_path / "o2"), "--idf"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("lod2energy: error: ") and "nope.city.json" in err


def test_verbose_sets_the_level_and_quiet_keeps_the_notes(tmp_path, capsys):
    doc = box_doc()
    doc.get("metadata", {}).pop("referenceSystem", None)
    path = write(tmp_path, doc)
    main(["validate", "-v", path])
    assert logging.getLogger("lod2energy").level == logging.DEBUG
    assert f"lod2energy: debug: {path}: read as CityJSON" in capsys.readouterr().err
    main(["validate", path])
    assert logging.getLogger("lod2energy").level == logging.INFO
    capsys.readouterr()
    main(["validate", path, "-q"])
    err = capsys.readouterr().err
    assert err.startswith("lod2energy: note: ") and "taken as metres" in err and "features" not in err
