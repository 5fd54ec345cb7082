"""The IDF writer's and self-check's shortcuts give what the full computations give.

- :func:`lod2energy.validate.closed._surely_outward` (the closed-shell check's volume sign without
  triangulating) only says "positive" when the earcut volume is positive, so the check's
  problems are those of the full computation;
- :func:`lod2energy.energy.openings.window_for` (one containment test when the ratio, not
  the piece's shape, limits the window) equals the 24-step bisection.
"""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.geometry import polygons, signed_volume
from lod2energy.geometry.snap import drop_repeats, split_at_points, weld
from lod2energy.validate import closed as shellcheck


def _prism(outline: np.ndarray, z0: float, z1: float) -> list[np.ndarray]:
    """Closed outward prism over a counter-clockwise outline (k, 2): floor, roof, walls."""
    k = len(outline)
    lo = np.column_stack([outline, np.full(k, z0)])
    hi = np.column_stack([outline, np.full(k, z1)])
    faces = [lo[::-1].copy(), hi.copy()]
    for i in range(k):
        j = (i + 1) % k
        faces.append(np.array([lo[i], lo[j], hi[j], hi[i]]))
    return faces


def _shells(rng) -> list[list[np.ndarray]]:
    out = []
    for i in range(80):
        k = 3 + i % 6
        ang = np.sort(rng.random(k)) * 2 * np.pi
        r = 0.2 + rng.random(k) * 8 if i % 3 else np.full(k, 4.0)
        outline = np.column_stack([r * np.cos(ang), r * np.sin(ang)])  # star-shaped: convex or not
        h = [3.0, 0.05, 1e-4, 0.0][i % 4]  # down to a flat (zero-volume) shell
        faces = _prism(outline, 0.0, h)
        noise = [0.0, 1e-4, 2e-3][i % 3]  # non-planar faces: triangulations differ in volume
        faces = [f + rng.normal(0, noise, f.shape) * (f[:, 2:3] > 0) for f in faces]
        faces = [np.round(f + [85000.0, 447000.0, 0.0], 3) - [85000.0, 447000.0, 0.0] for f in faces]
        out.append(faces)
        out.append([f[::-1].copy() for f in faces])  # inward: a negative volume
    # an L-shaped prism (a non-convex floor and roof)
    out.append(_prism(np.array([[0, 0], [4, 0], [4, 1], [1, 1], [1, 3], [0, 3]], dtype=float), 0, 2.5))
    return out


def _earcut_volume(polys: list[np.ndarray]) -> float:
    """The volume check_closed_outward computes (earcut triangles, signed volume about the centroid)."""
    allp = np.concatenate(polys)
    v, idx = weld(allp, 1e-3)
    rings, k = [], 0
    for p in polys:
        ring = drop_repeats(idx[k:k + len(p)].tolist())
        k += len(p)
        if len(set(ring)) >= 3:
            rings.append(ring)
    rings = split_at_points(v, rings, 0.0127, only_unmatched=True)
    tris = [[r[i] for i in t] for r in rings for t in polygons.triangulate(v[r], [len(r)])]
    return signed_volume(v, np.asarray(tris, dtype=np.intp).reshape(-1, 3)), v, rings


def test_surely_outward_only_when_the_earcut_volume_is_positive():
    rng = np.random.default_rng(13)
    said = 0
    for faces in _shells(rng):
        vol, v, rings = _earcut_volume(faces)
        if shellcheck._surely_outward(v, rings):
            said += 1
            assert vol > 0
    assert said >= 10  # the shortcut is taken (on the convex outward shells)


def test_closed_outward_problems_same_without_the_shortcut(monkeypatch):
    rng = np.random.default_rng(7)
    shells = _shells(rng)
    got = [shellcheck.check_closed_outward(f) for f in shells]
    monkeypatch.setattr(shellcheck, "_surely_outward", lambda v, polys: False)
    ref = [shellcheck.check_closed_outward(f) for f in shells]
    assert got == ref
    assert any("not outward" in " ".join(p) for p in ref) and any(not p for p in ref)


def test_surely_outward_refuses_a_ring_that_winds_twice():
    # a pentagram: every turn to the left, two turns in all (earcut's triangles need not cover it)
    ang = np.arange(5) * 4 * np.pi / 5
    star = np.column_stack([np.cos(ang), np.sin(ang), np.zeros(5)])
    v = np.vstack([star, [[0.0, 0.0, 1.0]]])
    rings = [[0, 1, 2, 3, 4]] + [[i, 5, (i + 1) % 5][::-1] for i in range(5)]
    assert not shellcheck._surely_outward(v, rings)


@pytest.mark.parametrize("wwr", [0.05, 0.3, 0.85, 0.97])
def test_window_for_same_as_the_bisection(wwr):
    from lod2energy.energy.openings import window_for

    from _window_reference import bisection_window as ref

    rng = np.random.default_rng(21)
    for i in range(80):
        w, h = rng.random(2) * 10 + 0.1
        top = h * (1 + 3 * rng.random() * (i % 2))       # rectangles and steep gables
        shift = w * rng.random() * (i % 3 == 2)          # leaning (parallelogram-like) pieces
        p = np.array([[0.0, 0, 0], [w, 0, 0], [w + shift, 0, h], [shift, 0, top]])
        if i % 5 == 4:
            p = np.array([[0.0, 0, 0], [w, 0, 0], [w / 2, 0, top], [w / 4, 0, top * 0.9]])
        ang = rng.random() * 6.28
        rot = np.array([[np.cos(ang), -np.sin(ang), 0], [np.sin(ang), np.cos(ang), 0], [0, 0, 1]])
        p = np.round(p @ rot.T + [85000.0, 447000.0, 1.0], 4) - [85000.0, 447000.0, 0.0]
        got, exp = window_for(p, wwr), ref(p, wwr)
        assert (got is None and exp is None) or np.array_equal(got, exp), i


