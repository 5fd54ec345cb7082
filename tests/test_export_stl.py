"""STL export: closed outward surfaces, per-class patches, local frame, union of parts."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from export_helpers import DATA, energy_ready, l_shaped, parts_building, real_buildings, shifted, two_part_building
from factories import box, box_polygons, gabled_house

from lod2energy.errors import ParameterError
from lod2energy.exporters.stl import writer as stl


@pytest.mark.parametrize("ascii_", [True, False], ids=["ascii", "binary"])
@pytest.mark.parametrize("make", [box, gabled_house, l_shaped], ids=lambda f: f.__name__)
def test_canonical_buildings_closed_outward(tmp_path, make, ascii_):
    b = energy_ready(make())
    res = stl.write([b], tmp_path, stl.StlOptions(ascii=ascii_))
    assert len(res) == 1 and res[0].ok, res[0].problems
    tris, codes, names = stl.read_stl(res[0].path)
    mesh = trimesh.Trimesh(tris.reshape(-1, 3), np.arange(len(tris) * 3).reshape(-1, 3))
    assert mesh.is_watertight and mesh.is_winding_consistent
    ref = trimesh.Trimesh(*_zone_mesh_of(b))
    assert mesh.volume == pytest.approx(abs(ref.volume), rel=1e-6) and mesh.volume > 0


def _zone_mesh_of(b):
    from lod2energy.energy.zones.shells import local_origin, zone_shells
    z = zone_shells(b, local_origin([b]))[0]
    t, _ = z.triangles()
    return z.vertices, t


def test_ascii_has_one_named_solid_per_class(tmp_path):
    res = stl.write([energy_ready(gabled_house())], tmp_path, stl.StlOptions(ascii=True))
    text = Path(res[0].path).read_text()
    solids = [ln.split()[1] for ln in text.splitlines() if ln.startswith("solid ")]
    assert solids == ["roof", "wall", "ground"]
    _, codes, names = stl.read_stl(res[0].path)
    counts = {names[c]: int((codes == c).sum()) for c in set(codes.tolist())}
    assert counts == {"roof": 4, "wall": 10, "ground": 2}  # quads: 2 triangles, pentagons: 3


def test_binary_patch_attribute_and_sidecar(tmp_path):
    b = energy_ready(shifted(box(10, 8, 6), (85123.4, 446789.6, 2.5)))
    res = stl.write([b], tmp_path)
    side = json.loads(Path(res[0].path).with_suffix(".stl.json").read_text())
    assert side["patches"] == {"roof": 2, "wall": 8, "ground": 2}
    assert side["offset"] == list(res[0].offset)
    tris, codes, names = stl.read_stl(res[0].path)
    assert np.abs(tris).max() < 100
    assert np.allclose(tris.reshape(-1, 3).min(axis=0) + np.asarray(side["offset"]), b.vertices.min(axis=0),
                       atol=1e-3)
    roof = tris[codes == stl.PATCHES.index("roof")]
    assert np.allclose(roof[:, :, 2] + side["offset"][2], b.vertices[:, 2].max(), atol=1e-3)


def test_parts_are_merged_without_internal_walls(tmp_path):
    b = energy_ready(two_part_building())
    res = stl.write([b], tmp_path)
    assert res[0].ok, res[0].problems
    tris, codes, _ = stl.read_stl(res[0].path)
    mesh = trimesh.Trimesh(tris.reshape(-1, 3), np.arange(len(tris) * 3).reshape(-1, 3))
    assert mesh.is_watertight and mesh.volume == pytest.approx(10 * 8 * 6 + 6 * 8 * 9, rel=1e-4)
    # no triangle lies inside the shared 36 m2 rectangle at x = 10, 2 < y < 8, 0 < z < 6
    c = tris.mean(axis=1)
    inside = (np.abs(c[:, 0] - 10) < 1e-6) & (c[:, 1] > 2) & (c[:, 1] < 8) & (c[:, 2] < 6)
    assert not inside.any()


def test_unmerged_parts_keep_two_bodies(tmp_path):
    b = energy_ready(two_part_building())
    res = stl.write([b], tmp_path, stl.StlOptions(union=False))
    tris, _, _ = stl.read_stl(res[0].path)
    assert len(tris) == 24  # two boxes of 12 triangles


def test_parts_touching_along_an_edge_stay_manifold(tmp_path):
    # two boxes meeting only along the vertical edge x = 10, y = 8
    b = energy_ready(parts_building([box_polygons(10, 8, 6), box_polygons(5, 5, 6, (10, 8, 0))], "edge"))
    res = stl.write([b], tmp_path)
    assert res[0].ok, res[0].problems


def test_dataset_mode_merges_touching_buildings(tmp_path):
    bs = [energy_ready(box(10, 8, 6, id="l")), energy_ready(box(10, 8, 6, origin=(10, 0, 0), id="r")),
          energy_ready(box(4, 4, 4, origin=(40, 0, 0), id="far"))]
    res = stl.write(bs, tmp_path, stl.StlOptions(mode="dataset"))
    assert len(res) == 1 and res[0].ok, res[0].problems
    tris, _, _ = stl.read_stl(res[0].path)
    mesh = trimesh.Trimesh(tris.reshape(-1, 3), np.arange(len(tris) * 3).reshape(-1, 3))
    assert len(mesh.split(only_watertight=True)) == 2
    assert mesh.volume == pytest.approx(2 * 480 + 64, rel=1e-6)


@pytest.mark.parametrize("evil", ["../../x", "a/b\\c", "con", "..", "x" * 300])
def test_file_names_stay_in_outdir(tmp_path, evil):
    out = tmp_path / "out"
    res = stl.write([energy_ready(box(id=evil))], out)
    p = Path(res[0].path)
    assert p.parent == out.resolve() and p.with_suffix(".stl.json").parent == out.resolve()
    assert sorted(x.name for x in tmp_path.iterdir()) == ["out"]
    assert json.loads(p.with_suffix(".stl.json").read_text())["building_ids"] == [evil]


def test_self_check_catches_open_and_inverted(tmp_path):
    res = stl.write([energy_ready(box())], tmp_path, stl.StlOptions(ascii=True))
    text = Path(res[0].path).read_text()
    first = text.index("  facet")
    second = text.index("  facet", first + 1)
    opened = tmp_path / "open.stl"
    opened.write_text(text[:first] + text[second:])
    assert any(p.startswith("not closed") for p in stl.self_check(opened))
    tris, codes, _ = stl.read_stl(res[0].path)
    flipped = tmp_path / "flipped.stl"
    stl.write_binary(flipped, tris[:, ::-1].reshape(-1, 3), np.arange(len(tris) * 3).reshape(-1, 3), codes)
    assert any("not outward" in p for p in stl.self_check(flipped))


def test_bad_mode(tmp_path):
    with pytest.raises(ParameterError):
        stl.write([energy_ready(box())], tmp_path, stl.StlOptions(mode="tile"))


REAL = [("3dbag/3dbag_b2.city.json", False, 2), ("denhaag/DenHaag_01.city.json", True, 12),
        ("rotterdam/Example_CityGML_Converted_Rotterdam.json", False, 10), ("3dbag/tile901_trimmed.city.jsonl", False, 10)]


@pytest.mark.parametrize("rel,multipart,n", REAL, ids=[r[0].split("/")[0] + str(i) for i, r in enumerate(REAL)])
def test_real_buildings_closed(tmp_path, rel, multipart, n):
    if not (DATA / rel).exists():
        pytest.skip(f"shared data not available: {rel}")
    bs = real_buildings(rel, n=n, multipart=multipart)
    res = stl.write(bs, tmp_path)
    assert len(res) == len(bs)
    assert [(r.building_ids, r.problems) for r in res if not r.ok] == []


# --- issue 5: what surfaceCheck sees (float32 corners merged only when equal) ----------------

def bipyramid_over_sliver(gap: float = 1e-4) -> tuple[np.ndarray, np.ndarray]:
    """Two pyramids on a sliver triangle a-b-c whose edge a-b is ``gap`` (m) long.

    The cycle a-b-c is not a face (the link condition fails on a-b): collapsing a-b merges
    the edges a-c and b-c into one used by four triangles (a pinch).
    """
    v = np.array([[0, 0, 0], [gap, 0, 0], [10, 5, 0], [3, 2, 6], [3, 2, -6]], float)
    a, b, c, p, q = range(5)
    t = np.array([[p, a, b], [p, b, c], [p, c, a], [q, b, a], [q, c, b], [q, a, c]])
    return v, t


def _closed_by_index(t: np.ndarray) -> bool:
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    _, n = np.unique(np.sort(e, axis=1), axis=0, return_counts=True)
    _, nd = np.unique(e, axis=0, return_counts=True)
    return len(t) > 0 and bool((n == 2).all() and (nd == 1).all())


def test_collapse_short_edges_does_not_pinch():
    v, t = bipyramid_over_sliver()
    vol = trimesh.Trimesh(v, t, process=False).volume
    v2, t2, c2 = stl.collapse_short_edges(v, t, np.arange(len(t)), 1e-3)
    assert _closed_by_index(t2)
    assert trimesh.Trimesh(v2, t2, process=False).volume == pytest.approx(vol, rel=1e-9)
    assert len(c2) == len(t2)


def test_collapse_short_edges_removes_a_micro_edge():
    # a box whose top front edge carries an extra vertex 10 um from a corner
    m = trimesh.creation.box((10, 8, 6))
    v, t = m.vertices.copy(), m.faces.copy()
    corner = int(np.argmax(v @ np.array([1e3, 1e-3, 1.0])))  # (5, -4, 3)-ish corner
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    a, b = next((int(x), int(y)) for x, y in e if x == corner)
    p = v[a] + (v[b] - v[a]) / np.linalg.norm(v[b] - v[a]) * 1e-5
    v = np.vstack([v, p])
    k = len(v) - 1
    out = []
    for tri in t.tolist():  # split both triangles on edge a-b at the new vertex
        s = set(tri)
        if {a, b} <= s:
            i = tri.index(a)
            j = tri.index(b)
            t1, t2_ = list(tri), list(tri)
            t1[j] = k
            t2_[i] = k
            out += [t1, t2_]
        else:
            out.append(tri)
    t = np.array(out)
    assert _closed_by_index(t)
    v2, t2, _ = stl.collapse_short_edges(v, t, np.zeros(len(t), int), 1e-3)
    assert len(v2) == 8 and _closed_by_index(t2)
    assert trimesh.Trimesh(v2, t2, process=False).volume == pytest.approx(480, rel=1e-6)


def gap_stl(path: Path, gap: float = 3e-6) -> Path:
    """Box STL with one triangle corner moved ``gap`` (m): an open surface that 5-digit
    rounding would close."""
    tris = trimesh.creation.box((10, 8, 6)).triangles + 5.0  # corners at 0 and 10, 8, 6
    tris[0, 0, 0] += gap
    stl.write_binary(path, tris.reshape(-1, 3), np.arange(len(tris) * 3).reshape(-1, 3),
                     np.zeros(len(tris), dtype=np.intp))
    return path


def float32_pinch_stl(path: Path, d: float = 1e-7) -> Path:
    """Box STL whose top face has a vertex ``d`` (m) from a corner (distinct in float64, one
    point in float32): a triangle with two equal corners once read."""
    m = trimesh.creation.box((10, 8, 6))
    v = m.vertices + 50.0
    t = m.faces
    top = [i for i in range(len(t)) if np.allclose(v[t[i]][:, 2], v[:, 2].max())][0]
    a, b, c = t[top]
    p = v[a] + (v[b] - v[a]) * d / np.linalg.norm(v[b] - v[a])
    assert np.any(p != v[a]) and np.all(p.astype(np.float32) == v[a].astype(np.float32))
    v = np.vstack([v, p])
    k = len(v) - 1
    t = np.vstack([np.delete(t, top, axis=0), [[a, k, c], [k, b, c]]])
    stl.write_binary(path, v, t, np.zeros(len(t), dtype=np.intp))
    return path


def test_self_check_merges_points_exactly_like_surface_check(tmp_path):
    probs = stl.self_check(gap_stl(tmp_path / "gap.stl"))
    assert any(p.startswith("not closed") for p in probs), probs
    probs = stl.self_check(float32_pinch_stl(tmp_path / "pinch.stl"))
    assert any("coincident corners" in p for p in probs), probs
    assert stl.self_check(gap_stl(tmp_path / "nogap.stl", gap=0.0)) == []


def test_separate_touching_sees_float32_coincidence():
    # two tetrahedra touching at a point; the copies are 3 um apart (more than 1e-6 m, but one
    # float32 value at x = 100 m)
    tet = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    t = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    v = np.vstack([tet + [99.0, 0, 0], -tet + [100.0 + 3e-6, 1, 1]])
    v[1] = [100.0, 0, 0]
    v[4] = [100.0 + 3e-6, 0, 0]
    assert np.all(v[1].astype(np.float32) == v[4].astype(np.float32))
    v2, moved = stl.separate_touching(v, np.vstack([t, t[:, ::-1] + 4]))
    assert moved == 2
    assert np.linalg.norm(v2[1].astype(np.float32) - v2[4].astype(np.float32)) > 1e-3


def test_flip_caps_removes_a_collinear_cap_and_keeps_the_surface_closed():
    # a tetrahedron whose side face (0, 1, 3) is split at 4, the midpoint of edge 0-1; the
    # bottom is triangulated as (0, 2, 1) plus the zero-area cap (0, 1, 4)
    v = np.array([[0, 0, 0], [2, 0, 0], [1, 2, 0], [1, 1, 2], [1, 0, 0]], dtype=float)
    capped = np.array([[0, 2, 1], [0, 1, 4], [0, 4, 3], [4, 1, 3], [1, 2, 3], [2, 0, 3]])
    tm = trimesh.Trimesh(v, capped, process=False)
    assert tm.is_watertight and tm.is_winding_consistent and (tm.area_faces < 1e-12).sum() == 1
    t2, c2 = stl.flip_caps(v, capped, np.arange(len(capped)))
    tm2 = trimesh.Trimesh(v, t2, process=False)
    assert tm2.is_watertight and tm2.is_winding_consistent
    assert (tm2.area_faces < 1e-12).sum() == 0
    assert tm2.volume == pytest.approx(tm.volume) and tm2.volume > 0
    assert 1 not in c2.tolist()  # the cap is gone: both new triangles take the neighbour's value


def test_flip_caps_leaves_a_cap_next_to_a_degenerate_neighbour():
    v = np.array([[0, 0, 0], [2, 0, 0], [1, 0, 0]], dtype=float)
    t = np.array([[0, 1, 2], [1, 0, 1]])  # the neighbour across 0-1 has no third vertex
    t2, _ = stl.flip_caps(v, t, np.zeros(2, dtype=int))  # used to raise StopIteration
    assert t2.shape == t.shape


def fanned_box_with_collinear_runs(points_per_edge: int, rng) -> tuple[np.ndarray, np.ndarray]:
    """A unit cube whose 12 edges each carry ``points_per_edge`` extra points (shared by the two
    faces of the edge), every face fan-triangulated from a random ring vertex: many caps."""
    corners = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    verts, runs, tris = list(corners), {}, []
    for f in ([0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]):
        ring = []
        for a, b in zip(f, f[1:] + f[:1]):
            if (b, a) not in runs:
                runs[(a, b)] = list(range(len(verts), len(verts) + points_per_edge))
                verts += [corners[a] + s * (corners[b] - corners[a])
                          for s in np.sort(rng.uniform(0.05, 0.95, points_per_edge))]
            ring += [a] + (runs[(a, b)] if (a, b) in runs else runs[(b, a)][::-1])
        k = int(rng.integers(len(ring)))
        ring = ring[k:] + ring[:k]
        tris += [(ring[0], ring[j], ring[j + 1]) for j in range(1, len(ring) - 1)]
    return np.array(verts), np.array(tris)


def test_flip_caps_removes_hundreds_of_caps_and_keeps_the_box():
    rng = np.random.default_rng(5)
    v, t = fanned_box_with_collinear_runs(40, rng)
    t = t[rng.permutation(len(t))]
    before, _ = stl._caps(v, t)
    assert before.sum() > 200
    t2, c2 = stl.flip_caps(v, t, np.arange(len(t)))
    def balance(tt):  # per undirected edge: uses one way minus the other (0 everywhere: closed)
        e = np.concatenate([tt[:, [0, 1]], tt[:, [1, 2]], tt[:, [2, 0]]])
        key, sign = np.sort(e, axis=1), np.where(e[:, 0] < e[:, 1], 1, -1)
        _, inv = np.unique(key, axis=0, return_inverse=True)
        return np.bincount(inv.ravel(), weights=sign)
    assert not balance(t).any() and not balance(t2).any()
    assert stl.signed_volume(v, t2) == pytest.approx(1.0)
    after, _ = stl._caps(v, t2)
    assert after.sum() < before.sum()          # those left lie against another cap's chord
    tr, cr = reference_flip_caps(v, t, np.arange(len(t)))
    assert np.array_equal(t2, tr) and np.array_equal(c2, cr)   # the flips of before (len(t) at most)


def reference_flip_caps(v, t, c):
    """flip_caps as it was before its edge index: every cap looked at again after each flip."""
    t, c = np.array(t, dtype=np.intp).reshape(-1, 3), np.array(c)
    for _ in range(len(t)):
        is_cap, L2 = stl._caps(v, t)
        for k in np.nonzero(is_cap)[0]:
            i = int(np.argmax(L2[k]))
            a, b, cc = t[k, i], t[k, (i + 1) % 3], t[k, (i + 2) % 3]
            hit = [h for h in np.nonzero(((t[:, 0] == b) & (t[:, 1] == a)) | ((t[:, 1] == b) & (t[:, 2] == a))
                                         | ((t[:, 2] == b) & (t[:, 0] == a)))[0] if h != k]
            rest = [int(x) for x in t[hit[0]] if x not in (a, b)] if len(hit) == 1 else []
            if rest and rest[0] != cc:
                h, d = hit[0], rest[0]
                t[k], t[h], c[k] = (b, cc, d), (cc, a, d), c[h]
                break
        else:
            break
    return t, c


@pytest.mark.parametrize("seed", range(6))
def test_flip_caps_makes_the_same_flips_in_the_same_order_as_before(seed):
    rng = np.random.default_rng(seed)
    v, t = fanned_box_with_collinear_runs(int(rng.integers(1, 12)), rng)
    t = t[rng.permutation(len(t))]
    c = rng.integers(0, 4, len(t))
    t2, c2 = stl.flip_caps(v, t, c)
    tr, cr = reference_flip_caps(v, t, c)
    assert np.array_equal(t2, tr) and np.array_equal(c2, cr) and not np.array_equal(t2, t)


def test_one_failing_building_does_not_stop_the_batch(tmp_path, monkeypatch):
    good, bad = energy_ready(box()), energy_ready(shifted(box(), (30.0, 0.0, 0.0)))
    bad = type(bad)(bad.id + "_bad", bad.type, bad.vertices, bad.objects, bad.provenance)
    real = stl._zone_mesh

    def boom(z):
        if z.building_id.endswith("_bad"):
            raise ValueError("synthetic failure")
        return real(z)
    monkeypatch.setattr(stl, "_zone_mesh", boom)
    res = stl.write([bad, good], tmp_path)
    by = {r.building_ids[0]: r for r in res}
    assert not by[bad.id].ok and "synthetic failure" in by[bad.id].problems[0]
    assert by[good.id].ok and Path(by[good.id].path).exists()


def test_caps_of_two_faces_on_one_chord_are_flipped_face_by_face(monkeypatch):
    # The ground and the front wall share the run A-P-Q-B, whose inner points lie 50 nm off
    # the line (Berlin LoD2 ground outlines). Both faces triangulate into caps fanned onto
    # the chord A-B, which so carries four triangles: a non-manifold STL, and no single
    # neighbour across A-B to flip a cap into. Flipped face by face, it closes.
    from lod2energy.energy.zones.shells import ZoneFace, ZoneShell
    e = 5e-8
    v = np.array([[0, 0, 0], [6, -e, 0], [13, -e, 0], [20, 0, 0], [20, 10, 0], [0, 10, 0],
                  [0, 0, 6], [20, 0, 6], [20, 10, 6], [0, 10, 6]], dtype=float)
    A, P, Q, B, C, D, A2, B2, C2, D2 = range(10)
    faces = {  # hand-made triangulations, each face wound outward
        "ground": [(A, D, C), (A, C, B), (A, B, Q), (A, Q, P)],
        "front": [(A, P, Q), (A, Q, B), (A, B, B2), (A, B2, A2)],
        "back": [(C, D, D2), (C, D2, C2)], "left": [(D, A, A2), (D, A2, D2)],
        "right": [(B, C, C2), (B, C2, B2)], "roof": [(A2, B2, C2), (A2, C2, D2)]}
    kind = {"ground": "ground", "roof": "roof"}
    zfaces = tuple(ZoneFace((tuple(sorted({i for t in tris for i in t})),), kind.get(n, "wall"), None, 1.0, k)
                   for k, (n, tris) in enumerate(faces.items()))
    tri_of = {f.index: np.array(faces[n], dtype=np.intp) for f, n in zip(zfaces, faces)}
    monkeypatch.setattr(ZoneShell, "face_triangles", lambda self, f: tri_of[f.index].copy())
    z = ZoneShell("chord", "chord", v, zfaces, 2.8, 0.0)
    all_tris = np.concatenate(list(tri_of.values()))
    assert not trimesh.Trimesh(v, all_tris, process=False).is_watertight       # A-B in four triangles
    _, t, codes = stl._zone_mesh(z)
    tm = trimesh.Trimesh(v, t, process=False)
    assert tm.is_watertight and tm.is_winding_consistent and tm.volume == pytest.approx(1200.0)
    P3 = v[t]
    h2 = np.linalg.norm(np.cross(P3[:, 1] - P3[:, 0], P3[:, 2] - P3[:, 0]), axis=1)
    assert h2.min() > 1e-3                                                    # no cap left
    assert np.bincount(codes, minlength=3)[:3].tolist() == [2, 10, 4]        # roof, wall, ground kept


@pytest.mark.skipif(not (DATA / "citygml-real").exists(), reason="shared CityGML tiles not available")
def test_berlin_tile_stls_are_closed(tmp_path):
    # real LoD2 CityGML: ground outlines with collinear runs shared with walls (see above)
    from lod2energy.config import Tolerances
    from lod2energy.io import read
    from lod2energy.prepare import repair_one
    _, feats = read(str(DATA / "citygml-real" / "berlin" / "3920_5818.gml"))
    bs = [energy_ready(repair_one(b, Tolerances())) for b in feats if hasattr(b, "vertices")]
    res = stl.write(bs, tmp_path)
    assert len(res) == len(bs) >= 70
    assert [r.building_ids for r in res if not r.ok] == []
