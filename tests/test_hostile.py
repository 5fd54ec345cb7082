"""Hostile input and conditions (issue 15): nothing lost, nothing overwritten, no traceback.

Every input is generated on the fly from the bundled Delft example (a few real 3DBAG
buildings) with one thing broken. Each test checks the same invariants:

- the exit code, and one clear line for the broken building or file (on stderr for
  ``export``, in the report for ``validate``), no traceback;
- every other building of the input present in the report;
- nothing written outside OUTDIR (a file planted outside is unchanged, no new files);
- no file left under a good name that failed its self-check;
- the input unchanged.

The checks that need the command-line work of the pipeline (exit 2 for an output that is
an input, SIGTERM, ``--timeout``, export of an external entity) are in ``test_hostile_cli.py``.
"""
from __future__ import annotations

import copy
import errno
import json
import os
from pathlib import Path

import pytest

from lod2energy.cli import main

REPO = Path(__file__).resolve().parents[1]
EXAMPLE = REPO / "examples" / "delft_subset.city.jsonl"
_LINES = EXAMPLE.read_text(encoding="utf-8").splitlines()
HEADER = json.loads(_LINES[0])
FEATURES = [json.loads(x) for x in _LINES[1:4]]  # three real buildings (with BuildingParts)


def _building_id(f: dict) -> str:
    return next(k for k, v in f["CityObjects"].items() if v["type"] == "Building")


def _part_id(f: dict) -> str:
    return next(k for k, v in f["CityObjects"].items() if v["type"] == "BuildingPart")


IDS = [_building_id(f) for f in FEATURES]


# ----------------------------------------------------------------------------- helpers

def features() -> list[dict]:
    return copy.deepcopy(FEATURES)


def write_seq(folder: Path, feats: list, name: str = "in.city.jsonl", header: dict | None = None) -> Path:
    """A CityJSONSeq file: the example's header, then one line per feature (dict or raw text)."""
    p = folder / name
    with open(p, "w", encoding="utf-8") as f:
        f.write(json.dumps(header or HEADER) + "\n")
        for x in feats:
            f.write((x if isinstance(x, str) else json.dumps(x)) + "\n")
    return p


def as_document(feats: list) -> dict:
    """One CityJSON document holding the features (vertices shifted into one list)."""
    doc = {k: v for k, v in HEADER.items() if k not in ("CityObjects", "vertices")}
    doc["CityObjects"], doc["vertices"] = {}, []

    def shift(x, off):
        return [shift(i, off) for i in x] if isinstance(x, list) else x + off
    for f in feats:
        off = len(doc["vertices"])
        doc["vertices"] += f["vertices"]
        for k, co in f["CityObjects"].items():
            co = copy.deepcopy(co)
            for g in co.get("geometry", []):
                g["boundaries"] = shift(g["boundaries"], off)
            doc["CityObjects"][k] = co
    return doc


def tree(folder: Path, skip: Path | None = None) -> dict[str, bytes]:
    """Every file under ``folder`` (links as their target text), except under ``skip``."""
    out = {}
    for root, dirs, files in os.walk(folder):
        if skip is not None and Path(root).resolve() == skip.resolve():
            dirs[:] = []
            continue
        for n in files + [d for d in dirs if os.path.islink(os.path.join(root, d))]:
            p = Path(root, n)
            if skip is not None and skip.resolve() in p.resolve().parents and not p.is_symlink():
                continue
            out[str(p)] = ("-> " + os.readlink(p)).encode() if p.is_symlink() else p.read_bytes()
    return out


def run(args: list[str], capsys) -> tuple[int, str, str]:
    rc = main([str(a) for a in args])
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return rc, out, err


def error_lines(err: str) -> list[str]:
    return [ln for ln in err.splitlines() if "error" in ln.lower()]


def self_checked_names(outdir: Path) -> None:
    """Every exported file under a good name passes its own self-check."""
    from lod2energy.exporters import energyplus
    from lod2energy.exporters.cityjson import writer as cj
    from lod2energy.exporters.stl import writer as stl
    for p in outdir.iterdir():
        if p.is_symlink() or p.name.startswith("."):
            continue
        if p.name.endswith(".stl"):
            assert stl.self_check(p) == [], p.name
        elif p.name.endswith(".idf"):
            assert energyplus.check.self_check(p) == [], p.name
        elif p.name.endswith(".energy.city.json"):
            assert cj.self_check(str(p)) == [], p.name
    assert not [p.name for p in outdir.iterdir()
                if p.name.endswith((".part", ".staged", ".tmp", ".tmp.json")) and not p.is_symlink()]


