"""The fast paths of the repair ladder's input check give the same answers as the code they replace.

- :func:`lod2energy.repair.validity._candidate_pairs` (one vectorised sweep) against the
  triangle-by-triangle loop it replaces, on random triangle soups;
- :func:`lod2energy.repair.validity.polygon_defects` (edge lengths of all rings at once, the
  exact face area only for the faces that may be slivers) against the face-by-face loop;
- the polygon validator's verdict of a building's shell (:func:`invalid_surfaces`, the one
  ``_input_defects`` reuses) against the verdict on the shell's renumbered mesh
  (:func:`invalid_polygons`), on real buildings.
"""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.config import DEFAULT
from lod2energy.polymesh import Face, PolyMesh, face_area
from lod2energy.repair.cleanup import snap_vertices
from lod2energy.validate import closed as validity
from lod2energy.validate.closed import invalid_polygons, invalid_surfaces
from lod2energy.repair.convert import mesh_of_geometry

from conftest import DATA


def _ref_candidate_pairs(T):
    lo, hi = T.min(axis=1), T.max(axis=1)
    eps = 1e-9
    order = np.argsort(lo[:, 0], kind="stable")
    slo, shi = lo[order], hi[order]
    out = []
    for k in range(len(T)):
        end = np.searchsorted(slo[:, 0], shi[k, 0] + eps, side="right")
        if end <= k + 1:
            continue
        j = np.arange(k + 1, end)
        ok = np.all((slo[j, 1:] <= shi[k, 1:] + eps) & (shi[j, 1:] >= slo[k, 1:] - eps), axis=1)
        j = j[ok]
        if len(j):
            out.append(np.column_stack([np.full(len(j), order[k]), order[j]]))
    if not out:
        return np.zeros((0, 2), dtype=np.int64)
    return np.sort(np.vstack(out), axis=1)


def _ref_polygon_defects(m, tol):
    V = m.vertices
    out = []
    for fi, f in enumerate(m.faces):
        bad = False
        for r in f.rings:
            if len(set(r)) < 3:
                out.append((fi, 101, f"{len(set(r))} distinct points"))
                bad = True
                break
            P = V[list(r)]
            d = np.linalg.norm(P - np.roll(P, -1, axis=0), axis=1)
            if (d <= tol.snap_tol).any():
                out.append((fi, 102, f"points {float(d.min()):.4f} m apart"))
                bad = True
                break
        if bad:
            continue
        a = face_area(V, f)
        if a <= tol.sliver_area:
            out.append((fi, 1003, f"area {a:.2e} m2"))
    if out:
        return out
    for fi, codes in sorted(invalid_polygons(m, tol).items()):
        for c in sorted(codes):
            out.append((fi, c, "polygon validator"))
    return out


@pytest.mark.parametrize("seed", range(6))
def test_candidate_pairs_same_rows(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 400))
    T = rng.uniform(0, 20, size=(n, 3, 3))
    if seed % 2:
        T = np.round(T)  # ties and touching boxes
    if seed == 3:
        T += np.array([85000.0, 447000.0, 0.0])
    ref = _ref_candidate_pairs(T)
    assert len(ref) > 0 or n < 3
    for chunk in (1, 7, 1 << 20):  # the chunks cut the sweep anywhere
        got = validity._candidate_pairs(T, chunk=chunk)
        assert got.dtype == ref.dtype and np.array_equal(got, ref)


def _random_mesh(rng, offset):
    faces, pts = [], []
    for i in range(60):
        k = int(rng.integers(3, 9))
        scale = rng.choice([1e-4, 5e-3, 1e-2, 1.0, 10.0])
        c = rng.uniform(0, 30, size=3)
        p = c + rng.normal(size=(k, 3)) * scale
        if i % 3 == 0:
            p[:, 2] = c[2]  # planar
        base = len(pts)
        pts.extend(p)
        ring = tuple(range(base, base + k))
        if i % 11 == 0:
            ring = ring[:2] + (ring[0],)  # two distinct points
        if i % 13 == 0 and k > 4:
            pts[base + 1] = pts[base] + 1e-4  # points a hair apart
        rings = [ring]
        if i % 7 == 0:  # a small hole
            h = c + rng.normal(size=(4, 3)) * scale * 0.1
            hb = len(pts)
            pts.extend(h)
            rings.append(tuple(range(hb, hb + 4)))
        faces.append(Face(tuple(rings), i, None))
    return PolyMesh(np.asarray(pts) + offset, tuple(faces))


