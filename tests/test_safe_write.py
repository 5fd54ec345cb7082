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


def test_write_checked_syncs_the_folder_once_after_the_final_rename(tmp_path, monkeypatch):
    """The file is synced before its renames; the folder once, after the good name is given
    (the staged name never needs to last); a sidecar written with ``sync_folder=False`` just
    before is covered by that same folder sync."""
    import stat
    from lod2energy import safe_write as sw
    events = []
    real_fsync, real_replace = os.fsync, os.replace

    def fsync(fd):
        events.append("dir" if stat.S_ISDIR(os.fstat(fd).st_mode) else "file")
        return real_fsync(fd)

    def replace(a, b):
        events.append("final" if not os.path.basename(str(b)).startswith(".") else "staged")
        return real_replace(a, b)

    monkeypatch.setattr(os, "fsync", fsync)
    monkeypatch.setattr(os, "replace", replace)
    sw.write_text(tmp_path / "a.json", "{}", root=tmp_path, sync_folder=False)
    assert events == ["file", "final"]
    events.clear()
    final, problems = sw.write_checked(tmp_path / "a.stl", lambda f: f.write("x"), lambda p: [], root=tmp_path)
    assert final == str(tmp_path / "a.stl") and problems == []
    assert events == ["file", "staged", "final", "dir"]
    events.clear()
    sw.write_text(tmp_path / "b.txt", "y", root=tmp_path)  # the default: the folder too
    assert events == ["file", "final", "dir"]
    events.clear()
    sw.write_checked(tmp_path / "c.stl", lambda f: f.write("x"), lambda p: [], root=tmp_path, fsync=False)
    assert events == ["staged", "final"]
