"""Streaming (issue 13 item 3): report rows as each building finishes, report.json from the
journal, the one-file writers and their self-checks one building at a time."""
from __future__ import annotations

import csv
import io
import json
import os
import random
import signal
import subprocess
import sys
import time
import weakref
from dataclasses import replace
from pathlib import Path

import pytest

from lod2energy.cli import main
from lod2energy.io.json_stream import Scanner, StreamError

from spine_inputs import row_of_boxes_seq

REPO = Path(__file__).resolve().parents[1]
DELFT = REPO / "examples" / "delft_subset.city.jsonl"


def _csv_ids(path: Path) -> list[str]:
    with open(path, newline="", encoding="utf-8") as f:
        return [r["id"] for r in csv.DictReader(f)]


# ----------------------------------------------------------------------------- the JSON scanner

def _walk(sc: Scanner, depth: int = 0):
    """Rebuild a value with the scanner's members/items (nested ones walked too)."""
    c = sc.peek()
    if c == "{" and depth < 2:
        return {k: _walk(sc, depth + 1) for k in sc.members()}
    if c == "[" and depth < 2:
        return [_walk(sc, depth + 1) for _ in sc.items()]
    return sc.value()


def _random_value(rng: random.Random, depth: int = 0):
    kind = rng.randrange(7 if depth < 3 else 4)
    if kind == 0:
        return rng.randint(-10 ** 12, 10 ** 12)
    if kind == 1:
        return rng.uniform(-1e6, 1e6)
    if kind == 2:
        return rng.choice([True, False, None, "", "a\u00e9\"\\\n", "\u2603" * rng.randrange(5)])
    if kind == 3:
        return "x" * rng.randrange(30)
    if kind in (4, 5):
        return {f"k{i}\u00fc": _random_value(rng, depth + 1) for i in range(rng.randrange(5))}
    return [_random_value(rng, depth + 1) for _ in range(rng.randrange(6))]


@pytest.mark.parametrize("chunk", [1, 2, 7, 64, 1 << 20])
def test_scanner_reads_what_json_loads_reads_whatever_the_chunk(chunk):
    rng = random.Random(chunk)
    for _ in range(40):
        doc = {"a": _random_value(rng), "b": [_random_value(rng) for _ in range(rng.randrange(8))],
               "n": rng.randint(-10 ** 9, 10 ** 9)}
        for text in (json.dumps(doc), json.dumps(doc, indent=2), json.dumps(doc, separators=(",", ":"))):
            sc = Scanner(io.StringIO(text), chunk=chunk)
            got = _walk(sc)
            sc.end()
            assert got == json.loads(text)


@pytest.mark.parametrize("text", ['{"a": 1,}', '{"a": [1, 2,]}', '{"a": 1} x', '{"a" 1}', '{"a": [1 2]}',
                                  '{"a": 12', '{"a": "b', '[1, 2]]', '{1: 2}', ''])
def test_scanner_refuses_what_json_loads_refuses(text):
    with pytest.raises(json.JSONDecodeError):
        json.loads(text)
    for chunk in (1, 3, 1 << 20):
        with pytest.raises(StreamError):
            sc = Scanner(io.StringIO(text), chunk=chunk)
            _walk(sc)
            sc.end()


# ----------------------------------------------------------------------------- the CityJSON document

def _delft():
    from lod2energy.io import read
    model, feats = read(str(DELFT))
    return model, [f for f in feats]


def _whole_document(model, buildings, version):
    """The CityJSON document (dict) of ``buildings``, built in memory at once."""
    from lod2energy.io.cityjson_grid import quantise
    from lod2energy.io.cityjson_write import _header_json, cityobject_json, transform_for
    doc = _header_json(model, version)
    doc["transform"] = transform = transform_for(model, buildings)
    cos, verts = {}, []
    for b in buildings:
        off = len(verts)
        verts.extend(quantise(b.vertices, transform, model.frame))
        for o in b.objects:
            cos[o.id] = cityobject_json(o, off, version)
    doc["CityObjects"], doc["vertices"] = cos, verts
    return doc