def export(tmp_path: Path, inp: Path, capsys, *flags: str, expect_rc: int = 1, bad: str | None = None,
           good: list[str] = IDS) -> tuple[Path, dict, str]:
    """Run ``export`` and check the invariants; returns (OUTDIR, report, stderr)."""
    outdir = tmp_path / "out"
    victim = tmp_path / "victim.txt"
    if not victim.exists():
        victim.write_text("do not touch\n")
    before_in = inp.read_bytes()
    outside = tree(tmp_path, skip=outdir)
    rc, _, err = run(["export", inp, "-o", outdir, *(flags or ("--cityjson", "--stl")), "-q"], capsys)
    assert rc == expect_rc, err
    assert inp.read_bytes() == before_in, "the input changed"
    assert tree(tmp_path, skip=outdir) == outside, "something was written outside OUTDIR"
    assert victim.read_text() == "do not touch\n"
    rep = json.loads((outdir / "report.json").read_text())
    ids = [b["id"] for b in rep["buildings"]]
    for g in good:
        assert g in ids, f"{g} vanished from the report"
    if bad is not None:
        lines = [ln for ln in error_lines(err) if bad in ln]
        assert len(lines) == 1 and len(lines[0]) < 400, err
    self_checked_names(outdir)
    return outdir, rep, err


def validate(tmp_path: Path, inp: Path, capsys, expect_rc: int = 1) -> dict:
    rep_path = tmp_path / "validation.json"
    before = inp.read_bytes()
    rc, _, err = run(["validate", inp, "--report", rep_path, "-q"], capsys)
    assert rc == expect_rc, err
    assert inp.read_bytes() == before
    return json.loads(rep_path.read_text())


def feature_errors(rep: dict) -> dict[str, list[str]]:
    """Feature id -> its 901 messages (val3dity report)."""
    return {f["id"]: [e.get("info") or e.get("description") for e in f["errors"] if e["code"] == 901]
            for f in rep["features"]}


# ----------------------------------------------------------------------------- tracebacks

def _deep(n: int) -> str:
    return "[" * n + "]" * n


def test_a_line_nested_100000_deep_is_one_error_and_the_other_lines_are_kept(tmp_path, capsys):
    fs = features()
    inp = write_seq(tmp_path, fs[:1] + [_deep(100_000)] + fs[1:])
    rep = validate(tmp_path, inp, capsys)
    errs = feature_errors(rep)
    assert [m for m in errs["line 3"] if "nested too deeply" in m]
    assert all(i in errs and errs[i] == [] for i in IDS)
    export(tmp_path, inp, capsys, bad="nested too deeply")


def test_a_document_nested_100000_deep_is_one_file_error(tmp_path, capsys):
    inp = tmp_path / "deep.city.json"
    inp.write_text('{"type": "CityJSON", "version": "2.0", "metadata": ' + '{"a": ' * 100_000 + "1"
                   + "}" * 100_000 + ', "CityObjects": {}, "vertices": []}')
    rc, _, err = run(["validate", inp], capsys)
    assert rc == 2 and len(error_lines(err)) == 1 and "nested too deeply" in err


def test_an_attribute_nested_500_deep_fails_only_its_building(tmp_path, capsys):
    fs = features()
    v: dict = {}
    cur = v
    for _ in range(500):
        cur["x"] = {}
        cur = cur["x"]
    fs[1]["CityObjects"][IDS[1]]["attributes"]["deep"] = v
    inp = write_seq(tmp_path, fs)
    errs = feature_errors(validate(tmp_path, inp, capsys))
    assert any("nested more than" in m for m in errs[IDS[1]])
    assert errs[IDS[0]] == [] and errs[IDS[2]] == []
    export(tmp_path, inp, capsys, bad="nested more than", good=[IDS[0], IDS[2]])


def _with_text(f: dict, old: str, new: str) -> str:
    s = json.dumps(f)
    assert old in s
    return s.replace(old, new, 1)


@pytest.mark.parametrize("literal", ["1e400", "-1e400", "1" * 400, "1" * 5000])
def test_a_coordinate_out_of_range_fails_only_its_building(tmp_path, capsys, literal):
    fs = features()
    x = fs[1]["vertices"][0][0]
    line = _with_text(fs[1], f"[{x}, ", f"[{literal}, ")
    inp = write_seq(tmp_path, [fs[0], line, fs[2]])
    errs = feature_errors(validate(tmp_path, inp, capsys))
    bad = [i for i, m in errs.items() if m]
    assert len(bad) == 1 and errs[IDS[0]] == [] and errs[IDS[2]] == []
    export(tmp_path, inp, capsys, good=[IDS[0], IDS[2]])


