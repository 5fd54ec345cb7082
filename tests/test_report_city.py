"""report.html at city scale: rows read once into counters and a bounded choice of panels; a
file over ``plan_max`` buildings gets its plan as a picture drawn from a scratch file of
footprints and embeds its panels' rows only; memory that does not grow with the file."""
from __future__ import annotations

import base64
import io
import json
import re
import tracemalloc

import numpy as np
import pytest

from lod2energy.io.seen_ids import id_key
from lod2energy.viz import data as D
from lod2energy.viz import footprints as FP
from lod2energy.viz import report as VR
from lod2energy.viz.report import FootprintSpill, PageRows, read_for_page, render_report_html

from conftest import shared_path

STAGE_CHOICES = ("valid", "cleanup", "orientation", "holefill", "refill", "roofs", "alphashape", "footprint",
                 "hull", "irreparable")


def random_report(n: int, seed: int = 7, heat: bool = True):
    """An export-shape report of ``n`` buildings with random stages, codes, IoU, displacement,
    compliance, typology, heating and export verdicts; ``buildings`` is a generator (read once)."""
    def rows():
        rng = np.random.default_rng(seed)
        for i in range(n):
            stage = STAGE_CHOICES[int(rng.integers(len(STAGE_CHOICES)))]
            before = sorted({int(c) for c in rng.choice([101, 104, 203, 302, 601, 1001], int(rng.integers(0, 3)))})
            after = [c for c in before if stage == "irreparable" or c == 601]
            fp = float(rng.uniform(40, 400))
            yield {"id": f"b{i}", "type": "Building",
                   "repair": {"stage": stage, "iou": float(rng.uniform(0.3, 1.0)),
                              "mean_displacement": float(rng.exponential(0.2)) if rng.random() < 0.9 else None,
                              "defects_before": before, "defects_after": after},
                   "energy": {"compliant": bool(rng.random() < 0.8), "closed_2manifold": bool(rng.random() < 0.9),
                              "labelled": True},
                   "thermal": {"typology": ["terraced", "single-family", "apartment"][i % 3], "footprint": fp,
                               "storeys": int(rng.integers(1, 5))},
                   "exports": {"idf": {"ok": bool(rng.random() < 0.95), "problems": ["x"],
                                       **({"heating_kwh": float(rng.uniform(1e3, 5e4))} if heat else {})}}}
    return {"input_file": "random", "buildings": rows()}


def listed(report: dict) -> dict:
    return {**report, "buildings": list(report["buildings"])}


# --- counters ------------------------------------------------------------------------------------

def test_tally_gives_the_numbers_of_every_row_read_once(monkeypatch):
    monkeypatch.setattr(D._Histogram, "CHUNK", 37)  # values cross many chunks
    rep = listed(random_report(1500))
    rs = D.rows(rep)
    fd = D.Tally(iter(rs)).figure_data()  # one pass over an iterator
    fixed = [r for r in rs if r.stage not in ("valid", "irreparable")]
    assert fd["summary"]["buildings"] == 1500 and fd["summary"]["n_measured"] == len(fixed)
    assert fd["summary"]["miou"] == pytest.approx(np.mean([r.iou for r in fixed]), abs=1e-6)
    disp = [r.displacement for r in fixed if r.displacement is not None]
    assert fd["summary"]["map_v"] == pytest.approx(np.mean(disp), abs=1e-6)
    want, _ = np.histogram(np.clip(disp, 0, D.DISPLACEMENT_BINS[-1]), bins=np.asarray(D.DISPLACEMENT_BINS))
    assert fd["displacement"]["counts"] == want.tolist() and fd["displacement"]["n"] == len(disp)
    want, _ = np.histogram([r.iou for r in fixed], bins=np.asarray(D.IOU_BINS))
    assert fd["iou"]["counts"] == want.tolist()
    assert sum(fd["stages"].values()) == 1500 and list(fd["stages"]) == [s for s in D.STAGES if s in fd["stages"]]
    for code, (b, a) in fd["validity_by_code"].items():
        assert b == sum(int(code) in r.before for r in rs) and a == sum(int(code) in (r.after or ()) for r in rs)
    by_typ: dict = {}
    for r in rs:
        by_typ.setdefault(r.typology, []).append(r.heating_kwh_m2)
    for t, (mean, n) in fd["heating_by_typology"].items():
        assert n == len(by_typ[t]) and mean == pytest.approx(np.mean(by_typ[t]), abs=1e-3)
    assert fd["exports"]["idf"]["ok"] + fd["exports"]["idf"]["failed"] == 1500
    assert len(fd["exports"]["idf"]["problems"]) == 5
    assert fd["compliance"]["after"] == sum(bool(r.compliant) for r in rs)
    assert fd["compliance"]["conditions"]["closed_2manifold"] == sum(r.conditions["closed_2manifold"] for r in rs)


