"""Fuzzing the readers, validation, repair and export with mutated real CityJSON features (issue 15).

Hypothesis takes a real building (the bundled Delft example, the 3DBAG tiles of
``../shared``), changes it - a value of another type or size anywhere in it, a deeper
nesting, a removed member, its id given to another feature, a parents/children cycle - and
writes it as a CityJSONSeq line between two untouched real buildings. Whatever the change:

- reading, validation, repair and export raise nothing (no uncaught exception);
- the mutated feature becomes a building or a :class:`FeatureError` with one clear line
  (val3dity code, no exception class names, no newline);
- the two untouched buildings are read, validated and exported as without the mutant;
- the input file is unchanged and nothing is written outside OUTDIR.

Profiles: ``ci`` (``CI`` set) runs 2,000 examples of the read/validate test and 300 of the
repair/export test; ``dev`` (default) 150 and 30. ``HYPOTHESIS_PROFILE`` overrides.
"""
from __future__ import annotations

import copy
import json
import math
import os
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from lod2energy.model import Building, FeatureError

REPO = Path(__file__).resolve().parents[1]
from conftest import DATA  # noqa: E402

_COMMON = dict(deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                                     HealthCheck.filter_too_much],
               # no shrinking: a failing example is reported as found (shrinking whole buildings
               # takes minutes and the mutation list says what was changed)
               phases=[Phase.explicit, Phase.reuse, Phase.generate])
