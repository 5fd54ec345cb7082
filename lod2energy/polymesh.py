"""The indexed polygon mesh every repair stage (and the IDF zone fallback) works on.

A :class:`PolyMesh` is one shell: its own vertex array and a tuple of :class:`Face` (rings
of vertex indices, the index of the input face it derives from, and the semantic index it
carries). Faces stay polygons; only what must change is triangulated. Here: the types, their
topology (edge incidence, boundary / non-manifold edges and vertices, components) and the
per-face measures; the maths itself is :mod:`lod2energy.geometry`.
"""
from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field
from itertools import accumulate

import numpy as np
import shapely

from lod2energy import cache
from lod2energy.geometry import (
    constrained_delaunay, earcut_rings, newell_normal, plane_basis, plane_distance, rings_normal,
    signed_volume as _signed_volume,
)
from lod2energy.geometry.vectors import vector_length

__all__ = ["Face", "PolyMesh", "Topology", "face_normal", "face_area", "planarity", "triangulate_face",
           "triangulate_mesh", "signed_volume", "edge_faces", "topology", "fan_groups", "nonmanifold_vertices",
           "compact", "split_loop", "ring_is_simple_2d", "triangles_to_mesh", "merge_coplanar"]


@dataclass(frozen=True)
class Face:
    """One polygon of a shell being repaired.

    Parameters
    ----------
    rings : tuple of tuple of int
        Outer ring first, then holes; open rings of indices into ``PolyMesh.vertices``.
    source : int
        Index of the input face this one derives from (-1: new face made by a repair stage).
    semantic : int or None
        Semantic surface index carried over from the input face (None for new faces).
    """

    rings: tuple[tuple[int, ...], ...]
    source: int = -1
    semantic: int | None = None

    @property
    def outer(self) -> tuple[int, ...]:
        return self.rings[0]

    def flipped(self) -> "Face":
        return Face(tuple(tuple(reversed(r)) for r in self.rings), self.source, self.semantic)

    def edges(self):
        """Directed edges ``(a, b)`` of every ring."""
        for r in self.rings:
            n = len(r)
            for i in range(n):
                yield r[i], r[(i + 1) % n]


@dataclass(frozen=True)
class PolyMesh:
    """A shell being repaired.

    Parameters
    ----------
    vertices : (n, 3) float
        Coordinates, m.
    faces : tuple of Face
    """

    vertices: np.ndarray
    faces: tuple[Face, ...] = field(default_factory=tuple)

    def with_faces(self, faces, vertices=None) -> "PolyMesh":
        return PolyMesh(self.vertices if vertices is None else vertices, tuple(faces))

    @property
    def n_faces(self) -> int:
        return len(self.faces)


# ----------------------------------------------------------------------------- per-face measures

def face_normal(V: np.ndarray, f: Face) -> np.ndarray:
    """Unit normal of a face (outer ring minus holes by Newell); zero vector if degenerate."""
    return rings_normal(V, f.rings, centred=False)


def face_area(V: np.ndarray, f: Face) -> float:
    """Area of a face, m2 (outer ring minus holes, projected on its own plane)."""
    a = vector_length(newell_normal(V[list(f.outer)], centred=False)) / 2
    for r in f.rings[1:]:
        a -= vector_length(newell_normal(V[list(r)], centred=False)) / 2
    return a


def planarity(V: np.ndarray, f: Face) -> tuple[float, float]:
    """(largest distance to the fitted plane, m; largest normal deviation of its triangles, deg)."""
    idx = [i for r in f.rings for i in r]
    P = V[idx]
    if len(P) <= 3:
        return 0.0, 0.0
    d = plane_distance(P)
    tris = triangulate_face(V, f)
    if len(tris) < 2:
        return d, 0.0
    T = V[tris]
    tn = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    ln = np.linalg.norm(tn, axis=1)
    ok = ln > 1e-12
    if ok.sum() < 2:
        return d, 0.0
    tn = tn[ok] / ln[ok, None]
    ref = tn[np.argmax(ln[ok])]
    dev = float(np.degrees(np.arccos(np.clip(tn @ ref, -1, 1))).max())
    return d, dev


