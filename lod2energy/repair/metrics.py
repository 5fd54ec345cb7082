"""Fidelity of a repair: volumetric IoU, mean vertex displacement (mAP_v), Hausdorff distance.

IoU uses exact manifold3d booleans when both shells are closed 2-manifolds. An open or
non-manifold input has no inside; its envelope is then closed by the generalised winding
number (Jacobson et al. 2013: a point is inside when the winding number of the input's
faces around it is >= 1/2) and the IoU is estimated on a fixed grid of sample points in the
union of both bounding boxes (``closure = "winding-number"``).
"""
from __future__ import annotations

import manifold3d as m3d
import numpy as np

from lod2energy.polymesh import PolyMesh, triangulate_mesh


def _manifold(V: np.ndarray, tris: np.ndarray):
    mesh = m3d.Mesh(vert_properties=np.ascontiguousarray(V, dtype=np.float32),
                    tri_verts=np.ascontiguousarray(tris, dtype=np.uint32))
    man = m3d.Manifold(mesh)
    if man.status() != m3d.Error.NoError or man.is_empty():
        return None
    return man


def closed_mesh(m: PolyMesh):
    """``(V, tris)`` of ``m`` recentred near the origin (float32-safe), with the offset."""
    tris, _ = triangulate_mesh(m)
    return m.vertices, tris


def iou_exact(Va, Ta, Vb, Tb, origin) -> float | None:
    """Volumetric IoU by manifold3d booleans, or None when a mesh is not a 2-manifold."""
    a = _manifold(Va - origin, Ta)
    b = _manifold(Vb - origin, Tb)
    if a is None or b is None:
        return None
    inter = (a ^ b).volume()
    union = (a + b).volume()
    # floating-point booleans can give inter a hair above union: IoU is a ratio in [0, 1]
    return min(1.0, float(inter / union)) if union > 0 else None


