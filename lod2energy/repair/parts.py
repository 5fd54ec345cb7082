"""BuildingParts that overlap (601): find them, and merge them into one solid on request.

The union is computed with manifold3d booleans on the parts' closed solids; each face of the
union that lies on a part's face keeps that face's semantic surface (the parts' semantic
lists are concatenated), other faces get none. The merged solid goes on the Building at the
same LoD and the parts keep their attributes but lose that geometry.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Sequence

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import bbox_pairs, closest_on_triangle, collapse_short_edges
from lod2energy.io.cityjson_grid import building_grid, on_grid
from lod2energy.model import Building, Geometry, Shell, Solid, Surface
from lod2energy.polymesh import Face, PolyMesh, compact, face_area, merge_coplanar, signed_volume, triangulate_mesh
from lod2energy.repair.accept import is_repaired
from lod2energy.repair.convert import mesh_of_geometry
from lod2energy.repair.meshops import PartMeshes, part_mesh, solid_manifold, with_part
from lod2energy.repair.metrics import _sqdist, winding_number
from lod2energy.validate.solid import check_parts_overlap


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


#: Boxes of two parts farther apart than this (m) are not tested for a shared volume.
BOX_PAD = 1e-3


def overlapping_parts(b: Building, lod=None, min_volume: float = 1e-6) -> list[tuple[str, str, float]]:
    """Pairs of BuildingParts whose solids share volume: ``(id_a, id_b, m3)``."""
    lod = lod if lod is not None else b.default_lod()
    parts = _part_meshes(b, lod)
    if len(parts) < 2:
        return []
    origin = np.vstack([m.vertices for *_, m in parts]).mean(axis=0)
    mans = [solid_manifold(m, origin) for *_, m in parts]
    # only parts whose boxes come within a millimetre can share volume (the float32
    # booleans move a corner by far less)
    lo = np.array([m.vertices.min(axis=0) for *_, m in parts])
    hi = np.array([m.vertices.max(axis=0) for *_, m in parts])
    out = []
    for i, j in sorted(map(tuple, bbox_pairs(lo, hi, pad=BOX_PAD).tolist())):
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
    a = solid_manifold(m0, origin)
    if a is None:
        return None
    best, best_vol = None, -1.0
    for o, _, _, m in parts:
        if o.id == part_id or np.any(m.vertices.max(axis=0) < lo0) or np.any(m.vertices.min(axis=0) > hi0):
            continue
        other = solid_manifold(m, origin)
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
    mans = [solid_manifold(m, origin) for *_, m in parts]
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


# ----------------------------------------------------------------------------- repair keeps parts apart

#: Largest move (m) of a repaired part's vertex back onto its neighbour's surface.
SNAP_BACK = 0.25


def overlap_pairs(b: Building, tol: Tolerances = DEFAULT, overlaps: Sequence[str] | None = None,
                  meshes: PartMeshes | None = None, only: tuple[str, str] | None = None
                  ) -> dict[tuple[str, str], float | None]:
    """val3dity 601 pairs of ``b`` (at ``tol.overlap_tol``): ``{(id_a, id_b): shared m3}``.

    The shared volume is manifold3d's intersection volume (None when a solid is rejected).
    ``overlaps``: the locations of the 601 defects of ``b`` at ``tol`` when the validator
    already found them (:func:`lod2energy.validate.solid.check_parts_overlap` otherwise).
    ``meshes``: the parts' meshes of ``b`` when the caller has them (at ``b``'s default LoD);
    ``only``: the one pair of objects to look at (the others are not checked).
    """
    if overlaps is None:
        overlaps = [loc for loc, _code, _info in check_parts_overlap([b], tol, only=only)[0]]
    out: dict[tuple[str, str], float | None] = {}
    for loc in overlaps:
        a, c = (s.split("|", 1)[0].removeprefix("coid=") for s in loc.split("&&", 1))
        out[(a, c)] = None
    if not out:
        return out
    lod = b.default_lod()
    if meshes is None or meshes.building is not b or meshes.lod != lod:
        meshes = PartMeshes(b, lod)
    origin = meshes.origin()
    for (a, c) in out:
        ma, mc = meshes.mesh(a), meshes.mesh(c)
        man_a = None if ma is None else solid_manifold(ma, origin)
        man_c = None if man_a is None or mc is None else solid_manifold(mc, origin)
        if man_a is not None and man_c is not None:
            out[(a, c)] = float((man_a ^ man_c).volume())
    return out


def _onto_surface(m: PolyMesh, other: PolyMesh, tol: float) -> PolyMesh | None:
    """``m`` with each vertex within ``tol`` (m) of ``other``'s surface (but not on it) put
    onto its nearest point there; None when no vertex moves.

    Where a part's corner stands a fraction of a millimetre off its neighbour's wall, the
    difference of the two (:func:`lod2energy.repair.parts.clip_overlapping_parts`) keeps a
    hairline strip along the part's edge, which folds into a line once written on a
    millimetre grid (a self-intersecting ring); with the corner on the wall the difference
    leaves no strip.
    """
    tris, _ = triangulate_mesh(other)
    if not len(tris):
        return None
    A, B, C = (other.vertices[tris[:, k]] for k in range(3))
    V = np.array(m.vertices, dtype=np.float64)
    moved = False
    for i in range(len(V)):
        d = _sqdist(V[i][None, :], A, B, C)
        k = int(np.argmin(d))
        if not 1e-16 < d[k] <= tol * tol:
            continue
        V[i] = closest_on_triangle(V[i], A[k], B[k], C[k])
        moved = True
    return m.with_faces(m.faces, V) if moved else None


def _snap_back(m: PolyMesh, other: PolyMesh, max_move: float = SNAP_BACK) -> PolyMesh | None:
    """``m`` with its vertices inside (or on) ``other`` projected onto the nearest face plane of
    ``other`` that faces a face of ``m`` (antiparallel normals within 10 degrees: the wall they
    share); None when no vertex is inside or one would move farther than ``max_move``."""
    tris, _ = triangulate_mesh(other)
    mt, _ = triangulate_mesh(m)
    if not len(tris) or not len(mt):
        return None

    def normals(V, T):
        N = np.cross(V[T[:, 1]] - V[T[:, 0]], V[T[:, 2]] - V[T[:, 0]])
        return N / np.maximum(np.linalg.norm(N, axis=1), 1e-12)[:, None]

    N, Nm = normals(other.vertices, tris), normals(m.vertices, mt)
    facing = np.flatnonzero((N @ Nm.T).min(axis=1) < -0.985)
    if not len(facing):
        return None
    A, B, C = (other.vertices[tris[facing, k]] for k in range(3))
    N = N[facing]
    inside = np.flatnonzero(winding_number(m.vertices, other.vertices, tris) > 0.1)
    V = m.vertices.copy()
    moved = False
    for i in inside:
        # the nearest face of the neighbour that the vertex is behind, its foot inside the face
        off = np.einsum("ij,ij->i", V[i] - A, N)
        d = np.sqrt(_sqdist(V[i][None, :], A, B, C))
        ok = np.flatnonzero((off < -1e-9) & (d <= -off + 1e-6))
        if not len(ok):
            continue
        k = int(ok[np.argmin(-off[ok])])
        if -off[k] > max_move:
            return None
        V[i] = V[i] - off[k] * N[k]
        moved = True
    return m.with_faces(m.faces, V) if moved else None


def _clip_by(m: PolyMesh, other: PolyMesh, min_edge: float = 0.0, snap_to: np.ndarray | None = None
             ) -> PolyMesh | None:
    """``m`` minus ``other`` (manifold3d), faces on ``m``'s faces keeping their semantic surface,
    vertices within 0.1 mm of ``other``'s triangle planes put onto them; with ``min_edge`` (m)
    the result's edges shorter than that are collapsed (where the two solids' corners lie a
    hair apart, the difference keeps sub-millimetre edges that a writer's grid would fold), after
    its vertices within ``min_edge`` of a corner of ``other`` (or of ``snap_to``, (n, 3) m: the
    corners of the building's other parts) are put onto that corner."""
    origin = np.vstack([m.vertices, other.vertices]).mean(axis=0)
    a, b = solid_manifold(m, origin), solid_manifold(other, origin)
    if a is None or b is None:
        return None
    mesh = (a - b).to_mesh()
    V = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3] + origin
    T = np.asarray(mesh.tri_verts, dtype=np.int64)
    if not len(T):
        return None
    if min_edge > 0:  # corners of the neighbour a hair away: onto them (one wall, one corner)
        from scipy.spatial import cKDTree
        P = other.vertices if snap_to is None else np.vstack([other.vertices, snap_to])
        d, j = cKDTree(P).query(V, distance_upper_bound=min_edge)
        hit = np.isfinite(d)
        V[hit] = P[j[hit]]
    for src in (other, m):  # float32 booleans: back onto the exact planes
        tris, _ = triangulate_mesh(src)
        A, B, C = src.vertices[tris[:, 0]], src.vertices[tris[:, 1]], src.vertices[tris[:, 2]]
        N = np.cross(B - A, C - A)
        N /= np.maximum(np.linalg.norm(N, axis=1), 1e-12)[:, None]
        for i in range(len(V)):
            d = _sqdist(V[i][None, :], A, B, C)
            k = int(np.argmin(d))
            if d[k] <= 1e-8:
                V[i] = V[i] - float((V[i] - A[k]) @ N[k]) * N[k]
    tris, owner = triangulate_mesh(m)
    A, B, C = m.vertices[tris[:, 0]], m.vertices[tris[:, 1]], m.vertices[tris[:, 2]]
    tn = np.cross(B - A, C - A)
    tn /= np.maximum(np.linalg.norm(tn, axis=1), 1e-12)[:, None]
    own = np.full(len(T), -1, dtype=np.intp)
    for k, t in enumerate(T):
        c = V[t].mean(axis=0)
        n = np.cross(V[t[1]] - V[t[0]], V[t[2]] - V[t[0]])
        n /= np.linalg.norm(n) or 1.0
        hit = np.flatnonzero((_sqdist(c[None], A, B, C) < 1e-6) & (tn @ n > 0.999))
        if len(hit):
            own[k] = int(owner[hit[0]])
    if min_edge > 0:
        V, T, own = collapse_short_edges(V, T, own, min_edge)
        if not len(T):
            return None
    faces = []
    for t, k in zip(T, own):
        f = m.faces[int(k)] if k >= 0 else None
        faces.append(Face((tuple(int(i) for i in t),), -1 if f is None else f.source,
                          None if f is None else f.semantic))
    return compact(merge_coplanar(PolyMesh(V, tuple(faces)), angle_tol=1e-6, dist_tol=1e-4))


