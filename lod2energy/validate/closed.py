"""Is this shell closed and acceptable? The one answer, for the repair ladder and for the writers.

:func:`shell_defects` judges a :class:`~lod2energy.polymesh.PolyMesh` (the repair ladder's
stopping criterion, the input check of every geometry): a shell passes when every ring has >= 3 distinct points, no face is non-planar (203/204),
degenerate or a sliver (area <= ``tol.sliver_area``), every edge is used by exactly two faces
in opposite directions (N_b = N_nm = 0, 302/303/307), every vertex is a single fan (303),
the faces form one component (305), the signed volume is positive (outward normals, 405)
and no two faces cross (306). Codes are val3dity's; the energy ones (1001-1003) are used by
:func:`energy_codes` for surface geometries that val3dity would not check as shells.

:func:`check_closed_outward` judges the polygons a writer wrote for one zone (the IDF and STL
self-checks): welded, T-junctions split, every edge used twice, positive volume.

:func:`export_problem` is the final check of a building before it is called compliant and
written (on the output file's grid: :func:`acceptance_problem`, then the val3dity checks of
its envelope); :func:`envelope_problems` the envelope part, which the CityJSON self-check runs
on the file it reads back.
"""
from __future__ import annotations

from collections import defaultdict
from typing import Iterable, Mapping, Sequence

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import cross_rows, newell_normals, signed_volume, split_at_points, triangle_pairs_intersect
from lod2energy.geometry.polygons import triangulate
from lod2energy.geometry.snap import drop_repeats, weld
from lod2energy.io.cityjson_grid import building_grid, on_grid
from lod2energy.model import Building, Shell, Surface
from lod2energy.polymesh import PolyMesh, face_area, topology, triangulate_mesh
from lod2energy.semantics import ENVELOPE_TYPES, envelope_objects, face_metrics, strip_to_energy
from lod2energy.validate.checks import validate_building
from lod2energy.validate.polygon import check_polygons


def polygon_defects(m: PolyMesh, tol: Tolerances = DEFAULT,
                    invalid: dict[int, set[int]] | None = None) -> list[tuple[int, int, str]]:
    """Polygon-level problems: ``(face_index, code, info)``.

    ``invalid`` is the project's polygon validator's verdict on the faces of ``m``
    (:func:`invalid_polygons`, ``{face_index: {codes}}``) when the caller already knows it;
    it is computed here otherwise.
    """
    V = m.vertices
    out = []
    flat = _Rings(V, m.faces)
    sliver = flat.sliver_candidates(tol.sliver_area)
    k = 0
    for fi, f in enumerate(m.faces):
        bad = False
        for j, r in enumerate(f.rings):
            if len(set(r)) < 3:
                out.append((fi, 101, f"{len(set(r))} distinct points"))
                bad = True
                break
            d = flat.edge_lengths(k + j)
            if (d <= tol.snap_tol).any():
                out.append((fi, 102, f"points {float(d.min()):.4f} m apart"))
                bad = True
                break
        k += len(f.rings)
        if bad or not sliver[fi]:
            continue
        a = face_area(V, f)
        if a <= tol.sliver_area:
            out.append((fi, 1003, f"area {a:.2e} m2"))
            continue
    if out:
        return out
    if invalid is None:
        invalid = invalid_polygons(m, tol)
    for fi, codes in sorted(invalid.items()):
        for c in sorted(codes):
            out.append((fi, c, "polygon validator"))
    return out