@pytest.mark.parametrize("seed", range(8))
def test_polygon_defects_same_answer(seed):
    rng = np.random.default_rng(seed)
    offset = np.array([85000.0, 447000.0, 2.0]) if seed % 2 else np.zeros(3)
    m = _random_mesh(rng, offset)
    tol = DEFAULT
    ref = _ref_polygon_defects(m, tol)
    assert ref  # the soup has slivers, hairline edges and two-point rings
    assert validity.polygon_defects(m, tol) == ref
    # slivers alone: the only faces whose exact area is taken
    assert any(c == 1003 for _, c, _ in ref)


def test_sliver_candidates_cover_every_sliver():
    rng = np.random.default_rng(11)
    for _ in range(30):
        m = _random_mesh(rng, np.array([85000.0, 447000.0, 2.0]) * rng.integers(0, 2))
        cand = validity._Rings(m.vertices, m.faces).sliver_candidates(DEFAULT.sliver_area)
        for fi, f in enumerate(m.faces):
            if len(set(f.outer)) >= 3 and face_area(m.vertices, f) <= DEFAULT.sliver_area:
                assert cand[fi]


REAL = [("3dbag/tile901_trimmed.city.jsonl", 40), ("denhaag/DenHaag_01.city.json", 60)]


@pytest.mark.parametrize("rel,n", REAL, ids=[r[0].split("/")[-1] for r in REAL])
def test_real_shells_same_verdicts(rel, n):
    """On real shells: the polygon verdict of the building's shell is the one of its mesh, and
    shell_defects with it (and the fast polygon checks) answers as the reference path."""
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    tol = DEFAULT
    seen = 0
    import itertools

    from lod2energy.io import read
    from lod2energy.model import Building
    _, it = read(str(DATA / rel))
    for b in itertools.islice((x for x in it if isinstance(x, Building)), n):
        for o in b.objects:
            for g in o.geometries:
                if not g.is_polygonal or len(g.solids) != 1 or len(g.solids[0].shells) != 1:
                    continue
                m = mesh_of_geometry(b.vertices, g)
                if snap_vertices(m, tol.snap_tol) is not m or not m.faces:
                    continue
                shell = g.solids[0].shells[0]
                assert dict(invalid_surfaces(b.vertices, shell, tol)) == dict(invalid_polygons(m, tol))
                fast = validity.shell_defects([m], tol, invalid=[invalid_surfaces(b.vertices, shell, tol)])[0]
                slow_poly = _ref_polygon_defects(m, tol)
                assert validity.polygon_defects(m, tol) == slow_poly
                if not slow_poly:
                    assert fast == validity.shell_defects([m], tol)[0]
                seen += 1
    assert seen > 10 or "3dbag" in rel  # 3DBAG shells repeat vertices: snapping changes them


def test_known_overlaps_same_pairs():
    """The 601 locations the validator found on a building (no other defect) give the pairs
    overlap_pairs finds by itself, on real multi-part buildings."""
    rel = "denhaag/DenHaag_01.city.json"
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    import itertools

    from lod2energy.io import read
    from lod2energy.model import Building
    from lod2energy.repair.parts import clip_overlapping_parts, overlap_pairs
    from lod2energy.validate.checks import validate_building
    _, it = read(str(DATA / rel))
    with_pairs = 0
    for b in itertools.islice((x for x in it if isinstance(x, Building)), 80):
        before = validate_building(b, DEFAULT)
        if not all(d.code == 601 for d in before):
            continue
        known = [d.location for d in before]
        ref = overlap_pairs(b, DEFAULT)
        assert overlap_pairs(b, DEFAULT, known) == ref
        with_pairs += bool(ref)
        if ref:
            nb, rec = clip_overlapping_parts(b, DEFAULT, overlaps=known)
            nb0, rec0 = clip_overlapping_parts(b, DEFAULT)
            assert rec == rec0 and (nb is b) == (nb0 is b)
    assert with_pairs > 0


