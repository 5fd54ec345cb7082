"""report.html of ``export`` from the footprints its workers drew, not from a second read of the
whole input: the reader's ``only`` option, and the same page as when the file is read again."""
from __future__ import annotations

import json

import numpy as np
import pytest

import lod2energy.io.cityjson as CJ
from lod2energy.cli import main
from lod2energy.io import read
from lod2energy.model import Building

from cityjson_docs import to_seq, write
from conftest import shared_path
from spine_inputs import row_of_boxes_seq
from test_geographic import geographic_box_doc


def _buildings(path, **options) -> list[Building]:
    return [f for f in read(str(path), **options)[1] if isinstance(f, Building)]


def _denhaag():
    return shared_path("denhaag", "DenHaag_01.city.json")


@pytest.mark.parametrize("parts", [
    ("denhaag", "DenHaag_01.city.json"),                # CityJSON document
    ("3dbag", "delft_subset.city.jsonl"),               # CityJSONSeq
    ("citygml-real", "berlin", "3920_5818.gml"),        # CityGML (filtered after it is built)
])
def test_read_only_gives_the_buildings_asked_for_as_a_full_read_gives_them(parts):
    p = shared_path(*parts)
    every = _buildings(p)
    pick = [every[1].id, every[len(every) // 2].id, every[-1].id]
    got = _buildings(p, only=set(pick))
    assert [b.id for b in got] == [b.id for b in every if b.id in set(pick)]
    full = {b.id: b for b in every}
    for b in got:
        np.testing.assert_array_equal(b.vertices, full[b.id].vertices)
        assert [o.id for o in b.objects] == [o.id for o in full[b.id].objects]


def test_read_only_builds_nothing_else(monkeypatch):
    calls = []
    real = CJ.build_feature
    monkeypatch.setattr(CJ, "build_feature", lambda *a, **k: calls.append(a[0]) or real(*a, **k))
    every = _buildings(_denhaag())
    n_all = len(calls)
    calls.clear()
    _buildings(_denhaag(), only={every[0].id, every[7].id})
    assert n_all == len(every) and sorted(calls) == sorted([every[0].id, every[7].id])


def test_read_only_of_a_geographic_file_keeps_the_frame_of_the_first_building(tmp_path):
    """No geographicalExtent: the local frame is tangent at the first building's first vertex,
    so asking for the third alone must still build the first (else its metres would differ)."""
    src = write(tmp_path, None, "geo.city.jsonl", to_seq(geographic_box_doc(n=3)))
    every = {b.id: b for b in _buildings(src)}
    (b3,) = _buildings(src, only={"b3"})
    np.testing.assert_array_equal(b3.vertices, every["b3"].vertices)
    assert b3.vertices[:, 0].min() > 50  # 60 m east of the first box, in the first box's frame


def _row_with_open_boxes(path, n: int = 40) -> str:
    """``n`` boxes apart, every fourth without its roof (a hole to fill: a panel of the page)."""
    row_of_boxes_seq(path, n=n, touching=False)
    lines = path.read_text().splitlines()
    for k in range(1, len(lines), 4):
        doc = json.loads(lines[k])
        for co in doc["CityObjects"].values():
            g = co["geometry"][0]
            g["boundaries"][0].pop(1)
            g["semantics"]["values"][0].pop(1)
        lines[k] = json.dumps(doc)
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def _export_page(src, out, monkeypatch, reread: bool, plan_max: int | None = None) -> bytes:
    """report.html of ``export --stl -j 1``; ``reread``: as before, reading the input again."""
    import lod2energy.pipeline as P
    import lod2energy.viz.report as VR
    if plan_max is not None:
        monkeypatch.setattr(VR, "PLAN_SVG_MAX", plan_max)
    if reread:
        real = P.write_html_report
        monkeypatch.setattr(P, "write_html_report", lambda *a, **k: real(*a[:7], None, **k))
    assert main(["export", str(src), "-o", str(out), "--stl", "-j", "1", "-q"]) == 0
    monkeypatch.undo()
    return (out / "report.html").read_bytes()


@pytest.mark.parametrize("plan_max", [None, 10])  # an SVG plan; a picture (over 10 buildings)
def test_export_page_from_the_workers_footprints_equals_the_page_of_a_second_read(tmp_path, capsys, monkeypatch,
                                                                                  plan_max):
    src = _row_with_open_boxes(tmp_path / "row.city.jsonl")
    new = _export_page(src, tmp_path / "new", monkeypatch, reread=False, plan_max=plan_max)
    old = _export_page(src, tmp_path / "old", monkeypatch, reread=True, plan_max=plan_max)
    capsys.readouterr()
    assert new == old
    assert (b'"buildings_embedded": "panels"' in new) == (plan_max is not None)


def test_export_page_builds_only_its_panels_again(tmp_path, capsys, monkeypatch):
    src = _row_with_open_boxes(tmp_path / "row.city.jsonl")
    calls = []
    real = CJ.build_feature
    monkeypatch.setattr(CJ, "build_feature", lambda *a, **k: calls.append(a[0]) or real(*a, **k))
    assert main(["export", str(src), "-o", str(tmp_path / "out"), "--stl", "-j", "1", "-q"]) == 0
    capsys.readouterr()
    page = (tmp_path / "out" / "report.html").read_text()
    panels = page.count('class="panel"')
    assert 0 < panels < 40
    assert len(calls) == 40 + panels  # the export's own read, then the panels' buildings only
