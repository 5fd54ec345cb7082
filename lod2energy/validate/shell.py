"""Shell-level checks (301-307), as val3dity runs them on shells whose polygons are valid.

val3dity snaps the shell's vertices, triangulates every face, then builds a CGAL
polyhedron triangle by triangle (face order). A triangle that cannot be added is a 307
POLYGON_WRONG_ORIENTATION when its reversed version could be, else a 303
NON_MANIFOLD_CASE; any such error stops the shell. A built shell is then checked for
several components (305), holes (302, one per border loop, "Location hole: (x, y, z)")
and finally self-intersections (306, "Location close to: (centroid)"). A
CompositeSurface needs no closedness but gets 303 for vertices where several open fans
meet ("Non-manifold vertex at (x, y, z)").

:func:`check_shells` works on many shells at once (of one building or of many); only shells
that are *not* clean 2-manifolds go through a short sequential replay of val3dity's
incremental construction (CGAL's rules: no reused directed edge, no face at a closed vertex,
no face closing one fan of a vertex that has another), to name the refused faces as it does.
Snapped triangulations (:func:`shell_meshes`) are kept in :mod:`lod2energy.cache` for the
solid-level checks.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np

from lod2energy import cache
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import bbox_pairs, triangle_pairs_intersect, triangulate_flat
from lod2energy.geometry.pairs import close_pairs_grid, connected_components
from lod2energy.geometry.snap import snapped_ids
from lod2energy.model import Shell
from lod2energy.validate.memo import shell_keys
from lod2energy.validate.polygon import _fmt


def _loc(p) -> str:
    return f"({_fmt(p[0])}, {_fmt(p[1])}, {_fmt(p[2])})"


# ----------------------------------------------------------------------------- shell meshes

@dataclass(frozen=True, eq=False)
class ShellMesh:
    """A shell's triangles after snapping.

    Parameters
    ----------
    tris : (T, 3) int
        Indices into the building's vertices (snapped representatives), each triangle
        oriented like its face.
    face_of_tri : (T,) int
        Face index (in ``shell.surfaces``) of each triangle.
    n_faces : int
    """

    tris: np.ndarray
    face_of_tri: np.ndarray
    n_faces: int


#: Shells whose snapped triangulation is kept per process (:mod:`lod2energy.cache`).
KEPT_MESHES = 8192


def _snap_lut(vertices: np.ndarray, shell: Shell, snap_tol: float):
    rings = [r for s in shell.surfaces for r in s.rings]
    if not rings:
        return None
    ids = np.concatenate(rings).astype(np.intp, copy=False)
    snapped = snapped_ids(vertices, ids, snap_tol)
    if np.array_equal(snapped, ids):
        return None
    lut = np.arange(len(vertices), dtype=np.intp)
    lut[ids] = snapped
    return lut


def shell_meshes(items: Sequence[tuple[np.ndarray, Shell]], tol: Tolerances = DEFAULT) -> list[ShellMesh]:
    """Snapped triangulations of shells of one or more buildings, in one batch, kept by content.

    Snapping is per shell (val3dity's ``snap_tol``, first-come representative); shells
    without any pair of vertices closer than ``snap_tol`` are left as they are.

    Parameters
    ----------
    items : sequence of (vertices (n, 3) float, Shell)
        The building's vertices (m) and a shell whose rings index them.
    tol : Tolerances

    Returns
    -------
    list of ShellMesh (triangles index the item's own vertex array)
    """
    items = list(items)
    return cache.remember_each("validate.meshes", shell_keys(items, tol.snap_tol),
                               lambda todo: _meshes([items[i] for i in todo], tol), KEPT_MESHES)


def _meshes(items: Sequence[tuple[np.ndarray, Shell]], tol: Tolerances) -> list[ShellMesh]:
    """:func:`shell_meshes` without the cache."""
    offs: dict[int, int] = {}
    blocks = []
    n = 0
    for v, _ in items:
        if id(v) not in offs:
            offs[id(v)] = n
            blocks.append(np.asarray(v, dtype=np.float64))
            n += len(v)
    V = np.concatenate(blocks) if len(blocks) > 1 else blocks[0]
    # vertices closer than snap_tol: clusters whose points are all mutually close merge
    # into their lowest index (any member is the same point within snap_tol); shells
    # touching a chain of close points get val3dity's order-dependent snapping
    rep = None
    chain = np.zeros(n, dtype=bool)
    if tol.snap_tol > 0 and n > 1:
        pairs = close_pairs_grid(V, tol.snap_tol * (1 + 1e-9))
        if len(pairs):
            d = V[pairs[:, 0]] - V[pairs[:, 1]]
            bid = np.repeat(np.arange(len(blocks)), [len(b) for b in blocks])
            pairs = pairs[(np.einsum("ij,ij->i", d, d) <= tol.snap_tol ** 2)
                          & (bid[pairs[:, 0]] == bid[pairs[:, 1]])]
        if len(pairs):
            lab, _ = connected_components(n, pairs[:, 0], pairs[:, 1])
            size = np.bincount(lab)
            npairs = np.bincount(lab[pairs[:, 0]], minlength=len(size))
            clique = npairs == size * (size - 1) // 2
            first = np.full(len(size), n, dtype=np.intp)
            np.minimum.at(first, lab, np.arange(n))
            rep = np.where(clique[lab], first[lab], np.arange(n))
            chain = ~clique[lab]
    flat, ring_len, rpp, owner, item_off = [], [], [], [], []
    any_chain = bool(chain.any())
    for v, sh in items:
        off = offs[id(v)]
        rings = [r for f in sh.surfaces for r in f.rings]
        ids = np.concatenate(rings).astype(np.intp, copy=False) if rings else np.zeros(0, dtype=np.intp)
        g = ids + off
        if any_chain and len(ids) and chain[g].any():
            lut = _snap_lut(v, sh, tol.snap_tol)
            if lut is not None:
                g = lut[ids] + off
        elif rep is not None:
            g = rep[g]
        flat.append(g)
        ring_len.append(np.fromiter((len(r) for r in rings), dtype=np.intp, count=len(rings)))
        rpp.append(np.fromiter((len(f.rings) for f in sh.surfaces), dtype=np.intp, count=len(sh.surfaces)))
        owner.append(len(sh.surfaces))
        item_off.append(off)
    tris, poly = triangulate_flat(V, np.concatenate(flat), np.concatenate(ring_len), np.concatenate(rpp))
    starts = np.concatenate(([0], np.cumsum(owner)))
    cut = np.searchsorted(poly, starts)
    out = []
    for k in range(len(items)):
        t = tris[cut[k]:cut[k + 1]]
        t = t - item_off[k] if item_off[k] else t.copy()
        fot = poly[cut[k]:cut[k + 1]] - starts[k]
        t.setflags(write=False)
        fot.setflags(write=False)
        out.append(ShellMesh(t, fot, owner[k]))
    return out


# ----------------------------------------------------------------------------- construction replay

def replay_construction(tris: np.ndarray, face_of_tri: np.ndarray) -> list[tuple[int, int]]:
    """Replay val3dity's incremental polyhedron construction; ``(face, code)`` for refused triangles.

    A triangle is refused when it repeats a vertex, reuses a directed edge already
    used, or touches a vertex whose umbrella is already closed. A refused triangle
    whose reversed version would be accepted is a 307, otherwise a 303. Refused
    triangles are not added. Each ``(face, code)`` is reported once.

    Parameters
    ----------
    tris : (T, 3) int
    face_of_tri : (T,) int

    Returns
    -------
    list of (int, int)
    """
    used: set[tuple[int, int]] = set()
    # per vertex: its fans (triangles around it linked through shared edges), as CGAL's
    # halfedge structure holds them; CGAL walks the fan of the last face added at a vertex
    edge_fan: dict[int, dict[int, int]] = {}      # v -> {neighbour: fan id}
    fan_count: dict[int, dict[int, int]] = {}     # fan id -> {neighbour: faces at that edge}
    fan_open: dict[int, int] = {}                 # fan id -> edges with one face only
    last_fan: dict[int, int] = {}
    next_id = [0]

    def closed(v: int) -> bool:
        f = last_fan.get(v)
        return f is not None and fan_open[f] == 0

    def closes_one_of_many(v: int, x: int, y: int) -> bool:
        """Would the wedge (x, v, y) close a fan of v while v keeps another fan?"""
        ef = edge_fan.get(v)
        if not ef:
            return False
        fx, fy = ef.get(x), ef.get(y)
        if fx is None or fy is None:
            return False                          # a new border edge at v: stays open
        n_fans = len(set(ef.values())) - (fx != fy)
        if n_fans < 2:
            return False
        opened = fan_open[fx] + (fan_open[fy] if fy != fx else 0)
        opened -= (fan_count[fx].get(x, 0) + (fan_count[fy].get(x, 0) if fy != fx else 0)) == 1
        opened -= (fan_count[fx].get(y, 0) + (fan_count[fy].get(y, 0) if fy != fx else 0)) == 1
        return opened == 0

    def ok(a: int, b: int, c: int) -> bool:
        if a == b or b == c or a == c:
            return False
        if (a, b) in used or (b, c) in used or (c, a) in used:
            return False
        if closed(a) or closed(b) or closed(c):
            return False
        return not (closes_one_of_many(a, b, c) or closes_one_of_many(b, c, a) or closes_one_of_many(c, a, b))

    def add_wedge(v: int, x: int, y: int) -> None:
        ef = edge_fan.setdefault(v, {})
        fx, fy = ef.get(x), ef.get(y)
        if fx is None and fy is None:
            f = next_id[0]
            next_id[0] += 1
            fan_count[f] = {}
            fan_open[f] = 0
        elif fx is None or fy is None or fx == fy:
            f = fx if fx is not None else fy
        else:                                     # the face joins two fans
            f = fx
            fan_open[f] += fan_open.pop(fy)
            for n, k in fan_count.pop(fy).items():
                fan_count[f][n] = k
                ef[n] = f
        cnt = fan_count[f]
        for n in (x, y):
            ef[n] = f
            k = cnt.get(n, 0) + 1
            cnt[n] = k
            fan_open[f] += 1 if k == 1 else (-1 if k == 2 else 0)
        last_fan[v] = f

    out: list[tuple[int, int]] = []
    seen: set[tuple[int, int]] = set()
    for (a, b, c), f in zip(tris.tolist(), face_of_tri.tolist()):
        if ok(a, b, c):
            used.update(((a, b), (b, c), (c, a)))
            add_wedge(a, b, c)
            add_wedge(b, c, a)
            add_wedge(c, a, b)
            continue
        code = 307 if ok(a, c, b) else 303
        if (f, code) not in seen:
            seen.add((f, code))
            out.append((f, code))
    return out


# ----------------------------------------------------------------------------- batch checks

def _group_count(keys: np.ndarray, groups: np.ndarray, n_groups: int) -> np.ndarray:
    """Number of distinct ``keys`` per group."""
    if len(keys) == 0:
        return np.zeros(n_groups, dtype=np.intp)
    k = np.asarray(keys, dtype=np.int64)
    span = int(k.max()) + 1
    u = np.unique(np.asarray(groups, dtype=np.int64) * span + k)
    return np.bincount(u // span, minlength=n_groups)


def check_shells(items: Sequence[tuple[np.ndarray, Shell, bool]], tol: Tolerances = DEFAULT
                 ) -> list[list[tuple[int | None, int, str]]]:
    """Shell checks (301-307) of many shells whose polygons are valid, in one vectorised pass.

    Parameters
    ----------
    items : sequence of (vertices (n, 3) float, Shell, volumetric bool)
        The building's vertices (m), a shell whose polygons passed the 1xx/2xx checks, and True
        for a shell of a Solid (closedness required, 301/302) or False for a CompositeSurface
        (303 for non-manifold vertices, 305, 306, 307 still). Shells of one building share its
        vertex array.
    tol : Tolerances

    Returns
    -------
    list (one per item) of lists of ``(face_index | None, code, info)``
    """
    items = list(items)
    base = shell_meshes([(v, sh) for v, sh, _ in items], tol)
    offsets: dict[int, int] = {}
    blocks, off = [], 0
    meshes = []
    for (v, _, _), m in zip(items, base):
        if id(v) not in offsets:
            offsets[id(v)] = off
            blocks.append(np.asarray(v, dtype=np.float64))
            off += len(v)
        o = offsets[id(v)]
        meshes.append(ShellMesh(m.tris + o, m.face_of_tri, m.n_faces) if o else m)
    V = np.concatenate(blocks) if blocks else np.zeros((0, 3))
    vol = np.fromiter((bool(it[2]) for it in items), dtype=bool, count=len(items))
    return _check_meshes(V, meshes, vol)


def _check_meshes(vertices: np.ndarray, meshes: Sequence[ShellMesh], vol: np.ndarray
                  ) -> list[list[tuple[int | None, int, str]]]:
    """Shell checks on already snapped and triangulated shells over one vertex array."""
    S = len(meshes)
    out: list[list] = [[] for _ in range(S)]
    if S == 0:
        return out
    active = np.ones(S, dtype=bool)
    for s, m in enumerate(meshes):
        if vol[s] and m.n_faces < 4:
            out[s].append((None, 301, ""))
            active[s] = False
        elif len(m.tris) == 0:
            active[s] = False
    idx = np.flatnonzero(active)
    if len(idx) == 0:
        return out
    ntri = np.array([len(meshes[s].tris) for s in idx], dtype=np.int64)
    # edge keys (shell, u, v) must fit in int64: split huge batches
    if len(idx) > 1 and float(len(idx)) * float(len(vertices)) ** 2 >= 2.0 ** 62:
        half = len(idx) // 2
        for part in (idx[:half], idx[half:]):
            sub = _check_meshes(vertices, [meshes[s] for s in part], vol[part])
            for s, r in zip(part, sub):
                out[s].extend(r)
        return out
    tris = np.concatenate([meshes[s].tris for s in idx])
    fot = np.concatenate([meshes[s].face_of_tri for s in idx])
    tsh = np.repeat(idx, ntri)
    T = len(tris)
    N = np.int64(len(vertices))

    # --- combinatorial screening: directed/undirected edge multiplicities, vertex fans
    a, b = tris, np.roll(tris, -1, axis=1)
    src, dst = a.ravel().astype(np.int64), b.ravel().astype(np.int64)
    esh = np.repeat(tsh, 3).astype(np.int64)
    etri = np.repeat(np.arange(T), 3)
    degenerate = (tris[:, 0] == tris[:, 1]) | (tris[:, 1] == tris[:, 2]) | (tris[:, 0] == tris[:, 2])
    dkey = (esh * N + src) * N + dst
    lo, hi = np.minimum(src, dst), np.maximum(src, dst)
    ukey = (esh * N + lo) * N + hi
    _, dinv, dcnt = np.unique(dkey, return_inverse=True, return_counts=True)
    _, uinv, ucnt = np.unique(ukey, return_inverse=True, return_counts=True)
    bad = np.zeros(S, dtype=bool)
    bad[tsh[degenerate]] = True
    bad[esh[dcnt[dinv.ravel()] > 1]] = True
    bad[esh[ucnt[uinv.ravel()] > 2]] = True

    # wedges (vertex, triangle) linked through interior edges: fans per vertex
    ecount = ucnt[uinv.ravel()]
    order = np.argsort(uinv.ravel(), kind="stable")
    su = uinv.ravel()[order]
    first = np.r_[True, su[1:] != su[:-1]]
    starts = np.flatnonzero(first)
    two = starts[ucnt[su[starts]] == 2]
    e1, e2 = order[two], order[two + 1]                  # half-edge slots of the two triangles
    t1, t2 = etri[e1], etri[e2]
    # wedge id = 3 * tri + corner; corner k holds vertex tris[t, k]
    def wedge(t, v):
        k = np.argmax(tris[t] == v[:, None], axis=1)
        return 3 * t + k
    l1, l2 = lo[e1], hi[e1]
    wa = np.concatenate([wedge(t1, l1), wedge(t1, l2)])
    wb = np.concatenate([wedge(t2, l1), wedge(t2, l2)])
    W = 3 * T
    wlab, _ = connected_components(W, wa, wb)
    vkey = np.repeat(tsh, 3).astype(np.int64) * N + tris.ravel()
    vk, vinv = np.unique(vkey, return_inverse=True)
    vinv = vinv.ravel()
    nfans = _group_count(wlab, vinv, len(vk))
    # border edges at each vertex (2 per open fan)
    border = ecount == 1
    bv = np.bincount(np.searchsorted(vk, np.concatenate([esh[border] * N + src[border],
                                                         esh[border] * N + dst[border]])),
                     minlength=len(vk))
    multi = nfans > 1
    closed_fan_pinch = multi & (bv < 2 * nfans)
    vsh = (vk // N).astype(np.intp)
    bad[vsh[closed_fan_pinch]] = True
    open_pinch = multi & ~closed_fan_pinch

    # --- replay the construction where the screening found a problem
    for s in np.flatnonzero(bad):
        m = meshes[s]
        errs = replay_construction(m.tris, m.face_of_tri)
        if errs:
            out[s].extend((f, c, "") for f, c in errs)
        else:
            for v in (vk[(vsh == s) & multi] % N).tolist():
                out[s].append((None, 303, "Non-manifold vertex at " + _loc(vertices[v])))
    good = active & ~bad
    if not good.any():
        return out

    # --- connected components (triangles sharing an edge), holes
    keep_t = good[tsh]
    gl = keep_t[t1] & keep_t[t2]
    tlab, _ = connected_components(T, t1[gl], t2[gl])
    ncomp = _group_count(tlab[keep_t], tsh[keep_t], S)
    nborder = np.bincount(esh[border], minlength=S)
    done = np.zeros(S, dtype=bool)
    for s in np.flatnonzero(good):
        if ncomp[s] > 1:
            out[s].append((None, 305, "" if (vol[s] and nborder[s]) else "More than one connected components."))
            done[s] = True
        elif not vol[s]:
            for v in (vk[(vsh == s) & open_pinch] % N).tolist():
                out[s].append((None, 303, "Non-manifold vertex at " + _loc(vertices[v])))
                done[s] = True
    holes = good & ~done & vol & (nborder > 0)
    if holes.any():
        sel = border & holes[esh]
        bs, bsrc, bdst = esh[sel], src[sel], dst[sel]
        nodes, ninv = np.unique(np.concatenate([bs * N + bsrc, bs * N + bdst]), return_inverse=True)
        ninv = ninv.ravel()
        k = len(bs)
        lab, nl = connected_components(len(nodes), ninv[:k], ninv[k:])
        firstnode = np.full(nl, len(nodes), dtype=np.intp)
        np.minimum.at(firstnode, lab, np.arange(len(nodes)))
        for n_ in firstnode.tolist():
            s, v = divmod(int(nodes[n_]), int(N))
            out[s].append((None, 302, "Location hole: " + _loc(vertices[v])))
            done[s] = True

    # --- geometric consistency: self-intersections
    todo = good & ~done
    if todo.any():
        sel_t = np.flatnonzero(todo[tsh])
        # zero-area triangles (ear clipping along collinear vertices) bound nothing
        Q = vertices[tris[sel_t]]
        cr = np.cross(Q[:, 1] - Q[:, 0], Q[:, 2] - Q[:, 0])
        e2 = np.maximum(np.einsum("ij,ij->i", Q[:, 1] - Q[:, 0], Q[:, 1] - Q[:, 0]),
                        np.einsum("ij,ij->i", Q[:, 2] - Q[:, 0], Q[:, 2] - Q[:, 0]))
        sel_t = sel_t[np.einsum("ij,ij->i", cr, cr) > 1e-18 * e2 * e2]
        P = vertices[tris[sel_t]]
        origin = P.reshape(-1, 3).min(axis=0)
        local = vertices - origin
        lo_b, hi_b = P.min(axis=1) - origin, P.max(axis=1) - origin
        # shift each shell along x so that the sweep only pairs triangles of one shell
        shift = tsh[sel_t] * (float(hi_b[:, 0].max()) + 1.0)
        lo_b[:, 0] += shift
        hi_b[:, 0] += shift
        pairs = bbox_pairs(lo_b, hi_b, pad=1e-6)
        if len(pairs):
            pa, pb = sel_t[pairs[:, 0]], sel_t[pairs[:, 1]]
            keep = (tsh[pa] == tsh[pb]) & (fot[pa] != fot[pb])
            pa, pb = pa[keep], pb[keep]
            hit = triangle_pairs_intersect(local, tris, np.stack([pa, pb], axis=1))
            if hit.any():
                bad_t = np.unique(np.concatenate([pa[hit], pb[hit]]))
                for t in bad_t.tolist():
                    c = vertices[tris[t]].mean(axis=0)
                    out[int(tsh[t])].append((None, 306, "Location close to: " + _loc(c)))
    return out
