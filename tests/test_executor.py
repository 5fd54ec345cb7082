"""Executors: every executor writes the same bytes; timeouts, SIGTERM and --resume."""
from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from lod2energy.cli import main
from lod2energy.run.side_process import Beside
from lod2energy.run.executor import Failure, InProcessExecutor, Overrun, ProcessPoolExecutor

from conftest import shared_path
from spine_inputs import huge_building_line, row_of_boxes_seq, terraced_subset, tree_bytes

REPO = Path(__file__).resolve().parents[1]
DELFT = REPO / "examples" / "delft_subset.city.jsonl"


# ----------------------------------------------------------------------------- executors alone

def _square(x):
    return x * x


def _sleepy(x):
    time.sleep(x)
    return x


def _boom(x):
    raise ValueError(f"bad {x}")


@pytest.mark.parametrize("make", [InProcessExecutor, lambda: ProcessPoolExecutor(2, window=3)])
def test_results_come_in_input_order_with_failures_and_overruns(make):
    with make() as ex:
        got = list(ex.map(_square, range(7)))
        assert got == [(i, i * i) for i in range(7)]
        (arg, res), = list(ex.map(_boom, [3]))
        assert isinstance(res, Failure) and "ValueError: bad 3" in res.message
        out = list(ex.map(_sleepy, [0.0, 30.0, 0.0], timeout=1.0))
        assert [a for a, _ in out] == [0.0, 30.0, 0.0]
        assert out[0][1] == 0.0 and isinstance(out[1][1], Overrun) and out[2][1] == 0.0


def test_pool_replaces_a_killed_worker_and_goes_on():
    with ProcessPoolExecutor(2) as ex:
        out = list(ex.map(_sleepy, [30.0, 30.0, 0.0, 0.0], timeout=0.5))
        assert [type(r) for _, r in out[:2]] == [Overrun, Overrun]
        assert [r for _, r in out[2:]] == [0.0, 0.0]
        assert len(ex._workers) == 2 and all(w.proc.is_alive() for w in ex._workers)


def _spin(seconds):
    """Busy for ``seconds`` s of CPU time (s); returns them."""
    t0 = time.process_time()
    while time.process_time() - t0 < seconds:
        pass
    return seconds


@pytest.mark.parametrize("make", [InProcessExecutor, lambda: ProcessPoolExecutor(1)])
def test_a_cpu_bound_job_is_stopped_at_its_budget_not_later(make):
    import resource

    def cpu():
        me, ch = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
        return me.ru_utime + me.ru_stime + ch.ru_utime + ch.ru_stime

    with make() as ex:
        c0 = cpu()
        (_, res), = list(ex.map(_spin, [20.0], timeout=1.0))
        assert isinstance(res, Overrun)
    spent = cpu() - c0  # the killed worker is reaped by close(): its CPU is counted here
    assert 0.9 <= spent < 2.5, f"a job with a 1 s budget cost {spent:.2f} CPU s"


def test_export_stops_a_job_at_the_timeout_itself_and_repair_keeps_its_margin():
    from lod2energy.options import ExportOptions, PrepareOptions, hard_budget

    assert ExportOptions(prepare=PrepareOptions(timeout=5.0)).job_timeout == 5.0
    assert ExportOptions(prepare=PrepareOptions(timeout=5.0), hard_timeout=3.0).job_timeout == 3.0
    assert ExportOptions(prepare=PrepareOptions(timeout=5.0), hard_timeout=0).job_timeout is None
    assert hard_budget(5.0) == 7.0 and hard_budget(30.0) == 36.0  # lod2energy repair
    assert hard_budget(5.0, margin=False) == 5.0 and hard_budget(0) is None


# ----------------------------------------------------------------------------- byte-identical outputs

def _export(args, out: Path, capsys=None) -> int:
    rc = main(["export", *args, "-o", str(out), "-q"])
    if capsys is not None:
        o, e = capsys.readouterr()
        assert "Traceback" not in o + e
    return rc


