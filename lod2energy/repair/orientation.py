"""Stage 1 of the repair ladder: coherent orientation over the face graph, then outward.

Faces are flipped so that every edge shared by exactly two faces is walked in opposite
directions (breadth-first from the lowest face of each component); a component whose signed
volume is negative is then flipped as a whole. Nothing moves.
"""
from __future__ import annotations

from collections import deque

from lod2energy.polymesh import PolyMesh, edge_faces, signed_volume


def orient(m: PolyMesh) -> PolyMesh:
    """Coherently and outward oriented copy of ``m`` (faces flipped, never moved)."""
    faces = list(m.faces)
    n = len(faces)
    if n == 0:
        return m
    inc = edge_faces(faces)
    adj: list[list[tuple[int, int]]] = [[] for _ in range(n)]
    for e, lst in inc.items():
        if len(lst) != 2:
            continue  # boundary and non-manifold edges say nothing reliable
        (f, df), (g, dg) = lst
        if f == g:
            continue
        same = 1 if df == dg else 0  # same direction: one of the two must flip
        adj[f].append((g, same))
        adj[g].append((f, same))
    flip = [-1] * n
    comps = []
    for s in range(n):
        if flip[s] >= 0:
            continue
        flip[s] = 0
        comp = [s]
        q = deque([s])
        while q:
            f = q.popleft()
            for g, same in sorted(adj[f]):
                want = flip[f] ^ same
                if flip[g] < 0:
                    flip[g] = want
                    comp.append(g)
                    q.append(g)
        comps.append(comp)
    out = [faces[i].flipped() if flip[i] else faces[i] for i in range(n)]
    for comp in comps:
        sub = PolyMesh(m.vertices, tuple(out[i] for i in comp))
        if signed_volume(sub) < 0:
            for i in comp:
                out[i] = out[i].flipped()
    if all(a is b for a, b in zip(out, faces)):
        return m
    return m.with_faces(out)
