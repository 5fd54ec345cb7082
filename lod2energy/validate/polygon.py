"""Polygon-level checks (101-104, 201-208) with val3dity 2.6's semantics and messages.

What val3dity does for one shell (``Surface::validate_2d_primitives``), reproduced here:

1. vertices are snapped per shell (see :mod:`lod2energy.validate.snap`);
2. per face, in this order, the first failing test ends the face's checks:
   101 (a ring with < 3 points), 102 (two consecutive snapped points the same, first-last
   included), a lone triangle is only tested for collinearity (104), 203 (a point farther
   than ``planarity_d2p_tol`` from the least-squares plane of all the face's points; the
   first such point in ring order is reported), 104 (a ring, projected on that plane, is not
   simple), 208 (an inner ring oriented as the outer), then GEOS ``IsValidReason`` on the
   projected polygon (201, 202, 205, 206, 207);
3. only when every face of the shell passed: 204 (the normals of the face's constrained
   Delaunay triangles deviate from the first one's by more than ``planarity_n_tol``).

:func:`check_polygons` works on many shells at once (also across buildings): plane fits by
segment sums and one batched eigen-decomposition, ring tests through shapely's array
functions, and the 204 triangulation only for polygons where some triangle of their vertices
could tilt enough (all-triples bound). Its answers are kept in :mod:`lod2energy.cache` by
content, so a shell checked once (by the validation) is not checked again (by the repair).
"""
from __future__ import annotations

import itertools
from fractions import Fraction
from typing import Sequence

import numpy as np
import shapely

from lod2energy import cache
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import constrained_delaunay_many, cross_rows, plane_bases
from lod2energy.geometry.pairs import close_pairs_grid
from lod2energy.geometry.snap import snapped_ids
from lod2energy.model import Shell
from lod2energy.validate.memo import shell_keys

INFO_104_TRIANGLE = " outer ring (a triangle) is collapsed to a line"
INFO_104_RING = "ring self-intersects or is collapsed to a line"
INFO_208 = "same orientation for outer and inner rings"

_GEOS_CODES = (("Self-intersection", 201), ("Duplicate Rings", 202), ("Interior is disconnected", 205),
               ("Hole lies outside shell", 206), ("Holes are nested", 207))
_MAX_TRIPLES_POINTS = 14  # above this the all-triples bound costs more than the CDT


def _fmt(x: float) -> str:
    """A number as C++ ``ostream << double`` prints it (6 significant digits)."""
    return format(float(x), "g")


def info_203(value: float, tol: float) -> str:
    return f"distance to fitted plane: {_fmt(value)} (tolerance={_fmt(tol)})"


def info_204(value: float, tol: float) -> str:
    return f"deviation normals: {_fmt(value)} (tolerance={_fmt(tol)})"


def geos_code(reason: str) -> int:
    """val3dity code for a GEOS ``IsValidReason`` text (999 when unknown)."""
    for key, code in _GEOS_CODES:
        if key in reason:
            return code
    return 999