def test_an_attribute_of_1e400_fails_its_building_not_the_batch(tmp_path, capsys):
    fs = features()
    fs[1]["CityObjects"][IDS[1]]["attributes"]["yearOfConstruction"] = 12345
    line = _with_text(fs[1], '"yearOfConstruction": 12345', '"yearOfConstruction": 1e400')
    inp = write_seq(tmp_path, [fs[0], line, fs[2]])
    errs = feature_errors(validate(tmp_path, inp, capsys))
    assert any("out of range" in m for m in errs[IDS[1]])
    export(tmp_path, inp, capsys, bad="out of range", good=[IDS[0], IDS[2]])


WRONG_TYPES = {
    "children is a number": lambda f: f["CityObjects"][_building_id(f)].__setitem__("children", 5),
    "parents is an object": lambda f: f["CityObjects"][_part_id(f)].__setitem__("parents", {"a": 1}),
    "children holds a list": lambda f: f["CityObjects"][_building_id(f)].__setitem__("children", [[1]]),
    "attributes is a list": lambda f: f["CityObjects"][_building_id(f)].__setitem__("attributes", [1, 2]),
    "geometry is a string": lambda f: f["CityObjects"][_part_id(f)].__setitem__("geometry", "Solid"),
    "a geometry is a list": lambda f: f["CityObjects"][_part_id(f)].__setitem__("geometry", [[1, 2]]),
    "type is a number": lambda f: f["CityObjects"][_part_id(f)].__setitem__("type", 7),
    "CityObject is a list": lambda f: f["CityObjects"].__setitem__(_part_id(f), [1, 2, 3]),
    "a coordinate is a string": lambda f: f["vertices"][0].__setitem__(0, "12"),
    "a vertex is a number": lambda f: f["vertices"].__setitem__(0, 7),
    "boundaries hold strings": lambda f: f["CityObjects"][_part_id(f)]["geometry"][0].__setitem__(
        "boundaries", [[["a", "b", "c"]]]),
    "boundaries are an object": lambda f: f["CityObjects"][_part_id(f)]["geometry"][0].__setitem__(
        "boundaries", {"a": 1}),
    "lod is a list": lambda f: f["CityObjects"][_part_id(f)]["geometry"][0].__setitem__("lod", [2]),
    "semantics is a list": lambda f: f["CityObjects"][_part_id(f)]["geometry"][0].__setitem__("semantics", [1]),
    "a semantic surface type is a number": lambda f: f["CityObjects"][_part_id(f)]["geometry"][0][
        "semantics"]["surfaces"][0].__setitem__("type", 5),
    "semantic values are a string": lambda f: f["CityObjects"][_part_id(f)]["geometry"][0][
        "semantics"].__setitem__("values", "x"),
    "an id is empty": lambda f: f["CityObjects"].__setitem__("", f["CityObjects"].pop(_part_id(f))),
}


@pytest.mark.parametrize("kind", sorted(WRONG_TYPES))
def test_a_value_of_the_wrong_type_is_a_clear_error_for_its_building(tmp_path, capsys, kind):
    fs = features()
    WRONG_TYPES[kind](fs[1])
    inp = write_seq(tmp_path, fs)
    rep = validate(tmp_path, inp, capsys)
    ids = [f["id"] for f in rep["features"]]
    assert IDS[0] in ids and IDS[2] in ids
    errs = feature_errors(rep)
    assert errs[IDS[0]] == [] and errs[IDS[2]] == []
    outdir, erep, err = export(tmp_path, inp, capsys, good=[IDS[0], IDS[2]], expect_rc=None or 1)
    assert all(len(ln) < 400 for ln in error_lines(err))
    assert "Error:" not in err.replace("error:", "")  # no exception class names leaking as the message


def test_a_transform_of_strings_is_one_file_error(tmp_path, capsys):
    h = copy.deepcopy(HEADER)
    h["transform"]["scale"] = ["0.001", "0.001", "0.001"]
    inp = write_seq(tmp_path, features(), header=h)
    rc, _, err = run(["validate", inp], capsys)
    assert rc == 2 and len(error_lines(err)) == 1 and "transform" in err


# ----------------------------------------------------------------------------- buildings that vanish

