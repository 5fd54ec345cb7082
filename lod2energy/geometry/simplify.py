"""Mesh simplification: collapse short edges.

Coplanar faces are merged on the polygon mesh (:func:`lod2energy.polymesh.merge_coplanar`).
"""
from __future__ import annotations

import numpy as np

__all__ = ["collapse_short_edges"]


def collapse_short_edges(v: np.ndarray, t: np.ndarray, c: np.ndarray, tol: float
                         ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Collapse edges shorter than ``tol`` (m) one at a time, keeping the mesh 2-manifold.

    Unions leave micro-edges where a vertex of one part lies a few micrometres off a face of
    another; the triangles around them are slivers that STL readers see as degenerate (a
    binary STL stores float32, so endpoints closer than about 1e-6 m become one point).
    Shortest edges first, an edge a-b is collapsed only when it is used by exactly two
    triangles and the link condition holds (the vertices adjacent to both a and b are the
    two opposite vertices of those triangles): collapsing all short edges at once can pinch
    the surface into an edge used by four triangles. The surviving endpoint keeps its
    position; the collapse is tried the other way round, and skipped, when it would turn the
    normal of a remaining triangle by more than 60 degrees or flatten it.

    Parameters
    ----------
    v : (n, 3) float
        Vertices (m).
    t : (t, 3) int
        Triangles, closed and consistently wound.
    c : (t,) int
        A value per triangle (kept for the triangles that stay).
    tol : float
        Edge length (m) below which edges are collapsed.

    Returns
    -------
    vertices (n', 3) float, triangles (t', 3) int, values (t',) int
    """
    v = np.asarray(v, dtype=np.float64)
    t = np.array(t, dtype=np.intp).reshape(-1, 3)
    c = np.asarray(c)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    L = np.linalg.norm(v[e[:, 0]] - v[e[:, 1]], axis=1)
    sel = np.nonzero(L < tol)[0]
    if len(sel) == 0:
        return v, t, c
    sel = sel[np.argsort(L[sel], kind="stable")]
    alive = np.ones(len(t), dtype=bool)
    vt: list[set[int]] = [set() for _ in range(len(v))]
    for i, tri in enumerate(t.tolist()):
        for x in tri:
            vt[x].add(i)

    def ring(x: int) -> set[int]:
        return {int(y) for ti in vt[x] for y in t[ti]} - {x}

    def normal(p: np.ndarray) -> np.ndarray:
        return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])

    def keeps_shape(keep: int, gone: int, shared: set[int]) -> bool:
        moved = sorted(vt[gone] - shared)
        if not moved:
            return True
        tri = t[moved]
        before = normal(v[tri])
        after_idx = np.where(tri == gone, keep, tri)
        after = normal(v[after_idx])
        nb, na = np.linalg.norm(before, axis=1), np.linalg.norm(after, axis=1)
        ok = (na > 1e-12) & (np.einsum("ij,ij->i", before, after) > 0.5 * nb * na)
        return bool(ok.all())

    for a, b in e[sel].tolist():
        if not vt[a] or not vt[b] or np.linalg.norm(v[a] - v[b]) >= tol:
            continue
        shared = vt[a] & vt[b]
        if len(shared) != 2:
            continue
        opposite = {int(y) for ti in shared for y in t[ti]} - {a, b}
        if (ring(a) & ring(b)) != opposite:
            continue
        if keeps_shape(a, b, shared):
            keep, gone = a, b
        elif keeps_shape(b, a, shared):
            keep, gone = b, a
        else:
            continue
        for ti in shared:
            alive[ti] = False
            for x in t[ti]:
                vt[int(x)].discard(ti)
        for ti in vt[gone]:
            t[ti][t[ti] == gone] = keep
            vt[keep].add(ti)
        vt[gone] = set()
    t, c = t[alive], c[alive]
    used, inv = np.unique(t, return_inverse=True)
    return v[used], inv.reshape(-1, 3), c