def _runs_agree(src: str, fmt_args: list[str], variants: list[list[str]], tmp_path: Path, capsys) -> dict:
    """Export ``src`` once per variant into the same OUTDIR; every tree must be byte-identical."""
    out = tmp_path / "out"
    trees = []
    for extra in variants:
        if out.exists():
            shutil.rmtree(out)
        rc = _export([src, *fmt_args, *extra], out, capsys)
        assert rc in (0, 1)
        trees.append(tree_bytes(out))
    first = trees[0]
    assert any(k.endswith(".idf") for k in first) or "--idf" not in fmt_args
    for t in trees[1:]:
        assert sorted(t) == sorted(first)
        for k in first:
            assert t[k] == first[k], f"{k} differs between executors"
    return first


def _dies(x):
    os._exit(3)


def test_a_job_beside_the_pool_returns_its_result_or_its_failure():
    assert Beside(_square, 7).result() == 49
    bad = Beside(_boom, 2).result()
    assert isinstance(bad, Failure) and bad.message == "ValueError: bad 2"
    dead = Beside(_dies, 0).result()
    assert isinstance(dead, Failure) and "exit code 3" in dead.message


def test_a_job_beside_the_pool_is_stopped_by_cancel_and_only_once():
    job = Beside(_sleepy, 60)
    assert job.cancel() is True
    assert not job.proc.is_alive()
    assert job.cancel() is False
    done = Beside(_square, 3)
    assert done.result() == 9 and done.cancel() is False


def test_the_one_file_writers_wait_for_pass_2_only_when_idfs_are_written():
    # they carry the written IDF's areas and UA (and a run's figures)
    from lod2energy.dataset import beside_ok
    from lod2energy.exporters.energyplus.options import IdfOptions
    from lod2energy.options import ExportOptions
    assert not beside_ok(ExportOptions(formats=("idf", "stl", "cityjson")))
    assert not beside_ok(ExportOptions(formats=("idf", "cityjson"), idf=IdfOptions(run=True)))
    assert beside_ok(ExportOptions(formats=("stl", "cityjson"), idf=IdfOptions(run=True)))


ALL = ["--idf", "--stl", "--cityjson"]


def test_jobs_2_writes_the_same_bytes_as_jobs_1_on_delft(tmp_path, capsys):
    tree = _runs_agree(str(DELFT), ALL, [["-j", "1"], ["-j", "2"]], tmp_path, capsys)
    rep = json.loads(tree["report.json"])
    assert len(rep["buildings"]) == 10 and "seconds" not in rep
    assert sum(k.endswith(".stl") for k in tree) == 10 and "report.jsonl" in tree


def test_party_walls_and_shading_agree_across_executors_on_a_row_of_boxes(tmp_path, capsys):
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=5)
    tree = _runs_agree(src, ALL + ["--shading"], [["-j", "1"], ["-j", "2"]], tmp_path, capsys)
    idf = tree["b2.idf"].decode()
    # the middle box shares two walls: adiabatic, and its neighbours shade it
    assert idf.count("Adiabatic") >= 2 and "Shading:Building:Detailed" in idf


def test_terraced_3dbag_subset_with_shading_agrees_across_executors(tmp_path, capsys):
    tile = shared_path("3dbag", "tile901_trimmed.city.jsonl")
    if not tile.exists():
        pytest.skip("3dbag/tile901_trimmed.city.jsonl missing")
    src = terraced_subset(tile, tmp_path / "terraced.city.jsonl", k=5)
    assert src is not None
    tree = _runs_agree(src, ALL + ["--shading"], [["-j", "1"], ["-j", "2"]], tmp_path, capsys)
    idfs = [v.decode() for k, v in tree.items() if k.endswith(".idf")]
    assert idfs and any("Adiabatic" in t for t in idfs)


def test_dask_local_cluster_writes_the_same_bytes_as_jobs_1(tmp_path, capsys):
    distributed = pytest.importorskip("dask.distributed")
    from lod2energy.cli import build_parser
    from lod2energy.options import export_options
    from lod2energy.run.executor import DaskExecutor
    from lod2energy.options import RunOptions
    from lod2energy.pipeline import export

    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=4)
    out = tmp_path / "out"
    assert _export([src, *ALL, "--shading", "-j", "1"], out, capsys) in (0, 1)
    ref = tree_bytes(out)
    shutil.rmtree(out)
    a = build_parser().parse_args(["export", src, "-o", str(out), *ALL, "--shading"])
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        res = export(src, str(out), export_options(a), RunOptions(quiet=True), executor=DaskExecutor(client))
    assert res.exit_code in (0, 1)
    got = tree_bytes(out)
    assert sorted(got) == sorted(ref)
    for k in ref:
        assert got[k] == ref[k], f"{k} differs between Dask and --jobs 1"