def _reference_self_intersections(V, tris, owner):
    """The one-shell test as it was before the batch (one triangle_pairs_intersect call)."""
    from lod2energy.geometry import triangle_pairs_intersect
    if len(tris) < 2:
        return np.zeros((0, 2), dtype=np.int64)
    origin = V[tris[0, 0]]
    pairs = validity._candidate_pairs(V[tris] - origin)
    if len(pairs) == 0:
        return pairs
    pairs = pairs[owner[pairs[:, 0]] != owner[pairs[:, 1]]]
    if len(pairs) == 0:
        return pairs
    return pairs[triangle_pairs_intersect(V - origin, tris, pairs)]


@pytest.mark.parametrize("seed", range(4))
def test_self_intersections_batch_same_pairs(seed):
    """Shells tested together find, shell by shell, the pairs each finds alone."""
    rng = np.random.default_rng(seed)
    items = []
    for k in range(7):
        n = int(rng.integers(1, 60))
        V = rng.uniform(0, 5, size=(n + 3, 3))
        if k % 2:
            V = np.round(V, 1) + np.array([85000.0, 447000.0, 0.0])  # touching, coplanar, far away
        tris = rng.integers(0, len(V), size=(n, 3))
        owner = rng.integers(0, max(1, n // 2), size=n)
        items.append((V, tris, owner))
    got = validity.self_intersections(items)
    hits = 0
    for (V, tris, owner), g in zip(items, got):
        ref = _reference_self_intersections(V, tris, owner)
        assert g.dtype == ref.dtype and np.array_equal(g, ref)
        assert np.array_equal(validity.self_intersections([(V, tris, owner)])[0], ref)
        hits += len(ref)
    assert hits > 0


@pytest.mark.parametrize("rel,n", REAL, ids=[r[0].split("/")[-1] for r in REAL])
def test_real_shells_batch_same_defects(rel, n):
    """shell_defects of a building's shells together (valid and broken, as the ladder gets them)
    answers as shell by shell."""
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    import itertools

    from lod2energy.io import read
    from lod2energy.model import Building
    tol = DEFAULT
    _, it = read(str(DATA / rel))
    some_306 = False
    for b in itertools.islice((x for x in it if isinstance(x, Building)), n):
        shells = [snap_vertices(mesh_of_geometry(b.vertices, g), tol.snap_tol)
                  for o in b.objects for g in o.geometries if g.is_polygonal and g.solids]
        if not shells:
            continue
        got = validity.shell_defects(shells, tol)
        ref = [validity.shell_defects([m], tol)[0] for m in shells]
        assert got == ref
        some_306 |= any(c == 306 for r in ref for _, c, _ in r)


@pytest.mark.parametrize("seed", range(4))
def test_shell_verdict_is_the_renumbered_mesh_verdict(seed):
    """The polygon validator answers alike on a building's shell and on its mesh (the shell's
    vertices only, renumbered in order): what _input_defects relies on to reuse the verdict."""
    from lod2energy.model import Geometry, Shell, Solid, Surface
    rng = np.random.default_rng(seed)
    m = _random_mesh(rng, np.array([85000.0, 447000.0, 2.0]) if seed % 2 else np.zeros(3))
    # the building's array: the mesh's points among unused ones
    n = len(m.vertices)
    pos = np.sort(rng.choice(3 * n, size=n, replace=False))
    V = rng.uniform(-50, 50, size=(3 * n, 3))
    V[pos] = m.vertices
    shell = Shell(tuple(Surface.from_lists([[int(pos[i]) for i in r] for r in f.rings]) for f in m.faces))
    g = Geometry("Solid", "2", (Solid((shell,)),))
    mesh = mesh_of_geometry(V, g)
    found = dict(invalid_polygons(mesh, DEFAULT))
    assert found  # non-planar and degenerate faces among them
    assert dict(invalid_surfaces(V, shell, DEFAULT)) == found
