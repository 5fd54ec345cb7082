"""report.html: figure data of the three report shapes, the graph picture's colours, the page in a real Chromium."""
from __future__ import annotations

import base64
import io
import json
import re
from types import SimpleNamespace

import numpy as np
import pytest

from lod2energy.config import DEFAULT
from lod2energy.io import read
from lod2energy.model import Building
from lod2energy.prepare import prepare
from lod2energy.validate.checks import validate_building
from lod2energy.viz import data as D
from lod2energy.viz import render as R
from lod2energy.viz.report import PageRows, render_report_html, write_report_html
from lod2energy.viz.view import write_report_for

from conftest import shared_path
from factories import BOX_SEMANTICS, box, box_polygons, building_from_polygons, open_box

OPTS = SimpleNamespace(lod=None, timeout=10.0, merge_parts=False)


def fin_box(id: str = "fin_box"):
    """A box with a fin of two triangles on the roof edge x=10, y=0..8: one non-manifold edge."""
    polys = box_polygons()
    a, b, c = np.array([10.0, 0, 6]), np.array([10.0, 8, 6]), np.array([12.0, 4, 9])
    polys += [[np.array([a, b, c])], [np.array([b, a, c])]]
    return building_from_polygons(polys, "Solid", BOX_SEMANTICS + ["RoofSurface", "RoofSurface"], id=id)


def export_report(buildings):
    """An export-shape report (as ``export`` writes report.json) and the prepared buildings."""
    rows, outs = [], {}
    for b in buildings:
        pb, rec = prepare(b, DEFAULT, OPTS)
        outs[b.id] = pb
        rows.append({**rec.row(), "repair": rec.repair, "energy": rec.energy, "thermal": rec.thermal,
                     "exports": {"stl": {"ok": True, "path": f"{b.id}.stl", "problems": []}}})
    return {"input_file": "factories", "buildings": rows}, outs


def page_data(html: str) -> dict:
    m = re.search(r'<script type="application/json" id="report-data">(.*?)</script>', html, re.S)
    return json.loads(m.group(1).replace("<\\/", "</"))


# --- figure data ---------------------------------------------------------------------------------

def test_three_report_shapes_give_the_same_rows():
    export = {"buildings": [
        {"id": "a", "type": "Building", "input_errors": "", "repair": {"stage": "valid", "iou": 1.0,
         "mean_displacement": 0.0, "defects_before": [], "defects_after": []}, "energy": {"compliant": True}},
        {"id": "b", "type": "Building", "repair": {"stage": "holefill", "iou": 0.97, "mean_displacement": 0.012,
         "defects_before": [302, 1001], "defects_after": []}, "energy": {"compliant": True},
         "thermal": {"typology": "terraced", "footprint": 50.0, "storeys": 2},
         "exports": {"idf": {"ok": True, "heating_kwh": 8000.0, "problems": []}}},
        {"id": "c", "type": "Building", "repair": {"stage": "irreparable", "iou": None,
         "defects_before": [104], "defects_after": [104]}, "energy": {"compliant": False}}]}
    repair = {"summary": {}, "output_file": "o.json", "buildings": [
        {"id": "a", "stage": "valid", "iou": 1.0, "mean_displacement": 0.0, "defects_before": [], "defects_after": []},
        {"id": "b", "stage": "holefill", "iou": 0.97, "mean_displacement": 0.012, "defects_before": [302, 1001],
         "defects_after": []},
        {"id": "c", "stage": "irreparable", "iou": None, "defects_before": [104], "defects_after": [104]}]}
    validate = {"type": "val3dity_report", "features": [
        {"id": "a", "type": "Building", "validity": True, "errors": [], "energy": {"compliant": True}},
        {"id": "b", "type": "Building", "validity": False, "errors": [{"code": 302, "id": "", "info": ""}],
         "energy": {"compliant": False}},
        {"id": "c", "type": "Building", "validity": False, "errors": [{"code": 104, "id": "", "info": ""}],
         "energy": {"compliant": False}}]}
    assert [D.report_kind(r) for r in (export, repair, validate)] == ["export", "repair", "validate"]
    for rep in (export, repair):
        rs = D.rows(rep)
        assert [r.status for r in rs] == ["valid", "repaired locally", "irreparable"]
        assert D.Tally(rs).stage_distribution() == {"valid": 1, "holefill": 1, "irreparable": 1}
        assert D.Tally(rs).validity_by_code() == {"104": [1, 1], "302": [1, 0], "1001": [1, 0]}
        h = D.Tally(rs).iou.result()
        assert h["n"] == 1 and sum(h["counts"]) == 1 and h["counts"][-1] == 1      # 0.97 in the last bin
        d = D.Tally(rs).displacement.result()
        assert d["counts"][2] == 1                                                  # 0.01 <= 0.012 < 0.02
        s = D.Tally(rs).summary()
        assert (s["miou"], s["map_v"], s["local_repairs"], s["irreparable"]) == (0.97, 0.012, 1, 1)
    rs = D.rows(validate)
    assert D.Tally(rs).stage_distribution() == {} and [r.status for r in rs] == ["valid", "not repaired", "not repaired"]
    assert D.Tally(rs).validity_by_code() == {"104": [1, 0], "302": [1, 0]}
    # heating per m2 of floor: 8000 kWh / (50 m2 x 2 storeys)
    assert D.Tally(D.rows(export)).heating_by_typology() == {"terraced": [80.0, 1]}


