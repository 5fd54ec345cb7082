"""Solid-level (401-405), Multi/CompositeSolid (501-503) and BuildingPart (601) checks.

These run only on primitives whose shells passed the shell checks, so every shell is a
closed 2-manifold here. val3dity decides them with exact Nef polyhedra; here volumes of
boolean results come from manifold3d (robust, double precision, about a local origin),
after two cheap filters: bounding boxes, then a separating face plane (one solid behind
one of its faces, the other in front: parts sharing a wall). Inner shells are first
placed by the winding numbers of their vertices, which is exact where a shared volume
would be below round-off (a cavity poking 10 um out of its solid). "Interiors overlap" means a shared volume above
``Tolerances.volume_eps`` (m3; val3dity's exact test reports any positive volume; the floor only
absorbs round-off of coplanar shared walls). With ``overlap_tol > 0`` two solids
overlap when the shared part is thicker than ``overlap_tol`` (its volume / area ratio,
a stand-in for val3dity's erosion by ``overlap_tol``).
"""
from __future__ import annotations

from typing import Sequence

import manifold3d as m3d
import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import bbox_pairs, cross_rows, signed_volume, winding_number
from lod2energy.model import BUILDING_TYPES, Building, Geometry, Solid
from lod2energy.validate.shell import shell_meshes


# ----------------------------------------------------------------------------- meshes -> manifolds

def _triangles(vertices: np.ndarray, solids, tol: Tolerances) -> list[list[np.ndarray]]:
    """Snapped triangles (T, 3) int of each shell of each solid, as they are oriented."""
    meshes = iter(shell_meshes([(vertices, sh) for so in solids for sh in so.shells], tol))
    return [[next(meshes).tris for _ in so.shells] for so in solids]


def to_manifold(vertices: np.ndarray, tris: np.ndarray, origin: np.ndarray):
    """manifold3d Manifold of closed triangles (double precision, about ``origin``).

    Parameters
    ----------
    vertices : (n, 3) float
    tris : (T, 3) int
        Outward-oriented closed triangle set (cavities inward).
    origin : (3,) float
        Subtracted from the coordinates.

    Returns
    -------
    manifold3d.Manifold or None
        None when manifold3d rejects the mesh.
    """
    tris = np.asarray(tris, dtype=np.intp)
    if len(tris) == 0:
        return None
    used, inv = np.unique(tris, return_inverse=True)
    pts = np.ascontiguousarray(vertices[used] - origin, dtype=np.float64)
    mesh = m3d.Mesh64(vert_properties=pts, tri_verts=np.ascontiguousarray(inv.reshape(-1, 3), dtype=np.uint64))
    man = m3d.Manifold(mesh)
    if man.status() != m3d.Error.NoError or man.is_empty():
        return None
    return man


def _overlaps(a, b, tol: Tolerances) -> bool:
    """Whether two manifolds' interiors share volume (see module docstring)."""
    x = a ^ b
    v = x.volume()
    if v <= tol.volume_eps:
        return False
    if tol.overlap_tol > 0:
        area = x.surface_area()
        return area > 0 and v / area > tol.overlap_tol
    return True


def _geometry_manifold(vertices: np.ndarray, solids: list[np.ndarray], origin: np.ndarray):
    """Manifold of a Solid, or the union of a CompositeSolid's members, given each solid's
    triangles (T_i, 3) int (None if rejected)."""
    mans = []
    for t in solids:
        m = to_manifold(vertices, t, origin)
        if m is None:
            return None
        mans.append(m)
    if not mans:
        return None
    return mans[0] if len(mans) == 1 else m3d.Manifold.batch_boolean(mans, m3d.OpType.Add)


def _overlap_by_vertices(vertices: np.ndarray, t1: np.ndarray, t2: np.ndarray) -> bool:
    """Fallback when manifold3d rejects a mesh: a vertex of one solid strictly inside the other."""
    w12 = winding_number(vertices[np.unique(t1)], vertices, t2)
    w21 = winding_number(vertices[np.unique(t2)], vertices, t1)
    return bool((np.abs(w12) > 0.75).any() or (np.abs(w21) > 0.75).any())


def _positive_parts(man, tol: Tolerances) -> int:
    """Number of connected solid pieces (cavity boundaries are not pieces)."""
    return sum(1 for p in man.decompose() if p.volume() > tol.volume_eps)


