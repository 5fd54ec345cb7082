"""Stage 3 of the repair ladder ("Output A+"): cut out corrupted neighbourhoods and refill.

The faces touching a non-manifold edge or vertex, an edge walked twice in one direction or
a crossing face pair (found on the face graph and by triangle tests) are removed together
with their k-ring of neighbours (k = 0, 1, 2); the shell is then cleaned, re-oriented and its
holes filled as in stage 2. Small detached pieces left behind (under 5% of the area) are
dropped.
"""
from __future__ import annotations

from collections import defaultdict

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.polymesh import PolyMesh, face_area, topology, triangulate_mesh
from lod2energy.repair.cleanup import drop_degenerate, fix_nonplanar, merge_slivers
from lod2energy.repair.holefill import fill_holes
from lod2energy.repair.orientation import orient
from lod2energy.validate.closed import self_intersections, shell_defects


def corrupted_faces(m: PolyMesh) -> set[int]:
    """Faces at non-manifold edges/vertices, misoriented edges or crossings."""
    topo = topology(m)
    bad: set[int] = set()
    for e in topo.nonmanifold + topo.misoriented:
        bad.update(f for f, _ in topo.inc[e])
    nmv = set(topo.nm_vertices)
    if nmv:
        for fi, f in enumerate(m.faces):
            if any(v in nmv for r in f.rings for v in r):
                bad.add(fi)
    tris, owner = triangulate_mesh(m)
    for i, j in self_intersections([(m.vertices, tris, owner)])[0]:
        bad.add(int(owner[i]))
        bad.add(int(owner[j]))
    return bad


def _grow(m: PolyMesh, faces: set[int], k: int) -> set[int]:
    vf = defaultdict(set)
    for fi, f in enumerate(m.faces):
        for r in f.rings:
            for v in r:
                vf[v].add(fi)
    out = set(faces)
    for _ in range(k):
        nxt = set(out)
        for fi in out:
            for r in m.faces[fi].rings:
                for v in r:
                    nxt |= vf[v]
        out = nxt
    return out


def drop_small_components(m: PolyMesh, share: float = 0.05) -> PolyMesh:
    """Drop face components holding less than ``share`` of the total area."""
    topo = topology(m)
    if topo.components <= 1:
        return m
    areas = np.array([face_area(m.vertices, f) for f in m.faces])
    tot = areas.sum()
    keep = []
    for lab in np.unique(topo.labels):
        sel = topo.labels == lab
        if areas[sel].sum() >= share * tot:
            keep.extend(np.flatnonzero(sel).tolist())
    return m.with_faces([m.faces[i] for i in sorted(keep)])


def close(m: PolyMesh, tol: Tolerances) -> PolyMesh:
    """Orient, fill, merge new slivers, split bad new polygons, re-orient (stage-2 closing).

    Runs up to three rounds: a round can leave zero-area triangles (collinear vertices of a
    fill) whose removal opens slits that the next round zips.
    """
    m = orient(m)
    for _ in range(3):
        m = drop_degenerate(fill_holes(m, tol))
        m = merge_slivers(m, tol, only_new=True)
        m = drop_degenerate(fix_nonplanar(m, tol))
        if not topology(m).boundary:
            break
    return orient(m)


def refill(m: PolyMesh, tol: Tolerances = DEFAULT, rings=(0, 1, 2), accept=None) -> PolyMesh | None:
    """Stage 3: first k-ring cut-and-refill that yields a clean shell, else None.

    Parameters
    ----------
    accept : callable or None
        The acceptance test (default: :func:`shell_defects` finds nothing).
    """
    if accept is None:
        def accept(r):
            return not shell_defects([r], tol, first_only=True)[0]
    bad = corrupted_faces(m)
    best = None
    for k in rings:
        cut = _grow(m, bad, k) if bad else set()
        if cut and len(cut) >= len(m.faces) - 3:
            break
        r = m.with_faces([f for i, f in enumerate(m.faces) if i not in cut])
        r = drop_small_components(r)
        r = close(r, tol)
        if accept(r):
            return r
        best = r
        if not bad:
            break
    del best
    return None