def test_panel_cap_keeps_every_building_of_a_small_file_and_the_worst_of_a_large_one():
    rs = [D.Row(id=f"v{i}", stage="valid") for i in range(30)] + [
        D.Row(id="loc", stage="cleanup", before=(203,), after=()),
        D.Row(id="glob", stage="alphashape", before=(302,), after=()),
        D.Row(id="bad", stage="irreparable", before=(104,), after=(104,))]
    small, large = PageRows(rs[:5], 5), PageRows(rs, 2)
    assert ([r.id for r in small.panel_rows()], small.left_out) == ([f"v{i}" for i in range(5)], 0)
    assert ([r.id for r in large.panel_rows()], large.left_out) == (["bad", "glob"], 1)


# --- the graph picture ---------------------------------------------------------------------------

def _png_has_colour(url: str, hex_colour: str, tol: int = 12) -> int:
    from PIL import Image
    img = np.asarray(Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1]))).convert("RGB")).astype(int)
    want = np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)])
    return int((np.abs(img - want).max(axis=2) <= tol).sum())


def test_graph_of_a_building_with_a_hole_uses_the_methods_colours():
    b = open_box()                                         # roof missing: a hole bounded by 4 edges
    pic = R.graph_picture(b, validate_building(b))
    boundary = [e for e in pic["edges"] if e["kind"] == "boundary_edge"]
    assert len(boundary) == 4 and {e["colour"] for e in boundary} == {R.GRAPH_COLOURS["boundary_edge"]}
    assert not [e for e in pic["edges"] if e["kind"] == "nonmanifold_edge"]
    kinds = {nd["kind"] for nd in pic["nodes"]}
    assert kinds == {"valid_face", "defective_face"}      # the ground touches no hole edge
    assert all(nd["colour"] == R.GRAPH_COLOURS[nd["kind"]] for nd in pic["nodes"])
    assert sum(nd["kind"] == "defective_face" for nd in pic["nodes"]) == 4   # the 4 walls around the hole
    url = R.panel_image(b, None, pic)
    for k in ("boundary_edge", "defective_face", "valid_face"):
        assert _png_has_colour(url, R.GRAPH_COLOURS[k]) > 3, k


def test_graph_of_a_building_with_a_nonmanifold_edge_uses_the_methods_colours():
    b = fin_box()
    pic = R.graph_picture(b, validate_building(b))
    nm = [e for e in pic["edges"] if e["kind"] == "nonmanifold_edge"]
    assert len(nm) == 1 and nm[0]["colour"] == R.GRAPH_COLOURS["nonmanifold_edge"]
    assert pic["status"] == "non-manifold"
    bad = [nd for nd in pic["nodes"] if nd["kind"] == "defective_face"]
    assert len(bad) >= 3 and all(nd["colour"] == R.GRAPH_COLOURS["defective_face"] for nd in bad)
    assert _png_has_colour(R.panel_image(b, None, pic), R.GRAPH_COLOURS["nonmanifold_edge"]) > 3


def test_valid_box_graph_has_only_valid_faces():
    pic = R.graph_picture(box())
    assert {nd["kind"] for nd in pic["nodes"]} == {"valid_face"} and len(pic["nodes"]) == 6
    assert pic["counts"] == {"valid_face": 6, "adjacency": 12}


# --- the page (no browser) -----------------------------------------------------------------------

