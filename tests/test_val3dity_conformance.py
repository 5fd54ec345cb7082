"""val3dity's own test suite (EXPECTED_RESULTS.json, status "tested", CityGML/IndoorGML excluded).

Each case is read with val3dity's options and validated; the distinct codes over the file
must be one of the expected outcomes. Known divergences are xfail (not strict) with the
reason; the overall pass share must stay >= 95 %.
"""
from __future__ import annotations

import pytest

from conftest import VAL3DITY_TESTS
from _val3dity_suite import case_id, load_cases, matches, run_case

_HAVE = (VAL3DITY_TESTS / "EXPECTED_RESULTS.json").exists()
CASES = load_cases(VAL3DITY_TESTS) if _HAVE else []
# valid solids with inner shells, asserted by val3dity only with --runfull: checked too,
# not counted in the share
RUNFULL = load_cases(VAL3DITY_TESTS, statuses=("tested (--runfull only)",)) if _HAVE else []

# case id -> why lod2energy differs from val3dity on purpose (or for now)
KNOWN_DIVERGENCES = {
    "test_empty/empty_primitive_1.json":
        "declares CityJSON version '0.1': lod2energy refuses unsupported versions (904) before "
        "looking at the geometry; val3dity ignores the version and reports the empty solid (902)",
}


def _params():
    for c in CASES + RUNFULL:
        cid = case_id(c)
        marks = []
        if cid in KNOWN_DIVERGENCES:
            marks.append(pytest.mark.xfail(reason=KNOWN_DIVERGENCES[cid], strict=False))
        yield pytest.param(c, id=cid, marks=marks)


@pytest.mark.parametrize("case", list(_params()))
def test_case(case, val3dity_suite):
    got = run_case(case, val3dity_suite)
    assert matches(case, got), f"expected one of {case['expected']}, got {got}"


def test_overall_pass_share(val3dity_suite):
    results = [(case_id(c), matches(c, run_case(c, val3dity_suite))) for c in CASES]
    failed = [cid for cid, ok in results if not ok]
    share = 1 - len(failed) / len(results)
    assert len(results) >= 100
    assert share >= 0.95, f"pass share {share:.1%}; failing: {failed}"


def test_run_case_reports_crash_as_999_not_exception(tmp_path):
    # an unknown option is a parameter error, never an exception
    assert run_case({"file": "nope.poly", "options": ["--frobnicate"], "expected": [[903]]}, tmp_path) == [903]
    assert run_case({"file": "nope.poly", "options": [], "expected": [[901]]}, tmp_path) == [901]


def test_matches_semantics():
    assert matches({"expected": [[202], [201]]}, [201])
    assert matches({"expected": ["CRASH"]}, [901])
    assert not matches({"expected": ["CRASH"]}, [])
    assert matches({"expected": "invalid"}, [302])
    assert not matches({"expected": [[]]}, [203])