@pytest.mark.parametrize("own_grid", [True, False])
def test_streamed_document_has_the_bytes_of_the_whole_document(own_grid):
    from lod2energy.io.cityjson_write import write_document
    model, bs = _delft()
    if not own_grid:  # the grid from the buildings' smallest coordinates, as for a mesh input
        model = replace(model, transform=None)
    whole = json.dumps(_whole_document(model, bs, "2.0"), separators=(",", ":"), ensure_ascii=False)
    f = io.StringIO()
    write_document(f, model, iter(bs) if own_grid else bs, "2.0")
    assert f.getvalue() == whole
    assert json.loads(f.getvalue())["vertices"]  # the vertices made it through the scratch file


def test_streamed_document_refuses_two_objects_with_one_id():
    from lod2energy.io.cityjson_write import write_document
    model, bs = _delft()
    with pytest.raises(ValueError, match="two CityObjects"):
        write_document(io.StringIO(), model, [bs[0], bs[0]], "2.0")


@pytest.fixture(scope="module")
def delft_export(tmp_path_factory):
    """One export of Delft with the one-file writers and the records it returned."""
    from lod2energy.cli import build_parser
    from lod2energy.options import export_options
    from lod2energy.options import RunOptions
    from lod2energy.pipeline import export
    out = tmp_path_factory.mktemp("delft") / "out"
    a = build_parser().parse_args(["export", str(DELFT), "-o", str(out), "--stl", "--cityjson", "--geojson",
                                   "--no-html"])
    res = export(str(DELFT), str(out), export_options(a), RunOptions(jobs=1, quiet=True))
    assert res.exit_code == 0
    return out, res


def test_streamed_self_check_passes_the_file_and_catches_what_the_whole_check_caught(delft_export, tmp_path):
    from lod2energy.exporters.cityjson.writer import self_check
    out, _ = delft_export
    good = out / "delft_subset.energy.city.json"
    assert self_check(str(good)) == []
    text = good.read_text(encoding="utf-8")
    doc = json.loads(text)

    def check(d_or_text) -> list[str]:
        p = tmp_path / "x.energy.city.json"
        p.write_text(d_or_text if isinstance(d_or_text, str) else json.dumps(d_or_text), encoding="utf-8")
        (tmp_path / "energy.ext.json").write_bytes((out / "energy.ext.json").read_bytes())
        return self_check(str(p))

    assert any("not valid JSON" in p for p in check(text[:-40]))
    assert any("not valid JSON" in p for p in check(text + "x"))
    oid = next(iter(doc["CityObjects"]))
    bad = json.loads(text)
    bad["CityObjects"][oid]["type"] = "NoSuchType"
    assert any("schema" in p for p in check(bad))
    bad = json.loads(text)
    bad["vertices"][3] = [1, 2]  # not a triple: the schema's
    assert any("schema" in p for p in check(bad))
    bad = json.loads(text)
    bad["CityObjects"][oid]["attributes"]["+energyUA"] = "much"  # the extension's
    assert check(bad)
    bad = json.loads(text)
    bad["vertices"][0] = [bad["vertices"][0][0] + 5_000, *bad["vertices"][0][1:]]  # a geometry problem
    assert check(bad)
    bad = json.loads(text)
    part = next(k for k, co in bad["CityObjects"].items() if co.get("geometry"))
    g = bad["CityObjects"][part]["geometry"][0]
    g["boundaries"][0].pop()  # a face less: the shell is open
    g["semantics"]["values"][0].pop()
    assert check(bad)
    dup = text.replace('"CityObjects":{', '"CityObjects":{' + json.dumps(oid) + ":"
                       + json.dumps(doc["CityObjects"][oid], separators=(",", ":")) + ",", 1)
    assert any("more than one CityObject" in p for p in check(dup))


def test_one_file_writers_hold_one_building_at_a_time(delft_export, monkeypatch):
    """The CityJSON and GeoJSON passes read the spool as they write: never all buildings alive."""
    from lod2energy import dataset
    from lod2energy.exporters.registry import writer
    from lod2energy.run.spool import Job, Spooled
    out, res = delft_export
    alive, peak = [0], [0]

    def gone():
        alive[0] -= 1

    real = Spooled._get

    def tracked(self, seq):
        b = real(self, seq)
        alive[0] += 1
        peak[0] = max(peak[0], alive[0])
        weakref.finalize(b, gone)
        return b

    monkeypatch.setattr(Spooled, "_get", tracked)
    from lod2energy.cli import build_parser
    from lod2energy.options import export_options
    from lod2energy.io import read
    from lod2energy.options import resolve
    model, _ = read(str(DELFT))
    a = build_parser().parse_args(["export", str(DELFT), "-o", str(out), "--stl", "--cityjson", "--geojson"])
    opts = resolve(export_options(a), model)
    job = Job(opts, str(out), str(out / ".lod2energy" / "spool"), model.crs)
    from lod2energy.run.record_store import RecordStore
    records = RecordStore({r.seq: r for r in res.records})
    before = {n: (out / n).read_bytes() for n in ("delft_subset.energy.city.json", "delft_subset.footprints.geojson")}
    for name in ("cityjson", "geojson"):
        dataset.dataset_pass(writer(name), opts, job, records, [], model, str(DELFT), True)
    n = sum(r.outcome == "done" for r in res.records)
    assert n >= 5 and 1 <= peak[0] <= 3, peak[0]
    for k, v in before.items():
        assert (out / k).read_bytes() == v
    assert all(r.export("cityjson").ok and r.export("geojson").ok for r in records.values() if r.outcome == "done")


