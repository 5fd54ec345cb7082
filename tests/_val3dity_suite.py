"""val3dity's own test suite run through lod2energy (helpers of ``test_val3dity_conformance.py``).

``../shared/data/val3dity-tests/EXPECTED_RESULTS.json`` lists, for each test file of
val3dity, the command-line options and the acceptable outcomes (lists of distinct error
codes, ``[]`` = valid, ``"CRASH"`` = val3dity crashes). :func:`run_case` reads one case
with the same options and returns the distinct codes lod2energy finds over the whole
file; :func:`matches` compares them with the expectation (for a CRASH case, not crashing
and reporting the file as invalid input, 901, is the right outcome).
"""
from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path
from typing import Any, Iterable, Mapping

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.io import read
from lod2energy.model import FeatureError
from lod2energy.validate.checks import validate_building

SUITE = Path(__file__).resolve().parents[2] / "shared" / "data" / "val3dity-tests"
"""Default location of val3dity's test data (``../shared/...`` next to the repository)."""

_FLOAT_OPTIONS = {"--snap_tol": "snap_tol", "--overlap_tol": "overlap_tol",
                  "--planarity_n_tol": "planarity_n_tol", "--planarity_d2p_tol": "planarity_d2p_tol"}


def load_cases(root: Path | str = SUITE, statuses: Iterable[str] = ("tested",),
               skip_suffixes: Iterable[str] = (".gml",)) -> list[dict]:
    """Cases of ``EXPECTED_RESULTS.json`` with one of ``statuses``, minus CityGML/IndoorGML files."""
    doc = json.loads((Path(root) / "EXPECTED_RESULTS.json").read_text(encoding="utf-8"))
    statuses = tuple(statuses)
    skip = tuple(s.lower() for s in skip_suffixes)
    return [c for c in doc["cases"]
            if c.get("status") in statuses and not c["file"].lower().endswith(skip)]


def case_id(case: Mapping[str, Any]) -> str:
    """A short readable id: file, options and inner shells."""
    opts = [o for o in case.get("options", []) if o != "--unittests"]
    parts = [case["file"]] + opts + [f"ishell={Path(s).name}" for s in case.get("inner_shells", [])]
    return " ".join(parts)


def parse_options(options: Iterable[str]) -> tuple[dict, Tolerances]:
    """val3dity command-line options -> (reader options, tolerances).

    Raises
    ------
    ValueError
        An option lod2energy does not know.
    """
    opts = list(options)
    read_opts: dict[str, Any] = {}
    tol = DEFAULT
    i = 0
    while i < len(opts):
        o = opts[i]
        if o in ("--unittests", "--verbose", "--notranslate", "--onlyinvalid"):
            i += 1
        elif o in ("-p", "--primitive"):
            read_opts["primitive"] = opts[i + 1]
            i += 2
        elif o in _FLOAT_OPTIONS:
            tol = replace(tol, **{_FLOAT_OPTIONS[o]: float(opts[i + 1])})
            i += 2
        elif o == "--ignore204":
            tol = replace(tol, ignore204=True)
            i += 1
        else:
            raise ValueError(f"unknown val3dity option {o!r}")
    return read_opts, tol


def run_file(path: str, read_opts: Mapping[str, Any] | None = None, tol: Tolerances = DEFAULT) -> list[int]:
    """Sorted distinct codes lod2energy reports for a whole file (``[]`` when valid)."""
    codes: set[int] = set()
    mesh_only = {"primitive", "inner_shells"}
    opts = dict(read_opts or {})
    if not path.lower().endswith((".poly", ".obj", ".off")):
        opts = {k: v for k, v in opts.items() if k not in mesh_only}
    _, features = read(path, **opts)
    for f in features:
        if isinstance(f, FeatureError):
            codes.add(int(f.code))
            continue
        codes.update(d.code for d in validate_building(f, tol))
    return sorted(codes)


def run_case(case: Mapping[str, Any], root: Path | str = SUITE) -> list[int]:
    """Run one case of ``EXPECTED_RESULTS.json``; returns the sorted distinct codes.

    Never raises for bad input; an unexpected exception (a crash of lod2energy) gives
    ``[999]`` (UNKNOWN_ERROR) so that benchmarks count it as a failure.
    """
    root = Path(root)
    try:
        read_opts, tol = parse_options(case.get("options", []))
    except ValueError:
        return [903]
    shells = [str(root / s) for s in case.get("inner_shells", [])]
    if shells:
        read_opts["inner_shells"] = shells
    try:
        return run_file(str(root / case["file"]), read_opts, tol)
    except Exception:  # noqa: BLE001 - a crash is a result here, not an error
        return [999]


def matches(case: Mapping[str, Any], outcome: list[int]) -> bool:
    """True when ``outcome`` is one of the case's acceptable outcomes."""
    got = sorted(set(outcome))
    expected = case.get("expected")
    if expected == "invalid":  # documented invalid without a code
        return bool(got) and 999 not in got
    for exp in expected or []:
        if exp == "CRASH":
            if got == [901]:
                return True
        elif isinstance(exp, list) and sorted(set(exp)) == got:
            return True
    return False