def test_union_roots_same_as_scipy_disjoint_set():
    from scipy.cluster.hierarchy import DisjointSet

    from lod2energy.geometry.snap import _union_roots

    rng = np.random.default_rng(5)
    for n in (1, 2, 7, 40, 300):
        for m in (0, n // 2, 2 * n, 5 * n):
            pairs = rng.integers(0, n, size=(m, 2)).tolist()
            ds = DisjointSet(range(n))
            for a, b in pairs:
                ds.merge(a, b)
            assert _union_roots(n, pairs) == [ds[i] for i in range(n)]


def _ref_area(p):  # zoning._area before its fast path
    if len(p) < 3:
        return 0.0
    return 0.5 * float(np.linalg.norm(np.cross(p - p[0], np.roll(p, -1, axis=0) - p[0]).sum(axis=0)))


from _zoning_reference import clip_before_fast_path as _ref_clip  # noqa: E402


def test_zoning_area_and_clip_same_bits():
    from lod2energy.energy.zones import cut as zoning

    rng = np.random.default_rng(17)
    for i in range(400):
        k = 1 + i % 9
        p = rng.random((k, 3)) * [30, 30, 12] + np.array([85000.0, 447000.0, 0.0]) * (i % 2)
        if i % 7 == 0 and k > 2:
            p[2] = p[1]  # a repeated vertex
        if i % 5 == 0:
            p[:, 2] = np.round(p[:, 2])  # vertices on a cut
        assert zoning._area(p) == _ref_area(p)
        for c in (0.0, 3.0, 6.0, 13.0):
            for above in (True, False):
                got, exp = zoning._clip(p, c, above), _ref_clip(p, c, above)
                assert got.shape == exp.shape and np.array_equal(got, exp), (i, c, above)


def test_idd_classes_built_on_first_use_equal_the_eager_parse():
    from lod2energy.exporters import energyplus
    from lod2energy.exporters.energyplus.idd import check_idf, parse_idd, parse_idf

    from _idd_reference import parse_idd_reference

    p = energyplus.run.idd_path()
    if p is None:
        pytest.skip("no Energy+.idd installed")
    text = p.read_text(encoding="latin-1")
    lazy, eager = parse_idd(text), parse_idd_reference(text)
    assert lazy.version == eager.version and list(lazy.classes) == list(eager.classes)
    name = "BUILDINGSURFACE:DETAILED"
    first = lazy.classes[name]
    assert first == eager.classes[name] and lazy.classes[name] is first  # built once, then kept
    assert all(lazy.classes[k] == c for k, c in eager.classes.items())  # every class, any order of use
    assert lazy.classes._all is None  # each read from its own piece: the real IDD is cut right
    assert lazy == eager
    # the unique / required objects come from the classes as read: the same problems
    bad = "Version, 1.0;\nTimestep, 4;\nTimestep, 6;\nZone, Z;\nNotAnObject, 1;\n"
    fresh = parse_idd(text)
    assert check_idf(parse_idf(bad), fresh) == check_idf(parse_idf(bad), eager)
    assert any("unique" in x for x in check_idf(parse_idf(bad), fresh))
    assert any("required object" in x for x in check_idf(parse_idf(bad), fresh))


def test_self_check_still_flags_non_planar_and_tiny_surfaces(tmp_path):
    import re

    from export_helpers import energy_ready, write_idf
    from factories import box

    from lod2energy.exporters import energyplus

    res = write_idf([energy_ready(box())], tmp_path, energyplus.options.IdfOptions(wwr=0.0))
    text = open(res[0].path).read()
    assert energyplus.check.self_check(res[0].path) == []
    roof = re.search(r"BuildingSurface:Detailed,\s*\n\s*(\S+Roof1),.*?;\n", text, flags=re.S)
    verts = re.findall(r"^\s*(-?[\d.]+), (-?[\d.]+), (-?[\d.]+)[,;]", roof.group(0), flags=re.M)
    x, y, z = verts[0]
    # one roof corner 5 cm up: out of plane by more than 2 x PIECE_PLANAR
    bent = roof.group(0).replace(f"{x}, {y}, {z}", f"{x}, {y}, {float(z) + 0.05:.3f}", 1)
    (tmp_path / "bent.idf").write_text(text.replace(roof.group(0), bent))
    problems = energyplus.check.self_check(tmp_path / "bent.idf")
    assert any(f"surface {roof.group(1)}: non-planar for EnergyPlus (0.0" in p for p in problems)
    # every roof corner on the first one: no area
    flat = roof.group(0)
    for a, b, c in verts[1:]:
        flat = flat.replace(f"{a}, {b}, {c}", f"{x}, {y}, {z}", 1)
    (tmp_path / "flat.idf").write_text(text.replace(roof.group(0), flat))
    problems = energyplus.check.self_check(tmp_path / "flat.idf")
    assert any(f"surface {roof.group(1)}: degenerate for EnergyPlus (4 vertices)" in p for p in problems)