class _Rings:
    """Every ring of ``faces`` (indices into ``V`` (n, 3), m) in one flat array, for the
    per-ring measures of :func:`polygon_defects` in a few numpy calls."""

    def __init__(self, V: np.ndarray, faces) -> None:
        self.V, self.faces = V, faces
        rings = [np.asarray(r, dtype=np.intp) for f in faces for r in f.rings]
        self.rings = rings
        self.nr = np.fromiter((len(f.rings) for f in faces), dtype=np.intp, count=len(faces))
        self.lens = np.fromiter((len(r) for r in rings), dtype=np.intp, count=len(rings))
        self.starts = np.concatenate(([0], np.cumsum(self.lens)[:-1])).astype(np.intp)
        self.idx = np.concatenate(rings) if rings else np.zeros(0, dtype=np.intp)
        nxt = np.arange(len(self.idx)) + 1
        full = self.lens > 0
        nxt[(self.starts + self.lens - 1)[full]] = self.starts[full]
        self.nxt = nxt
        self.ok = not len(self.idx) or (-len(V) <= self.idx.min() and self.idx.max() < len(V))
        P = V[self.idx] if self.ok else np.zeros((0, 3))
        # the rows of P - roll(P, -1) ring by ring, each norm taken on its own row: the bits
        # of np.linalg.norm on one ring
        self.P = P
        self.d = np.linalg.norm(P - P[nxt], axis=1) if len(P) else np.zeros(0)

    def edge_lengths(self, k: int) -> np.ndarray:
        """(len(ring),) float: the length of each edge of ring ``k`` (from point i to i + 1), m."""
        if not self.ok:  # indices outside V: as the ring alone would fail
            P = self.V[self.rings[k]]
            return np.linalg.norm(P - np.roll(P, -1, axis=0), axis=1)
        s = self.starts[k]
        return self.d[s:s + self.lens[k]]

    def sliver_candidates(self, sliver_area: float) -> np.ndarray:
        """(len(faces),) bool: False only for the faces whose :func:`face_area` is certainly
        above ``sliver_area`` (m2), judged on the centred Newell normals of their rings with a
        bound on the rounding of both sums; the others need :func:`face_area` itself."""
        nr, lens = self.nr, self.lens
        out = np.ones(len(nr), dtype=bool)
        if not len(self.rings) or not self.ok or (nr == 0).any() or (lens < 3).any():
            return out
        first = np.concatenate(([0], np.cumsum(nr)[:-1]))
        # every product of either Newell sum (raw coordinates in face_area, about the mean of
        # all points here) is at most |p - q| * 4 max|coordinate|: their sum bounds the rounding
        big = 4.0 * float(np.abs(self.P).max())
        mag = np.add.reduceat(np.abs(self.P - self.P[self.nxt]).sum(axis=1), self.starts) * big
        half = np.linalg.norm(newell_normals(self.V, self.rings), axis=1) / 2
        signed = np.where(np.arange(len(self.rings)) == np.repeat(first, nr), half, -half)
        area = np.add.reduceat(signed, first)
        err = np.add.reduceat(mag * (lens + 8) * 4e-16 + half * 1e-14, first) + 1e-12
        return ~(area - err > sliver_area)


def invalid_polygons(m: PolyMesh, tol: Tolerances) -> dict[int, set[int]]:
    """Faces of ``m`` the project's polygon validator rejects: ``{face_index: {codes}}``."""
    shell = Shell(tuple(Surface.from_lists([list(r) for r in f.rings]) for f in m.faces))
    return invalid_surfaces(m.vertices, shell, tol)


def invalid_surfaces(vertices: np.ndarray, shell: Shell, tol: Tolerances) -> dict[int, set[int]]:
    """:func:`invalid_polygons` of a shell of a building (``vertices`` (n, 3), m)."""
    out: dict[int, set[int]] = defaultdict(set)
    for fi, code, _ in check_polygons([(vertices, shell)], tol)[0]:
        if fi is not None:
            out[int(fi)].add(int(code))
    return out