# CI: the same 2,000 examples every run (derandomized), so a green run is a reproducible one;
# locally each run draws new ones
settings.register_profile("ci", max_examples=2000, derandomize=True, database=None, **_COMMON)
settings.register_profile("dev", max_examples=150, **_COMMON)
PROFILE = os.environ.get("HYPOTHESIS_PROFILE") or ("ci" if os.environ.get("CI") else "dev")
EXAMPLES = settings.get_profile(PROFILE).max_examples
#: the repair/export test runs a building through the whole pipeline: fewer examples
EXPORT_EXAMPLES = max(EXAMPLES // 7, 20)


# ----------------------------------------------------------------------------- corpus

def _seq_features(path: Path) -> tuple[dict, list[dict]]:
    lines = path.read_text(encoding="utf-8").splitlines()
    return json.loads(lines[0]), [json.loads(x) for x in lines[1:] if x.strip()]


def _corpus() -> list[tuple[dict, dict]]:
    """(header, feature) pairs of small real buildings: the bundled example and ../shared's 3DBAG."""
    out = []
    paths = [REPO / "examples" / "delft_subset.city.jsonl"]
    paths += sorted((DATA / "3dbag").glob("*.jsonl")) if (DATA / "3dbag").is_dir() else []
    for p in paths:
        try:
            header, feats = _seq_features(p)
        except (OSError, ValueError):
            continue
        for f in feats:
            if len(json.dumps(f)) < 40_000 and any(co.get("type") == "Building" for co in f["CityObjects"].values()):
                out.append((header, f))
    return out


def _root(f: dict) -> str:
    return next(k for k, v in f["CityObjects"].items() if v.get("type") == "Building")


DELFT_HEADER, DELFT = _seq_features(REPO / "examples" / "delft_subset.city.jsonl")
NEIGHBOURS = (DELFT[0], DELFT[-1])  # the two untouched buildings around every mutant
NEIGHBOUR_IDS = tuple(_root(f) for f in NEIGHBOURS)
# the mutants: every other building (a mutant keeping a neighbour's id is made by the "id" mutation)
CORPUS = [(h, f) for h, f in _corpus() if not set(f["CityObjects"]) & {k for n in NEIGHBOURS for k in n["CityObjects"]}]


def test_the_corpus_holds_real_buildings():
    # every building of the bundled example but the two neighbours (8) ...
    assert len(CORPUS) >= len(DELFT) - len(NEIGHBOURS) == 8
    if (DATA / "3dbag").is_dir():
        assert len(CORPUS) >= 10 and len(CORPUS) > len(DELFT)  # ... and ../shared's 3DBAG buildings


# ----------------------------------------------------------------------------- mutations

_ODD = st.one_of(
    st.none(), st.booleans(), st.integers(-2**70, 2**70), st.just(10**400),
    st.floats(allow_nan=True, allow_infinity=True), st.sampled_from([1e400, -1e400, 1e308, -0.0, 5e-324]),
    st.text(max_size=12), st.sampled_from(["", "2.2", "Solid", "Building", "NaN", "1e400", "\u0000", "\ud7ff"]),
    st.just([]), st.just({}), st.lists(st.integers(-3, 50), max_size=4),
    st.dictionaries(st.text(max_size=4), st.integers(), max_size=3),
    st.integers(1, 400).map(lambda n: json.loads("[" * n + "]" * n)),
)


def _paths(x, prefix=()) -> list[tuple]:
    """Every path to a value inside ``x`` (at most a few thousand)."""
    out = [prefix]
    if isinstance(x, dict):
        for k, v in x.items():
            out += _paths(v, prefix + (k,))
    elif isinstance(x, list):
        step = max(1, len(x) // 8)  # long vertex / boundary arrays: a sample
        for i in range(0, len(x), step):
            out += _paths(x[i], prefix + (i,))
    return out


def _get(x, path):
    for k in path:
        x = x[k]
    return x


#: members whose change breaks the geometry itself (excluded by ``light`` mutations, so that
#: the repair ladder stays short and the export runs on every example)
_GEOMETRY_KEYS = ("boundaries", "vertices")


@st.composite
def mutations(draw, f: dict, light: bool = False) -> tuple[dict, list[str]]:
    """``f`` changed by one to three mutations; returns (feature, what was done)."""
    f = copy.deepcopy(f)
    done = []
    for _ in range(draw(st.integers(1, 3))):
        paths = [p for p in _paths(f) if p and not (light and any(k in p for k in _GEOMETRY_KEYS))]
        kind = draw(st.sampled_from(["replace", "replace", "replace", "delete", "wrap", "duplicate-key",
                                     "cycle", "children", "parents", "id"]))
        cos = f.get("CityObjects") if isinstance(f.get("CityObjects"), dict) else {}
        if kind in ("replace", "delete", "wrap") and paths:
            p = draw(st.sampled_from(paths))
            parent = _get(f, p[:-1])
            if kind == "replace":
                parent[p[-1]] = draw(_ODD)
            elif kind == "wrap":
                parent[p[-1]] = [parent[p[-1]]] if draw(st.booleans()) else {"x": parent[p[-1]]}
            elif isinstance(parent, dict):
                del parent[p[-1]]
            else:
                parent.pop(p[-1])
            done.append(f"{kind} {p}")
        elif kind == "cycle" and len(cos) >= 2:
            a, b = draw(st.permutations(list(cos)))[:2]
            if isinstance(cos[a], dict) and isinstance(cos[b], dict):
                cos[a]["parents"], cos[b]["children"] = [b], [a]
                cos[b]["parents"], cos[a]["children"] = [a], [b]
            done.append(f"cycle {a} {b}")
        elif kind in ("children", "parents") and cos:
            oid = draw(st.sampled_from(list(cos)))
            if isinstance(cos[oid], dict):
                cos[oid][kind] = draw(st.one_of(_ODD, st.lists(st.sampled_from(list(cos) + ["nowhere"]), max_size=3)))
            done.append(f"{kind} of {oid}")
        elif kind == "id" and cos:
            oid = draw(st.sampled_from(list(cos)))
            # the first neighbour's id (its line comes first and is kept), or an odd one
            new = draw(st.sampled_from([NEIGHBOUR_IDS[0], "", "../../etc/passwd", "a" * 300, "x\ny", "é/ü"]))
            cos[new] = cos.pop(oid)
            done.append(f"id {oid} -> {new!r}")
        elif kind == "duplicate-key" and cos:
            done.append("duplicate-key")
            f["__dup__"] = True  # written with a repeated CityObjects key, see _line
    return f, done


def _line(f: dict) -> str:
    dup = f.pop("__dup__", False)
    s = json.dumps(f, allow_nan=True)
    if dup and isinstance(f.get("CityObjects"), dict) and f["CityObjects"]:
        k, v = next(iter(f["CityObjects"].items()))
        s = s.replace('"CityObjects": {', '"CityObjects": {' + json.dumps(k) + ": " + json.dumps(v) + ", ", 1)
    return s


_NEIGHBOUR_LINES: dict[str, list[str]] = {}


def _neighbour_lines(transform: dict) -> list[str]:
    """The two untouched buildings as CityJSONSeq lines in ``transform`` (the mutant's file's)."""
    key = json.dumps(transform, sort_keys=True)
    if key not in _NEIGHBOUR_LINES:
        from lod2energy.io.cityjson import build_feature, _transform_vertices
        from lod2energy.io.cityjson_write import feature_document
        lines = []
        for f in NEIGHBOURS:
            verts = _transform_vertices(f["vertices"], DELFT_HEADER["transform"], "neighbour")
            ids = [_root(f)] + [k for k in f["CityObjects"] if k != _root(f)]
            b = build_feature(ids[0], ids, f["CityObjects"], verts)
            lines.append(json.dumps(feature_document(b, transform, "2.0")))
        _NEIGHBOUR_LINES[key] = lines
    return _NEIGHBOUR_LINES[key]


def _write_input(folder: Path, header: dict, mutant: dict) -> Path:
    """``in.city.jsonl``: the Delft header in the mutant's transform, a neighbour, the mutant, a neighbour."""
    p = folder / "in.city.jsonl"
    h = copy.deepcopy(DELFT_HEADER)
    h["transform"] = header.get("transform", h["transform"])
    a, b = _neighbour_lines(h["transform"])
    p.write_text("\n".join([json.dumps(h), a, _line(mutant), b]) + "\n", encoding="utf-8")
    return p


def _clear(msg: str) -> bool:
    return bool(msg) and "\n" not in msg and len(msg) < 600 and "Traceback" not in msg


# ----------------------------------------------------------------------------- the invariants

def _read_all(path: Path):
    from lod2energy.io import read
    model, feats = read(str(path))
    assert model is not None, list(feats)
    items = list(feats)
    for it in items:
        assert isinstance(it, (Building, FeatureError))
        if isinstance(it, FeatureError):
            assert it.code in (901, 902, 904) and _clear(it.message), it
    buildings = [b for b in items if isinstance(b, Building)]
    ids = [b.id for b in buildings]
    for nid in NEIGHBOUR_IDS:
        assert nid in ids, f"untouched building {nid} lost"
    return model, items, buildings


@given(data=st.data())
@settings(settings.get_profile(PROFILE), max_examples=EXAMPLES)
def test_read_and_validate_never_raise_and_keep_the_other_buildings(data):
    from lod2energy.config import DEFAULT
    from lod2energy.validate.checks import validate_building
    from lod2energy.validate.compliance import energy_compliance
    header, base = data.draw(st.sampled_from(CORPUS))
    mutant, how = data.draw(mutations(base))
    with tempfile.TemporaryDirectory() as d:
        inp = _write_input(Path(d), header, mutant)
        before = inp.read_bytes()
        _, items, buildings = _read_all(inp)
        for b in buildings:
            defects = validate_building(b, DEFAULT)
            comp = energy_compliance(b, defects, tol=DEFAULT)
            assert isinstance(comp["compliant"], bool)
            if b.id in NEIGHBOUR_IDS:
                assert not [x for x in defects if x.code >= 900 and x.code < 1000], (b.id, defects)
        assert inp.read_bytes() == before
        assert sorted(os.listdir(d)) == ["in.city.jsonl"]


@given(data=st.data())
@settings(settings.get_profile(PROFILE), max_examples=EXPORT_EXAMPLES)
def test_repair_and_export_never_raise_and_keep_the_other_buildings(data, tmp_path_factory):
    from lod2energy.config import DEFAULT
    from lod2energy.exporters.cityjson import writer as cj_export
    from lod2energy.exporters.stl import writer as stl
    from lod2energy.repair.pipeline import repair_building
    from lod2energy.semantics import label_building
    from lod2energy.thermal import ThermalOptions, assign_u_values
    from lod2energy.validate.checks import validate_building
    from lod2energy.validate.compliance import energy_compliance
    header, base = data.draw(st.sampled_from(CORPUS))
    mutant, how = data.draw(mutations(base, light=True))
    root = tmp_path_factory.mktemp("fuzz")
    inp = _write_input(root, header, mutant)
    before = inp.read_bytes()
    model, items, buildings = _read_all(inp)
    outdir = root / "out"
    ready = []
    for b in buildings:
        rb = repair_building(b, tol=DEFAULT, timeout=5.0)
        lb = label_building(rb, source=b)
        tb = assign_u_values(lb, ThermalOptions(crs=model.crs))
        comp = energy_compliance(tb, validate_building(tb, DEFAULT), tol=DEFAULT, assess_labels=True,
                                 assess_u_values=True)
        if b.id in NEIGHBOUR_IDS:
            assert comp["geometry_ready"], (b.id, comp["reasons"])
        ready.append(tb)
    res = cj_export.write(str(outdir / "in.energy.city.json"), model, ready)
    assert all(_clear(p) for p in res.problems)
    written = set(res.building_ids)
    assert set(NEIGHBOUR_IDS) <= written, (res.problems, res.skipped)
    results = stl.write([b for b in ready if b.id in NEIGHBOUR_IDS or b.id in written], outdir)
    for r in results:
        if set(r.building_ids) & set(NEIGHBOUR_IDS):
            assert r.ok, r.problems
        if r.path:
            assert r.ok or r.path.endswith(".invalid")
    assert inp.read_bytes() == before
    assert {p.name for p in root.iterdir()} == {"in.city.jsonl", "out"}
    for p in outdir.iterdir():
        assert p.resolve().parent == outdir.resolve() and not p.is_symlink()