def _same_solid(m: PolyMesh, other: PolyMesh | None) -> bool:
    """Same coordinates, same number of faces: a part the repair left as it was."""
    if other is None or len(m.faces) != len(other.faces) or len(m.vertices) != len(other.vertices):
        return False
    return bool(np.array_equal(np.unique(m.vertices, axis=0), np.unique(other.vertices, axis=0)))


def keep_parts_apart(before: Building, after: Building, tol: Tolerances = DEFAULT, lod=None
                     ) -> tuple[Building, dict]:
    """``after`` (the repair of ``before``) without the BuildingPart overlaps the repair made.

    Parts closed one by one can cut into a neighbour by millimetres. For every pair that is a
    val3dity 601 after the repair but not before, or whose shared volume grew, the repaired
    part of the pair (then the other, when that fails) is first snapped back: its
    vertices inside the neighbour go onto the neighbour's nearest face plane (at most
    :data:`SNAP_BACK`), so the two keep one wall; else it is clipped by the neighbour
    (manifold3d difference). A candidate is kept only if it is a valid solid and the pair is
    no longer worse than in the input.

    Returns
    -------
    building : Building
    record : dict
        ``{"created": [[a, b, m3], ...], "resolved": [[moved, neighbour, "snap"|"clip"], ...],
        "left": [[a, b, m3], ...]}``; empty when the repair made no overlap.
    """
    lod = lod if lod is not None else after.default_lod()
    if after is before:
        return after, {}
    meshes = PartMeshes(after, lod)
    if len(meshes) < 2:
        return after, {}
    before_meshes = PartMeshes(before, lod)
    pb, pa = overlap_pairs(before, tol, meshes=before_meshes), overlap_pairs(after, tol, meshes=meshes)

    def worse(pairs, key) -> bool:
        """A 601 pair new after the repair, or sharing more volume than in the input (a pair
        whose input volume is unknown - a solid manifold3d rejects - counts as kept)."""
        if key not in pairs:
            return False
        if key not in pb:
            return True
        return pb[key] is not None and pairs[key] is not None and pairs[key] > pb[key] * 1.01 + 1e-6

    bad = [k for k in pa if worse(pa, k)]
    if not bad:
        return after, {}
    def vol(x):
        return None if x is None else round(x, 6)

    rec: dict = {"created": [[a, c, vol(pa[(a, c)])] for a, c in bad], "resolved": [], "left": []}
    out = after
    for a, c in bad:
        # this pair alone, again only once an earlier pair's resolution changed the building
        cur = pa if out is after else overlap_pairs(out, tol, meshes=meshes, only=(a, c))
        if not worse(cur, (a, c)):
            continue
        parts = meshes.parts
        changed = [k for k in (a, c) if k in parts and not _same_solid(parts[k][3], before_meshes.mesh(k))]
        done = False
        # the repaired part moves first; the neighbour yields only when that fails
        for mover in changed + [k for k in (a, c) if k not in changed]:
            other = c if mover == a else a
            o, gi, g, m = parts[mover]
            for how, cand in (("snap", lambda: _snap_back(m, parts[other][3])),
                              ("clip", lambda: _clip_by(m, parts[other][3]))):
                res = cand()
                if res is None or not is_repaired(res, lod, tol):
                    continue
                trial = with_part(out, o.id, gi, g, res)
                trial_meshes = meshes.replaced(trial, (o.id,))
                if not worse(overlap_pairs(trial, tol, meshes=trial_meshes, only=(a, c)), (a, c)):
                    out, meshes, done = trial, trial_meshes, True
                    rec["resolved"].append([mover, other, how])
                    break
            if done:
                break
        if not done:
            rec["left"].append([a, c, vol(cur.get((a, c)))])
    return out, rec


