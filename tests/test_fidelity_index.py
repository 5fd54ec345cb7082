"""The fidelity metrics' spatial index gives every value of measuring every pair, bit for bit."""
from __future__ import annotations

import numpy as np
import pytest
from conftest import shared_path
from factories import box, gabled_house, open_box, stepped_tower

from lod2energy.repair import metrics
from lod2energy.repair.metrics import _indexed_sqdist, closed_mesh, _sqdist, fidelity, point_triangle_distance
from lod2energy.repair.pipeline import mesh_of_geometry


def reference_distance(P, V, tris, chunk=256):
    """point_triangle_distance as it was before the index: every point against every triangle."""
    A, B, C = V[tris[:, 0]], V[tris[:, 1]], V[tris[:, 2]]
    out = np.empty(len(P))
    chunk = max(1, min(chunk, 200000 // max(len(tris), 1)))
    for s in range(0, len(P), chunk):
        p = P[s:s + chunk, None, :]
        out[s:s + chunk] = np.sqrt(_sqdist(p, A[None], B[None], C[None]).min(axis=1))
    return out


def same_bits(a, b) -> bool:
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def probes(V, rng, n=300):
    """Vertices, points near the surface and points around the mesh: (k, 3) float."""
    lo, hi = V.min(axis=0), V.max(axis=0)
    return np.vstack([V, V + rng.normal(scale=0.05, size=V.shape),
                      lo + (hi - lo) * rng.uniform(-0.5, 1.5, size=(n, 3))])


def indexed(P, V, tris):
    """The indexed path alone (whatever the size), as distances."""
    d2 = _indexed_sqdist(P, V[tris[:, 0]], V[tris[:, 1]], V[tris[:, 2]])
    assert d2 is not None
    return np.sqrt(d2)


NAMED = {"box": box, "gabled": gabled_house, "open_box": open_box, "stepped_tower": stepped_tower}


@pytest.mark.parametrize("name", sorted(NAMED))
@pytest.mark.parametrize("offset", [0.0, 445000.0])
def test_named_geometries_bit_identical(name, offset):
    b = NAMED[name]()
    m = mesh_of_geometry(b.vertices + offset, b.root.geometries[0])
    V, tris = closed_mesh(m)
    P = probes(V, np.random.default_rng(1))
    ref = reference_distance(P, V, tris)
    assert same_bits(indexed(P, V, tris), ref)
    assert same_bits(point_triangle_distance(P, V, tris), ref)
    assert ref[:len(V)].max() == 0.0  # the mesh's own vertices lie on it


def random_soup(rng, slivers: bool, offset: float):
    n, t = int(rng.integers(10, 300)), int(rng.integers(5, 500))
    V = rng.normal(size=(n, 3)) * rng.choice([0.5, 10.0, 80.0]) + offset
    if slivers:  # a third of the vertices nearly on one line: slivers and needles
        k = n // 3
        V[:k] = V[0] + np.outer(rng.random(k), V[1] - V[0]) + rng.normal(scale=1e-9, size=(k, 3))
    tris = rng.integers(0, n, size=(t, 3))
    tris[: t // 10, 1] = tris[: t // 10, 0]  # degenerate: a repeated corner
    return V, tris


@pytest.mark.parametrize("seed", range(12))
def test_random_triangle_soups_bit_identical(seed):
    rng = np.random.default_rng(seed)
    V, tris = random_soup(rng, slivers=seed % 2 == 0, offset=[0.0, 85000.0, -3.0][seed % 3])
    P = probes(V, rng)
    ref = reference_distance(P, V, tris)
    assert same_bits(indexed(P, V, tris), ref)
    assert same_bits(point_triangle_distance(P, V, tris), ref)


def test_index_prunes_on_a_fine_mesh():
    """A fine grid of triangles: each point is measured against few of them, same result."""
    g = np.linspace(0, 50, 26)
    X, Y = np.meshgrid(g, g, indexing="ij")
    V = np.column_stack([X.ravel(), Y.ravel(), np.sin(X.ravel() / 7) * 3])
    i = np.arange(25)[:, None] * 26 + np.arange(25)[None]
    q = np.column_stack([i.ravel(), i.ravel() + 26, i.ravel() + 1, i.ravel() + 27])
    tris = np.vstack([q[:, [0, 1, 2]], q[:, [2, 1, 3]]])
    P = probes(V, np.random.default_rng(3), n=500)
    seen = []
    orig = metrics._pairs_sqdist

    def count(P_, A, B, C, pi, ti):
        seen.append(len(pi))
        return orig(P_, A, B, C, pi, ti)
    metrics._pairs_sqdist = count
    try:
        got = indexed(P, V, tris)
    finally:
        metrics._pairs_sqdist = orig
    assert same_bits(got, reference_distance(P, V, tris))
    assert sum(seen) < 0.05 * len(P) * len(tris)


def test_non_finite_input_falls_back_to_every_pair():
    b = box()
    m = mesh_of_geometry(b.vertices, b.root.geometries[0])
    V, tris = closed_mesh(m)
    P = probes(V, np.random.default_rng(2), n=5000)
    P[7] = np.nan
    assert _indexed_sqdist(P, V[tris[:, 0]], V[tris[:, 1]], V[tris[:, 2]]) is None
    ref = reference_distance(P, V, tris)
    assert np.isnan(ref[7])
    assert same_bits(point_triangle_distance(P, V, tris), ref)


def _fidelity_both(monkeypatch, *args):
    new = fidelity(*args)
    with monkeypatch.context() as mp:
        mp.setattr(metrics, "point_triangle_distance", reference_distance)
        old = fidelity(*args)
    return new, old


def test_fidelity_values_unchanged_on_named_repairs(monkeypatch):
    a = mesh_of_geometry(gabled_house().vertices, gabled_house().root.geometries[0])
    b = mesh_of_geometry(box(dz=7.0).vertices, box(dz=7.0).root.geometries[0])
    o = mesh_of_geometry(open_box().vertices, open_box().root.geometries[0])
    for args in [(a, b, True), (b, a, True), (o, b, False)]:
        new, old = _fidelity_both(monkeypatch, *args)
        assert new.keys() == old.keys()
        assert all(np.asarray(new[k]).tobytes() == np.asarray(old[k]).tobytes() for k in new), (new, old)
        assert new["hausdorff"] > 0


def test_real_tile_meshes_bit_identical():
    from lod2energy.io import read
    from lod2energy.model import Building

    _, it = read(str(shared_path("3dbag", "tile901_trimmed.city.jsonl")))
    rng = np.random.default_rng(4)
    n = 0
    for b in it:
        if not isinstance(b, Building):
            continue
        for g in (g for o in b.objects for g in o.geometries if g.is_polygonal):
            V, tris = closed_mesh(mesh_of_geometry(b.vertices, g))
            if len(tris) < 20:
                continue
            P = probes(V[np.unique(tris)], rng, n=200)
            ref = reference_distance(P, V, tris)
            assert same_bits(indexed(P, V, tris), ref), b.id
            n += 1
        if n >= 15:
            break
    assert n >= 5


def test_float32_input_measured_as_before():
    rng = np.random.default_rng(5)
    V, tris = random_soup(rng, slivers=False, offset=0.0)
    V = V.astype(np.float32)
    P = probes(V, rng).astype(np.float32)
    ref = reference_distance(P, V, tris)
    assert P.dtype == V.dtype == np.float32  # computed in float32 by every pair, as before
    assert same_bits(point_triangle_distance(P, V, tris), ref)


def reference_winding_number(Q, V, tris, chunk=2048):
    """metrics.winding_number as it was before it went per coordinate: (points, triangles, 3) blocks."""
    A, B, C = V[tris[:, 0]], V[tris[:, 1]], V[tris[:, 2]]
    out = np.zeros(len(Q))
    chunk = max(1, min(chunk, 200000 // max(len(tris), 1)))
    for s in range(0, len(Q), chunk):
        q = Q[s:s + chunk, None, :]
        a, b, c = A[None] - q, B[None] - q, C[None] - q
        la, lb, lc = (np.linalg.norm(x, axis=2) for x in (a, b, c))
        det = np.einsum("ijk,ijk->ij", a, np.cross(b, c))
        den = la * lb * lc + np.einsum("ijk,ijk->ij", a, b) * lc + \
            np.einsum("ijk,ijk->ij", b, c) * la + np.einsum("ijk,ijk->ij", c, a) * lb
        out[s:s + chunk] = np.arctan2(det, den).sum(axis=1) / (2 * np.pi)
    return out


def scalar_winding_number(q, V, tris) -> float:
    """The generalised winding number of one point (Jacobson et al. 2013, eq. 6), triangle by triangle."""
    total = 0.0
    for t in tris:
        a, b, c = (V[k] - q for k in t)
        la, lb, lc = (float(np.sqrt(x @ x)) for x in (a, b, c))
        det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) \
            + a[2] * (b[0] * c[1] - b[1] * c[0])
        den = la * lb * lc + (a @ b) * lc + (b @ c) * la + (c @ a) * lb
        total += np.arctan2(det, den)
    return total / (2 * np.pi)


def soup(rng, n_tris=40):
    """Random triangles (an open, self-crossing soup) far from the origin, as map coordinates are."""
    V = rng.normal(scale=8.0, size=(3 * n_tris, 3)) + [85000.0, 446000.0, 10.0]
    return V, rng.permutation(len(V)).reshape(-1, 3)


@pytest.mark.parametrize("make", [box, gabled_house, open_box, stepped_tower, soup],
                         ids=["box", "gabled", "open_box", "tower", "soup"])
def test_winding_number_is_the_scalar_formula_and_the_former_sums(make):
    rng = np.random.default_rng(7)
    if make is soup:
        V, tris = soup(rng)
    else:
        b = make()
        V, tris = closed_mesh(mesh_of_geometry(b.vertices, b.objects[0].geometries[0]))
    Q = probes(V[np.unique(tris)], rng)
    w = metrics.winding_number(Q, V, tris)
    # the same sums as before: bit for bit where numpy's einsum adds x, z, then y (measured on the
    # machine that made the change); other CPUs may add in another order, so 1e-12 here
    assert np.allclose(w, reference_winding_number(Q, V, tris), rtol=0, atol=1e-12)
    assert same_bits(metrics.winding_number(Q, V, tris, chunk=7), w)   # whatever the blocks
    scalar = np.array([scalar_winding_number(q, V, tris) for q in Q[::7]])
    assert np.allclose(w[::7], scalar, rtol=0, atol=1e-9)


def test_winding_number_tells_inside_from_outside():
    b = box(10, 8, 6)
    V, tris = closed_mesh(mesh_of_geometry(b.vertices, b.objects[0].geometries[0]))
    w = metrics.winding_number(np.array([[5.0, 4.0, 3.0], [15.0, 4.0, 3.0], [5.0, 4.0, -1.0]]), V, tris)
    assert np.allclose(w, [1.0, 0.0, 0.0], atol=1e-12)
    assert len(metrics.winding_number(np.zeros((0, 3)), V, tris)) == 0
    assert np.array_equal(metrics.winding_number(np.ones((2, 3)), V, tris[:0]), np.zeros(2))