# ----------------------------------------------------------------------------- time budget

@pytest.mark.parametrize("jobs", ["2", "1"])
def test_a_100000_face_building_is_reported_timeout_and_the_others_exported(tmp_path, capsys, jobs):
    src = row_of_boxes_seq(tmp_path / "with_huge.city.jsonl", n=2, touching=False,
                           extra_lines=[huge_building_line(129)])
    out = tmp_path / "out"
    rc = main(["export", src, "-o", str(out), "--stl", "--cityjson", "--timeout", "5", "-j", jobs, "-q"])
    o, e = capsys.readouterr()
    assert "Traceback" not in o + e and rc == 1
    rows = {b["id"]: b for b in json.loads((out / "report.json").read_text())["buildings"]}
    assert rows["huge"]["outcome"] == "timeout" and "timeout" in rows["huge"]["message"]
    for bid in ("b0", "b1"):
        assert rows[bid]["outcome"] == "done" and rows[bid]["stl_ok"] and rows[bid]["cityjson_ok"]
    assert "huge: timeout" in e or "timeout" in e
    assert not (out / ".lod2energy" / "spool" / f"{2:08d}.pkl").exists()  # a timeout is not spooled
    page = (out / "report.html").read_text(encoding="utf-8")  # drawn, the huge one by its hull
    assert "huge" in page and len(page) < 500_000, len(page)  # one ring per downward face: > 1.2 MB


def test_an_idf_context_job_past_the_timeout_is_stopped_and_the_neighbours_exported(tmp_path, capsys,
                                                                                    monkeypatch):
    """Pass 2 (the IDF writer with its neighbours) has the --timeout budget of pass 1: the
    energy model of the middle box of a terraced row of 3 spins past it; its IDF is reported
    not written (timeout), the other two are written (in-process: the patch reaches the job)."""
    from lod2energy.energy import model as energy_model
    real = energy_model.prepare_energy_model

    def slow_for_b1(buildings, options, context=()):
        buildings = list(buildings)
        if context and any(str(b.id) == "b1" for b in buildings):
            _spin(60.0)
        return real(buildings, options, context)

    monkeypatch.setattr(energy_model, "prepare_energy_model", slow_for_b1)
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=3, touching=True)
    out = tmp_path / "out"
    rc = main(["export", src, "-o", str(out), "--idf", "--timeout", "3", "-j", "1", "-q"])
    o, e = capsys.readouterr()
    assert "Traceback" not in o + e and rc == 1
    rows = {b["id"]: b for b in json.loads((out / "report.json").read_text())["buildings"]}
    assert rows["b1"]["outcome"] == "done" and not rows["b1"]["idf_ok"]
    assert not list(out.glob("**/b1*.idf"))
    for bid in ("b0", "b2"):
        assert rows[bid]["idf_ok"] and list(out.glob(f"**/{bid}*.idf")), bid
    # the user reads that no file was written, and why; not that a file failed its self-check
    assert "IDF export b1 not written: timeout: not finished within 3 s (--timeout)" in e
    assert "failed its self-check" not in e
    csv_text = next(out.glob("*.csv")).read_text(encoding="utf-8")
    assert "not finished within 3 s" in (out / "report.json").read_text() or "timeout" in csv_text


# ----------------------------------------------------------------------------- time budget on Dask

def _spin_and_tell(job):
    """Write this process's id to ``job[0]``, then spin ``job[1]`` s of CPU time."""
    Path(job[0]).write_text(str(os.getpid()))
    return _spin(job[1])


def _pid(_):
    return os.getpid()


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return Path(f"/proc/{pid}").exists() and "Z" not in Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1][:3]