def shell_defects(meshes: Sequence[PolyMesh], tol: Tolerances = DEFAULT, first_only: bool = False,
                  self_intersection: bool = True, invalid: Sequence[dict | None] | None = None
                  ) -> list[list[tuple[int | None, int, str]]]:
    """Every reason why each of ``meshes`` is not a closed, outward, clean 2-manifold shell.

    Parameters
    ----------
    meshes : sequence of PolyMesh
    tol : Tolerances
    first_only : bool
        Stop at the first level that fails (polygons, topology, orientation).
    self_intersection : bool
        Test crossing faces (306), the shells' tests in one batch.
    invalid : sequence of dict or None, optional
        The polygon validator's verdict on each mesh's faces when already known (see
        :func:`polygon_defects`).

    Returns
    -------
    list (one per mesh) of lists of (face_index or None, code, info)
        Empty when the shell passes.
    """
    outs, todo = [], []
    for k, m in enumerate(meshes):
        out, crossing = _defects(m, tol, first_only, None if invalid is None else invalid[k])
        outs.append(out)
        if crossing and self_intersection:
            tris, owner = triangulate_mesh(m)
            todo.append((k, m.vertices, tris, owner))
    for (k, _, _, owner), pairs in zip(todo, self_intersections([t[1:] for t in todo])):
        if len(pairs):
            outs[k].append((int(owner[pairs[0][0]]), 306, f"{len(pairs)} crossing triangle pairs"))
    return outs


def _defects(m: PolyMesh, tol: Tolerances, first_only: bool, invalid: dict | None
             ) -> tuple[list[tuple[int | None, int, str]], bool]:
    """:func:`shell_defects` of one mesh but crossings, and whether its crossings are to be tested."""
    if len(m.faces) < 4:
        return [(None, 301, f"{len(m.faces)} faces")], False
    out = polygon_defects(m, tol, invalid)
    if out and first_only:
        return out, False
    topo = topology(m)
    if topo.boundary:
        out.append((None, 302, f"N_b={len(topo.boundary)}"))
    if topo.nonmanifold:
        out.append((None, 303, f"N_nm={len(topo.nonmanifold)} edges"))
    if topo.nm_vertices:
        out.append((None, 303, f"{len(topo.nm_vertices)} non-manifold vertices"))
    if topo.misoriented:
        out.append((None, 307, f"{len(topo.misoriented)} edges used twice in one direction"))
    if topo.components > 1:
        out.append((None, 305, f"{topo.components} components"))
    if out:
        return out, False
    tris, _ = triangulate_mesh(m)
    if signed_volume(m.vertices, tris) <= 0:
        out.append((None, 405, "normals point inwards"))
        if first_only:
            return out, False
    return out, True


def energy_codes(defects) -> list[int]:
    """Map shell codes to the energy-compliance ones (for surface geometries)."""
    out = set()
    for _, c, _ in defects:
        if c in (301, 302, 303, 305):
            out.add(1001)
        elif c in (307, 405):
            out.add(1002)
        elif c in (101, 102, 1003):
            out.add(1003)
        else:
            out.add(c)
    return sorted(out)


# ----------------------------------------------------------------------------- self-intersection

def _candidate_pairs(T: np.ndarray, chunk: int = 1 << 20) -> np.ndarray:
    """Pairs of triangles whose bounding boxes overlap: (p, 2) int, i < j.

    A sweep along x: each triangle (in x order of its lowest point) against the ones that
    start before it ends, kept when y and z overlap too; rows in sweep order, ``chunk``
    candidates at a time.
    """
    lo, hi = T.min(axis=1), T.max(axis=1)
    eps = 1e-9
    order = np.argsort(lo[:, 0], kind="stable")
    slo, shi = lo[order], hi[order]
    n = len(T)
    ends = np.searchsorted(slo[:, 0], shi[:, 0] + eps, side="right")
    ks = np.arange(n)
    cnt = np.maximum(ends - (ks + 1), 0)
    out = []
    csum = np.cumsum(cnt)
    k0 = 0
    while k0 < n:
        base = csum[k0 - 1] if k0 else 0
        k1 = max(int(np.searchsorted(csum, base + chunk, side="right")), k0 + 1)
        c = cnt[k0:k1]
        tot = int(c.sum())
        if tot:
            k = np.repeat(ks[k0:k1], c)
            off = np.arange(tot) - np.repeat(np.cumsum(c) - c, c)
            j = k + 1 + off
            ok = np.all((slo[j, 1:] <= shi[k, 1:] + eps) & (shi[j, 1:] >= slo[k, 1:] - eps), axis=1)
            if ok.any():
                out.append(np.column_stack([order[k[ok]], order[j[ok]]]))
        k0 = k1
    if not out:
        return np.zeros((0, 2), dtype=np.int64)
    p = np.vstack(out)
    return np.sort(p, axis=1)


