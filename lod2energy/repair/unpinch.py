"""Part of stage 3 ("Output A+"): separate sheets that touch at a non-manifold edge or vertex.

Reconstructed LoD2.2 buildings often have two roof or wall sheets that meet along one edge
(four faces on the edge) or at one vertex (two fans around it): val3dity's 303. Cutting the
neighbourhood out and refilling it (:mod:`refill`) then has to fill a pinched hole and often
fails. Here nothing is cut: at every non-manifold edge the incident faces are paired around
the edge so that each pair bounds one wedge of material; every vertex then gets one copy per
fan of faces (faces linked through two-face edges and through those pairs), and each copy is
moved ``offset`` metres into its own fan's material. The sheets no longer touch, every edge
is used by two faces, and only the pinch vertices move (by a few millimetres, below val3dity's
planarity tolerance).
"""
from __future__ import annotations

from collections import defaultdict

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.polymesh import Face, PolyMesh, face_normal, fan_groups, topology

#: Distance (m) each copy of a pinch vertex moves into its own material: more than the
#: clean-up's T-junction distance (5 mm, which would zip the sheets together again) and
#: under val3dity's planarity tolerance (10 mm). Default of ``Tolerances.unpinch_offset``.
OFFSET = DEFAULT.unpinch_offset


def _edge_pairs(m: PolyMesh, e: tuple[int, int], lst: list[tuple[int, int]], normals: np.ndarray,
                bridge: bool = False) -> list[tuple[int, int]] | None:
    """Pair the faces around non-manifold edge ``e`` by the wedges between them.

    Faces are sorted by the angle of their in-face direction around the edge; two angular
    neighbours bound material when the bisector between them lies behind both (outward)
    normals. Faces bounding the same wedge of material are paired (``bridge``: the same
    empty wedge). A valid pairing uses every face once and joins opposite edge directions.
    """
    if len(lst) % 2 or sum(d for _, d in lst) != 0 or len({f for f, _ in lst}) != len(lst):
        return None
    V = m.vertices
    a, b = e
    axis = V[b] - V[a]
    L = np.linalg.norm(axis)
    if L == 0:
        return None
    axis = axis / L
    w1 = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    w1 /= np.linalg.norm(w1)
    w2 = np.cross(axis, w1)
    ang = []
    for f, d in lst:
        n = normals[f]
        if not np.any(n):
            return None
        # the face lies to the left of its own walking direction (seen from outside)
        inward = np.cross(n, axis * d)
        ang.append(float(np.arctan2(inward @ w2, inward @ w1)))
    order = np.argsort(ang, kind="stable")
    k = len(order)
    # the two ways of pairing angular neighbours; each must join opposite edge directions
    best, best_votes = None, -1
    for start in (0, 1):
        pairs, votes = [], 0
        for s in range(start, start + k, 2):
            i, j = order[s % k], order[(s + 1) % k]
            if lst[i][1] == lst[j][1]:
                pairs = None
                break
            t0, t1 = ang[i], ang[j] + (2 * np.pi if (s + 1) % k < s % k else 0.0)
            mid = 0.5 * (t0 + t1)
            bis = np.cos(mid) * w1 + np.sin(mid) * w2
            material = bis @ normals[lst[i][0]] < 0 and bis @ normals[lst[j][0]] < 0
            empty = bis @ normals[lst[i][0]] > 0 and bis @ normals[lst[j][0]] > 0
            votes += int(empty if bridge else material)
            pairs.append((lst[i][0], lst[j][0]))
        if pairs is not None and votes > best_votes:
            best, best_votes = pairs, votes
    return best


def _corner_direction(normals: list[np.ndarray]) -> np.ndarray:
    """Sum of the distinct unit normals of a fan: points out of its corner (unweighted, so a
    large roof face does not hide the walls)."""
    distinct: list[np.ndarray] = []
    for n in normals:
        if np.any(n) and all(n @ d < 0.999 for d in distinct):
            distinct.append(n)
    return np.sum(distinct, axis=0) if distinct else np.zeros(3)


def unpinch(m: PolyMesh, tol: Tolerances = DEFAULT, offset: float | None = None, bridge: bool = False
            ) -> PolyMesh | None:
    """Separate the sheets of ``m`` that meet at non-manifold edges or vertices.

    Parameters
    ----------
    m : PolyMesh
        A consistently and outward oriented shell (see :func:`orientation.orient`).
    tol : Tolerances
    offset : float, m
        How far each copy of a pinch vertex moves into its own fan's material (default
        ``tol.unpinch_offset``).
    bridge : bool
        Pair the faces around a non-manifold edge across the empty wedges instead, and move
        the copies into those wedges: the sheets are joined by a thin bridge of material
        rather than separated (the other of the two ways to make the edge 2-manifold).

    Returns
    -------
    PolyMesh or None
        The separated shell (new vertices appended), or None when there is no pinch or the
        faces around a non-manifold edge cannot be paired consistently.
    """
    offset = tol.unpinch_offset if offset is None else offset
    topo = topology(m)
    if not topo.nonmanifold and not topo.nm_vertices:
        return None
    normals = np.array([face_normal(m.vertices, f) for f in m.faces]).reshape(-1, 3)
    # face links around each vertex: two-face edges and the wedge pairs of non-manifold edges
    links: dict[int, list[tuple[int, int]]] = defaultdict(list)
    for e, lst in topo.inc.items():
        if len(lst) == 2:
            pairs = [(lst[0][0], lst[1][0])]
        elif len(lst) > 2:
            pairs = _edge_pairs(m, e, lst, normals, bridge)
            if pairs is None:
                return None
        else:
            continue
        for v in e:
            links[v].extend(pairs)
    on_edges = {v for e in topo.nonmanifold for v in e}
    suspects = on_edges | set(topo.nm_vertices)
    vf: dict[int, list[int]] = defaultdict(list)
    for fi, f in enumerate(m.faces):
        for v in {v for r in f.rings for v in r}:
            if v in suspects:
                vf[v].append(fi)
    V = [p for p in np.asarray(m.vertices, dtype=np.float64)]
    remap: dict[tuple[int, int], int] = {}  # (face, old vertex) -> new vertex
    moved = 0
    for v in sorted(suspects):
        fans = fan_groups(vf.get(v, []), links.get(v, ()))
        if len(fans) < 2:
            continue
        for k, fan in enumerate(sorted(fans)):
            n = _corner_direction([normals[f] for f in fan])
            ln = np.linalg.norm(n)
            if ln == 0:
                return None
            sign = 1.0 if (bridge and v in on_edges) else -1.0
            p = m.vertices[v] + sign * n / ln * offset
            if k == 0:
                V[v] = p
                idx = v
            else:
                idx = len(V)
                V.append(p)
            for f in fan:
                remap[(f, v)] = idx
            moved += 1
    if not moved:
        return None
    faces = []
    for fi, f in enumerate(m.faces):
        rings = tuple(tuple(remap.get((fi, v), v) for v in r) for r in f.rings)
        faces.append(Face(rings, f.source, f.semantic))
    return PolyMesh(np.asarray(V), tuple(faces))


__all__ = ["unpinch", "OFFSET"]
