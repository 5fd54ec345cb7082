"""What the CityJSON self-check keeps while it reads an exported document (exporters.cityjson_check)."""
from __future__ import annotations

import json

import numpy as np

from lod2energy.exporters import cityjson_check as C
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


def test_the_first_reading_groups_as_the_reader_and_converts_vertices_bit_for_bit(tmp_path):
    doc = _doc(50)
    path = tmp_path / "d.city.json"
    path.write_text(json.dumps(doc), encoding="utf-8")
    p = C._first_pass(str(path))
    cos = doc["CityObjects"]
    assert cjio._feature_ids(p.links) == cjio._feature_ids(cos)
    groups = cjio._feature_ids(cos)
    assert ([e.message for e in cjio._orphan_errors(p.links, groups, "d")]
            == [e.message for e in cjio._orphan_errors(cos, groups, "d")])
    assert {k: dict(v) for k, v in p.links.items()} == {
        k: {x: v[x] for x in ("type", "parents", "children") if x in v} for k, v in cos.items()}
    t = doc["transform"]
    want = np.asarray(doc["vertices"], dtype=np.int64).astype(np.float64) * np.asarray(t["scale"]) \
        + np.asarray(t["translate"])
    got = p.vertices(t)
    assert got.dtype == np.float64 and got.tobytes() == want.tobytes()


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
    from lod2energy.heap import give_back
    assert give_back() is sys.platform.startswith("linux")
