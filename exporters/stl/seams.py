"""Seams of the STL: where neighbouring triangles must share their edges.

A face whose edge the neighbour holds in two pieces (a T-junction between faces), and a face
triangulated with one long edge along a line its other triangles use in pieces (a row of LoD3
window sills), leave edges in one triangle only: STL readers and OpenFOAM's surfaceCheck then
find the surface open. Both are split at the vertices lying on those edges.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from lod2energy.geometry import split_at_points
from lod2energy.exporters.stl.rows import unique_rows
from lod2energy.energy.zones.shells import ZoneShell

#: A vertex this close (m) to an edge that has no twin (or an open triangle edge) is a T-junction:
#: it is inserted into that edge (:func:`split_t_junctions`, :func:`split_open_edges`).
T_JUNCTION_TOL = 1e-3


def split_t_junctions(z: ZoneShell, tol: float = T_JUNCTION_TOL) -> ZoneShell:
    """``z`` with the vertices that lie on an edge without a twin (a T-junction: the neighbour
    has the edge in two pieces) inserted into that edge, so that its triangles share both
    pieces; ``z`` itself when no edge lacks a twin."""
    rings = [list(r) for f in z.faces for r in f.rings]
    directed = {(r[k], r[(k + 1) % len(r)]) for r in rings for k in range(len(r))}
    if all((b, a) in directed for a, b in directed):
        return z
    split = iter(split_at_points(z.vertices, rings, tol, only_unmatched=True))
    faces = tuple(replace(f, rings=tuple(tuple(next(split)) for _ in f.rings)) for f in z.faces)
    return replace(z, faces=faces)


def split_open_edges(v: np.ndarray, t: np.ndarray, c: np.ndarray, tol: float = T_JUNCTION_TOL,
                     rounds: int = 4) -> tuple[np.ndarray, np.ndarray]:
    """Split triangles at the vertices lying inside their open edges (T-junctions in a face).

    A face whose holes have collinear edges (the sills of a row of LoD3 windows) can be
    triangulated with one long triangle edge along that line, while the triangles on the
    other side of it use its pieces between the window corners: the long edge and its pieces
    are each in one triangle only. Each such triangle ``(a, b, o)`` with the vertices
    ``w1 .. wn`` lying on ``ab`` (within ``tol``, strictly between ``a`` and ``b``) becomes the
    fan ``(a, w1, o), (w1, w2, o), ..., (wn, b, o)``: same surface, same orientation, and every
    piece of the line now in two triangles. A mesh without open edges is returned as it is.

    Parameters
    ----------
    v : (n, 3) float, m
    t : (t, 3) int
    c : (t,) int
        Each triangle's value, kept by its pieces.
    tol : float, m
        Largest distance of a vertex from the edge it splits.

    Returns
    -------
    triangles (t', 3) int, values (t',) int
    """
    for _ in range(rounds):
        if not len(t):
            break
        e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
        u, inv, cnt = unique_rows(e, return_inverse=True, return_counts=True)
        open_ = cnt[inv.ravel()] == 1
        if not open_.any():
            break
        nt = len(t)
        cand = np.unique(u[cnt == 1].ravel())  # the T vertices end open edges themselves
        P = v[cand]
        new_t, new_c, done = [], [], np.zeros(nt, dtype=bool)
        for j in np.flatnonzero(open_):
            k, side = j % nt, j // nt
            if done[k]:
                continue
            a, b, o = t[k, side], t[k, (side + 1) % 3], t[k, (side + 2) % 3]
            ab = v[b] - v[a]
            L2 = float(ab @ ab)
            if L2 <= 0:
                continue
            s = (P - v[a]) @ ab / L2
            d = np.linalg.norm(P - (v[a] + s[:, None] * ab), axis=1)
            eps = tol / np.sqrt(L2)
            on = (d <= tol) & (s > eps) & (s < 1 - eps) & (cand != a) & (cand != b) & (cand != o)
            if not on.any():
                continue
            ws = cand[on][np.argsort(s[on], kind="stable")]
            chain = [a, *ws.tolist(), b]
            new_t.extend((chain[i], chain[i + 1], o) for i in range(len(chain) - 1))
            new_c.extend([c[k]] * (len(chain) - 1))
            done[k] = True
        if not done.any():
            break
        t = np.concatenate([t[~done], np.asarray(new_t, dtype=t.dtype).reshape(-1, 3)])
        c = np.concatenate([c[~done], np.asarray(new_c, dtype=c.dtype)])
    return t, c