@pytest.mark.parametrize("cap", [1, 4, 16, 2000])
def test_page_rows_choose_the_panels_of_sorting_every_row(cap):
    rs = D.rows(listed(random_report(1200, seed=cap)))
    page = PageRows(iter(rs), cap=cap, plan_max=100)
    if len(rs) <= cap:
        want = rs
    else:
        want = sorted([r for r in rs if r.repaired or r.invalid_input or r.status != "valid"],
                      key=lambda r: VR._SEVERITY.get(r.status, 5))[:cap]
    assert [r.id for r in page.panel_rows()] == [r.id for r in want]
    deserving = sum(1 for r in rs if r.repaired or r.invalid_input or r.status != "valid")
    assert page.left_out == (0 if len(rs) <= cap else max(0, deserving - cap))
    assert page.large and page.rows is None  # 1,200 rows over plan_max: none kept
    assert len(page.keys) == len(page.status) == len(page.heat) == 1200


# --- footprints in a scratch file ------------------------------------------------------------------

def _squares(n: int, seed: int = 0, places: int | None = None):
    """``n`` footprints (id, rings); with ``places``, the ``i``-th stands where the
    ``i % places``-th does (the plan picture then looks the same for any ``n``)."""
    xy = np.random.default_rng(seed).uniform(0, 2000, (places or n, 2))
    for i in range(n):
        x, y = xy[i % len(xy)]
        rings = [np.array([[x, y], [x + 9, y], [x + 9, y + 7], [x, y + 7]])]
        if i % 5 == 0:  # two ground faces, one of odd length
            rings.append(np.array([[x + 9, y], [x + 12, y], [x + 12, y + 3], [x + 10, y + 4], [x + 9, y + 3]]))
        if i % 11 == 0:
            rings = []  # nothing to draw
        yield f"b{i}", rings


def gives_back(spill: FootprintSpill, want: list) -> None:
    """``spill`` yields the keys of ``want``'s ids and their rings, in order."""
    got = list(spill)
    assert len(got) == len(want)
    for (k, rings), (i, w) in zip(got, want):
        assert k == id_key(i) and len(rings) == len(w)
        assert all(np.array_equal(a, b) for a, b in zip(rings, w))


def test_footprint_spill_gives_back_every_ring_in_order_across_read_chunks(tmp_path):
    spill = FootprintSpill(str(tmp_path))
    want = list(_squares(30000))  # ~3 MB: several 1 MB reads, records cut at their ends
    for i, rings in want:
        spill.add(i, rings)
    assert list(tmp_path.iterdir()) == []  # the scratch file has no name
    for _ in range(2):  # read twice: the page reads it for its bounds, then draws
        gives_back(spill, want)
    allpts = np.vstack([r for _, rs in want for r in rs])
    assert np.array_equal(spill.lo, allpts.min(axis=0)) and np.array_equal(spill.hi, allpts.max(axis=0))
    spill.close()


def test_footprint_spill_keeps_the_rings_in_memory_without_a_scratch_file(tmp_path, monkeypatch):
    def no_file(*a, **k):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(FP.tempfile, "TemporaryFile", no_file)
    spill = FootprintSpill(str(tmp_path))
    want = list(_squares(50))
    for i, rings in want:
        spill.add(i, rings)
    gives_back(spill, want)


def test_footprint_spill_takes_back_what_it_wrote_when_the_disk_fills(tmp_path):
    spill = FootprintSpill(str(tmp_path))
    want = list(_squares(40))
    real = spill._f

    class Filling:  # the disk fills at the 21st record
        def __init__(self):
            self.n = 0

        def write(self, b):
            self.n += 1
            if self.n > 20:
                raise OSError(28, "No space left on device")
            return real.write(b)

        def __getattr__(self, name):
            return getattr(real, name)

    spill._f = Filling()
    for i, rings in want:
        spill.add(i, rings)
    assert spill._f is None and real.closed
    gives_back(spill, want)


def test_a_footprint_that_cannot_be_drawn_leaves_the_others_on_the_picture(tmp_path):
    spill = FootprintSpill(str(tmp_path))
    good = list(_squares(30))
    for i, rings in good:
        spill.add(i, rings)
    spill.add("nan", [np.array([[0.0, 0.0], [np.nan, 1.0], [1.0, 1.0]])])
    spill.add("inf", [np.array([[0.0, 0.0], [1e9, np.inf], [1.0, 1.0]])])
    assert np.isfinite(spill.lo).all() and np.isfinite(spill.hi).all()
    rows = [{"id": i, "repair": {"stage": "valid"}, "energy": {"compliant": True}} for i, _ in good]
    rows += [{"id": i, "repair": {"stage": "valid"}, "energy": {"compliant": True}} for i in ("nan", "inf")]
    page = PageRows(D.iter_rows({"buildings": rows}), plan_max=5)
    urls, info = VR._plan_picture(page, spill, {}, {})
    assert info["drawn"] == sum(1 for _, r in good if r) and (_png(urls["status"]) != 255).any()


