"""Hostile conditions at the command line (issue 15): outputs that are inputs, links under the
report names, signals, the time budget, an external entity given to ``export``.

Run as separate processes (``python -m lod2energy``), as a user would; the invariants are
those of ``test_hostile.py``: exit code, one clear line, no traceback, input unchanged,
nothing written outside OUTDIR.
"""
from __future__ import annotations

import copy
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from test_hostile import FEATURES, HEADER, IDS, error_lines, write_seq



def cli(*args, timeout: float = 300, **kw) -> subprocess.CompletedProcess:
    p = subprocess.run([sys.executable, "-m", "lod2energy", *map(str, args)], capture_output=True, text=True,
                       timeout=timeout, **kw)
    assert "Traceback" not in p.stdout + p.stderr, p.stderr
    return p


@pytest.fixture
def seq(tmp_path) -> Path:
    return write_seq(tmp_path, copy.deepcopy(FEATURES))


# ----------------------------------------------------------------------------- data destroyed

@pytest.mark.parametrize("cmd", ["validate-report", "repair-output", "repair-report"])
def test_an_output_that_is_an_input_is_refused_with_exit_2(tmp_path, seq, cmd):
    before = seq.read_bytes()
    args = {"validate-report": ["validate", seq, "--report", seq],
            "repair-output": ["repair", seq, "-o", seq],
            "repair-report": ["repair", seq, "-o", tmp_path / "r.city.jsonl", "--report", seq]}[cmd]
    p = cli(*args)
    assert p.returncode == 2
    assert len(error_lines(p.stderr)) == 1 and "input" in p.stderr
    assert seq.read_bytes() == before


def test_an_output_that_is_an_input_through_a_link_is_refused(tmp_path, seq):
    before = seq.read_bytes()
    alias = tmp_path / "alias.json"
    alias.symlink_to(seq)
    p = cli("validate", seq, "--report", alias)
    assert p.returncode == 2 and seq.read_bytes() == before


# ----------------------------------------------------------------------------- links in OUTDIR

def test_links_under_the_report_names_are_not_followed(tmp_path, seq):
    outdir = tmp_path / "out"
    outdir.mkdir()
    victim = tmp_path / "victim.txt"
    victim.write_text("do not touch\n")
    for n in ("report.json", "report.csv", "report.json.part", ".report.json.part", "report.csv.part",
              ".report.csv.part", "energy.ext.json", "in.energy.city.json"):
        (outdir / n).symlink_to(victim)
    p = cli("export", seq, "-o", outdir, "--cityjson", "-q")
    assert victim.read_text() == "do not touch\n"
    assert p.returncode != 0 and "symbolic link" in p.stderr
    assert len([ln for ln in error_lines(p.stderr) if "report" in ln]) >= 1


# ----------------------------------------------------------------------------- signals

def _many(tmp_path: Path, copies: int = 16) -> Path:
    feats = []
    for k in range(copies):
        for f in FEATURES:
            s = json.dumps(f)
            for oid in f["CityObjects"]:
                s = s.replace(json.dumps(oid), json.dumps(f"{oid}-copy{k}"))
            feats.append(json.loads(s))
    return write_seq(tmp_path, feats, "many.city.jsonl")


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_finishes_the_report(tmp_path, sig):
    inp = _many(tmp_path)
    outdir = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "lod2energy", "export", str(inp), "-o", str(outdir),
                             "--cityjson", "--stl", "--idf", "-q"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while not outdir.exists() and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.05)  # OUTDIR is made once the input is open: the buildings are being prepared
    time.sleep(1.0)
    assert proc.poll() is None, "the export ended before the signal"
    proc.send_signal(sig)
    out, err = proc.communicate(timeout=120)
    assert "Traceback" not in out + err
    assert proc.returncode != 0
    assert len(error_lines(err)) >= 1 and len(err.strip().splitlines()) <= 3, err
    rep = json.loads((outdir / "report.json").read_text())
    assert isinstance(rep["buildings"], list)


# ----------------------------------------------------------------------------- time budget

def _grid_box(x0: float, n: int, size: float = 10.0) -> tuple[list, list]:
    """A box whose six sides are n x n grids of quads: (vertices in mm, faces)."""
    import numpy as np
    s = np.linspace(0, size, n + 1)
    verts: dict = {}
    faces = []

    def vid(p):
        key = tuple(int(round(c * 1000)) for c in p)
        if key not in verts:
            verts[key] = len(verts)
        return verts[key]
    for axis in range(3):
        for side in (0, size):
            for i in range(n):
                for j in range(n):
                    q = []
                    for a, b in ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)):
                        p = [0.0, 0.0, 0.0]
                        p[axis] = side
                        p[(axis + 1) % 3], p[(axis + 2) % 3] = s[a], s[b]
                        p[0] += x0
                        q.append(vid(p))
                    faces.append([q if side else q[::-1]])
    v = [list(k) for k in sorted(verts, key=verts.get)]
    return v, faces


def test_timeout_bounds_the_repair_of_a_100000_face_building(tmp_path):
    v1, f1 = _grid_box(0.0, 91)
    v2, f2 = _grid_box(4.0, 91)  # a second box overlapping the first, in the same shell
    f2 = [[[i + len(v1) for i in r] for r in f] for f in f2]
    faces = f1 + f2
    del faces[5]  # and a hole
    assert len(faces) >= 99_000
    h = copy.deepcopy(HEADER)
    h["transform"] = {"scale": [0.001, 0.001, 0.001], "translate": [85000.0, 447000.0, 0.0]}
    feat = {"type": "CityJSONFeature", "id": "big", "vertices": v1 + v2,
            "CityObjects": {"big": {"type": "Building", "geometry": [
                {"type": "Solid", "lod": "2.2", "boundaries": [faces]}]}}}
    inp = write_seq(tmp_path, [feat], "big.city.jsonl", header=h)
    p = cli("repair", inp, "-o", tmp_path / "r.city.jsonl", "--report", tmp_path / "r.json", "--timeout", "5",
            "-q", timeout=300)
    assert p.returncode == 1
    rep = json.loads((tmp_path / "r.json").read_text())
    # its job is stopped at its CPU budget and the building kept as read (no assertion on wall time)
    (b,) = rep["buildings"]
    assert b["id"] == "big" and b["stage"] == "timeout" and "kept as read" in b["error"]


# ----------------------------------------------------------------------------- XML

def test_export_of_a_citygml_external_entity_exits_2_without_a_fake_building(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("s3cret")
    gml = tmp_path / "xxe.gml"
    gml.write_text(f'<?xml version="1.0"?>\n<!DOCTYPE x [<!ENTITY e SYSTEM "file://{secret}">]>\n'
                   '<CityModel xmlns="http://www.opengis.net/citygml/2.0"><name>&e;</name></CityModel>\n')
    outdir = tmp_path / "out"
    p = cli("export", gml, "-o", outdir, "--cityjson", "--idf", "-q")
    assert p.returncode == 2, p.stderr
    assert "s3cret" not in p.stdout + p.stderr and len(error_lines(p.stderr)) == 1
    rp = outdir / "report.json"
    if rp.exists():
        rep = json.loads(rp.read_text())
        assert all(b["id"] not in (None, "None") for b in rep.get("buildings", []))
    assert not list(outdir.glob("*.energy.city.json")) if outdir.exists() else True
    assert os.listdir(tmp_path) and secret.read_text() == "s3cret"
