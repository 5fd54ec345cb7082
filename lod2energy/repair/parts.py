"""BuildingParts that overlap (601): find them, and merge them into one solid on request.

The union is computed with manifold3d booleans on the parts' closed solids; each face of the
union that lies on a part's face keeps that face's semantic surface (the parts' semantic
lists are concatenated), other faces get none. The merged solid goes on the Building at the
same LoD and the parts keep their attributes but lose that geometry.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.model import Building, Geometry, Shell, Solid, Surface
from lod2energy.polymesh import Face, PolyMesh, compact, merge_coplanar, triangulate_mesh
from lod2energy.repair.accept import is_repaired
from lod2energy.repair.convert import mesh_of_geometry


def _part_meshes(b: Building, lod):
    out = []
    for o in b.objects[1:]:
        if o.type != "BuildingPart":
            continue
        for gi, g in enumerate(o.geometries):
            if g.is_polygonal and g.lod == lod and g.type == "Solid":
                out.append((o, gi, g, mesh_of_geometry(b.vertices, g)))
                break
    return out


def without_geometry(b: Building, ids, lod) -> Building:
    """``b`` with the polygonal geometries at ``lod`` of the objects ``ids`` removed."""
    return replace(b, objects=tuple(
        replace(o, geometries=tuple(g for g in o.geometries if not (g.is_polygonal and g.lod == lod)))
        if o.id in ids else o for o in b.objects))


def _manifold(m: PolyMesh, origin):
    import manifold3d as m3d
    tris, _ = triangulate_mesh(m)
    man = m3d.Manifold(m3d.Mesh(vert_properties=np.ascontiguousarray(m.vertices - origin, dtype=np.float32),
                                tri_verts=np.ascontiguousarray(tris, dtype=np.uint32)))
    return None if man.status() != m3d.Error.NoError else man


def overlapping_parts(b: Building, lod=None, min_volume: float = 1e-6) -> list[tuple[str, str, float]]:
    """Pairs of BuildingParts whose solids share volume: ``(id_a, id_b, m3)``."""
    lod = lod if lod is not None else b.default_lod()
    parts = _part_meshes(b, lod)
    if len(parts) < 2:
        return []
    origin = np.vstack([m.vertices for *_, m in parts]).mean(axis=0)
    mans = [_manifold(m, origin) for *_, m in parts]
    out = []
    for i in range(len(parts)):
        for j in range(i + 1, len(parts)):
            if mans[i] is None or mans[j] is None:
                continue
            v = (mans[i] ^ mans[j]).volume()
            if v > min_volume:
                out.append((parts[i][0].id, parts[j][0].id, float(v)))
    return out


def merge_overlapping_parts(b: Building, tol: Tolerances = DEFAULT, lod=None) -> Building:
    """``b`` with its overlapping parts' solids united on the Building (unchanged if none)."""
    lod = lod if lod is not None else b.default_lod()
    pairs = overlapping_parts(b, lod)
    if not pairs:
        return b
    return merge_parts(b, {a for a, _, _ in pairs} | {c for _, c, _ in pairs}, tol, lod)


def touching_part(b: Building, part_id: str, lod=None, gap: float = 0.01) -> str | None:
    """The BuildingPart whose solid touches or overlaps ``part_id``'s solid (within ``gap``),
    the largest by volume when several do; None when it stands alone.

    Parameters
    ----------
    gap : float, m
        Largest distance between two solids that still touch.
    """
    lod = lod if lod is not None else b.default_lod()
    parts = _part_meshes(b, lod)
    mine = [p for p in parts if p[0].id == part_id]
    if not mine:
        return None
    m0 = mine[0][3]
    lo0, hi0 = m0.vertices.min(axis=0) - gap, m0.vertices.max(axis=0) + gap
    origin = m0.vertices.mean(axis=0)
    a = _manifold(m0, origin)
    if a is None:
        return None
    best, best_vol = None, -1.0
    for o, _, _, m in parts:
        if o.id == part_id or np.any(m.vertices.max(axis=0) < lo0) or np.any(m.vertices.min(axis=0) > hi0):
            continue
        other = _manifold(m, origin)
        # touching solids stay two bodies for manifold3d's booleans: ask for the gap instead
        if other is None or a.min_gap(other, 2 * gap) > gap:
            continue
        if other.volume() > best_vol:
            best, best_vol = o.id, other.volume()
    return best