def self_intersections(items: Sequence[tuple[np.ndarray, np.ndarray, np.ndarray]]) -> list[np.ndarray]:
    """Pairs of triangles of different faces that cross, touch or overlap (val3dity's 306), of
    several shells, their candidate pairs tested in one call (each shell in its own local
    coordinates, as alone: :func:`lod2energy.geometry.triangle_pairs_intersect` works row by
    row; touching counts, as with exact predicates; shared vertices and edges do not).

    Parameters
    ----------
    items : sequence of (V (n, 3) float, tris (t, 3) int, owner (t,) int)
        Each shell's triangles and the face of each (triangles of one face are never compared).

    Returns
    -------
    list of (p, 2) int
        Per shell, indices into its ``tris``.
    """
    outs = [np.zeros((0, 2), dtype=np.int64) for _ in items]
    local, tri_sets, pair_sets, where = [], [], [], []
    nv = nt = 0
    for k, (V, tris, owner) in enumerate(items):
        if len(tris) < 2:
            continue
        origin = V[tris[0, 0]]
        T = V[tris] - origin
        pairs = _candidate_pairs(T)
        if len(pairs) == 0:
            outs[k] = pairs
            continue
        pairs = pairs[owner[pairs[:, 0]] != owner[pairs[:, 1]]]
        if len(pairs) == 0:
            outs[k] = pairs
            continue
        local.append(V - origin)
        tri_sets.append(np.asarray(tris) + nv)
        pair_sets.append(pairs + nt)
        where.append((k, pairs))
        nv += len(V)
        nt += len(tris)
    if not where:
        return outs
    hit = triangle_pairs_intersect(np.vstack(local), np.vstack(tri_sets), np.vstack(pair_sets))
    start = 0
    for k, pairs in where:
        outs[k] = pairs[hit[start:start + len(pairs)]]
        start += len(pairs)
    return outs


# ----------------------------------------------------------------------------- energy buildings

#: Overlapping BuildingParts (601) are reported by the validator but do not stop an export:
#: each part is still a closed, outward shell (the repair ladder's own criterion); use
#: ``--merge-parts`` to union them.
TOLERATED_CODES = frozenset({601})
#: At most this many envelope problems are listed for one building.
MAX_PROBLEMS = 50


def acceptance_problem(b: Building, lod: str | None) -> str | None:
    """The checks of an energy building besides its val3dity validity: a Building with thermal
    data and an envelope at ``lod`` that is closed, outward, labelled and has U-values; the first
    problem, or None. The pipeline's final check and the CityJSON writer's both start with it."""
    if b.type != "Building":
        return f"not a Building (type {b.type!r})"
    if "thermal" not in b.provenance:
        return "no thermal data (labels / U-values not assigned)"
    energy = envelope_objects(b, lod)
    if not energy:
        return "no polygonal geometry at the energy LoD"
    probs = envelope_problems(b, energy)
    return probs[0] if probs else None