@pytest.mark.parametrize("processes", [True, False])
def test_dask_stops_a_cpu_bound_job_at_its_budget_and_the_worker_goes_on(tmp_path, processes):
    distributed = pytest.importorskip("dask.distributed")
    from lod2energy.run.executor import DaskExecutor

    tell = tmp_path / "pid"
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=processes,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        worker_pid, = client.run(os.getpid).values()
        with DaskExecutor(client) as ex:
            first = list(ex.map(_pid, [0], timeout=5.0))[0][1]  # the budget process, started
            out = list(ex.map(_spin_and_tell, [(str(tell), 0.0), (str(tell), 60.0), (str(tell), 0.0)],
                              timeout=1.0))
            assert [a[1] for a, _ in out] == [0.0, 60.0, 0.0]
            assert out[0][1] == 0.0 and out[2][1] == 0.0  # the one thread went on after the overrun
            stopped = out[1][1]
            assert isinstance(stopped, Overrun), stopped
            after = int(tell.read_text())  # the third job ran in a fresh budget process
            assert first not in (worker_pid, after) and not _alive(first)  # killed and reaped
            assert list(ex.map(_square, range(4), timeout=1.0)) == [(i, i * i) for i in range(4)]
            assert list(ex.map(_boom, [2], timeout=1.0))[0][1].message.startswith("ValueError: bad 2")
            assert list(ex.map(_square, [3]))[0][1] == 9  # no budget: in the worker thread
        assert not _alive(after)  # close() stops the budget processes on every worker


def test_dask_reports_a_100000_face_building_timeout_with_the_bytes_of_jobs_1(tmp_path, capsys):
    # worker processes (processes=False is covered by the budget test above)
    distributed = pytest.importorskip("dask.distributed")
    from lod2energy.cli import build_parser
    from lod2energy.options import export_options
    from lod2energy.run.executor import DaskExecutor
    from lod2energy.options import RunOptions
    from lod2energy.pipeline import export

    src = row_of_boxes_seq(tmp_path / "with_huge.city.jsonl", n=2, touching=False,
                           extra_lines=[huge_building_line(129)])
    fmt = ["--stl", "--cityjson", "--timeout", "5"]
    out = tmp_path / "out"
    assert _export([src, *fmt, "-j", "1"], out, capsys) == 1
    ref = tree_bytes(out)
    shutil.rmtree(out)
    a = build_parser().parse_args(["export", src, "-o", str(out), *fmt])
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        with DaskExecutor(client) as ex:
            res = export(src, str(out), export_options(a), RunOptions(quiet=True), executor=ex)
    assert res.exit_code == 1
    rows = {b["id"]: b for b in json.loads((out / "report.json").read_text())["buildings"]}
    assert rows["huge"]["outcome"] == "timeout" and "timeout" in rows["huge"]["message"]
    assert all(rows[b]["outcome"] == "done" and rows[b]["stl_ok"] for b in ("b0", "b1"))
    got = tree_bytes(out)
    assert sorted(got) == sorted(ref)
    for k in ref:
        assert got[k] == ref[k], f"{k} differs between Dask and --jobs 1"


# ----------------------------------------------------------------------------- SIGTERM and --resume

def _journal_buildings(out: Path) -> int:
    p = out / "report.jsonl"
    if not p.exists():
        return 0
    return sum('"kind": "building"' in ln for ln in p.read_text().splitlines())


def test_sigterm_then_resume_ends_with_the_files_of_an_uninterrupted_run(tmp_path):
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=12)
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "lod2energy", "export", src, "-o", str(out), *ALL, "-j", "1", "-q"]
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    assert subprocess.run(cmd, env=env, capture_output=True).returncode == 0
    ref = tree_bytes(out, skip=(".lod2energy", "report.jsonl"))
    shutil.rmtree(out)

    p = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t0 = time.monotonic()
    while _journal_buildings(out) < 3 and time.monotonic() - t0 < 120 and p.poll() is None:
        time.sleep(0.05)
    assert p.poll() is None, "the run ended before it could be interrupted"
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 143, err
    assert "Traceback" not in err and "interrupted by SIGTERM" in err
    part = json.loads((out / "report.json").read_text())
    assert part["interrupted"] == "SIGTERM" and 3 <= len(part["buildings"]) < 12
    done_before = _journal_buildings(out)

    r = subprocess.run(cmd + ["--resume"], env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    got = tree_bytes(out, skip=(".lod2energy", "report.jsonl"))
    assert sorted(got) == sorted(ref)
    for k in ref:
        assert got[k] == ref[k], f"{k} differs after --resume"
    # the resumed run re-used the buildings the first one had finished
    lines = [json.loads(ln) for ln in (out / "report.jsonl").read_text().splitlines()]
    assert sum(ln["kind"] == "building" for ln in lines) == done_before + 12


def test_resume_redoes_a_building_whose_file_changed(tmp_path, capsys):
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=3, touching=False)
    out = tmp_path / "out"
    assert _export([src, "--stl"], out, capsys) == 0
    stl = out / "b1.stl"
    good = stl.read_bytes()
    stl.write_bytes(good[:-10])
    assert _export([src, "--stl", "--resume"], out, capsys) == 0
    assert stl.read_bytes() == good