def _exactly_collinear(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> bool:
    """CGAL::collinear on doubles (exact): float test first, exact rationals when close."""
    u, v = b - a, c - a
    cr = np.cross(u, v)
    nu, nv = float(np.linalg.norm(u)), float(np.linalg.norm(v))
    if float(np.linalg.norm(cr)) > 1e-9 * nu * nv:
        return False
    A = [Fraction(float(x)) for x in a]
    U = [Fraction(float(x)) - A[i] for i, x in enumerate(b)]
    V = [Fraction(float(x)) - A[i] for i, x in enumerate(c)]
    return (U[1] * V[2] - U[2] * V[1] == 0 and U[2] * V[0] - U[0] * V[2] == 0
            and U[0] * V[1] - U[1] * V[0] == 0)


def _smallest_eigenvector(cov: np.ndarray) -> np.ndarray:
    """Unit eigenvector of the smallest eigenvalue of each (3, 3) covariance, as a plane normal.

    Components under 1e-12 are set to 0 as val3dity does (``get_best_fitted_plane``);
    a degenerate covariance gives (0, 0, 1).
    """
    with np.errstate(invalid="ignore"):
        _, vecs = np.linalg.eigh(cov)
    n = vecs[:, :, 0]
    n = np.where(np.abs(n) < 1e-12, 0.0, n)
    norm = np.linalg.norm(n, axis=1, keepdims=True)
    bad = ~(norm[:, 0] > 0) | ~np.isfinite(norm[:, 0])
    return np.where(bad[:, None], np.array([0.0, 0.0, 1.0]), n / np.where(norm > 0, norm, 1.0))


def _triples(n: int) -> np.ndarray:
    return np.asarray(list(itertools.combinations(range(n), 3)), dtype=np.intp).reshape(-1, 3)


_TRIPLES = {n: _triples(n) for n in range(3, _MAX_TRIPLES_POINTS + 1)}


def _triangle_tilt(p0, p1, p2, h0, h1, h2) -> np.ndarray:
    """Tilt (degrees) from the plane of triangles given in-plane points and heights.

    Parameters
    ----------
    p0, p1, p2 : (t, 2) float
        Corners in the plane, m.
    h0, h1, h2 : (t,) float
        Heights of the corners above the plane, m.

    Returns
    -------
    (t,) float
        Degrees; 0 for zero-area triples (no triangulation uses them), large for
        near-degenerate ones.
    """
    e1, e2 = p1 - p0, p2 - p0
    d1, d2 = h1 - h0, h2 - h0
    area2 = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
    g = np.hypot(d1 * e2[:, 1] - d2 * e1[:, 1], d2 * e1[:, 0] - d1 * e2[:, 0])
    with np.errstate(divide="ignore", invalid="ignore"):
        slope = np.where(area2 != 0, g / np.abs(area2), 0.0)
    return np.degrees(np.arctan(slope))


def _normals_deviation(P3: np.ndarray, tri: np.ndarray, tol_deg: float) -> float | None:
    """First deviation (degrees) above ``tol_deg`` from the first triangle's normal, or None."""
    if len(tri) < 2:
        return None
    a, b, c = P3[tri[:, 0]], P3[tri[:, 1]], P3[tri[:, 2]]
    nrm = cross_rows(b - a, c - a)
    with np.errstate(invalid="ignore", divide="ignore"):
        nrm = nrm / np.linalg.norm(nrm, axis=1, keepdims=True)
    v0 = nrm[0]
    cr = np.linalg.norm(cross_rows(np.broadcast_to(v0, nrm[1:].shape), nrm[1:]), axis=1)
    dot = nrm[1:] @ v0
    ang = np.degrees(np.arctan2(cr, dot))
    over = np.nonzero(ang > tol_deg)[0]
    if len(over) == 0:
        return None
    return float(ang[over[0]])


#: Shells whose polygon defects are kept per process (:mod:`lod2energy.cache`).
KEPT_SHELLS = 8192
#: Shells checked in one vectorised pass (bounds the temporaries of a large batch).
CHUNK = 500


def check_polygons(items: Sequence[tuple[np.ndarray, Shell]], tol: Tolerances = DEFAULT) -> list[list[tuple[int, int, str]]]:
    """Polygon defects of every surface of many shells, as val3dity reports them.

    Parameters
    ----------
    items : sequence of (vertices (n, 3) float, Shell)
        The building's vertices (m) and a shell whose rings index them; shells of several
        buildings may be checked together.
    tol : Tolerances
        ``snap_tol``, ``planarity_d2p_tol`` (m), ``planarity_n_tol`` (degrees), ``ignore204``.

    Returns
    -------
    list (one per item) of lists of (face_index, code, info)
        In val3dity's order: face by face, then the 204s. Empty when every polygon is valid.

    Examples
    --------
    >>> import numpy as np
    >>> from lod2energy.model import Shell, Surface
    >>> v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]])
    >>> check_polygons([(v, Shell((Surface.from_lists([[0, 1, 2, 3]]),)))])
    [[(0, 203, 'distance to fitted plane: 0.117072 (tolerance=0.01)')]]
    """
    items = list(items)

    def make(todo: list[int]) -> list[tuple]:
        return [tuple(r) for k in range(0, len(todo), CHUNK)
                for r in _check([items[i] for i in todo[k:k + CHUNK]], tol)]
    return [list(f) for f in cache.remember_each("validate.polygons", shell_keys(items, tol), make, KEPT_SHELLS)]


def _check(items: Sequence[tuple[np.ndarray, Shell]], tol: Tolerances) -> list[list[tuple[int, int, str]]]:
    """:func:`check_polygons` without the cache."""
    S = len(items)
    groups: dict[int, int] = {}
    arrays: list[np.ndarray] = []
    shell_group = np.empty(S, dtype=np.intp)
    for k, (v, _) in enumerate(items):
        g = groups.get(id(v))
        if g is None:
            g = groups[id(v)] = len(arrays)
            arrays.append(np.asarray(v, dtype=np.float64).reshape(-1, 3))
        shell_group[k] = g
    sizes = np.fromiter((len(a) for a in arrays), dtype=np.intp, count=len(arrays))
    offsets = np.cumsum(sizes) - sizes
    V = np.concatenate(arrays) if arrays else np.zeros((0, 3))
    shells = [sh for _, sh in items]
    shell_nfaces = np.fromiter((len(sh.surfaces) for sh in shells), dtype=np.intp, count=S)
    shell_first_face = np.cumsum(shell_nfaces) - shell_nfaces
    surfaces = [s for sh in shells for s in sh.surfaces]
    results: list[list[tuple[int, int, str]]] = [[] for _ in range(S)]
    if not surfaces:
        return results
    face_shell = np.repeat(np.arange(S), shell_nfaces)
    rings = [r for s in surfaces for r in s.rings]
    F = len(surfaces)
    face_nrings = np.fromiter((len(s.rings) for s in surfaces), dtype=np.intp, count=F)
    ring_size = np.fromiter((len(r) for r in rings), dtype=np.intp, count=len(rings))
    ring_face = np.repeat(np.arange(F), face_nrings)
    face_first_ring = np.cumsum(face_nrings) - face_nrings
    ring_start = np.cumsum(ring_size) - ring_size
    K = int(ring_size.sum())
    flat = (np.concatenate([np.asarray(r, dtype=np.intp).reshape(-1) for r in rings]) if K
            else np.zeros(0, np.intp))
    pos_ring = np.repeat(np.arange(len(rings)), ring_size)
    pos_shell = face_shell[ring_face[pos_ring]]
    pos_group = shell_group[pos_shell]
    if K:
        out_of_range = (flat < 0) | (flat >= sizes[pos_group])
        if out_of_range.any():
            bad = np.unique(ring_face[pos_ring[out_of_range]])
            for f in bad.tolist():
                sh = int(face_shell[f])
                results[sh].append((f - int(shell_first_face[sh]), 999, "vertex index out of range"))
            bad_shells = set(np.unique(face_shell[bad]).tolist())
            keep = [i for i in range(S) if i not in bad_shells]
            if keep:
                for i, r in zip(keep, _check([items[i] for i in keep], tol)):
                    results[i] = r
            return results
        flat = flat + offsets[pos_group]
    ids = _snap_shells(V, flat, pos_shell, offsets, tol.snap_tol) if K else flat
    nxt = np.arange(K) + 1
    nonempty = ring_size > 0
    nxt[(ring_start + ring_size - 1)[nonempty]] = ring_start[nonempty]
    face_npts = np.bincount(ring_face, weights=ring_size, minlength=F).astype(np.intp)
    face_start = np.cumsum(face_npts) - face_npts

    # ---- 101, 102
    few = (face_nrings == 0) | (np.bincount(ring_face[ring_size < 3], minlength=F) > 0)
    same = ids == ids[nxt] if K else np.zeros(0, bool)
    dup = np.bincount(ring_face[pos_ring[same]], minlength=F) > 0
    dup &= ~few
    finite_pt = np.isfinite(V[ids]).all(axis=1) if K else np.zeros(0, bool)
    nonfinite = np.bincount(ring_face[pos_ring[~finite_pt]], minlength=F) > 0
    code = np.zeros(F, dtype=np.int64)
    code[few] = 101
    code[dup] = 102
    info: dict[int, list[tuple[int, int, str]]] = {}
    # ---- lone triangles: only collinearity
    tri = (code == 0) & (face_nrings == 1) & (face_npts == 3)
    if tri.any():
        fidx = np.nonzero(tri)[0]
        P = V[ids[face_start[fidx][:, None] + np.arange(3)]]
        cr = cross_rows(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0])
        lim = 1e-9 * np.linalg.norm(P[:, 1] - P[:, 0], axis=1) * np.linalg.norm(P[:, 2] - P[:, 0], axis=1)
        close = ~(np.linalg.norm(cr, axis=1) > lim)
        for k in np.nonzero(close)[0].tolist():
            if not np.isfinite(P[k]).all() or _exactly_collinear(*P[k]):
                code[fidx[k]] = 104
                info[int(fidx[k])] = [(int(fidx[k]), 104, INFO_104_TRIANGLE)]
        code[fidx[code[fidx] == 0]] = -1  # valid triangle: done
    bad_pts = (code == 0) & nonfinite
    code[bad_pts] = 104
    for f in np.nonzero(bad_pts)[0].tolist():
        info[f] = [(f, 104, INFO_104_RING)]

    # ---- 203 and projection on the fitted plane (segment sums: no grouping by size)
    general = code == 0
    thr = float(np.float32(tol.planarity_d2p_tol) * np.float32(tol.planarity_d2p_tol))
    XY = np.zeros((K, 2))
    H = np.zeros(K)
    planar = np.zeros(F, dtype=bool)
    gf = np.nonzero(general)[0]
    if len(gf):
        fp = ring_face[pos_ring]
        sel = general[fp]
        P = V[ids]
        w = fp[sel]
        cnt = np.maximum(face_npts, 1)
        c = np.stack([np.bincount(w, weights=P[sel, i], minlength=F) for i in range(3)], axis=1) / cnt[:, None]
        X = P - c[fp]
        Xs = X[sel]
        cov = np.empty((F, 3, 3))
        for i in range(3):
            for j in range(i, 3):
                cov[:, i, j] = cov[:, j, i] = np.bincount(w, weights=Xs[:, i] * Xs[:, j], minlength=F)
        nrm = np.zeros((F, 3))
        nrm[gf] = _smallest_eigenvector(cov[gf])
        h = np.einsum("ki,ki->k", X, nrm[fp])
        over = sel & (h * h > thr)
        if over.any():
            opos = np.nonzero(over)[0]
            ofaces, first = np.unique(fp[opos], return_index=True)
            for f, k in zip(ofaces.tolist(), opos[first].tolist()):
                code[f] = 203
                info[f] = [(f, 203, info_203(abs(h[k]), tol.planarity_d2p_tol))]
        u = np.zeros((F, 3))
        v = np.zeros((F, 3))
        u[gf], v[gf] = plane_bases(nrm[gf], helper="least")
        XY[:, 0] = np.einsum("ki,ki->k", X, u[fp])
        XY[:, 1] = np.einsum("ki,ki->k", X, v[fp])
        H[:] = np.where(sel, h, 0.0)
        planar = code == 0

    # ---- 104 on projected rings, 208, GEOS
    pf = np.nonzero(planar)[0]
    if len(pf):
        rsel = np.nonzero(planar[ring_face])[0]
        psel = planar[ring_face[pos_ring]]
        lr = shapely.linearrings(XY[psel], indices=np.searchsorted(rsel, pos_ring[psel]))
        simple = np.zeros(len(rings), dtype=bool)
        simple[rsel] = shapely.is_simple(lr)
        zero_edge = np.bincount(pos_ring[(XY == XY[nxt]).all(axis=1) & psel], minlength=len(rings)) > 0
        ring_ok = simple & ~zero_edge
        cross_terms = XY[:, 0] * XY[nxt, 1] - XY[:, 1] * XY[nxt, 0]
        ring_area = np.bincount(pos_ring, weights=cross_terms, minlength=len(rings))
        to_geos = []
        for f in pf.tolist():
            r0 = int(face_first_ring[f])
            if not ring_ok[r0]:
                info[f] = [(f, 104, INFO_104_RING)]
                planar[f] = False
                continue
            nr = int(face_nrings[f])
            if nr == 1:
                continue
            fe = []
            kept = [r0]
            for r in range(r0 + 1, r0 + nr):
                if ring_ok[r]:
                    kept.append(r)
                else:
                    fe.append((f, 104, INFO_104_RING))
            if len(kept) > 1:
                if any((ring_area[r] > 0) == (ring_area[r0] > 0) for r in kept[1:]):
                    fe.append((f, 208, INFO_208))
                else:
                    to_geos.append((f, kept))
            if fe:
                info[f] = fe
                planar[f] = False
        if to_geos:
            polys = [shapely.Polygon(XY[ring_start[kept[0]]:ring_start[kept[0]] + ring_size[kept[0]]],
                                     [XY[ring_start[r]:ring_start[r] + ring_size[r]] for r in kept[1:]])
                     for f, kept in to_geos]
            reasons = shapely.is_valid_reason(np.asarray(polys + [None], dtype=object)[:-1])
            for (f, _), reason in zip(to_geos, reasons.tolist()):
                if reason is not None and not reason.startswith("Valid Geometry"):
                    info.setdefault(f, []).append((f, geos_code(reason), reason))
                    planar[f] = False

    bad_face = np.zeros(F, dtype=bool)
    for f in np.nonzero((code == 101) | (code == 102))[0].tolist():
        sh = int(face_shell[f])
        results[sh].append((f - int(shell_first_face[sh]), int(code[f]), ""))
        bad_face[f] = True
    for f in sorted(info):
        sh = int(face_shell[f])
        base = int(shell_first_face[sh])
        results[sh].extend((g - base, c_, i_) for g, c_, i_ in info[f])
        bad_face[f] = True
    for sh in range(S):
        results[sh].sort(key=lambda e: e[0])  # face order, as val3dity's loop
    if tol.ignore204:
        return results

    # ---- 204, only for a shell whose every polygon is valid
    shell_bad = np.bincount(face_shell[bad_face], minlength=S) > 0
    cand = np.nonzero(planar & ~shell_bad[face_shell])[0]
    for f, c_, i_ in _check_normals(cand, face_npts, face_start, face_first_ring, face_nrings,
                                    ring_size, ids, V, XY, H, tol.planarity_n_tol):
        sh = int(face_shell[f])
        results[sh].append((f - int(shell_first_face[sh]), c_, i_))
    return results