def _same_shell(vertices: np.ndarray, t1: np.ndarray, t2: np.ndarray, tol: Tolerances) -> bool:
    """Whether two closed shells have the same vertices (within snap_tol) and volume."""
    p1 = np.unique(np.round(vertices[np.unique(t1)] / max(tol.snap_tol, 1e-12)), axis=0)
    p2 = np.unique(np.round(vertices[np.unique(t2)] / max(tol.snap_tol, 1e-12)), axis=0)
    if p1.shape != p2.shape or not np.array_equal(p1, p2):
        return False
    v1, v2 = signed_volume(vertices, t1, origin="first"), signed_volume(vertices, t2, origin="first")
    return abs(abs(v1) - abs(v2)) <= tol.volume_eps


# ----------------------------------------------------------------------------- 401-405

def check_solids(items: Sequence[tuple[np.ndarray, Solid]], tol: Tolerances = DEFAULT
                 ) -> list[list[tuple[int | None, int, str]]]:
    """Solid checks of many solids (of one or more buildings): 405 orientation of shells, then
    401-404 between the shells of a solid with cavities.

    Parameters
    ----------
    items : sequence of (vertices (n, 3) float, Solid)
        The building's vertices (m) and a solid (exterior shell first) whose every shell
        already passed the shell checks.
    tol : Tolerances

    Returns
    -------
    list (one per item) of lists of ``(shell_index | None, code, info)``; for 401/402 the
    info names the pair (``"0--2"``) as val3dity does.
    """
    out: list[list[tuple[int | None, int, str]]] = [[] for _ in items]
    single = [k for k, (_, so) in enumerate(items) if len(so.shells) == 1]
    meshes = shell_meshes([(items[k][0], items[k][1].shells[0]) for k in single], tol)
    for k, m in zip(single, meshes):
        if signed_volume(items[k][0], m.tris, origin="first") <= 0:
            out[k].append((0, 405, "exterior shell oriented inwards"))
    for k, (v, so) in enumerate(items):
        if len(so.shells) > 1:
            out[k] = _check_cavities(v, so, tol)
    return out


def _check_cavities(vertices: np.ndarray, solid: Solid, tol: Tolerances) -> list[tuple[int | None, int, str]]:
    """:func:`check_solids` of one solid with interior shells."""
    tris, = _triangles(vertices, [solid], tol)
    out: list[tuple[int | None, int, str]] = []
    for i, t in enumerate(tris):
        v = signed_volume(vertices, t, origin="first")
        if (i == 0 and v <= 0) or (i > 0 and v >= 0):
            out.append((i, 405, "exterior shell oriented inwards" if i == 0
                        else "interior shell oriented outwards"))
    if out or len(tris) == 1:
        return out
    origin = vertices[np.unique(tris[0])].min(axis=0)
    outer = to_manifold(vertices, tris[0], origin)
    inner = [to_manifold(vertices, t[:, ::-1], origin) for t in tris[1:]]   # as volumes
    if outer is None or any(m is None for m in inner):
        return out
    a_outer = outer.surface_area()
    for k, m in enumerate(inner, start=1):
        # vertices first: exact enough where shared volumes are below round-off
        w = winding_number(vertices[np.unique(tris[k])], vertices, tris[0])
        w_out = winding_number(vertices[np.unique(tris[0])], vertices, tris[k][:, ::-1])
        v_in, v_out = w > 0.75, np.abs(w) < 0.25
        if v_in.any() and v_out.any():
            out.append((k, 401, f"0--{k}"))
            continue
        if v_out.all():
            if (w_out > 0.75).any() or (m ^ outer).volume() > tol.volume_eps:
                out.append((k, 401, f"0--{k}"))
            else:
                out.append((k, 403, f"Inner shell (#{k}) is completely outside the outer shell (#0)"))
            continue
        outside = (m - outer).volume()
        if outside > tol.volume_eps:
            if (m ^ outer).volume() <= tol.volume_eps:
                out.append((k, 403, f"Inner shell (#{k}) is completely outside the outer shell (#0)"))
            else:
                out.append((k, 401, f"0--{k}"))
            continue
        # inside: it must not share a face with the exterior shell
        if (outer - m).surface_area() < a_outer + m.surface_area() - tol.area_eps:
            out.append((k, 401, f"0--{k}"))
    for i in range(len(inner)):
        for j in range(i + 1, len(inner)):
            if _same_shell(vertices, tris[i + 1], tris[j + 1], tol):
                out.append((i + 1, 402, f"{i + 1}--{j + 1}"))
                continue
            a, b = inner[i], inner[j]
            if (a ^ b).volume() > tol.volume_eps or \
                    (a + b).surface_area() < a.surface_area() + b.surface_area() - tol.area_eps:
                out.append((i + 1, 401, f"{i + 1}--{j + 1}"))
    if out:
        return out
    rest = outer
    for m in inner:
        rest = rest - m
    if _positive_parts(rest, tol) != 1:
        out.append((None, 404, ""))
    return out


