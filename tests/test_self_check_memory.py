"""What the CityJSON self-check keeps while it reads an exported document (exporters.cityjson.check)."""
from __future__ import annotations

import json

import numpy as np

from lod2energy.exporters.cityjson import check as C
from lod2energy.io import cityjson as cjio


def _doc(n: int) -> dict:
    cos = {}
    for i in range(n):
        cos[f"b{i}"] = {"type": "Building", "children": [f"b{i}_1", f"b{i}_2"]}
        for k in (1, 2):
            cos[f"b{i}_{k}"] = {"type": "BuildingPart", "parents": [f"b{i}"], "geometry": []}
    cos["orphan"] = {"type": "BuildingPart", "parents": ["nobody"]}
    cos["cycle_a"] = {"type": "BuildingPart", "parents": ["cycle_b"], "children": ["cycle_b"]}
    cos["cycle_b"] = {"type": "BuildingPart", "parents": ["cycle_a"], "children": ["cycle_a"]}
    rng = np.random.default_rng(3)
    verts = rng.integers(-10**9, 10**9, size=(70_000, 3)).tolist()  # more than one chunk
    return {"type": "CityJSON", "version": "2.0", "transform": {"scale": [0.001, 0.002, 0.0005],
            "translate": [85000.25, 446000.5, -3.125]}, "CityObjects": cos, "vertices": verts}


def _written(tmp_path, doc: dict):
    """``doc`` written as ``d.city.json``; its transform and its vertices as the reader computes them."""
    path = tmp_path / "d.city.json"
    path.write_text(json.dumps(doc), encoding="utf-8")
    t = doc["transform"]
    want = np.asarray(doc["vertices"], dtype=np.int64).astype(np.float64) * np.asarray(t["scale"]) \
        + np.asarray(t["translate"])
    return path, t, want


def test_the_first_reading_keeps_the_vertices_out_of_memory_bit_for_bit(tmp_path):
    path, t, want = _written(tmp_path, _doc(50))
    rng = np.random.default_rng(5)
    picks = [np.arange(len(want)), np.arange(65_530, 65_545), np.array([0, 3, 65_535, 65_536, 69_999]),
             np.unique(rng.integers(0, len(want), 300)), np.zeros(0, dtype=np.intp)]
    p = C._first_pass(str(path), str(tmp_path))
    got = p.vertices(t)
    assert got._array is None and got._f is not None  # in the scratch file, not in memory
    assert len(got) == len(want)
    for used in picks:  # a run, across a chunk's end, scattered, none
        g = got[used]
        assert g.dtype == np.float64 and g.tobytes() == want[used].tobytes()
    p.verts.close()
    # without a scratch file (a folder that cannot hold one): in memory, the same values
    q = C._first_pass(str(path), str(tmp_path / "missing"))
    mem = q.vertices(t)
    assert mem._array is not None and mem._array.tobytes() == want.tobytes()
    assert mem[picks[3]].tobytes() == want[picks[3]].tobytes()
    assert list(tmp_path.iterdir()) == [path]  # the scratch file has no name, nothing is left


def test_a_full_disk_brings_the_vertices_back_to_memory(tmp_path, monkeypatch):
    import errno
    path, t, want = _written(tmp_path, _doc(5))
    real, calls = C._write_all, []

    def fills_up(fd, data):  # the first chunk fits, the disk is full at the second
        calls.append(len(data))
        if len(calls) > 1:
            real(fd, data[:1000])  # part of it lands before the error
            raise OSError(errno.ENOSPC, "No space left on device")
        real(fd, data)
    monkeypatch.setattr(C, "_write_all", fills_up)
    p = C._first_pass(str(path), str(tmp_path))
    got = p.vertices(t)
    assert len(calls) == 2 and got._f is None and got._array is not None
    assert got._array.tobytes() == want.tobytes()


def test_the_links_reading_groups_as_the_reader(tmp_path):
    doc = _doc(50)
    path = tmp_path / "d.city.json"
    path.write_text(json.dumps(doc), encoding="utf-8")
    links, dups = C._links_pass(str(path))
    cos = doc["CityObjects"]
    assert dups == [] and cjio._feature_ids(links) == cjio._feature_ids(cos)
    groups = cjio._feature_ids(cos)
    assert ([e.message for e in cjio._orphan_errors(links, groups, "d")]
            == [e.message for e in cjio._orphan_errors(cos, groups, "d")])
    assert {k: dict(v) for k, v in links.items()} == {
        k: {x: v[x] for x in ("type", "parents", "children") if x in v} for k, v in cos.items()}