#: Faces whose triangles are kept per process (:mod:`lod2energy.cache`): enough for the faces
#: of the buildings a job handles, small enough that a worker's memory does not grow with the file.
KEPT_FACES = 8192


def triangulate_face(V: np.ndarray, f: Face) -> np.ndarray:
    """Triangles of a polygon (with holes) by ear clipping in its own plane.

    Returns
    -------
    (t, 3) int
        Indices into ``V``, oriented like the face.
    """
    if len(f.rings) == 1 and len(f.rings[0]) == 3:
        return np.array([f.rings[0]], dtype=np.int64)
    key = (f.rings, V[[i for r in f.rings for i in r]].tobytes())
    return cache.remember("polymesh.face-triangles", key, lambda: _read_only(_triangulate_face(V, f)), KEPT_FACES)


def _read_only(a: np.ndarray) -> np.ndarray:
    a.setflags(write=False)
    return a


def _triangulate_face(V: np.ndarray, f: Face) -> np.ndarray:
    rings = [list(r) for r in f.rings if len(r) >= 3]
    if not rings:
        return np.zeros((0, 3), dtype=np.int64)
    if len(rings) == 1 and len(rings[0]) == 3:
        return np.array([rings[0]], dtype=np.int64)
    n = face_normal(V, f)
    if not n.any():
        n = np.array([0, 0, 1.0])
    B = plane_basis(n)
    idx = np.array([i for r in rings for i in r], dtype=np.int64)
    P = V[idx]
    P2 = (P - P.mean(axis=0)) @ B.T
    ends = np.fromiter(accumulate(len(r) for r in rings), dtype=np.uint32, count=len(rings))
    t = earcut_rings(P2, ends)
    if len(t):
        p, q, r = P2[t[:, 0]], P2[t[:, 1]], P2[t[:, 2]]
        ar = (q[:, 0] - p[:, 0]) * (r[:, 1] - p[:, 1]) - (q[:, 1] - p[:, 1]) * (r[:, 0] - p[:, 0])
        if (ar < 0).all():
            t = t[:, ::-1]  # earcut answers clockwise: the face walks counter-clockwise here
            ar = -ar
        if (ar < 1e-9).any() or len(t) != len(idx) - 2 + 2 * (len(rings) - 1):
            t = None  # needles or gaps: ask for the constrained Delaunay triangulation
    if t is None:
        try:
            t = np.asarray(constrained_delaunay(P2, ends.astype(np.intp)), dtype=np.int64).reshape(-1, 3)
        except Exception:  # noqa: BLE001
            t = np.zeros((0, 3), dtype=np.int64)
    if len(t) == 0 and len(rings[0]) >= 3:
        r = rings[0]  # earcut gave up (degenerate projection): a fan keeps the faces counted
        t = np.array([[0, i, i + 1] for i in range(1, len(r) - 1)], dtype=np.int64)
    tri = idx[t]
    # earcut keeps the 2D orientation of its input; our basis is right-handed with n, so
    # counter-clockwise in 2D = the face's own orientation
    return tri


def triangulate_mesh(m: PolyMesh) -> tuple[np.ndarray, np.ndarray]:
    """All faces triangulated.

    Returns
    -------
    tris : (t, 3) int
    owner : (t,) int
        Index of the face each triangle comes from.
    """
    out, own = [], []
    for i, f in enumerate(m.faces):
        t = triangulate_face(m.vertices, f)
        out.append(t)
        own.append(np.full(len(t), i, dtype=np.int64))
    if not out:
        return np.zeros((0, 3), dtype=np.int64), np.zeros(0, dtype=np.int64)
    return np.vstack(out), np.concatenate(own)


def signed_volume(m: PolyMesh, tris: np.ndarray | None = None) -> float:
    """Signed volume of the shell, m3 (relative to its centroid; positive = outward normals)."""
    if tris is None:
        tris, _ = triangulate_mesh(m)
    return _signed_volume(m.vertices, tris, origin="centroid")


# ----------------------------------------------------------------------------- topology