# ----------------------------------------------------------------------------- energy model: no volume twice

#: Shared volume (m3) from which two overlapping parts are clipped for the energy model; below
#: it the overlap is numerical noise for the heat balance (10 litres).
ENERGY_OVERLAP = 0.01


#: A clipped part keeps no edge shorter than this (m) and no face smaller than this (m2): the
#: boolean's hairline remnants would be merged away once written (float32 STL, EnergyPlus's
#: 1.27 cm point merge) and leave the written zone open.
CLIP_MIN_EDGE = 0.005
CLIP_MIN_AREA = 1e-3


def _writable(m: PolyMesh) -> bool:
    """No hairline edge or sliver face in ``m`` (see :data:`CLIP_MIN_EDGE`)."""
    V = m.vertices
    for f in m.faces:
        if face_area(V, f) < CLIP_MIN_AREA:
            return False
        for r in f.rings:
            P = V[list(r)]
            if len(P) and float(np.min(np.linalg.norm(P - np.roll(P, -1, axis=0), axis=1))) < CLIP_MIN_EDGE:
                return False
    return True


def _valid_on_grid(b: Building, part_id: str, lod, tol: Tolerances) -> bool:
    """The solid of ``part_id`` in ``b`` is still a valid, writable solid once its vertices are
    rounded to the grid ``b`` will be written on (the writers' final check,
    :func:`lod2energy.validate.closed.export_problem`, judges it there)."""
    snapped = on_grid(b, *building_grid(b))
    o = next((x for x in snapped.envelope_objects if x.id == part_id), None)
    mine = None if o is None else part_mesh(snapped, o, lod)  # this part's mesh only
    return mine is not None and is_repaired(mine[2], lod, tol) and _writable(mine[2])