def test_a_link_costs_a_fraction_of_the_dict_it_replaces():
    """Each CityObject is parsed afresh, as the first reading parses it, and only what is kept of
    it is counted: the dict of its three members, or its :class:`_Link`."""
    import sys
    import tracemalloc
    texts = [(k, json.dumps(v)) for k, v in _doc(400)["CityObjects"].items()]

    def kept(make, name=str) -> tuple[dict, int]:
        tracemalloc.start()
        try:
            base = tracemalloc.get_traced_memory()[0]
            out = {}
            for k, t in texts:
                key = name(json.loads(json.dumps(k)))
                out[key] = make(json.loads(t))
            return out, tracemalloc.get_traced_memory()[0] - base
        finally:
            tracemalloc.stop()

    as_dicts, dicts = kept(lambda co: {x: co[x] for x in ("type", "parents", "children") if x in co})
    as_links, links = kept(C._Link.of, sys.intern)  # as the first reading keys them
    assert {k: dict(v) for k, v in as_links.items()} == as_dicts
    assert links < 0.7 * dicts, (links, dicts)  # measured: 0.61


def test_give_back_asks_the_c_library_on_linux():
    import sys
    from lod2energy.run.memory import give_back
    assert give_back() is sys.platform.startswith("linux")


# ---------------------------------------------------------------- local runs vs every link

_CUBE = [[[[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]]]]


def _cube_doc(n: int, open_every: int = 0) -> dict:
    """``n`` Buildings, each a part with a 10 m cube (8 vertices of its own, written after the
    previous building's), every ``open_every``-th part missing its roof."""
    cos, verts = {}, []
    for i in range(n):
        o = len(verts)
        verts += [[i * 20000 + x * 10000, y * 10000, z * 10000]
                  for z in (0, 1) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))]
        shell = [[[o + k for k in ring[0]]] for ring in _CUBE[0]]
        values = [0, 1, 2, 2, 2, 2]
        if open_every and i % open_every == 0:
            shell, values = shell[:-1], values[:-1]
        sem = {"surfaces": [{"type": t, "uValue": 0.3} for t in ("GroundSurface", "RoofSurface", "WallSurface")],
               "values": [values]}
        cos[f"b{i}"] = {"type": "Building", "attributes": {"+energy-note": i}, "children": [f"b{i}-p"]}
        cos[f"b{i}-p"] = {"type": "BuildingPart", "parents": [f"b{i}"],
                          "geometry": [{"type": "Solid", "lod": "2.2", "boundaries": [shell], "semantics": sem}]}
    return {"type": "CityJSON", "version": "2.0", "transform": {"scale": [0.001, 0.001, 0.001],
            "translate": [85000.0, 446000.0, 0.0]}, "CityObjects": cos, "vertices": verts}


def _both(tmp_path, monkeypatch, text: str, name: str) -> tuple[list, list, bool]:
    """The verdict of the check and of the check reading every link; whether the first read them."""
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    read_links = []
    real = C._links_pass
    monkeypatch.setattr(C, "_links_pass", lambda p: (read_links.append(p), real(p))[1])
    first = C.self_check_document(str(path))
    used_links = bool(read_links)
    real_first = C._first_pass

    def every_link(*a, **k):
        p = real_first(*a, **k)
        p.repeated = True  # as if two ids might be equal: the check reads every link
        return p
    monkeypatch.setattr(C, "_first_pass", every_link)
    second = C.self_check_document(str(path))
    monkeypatch.setattr(C, "_first_pass", real_first)
    return first, second, used_links


def test_runs_of_linked_objects_give_the_verdict_of_every_link(tmp_path, monkeypatch):
    doc = _cube_doc(30, open_every=7)
    first, second, used = _both(tmp_path, monkeypatch, json.dumps(doc), "runs.city.json")
    assert first == second and not used
    assert sum("coid=b" in x for x in first) >= 4, first  # the open cubes are found (b0, b7, b14, ...)