def _snap_shells(V: np.ndarray, flat: np.ndarray, pos_shell: np.ndarray, offsets: np.ndarray,
                 snap_tol: float) -> np.ndarray:
    """Snapped vertex ids, shell by shell (val3dity snaps per shell, in ring order).

    One grid of cells finds the few close pairs; only shells holding both ends of a pair (of the
    same vertex array) are snapped one by one.
    """
    if not snap_tol or snap_tol <= 0 or len(flat) < 2:
        return flat.copy()
    used, inv = np.unique(flat, return_inverse=True)
    pts = V[used]
    if not np.isfinite(pts).all():
        return flat.copy()
    pairs = close_pairs_grid(pts, snap_tol * (1 + 1e-9) + 1e-300)
    if len(pairs):  # pairs across vertex arrays (neighbouring buildings) do not matter
        grp = np.searchsorted(offsets, used, side="right")
        pairs = pairs[grp[pairs[:, 0]] == grp[pairs[:, 1]]]
    if len(pairs) == 0:
        return flat.copy()
    involved = np.zeros(len(used), dtype=bool)
    involved[pairs.ravel()] = True
    out = flat.copy()
    inv = np.asarray(inv).reshape(-1)
    hit = involved[inv]
    # a shell needs snapping only if it holds both ends of some pair
    pair_set = {(int(a), int(b)) for a, b in pairs.tolist()}
    for sh in np.unique(pos_shell[hit]).tolist():
        m = pos_shell == sh
        local = np.unique(inv[m & hit])
        if len(local) < 2:
            continue
        ls = set(local.tolist())
        if not any(a in ls and b in ls for a, b in pair_set):
            continue
        out[m] = snapped_ids(V, flat[m], snap_tol)
    return out