def _find(parent, x):
    """Root of ``x`` in a union-find forest ``parent`` (list or dict), halving the path."""
    while parent[x] != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x


def edge_faces(faces) -> dict[tuple[int, int], list[tuple[int, int]]]:
    """Undirected edge ``(min, max)`` -> list of ``(face_index, +1 if min->max else -1)``."""
    inc: dict[tuple[int, int], list[tuple[int, int]]] = defaultdict(list)
    for fi, f in enumerate(faces):
        fwd, bwd = (fi, 1), (fi, -1)
        for r in f.rings:  # the edges of Face.edges, in its order, without a generator
            for a, b in zip(r, r[1:] + r[:1]):
                if a < b:
                    inc[(a, b)].append(fwd)
                elif a > b:
                    inc[(b, a)].append(bwd)
    return inc


@dataclass
class Topology:
    """Edge incidence summary of a shell.

    ``boundary`` : edges used once; ``nonmanifold`` : edges used more than twice;
    ``misoriented`` : edges used twice in the same direction; ``nm_vertices`` : vertices
    whose incident faces form more than one fan; ``components`` : number of face components.
    """

    inc: dict
    boundary: list
    nonmanifold: list
    misoriented: list
    nm_vertices: list
    components: int
    labels: np.ndarray


def topology(m: PolyMesh) -> Topology:
    inc = edge_faces(m.faces)
    boundary, nonman, misor = [], [], []
    n = len(m.faces)
    parent = list(range(n))
    for e, lst in inc.items():
        k = len(lst)
        if k == 1:
            boundary.append(e)
        elif k > 2:
            nonman.append(e)
        else:
            if lst[0][1] == lst[1][1]:
                misor.append(e)
        for (f, _) in lst[1:]:
            ra, rb = _find(parent, lst[0][0]), _find(parent, f)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    labels = np.array([_find(parent, i) for i in range(n)], dtype=np.int64)
    ncomp = len(set(labels.tolist()))
    nmv = nonmanifold_vertices(m.faces, inc)
    return Topology(inc, sorted(boundary), sorted(nonman), sorted(misor), nmv, ncomp, labels)


def fan_groups(faces, links) -> list[list[int]]:
    """Connected groups of ``faces`` (ids) where each item of ``links`` (a sequence of face ids)
    joins its members; faces outside ``faces`` are ignored. Groups in order of first face."""
    parent = {f: f for f in faces}
    for grp in links:
        grp = [g for g in grp if g in parent]
        for g in grp[1:]:
            ra, rb = _find(parent, grp[0]), _find(parent, g)
            if ra != rb:
                parent[rb] = ra
    out: dict[int, list[int]] = {}
    for f in faces:
        out.setdefault(_find(parent, f), []).append(f)
    return list(out.values())


def nonmanifold_vertices(faces, inc) -> list[int]:
    """Vertices where the incident faces form more than one edge-connected fan."""
    vf: dict[int, set] = defaultdict(set)
    for fi, f in enumerate(faces):
        for r in f.rings:
            for v in r:
                vf[v].add(fi)
    # faces around v are linked when they share an edge containing v
    links: dict[int, list] = defaultdict(list)
    for (a, b), lst in inc.items():
        if len(lst) < 2:
            continue
        fs = [f for f, _ in lst]
        links[a].append(fs)
        links[b].append(fs)
    bad = []
    for v, fs in vf.items():
        if len(fs) <= 1:
            continue
        if len(fan_groups(fs, links.get(v, ()))) > 1:
            bad.append(v)
    return sorted(bad)


def split_loop(r: list[int]) -> list[list[int]]:
    """Split a closed vertex loop at repeated vertices into loops without repeats."""
    out, stack, pos = [], [], {}
    for v in r:
        if v in pos:
            k = pos[v]
            sub = stack[k:]
            out.append(sub)
            for u in sub[1:]:
                pos.pop(u, None)
            stack = stack[:k + 1]
        else:
            pos[v] = len(stack)
            stack.append(v)
    if len(stack) >= 3:
        out.append(stack)
    return out


