"""Agreement with val3dity 2.6 reports on the real tiles (../shared/reference/*.report.json).

Over every Building of every reference report: the same valid/invalid verdict for at
least 98 % and the same set of error codes for at least 95 %; every Building reported.
The same shares hold over every first-level feature val3dity reports (installations,
terrain, roads, ...). Tolerances are the ones each report states. Skipped when the
shared data are absent.
"""
from __future__ import annotations

import json
import time

import pytest

from conftest import REFERENCE, SHARED
from _val3dity_agreement import compare, report_tolerances, validate_codes

REPORTS = sorted(REFERENCE.glob("*.report.json")) if REFERENCE.exists() else []


@pytest.fixture(scope="module")
def results() -> dict[str, tuple[dict, dict, float]]:
    """report name -> (report, our codes per feature, seconds)."""
    if not REPORTS:
        pytest.skip("shared reference reports not available")
    out = {}
    for r in REPORTS:
        with open(r, encoding="utf-8") as f:
            report = json.load(f)
        data_file = SHARED / report["input_file"]
        if data_file.exists():
            t0 = time.perf_counter()
            ours = validate_codes(str(data_file), report_tolerances(report))
            out[r.name] = (report, ours, time.perf_counter() - t0)
    if not out:
        pytest.skip("shared data files not available")
    return out


def _shares(results, types):
    agreements = {k: compare(ours, report, types) for k, (report, ours, _) in results.items()}
    n = sum(a.n for a in agreements.values())
    verdict = sum(a.verdict * a.n for a in agreements.values()) / n
    codes = sum(a.codes * a.n for a in agreements.values()) / n
    detail = {k: (a.n, round(a.verdict, 3), round(a.codes, 3), a.disagreements[:3])
              for k, a in agreements.items() if a.codes < 1}
    missing = {k: a.missing for k, a in agreements.items() if a.missing}
    return n, verdict, codes, detail, missing


def test_buildings_agree_with_val3dity(results):
    n, verdict, codes, detail, missing = _shares(results, ("Building",))
    assert n > 1000
    assert not missing
    assert verdict >= 0.98, detail
    assert codes >= 0.95, detail


def test_every_feature_type_agrees_with_val3dity(results):
    n, verdict, codes, detail, missing = _shares(results, None)
    assert not missing
    assert verdict >= 0.98, detail
    assert codes >= 0.95, detail


def test_compare_counts_disagreements():
    report = {"features": [
        {"id": "a", "type": "Building", "validity": True, "errors": []},
        {"id": "b", "type": "Building", "validity": False, "errors": [{"code": 302}, {"code": 302}]},
        {"id": "c", "type": "Building", "validity": False, "errors": [{"code": 203}]},
        {"id": "t", "type": "TINRelief", "validity": True, "errors": []},
    ]}
    a = compare({"a": [], "b": [302], "c": [203, 601]}, report)
    assert (a.n, a.verdict, a.codes) == (3, 1.0, pytest.approx(2 / 3))
    assert a.disagreements == [("c", [203, 601], [203])]
    b = compare({"a": [306]}, report)
    assert b.missing == ["b", "c"] and b.verdict == pytest.approx(0.0)
    assert compare({}, report, types=("TINRelief",)).missing == ["t"]


def test_installations_are_features_of_their_own():
    import numpy as np

    from lod2energy.model import Building, CityObject
    from _val3dity_agreement import split_by_feature
    from lod2energy.validate.codes import Defect

    b = Building("B", "Building", np.zeros((0, 3)), (
        CityObject("B", "Building", children=("B_1", "I")), CityObject("B_1", "BuildingPart", parents=("B",)),
        CityObject("I", "BuildingInstallation", parents=("B",))))
    got = split_by_feature(b, [Defect(203, "coid=B_1|geom=0|shell=0|face=1"),
                               Defect(405, "coid=I|geom=0|shell=0|face="), Defect(1003, "coid=B|geom=0")])
    assert got == {"B": {203}, "I": {405}}


def test_303_307_faces_match_val3dity(results):
    """Where val3dity names faces refused while building a shell, we name the same faces."""
    from lod2energy.io import read
    from lod2energy.validate.checks import validate_buildings

    checked = 0
    for report, _, _ in results.values():
        want = {(e["code"], e["id"]) for f in report["features"] for e in f["errors"] if e["code"] in (303, 307)
                and e["id"].rsplit("face=", 1)[-1] != ""}
        if not want:
            continue
        _, feats = read(str(SHARED / report["input_file"]))
        bs = [b for b in feats if hasattr(b, "objects")]
        got = {(d.code, d.location) for ds in validate_buildings(bs, report_tolerances(report)) for d in ds
               if d.code in (303, 307)}
        assert want <= got, sorted(want - got)
        checked += len(want)
    if not checked:
        pytest.skip("no face-located 303/307 in the reference reports")