def test_page_embeds_the_plotted_numbers_and_needs_no_network(tmp_path):
    bs = [box(id="ok"), open_box(id="hole")]
    rep, outs = export_report(bs)
    out = write_report_html(rep, tmp_path / "report.html", inputs={b.id: b for b in bs}, outputs=outs)
    html = out.read_text(encoding="utf-8")
    data = page_data(html)
    assert data["figures"] == json.loads(json.dumps(D.Tally(D.rows(rep)).figure_data()))
    assert data["figures"]["stages"] == {r["repair"]["stage"]: 1 for r in rep["buildings"]}
    assert data["panels"] == ["ok", "hole"] and html.count('class="panel"') == 2
    assert html.count('class="fp"') == 2 and 'href="#b-hole"' in html
    # every resource inline: no URL but data: and in-page anchors
    for attr in re.findall(r'(?:src|href)="([^"]*)"', html):
        assert attr.startswith(("data:", "#")), attr
    assert not re.search(r"https?://(?!www\.w3\.org/2000/svg)", html)


def test_page_outside_its_root_is_refused(tmp_path):
    from lod2energy.safe_write import UnsafeWriteError
    rep, _ = export_report([box()])
    with pytest.raises(UnsafeWriteError):
        write_report_html(rep, tmp_path / "a" / ".." / ".." / "escape.html", root=tmp_path / "a")


def test_validation_and_repair_reports_render(tmp_path):
    b = open_box(id="hole")
    from lod2energy.validate.report import feature_report
    val = {"type": "val3dity_report", "input_file": "x.city.json",
           "features": [{k: v for k, v in feature_report(b).items() if k != "_primitives"}]}
    from lod2energy.viz import keep
    store = {}
    assert list(keep([b], store)) == [b] and store == {"hole": b}
    html = render_report_html(val, inputs=store)
    d = page_data(html)
    assert d["kind"] == "validate" and d["figures"]["validity_by_code"] == {
        str(c): [1, 0] for c in sorted({e["code"] for e in val["features"][0]["errors"]})}
    rep = {"input_file": "x", "output_file": "y.json", "summary": {},
           "buildings": [{"id": "hole", "stage": "holefill", "iou": 1.0, "mean_displacement": 0.0,
                          "defects_before": [302], "defects_after": []}]}
    d = page_data(render_report_html(rep))                 # no geometry at all: tables and plots only
    assert d["kind"] == "repair" and d["figures"]["stages"] == {"holefill": 1} and d["plan"] == {}