def _journal_kinds(out: Path) -> list[str]:
    p = out / "report.jsonl"
    if not p.exists():
        return []
    kinds = []
    for ln in p.read_text().splitlines():
        try:
            kinds.append(json.loads(ln).get("kind"))
        except ValueError:
            pass  # a line being written
    return kinds


def test_sigterm_in_pass_2_with_the_cityjson_beside_leaves_no_temporary_and_resume_completes(tmp_path):
    # enough buildings that the CityJSON is still being written when pass 2 starts
    src = row_of_boxes_seq(tmp_path / "row.city.jsonl", n=60)
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "lod2energy", "export", src, "-o", str(out), *ALL, "-q"]
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    assert subprocess.run(cmd + ["-j", "1"], env=env, capture_output=True).returncode == 0
    ref = tree_bytes(out, skip=(".lod2energy", "report.jsonl"))
    shutil.rmtree(out)

    p = subprocess.Popen(cmd + ["-j", "2"], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t0 = time.monotonic()
    while "context" not in _journal_kinds(out) and time.monotonic() - t0 < 120 and p.poll() is None:
        time.sleep(0.02)
    assert p.poll() is None, "the run ended before pass 2 could be interrupted"
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 143, err
    assert "Traceback" not in err
    left = [f.name for f in out.iterdir() if f.name.startswith(".") and f.name != ".lod2energy"]
    assert left == [], f"temporaries left in OUTDIR: {left}"
    assert not [f.name for f in out.iterdir() if f.name.endswith(".invalid")]

    r = subprocess.run(cmd + ["-j", "2", "--resume"], env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    got = tree_bytes(out, skip=(".lod2energy", "report.jsonl"))
    assert sorted(got) == sorted(ref)
    for k in ref:
        assert got[k] == ref[k], f"{k} differs after --resume"


def _append_pid(arg, _=None):
    with open(arg, "a") as f:
        f.write(f"{os.getpid()}\n")


def _sleep_then_mark(arg):
    seconds, mark = arg
    time.sleep(seconds)
    Path(mark).write_text("done")
    return seconds


def test_pool_reads_the_next_argument_while_its_workers_run(tmp_path):
    marks = [tmp_path / f"m{i}" for i in range(4)]
    finished_when_read = []

    def args():
        for i, m in enumerate(marks):
            finished_when_read.append(sum(p.exists() for p in marks))
            yield (1.0 if i < 2 else 0.0), str(m)
    with ProcessPoolExecutor(2) as ex:
        assert [r for _, r in ex.map(_sleep_then_mark, args())] == [1.0, 1.0, 0.0, 0.0]
    # the third argument was read while the first two jobs ran, not after one of them ended
    assert finished_when_read[:3] == [0, 0, 0]


def test_tail_runs_once_in_each_worker_left_idle_and_its_result_is_dropped(tmp_path):
    from functools import partial
    marks = tmp_path / "tail.txt"
    with ProcessPoolExecutor(2) as ex:
        out = list(ex.map(_sleepy, [0.0, 1.0], tail=partial(_append_pid, str(marks))))
        assert [r for _, r in out] == [0.0, 1.0]
        again = list(ex.map(_square, range(6), tail=partial(_append_pid, str(marks))))
        assert [r for _, r in again] == [x * x for x in range(6)]  # a tail still running is waited for
        pids = {w.proc.pid for w in ex._workers}
    lines = marks.read_text().split()
    assert 1 <= len(lines) <= 2 and len(set(lines)) == len(lines) and set(map(int, lines)) <= pids