def envelope_problems(b: Building, energy=None) -> list[str]:
    """Closed, outward, labelled, with U-values: problems of the energy geometries of ``b``."""
    out = []
    energy = energy if energy is not None else envelope_objects(b)
    # identical coordinates = same vertex, whatever the index
    _, inv = np.unique(b.vertices, axis=0, return_inverse=True)
    inv = inv.reshape(-1)
    origin = b.vertices.mean(axis=0) if len(b.vertices) else np.zeros(3)
    for o, gi, g in energy:
        where = f"coid={o.id}|geom={gi}"
        if not g.is_volumetric:
            out.append(f"{where}: {g.type} is not a solid")
            continue
        for si, so in enumerate(g.solids):
            for hi, sh in enumerate(so.shells):
                edges: dict[tuple[int, int], int] = {}
                vol = 0.0
                for s in sh.surfaces:
                    for r in s.rings:
                        ids = inv[r].tolist()
                        for e in zip(ids, ids[1:] + ids[:1]):
                            if e[0] != e[1]:
                                edges[e] = edges.get(e, 0) + 1
                    ar, n, cen = face_metrics(b.vertices, s)
                    vol += float((cen - origin) @ (n * ar)) / 3.0
                bad = [e for e, k in edges.items() if k != 1 or edges.get((e[1], e[0]), 0) != 1]
                if bad:
                    out.append(f"{where}|solid={si}|shell={hi}: not closed or not consistently oriented "
                               f"({len(bad)} bad edges)")
                elif hi == 0 and vol <= 0:
                    out.append(f"{where}|solid={si}|shell={hi}: exterior shell oriented inwards (volume {vol:.3f} m3)")
        for si, hi, fi, s in g.iter_surfaces():
            loc = f"{where}|shell={hi}|face={fi}"
            if s.semantic is None or s.semantic >= len(g.semantic_surfaces):
                out.append(f"{loc}: no semantic surface")
                continue
            e = g.semantic_surfaces[s.semantic]
            if e.get("type") not in ENVELOPE_TYPES:
                out.append(f"{loc}: semantic type {e.get('type')!r} is not an envelope type")
            u = e.get("uValue")
            if not isinstance(u, (int, float)) or isinstance(u, bool) or not u > 0:
                out.append(f"{loc}: no positive uValue")
        if len(out) > MAX_PROBLEMS:
            break
    return out


def energy_defects(b: Building, defects: Iterable, lod: str | None) -> list:
    """The ``defects`` of ``b`` that concern its envelope at ``lod`` (or the building as a whole),
    without the tolerated ones (:data:`TOLERATED_CODES`)."""
    energy = envelope_objects(b, lod)
    heads = {f"coid={o.id}|geom={gi}" for o, gi, _ in energy}
    ids = {f"coid={o.id}" for o, _, _ in energy}
    bad = []
    for d in defects:
        if d.code in TOLERATED_CODES:
            continue
        locs = str(d.location).split("&&")
        if any("|".join(loc.split("|")[:2]) in heads or loc in ids or "geom=" not in loc for loc in locs):
            bad.append(d)
    return bad


def export_problem(b: Building, lod: str | None, tol: Tolerances, *, defects: Iterable | None = None,
                   transform: Mapping | None = None, frame=None, keep_other_lods: bool = False) -> str | None:
    """Why ``b`` may not be called compliant nor written (None when it may): the one final check.

    Judged on what a writer writes: the vertices are first rounded to the output file's grid
    (:func:`lod2energy.io.cityjson_grid.on_grid`, the function the CityJSON writer uses), then
    :func:`acceptance_problem` and the val3dity checks at the user's tolerances ``tol`` run on
    the envelope at ``lod`` (overlapping parts, 601, tolerated).

    Parameters
    ----------
    b : Building
        Labelled, with U-values (``provenance["thermal"]``).
    lod : str or None
        Energy LoD (None: the building's own).
    tol : Tolerances
    defects : iterable of Defect, optional
        Already computed defects of ``b`` at ``tol``: used when the grid leaves ``b`` as it is.
    transform, frame : optional
        The file's grid (scale, translate) and, for a geographic file, its local frame;
        default: :func:`lod2energy.io.cityjson_grid.building_grid`.
    keep_other_lods : bool
        Judge every geometry, not only the envelope at ``lod``.
    """
    if transform is None:
        transform, frame = building_grid(b)
    snapped = on_grid(b, transform, frame)
    why = acceptance_problem(snapped, lod)
    if why is not None:
        return why
    if snapped is b and defects is not None and not keep_other_lods:
        bad = energy_defects(b, defects, lod)
    else:
        bad = [d for d in validate_building(strip_to_energy(snapped, lod, keep_other_lods), tol)
               if d.code not in TOLERATED_CODES]
    if bad:
        codes = sorted({d.code for d in bad})
        return f"invalid geometry (val3dity codes {codes}), e.g. {bad[0].location}"
    return None