def test_view_writes_the_panel_of_one_building(tmp_path, capsys):
    from lod2energy.cli import main
    src = shared_path("citygml-real", "berlin", "3900_5819.gml")
    assert main(["view", str(src), "-o", str(tmp_path), "--no-open", "-q"]) == 0
    page = capsys.readouterr().out.strip()
    d = page_data(open(page, encoding="utf-8").read())
    assert len(d["panels"]) == 1 and d["buildings"][0]["id"] == d["panels"][0]
    assert main(["view", str(src), "--id", "no-such-building", "-o", str(tmp_path), "--no-open"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no-such-building" in err


# --- in a real browser -----------------------------------------------------------------------------

def _browser():
    pytest.importorskip("playwright")
    from chromium import chromium_path
    if chromium_path() is None:
        pytest.skip("chromium not installed (.ci/install-chromium.sh)")


def _variance(png: bytes) -> float:
    from PIL import Image
    return float(np.asarray(Image.open(io.BytesIO(png)).convert("L"), float).var())


@pytest.mark.external
def test_real_tile_report_in_chromium(tmp_path):
    _browser()
    from lod2energy.cli import main
    from chromium import open_page
    src = shared_path("citygml-real", "berlin", "3900_5819.gml")
    assert main(["export", str(src), "-o", str(tmp_path), "--stl", "-q"]) in (0, 1)
    rep = json.loads((tmp_path / "report.json").read_text())
    page, _ = write_report_for(tmp_path / "report.json")
    with open_page(page) as (p, log):
        assert log.console_errors == [] and log.page_errors == [] and log.blocked == []
        assert _variance(p.screenshot()) > 50.0                       # not a blank page
        panel = p.locator(".panel").first
        panel.scroll_into_view_if_needed()
        assert _variance(panel.screenshot()) > 50.0
        shown = p.evaluate("window.reportData")
        # the plotted numbers are report.json's
        stages = {}
        for b in rep["buildings"]:
            stages[b["repair"]["stage"]] = stages.get(b["repair"]["stage"], 0) + 1
        assert shown["figures"]["stages"] == stages
        cells = p.eval_on_selector_all("#stage-table td[data-stage]",
                                       "els => Object.fromEntries(els.map(e => [e.dataset.stage, +e.textContent]))")
        assert cells == stages
        fixed = [b for b in rep["buildings"] if b["repair"]["stage"] not in ("valid", "irreparable")]
        assert shown["figures"]["iou"]["n"] == len(fixed)
        if fixed:
            assert shown["figures"]["summary"]["miou"] == pytest.approx(
                np.mean([b["repair"]["iou"] for b in fixed]), abs=1e-6)
        codes = {}
        for b in rep["buildings"]:
            for c in set(b["repair"]["defects_before"]):
                codes.setdefault(str(c), [0, 0])[0] += 1
            for c in set(b["repair"]["defects_after"]):
                codes.setdefault(str(c), [0, 0])[1] += 1
        assert shown["figures"]["validity_by_code"] == dict(sorted(codes.items(), key=lambda kv: int(kv[0])))
        ok = sum(bool(b["exports"].get("stl", {}).get("ok")) for b in rep["buildings"])
        assert int(p.text_content("#exports-table td[data-format='stl'][data-when='ok']")) == ok
        # the plan view: a footprint per building, each linked to its panel (a small file: all)
        assert p.locator("#plan .fp").count() == len(rep["buildings"])
        hrefs = p.eval_on_selector_all("#plan a", "els => els.map(e => e.getAttribute('href'))")
        assert len(hrefs) == len(rep["buildings"])
        for h in hrefs:
            assert p.locator(h).count() == 1
        p.locator("#plan a").first.dispatch_event("click")           # follows the link to a panel
        assert p.evaluate("location.hash") == hrefs[0]
        assert p.locator(".panel img").count() == len(rep["buildings"])
        assert p.evaluate("[...document.images].every(i => i.complete && i.naturalWidth > 0)")


def test_every_plot_is_an_svg_image_and_heating_colours_the_plan(tmp_path):
    from lod2energy.viz import figures as F
    bs = [box(id="ok"), open_box(id="hole")]
    rep, outs = export_report(bs)
    for k, row in enumerate(rep["buildings"]):
        row["exports"]["idf"] = {"ok": True, "heating_kwh": 4000.0 * (k + 1), "problems": []}
    rs = D.rows(rep)
    fd = D.Tally(rs).figure_data()
    assert sum(n for _, n in fd["heating_by_typology"].values()) == 2
    urls = [F.plot_stages(fd["stages"]), F.plot_histograms(fd["iou"], fd["displacement"]),
            F.plot_compliance(fd["compliance"]), F.plot_validity(fd["validity_by_code"]),
            F.plot_heating(fd["heating_by_typology"])]
    for u in urls:
        assert u.startswith("data:image/svg+xml;base64,")
        assert b"<svg" in base64.b64decode(u.split(",", 1)[1])[:400]
    html = render_report_html(rep, inputs={b.id: b for b in bs}, outputs=outs)
    assert html.count("data-heat-fill=") == 2 and 'id="by-heat"' in html and 'id="plot-heating"' in html
    values = sorted(float(v) for v in re.findall(r'data-value="([0-9.]+)"', html))
    assert values == pytest.approx(sorted(r.heating_kwh_m2 for r in rs), abs=1e-3)


def test_the_page_of_a_large_file_keeps_only_its_panels_whole_and_draws_the_same_plan(tmp_path):
    """read_for_page: the panels' buildings whole, every other one as its footprint only; the
    page drawn from those is the page drawn from every building of the file."""
    from lod2energy.viz.report import plan_footprint, read_for_page
    src = str(shared_path("denhaag", "DenHaag_01.city.json"))
    every = {f.id: f for f in read(src)[1] if isinstance(f, Building)}
    ids = sorted(every)
    wanted = set(ids[:5]) | {"no-such-building"}
    keep, fps = read_for_page(src, wanted)
    assert sorted(keep) == ids[:5]
    assert sorted(fps) == ids[5:] and not set(fps) & set(keep)
    for i in ids[5:40]:
        want = plan_footprint(every[i])
        assert len(fps[i]) == len(want) and all(np.array_equal(a, b) for a, b in zip(fps[i], want))
    rows = [{"id": i, "valid": True, "errors": [], "repair": {"stage": "valid"}} for i in ids]
    report = {"input_file": src, "buildings": rows}
    whole = render_report_html(report, inputs=every)
    light = render_report_html(report, inputs=keep, footprints=fps)
    assert light == whole and "<svg" in light


def test_pictures_rendered_by_a_process_pool_give_the_same_page_and_a_failed_job_is_redone(tmp_path):
    from lod2energy.run.executor import Failure, ProcessPoolExecutor
    from lod2energy.viz.report import page_job
    bs = [box(id="ok"), open_box(id="hole"), fin_box()]
    rep, outs = export_report(bs)
    inputs = {b.id: b for b in bs}
    here = render_report_html(rep, inputs=inputs, outputs=outs)
    seen = []
    with ProcessPoolExecutor(2) as ex:
        def pool(fn, jobs):
            assert fn is page_job
            res = [r for _, r in ex.map(fn, jobs)]
            seen.append([j[0] for j in jobs])
            return res
        assert render_report_html(rep, inputs=inputs, outputs=outs, mapper=pool) == here
    assert seen == [["plots", "panel", "panel", "panel"]]

    def broken(fn, jobs):  # every second job failed: done here instead, the page unchanged
        return [Failure("worker lost") if i % 2 else fn(j) for i, j in enumerate(jobs)]
    assert render_report_html(rep, inputs=inputs, outputs=outs, mapper=broken) == here


# --- warnings by kind ----------------------------------------------------------------------------

def _warned_report():
    """Three boxes with the warnings report.json records: sentinels, a downgrade, a far station,
    a failed export; the study's --buildings ids not in the input."""
    rep, outs = export_report([box(id="a"), box(id="b"), box(id="c")])
    a, b, c = rep["buildings"]
    a["thermal"] = {**dict(a["thermal"].detail), "warnings": [{"field": "year", "message": "year 2099"}]}
    b["thermal"] = {**dict(b["thermal"].detail), "warnings": [{"field": "year", "message": "year 9999"},
                                                             {"field": "storeys", "message": "9999 storeys"}]}
    b["energy_downgrades"] = [{"kind": "lod1_block", "zone": "b"}]
    b["exports"]["idf"] = {"ok": True, "path": "b.idf", "problems": [],
                           "weather": {"station": "Far", "file": "far.epw", "distance_km": 120.0}}
    c["exports"]["stl"] = {"ok": False, "path": "", "problems": ["STL not written"]}
    rep["study"] = {"buildings_table_not_in_input": ["x", "y"]}
    return rep, outs


def _expected_warnings(rep) -> dict:
    """Kind -> count, straight from the report's fields."""
    from collections import Counter
    n = Counter()
    for b in rep["buildings"]:
        n.update(f"{f}: a sentinel or implausible value taken as unknown"
                 for f in {w["field"] for w in (b.get("thermal") or {}).get("warnings") or ()})
        n.update(f"energy model downgraded ({d['kind']})" for d in b.get("energy_downgrades") or ())
        if any((e.get("weather") or {}).get("distance_km", 0) > 50 for e in b["exports"].values()):
            n["weather station more than 50 km away"] += 1
        n.update(f"{f}: not written" for f, e in b["exports"].items() if not e["ok"] and not e["path"])
        n.update(f"{f}: failed its self-check" for f, e in b["exports"].items() if not e["ok"] and e["path"])
    n["--buildings ids not in the input"] = len(rep["study"]["buildings_table_not_in_input"])
    return dict(n)


def test_the_page_summarises_warnings_by_kind(tmp_path):
    rep, outs = _warned_report()
    html = write_report_html(rep, tmp_path / "report.html", outputs=outs).read_text(encoding="utf-8")
    shown = page_data(html)["warnings"]
    assert {w["kind"]: w["count"] for w in shown} == _expected_warnings(rep)
    assert [w["count"] for w in shown] == sorted((w["count"] for w in shown), reverse=True)
    year = next(w for w in shown if w["kind"].startswith("year"))
    assert year["count"] == 2 and year["example"] == "a"
    cells = dict(re.findall(r'<td class="n" data-kind="([^"]*)">(\d+)</td>', html))
    assert {k.replace("&gt;", ">"): int(v) for k, v in cells.items()} == _expected_warnings(rep)
    clean, outs = export_report([box(id="a")])
    assert page_data(render_report_html(clean, outputs=outs))["warnings"] == []


@pytest.mark.external
def test_the_warnings_table_in_chromium(tmp_path):
    _browser()
    from chromium import open_page
    rep, outs = _warned_report()
    page = write_report_html(rep, tmp_path / "report.html", outputs=outs)
    with open_page(page) as (p, log):
        assert log.console_errors == [] and log.page_errors == []
        assert p.locator("#warnings-table").is_visible()
        cells = p.eval_on_selector_all("#warnings-table td[data-kind]",
                                       "els => Object.fromEntries(els.map(e => [e.dataset.kind, +e.textContent]))")
        assert cells == _expected_warnings(rep)
        assert cells == {w["kind"]: w["count"] for w in p.evaluate("window.reportData").get("warnings")}
