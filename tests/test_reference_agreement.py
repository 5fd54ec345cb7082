"""Agreement with val3dity 2.6 reports on the real tiles (../shared/reference/*.report.json).

Over every Building of every reference report: the same valid/invalid verdict for at
least 98 % and the same set of error codes for at least 95 %; every Building reported.
Tolerances are the ones each report states. Skipped when the shared data are absent.
"""
from __future__ import annotations

import json

import pytest

from conftest import REFERENCE, SHARED
from lod2energy.validate.agreement import Agreement, agreement_with_report, compare

REPORTS = sorted(REFERENCE.glob("*.report.json")) if REFERENCE.exists() else []


@pytest.fixture(scope="module")
def agreements() -> dict[str, Agreement]:
    if not REPORTS:
        pytest.skip("shared reference reports not available")
    out = {}
    for r in REPORTS:
        with open(r, encoding="utf-8") as f:
            data_file = SHARED / json.load(f)["input_file"]
        if data_file.exists():
            out[r.name] = agreement_with_report(str(r), str(SHARED))
    if not out:
        pytest.skip("shared data files not available")
    return out


def test_every_building_is_reported(agreements):
    missing = {k: a.missing for k, a in agreements.items() if a.missing}
    assert not missing


def test_verdict_and_code_set_agreement(agreements):
    n = sum(a.n for a in agreements.values())
    verdict = sum(a.verdict * a.n for a in agreements.values()) / n
    codes = sum(a.codes * a.n for a in agreements.values()) / n
    detail = {k: (a.n, round(a.verdict, 3), round(a.codes, 3), a.disagreements[:3])
              for k, a in agreements.items() if a.codes < 1}
    assert n > 1000
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