# ----------------------------------------------------------------------------- 501-503

def check_multisolid(vertices: np.ndarray, geometry: Geometry, tol: Tolerances = DEFAULT
                     ) -> list[tuple[int | None, int, str]]:
    """MultiSolid / CompositeSolid checks: 502 duplicated, 501 intersecting, 503 disconnected.

    Parameters
    ----------
    vertices : (n, 3) float
        The building's vertices, m.
    geometry : Geometry
        "MultiSolid" or "CompositeSolid" whose solids are all valid.
    tol : Tolerances
        ``overlap_tol`` as in val3dity (-1: any shared volume; > 0: tolerated thickness).

    Returns
    -------
    list of ``(solid_index | None, code, info)``
    """
    solids = geometry.solids
    if len(solids) < 2:
        return []
    tris = _triangles(vertices, solids, tol)
    out: list[tuple[int | None, int, str]] = []
    allp = vertices[np.unique(np.concatenate([t for ts in tris for t in ts]))]
    origin = allp.min(axis=0)
    for i in range(len(solids)):
        for j in range(i + 1, len(solids)):
            if len(tris[i]) == len(tris[j]) and all(
                    _same_shell(vertices, a, b, tol) for a, b in zip(tris[i], tris[j])):
                out.append((i, 502, f"solid #{i} and solid #{j}"))
    if out:
        return out
    mans = [to_manifold(vertices, np.concatenate(ts), origin) for ts in tris]
    if any(m is None for m in mans):
        return out
    boxes = np.array([[vertices[np.unique(ts[0])].min(0), vertices[np.unique(ts[0])].max(0)] for ts in tris])
    for i, j in bbox_pairs(boxes[:, 0], boxes[:, 1], pad=1e-9).tolist():
        if _overlaps(mans[i], mans[j], tol):
            out.append((i, 501, f"solid #{i} and solid #{j}"))
    if out or geometry.type != "CompositeSolid":
        return out
    union = m3d.Manifold.batch_boolean(mans, m3d.OpType.Add)
    n = _positive_parts(union, tol)
    if n != 1:
        out.append((None, 503, f"CompositeSolid is formed of {n} parts"))
    return out


# ----------------------------------------------------------------------------- 601

def _ragged_pairs(na: np.ndarray, nb: np.ndarray):
    """For k groups of sizes na[k] x nb[k]: group id, index in a, index in b of every combination."""
    cnt = na * nb
    tot = int(cnt.sum())
    gid = np.repeat(np.arange(len(cnt)), cnt)
    loc = np.arange(tot) - np.repeat(np.cumsum(cnt) - cnt, cnt)
    return gid, loc // nb[gid], loc % nb[gid], cnt


#: Point-plane values of :func:`_separated_pairs` computed at once (about 80 bytes of
#: temporaries each): bounds its memory however many faces and points a batch holds.
PLANE_VALUES_CHUNK = 1 << 18