# --- the page of a large file ----------------------------------------------------------------------

def _png(url: str):
    from PIL import Image
    assert url.startswith("data:image/png;base64,")
    return np.asarray(Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1]))).convert("RGB"))


def page_data(html: str) -> dict:
    m = re.search(r'<script type="application/json" id="report-data">(.*?)</script>', html, re.S)
    return json.loads(m.group(1).replace("<\\/", "</"))


def denhaag_report():
    """DenHaag_01 (845 buildings), its footprints, and an export report of it with random
    stages and heating needs."""
    src = str(shared_path("denhaag", "DenHaag_01.city.json"))
    _, fps = read_for_page(src, set())
    ids = sorted(fps)
    rng = np.random.default_rng(3)
    stages = rng.choice(["valid", "holefill", "footprint", "irreparable"], len(ids), p=[.7, .1, .1, .1])
    rows = [{"id": i, "repair": {"stage": str(s), "defects_before": [] if s == "valid" else [302],
                                 "defects_after": [302] if s == "irreparable" else []},
             "energy": {"compliant": s != "irreparable"},
             "exports": {"idf": {"ok": True, "heating_kwh": float(h), "problems": []}},
             "thermal": {"footprint": 100.0, "storeys": 2}}
            for i, s, h in zip(ids, stages, rng.uniform(5e3, 3e4, len(ids)))]
    return src, fps, {"input_file": src, "buildings": rows}, stages


def test_a_file_over_plan_max_gets_a_plan_picture_and_embeds_its_panels_rows(tmp_path):
    src, fps, report, stages = denhaag_report()
    ids = sorted(fps)
    small = page_data(render_report_html(report, footprints=fps))            # the SVG plan
    spill = FootprintSpill(str(tmp_path))
    page = PageRows(D.iter_rows(report), plan_max=100)
    wanted = {r.id for r in page.panel_rows()}
    inputs, none = read_for_page(src, wanted, spill)
    assert none == {} and sorted(inputs) == sorted(wanted) and spill.n == len(ids) - len(wanted)
    html = render_report_html(report, inputs=inputs, footprints=spill, page=page)
    spill.close()
    big = page_data(html)
    assert big["figures"] == small["figures"] and big["panels"] == small["panels"]
    assert big["buildings_embedded"] == "panels" and [b["id"] for b in big["buildings"]] == big["panels"]
    assert small["buildings_embedded"] == "all" and len(small["buildings"]) == len(ids)
    assert 'class="fp"' not in html and big["plan"]["drawn"] == small["plan"]["drawn"]
    m = re.search(r'<img id="plan" class="picture"[^>]* src="([^"]+)" data-status-src="[^"]+" data-heat-src="([^"]+)"'
                  r' width="(\d+)" height="(\d+)"', html)
    status, heat = _png(m.group(1)), _png(m.group(2))
    assert status.shape[:2] == (int(m.group(4)), int(m.group(3))) == tuple(big["plan"]["picture"][::-1])
    assert max(status.shape[:2]) <= VR.PLAN_PX + 9
    # every status in the file has its colour on the picture; the heat picture is coloured otherwise
    colours = {tuple(c) for c in status.reshape(-1, 3)}
    for st in {D.Row(id="x", stage=str(s), before=() if s == "valid" else (302,),
                     after=(302,) if s == "irreparable" else ()).status for s in stages}:
        hexc = D.STATUS_COLOURS[st]
        assert tuple(int(hexc[j:j + 2], 16) for j in (1, 3, 5)) in colours, st
    painted = (status != 255).any(axis=2)
    assert 0.005 < painted.mean() < 0.9
    assert np.array_equal(painted, (heat != 255).any(axis=2))  # the same footprints, other colours
    assert not np.array_equal(status, heat)
    assert len(html) < 1_500_000


def test_view_of_a_large_report_json_prepares_only_the_panels_and_draws_a_picture(tmp_path):
    from lod2energy.viz.view import write_report_for
    _, _, report, _ = denhaag_report()
    (tmp_path / "report.json").write_text(json.dumps(report), encoding="utf-8")
    page, t = write_report_for(tmp_path / "report.json", plan_max=100)
    html = page.read_text(encoding="utf-8")
    d = page_data(html)
    assert d["buildings_embedded"] == "panels" and len(d["panels"]) == VR.DEFAULT_CAP
    assert '<img id="plan" class="picture"' in html and d["plan"]["drawn"] == len(report["buildings"])
    # every panel drawn from its building, input and prepared
    assert html.count('class="caps"') == VR.DEFAULT_CAP
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.html", "report.json"]  # no scratch left