# ----------------------------------------------------------------------------- written polygons

def check_closed_outward(polygons: Sequence[np.ndarray], tol: float = 1e-3,
                         t_tol: float = 0.0127) -> list[str]:
    """Is a set of 3D polygons (one zone's written surfaces) a closed, outward shell?

    Vertices are welded at ``tol``, T-junctions within ``t_tol`` (EnergyPlus's point
    tolerance, 1.27 cm) are split, then every undirected edge must
    be used exactly twice, once in each direction (closed, 2-manifold, consistent winding),
    and the enclosed signed volume must be positive (outward).

    Parameters
    ----------
    polygons : sequence of (k, 3) float
        Polygons as written, counter-clockwise seen from outside.

    Returns
    -------
    list of str
        Problems found (empty when the shell is fine).
    """
    if not polygons:
        return ["no surfaces"]
    allp = np.concatenate([np.asarray(p, dtype=np.float64) for p in polygons])
    v, idx = weld(allp, tol)
    polys, k = [], 0
    for p in polygons:
        ring = drop_repeats(idx[k:k + len(p)].tolist())
        k += len(p)
        if len(set(ring)) >= 3:
            polys.append(ring)
    polys = split_at_points(v, polys, t_tol, only_unmatched=True)
    directed: dict[tuple[int, int], int] = {}
    for poly in polys:
        for i in range(len(poly)):
            e = (poly[i], poly[(i + 1) % len(poly)])
            directed[e] = directed.get(e, 0) + 1
    problems = []
    boundary = sum(1 for (a, b), n in directed.items() if (b, a) not in directed)
    dup = sum(1 for n in directed.values() if n > 1)
    if boundary:
        problems.append(f"not closed: {boundary} edge(s) used by one surface only")
    if dup:
        problems.append(f"inconsistent winding or non-manifold: {dup} edge(s) used twice in one direction")
    if not boundary and not dup and _surely_outward(v, polys):
        return problems  # the volume below is positive (see _surely_outward): nothing to add
    tris = []
    for poly in polys:
        pts = v[poly]
        t = triangulate(pts, [len(poly)])
        tris.extend([[poly[i] for i in tt] for tt in t])
    vol = signed_volume(v, np.asarray(tris, dtype=np.intp).reshape(-1, 3))
    if vol <= 0:
        problems.append(f"not outward: signed volume {vol:.3f} m3")
    return problems


_Z = np.array([[0.0, 0.0, 1.0]])
_X = np.array([[1.0, 0.0, 0.0]])


#: Smallest sine of a turn of a ring projected on its plane for :func:`_surely_outward` to
#: take the ring as strictly convex.
_CONVEX_SIN = 1e-6