def _extreme_over_runs(nrm, off, pts, f_idx, p0, n, largest: bool, chunk: int = PLANE_VALUES_CHUNK) -> np.ndarray:
    """For each unit k (all ``n[k] >= 1``): the largest (or smallest) of ``nrm[f] . p - off[f]``
    with ``f = f_idx[k]`` over the points ``pts[p0[k] : p0[k] + n[k]]``, ``chunk`` values at a time."""
    out = np.empty(len(f_idx))
    cost = np.cumsum(n)
    reduce = np.maximum.reduceat if largest else np.minimum.reduceat
    lo = 0
    while lo < len(f_idx):
        base = int(cost[lo - 1]) if lo else 0
        hi = max(lo + 1, int(np.searchsorted(cost, base + chunk, side="right")))
        nn = n[lo:hi]
        unit = np.repeat(np.arange(lo, hi), nn)
        first = np.cumsum(nn) - nn
        q = p0[unit] + (np.arange(len(unit)) - np.repeat(first, nn))
        f = f_idx[unit]
        out[lo:hi] = reduce(np.einsum("ij,ij->i", nrm[f], pts[q]) - off[f], first)
        lo = hi
    return out


def _separated_pairs(pts, pstart, npts, nrm, off, fstart, nf, pairs, eps: float = 1e-6) -> np.ndarray:
    """Which pairs of items a face plane separates (item i behind one of its own face planes
    and item j in front of it, or the reverse), within ``eps`` m.

    Such a plane proves that the interiors do not overlap (parts sharing a wall) without a
    boolean operation. Items hold ragged runs of points (``pstart``, ``npts``) and of
    unit-normal planes ``n . x = off`` (``fstart``, ``nf``); ``pairs`` is (p, 2) int. Every
    point is set against every plane of the other item, at most :data:`PLANE_VALUES_CHUNK`
    values at a time.
    """
    # planes with the whole item behind them
    g, fi, _, _ = _ragged_pairs(nf, np.ones_like(nf))
    f_idx, n = fstart[g] + fi, npts[g]
    has = n > 0
    behind = np.zeros(len(nrm), dtype=bool)
    behind[f_idx[has]] = _extreme_over_runs(nrm, off, pts, f_idx[has], pstart[g][has], n[has], True) <= eps
    sep = np.zeros(len(pairs), dtype=bool)
    for a_col, b_col in ((0, 1), (1, 0)):
        ia, ib = pairs[:, a_col], pairs[:, b_col]
        g, fi, _, _ = _ragged_pairs(nf[ia], np.ones_like(ia))
        f_idx, n = fstart[ia][g] + fi, npts[ib][g]
        has = n > 0
        if not has.any():
            continue
        g, f_idx = g[has], f_idx[has]
        front = _extreme_over_runs(nrm, off, pts, f_idx, pstart[ib][g], n[has], False) >= -eps
        ok = front & behind[f_idx]
        sep |= np.bincount(g, weights=ok, minlength=len(pairs)) > 0
    return sep


