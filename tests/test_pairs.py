"""Close pairs and connected components without scipy (lod2energy.geometry.pairs): the same
results as scipy's k-d tree and csgraph (scipy stays a dependency, so it is the reference here),
and ``lod2energy validate`` no longer needs scipy for them."""
from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components as cs_components
from scipy.spatial import cKDTree

from conftest import shared_path
from lod2energy.geometry import pairs as P
from lod2energy.geometry.pairs import close_pairs_grid, connected_components


def _kd_pairs(p: np.ndarray, r: float) -> np.ndarray:
    q = cKDTree(p).query_pairs(r, output_type="ndarray").reshape(-1, 2).astype(np.intp)
    return q[np.lexsort((q[:, 1], q[:, 0]))]


def _same_pairs(p, r):
    got = close_pairs_grid(p, r)
    want = _kd_pairs(p, r)
    assert got.dtype == np.intp and got.shape == want.shape, (got.shape, want.shape)
    assert np.array_equal(got, want)
    return got


def _clouds(rng, n, d):
    """Uniform, grid-snapped (distances exactly r), clustered, duplicate-heavy, city-like."""
    yield rng.random((n, d))
    yield np.round(rng.random((n, d)) * 8) / 8
    centres = rng.random((max(n // 30, 1), d)) * 100
    yield centres[rng.integers(0, len(centres), n)] + rng.normal(scale=1e-3, size=(n, d))
    yield centres[rng.integers(0, len(centres), n)]                       # exact duplicates
    yield np.r_[rng.random((n // 2, d)), np.zeros((n - n // 2, d))]       # half in one point
    yield 1e7 + np.round(rng.random((n, d)) * 1e5) * 1e-3                  # RD-like mm grid


@pytest.mark.parametrize("d", [1, 2, 3, 4, 5])
@pytest.mark.parametrize("seed", range(3))
def test_pairs_equal_the_kd_tree(d, seed):
    rng = np.random.default_rng(100 * d + seed)
    for n in (0, 1, 2, 7, 60, 400):
        for p in _clouds(rng, n, d):
            for r in (0.0, 1e-3, 0.125, 0.25, 0.3, 1.0):
                _same_pairs(p, r)


def _brute_pairs(p: np.ndarray, r: float) -> np.ndarray:
    """Every pair tested with the k-d tree's sum ((dx^2 + dy^2) + dz^2) against ``r * r``."""
    i, j = np.triu_indices(len(p), 1)
    with np.errstate(over="ignore"):
        d = p[i] - p[j]
        s = d[:, 0] * d[:, 0]
        for k in range(1, p.shape[1]):
            s = s + d[:, k] * d[:, k]
        keep = s <= r * r
    return np.stack([i[keep], j[keep]], axis=1).astype(np.intp)


def _same_pairs_anywhere(p, r):
    """Against brute force, and against the k-d tree where it copes (it refuses ~1e154+)."""
    got = close_pairs_grid(p, r)
    assert np.array_equal(got, _brute_pairs(p, r))
    try:
        want = _kd_pairs(p, r)
    except ValueError:  # "Encountering floating point overflow"
        return
    assert np.array_equal(got, want)


def test_pairs_at_huge_and_tiny_scales():
    rng = np.random.default_rng(7)
    for scale in (1e-200, 1e-160, 1e-9, 1.0, 1e6, 1e15, 1e150, 1e300):
        p = rng.normal(size=(300, 3)) * scale
        p[::7] = p[1::7][: len(p[::7])]                # duplicates
        for frac in (0.0, 1e-3, 0.05, 0.3):
            _same_pairs_anywhere(p, frac * scale)
    # both ends of the float range at once: p - min overflows
    p = np.array([[-1.5e308, 0.0, 0.0], [1.5e308, 0.0, 0.0], [1.5e308, 0.0, 1.0], [0.0, 0.0, 0.0]])
    _same_pairs_anywhere(p, 2.0)
    _same_pairs(np.array([[1e16, 0.0, 0.0], [1e16 + 2.0, 0.0, 0.0], [1e16 + 4.0, 0.0, 0.0]]), 2.0)
    # squares that underflow: such points count as coinciding, as the k-d tree counts them
    _same_pairs(np.array([[0.0, 0.0, 0.0], [1e-170, 0.0, 0.0], [0.0, 1e-200, 0.0], [1.0, 1.0, 1.0]]), 0.0)


def test_pairs_many_in_one_cell_are_chunked(monkeypatch):
    rng = np.random.default_rng(3)
    p = np.r_[np.repeat(rng.random((3, 3)), 150, axis=0), rng.random((200, 3))]
    want = _kd_pairs(p, 0.05)
    monkeypatch.setattr(P, "CHUNK", 97)            # many small chunks, rows longer than one chunk
    assert np.array_equal(close_pairs_grid(p, 0.05), want)
    assert len(want) > 3 * 150 * 149 // 2


def test_pairs_edge_cases():
    p = np.random.default_rng(5).random((20, 3))
    assert close_pairs_grid(p, -1.0).shape == (0, 2)
    assert close_pairs_grid(p, float("nan")).shape == (0, 2)
    assert close_pairs_grid(np.zeros((0, 3)), 1.0).shape == (0, 2)
    assert close_pairs_grid(p[:1], 1.0).shape == (0, 2)
    _same_pairs(p, float("inf"))
    _same_pairs(p, 1e200)                           # r * r overflows: every pair, as the k-d tree
    _same_pairs(p.tolist(), 0.3)                    # array-likes
    for bad in (np.nan, np.inf, -np.inf):
        q = p.copy()
        q[4, 1] = bad
        with pytest.raises(ValueError):
            cKDTree(q)
        with pytest.raises(ValueError):
            close_pairs_grid(q, 0.1)


def _cs(n, i, j):
    g = coo_matrix((np.ones(len(i)), (i, j)), shape=(n, n))
    k, lab = cs_components(g, directed=False)
    return lab, k


@pytest.mark.parametrize("seed", range(4))
def test_components_equal_csgraph(seed):
    rng = np.random.default_rng(seed)
    for _ in range(60):
        n = int(rng.integers(1, 400))
        e = int(rng.integers(0, 3 * n))
        i, j = rng.integers(0, n, e), rng.integers(0, n, e)
        lab, k = connected_components(n, i, j)
        want, wk = _cs(n, i, j)
        assert k == wk and lab.dtype == np.intp and np.array_equal(lab, want)


def test_components_of_adversarial_graphs():
    rng = np.random.default_rng(11)
    n = 3000
    perm = rng.permutation(n)
    cases = {
        "path in random order": (perm[:-1], perm[1:]),
        "path descending": (np.arange(n - 1, 0, -1), np.arange(n - 2, -1, -1)),
        "star at the largest node": (np.full(n - 1, n - 1), np.arange(n - 1)),
        "zigzag": (np.arange(0, n - 2, 2), np.arange(3, n + 1, 2) % n),
        "self loops and repeats": (np.r_[np.arange(n), 5, 5, 9], np.r_[np.arange(n), 9, 9, 5]),
        "two interleaved paths": (np.arange(0, n - 2), np.arange(2, n)),
        "no edges": (np.zeros(0, dtype=int), np.zeros(0, dtype=int)),
    }
    for name, (i, j) in cases.items():
        lab, k = connected_components(n, i, j)
        want, wk = _cs(n, i, j)
        assert k == wk and np.array_equal(lab, want), name
    assert connected_components(0, [], [])[1] == 0
    with pytest.raises(ValueError):
        connected_components(3, [0], [3])


def test_snapping_callers_agree_with_the_kd_tree_way():
    """snap_map (transitive, lowest index) and snap_points (val3dity's first come) on clusters."""
    from lod2energy.geometry.snap import snap_map, snap_points
    rng = np.random.default_rng(2)
    for _ in range(20):
        c = rng.random((30, 3)) * 10
        p = c[rng.integers(0, 30, 300)] + rng.normal(scale=6e-4, size=(300, 3))
        tol = 1e-3
        pairs = _kd_pairs(p, tol)
        lab, _ = _cs(len(p), pairs[:, 0], pairs[:, 1]) if len(pairs) else (np.arange(len(p)), 0)
        first = np.full(lab.max() + 1, len(p))
        np.minimum.at(first, lab, np.arange(len(p)))
        assert np.array_equal(snap_map(p, tol), first[lab])
        rep = snap_points(p, tol)
        assert (rep <= np.arange(len(p))).all()
        kept = rep == np.arange(len(p))
        for i in np.flatnonzero(~kept):     # merged into the first kept point strictly closer than tol
            d = np.linalg.norm(p[:i] - p[i], axis=1)
            assert rep[i] == np.flatnonzero((d < tol) & kept[:i])[0]


# ----------------------------------------------------------------------------- what validate loads

def _validate_in_process(path: str, report: str, block_scipy: bool) -> dict:
    """Run ``lod2energy validate`` in a fresh interpreter; the scipy modules loaded, and (with
    ``block_scipy``) the lod2energy functions that tried to import scipy."""
    probe = textwrap.dedent(f"""
        import json, sys, traceback
        tried = set()
        class Block:
            def find_spec(self, name, path=None, target=None):
                if {block_scipy!r} and name.split(".")[0] == "scipy":
                    frames = [f for f in traceback.extract_stack() if "lod2energy" in f.filename]
                    tried.add(frames[-1].name if frames else "?")
                    raise ImportError("scipy blocked: " + name)
                return None
        sys.meta_path.insert(0, Block())
        from lod2energy.cli import main
        rc = main(["validate", {path!r}, "-q", "--report", {report!r}])
        print(json.dumps({{"rc": rc, "tried": sorted(tried),
                           "scipy": sorted(m for m in sys.modules if m.split(".")[0] == "scipy")}}))
    """)
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


_CUBE = {"type": "CityJSON", "version": "2.0", "transform": {"scale": [0.001] * 3, "translate": [0.0] * 3},
         "vertices": [[0, 0, 0], [9000, 0, 0], [9000, 9000, 0], [0, 9000, 0],
                      [0, 0, 6000], [9000, 0, 6000], [9000, 9000, 6000], [0, 9000, 6000]],
         "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
         "CityObjects": {"b": {"type": "Building", "geometry": [{"type": "Solid", "lod": "2.2", "boundaries": [[
             [[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]]]]}]}}}


def test_validate_of_a_building_without_a_cdt_loads_no_scipy(tmp_path):
    path = tmp_path / "cube.city.json"
    path.write_text(json.dumps(_CUBE), encoding="utf-8")
    got = _validate_in_process(str(path), str(tmp_path / "r.json"), block_scipy=False)
    assert got["rc"] == 0 and got["scipy"] == [], got


@pytest.mark.parametrize("name", ["tile901_trimmed.city.jsonl", "tile5908_subset_ext.city.jsonl"])
def test_validate_of_a_real_tile_loads_no_scipy(tmp_path, name):
    """Snapping, close pairs and components need no scipy, and the CDTs of the 204 check and of
    the shell meshes come from GEOS (:func:`lod2energy.geometry.constrained_delaunay_many`):
    Qhull is left to the polygons GEOS does not take. With scipy blocked the reports are the same."""
    tile = shared_path("3dbag", name)
    normal = _validate_in_process(str(tile), str(tmp_path / "r.json"), block_scipy=False)
    assert normal["scipy"] == [], normal
    free = _validate_in_process(str(tile), str(tmp_path / "r2.json"), block_scipy=True)
    assert free["tried"] == [] and free["rc"] == normal["rc"], free
    strip = (lambda d: {k: v for k, v in d.items() if k not in ("time", "seconds")})
    a, b = (json.loads((tmp_path / n).read_text(encoding="utf-8")) for n in ("r.json", "r2.json"))
    assert [strip(f) for f in a["features"]] == [strip(f) for f in b["features"]]