def test_a_parents_children_cycle_is_reported_not_dropped(tmp_path, capsys):
    fs = features()
    b, p = _building_id(fs[1]), _part_id(fs[1])
    fs[1]["CityObjects"][b]["parents"] = [p]
    fs[1]["CityObjects"][p]["children"] = [b]
    inp = write_seq(tmp_path, fs)
    errs = feature_errors(validate(tmp_path, inp, capsys))
    cyc = [i for i, m in errs.items() if any("cycle" in x for x in m)]
    assert len(cyc) == 1 and cyc[0] in (b, p)
    assert errs[IDS[0]] == [] and errs[IDS[2]] == []
    export(tmp_path, inp, capsys, bad="cycle", good=[IDS[0], IDS[2]])


def test_a_part_its_parent_does_not_list_is_reported(tmp_path, capsys):
    fs = features()
    fs[1]["CityObjects"][_building_id(fs[1])]["children"] = []
    inp = write_seq(tmp_path, fs)
    errs = feature_errors(validate(tmp_path, inp, capsys))
    assert any("does not list it" in m for m in errs[_part_id(fs[1])])


def test_two_lines_with_the_same_id_are_both_in_the_report_and_one_in_the_output(tmp_path, capsys):
    fs = features()
    twin = copy.deepcopy(fs[1])
    inp = write_seq(tmp_path, fs + [twin])
    errs = feature_errors(validate(tmp_path, inp, capsys))
    dup = [i for i in errs if i != IDS[1] and IDS[1] in i]
    assert len(dup) == 1 and any("already read" in m for m in errs[dup[0]])
    outdir, rep, _ = export(tmp_path, inp, capsys, "--cityjson", bad="already read")
    out = json.loads(next(outdir.glob("*.energy.city.json")).read_text())
    assert IDS[1] in out["CityObjects"]
    rows = [b for b in rep["buildings"] if IDS[1] in b["id"]]
    assert len(rows) == 2 and sum(1 for b in rows if b.get("cityjson_ok")) == 1


def test_two_cityobjects_with_the_same_key_in_one_document_are_reported(tmp_path, capsys):
    doc = as_document(features())
    text = json.dumps(doc)
    # the second building takes the first one's id: a JSON object with a repeated key
    text = text.replace(json.dumps(IDS[2]) + ": {", json.dumps(IDS[0]) + ": {", 1)
    inp = tmp_path / "dup.city.json"
    inp.write_text(text)
    errs = feature_errors(validate(tmp_path, inp, capsys))
    dup = [i for i in errs if i != IDS[0] and IDS[0] in i]
    assert len(dup) == 1 and any("more than one CityObject" in m for m in errs[dup[0]])
    export(tmp_path, inp, capsys, bad="more than one CityObject", good=[IDS[0], IDS[1]])


# ----------------------------------------------------------------------------- endless streams

def test_dev_zero_is_refused_with_one_line(tmp_path, capsys):
    if not os.path.exists("/dev/zero"):
        pytest.skip("no /dev/zero")
    import resource
    import subprocess
    import sys
    link = tmp_path / "zero.city.jsonl"
    link.symlink_to("/dev/zero")

    def cap():  # a reader that reads it whole gets a MemoryError, not the machine's memory
        resource.setrlimit(resource.RLIMIT_AS, (6 << 30, 6 << 30))
    p = subprocess.run([sys.executable, "-m", "lod2energy", "validate", str(link)], capture_output=True,
                       text=True, timeout=300, preexec_fn=cap)
    assert "Traceback" not in p.stderr and "MemoryError" not in p.stderr
    assert p.returncode == 2 and len(error_lines(p.stderr)) == 1 and "not a regular file" in p.stderr