# ----------------------------------------------------------------------------- the reports

def test_report_json_from_the_journal_equals_the_report_of_the_records(delft_export, tmp_path):
    from lod2energy.io import read
    from lod2energy.reports import write_reports
    out, res = delft_export
    model, _ = read(str(DELFT))
    other = tmp_path / "mem"
    other.mkdir()
    write_reports(str(out), str(DELFT), model, list(res.records), [], None, [str(DELFT)])  # from memory
    for name in ("report.json", "report.csv"):
        (other / name).write_bytes((out / name).read_bytes())
    # and from the journal again, as export wrote them
    from lod2energy.run.resume import read_lines
    head = next(iter(read_lines(out / "report.jsonl")))
    start = len((json.dumps(head, ensure_ascii=False) + "\n").encode())
    from lod2energy.reports import write_reports_from_journal
    write_reports_from_journal(str(out), str(DELFT), model, str(out / "report.jsonl"), start, [], None, [str(DELFT)])
    for name in ("report.json", "report.csv"):
        assert (out / name).read_bytes() == (other / name).read_bytes(), name
    doc = json.loads((out / "report.json").read_text())
    assert [b["id"] for b in doc["buildings"]] == [r.id for r in res.records]
    assert all(b["exports"]["cityjson"]["ok"] for b in doc["buildings"] if b["outcome"] == "done")


def test_report_csv_has_a_row_for_every_building_finished_so_far(tmp_path, capsys, monkeypatch):
    from lod2energy import pipeline
    out = tmp_path / "out"
    seen: list[tuple[int, list[str]]] = []
    real = pipeline.first_pass

    def spy(task):
        if task[1] == "building" and (out / "report.csv").exists():
            seen.append((task[0], _csv_ids(out / "report.csv")))
        return real(task)

    monkeypatch.setattr(pipeline, "first_pass", spy)
    assert main(["export", str(DELFT), "-o", str(out), "--stl", "--cityjson", "-q", "-j", "1", "--no-html"]) == 0
    capsys.readouterr()
    final = _csv_ids(out / "report.csv")
    assert len(seen) == len(final) == 10
    for k, (seq, ids) in enumerate(seen):
        assert ids == final[:k], f"before building {seq}: {ids}"


def test_a_killed_run_leaves_a_csv_row_per_building_in_its_journal(tmp_path):
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=12)
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "lod2energy", "export", src, "-o", str(out), "--idf", "--stl", "-j", "1", "-q"]
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    t0 = time.monotonic()
    journal = out / "report.jsonl"

    def done() -> int:
        return journal.exists() and sum('"kind": "building"' in ln for ln in journal.read_text().splitlines())

    while done() < 3 and time.monotonic() - t0 < 120 and p.poll() is None:
        time.sleep(0.05)
    assert p.poll() is None, "the run ended before it could be killed"
    os.kill(p.pid, signal.SIGKILL)  # no handler runs: what is on disk is what was appended
    p.wait(timeout=60)
    ids = [json.loads(ln)["id"] for ln in journal.read_text().splitlines() if '"kind": "building"' in ln]
    rows = _csv_ids(out / "report.csv")
    assert 3 <= len(ids) < 12
    # a row per finished building (the journal's line is appended just before the row)
    assert rows in (ids, ids[:-1]), (rows, ids)