def compact(m: PolyMesh) -> PolyMesh:
    """Drop unused vertices (indices renumbered in order of first use of the old order)."""
    used = sorted({i for f in m.faces for r in f.rings for i in r})
    lut = {o: n for n, o in enumerate(used)}
    faces = tuple(Face(tuple(tuple(lut[i] for i in r) for r in f.rings), f.source, f.semantic)
                  for f in m.faces)
    return PolyMesh(m.vertices[used] if used else np.zeros((0, 3)), faces)


def ring_is_simple_2d(P2: np.ndarray) -> bool:
    """True when a 2D ring does not touch or cross itself."""
    if len(P2) < 3:
        return False
    try:
        return bool(shapely.LinearRing(P2).is_simple)
    except Exception:  # noqa: BLE001 - shapely raises on degenerate rings
        return False


def triangles_to_mesh(V: np.ndarray, tris: np.ndarray) -> PolyMesh:
    """A PolyMesh of new triangle faces."""
    return PolyMesh(np.asarray(V, dtype=np.float64), tuple(Face((tuple(int(i) for i in t),)) for t in tris))


def merge_coplanar(m: PolyMesh, angle_tol: float = 1e-3, dist_tol: float = 1e-4) -> PolyMesh:
    """Merge edge-adjacent new (source -1) triangles lying in one plane into polygons.

    Used on alpha wraps and hulls to keep the face count low. A merged region becomes one
    polygon (holes allowed) only when its boundary forms simple rings; else it stays as is.
    """
    faces = list(m.faces)
    V = m.vertices
    inc = edge_faces(faces)
    normals = [face_normal(V, f) for f in faces]
    n = len(faces)
    parent = list(range(n))
    for (a, b), lst in inc.items():
        if len(lst) != 2:
            continue
        (f, _), (g, _) = lst
        if faces[f].source != faces[g].source or faces[f].semantic != faces[g].semantic:
            continue
        if np.dot(normals[f], normals[g]) < 1 - angle_tol:
            continue
        # same plane, not just parallel
        p = V[faces[g].outer[0]]
        if abs(np.dot(p - V[faces[f].outer[0]], normals[f])) > dist_tol:
            continue
        rf, rg = _find(parent, f), _find(parent, g)
        if rf != rg:
            parent[max(rf, rg)] = min(rf, rg)
    groups: dict[int, list[int]] = defaultdict(list)
    for i in range(n):
        groups[_find(parent, i)].append(i)
    out = []
    for root in sorted(groups):
        g = groups[root]
        if len(g) == 1:
            out.append(faces[g[0]])
            continue
        merged = _merge_group(V, [faces[i] for i in g])
        out.extend(merged)
    return PolyMesh(V, tuple(out))


def _merge_group(V, group: list[Face]) -> list[Face]:
    """Union of coplanar faces as one polygon when its boundary is made of simple rings."""
    cnt: dict[tuple[int, int], int] = defaultdict(int)
    for f in group:
        for a, b in f.edges():
            cnt[(a, b)] += 1
    bnd = [(a, b) for (a, b) in cnt if (b, a) not in cnt]
    nxt: dict[int, list[int]] = defaultdict(list)
    for a, b in bnd:
        nxt[a].append(b)
    if any(len(v) != 1 for v in nxt.values()):
        return group
    rings, seen = [], set()
    for a, _ in sorted(bnd):
        if a in seen:
            continue
        r = [a]
        seen.add(a)
        c = nxt[a][0]
        while c != a:
            if c in seen:
                return group
            r.append(c)
            seen.add(c)
            c = nxt[c][0]
        rings.append(tuple(r))
    if any(len(r) < 3 for r in rings):
        return group
    n = face_normal(V, group[0])
    areas = [float(np.dot(newell_normal(V[list(r)], centred=False), n)) for r in rings]
    outer = [i for i, a in enumerate(areas) if a > 0]
    if len(outer) != 1:
        return group
    o = outer[0]
    rings = [rings[o]] + [r for i, r in enumerate(rings) if i != o]
    f = Face(tuple(rings), group[0].source, group[0].semantic)
    B = plane_basis(n)
    for r in rings:
        if not ring_is_simple_2d(V[list(r)] @ B.T):
            return group
    return [f]