def merge_parts(b: Building, ids, tol: Tolerances = DEFAULT, lod=None, into: str | None = None) -> Building:
    """``b`` with the solids of the BuildingParts ``ids`` united into one solid.

    The union goes on the Building (it replaces the Building's own geometry at ``lod``), or
    on the part ``into`` (one of ``ids``). ``b`` unchanged when a part has no closed solid
    at ``lod`` or the union is not a valid closed solid. Each union face keeps the semantic
    surface of the part face it lies on; union edges shorter than the snap tolerance are
    collapsed.
    """
    lod = lod if lod is not None else b.default_lod()
    ids = set(ids)
    if into is not None and into not in ids:
        raise ValueError(f"into={into!r} is not one of the parts merged")
    parts = [p for p in _part_meshes(b, lod) if p[0].id in ids]
    if len(parts) < 2 or len(parts) != len(ids):
        return b
    origin = np.vstack([m.vertices for *_, m in parts]).mean(axis=0)
    mans = [_manifold(m, origin) for *_, m in parts]
    if any(x is None for x in mans):
        return b
    union = mans[0]
    for x in mans[1:]:
        union = union + x
    mesh = union.to_mesh()
    V = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3] + origin
    T = np.asarray(mesh.tri_verts, dtype=np.int64)
    # where parts meet, the union leaves sub-millimetre edges (a vertex of one part a hair off
    # a face of the other): collapsed one at a time, keeping the surface 2-manifold
    from lod2energy.geometry import collapse_short_edges
    V, T, _ = collapse_short_edges(V, T, np.zeros(len(T), dtype=np.intp), tol.snap_tol)
    # semantics: the part face each union triangle lies on
    sems, offs = [], []
    for o, gi, g, m in parts:
        offs.append(len(sems))
        sems.extend(g.semantic_surfaces)
    faces = []
    cands = []
    for k, (o, gi, g, m) in enumerate(parts):
        tris, owner = triangulate_mesh(m)
        cands.append((k, m, tris, owner))
    from lod2energy.repair.metrics import _sqdist
    for t in T:
        c = V[t].mean(axis=0)
        n = np.cross(V[t[1]] - V[t[0]], V[t[2]] - V[t[0]])
        n /= np.linalg.norm(n) or 1.0
        src, sem = -1, None
        for k, m, tris, owner in cands:
            A, B, C = m.vertices[tris[:, 0]], m.vertices[tris[:, 1]], m.vertices[tris[:, 2]]
            d = _sqdist(c[None], A, B, C)
            tn = np.cross(B - A, C - A)
            tn /= np.maximum(np.linalg.norm(tn, axis=1), 1e-12)[:, None]
            hit = np.flatnonzero((d < 1e-6) & (tn @ n > 0.999))
            if len(hit):
                f = m.faces[int(owner[hit[0]])]
                src = 100000 * k + f.source
                sem = None if f.semantic is None else offs[k] + f.semantic
                break
        faces.append(Face((tuple(int(i) for i in t),), src, sem))
    merged = compact(merge_coplanar(PolyMesh(V, tuple(faces)), angle_tol=1e-6, dist_tol=1e-4))
    if not is_repaired(merged, lod, tol):
        return b
    base = len(b.vertices)
    surfaces = tuple(Surface.from_lists([[base + i for i in r] for r in f.rings], f.semantic) for f in merged.faces)
    geom = Geometry("Solid", lod, (Solid((Shell(surfaces),)),), tuple(sems))
    target = b.root.id if into is None else into
    nb = without_geometry(b, ids | {target}, lod)
    objs = tuple(replace(o, geometries=o.geometries + (geom,)) if o.id == target else o for o in nb.objects)
    nb = replace(nb, objects=objs, vertices=np.vstack([b.vertices, merged.vertices]))
    done = sorted(set(b.provenance.get("merged_parts") or ()) | ids)
    return nb.with_provenance(merged_parts=done)