def winding_number(Q: np.ndarray, V: np.ndarray, tris: np.ndarray, chunk: int = 2048) -> np.ndarray:
    """Generalised winding number of a triangle soup around points.

    Parameters
    ----------
    Q : (q, 3) float
        Query points, m.
    V : (n, 3) float
    tris : (t, 3) int

    Returns
    -------
    (q,) float
        1 inside a closed outward surface, 0 outside, fractional near holes.
    """
    out = np.zeros(len(Q))
    if len(tris) == 0 or len(Q) == 0:
        return out
    # one contiguous (points, triangles) array per coordinate of each corner, rather than
    # (points, triangles, 3) blocks: the same products and sums, in the order numpy's
    # cross / einsum over 3-vectors took them (x, z, then y), so the same bits; 2.5x faster
    P = [[np.ascontiguousarray(V[tris[:, k], j])[None, :] for j in range(3)] for k in range(3)]
    chunk = max(1, min(chunk, 200000 // max(len(tris), 1)))  # bounded memory (~1.6 MB a temporary)
    for s in range(0, len(Q), chunk):
        q = Q[s:s + chunk]
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = ([X - q[:, j:j + 1] for j, X in enumerate(row)] for row in P)
        la = np.sqrt(ax * ax + ay * ay + az * az)
        lb = np.sqrt(bx * bx + by * by + bz * bz)
        lc = np.sqrt(cx * cx + cy * cy + cz * cz)
        det = (ax * (by * cz - bz * cy) + az * (bx * cy - by * cx)) + ay * (bz * cx - bx * cz)
        den = la * lb * lc + ((ax * bx + az * bz) + ay * by) * lc + \
            ((bx * cx + bz * cz) + by * cy) * la + ((cx * ax + cz * az) + cy * ay) * lb
        out[s:s + chunk] = np.arctan2(det, den).sum(axis=1) / (2 * np.pi)
    return out


def _grid(lo, hi, n: int) -> np.ndarray:
    """About ``n`` deterministic points filling the box (cell centres of a regular grid)."""
    ext = np.maximum(hi - lo, 1e-6)
    h = (np.prod(ext) / n) ** (1 / 3)
    k = np.maximum(np.ceil(ext / h).astype(int), 1)
    axes = [lo[i] + (np.arange(k[i]) + 0.5) * ext[i] / k[i] for i in range(3)]
    g = np.meshgrid(*axes, indexing="ij")
    return np.column_stack([x.ravel() for x in g])


def iou_sampled(Va, Ta, Vb, Tb, n: int = 3000) -> float:
    """IoU of two envelopes by winding numbers on a grid of about ``n`` points."""
    P = np.vstack([Va[np.unique(Ta)], Vb[np.unique(Tb)]])
    lo, hi = P.min(axis=0), P.max(axis=0)
    Q = _grid(lo, hi, n)
    ina = winding_number(Q, Va, Ta) >= 0.5
    inb = winding_number(Q, Vb, Tb) >= 0.5
    u = np.count_nonzero(ina | inb)
    return float(np.count_nonzero(ina & inb) / u) if u else 0.0


def point_triangle_distance(P: np.ndarray, V: np.ndarray, tris: np.ndarray, chunk: int = 256) -> np.ndarray:
    """Distance of each point to the nearest triangle, m.

    A k-d tree on the triangles' bounding spheres keeps, for each point, the triangles that can
    be nearest; :func:`_sqdist` measures those pairs, so the result is the one of measuring every
    pair, bit for bit. Degenerate and sliver triangles (where rounding may move the computed
    nearest point off the triangle) are measured against every point, and so is every pair of
    a small, non-finite or not float64 input.

    Parameters
    ----------
    P : (p, 3) float
    V : (n, 3) float
    tris : (t, 3) int
    chunk : int
        Points per block when every pair is measured.

    Returns
    -------
    (p,) float
    """
    A, B, C = V[tris[:, 0]], V[tris[:, 1]], V[tris[:, 2]]
    if len(P) * len(tris) > _ALL_PAIRS_MAX and np.result_type(P, A) == np.float64:
        d2 = _indexed_sqdist(P, A, B, C)
        if d2 is not None:
            return np.sqrt(d2)
    return _all_pairs_distance(P, A, B, C, chunk)


#: Up to this many point-triangle pairs every pair is measured (no index: faster when small).
_ALL_PAIRS_MAX = 20000
#: A triangle is a sliver, measured against every point, when ``|ab x ac|^2 / (|ab| |ac|)`` is below
#: _WIDE x extent^2 (the interior case's denominator ``|ab x ac|^2`` then has a relative rounding
#: error above ~50 eps extent^2 / that, ~6e-3) or ``|ab x ac|^2 / (|ab| |ac| (|ab| + |ac|))`` below _THIN x extent (its
#: nearest point then moves by more than ~50 eps extent^2 / that, ~5e-5 x extent).
_WIDE = 1e-12
_THIN = 1e-10
#: Margin of the pruning bound (x the extent): above that rounding for every triangle not a sliver.
_SLACK = 1e-3
#: Pairs measured at once (bounded memory: about 40 temporaries of (n, 3) floats).
_PAIR_CHUNK = 65536


def _all_pairs_distance(P, A, B, C, chunk: int) -> np.ndarray:
    """Distance of each point to the nearest of the triangles ``(A, B, C)``, every pair measured."""
    out = np.empty(len(P))
    chunk = max(1, min(chunk, 200000 // max(len(A), 1)))
    for s in range(0, len(P), chunk):
        p = P[s:s + chunk, None, :]
        out[s:s + chunk] = np.sqrt(_sqdist(p, A[None], B[None], C[None]).min(axis=1))
    return out


def _indexed_sqdist(P, A, B, C) -> np.ndarray | None:
    """Squared distance of each point to the nearest triangle, only the pairs that can be nearest.

    A pair is left out when the point is farther from the triangle's bounding sphere than from a
    triangle already measured (plus a margin far above the rounding of :func:`_sqdist` on
    triangles that are not slivers). None when an input is not finite or has no extent.

    Parameters
    ----------
    P : (p, 3) float
        Points, m.
    A, B, C : (t, 3) float
        Triangle corners, m.

    Returns
    -------
    (p,) float or None
        Squared distances, m2, equal to :func:`_all_pairs_distance`'s squared.
    """
    from scipy.spatial import cKDTree

    allpts = np.vstack([P, A, B, C])
    if not np.isfinite(allpts).all():
        return None
    ext = float(np.linalg.norm(allpts.max(axis=0) - allpts.min(axis=0)))
    if ext == 0.0:
        return None
    slack = _SLACK * ext
    ab, ac = B - A, C - A
    lab, lac = np.linalg.norm(ab, axis=1), np.linalg.norm(ac, axis=1)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # the interior case divides by |ab x ac|^2: its rounding moves the point by ~eps ext^2 / thin
        wide = np.einsum("ij,ij->i", *(2 * [np.cross(ab, ac)])) / (lab * lac)
        thin = wide / (lab + lac)
    safe = np.flatnonzero((wide >= _WIDE * ext * ext) & (thin >= _THIN * ext))
    unsafe = np.setdiff1d(np.arange(len(A)), safe)
    if len(safe) == 0:
        return None
    cen = (A[safe] + B[safe] + C[safe]) / 3
    rad = np.max([np.linalg.norm(X[safe] - cen, axis=1) for X in (A, B, C)], axis=0)
    # an upper bound per point: the nearest of the triangles with the nearest centroids
    k = min(4, len(safe))
    _, near = cKDTree(cen).query(P, k=k)
    near = near.reshape(len(P), k)
    ub2 = _pairs_sqdist(P, A, B, C, np.repeat(np.arange(len(P)), k), safe[near.ravel()])
    ub = np.sqrt(ub2.reshape(len(P), k).min(axis=1))
    # candidates by bounding sphere, the triangles grouped by radius (a factor 2 within a group)
    level = np.floor(np.log2(rad)).astype(np.int64)
    pi_parts, ti_parts = [], []
    for lv in np.unique(level):
        grp = np.flatnonzero(level == lv)
        hits = cKDTree(cen[grp]).query_ball_point(P, ub + rad[grp].max() + slack, return_sorted=False)
        n = np.fromiter(map(len, hits), dtype=np.intp, count=len(P))
        if not n.sum():
            continue
        pi = np.repeat(np.arange(len(P)), n)
        gi = grp[np.concatenate([h for h in hits if h]).astype(np.intp)]
        keep = np.linalg.norm(P[pi] - cen[gi], axis=1) <= ub[pi] + rad[gi] + slack
        pi_parts.append(pi[keep])
        ti_parts.append(safe[gi[keep]])
    pi = np.concatenate(pi_parts or [np.empty(0, np.intp)])
    ti = np.concatenate(ti_parts or [np.empty(0, np.intp)])
    out = np.full(len(P), np.inf)
    np.minimum.at(out, pi, _pairs_sqdist(P, A, B, C, pi, ti))
    if len(unsafe):  # every point against the slivers, in blocks as without the index
        Au, Bu, Cu = A[unsafe][None], B[unsafe][None], C[unsafe][None]
        step = max(1, 200000 // len(unsafe))
        for s in range(0, len(P), step):
            blk = out[s:s + step]
            np.minimum(blk, _sqdist(P[s:s + step, None, :], Au, Bu, Cu).min(axis=1), out=blk)
    return out


def _pairs_sqdist(P, A, B, C, pi, ti) -> np.ndarray:
    """:func:`_sqdist` of points ``P[pi]`` to triangles ``ti``, in blocks: (len(pi),) float, m2."""
    out = np.empty(len(pi))
    for s in range(0, len(pi), _PAIR_CHUNK):
        p, t = pi[s:s + _PAIR_CHUNK], ti[s:s + _PAIR_CHUNK]
        out[s:s + _PAIR_CHUNK] = _sqdist(P[p], A[t], B[t], C[t])
    return out


def _sqdist(p, a, b, c):
    """Squared distance point-triangle (Ericson, Real-Time Collision Detection 5.1.5), broadcast."""
    ab, ac, ap = b - a, c - a, p - a
    d1 = np.einsum("...k,...k->...", ab, ap)
    d2 = np.einsum("...k,...k->...", ac, ap)
    bp = p - b
    d3 = np.einsum("...k,...k->...", ab, bp)
    d4 = np.einsum("...k,...k->...", ac, bp)
    cp = p - c
    d5 = np.einsum("...k,...k->...", ab, cp)
    d6 = np.einsum("...k,...k->...", ac, cp)
    va = d3 * d6 - d5 * d4
    vb = d5 * d2 - d1 * d6
    vc = d1 * d4 - d3 * d2
    shape = np.broadcast_shapes(d1.shape, va.shape)
    # default: interior projection
    den = va + vb + vc
    den = np.where(np.abs(den) < 1e-300, 1e-300, den)
    v = vb / den
    w = vc / den
    X = a + ab * v[..., None] + ac * w[..., None]
    # edge ab
    m_ab = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
    t = d1 / np.where(np.abs(d1 - d3) < 1e-300, 1e-300, d1 - d3)
    X = np.where(m_ab[..., None], a + ab * t[..., None], X)
    m_ac = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
    t = d2 / np.where(np.abs(d2 - d6) < 1e-300, 1e-300, d2 - d6)
    X = np.where(m_ac[..., None], a + ac * t[..., None], X)
    m_bc = (va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0)
    t = (d4 - d3) / np.where(np.abs((d4 - d3) + (d5 - d6)) < 1e-300, 1e-300, (d4 - d3) + (d5 - d6))
    X = np.where(m_bc[..., None], b + (c - b) * t[..., None], X)
    X = np.where(((d1 <= 0) & (d2 <= 0))[..., None], np.broadcast_to(a, X.shape), X)
    X = np.where(((d3 >= 0) & (d4 <= d3))[..., None], np.broadcast_to(b, X.shape), X)
    X = np.where(((d6 >= 0) & (d5 <= d6))[..., None], np.broadcast_to(c, X.shape), X)
    del shape
    return np.einsum("...k,...k->...", p - X, p - X)


def surface_samples(V: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Vertices, edge midpoints and centroids of the triangles: (s, 3) float."""
    T = V[tris]
    return np.vstack([V[np.unique(tris)], (T[:, 0] + T[:, 1]) / 2, (T[:, 1] + T[:, 2]) / 2,
                      (T[:, 2] + T[:, 0]) / 2, T.mean(axis=1)])


def fidelity(inp: PolyMesh, out: PolyMesh, input_closed: bool, envelope: PolyMesh | None = None,
             envelope_name: str = "holefill") -> dict:
    """Fidelity of ``out`` to ``inp``.

    Parameters
    ----------
    inp : PolyMesh
        The input shell (distances are measured to and from it).
    out : PolyMesh
        The repaired shell.
    input_closed : bool
        ``inp`` bounds a volume by itself (exact IoU on it).
    envelope : PolyMesh or None
        The input's envelope for the IoU: a closed input re-oriented outward, or an open
        input closed without moving anything (its boundary loops filled,
        ``closure = envelope_name``). Without one (or when it is not a 2-manifold) an open
        input is closed by the winding number.

    Returns
    -------
    dict
        ``iou``; ``mean_displacement`` (m, mean distance of the input's vertices to the output
        surface, mAP_v); ``mean_displacement_back`` (m, output vertices to the input surface);
        ``hausdorff`` (m, both directions, on vertices, edge midpoints and centroids);
        ``closure`` (how the input envelope was closed for the IoU).
    """
    Va, Ta = closed_mesh(inp)
    Vb, Tb = closed_mesh(out)
    if len(Ta) == 0 or len(Tb) == 0:
        return {"iou": 0.0, "mean_displacement": float("nan"), "mean_displacement_back": float("nan"),
                "hausdorff": float("nan"), "closure": "none"}
    origin = Va[np.unique(Ta)].mean(axis=0)
    iou, closure = None, "closed"
    if input_closed and envelope is None:
        iou = iou_exact(Va, Ta, Vb, Tb, origin)
    elif envelope is not None:
        Ve, Te = closed_mesh(envelope)
        if len(Te):
            iou = iou_exact(Ve, Te, Vb, Tb, origin)
            closure = "closed" if input_closed else envelope_name
    if iou is None:
        closure = "winding-number"
        iou = iou_sampled(Va - origin, Ta, Vb - origin, Tb)
    pa = Va[np.unique(Ta)]
    pb = Vb[np.unique(Tb)]
    d_ab = point_triangle_distance(pa, Vb, Tb)
    # back to the input's envelope: a filled hole has no input surface to be near to
    Vr, Tr = (closed_mesh(envelope) if envelope is not None and closure != "winding-number" else (Va, Ta))
    d_ba = point_triangle_distance(pb, Vr, Tr)
    h1 = point_triangle_distance(surface_samples(Vr, Tr), Vb, Tb).max()
    h2 = point_triangle_distance(surface_samples(Vb, Tb), Vr, Tr).max()
    return {"iou": float(iou), "mean_displacement": float(d_ab.mean()),
            "mean_displacement_back": float(d_ba.mean()),
            "hausdorff": float(max(h1, h2, d_ab.max(), d_ba.max())), "closure": closure}