def test_a_fifo_is_refused_without_blocking(tmp_path, capsys):
    fifo = tmp_path / "stream.city.json"
    import subprocess
    import sys
    os.mkfifo(fifo)  # nobody writes: reading it would block forever
    try:
        p = subprocess.run([sys.executable, "-m", "lod2energy", "export", str(fifo), "-o", str(tmp_path / "out"),
                            "--cityjson"], capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        pytest.fail("export blocked reading a FIFO")
    assert "Traceback" not in p.stderr
    assert p.returncode == 2 and len(error_lines(p.stderr)) == 1 and "FIFO" in p.stderr


def test_a_gigantic_line_is_skipped_and_the_next_lines_read(tmp_path, capsys, monkeypatch):
    from lod2energy.io import shape
    monkeypatch.setattr(shape, "MAX_LINE_BYTES", 1 << 16)
    fs = features()
    huge = json.dumps({"type": "CityJSONFeature", "id": "x", "pad": "a" * (1 << 20)})
    inp = write_seq(tmp_path, fs[:1] + [huge] + fs[1:])
    errs = feature_errors(validate(tmp_path, inp, capsys))
    assert any("longer than" in m for m in errs["line 3"])
    assert all(errs[i] == [] for i in IDS)


def test_a_file_larger_than_the_limit_is_one_file_error(tmp_path, capsys, monkeypatch):
    from lod2energy.io import shape
    monkeypatch.setattr(shape, "MAX_INPUT_BYTES", 1000)
    inp = tmp_path / "big.city.json"
    inp.write_text(json.dumps(as_document(features())))
    rc, _, err = run(["validate", inp], capsys)
    assert rc == 2 and len(error_lines(err)) == 1 and "MiB" in err


# ----------------------------------------------------------------------------- links and temporaries

def test_links_planted_under_every_output_name_are_refused_and_not_followed(tmp_path, capsys):
    inp = write_seq(tmp_path, features())
    outdir = tmp_path / "out"
    outdir.mkdir()
    victim = tmp_path / "victim.txt"
    victim.write_text("do not touch\n")
    from lod2energy.io.cityjson import is_cityjsonseq  # noqa: F401 - the reader is importable
    from lod2energy.exporters.paths import safe_stem
    names = [f"{safe_stem(i, set())}{s}" for i in IDS[:2] for s in (".idf", ".stl", ".stl.json")]
    names += ["energy.ext.json", "in.energy.city.json"]
    pid = os.getpid()
    for n in list(names):  # the temporaries a writer in this process could pick
        names += [f".{n}.{pid}.{k}.part" for k in range(40)] + [f".{n}.{pid}.{k}.staged" for k in range(40)]
        names += [f".{n}.{pid}.tmp.json", f".{n}.{pid}.{0}.tmp.json", f"{n}.part"]
    for n in names:
        (outdir / n).symlink_to(victim)
    _, rep, err = export(tmp_path, inp, capsys, "--idf", "--stl", "--cityjson")
    assert victim.read_text() == "do not touch\n"
    assert "symbolic link" in err
    assert {b["id"] for b in rep["buildings"]} >= set(IDS)
    assert all((outdir / n).is_symlink() for n in names if not n.startswith("."))


# ----------------------------------------------------------------------------- half files

class _Hits:
    """Names the fake full disk refused, in a file: the workers and the one-file writers' process
    are forked children, whose lists the test would not see."""

    def __init__(self, path: Path):
        self.path = path

    def append(self, name: str) -> None:
        with open(self.path, "a", encoding="utf-8") as f:
            f.write(name + "\n")

    def names(self) -> list[str]:
        return self.path.read_text(encoding="utf-8").split() if self.path.exists() else []

    def __bool__(self) -> bool:
        return bool(self.names())


def _full_disk_for(suffixes: tuple[str, ...], monkeypatch, log: Path | None = None) -> _Hits:
    """os.fsync raising ENOSPC for the temporaries of files ending in ``suffixes`` (in this
    process and in its forked children); the refused names are logged in ``log``."""
    import tempfile
    hit = _Hits(log if log is not None else Path(tempfile.mkdtemp()) / "full_disk_hits.txt")
    real = os.fsync

    def fsync(fd):
        try:
            name = os.readlink(f"/proc/self/fd/{fd}")
        except OSError:
            name = ""
        base = os.path.basename(name)
        if any(s + "." in base for s in suffixes):
            hit.append(base)
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real(fd)
    monkeypatch.setattr(os, "fsync", fsync)
    return hit


def test_a_full_disk_leaves_no_half_file_under_a_final_name(tmp_path, capsys, monkeypatch):
    if not os.path.isdir("/proc/self/fd"):
        pytest.skip("needs /proc/self/fd")
    inp = write_seq(tmp_path, features())
    hit = _full_disk_for((".idf", ".stl", ".city.json", "energy.ext.json"), monkeypatch)
    outdir, rep, err = export(tmp_path, inp, capsys, "--idf", "--stl", "--cityjson")
    assert hit, "the simulated full disk was never reached"
    assert "No space left on device" in err
    left = [p.name for p in outdir.iterdir() if p.suffix in (".idf", ".stl") or p.name.endswith(".city.json")]
    assert left == [], left
    assert all(not b.get("idf_ok") and not b.get("stl_ok") and not b.get("cityjson_ok")
               for b in rep["buildings"])


@pytest.mark.parametrize("fmt", ["idf", "stl", "cityjson"])
def test_a_file_that_fails_its_self_check_never_keeps_a_good_name(tmp_path, capsys, monkeypatch, fmt):
    from lod2energy.exporters import energyplus
    from lod2energy.exporters.cityjson import writer as cj
    from lod2energy.exporters.stl import writer as stl
    mod = {"idf": energyplus.writer, "stl": stl, "cityjson": cj}[fmt]  # where the writer looks its check up
    monkeypatch.setattr(mod, "self_check", lambda *a, **k: ["forced failure"])
    inp = write_seq(tmp_path, features())
    outdir = tmp_path / "out"
    outdir.mkdir()
    suffix = {"idf": ".idf", "stl": ".stl", "cityjson": ".energy.city.json"}[fmt]
    from lod2energy.exporters.paths import safe_stem
    stem = safe_stem(IDS[0], set()) if fmt != "cityjson" else "in"
    old = outdir / f"{stem}{suffix}"  # an older good-looking file of this name
    old.write_text("from an earlier run")
    _, rep, err = export(tmp_path, inp, capsys, f"--{fmt}")
    assert not old.exists(), "a file that failed its check kept the good name"
    bad = sorted(p.name for p in outdir.iterdir() if p.name.endswith(suffix + ".invalid"))
    assert bad, "the failed file was not kept as .invalid"
    assert "forced failure" in err
    assert all(not b.get(f"{fmt}_ok") for b in rep["buildings"])


# ----------------------------------------------------------------------------- wrong results said right

def test_a_building_collapsed_to_centimetres_is_not_compliant(tmp_path, capsys):
    fs = features()
    import numpy as np
    v = np.array(fs[0]["vertices"], float)
    c = v.mean(axis=0)
    fs[0]["vertices"] = np.round(c + (v - c) * 0.01).astype(int).tolist()  # 10 m -> 10 cm
    inp = write_seq(tmp_path, fs)
    rep = validate(tmp_path, inp, capsys, expect_rc=0)
    e = next(f for f in rep["features"] if f["id"] == IDS[0])["energy"]
    assert e["compliant"] is False and e["geometry_ready"] is False
    assert any("collapsed" in r for r in e["reasons"])
    _, erep, _ = export(tmp_path, inp, capsys)
    row = next(b for b in erep["buildings"] if b["id"] == IDS[0])
    assert row["compliant"] is False and "collapsed" in row["message"]


def test_export_of_a_repaired_building_is_byte_reproducible(tmp_path, capsys):
    fs = features()
    for co in fs[1]["CityObjects"].values():  # flip one face and remove another: a repair runs
        for g in co.get("geometry", []):
            if g["type"] == "Solid":
                sh = g["boundaries"][0]
                sh[0] = [r[::-1] for r in sh[0]]
                del sh[1]
                if "semantics" in g:
                    del g["semantics"]["values"][0][1]
    inp = write_seq(tmp_path, fs)
    outs = []
    for k in range(2):
        outdir = tmp_path / f"out{k}"
        rc, _, err = run(["export", inp, "-o", outdir, "--cityjson", "--stl", "--idf", "-q"], capsys)
        outs.append({p.name: p.read_bytes() for p in outdir.iterdir() if p.name not in ("report.json", "report.jsonl") and p.is_file()})  # paths of this run; not the work folder
    rep = json.loads((tmp_path / "out0" / "report.json").read_text())
    assert any(b["repair"].get("stage") not in ("valid", None) for b in rep["buildings"])
    assert outs[0].keys() == outs[1].keys()
    differ = [n for n in outs[0] if outs[0][n] != outs[1][n]]
    assert differ == []


# ----------------------------------------------------------------------------- XML

def test_a_citygml_external_entity_is_refused_by_validate(tmp_path, capsys):
    secret = tmp_path / "secret.txt"
    secret.write_text("s3cret")
    gml = tmp_path / "xxe.gml"
    gml.write_text(f'<?xml version="1.0"?>\n<!DOCTYPE x [<!ENTITY e SYSTEM "file://{secret}">]>\n'
                   '<CityModel xmlns="http://www.opengis.net/citygml/2.0"><name>&e;</name></CityModel>\n')
    rc, out, err = run(["validate", gml], capsys)
    assert rc == 2 and "s3cret" not in out + err and len(error_lines(err)) == 1
