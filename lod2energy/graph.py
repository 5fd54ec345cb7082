"""Face-adjacency graph of a building: defect detection features in PyTorch Geometric's layout.

A node per face with the feature vector

    x_i = [area, n_x, n_y, n_z, h, degenerate, planarity, n_boundary_edges, n_nonmanifold_edges, degree]

and an edge per pair of faces sharing a mesh edge with ``[cos dihedral, boundary flag,
non-manifold flag]``. Mesh edges are the consecutive vertex pairs of every ring (inner rings
included) after snapping vertices closer than ``snap_tol``; the incidence ``c(e)`` of a mesh
edge is the number of ring edges on it: ``N_b = |c(e) = 1|`` (open boundary),
``N_nm = |c(e) > 2|`` (non-manifold).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry import snap_map
from lod2energy.model import Building, Surface

FEATURE_NAMES = ("area", "n_x", "n_y", "n_z", "h", "degenerate", "planarity",
                 "n_boundary_edges", "n_nonmanifold_edges", "degree")


@dataclass(frozen=True, eq=False)
class FaceGraph:
    """Face-adjacency graph (arrays in PyTorch Geometric's layout).

    Attributes
    ----------
    x : (N, 10) float
        Node features, see ``FEATURE_NAMES``; area in m2, planarity deviation in m.
    edge_index : (2, E) int
        Both directions of every adjacency (PyG convention for undirected graphs).
    edge_attr : (E, 3) float
        ``[cos dihedral, boundary flag, non-manifold flag]`` per directed edge.
    consistent : (E,) bool
        The two faces run through their shared mesh edge in opposite directions
        (coherent orientation).
    mesh_edges : (M, 2) int
        Undirected mesh edges as canonical vertex-id pairs.
    incidence : (M,) int
        ``c(e)`` per mesh edge.
    face_ids : tuple
        One ``(object_id, geom_index, solid_index, shell_index, face_index)`` per node.
    centroids : (N, 3) float
        Mean of each face's outer-ring vertices, m.
    shell_of_face : (N,) int
        Index of the shell each face belongs to.
    """

    x: np.ndarray
    edge_index: np.ndarray
    edge_attr: np.ndarray
    consistent: np.ndarray
    mesh_edges: np.ndarray
    incidence: np.ndarray
    face_ids: tuple
    centroids: np.ndarray = None
    shell_of_face: np.ndarray = None
    mesh_edge_shell: np.ndarray = None

    def shell_volumes(self) -> np.ndarray:
        """Signed volume per shell, m3 (divergence theorem over the planar faces).

        Positive when the shell's faces point outwards; only meaningful for closed shells.
        """
        if self.centroids is None or not len(self.x):
            return np.zeros(0)
        area_n = self.x[:, 0:1] * self.x[:, 1:4]
        contrib = np.einsum("ij,ij->i", self.centroids - self.centroids.mean(axis=0), area_n) / 3.0
        return np.bincount(self.shell_of_face, contrib, minlength=int(self.shell_of_face.max()) + 1)

    @property
    def n_faces(self) -> int:
        return len(self.x)

    @property
    def n_boundary(self) -> int:
        """N_b: mesh edges used by exactly one face ring."""
        return int(np.count_nonzero(self.incidence == 1))

    @property
    def n_nonmanifold(self) -> int:
        """N_nm: mesh edges used by more than two face rings."""
        return int(np.count_nonzero(self.incidence > 2))

    @property
    def n_inconsistent(self) -> int:
        """Undirected adjacencies whose faces are oriented incoherently."""
        return int(np.count_nonzero(~self.consistent)) // 2

    @property
    def status(self) -> str:
        """"non-manifold", "open", "watertight", or "empty" (no face: nothing bounds a volume)."""
        if self.n_faces == 0:
            return "empty"
        if self.n_nonmanifold:
            return "non-manifold"
        if self.n_boundary:
            return "open"
        return "watertight"

    def summary(self) -> dict:
        return {"faces": self.n_faces, "adjacencies": int(self.edge_index.shape[1]) // 2,
                "mesh_edges": int(len(self.incidence)), "N_b": self.n_boundary,
                "N_nm": self.n_nonmanifold, "inconsistent_adjacencies": self.n_inconsistent,
                "status": self.status}

    def to_pyg(self):
        """A ``torch_geometric.data.Data`` (needs the optional ``pyg`` extra)."""
        try:
            import torch
            from torch_geometric.data import Data
        except ImportError as e:  # pragma: no cover - optional extra
            raise ImportError("to_pyg() needs torch and torch_geometric: pip install 'lod2energy[pyg]'") from e
        return Data(x=torch.as_tensor(self.x, dtype=torch.float32),
                    edge_index=torch.as_tensor(self.edge_index, dtype=torch.long),
                    edge_attr=torch.as_tensor(self.edge_attr, dtype=torch.float32))


def _empty_graph(face_ids=()) -> FaceGraph:
    return FaceGraph(np.zeros((len(face_ids), 10)), np.zeros((2, 0), np.intp), np.zeros((0, 3)),
                     np.zeros(0, bool), np.zeros((0, 2), np.intp), np.zeros(0, np.intp), tuple(face_ids))


def face_graph(vertices: np.ndarray, surfaces: Sequence[Surface], tol: Tolerances = DEFAULT,
               z_range: tuple[float, float] | None = None, face_ids: Sequence | None = None,
               shell_of_face: np.ndarray | None = None,
               vertex_groups: np.ndarray | None = None, face_offset: np.ndarray | None = None) -> FaceGraph:
    """Build the face-adjacency graph of a set of polygons.

    Parameters
    ----------
    vertices : (n, 3) float
        Coordinates, m.
    surfaces : sequence of Surface
        The faces (rings index ``vertices``).
    tol : Tolerances
        ``snap_tol`` merges vertices; ``sliver_area`` sets the degenerate flag.
    z_range : (z_min, z_max), optional
        Extent used to normalise centroid heights (default: the faces' own extent); each
        may also be an (N,) array, one value per face.
    face_ids : sequence, optional
        Identifier per face (default ``range(len(surfaces))``).
    shell_of_face : (N,) int, optional
        Faces of different shells never share mesh edges (BuildingParts stay apart).
    vertex_groups : (n,) int, optional
        Vertices of different groups never snap together.
    face_offset : (N,) int, optional
        Added to each face's ring indices (faces of many buildings, each indexing its own
        vertices, over their stacked ``vertices``); default 0.
    """
    nf = len(surfaces)
    face_ids = tuple(face_ids) if face_ids is not None else tuple(range(nf))
    if nf == 0:
        return _empty_graph(face_ids)
    V = np.asarray(vertices, dtype=np.float64)
    # only the vertices the faces use snap: an unused vertex (the input's, kept in the vertex
    # list after a repair) must not chain two vertices of the shell into one
    canon = np.arange(len(V))
    shell_of_face = np.zeros(nf, np.intp) if shell_of_face is None else np.asarray(shell_of_face)

    # flatten every ring: element arrays (vertex id, ring id), ring arrays (face, is_outer)
    rings, ring_face, ring_outer = [], [], []
    for fi, s in enumerate(surfaces):
        for ri, ring in enumerate(s.rings):
            rings.append(ring)
            ring_face.append(fi)
            ring_outer.append(ri == 0)
    ring_face = np.asarray(ring_face, np.intp)
    ring_outer = np.asarray(ring_outer, bool)
    lens = np.fromiter((len(r) for r in rings), np.intp, len(rings))
    ids = np.concatenate([np.asarray(r, dtype=np.intp) for r in rings]) if rings else np.zeros(0, np.intp)
    if face_offset is not None and len(ids):
        ids = ids + np.repeat(np.asarray(face_offset, dtype=np.intp)[ring_face], lens)
    used = np.unique(ids) if rings and len(V) else np.zeros(0, np.intp)
    if len(used) > 1 and tol.snap_tol > 0:  # the lowest index of each cluster of close vertices
        groups = None if vertex_groups is None else np.asarray(vertex_groups)[used]
        canon[used] = used[snap_map(V[used], tol.snap_tol, groups)]
    flat = canon[ids] if lens.sum() else np.zeros(0, np.intp)
    rid = np.repeat(np.arange(len(rings)), lens)
    # drop consecutive repeats (cyclically) after snapping
    starts = np.cumsum(lens) - lens
    pos = np.arange(len(flat)) - starts[rid]
    prev = np.where(pos == 0, starts[rid] + lens[rid] - 1, np.arange(len(flat)) - 1)
    keep = flat != flat[prev] if len(flat) else np.zeros(0, bool)
    flat, rid = flat[keep], rid[keep]
    lens = np.bincount(rid, minlength=len(rings))
    starts = np.cumsum(lens) - lens
    nxt = np.arange(len(flat)) + 1
    last = starts + lens - 1
    nxt[last[lens > 0]] = starts[lens > 0]
    # Newell vectors per ring (relative to the ring's mean for precision)
    P = V[flat] if len(flat) else np.zeros((0, 3))
    cnt = np.maximum(lens, 1)[:, None]
    mean = np.stack([np.bincount(rid, P[:, k], minlength=len(rings)) for k in range(3)], axis=1) / cnt
    p = P - mean[rid]
    q = p[nxt] if len(p) else p
    comp = np.stack([(p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2]),
                     (p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0]),
                     (p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])], axis=1)
    nring = np.stack([np.bincount(rid, comp[:, k], minlength=len(rings)) for k in range(3)], axis=1)
    nring[lens < 2] = 0.0
    outer_n = np.zeros((nf, 3))
    outer_n[ring_face[ring_outer]] = nring[ring_outer]
    holes = ~ring_outer
    nvec = outer_n.copy()
    if holes.any():
        sgn = np.sign(np.einsum("ij,ij->i", nring[holes], outer_n[ring_face[holes]]))
        sgn[sgn == 0] = 1.0
        np.add.at(nvec, ring_face[holes], -sgn[:, None] * nring[holes])
    areas = 0.5 * np.linalg.norm(nvec, axis=1)
    normals = np.divide(nvec, (2 * areas)[:, None], out=np.zeros_like(nvec), where=areas[:, None] > 0)
    outer_idx = np.flatnonzero(ring_outer)
    centroids = np.zeros((nf, 3))
    centroids[ring_face[outer_idx]] = mean[outer_idx]
    centroid_z = centroids[:, 2]
    dist = np.abs(np.einsum("ij,ij->i", p, normals[ring_face[rid]])) if len(p) else np.zeros(0)
    ring_dev = np.zeros(len(rings))
    np.maximum.at(ring_dev, rid, dist)
    planarity = np.zeros(nf)
    planarity[ring_face[outer_idx]] = ring_dev[outer_idx]
    distinct = np.zeros(nf, np.intp)
    distinct[ring_face[outer_idx]] = lens[outer_idx]
    degenerate = ((distinct < 3) | (areas <= tol.sliver_area)).astype(float)
    src, dst, ef = flat, flat[nxt] if len(flat) else flat, ring_face[rid]
    if z_range is None:
        z_range = (float(centroid_z.min()), float(centroid_z.max()))
    zmin, zmax = (np.broadcast_to(np.asarray(z, dtype=np.float64), (nf,)) for z in z_range)
    span = zmax - zmin
    h = np.divide(centroid_z - zmin, span, out=np.zeros(nf), where=span > 0)

    if len(src) == 0:
        g = _empty_graph(face_ids)
        x = np.column_stack([areas, normals, h, degenerate, planarity, np.zeros((nf, 3))])
        return FaceGraph(x, g.edge_index, g.edge_attr, g.consistent, g.mesh_edges, g.incidence, face_ids,
                         centroids, shell_of_face)

    keep = src != dst
    src, dst, ef = src[keep], dst[keep], ef[keep]
    lo, hi = np.minimum(src, dst), np.maximum(src, dst)
    nv = np.int64(max(len(V), 1))
    key = (shell_of_face[ef].astype(np.int64) * nv + lo) * nv + hi
    ukey, inv, counts = np.unique(key, return_inverse=True, return_counts=True)
    inv = inv.reshape(-1)
    mesh_edges = np.stack([(ukey // nv) % nv, ukey % nv], axis=1)
    mesh_edge_shell = ukey // (nv * nv)
    forward = src < dst

    # node edge counts
    occ_count = counts[inv]
    n_bnd = np.bincount(ef[occ_count == 1], minlength=nf)
    n_nm = np.bincount(ef[occ_count > 2], minlength=nf)

    # face pairs per mesh edge: sort occurrences by edge, pair every two occurrences of a group
    order = np.argsort(inv, kind="stable")
    inv_s, ef_s, fw_s = inv[order], ef[order], forward[order]
    starts = np.r_[0, np.flatnonzero(np.diff(inv_s)) + 1]
    sizes = np.diff(np.r_[starts, len(inv_s)])
    pa, pb, pc, pnm = [], [], [], []
    two = starts[sizes == 2]
    pa.append(ef_s[two]); pb.append(ef_s[two + 1])
    pc.append(fw_s[two] != fw_s[two + 1]); pnm.append(np.zeros(len(two), bool))
    for st, sz in zip(starts[sizes > 2], sizes[sizes > 2]):
        fa = ef_s[st:st + sz]
        fw = fw_s[st:st + sz]
        i, j = np.triu_indices(sz, 1)
        pa.append(fa[i]); pb.append(fa[j]); pc.append(fw[i] != fw[j]); pnm.append(np.ones(len(i), bool))
    pa, pb = np.concatenate(pa), np.concatenate(pb)
    pc, pnm = np.concatenate(pc), np.concatenate(pnm)
    # the boundary flag marks adjacencies whose shared edge touches the open boundary
    bnd_vertices = np.zeros(len(V), bool)
    be = mesh_edges[counts == 1]
    bnd_vertices[be.ravel()] = True
    edge_of_pair = np.concatenate([inv_s[two]] + [np.repeat(inv_s[st], sz * (sz - 1) // 2)
                                                  for st, sz in zip(starts[sizes > 2], sizes[sizes > 2])])
    pbnd = bnd_vertices[mesh_edges[edge_of_pair]].any(axis=1)
    valid = pa != pb
    pa, pb, pc, pnm, pbnd = pa[valid], pb[valid], pc[valid], pnm[valid], pbnd[valid]

    cosd = np.einsum("ij,ij->i", normals[pa], normals[pb])
    edge_index = np.concatenate([np.stack([pa, pb]), np.stack([pb, pa])], axis=1)
    attr = np.column_stack([cosd, pbnd.astype(float), pnm.astype(float)])
    edge_attr = np.concatenate([attr, attr])
    consistent = np.concatenate([pc, pc])
    # degree: distinct neighbouring faces
    if len(pa):
        pairs = np.unique(np.sort(np.stack([pa, pb], axis=1), axis=1), axis=0)
        degree = np.bincount(pairs.ravel(), minlength=nf)
    else:
        degree = np.zeros(nf, np.intp)
    x = np.column_stack([areas, normals, h, degenerate, planarity, n_bnd, n_nm, degree]).astype(np.float64)
    return FaceGraph(x, edge_index, edge_attr, consistent, mesh_edges, counts, face_ids,
                     centroids, shell_of_face, mesh_edge_shell)


def building_graphs(buildings: Sequence[Building], lod: str | None = None,
                    tol: Tolerances = DEFAULT) -> list[FaceGraph]:
    """Face graphs of buildings' envelopes, computed in one vectorised pass.

    Every exterior shell at ``lod`` of a Building and its BuildingParts contributes its faces;
    shells never share mesh edges with each other (parts are separate shells).

    Parameters
    ----------
    buildings : sequence of Building
    lod : str, optional
        LoD for every building (default: each building's own default).

    Returns
    -------
    list of FaceGraph, one per building
    """
    surfaces, ids, shell_of, zlo, zhi, groups, offsets = [], [], [], [], [], [], []
    v_off, f_bounds, s_bounds, v_bounds = [], [], [], []
    nv = ns = 0
    for bi, b in enumerate(buildings):
        refs = b.shells(lod)
        f0, s0 = len(surfaces), ns
        bs = []
        for k, r in enumerate(refs):
            for fi, sf in enumerate(r.shell.surfaces):
                bs.append(sf)
                ids.append((r.object_id, r.geom_index, r.solid_index, r.shell_index, fi))
                shell_of.append(ns + k)
        ns += len(refs)
        rings = [ring for sf in bs for ring in sf.rings if len(ring)]
        if rings:
            used = np.concatenate(rings)
            z = b.vertices[used, 2]
            z0, z1 = float(z.min()), float(z.max())
        else:
            z0 = z1 = 0.0
        surfaces.extend(bs)  # their rings index b.vertices: face_graph adds the offset in one pass
        offsets.extend([nv] * len(bs))
        zlo.extend([z0] * len(bs))
        zhi.extend([z1] * len(bs))
        groups.append(np.full(len(b.vertices), bi, np.intp))
        v_off.append(nv)
        v_bounds.append((nv, nv + len(b.vertices)))
        nv += len(b.vertices)
        f_bounds.append((f0, len(surfaces)))
        s_bounds.append((s0, ns))
    if not surfaces:
        return [_empty_graph() for _ in buildings]
    V = np.vstack([b.vertices for b in buildings]) if buildings else np.zeros((0, 3))
    g = face_graph(V, surfaces, tol, (np.asarray(zlo), np.asarray(zhi)), ids, np.asarray(shell_of, np.intp),
                   np.concatenate(groups), np.asarray(offsets, np.intp))
    if len(buildings) == 1:
        return [g]
    # split: faces are contiguous per building; mesh edges are sorted by shell (hence building)
    node_b = np.repeat(np.arange(len(buildings)), [f1 - f0 for f0, f1 in f_bounds])
    e_b = node_b[g.edge_index[0]] if g.edge_index.shape[1] else np.zeros(0, np.intp)
    e_order = np.argsort(e_b, kind="stable")
    e_cuts = np.searchsorted(e_b[e_order], np.arange(len(buildings) + 1))
    me_shell = _mesh_edge_shells(g, len(V))
    me_cuts = np.searchsorted(me_shell, [s0 for s0, _ in s_bounds] + [ns])
    out = []
    for bi, ((f0, f1), (s0, _), vo) in enumerate(zip(f_bounds, s_bounds, v_off)):
        if f1 == f0:
            out.append(_empty_graph())
            continue
        sel = e_order[e_cuts[bi]:e_cuts[bi + 1]]
        m0, m1 = me_cuts[bi], me_cuts[bi + 1]
        out.append(FaceGraph(g.x[f0:f1], g.edge_index[:, sel] - f0, g.edge_attr[sel], g.consistent[sel],
                             g.mesh_edges[m0:m1] - vo, g.incidence[m0:m1], g.face_ids[f0:f1],
                             g.centroids[f0:f1], g.shell_of_face[f0:f1] - s0))
    return out


def _mesh_edge_shells(g: FaceGraph, n_vertices: int) -> np.ndarray:
    """Shell index of each mesh edge of ``g`` (mesh edges are sorted by shell)."""
    return g.mesh_edge_shell if g.mesh_edge_shell is not None else np.zeros(len(g.incidence), np.intp)