def clip_overlapping_parts(b: Building, tol: Tolerances = DEFAULT, lod=None,
                           min_volume: float = ENERGY_OVERLAP, overlaps: Sequence[str] | None = None
                           ) -> tuple[Building, dict]:
    """``b`` with no volume shared by two BuildingParts: the preparation stage in front of the
    writers, so that the energy model (zones) counts no volume twice and the written parts
    are val3dity-601-free.

    The parts are taken in the building's order (:attr:`Building.envelope_objects`). For every
    601 pair sharing more than ``min_volume`` m3, in that order (by the later part, then the
    earlier), the later part is clipped by the earlier one (manifold3d difference, faces on
    the later part's faces keeping their semantic surface); when that result is not a valid
    solid (also once on the output file's grid), has a hairline edge or sliver face
    (:func:`_writable`; the boolean's edges under :data:`CLIP_MIN_EDGE` are collapsed first) or
    does not lose the shared volume, the earlier part is clipped by the later one instead;
    when neither passes, both are tried again with the cut part's corners that lie within
    :data:`CLIP_MIN_EDGE` of the other part's surface put onto it first (:func:`_onto_surface`:
    such a corner leaves a hairline strip that the output grid folds); a pair no clip resolves
    is united into the earlier part (:func:`merge_parts` ``into``); else it is left and
    reported. The union of the parts is unchanged (but for those corners, moved at most
    :data:`CLIP_MIN_EDGE`).

    Parameters
    ----------
    b : Building
    tol : Tolerances
    lod : str, optional
        The LoD of the parts' solids (default: the building's default LoD).
    min_volume : float, m3
        Shared volumes up to this are left (numerical noise for the heat balance).
    overlaps : sequence of str, optional
        Locations of the 601 defects of ``b`` at ``tol`` when the validator already found
        them (see :func:`overlap_pairs`).

    Returns
    -------
    building : Building
        ``b`` itself when no pair shares more than ``min_volume``.
    record : dict
        ``{"clipped": [[clipped, by, shared m3, removed m3], ...], "united": [[into, other,
        shared m3], ...], "left": [[a, b, shared m3], ...], "volume_removed_m3": total}``
        (``volume_removed_m3`` counts the clipped and the united pairs); empty when nothing
        was to be done.
    """
    lod = lod if lod is not None else b.default_lod()
    meshes = PartMeshes(b, lod)  # each part's mesh built once, then again only when it changes
    if len(meshes) < 2:
        return b, {}
    pairs = {k: v for k, v in overlap_pairs(b, tol, overlaps, meshes=meshes).items()
             if v is not None and v > min_volume}
    if not pairs:
        return b, {}
    order = {oid: k for k, oid in enumerate(meshes.parts)}
    rec: dict = {"clipped": [], "united": [], "left": [], "volume_removed_m3": 0.0}
    out = b
    for a, c in sorted(pairs, key=lambda k: sorted((order.get(k[0], 0), order.get(k[1], 0)), reverse=True)):
        parts = meshes.parts
        if a not in parts or c not in parts:
            continue
        earlier, later = sorted((a, c), key=lambda k: order.get(k, 0))
        origin = np.vstack([parts[a][3].vertices, parts[c][3].vertices]).mean(axis=0)
        ma, mc = solid_manifold(parts[a][3], origin), solid_manifold(parts[c][3], origin)
        shared = None if ma is None or mc is None else (ma ^ mc).volume()
        if shared is None or shared <= min_volume:
            continue  # resolved by an earlier clip (or no longer measurable)
        done = False
        for cut, by, snap in ((later, earlier, False), (earlier, later, False),
                              (later, earlier, True), (earlier, later, True)):
            o, gi, g, m = parts[cut]
            cutter = parts[by][3]
            if snap:  # corners a hair off the other solid's surface: onto it first
                m = _onto_surface(m, cutter, CLIP_MIN_EDGE)
                if m is None:
                    continue
            res = _clip_by(m, cutter, CLIP_MIN_EDGE)
            if res is None or not is_repaired(res, lod, tol) or not _writable(res):
                continue
            removed = signed_volume(m) - signed_volume(res)
            if abs(removed - shared) > 0.01 * shared + 1e-3 * signed_volume(m) + 1e-3:
                continue  # the boolean (and the collapse of its hairline edges) lost or kept more
            trial = with_part(out, o.id, gi, g, res)
            if not _valid_on_grid(trial, cut, lod, tol):
                continue
            out, meshes = trial, meshes.replaced(trial, (cut,))
            rec["clipped"].append([cut, by, round(shared, 6), round(removed, 6)])
            rec["volume_removed_m3"] += removed
            done = True
            break
        if not done:
            merged = merge_parts(out, {a, c}, tol, lod, into=earlier)
            if merged is not out and _valid_on_grid(merged, earlier, lod, tol):
                out, meshes = merged, PartMeshes(merged, lod)
                rec["united"].append([earlier, later, round(shared, 6)])
                rec["volume_removed_m3"] += shared
            else:
                rec["left"].append([a, c, round(shared, 6)])
    rec["volume_removed_m3"] = round(rec["volume_removed_m3"], 6)
    if out is b:
        return b, rec
    return out.with_provenance(parts_energy=rec), rec


def keep_input_parts(clipped: Building, unclipped: Building) -> Building:
    """``clipped`` carrying the parts of ``unclipped`` (the same building before
    :func:`clip_overlapping_parts`, prepared alike) for the writers of the parts' union.

    The STL is the union of the parts, the same with the input parts as with the clipped ones;
    written from the input parts it gains no seam where a clipped part meets its neighbour.
    :func:`input_parts` gives the building back with them.
    """
    return clipped.with_provenance(parts_input=(unclipped.objects, unclipped.vertices))


def input_parts(b: Building) -> Building:
    """``b`` with the parts it had before :func:`clip_overlapping_parts` (``b`` itself when the
    stage left it as it was), see :func:`keep_input_parts`."""
    kept = b.provenance.get("parts_input")
    if kept is None:
        return b
    objects, vertices = kept
    return replace(b, objects=objects, vertices=vertices)