def test_documents_whose_links_leave_a_run_fall_back_to_every_link(tmp_path, monkeypatch):
    doc = _cube_doc(12)
    cos = doc["CityObjects"]
    # a part written before its parent, a part that names an earlier parent that does not list
    # it, an orphan, a cycle, a child shared by two parents, a link to an id the file lacks
    moved = {"b3-p": cos.pop("b3-p")}
    cos = {**moved, **cos}
    cos["late"] = {"type": "BuildingPart", "parents": ["b1"]}
    cos["orphan"] = {"type": "BuildingPart", "parents": ["nobody"]}
    cos["cyc_a"] = {"type": "BuildingPart", "parents": ["cyc_b"], "children": ["cyc_b"]}
    cos["cyc_b"] = {"type": "BuildingPart", "parents": ["cyc_a"], "children": ["cyc_a"]}
    cos["b5"]["children"] = ["b5-p", "ghost"]
    doc["CityObjects"] = cos
    first, second, used = _both(tmp_path, monkeypatch, json.dumps(doc), "links.city.json")
    assert first == second and used  # 'late' links back to b1: every link was read
    assert any("late" in x for x in first) and any("cyc_a" in x for x in first), first
    # the same document without 'late' is local: the child before its parent, the orphan and
    # the cycle each complete a run of their own
    del cos["late"]
    first, second, used = _both(tmp_path, monkeypatch, json.dumps(doc), "local.city.json")
    assert first == second and not used
    assert any("cyc_a" in x for x in first) and not any("late" in x for x in first), first


def test_a_repeated_id_reads_every_link(tmp_path, monkeypatch):
    text = json.dumps(_cube_doc(3))
    text = text.replace('"CityObjects": {', '"CityObjects": {"b1-p": {"type": "BuildingPart", "parents": ["b1"]}, ', 1)
    first, second, used = _both(tmp_path, monkeypatch, text, "dup.city.json")
    assert first == second and used
    assert any("more than one CityObject" in x for x in first), first


def test_what_the_check_holds_does_not_grow_with_the_document(tmp_path, monkeypatch):
    """Traced memory at the check's peak on 200 and on 2,000 Buildings (with their parts, sharing
    one vertex block), the file read 16 kB at a time: the runs, one batch for the schema and
    8 bytes an id, not every link."""
    import functools
    import tracemalloc

    monkeypatch.setattr(C, "Scanner", functools.partial(C.Scanner, chunk=1 << 14))
    # the schema sees one batch of 64 CityObjects at a time (bounded); this test leaves it out
    monkeypatch.setattr(C, "_schema_valid_fast", lambda *a: True)

    def peak(n: int) -> int:
        doc = _cube_doc(1)
        part = doc["CityObjects"]["b0-p"]
        doc["CityObjects"] = {}
        for i in range(n):
            doc["CityObjects"][f"building-{i:06d}"] = {"type": "Building", "children": [f"building-{i:06d}-part"]}
            doc["CityObjects"][f"building-{i:06d}-part"] = {**part, "parents": [f"building-{i:06d}"]}
        path = tmp_path / f"n{n}.city.json"
        path.write_text(json.dumps(doc), encoding="utf-8")
        C.self_check_document(str(path))  # imports and schema compilation outside the measure
        tracemalloc.start()
        try:
            assert C.self_check_document(str(path)) == []
            return tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()
    small, large = peak(200), peak(2000)
    # every link (the reading before runs): ~1.2 MB more for the 3,600 more CityObjects
    assert large - small < 200_000, (small, large)


def test_large_objects_are_schema_checked_a_few_at_a_time(tmp_path, monkeypatch):
    """A schema batch is closed at BATCH_SURFACES surfaces as well as at BATCH objects: ten
    terrain TINs of 3,000 triangles (Den Haag tiled x16 carries sixteen) are never held
    together (they were, in one batch of 64 objects: +20 MB at the end of the x16 check)."""
    n_tri = 3000
    cos = {}
    for k in range(10):
        cos[f"b{k}"] = {"type": "Building", "geometry": []}
        cos[f"tin{k}"] = {"type": "TINRelief", "geometry": [{"type": "CompositeSurface", "lod": "1", "boundaries": [
            [[i % 50, (i + 1) % 50, (i + 2) % 50]] for i in range(n_tri)]}]}
    verts = [[i, (i * 7) % 50, i % 3] for i in range(50)]
    doc = {"type": "CityJSON", "version": "2.0", "transform": {"scale": [0.001] * 3, "translate": [0, 0, 0]},
           "CityObjects": cos, "vertices": verts}
    path, _, _ = _written(tmp_path, doc)
    batches = []

    def record(*args):
        d = args[1] if isinstance(args[0], str) else args[1]
        batches.append([oid for oid in d.get("CityObjects", {})])
        return True if isinstance(args[0], str) else []
    monkeypatch.setattr(C, "_schema_valid_fast", record)
    monkeypatch.setattr(C, "_schema_errors", record)
    monkeypatch.setattr(C, "BATCH_SURFACES", 4096)
    C.self_check_document(str(path))
    tins = [sum(o.startswith("tin") for o in b) for b in batches if b]
    assert sum(tins) == 10 and max(tins) <= 2
    assert C._surfaces(cos["tin0"]) == n_tri and C._surfaces(cos["b0"]) == 1 and C._surfaces("junk") == 1