def _check_normals(faces, face_npts, face_start, face_first_ring, face_nrings, ring_size, ids, V, XY, H,
                   tol_deg: float) -> list[tuple[int, int, str]]:
    suspects: list[int] = []
    trip, owner = [], []
    for n in np.unique(face_npts[faces]).tolist():
        fidx = faces[face_npts[faces] == n]
        if n > _MAX_TRIPLES_POINTS:
            suspects.extend(fidx.tolist())
            continue
        T = _TRIPLES[n]
        trip.append((face_start[fidx][:, None, None] + T[None]).reshape(-1, 3))
        owner.append(np.repeat(fidx, len(T)))
    if trip:
        T = np.concatenate(trip)
        own = np.concatenate(owner)
        tilt = _triangle_tilt(XY[T[:, 0]], XY[T[:, 1]], XY[T[:, 2]], H[T[:, 0]], H[T[:, 1]], H[T[:, 2]])
        worst = np.zeros(len(face_npts))
        np.maximum.at(worst, own, tilt)
        cand = np.unique(own)
        suspects.extend(cand[~(2 * worst[cand] <= tol_deg)].tolist())
    out = []
    spans = [(f, int(face_start[f]), int(face_npts[f])) for f in sorted(suspects)]
    polys = [(XY[s:s + n], np.cumsum(ring_size[face_first_ring[f]:face_first_ring[f] + face_nrings[f]]))
             for f, s, n in spans]
    for (f, s, n), tri in zip(spans, constrained_delaunay_many(polys)):
        if tri is None:  # a triangulation failure is not a planarity defect
            continue
        dev = _normals_deviation(V[ids[s:s + n]], tri, tol_deg)
        if dev is not None:
            out.append((f, 204, info_204(dev, tol_deg)))
    return out
