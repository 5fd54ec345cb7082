"""SeenIds: the ids a streaming reader has read, 16 bytes a slot; a CityJSONSeq read whose
memory does not grow with the ids it has seen."""
from __future__ import annotations

import json
import tracemalloc

from lod2energy.io import read
from lod2energy.io.seen_ids import SeenIds, id_key
from lod2energy.model import Building, FeatureError


def test_seen_ids_remember_every_id_and_its_first_tag_across_growth():
    seen = SeenIds(lambda n: f"line {n}")
    ids = [f"GUID_{i:06d}-part{i % 3}" for i in range(50_000)]
    for n, i in enumerate(ids):
        seen.add(i, n)
    seen.add(ids[7], 999)  # an id already there keeps its first tag
    assert len(seen) == len(ids)
    assert all(i in seen for i in ids)
    assert not any(f"other-{i}" in seen for i in range(2000))
    assert seen.where(ids[0]) == "line 0" and seen.where(ids[7]) == "line 7" and seen.where(ids[-1]) == "line 49999"
    try:
        seen.where("never")
        raise AssertionError("KeyError expected")
    except KeyError:
        pass
    # at most half full, 16 bytes a slot
    slots = len(seen._keys)
    assert len(ids) <= slots // 2 + 1 and slots <= 4 * len(ids)
    assert seen._keys.itemsize + seen._tags.itemsize == 16


def test_duplicate_ids_are_counted_per_id():
    seen = SeenIds()
    assert [seen.duplicate_id("A"), seen.duplicate_id("A"), seen.duplicate_id("B")] == \
        ["A (duplicate)", "A (duplicate 2)", "B (duplicate)"]


def test_id_keys_are_stable_and_never_zero():
    assert id_key("A") == id_key("A") != id_key("B")
    assert id_key("") != 0 and id_key("\udcff") != 0  # a lone surrogate from a file decoded leniently


def _seq(path, n: int, repeat_at: int | None = None) -> None:
    """A CityJSONSeq of ``n`` boxes, each a Building with one BuildingPart; the line of building
    ``repeat_at`` (if any) reuses the id of the first."""
    box = [[[[0, 1, 2, 3]], [[4, 7, 6, 5]], [[0, 4, 5, 1]], [[1, 5, 6, 2]], [[2, 6, 7, 3]], [[3, 7, 4, 0]]]]
    verts = [[0, 0, 0], [1000, 0, 0], [1000, 1000, 0], [0, 1000, 0],
             [0, 0, 1000], [1000, 0, 1000], [1000, 1000, 1000], [0, 1000, 1000]]
    with open(path, "w", encoding="utf-8") as f:
        f.write(json.dumps({"type": "CityJSON", "version": "2.0",
                            "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0, 0, 0]},
                            "CityObjects": {}, "vertices": []}) + "\n")
        for k in range(n):
            b = "B0" if k == repeat_at else f"B{k}"
            f.write(json.dumps({"type": "CityJSONFeature", "id": b, "CityObjects": {
                b: {"type": "Building", "children": [f"{b}-p"]},
                f"{b}-p": {"type": "BuildingPart", "parents": [b],
                           "geometry": [{"type": "Solid", "lod": "2", "boundaries": box}]}},
                "vertices": verts}) + "\n")


def test_a_repeated_id_many_lines_later_names_the_line_of_the_first(tmp_path):
    p = tmp_path / "rep.city.jsonl"
    _seq(p, 3000, repeat_at=2900)
    _, feats = read(str(p))
    feats = list(feats)
    errs = [f for f in feats if isinstance(f, FeatureError)]
    assert len(feats) == 3000 and len(errs) == 1
    assert errs[0].id == "B0 (duplicate)" and "line 2)" in errs[0].message and "already read" in errs[0].message
    assert sum(isinstance(f, Building) for f in feats) == 2999


def test_reading_a_cityjsonseq_holds_nothing_per_id_but_a_slot(tmp_path):
    """What stays in memory after a CityJSONSeq is read grows by at most ~48 bytes a CityObject
    (the table's slots); a dict of id -> where kept ~200."""
    def kept(n: int) -> int:
        p = tmp_path / f"s{n}.city.jsonl"
        _seq(p, n)
        tracemalloc.start()
        _, feats = read(str(p))
        count = cur = 0
        for f in feats:
            count += isinstance(f, Building)
            last = f
            if count == n:  # the reader is still open (the stream could go on)
                cur, _ = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        assert count == n and last.id == f"B{n - 1}"
        return cur
    kept(200)
    small, large = kept(2000), kept(8000)
    objects = 2 * (8000 - 2000)
    assert large - small < 48 * objects, (small, large)


def test_the_document_writer_refuses_two_cityobjects_with_one_id(tmp_path):
    import io as _io

    import pytest

    from factories import box
    from lod2energy.io.cityjson_write import write_document
    from lod2energy.model import CityModel
    out = _io.StringIO()
    write_document(out, CityModel(), [box(id="a"), box(id="b")], "2.0", scratch_dir=str(tmp_path))
    doc = json.loads(out.getvalue())
    assert sorted(doc["CityObjects"]) == ["a", "b"] and len(doc["vertices"]) == 16
    with pytest.raises(ValueError, match="two CityObjects with id 'a'"):
        write_document(_io.StringIO(), CityModel(), [box(id="a"), box(id="b"), box(id="a")], "2.0",
                       scratch_dir=str(tmp_path))