@pytest.mark.parametrize("plan_max", [5000, 10])
def test_validate_html_reads_the_files_again_for_the_page(tmp_path, monkeypatch, plan_max):
    """``validate --html`` of two files keeps no building for the page while validating: the
    page reads the files again (panels whole, footprints only; a scratch file over plan_max)."""
    from lod2energy.cli import main
    monkeypatch.setattr(VR, "PLAN_SVG_MAX", plan_max)
    kept = []
    monkeypatch.setattr(VR, "keep", lambda feats, into: kept.append(1) or feats)
    files = [str(shared_path("citygml-real", "berlin", "3900_5819.gml")),
             str(shared_path("3dbag", "tile901_trimmed.city.jsonl"))]
    out = tmp_path / "v.html"
    assert main(["validate", *files, "--report", str(tmp_path / "v.json"), "--html", str(out), "-q"]) in (0, 1)
    assert kept == []
    rep = json.loads((tmp_path / "v.json").read_text())
    n = sum(1 for r in rep["reports"] for f in r["features"] if f.get("type") in ("Building", None) or "energy" in f)
    html = out.read_text(encoding="utf-8")
    d = page_data(html)
    assert d["figures"]["summary"]["buildings"] == n and d["plan"]["drawn"] == n
    if plan_max >= n:
        assert html.count('class="fp"') == n and d["buildings_embedded"] == "all"
    else:
        assert '<img id="plan" class="picture"' in html and 'class="fp"' not in html
        assert n > VR.DEFAULT_CAP and d["buildings_embedded"] == "panels"
        assert len(d["buildings"]) == len(d["panels"]) <= VR.DEFAULT_CAP
    assert sorted(p.name for p in tmp_path.iterdir()) == ["v.html", "v.json"]


def test_page_memory_does_not_grow_with_the_file():
    """The traced peak of reading a report's rows and drawing the picture plan from a scratch
    file of footprints is the same for 2,000 and 8,000 buildings standing on the same 2,000
    places (the same picture: its PNG is as large); it grew ~5 kB a building when every row
    and footprint was held."""
    def peak(n: int) -> int:
        spill = FootprintSpill()
        tracemalloc.start()
        page = PageRows(D.iter_rows(random_report(n)), plan_max=500)
        for i, rings in _squares(n, places=2000):
            spill.add(i, rings)
        VR._plan_picture(page, spill, {}, {})
        fd = page.tally.figure_data()
        _, top = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        spill.close()
        assert fd["summary"]["buildings"] == n
        return top
    peak(500)  # imports and caches
    small, large = peak(2000), peak(8000)
    # 17 bytes a building of arrays (and their sorted copies) may grow; nothing per row beyond
    assert large - small < 6000 * 120, (small, large)


@pytest.mark.external
def test_plan_picture_page_in_chromium(tmp_path):
    pytest.importorskip("playwright")
    from chromium import chromium_path, open_page
    from lod2energy.viz.report import write_report_html
    if chromium_path() is None:
        pytest.skip("chromium not installed (.ci/install-chromium.sh)")
    src, _, report, _ = denhaag_report()
    page = PageRows(D.iter_rows(report), plan_max=100)
    spill = FootprintSpill(str(tmp_path))
    inputs, _ = read_for_page(src, {r.id for r in page.panel_rows()}, spill)
    out = write_report_html(report, tmp_path / "report.html", inputs=inputs, footprints=spill, page=page)
    spill.close()
    want = page_data(out.read_text(encoding="utf-8"))
    with open_page(out) as (p, log):
        assert log.console_errors == [] and log.page_errors == [] and log.blocked == []
        assert p.evaluate("[...document.images].every(i => i.complete && i.naturalWidth > 0)")
        assert p.evaluate("document.querySelector('img#plan').naturalWidth") == want["plan"]["picture"][0]
        shown = p.evaluate("window.reportData")
        assert shown["figures"] == want["figures"] and shown["buildings_embedded"] == "panels"
        plan = p.locator("img#plan")
        plan.scroll_into_view_if_needed()
        before = plan.screenshot()
        assert float(np.asarray(__import__("PIL.Image").Image.open(io.BytesIO(before)).convert("L"), float).var()) > 50
        p.click("#by-heat")
        assert p.evaluate("document.body.dataset.planMode") == "heat"
        assert p.evaluate("document.querySelector('img#plan').getAttribute('src')") == \
            p.evaluate("document.querySelector('img#plan').dataset.heatSrc")
        p.wait_for_function("document.querySelector('img#plan').complete")
        assert plan.screenshot() != before                                   # the picture changed
        p.click("#by-status")
        assert p.evaluate("document.querySelector('img#plan').getAttribute('src')") == \
            p.evaluate("document.querySelector('img#plan').dataset.statusSrc")