def _surely_outward(v: np.ndarray, polys: list[list[int]]) -> bool:
    """Is the signed volume :func:`check_closed_outward` computes from its earcut triangles
    certainly positive? Decided without triangulating; False when it cannot tell.

    Only for a shell whose rings (index lists into ``v``, ``(n, 3)`` m) use every directed
    edge once and its reverse once (zero boundary). Then the volume does not depend on the
    triangulation of a ring as long as that triangulation's boundary is the ring: two of them
    differ by the volume of a closed surface, which is at most ``delta x sum of its triangles'
    areas`` (``delta``: the largest distance of the ring's vertices from any plane; the
    volume is the integral of the height above that plane over the projected area). Earcut
    triangulates a strictly convex ring (every turn of its projection on the plane that
    :func:`polygons.triangulate` uses to the left by a sine of at least :data:`_CONVEX_SIN`,
    one turn in all) into ``k - 2`` triangles of its vertices that cover it, all oriented as
    the ring. So when every ring is strictly convex, the volume ``V`` of the fans
    ``(p0, p_i, p_i+1)`` minus the bound ``sum_r delta_r 2 k_r D_r^2`` (``D_r`` the diagonal
    of the ring's box, so no triangle of its vertices is larger than ``D_r^2 / 2``) and a
    margin for floating-point rounding is a lower bound of the earcut volume: when positive,
    the earcut volume is positive and the check adds nothing.
    """
    rings = [np.asarray(r, dtype=np.intp) for r in polys]
    if not rings or any(len(set(r)) != len(r) for r in polys):
        return False
    lens = np.array([len(r) for r in rings])
    starts = np.concatenate(([0], np.cumsum(lens)[:-1]))
    idx = np.concatenate(rings)
    P = v[idx]
    o = P.mean(axis=0)
    P = P - o
    ring_of = np.repeat(np.arange(len(rings)), lens)
    pos = np.arange(len(P)) - starts[ring_of]
    nxt = starts[ring_of] + (pos + 1) % lens[ring_of]
    # each ring's plane: the Newell normal (any plane serves the bound; this one for the
    # convexity test), through the ring's centroid
    cen = np.add.reduceat(P, starts, axis=0) / lens[:, None]
    rel = P - cen[ring_of]
    nrm = np.add.reduceat(cross_rows(rel, rel[nxt]), starts, axis=0)
    nlen = np.sqrt(np.sum(nrm * nrm, axis=1))
    if not np.all(nlen > 0):
        return False
    n = nrm / nlen[:, None]
    # in-plane basis u, v (u x v = n): the convexity test in the projection
    helper = np.where(np.abs(n[:, 2:3]) < 0.9, _Z, _X)
    bu = cross_rows(helper, n)
    bu /= np.sqrt(np.sum(bu * bu, axis=1))[:, None]
    bv = cross_rows(n, bu)
    x = np.sum(rel * bu[ring_of], axis=1)
    y = np.sum(rel * bv[ring_of], axis=1)
    dx, dy = x[nxt] - x, y[nxt] - y            # edge i: vertex i -> i + 1
    ex, ey = dx[nxt], dy[nxt]                  # the edge after it
    cross = dx * ey - dy * ex
    dot = dx * ex + dy * ey
    scale = np.hypot(dx, dy) * np.hypot(ex, ey)
    if not np.all(cross >= _CONVEX_SIN * scale) or not np.all(scale > 0):
        return False
    turning = np.add.reduceat(np.arctan2(cross, dot), starts)
    if not np.all(np.abs(turning - 2 * np.pi) < 1e-3):
        return False  # winds more than once
    # the fans' volume about o
    p0 = P[starts[ring_of]]
    fan = (pos >= 1) & (pos <= lens[ring_of] - 2)
    a, b, c = p0[fan], P[fan], P[nxt[fan]]
    dets = np.sum(a * cross_rows(b, c), axis=1)
    vol = float(dets.sum()) / 6.0
    # the bound, with room for rounding
    delta = np.maximum.reduceat(np.abs(np.sum(rel * n[ring_of], axis=1)), starts)
    diag2 = np.sum((np.maximum.reduceat(P, starts, axis=0) - np.minimum.reduceat(P, starts, axis=0)) ** 2, axis=1)
    bound = float(np.sum(delta * 2 * lens * diag2)) * (1 + 1e-9) + 1e-9
    r3 = float(np.max(np.sum(P * P, axis=1))) ** 1.5
    rounding = 1e-12 * (len(dets) + int(lens.sum())) * 8 * r3
    return vol - bound - rounding > 0