def check_parts_overlap(buildings: Sequence[Building], tol: Tolerances = DEFAULT,
                        only: tuple[str, str] | None = None) -> list[list[tuple[str, int, str]]]:
    """601 BUILDINGPARTS_OVERLAP of many buildings: interiors of a Building's and its
    BuildingParts' solids overlap.

    Per LoD, every Solid / CompositeSolid geometry of the Building and its parts is
    tested against the others: bounding boxes first, then a separating face plane (parts
    sharing a wall), then the shared volume.

    Parameters
    ----------
    buildings : sequence of Building
        Their geometries already passed levels 1xx-5xx.
    tol : Tolerances
        ``overlap_tol`` as in val3dity.
    only : (str, str), optional
        Two object ids: only the geometries of these two objects are tested against each
        other (their verdict is the one the whole check gives them: every geometry still sets
        the building's local frame).

    Returns
    -------
    list (one per building) of lists of ``(location, 601, info)``, location
    ``"coid=A|geom=0&&coid=B|geom=0"`` and info ``"geometries are lod=2"``.
    """
    outs: list[list[tuple[str, int, str]]] = [[] for _ in buildings]
    items = []                                    # (building, group, lod, object id, geom index, Geometry)
    group = 0
    for bi, b in enumerate(buildings):
        if not b.is_building:
            continue
        prims: dict[str | None, list] = {}
        for o in b.objects:
            if o.type not in BUILDING_TYPES:
                continue
            for gi, g in enumerate(o.geometries):
                if g.type in ("Solid", "CompositeSolid") and g.solids:
                    prims.setdefault(g.lod, []).append((o.id, gi, g))
        for lod, its in prims.items():
            if len(its) > 1:
                items.extend((bi, group, lod, oid, gi, g) for oid, gi, g in its)
                group += 1
    if not items:
        return outs
    shells = [(buildings[it[0]].vertices, sh) for it in items for so in it[5].solids for sh in so.shells]
    meshes = iter(shell_meshes(shells, tol))
    # all items' triangles over one vertex array (buildings stacked), item by item
    boff: dict[int, int] = {}
    blocks, n = [], 0
    for it in items:
        if it[0] not in boff:
            boff[it[0]] = n
            blocks.append(buildings[it[0]].vertices)
            n += len(buildings[it[0]].vertices)
    V = np.concatenate(blocks)
    solid_tris = [[np.concatenate([next(meshes).tris for _ in so.shells]) for so in it[5].solids] for it in items]
    tris = [np.concatenate(ts) for ts in solid_tris]
    ntri = np.array([len(t) for t in tris])
    item_of_tri = np.repeat(np.arange(len(items)), ntri)
    gtris = np.concatenate(tris) + np.repeat([boff[it[0]] for it in items], ntri)[:, None]
    # each item's points (distinct vertices), in item order
    keys = np.unique(item_of_tri.repeat(3).astype(np.int64) * n + gtris.ravel())
    pt_item, pt_vid = keys // n, keys % n
    npts = np.bincount(pt_item, minlength=len(items))
    pstart = np.concatenate(([0], np.cumsum(npts)[:-1]))
    P = V[pt_vid]
    lo = np.minimum.reduceat(P, pstart, axis=0)
    hi = np.maximum.reduceat(P, pstart, axis=0)
    grp = np.array([it[1] for it in items])
    span = float((hi[:, 0] - lo[:, 0]).max() + (hi[:, 0].max() - lo[:, 0].min())) + 1.0
    glo, ghi = lo - lo[:, :1] * 0, hi.copy()
    shift = grp * span - lo[:, 0].min()
    glo[:, 0] = lo[:, 0] + shift
    ghi[:, 0] = hi[:, 0] + shift
    pairs = bbox_pairs(glo, ghi, pad=-1e-7)      # boxes that only touch cannot overlap
    if len(pairs):
        pairs = pairs[grp[pairs[:, 0]] == grp[pairs[:, 1]]]
    if only is not None and len(pairs):
        wanted = set(only)
        oid = np.array([it[3] for it in items], dtype=object)
        a, c = oid[pairs[:, 0]], oid[pairs[:, 1]]
        pairs = pairs[np.array([{x, y} == wanted for x, y in zip(a, c)], dtype=bool)]
    if len(pairs) == 0:
        return outs
    # separating face planes, in one local frame per building
    borigin: dict[int, np.ndarray] = {}
    for k, it in enumerate(items):
        borigin[it[0]] = np.minimum(borigin.get(it[0], lo[k]), lo[k])
    origin = np.array([borigin[it[0]] for it in items])
    Q = P - np.repeat(origin, npts, axis=0)
    T3 = V[gtris] - origin[item_of_tri][:, None, :]
    nrm = cross_rows(T3[:, 1] - T3[:, 0], T3[:, 2] - T3[:, 0])
    ln = np.sqrt(np.einsum("ij,ij->i", nrm, nrm))
    keep = ln > 0
    nrm = nrm[keep] / ln[keep, None]
    off = np.einsum("ij,ij->i", nrm, T3[keep, 0])
    nf = np.bincount(item_of_tri[keep], minlength=len(items))
    fstart = np.concatenate(([0], np.cumsum(nf)[:-1]))
    sep = _separated_pairs(Q, pstart, npts, nrm, off, fstart, nf, pairs)
    mans: dict[int, object] = {}
    for i, j in pairs[~sep].tolist():
        bi = items[i][0]
        v = buildings[bi].vertices
        for k in (i, j):
            if k not in mans:
                mans[k] = _geometry_manifold(v, solid_tris[k], borigin[items[k][0]])
        if mans[i] is None or mans[j] is None:
            overlap = _overlap_by_vertices(v, tris[i], tris[j])
        else:
            overlap = _overlaps(mans[i], mans[j], tol)
        if overlap:
            (_, _, lod, a, ga, _), (_, _, _, b, gb, _) = items[i], items[j]
            outs[bi].append((f"coid={a}|geom={ga}&&coid={b}|geom={gb}", 601, f"geometries are lod={lod}"))
    return outs
