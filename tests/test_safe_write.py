"""lod2energy.safe_write: temporaries of dead processes are swept, live ones and other files kept."""
import os
import subprocess
import sys

from lod2energy.safe_write import sweep_stale, write_text


def test_sweep_removes_only_temporaries_of_processes_that_are_gone(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True,
                          text=True).stdout.strip()  # a pid that has just ended
    names = [f".a.idf.{dead}.3.part", f".c.json.{dead}.2.tmp.json", f".d.stl.{dead}.1.staged",
             f".b.idf.{os.getpid()}.1.part", "x.part", "report.json"]
    for n in names:
        (tmp_path / n).write_text("")
    os.symlink(tmp_path / "report.json", tmp_path / f".e.idf.{dead}.4.part")
    removed = sweep_stale(tmp_path)
    assert sorted(removed) == sorted(names[:3])
    assert sorted(os.listdir(tmp_path)) == sorted(names[3:] + [f".e.idf.{dead}.4.part"])


def test_a_written_file_leaves_no_temporary(tmp_path):
    write_text(tmp_path / "f.txt", "x", root=tmp_path)
    assert os.listdir(tmp_path) == ["f.txt"]
