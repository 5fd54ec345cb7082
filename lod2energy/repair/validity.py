"""The repair ladder's stopping criterion: is a shell an energy-ready closed solid boundary?

A shell passes when every ring has >= 3 distinct points, no face is non-planar (203/204),
degenerate or a sliver (area <= ``tol.sliver_area``), every edge is used by exactly two faces
in opposite directions (N_b = N_nm = 0, 302/303/307), every vertex is a single fan (303),
the faces form one component (305), the signed volume is positive (outward normals, 405)
and no two faces cross (306). Codes are val3dity's; the energy ones (1001-1003) are used by
:func:`energy_codes` for surface geometries that val3dity would not check as shells.
"""
from __future__ import annotations

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.polymesh import (
    PolyMesh, face_area, face_normal, plane_basis, planarity, ring_is_simple_2d, signed_volume,
    topology, triangulate_mesh,
)


def polygon_defects(m: PolyMesh, tol: Tolerances = DEFAULT,
                    invalid: dict[int, set[int]] | None = None) -> list[tuple[int, int, str]]:
    """Polygon-level problems: ``(face_index, code, info)``.

    ``invalid`` is the project's polygon validator's verdict on the faces of ``m``
    (:func:`lod2energy.repair.cleanup.invalid_polygons`, ``{face_index: {codes}}``) when the
    caller already knows it; it is computed here otherwise.
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
        from lod2energy.repair.cleanup import invalid_polygons
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
        from lod2energy.geometry.vectors import newell_normals
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


def shell_defects(m: PolyMesh, tol: Tolerances = DEFAULT, first_only: bool = False,
                  self_intersection: bool = True, invalid: dict[int, set[int]] | None = None
                  ) -> list[tuple[int | None, int, str]]:
    """Every reason why ``m`` is not a closed, outward, clean 2-manifold shell.

    ``invalid``: the polygon validator's verdict on ``m``'s faces when already known (see
    :func:`polygon_defects`).

    Returns
    -------
    list of (face_index or None, code, info)
        Empty when the shell passes.
    """
    if len(m.faces) < 4:
        return [(None, 301, f"{len(m.faces)} faces")]
    out = polygon_defects(m, tol, invalid)
    if out and first_only:
        return out
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
        return out
    tris, owner = triangulate_mesh(m)
    if signed_volume(m, tris) <= 0:
        out.append((None, 405, "normals point inwards"))
        if first_only:
            return out
    if self_intersection:
        pairs = self_intersections(m.vertices, tris, owner)
        if len(pairs):
            out.append((int(owner[pairs[0][0]]), 306, f"{len(pairs)} crossing triangle pairs"))
    return out


def shell_defects_many(items, tol: Tolerances = DEFAULT) -> list[list[tuple[int | None, int, str]]]:
    """:func:`shell_defects` of several shells (``[(mesh, invalid)]``, ``invalid`` as there)
    with their self-intersection tests in one batch (:func:`self_intersections_many`)."""
    outs, todo = [], []
    for m, invalid in items:
        out = shell_defects(m, tol, self_intersection=False, invalid=invalid)
        outs.append(out)
        # shell_defects tests crossings only once every other check passed (405 aside)
        if all(c == 405 for _, c, _ in out):
            tris, owner = triangulate_mesh(m)
            todo.append((len(outs) - 1, m.vertices, tris, owner))
    found = self_intersections_many([t[1:] for t in todo])
    for (k, _, _, owner), pairs in zip(todo, found):
        if len(pairs):
            outs[k].append((int(owner[pairs[0][0]]), 306, f"{len(pairs)} crossing triangle pairs"))
    return outs


def is_closed_solid(m: PolyMesh, tol: Tolerances = DEFAULT) -> bool:
    """True when :func:`shell_defects` finds nothing."""
    return not shell_defects(m, tol, first_only=True)


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


def _seg_tri_cross(p0, p1, a, b, c, eps):
    """Vectorised: does segment p0-p1 cross the interior of triangle abc (strictly)?"""
    n = np.cross(b - a, c - a)
    ln = np.linalg.norm(n, axis=1)
    ok = ln > 1e-14
    n = n / np.where(ok, ln, 1.0)[:, None]
    d0 = np.einsum("ij,ij->i", p0 - a, n)
    d1 = np.einsum("ij,ij->i", p1 - a, n)
    cross = ok & (((d0 > eps) & (d1 < -eps)) | ((d0 < -eps) & (d1 > eps)))
    t = d0 / np.where(cross, d0 - d1, 1.0)
    x = p0 + (p1 - p0) * t[:, None]
    res = cross.copy()
    for u, v in ((a, b), (b, c), (c, a)):
        e = v - u
        s = np.einsum("ij,ij->i", np.cross(e, x - u), n)
        el = np.linalg.norm(e, axis=1)
        res &= s > eps * np.maximum(el, 1e-12)
    return res


def self_intersections(V: np.ndarray, tris: np.ndarray, owner: np.ndarray) -> np.ndarray:
    """Pairs of triangles of different faces that cross, touch or overlap (val3dity's 306).

    Uses :func:`lod2energy.geometry.triangle_pairs_intersect` (touching counts, as with
    exact predicates; shared vertices and edges do not).

    Parameters
    ----------
    V : (n, 3) float
    tris : (t, 3) int
    owner : (t,) int
        Face of each triangle; triangles of one face are never compared.

    Returns
    -------
    (p, 2) int
        Indices into ``tris``.
    """
    return self_intersections_many([(V, tris, owner)])[0]


def self_intersections_many(items) -> list[np.ndarray]:
    """:func:`self_intersections` of several shells ``[(V, tris, owner)]``, their candidate
    pairs tested in one call (each shell in its own local coordinates, as alone: the test is
    row by row).

    Returns
    -------
    list of (p, 2) int
        Per shell, indices into its ``tris``.
    """
    from lod2energy.geometry import triangle_pairs_intersect
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