def test_the_page_reads_report_json_one_building_at_a_time(tmp_path):
    """report.html's reading of report.json: the same document as ``json.load``, but its
    buildings parsed on each iteration rather than held (a city's report is ~25 KB a building
    as dicts)."""
    import json
    import tracemalloc
    from lod2energy.reports import report_lazily
    doc = {"input_file": "x.city.jsonl", "output_dir": "out",
           "buildings": [{"id": f"b{i}", "repair": {"stage": "valid", "metrics": {f"m{k}": k / 3 for k in range(30)}},
                          "exports": {"stl": {"ok": True, "problems": []}}} for i in range(400)],
           "dataset_errors": [{"code": 901, "info": "x"}]}
    path = tmp_path / "report.json"
    path.write_text(json.dumps(doc, indent=1), encoding="utf-8")
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        whole = json.loads(path.read_text(encoding="utf-8"))
        as_list = tracemalloc.get_traced_memory()[0] - base
        base = tracemalloc.get_traced_memory()[0]
        lazy = report_lazily(str(path))
        as_lazy = tracemalloc.get_traced_memory()[0] - base
    finally:
        tracemalloc.stop()
    assert {k: v for k, v in lazy.items() if k != "buildings"} == {k: v for k, v in whole.items() if k != "buildings"}
    assert list(lazy["buildings"]) == whole["buildings"] == list(lazy["buildings"])  # twice, the same
    assert as_lazy < 0.05 * as_list, (as_lazy, as_list)


def _fold_reference(path, start=0):
    """records_of as it was: every line decoded, each record folded into a dict as it came."""
    from lod2energy.run.resume import read_lines
    from lod2energy.records import BuildingRecord, ExportRecord
    out = {}
    for d in read_lines(path, start):
        kind = d.get("kind")
        if kind == "building":
            out[int(d["seq"])] = BuildingRecord.from_json(d)
        elif kind in ("context", "dataset") and int(d["seq"]) in out:
            s = int(d["seq"])
            rec = out[s]
            for e in d.get("exports") or ():
                rec = rec.with_export(ExportRecord.from_journal(e))
            out[s] = rec
    return out


def test_records_of_reads_the_journal_as_every_line_folded_in_order(delft_export, tmp_path):
    from lod2energy.run.resume import _dumps, read_lines, records_of
    out, res = delft_export
    lines = list(read_lines(out / "report.jsonl"))
    body = [ln for ln in lines if ln.get("kind") in ("building", "dataset")]
    b3 = next(ln for ln in body if ln["kind"] == "building" and ln["seq"] == 3)
    d5 = next(ln for ln in body if ln["kind"] == "dataset" and ln["seq"] == 5)
    odd = dict(reversed(list(d5.items())))  # another key order: decoded, not matched
    odd["exports"] = [{**e, "problems": ["from a line of another writer"]} for e in d5["exports"]]
    redo = {**b3, "message": "done again by a resumed run"}
    text = "".join(_dumps(ln) + "\n" for ln in lines) + _dumps(odd) + "\n" + _dumps(redo) + "\n"
    text += _dumps({"kind": "context", "seq": 999, "exports": []}) + "\n"  # no such building: ignored
    text += '{"kind": "dataset", "seq": 2, "exp'  # a torn last line
    path = tmp_path / "report.jsonl"
    path.write_text(text, encoding="utf-8")
    got, ref = records_of(path), _fold_reference(path)
    assert list(got) == list(ref) and len(got) == len(ref) == len(res.records)
    assert [got[s] for s in got] == [ref[s] for s in ref]
    assert got[3].message == "done again by a resumed run" and got[3].exports == (
        tuple(e for e in ref[3].exports))
    assert got[5].export("cityjson").problems == ("from a line of another writer",)
    assert list(got.ordered()) == [ref[s] for s in sorted(ref)]
    assert got.seqs_of([ref[5].id, ref[1].id, "nobody"]) == [1, 5]


def test_journal_fsyncs_at_most_once_a_second_and_when_closed(tmp_path, monkeypatch):
    import os as _os

    from lod2energy.run import resume as J
    calls = []
    real = _os.fsync
    monkeypatch.setattr(J.os, "fsync", lambda fd: (calls.append(fd), real(fd))[1])
    out = tmp_path / "o"
    out.mkdir()
    j = J.Journal(out / "report.jsonl", out, [], {"kind": "header"})
    n0 = len(calls)
    for i in range(200):
        j.append({"kind": "building", "seq": i})
    assert len(calls) - n0 <= 2  # the first line, and one more if a second went by
    j.close()
    assert len(calls) - n0 <= 3 and len(list(J.read_lines(out / "report.jsonl"))) == 201
