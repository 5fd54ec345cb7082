"""CFD STL export: closed, outward triangle surfaces with one patch per semantic class.

One file per building (default) or per dataset, in a local metric frame whose offset is
stored in a sidecar ``<name>.stl.json`` (map coordinate = STL coordinate + offset). The
BuildingParts of a building (and, in dataset mode, touching buildings) are merged with a
boolean union (manifold3d) so that the surface has no internal walls and stays 2-manifold:
what a CFD mesher (snappyHexMesh) needs. Triangles keep their semantic class through the
union and are written as one ``solid roof`` / ``solid wall`` / ``solid ground`` (...) each,
so OpenFOAM sees them as patches. Binary STL has no solid names: the class index goes in
each triangle's attribute word (OpenFOAM reads it as the region number) and the sidecar
lists the names.
"""
from __future__ import annotations

import heapq
import json
import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable

import manifold3d as m3
import numpy as np
from scipy.spatial import cKDTree

from lod2energy import safe_write
from lod2energy.energy.parts import united_input_parts
from lod2energy.energy.zones.shells import ZoneShell, local_origin, zone_shells
from lod2energy.errors import ParameterError
from lod2energy.exporters.paths import not_written, output_path, safe_stem
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.exporters.stl.rows import row_keys, same_position, unique_rows
from lod2energy.exporters.stl.seams import split_open_edges, split_t_junctions
from lod2energy.geometry.snap import weld
from lod2energy.geometry import collapse_short_edges, signed_volume, triangle_areas, triangle_normals
from lod2energy.model import BUILDING_TYPES, Building

#: Edge-collapse tolerance (m) after the union: removes sliver triangles.
SIMPLIFY_TOL = 1e-3
#: Vertices of different parts closer than this (m) are made identical before the union.
CROSS_WELD_TOL = 1e-3
#: Largest relative change of the union's volume that its clean-up (simplify, short-edge
#: collapse) may make; a clean-up that changes more is not applied.
VOLUME_RTOL = 1e-4
#: Weld distance (m) tried first for each zone's vertices: the repaired shells are already
#: snapped at val3dity's 1 mm, and a wider weld would re-join sheets the repair separated by
#: 8 mm (the usual 10 mm weld is used when the fine one leaves the zone open).
ZONE_WELD_TOL = 1e-3
#: Distance (m) by which vertices of bodies that only touch are moved apart.
SEPARATION = 2e-3
#: A triangle lower than this (m) over its longest edge is a cap to flip away (flip_caps).
CAP_HEIGHT = 1e-6
#: Patch order (binary attribute = index).
PATCHES = ("roof", "wall", "ground", "floor")


@dataclass(frozen=True)
class StlOptions:
    """Options of :func:`write`.

    Parameters
    ----------
    mode : {"building", "dataset"}
    ascii : bool
        ASCII STL with named solids (default binary with class attributes).
    union : bool
        Merge parts / touching buildings into one closed surface (manifold3d).
    lod : str, optional
    """
    mode: str = "building"
    ascii: bool = False
    union: bool = True
    lod: str | None = None


def _zone_mesh(z: ZoneShell) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    z = split_t_junctions(z)
    # caps are flipped inside each face first: a run of collinear points shared by two
    # faces makes each face's triangulation fan its caps onto the same chord, which then
    # carries four triangles, and no neighbour across it can be told apart afterwards
    tris, codes = [], []
    faces = [(f, t) for f in z.faces if len(t := z.face_triangles(f))]
    # which faces have a cap at all, in one pass (flip_caps of a face without one returns it as it is)
    capped = _faces_with_caps(z.vertices, [t for _, t in faces]) if faces else []
    for (f, t), has_cap in zip(faces, capped):
        if has_cap:
            t, _ = flip_caps(z.vertices, t, np.zeros(len(t), dtype=np.intp))
        else:
            t = np.array(t, dtype=np.intp).reshape(-1, 3)
        tris.append(t)
        codes.append(np.full(len(t), PATCHES.index(f.kind), dtype=np.intp))
    if not tris:
        return z.vertices, np.zeros((0, 3), dtype=np.intp), np.zeros(0, dtype=np.intp)
    tris, codes = np.concatenate(tris), np.concatenate(codes)
    tris, codes = cancel_fins(tris, codes)
    tris, codes = flip_caps(z.vertices, tris, codes)
    tris, codes = split_open_edges(z.vertices, tris, codes)
    return z.vertices, tris, codes


def flip_caps(v: np.ndarray, t: np.ndarray, c: np.ndarray, rel: float = 1e-9, height: float = CAP_HEIGHT
              ) -> tuple[np.ndarray, np.ndarray]:
    """Remove zero-area "cap" triangles by flipping their longest edge.

    A polygon with collinear points can triangulate into a cap ``(a, b, c)`` whose vertex
    ``c`` lies on ``ab``; STL readers reject it as degenerate. With ``(b, a, d)`` the
    triangle across ``ab``, both are replaced by ``(b, c, d)`` and ``(c, a, d)``: same
    surface, every edge still used twice, orientation kept. The new triangles take the
    neighbour's value.

    Parameters
    ----------
    v : (n, 3) float
    t : (t, 3) int
        Closed, consistently wound triangles.
    c : (t,) int
    rel : float
        A triangle is a cap when twice its area is under ``rel`` times its longest edge squared
        (its height over that edge under ``rel`` times the edge) ...
    height : float, m
        ... or its height over its longest edge is under ``height``: such a triangle is flat
        once its corners are stored as float32 (binary STL; ~2e-6 m resolution 30 m from the
        local origin).

    Returns
    -------
    triangles (t, 3) int, values (t,) int
    """
    t = np.array(t, dtype=np.intp).reshape(-1, 3)
    c = np.array(c)
    is_cap, L2 = _caps(v, t, rel, height)
    if not is_cap.any():
        return t, c
    # the caps are tried in index order and the first that can be flipped is, again and again
    # (at most len(t) flips): a heap of the caps not yet found unflippable, and an index of the
    # triangles by directed edge, so that a flip re-examines only the caps beside it
    by_edge: dict[tuple[int, int], set[int]] = {}
    for r, (x, y, z) in enumerate(t.tolist()):
        for e in ((x, y), (y, z), (z, x)):
            by_edge.setdefault(e, set()).add(r)
    todo = np.flatnonzero(is_cap).tolist()
    queued = set(todo)
    flips = 0
    while todo and flips < len(t):
        k = heapq.heappop(todo)
        queued.discard(k)
        if not is_cap[k]:
            continue
        i = int(np.argmax(L2[k]))
        a, b, cc = int(t[k, i]), int(t[k, (i + 1) % 3]), int(t[k, (i + 2) % 3])
        hit = by_edge.get((b, a), set()) - {k}
        if len(hit) != 1:
            continue
        (h,) = hit
        rest = [int(x) for x in t[h] if x not in (a, b)]
        if not rest or rest[0] == cc:
            continue  # the neighbour is degenerate too (a, b, a), or the same triangle turned
        d = rest[0]
        touched = set()
        for r in (k, h):
            x, y, z = t[r].tolist()
            for e in ((x, y), (y, z), (z, x)):
                by_edge[e].discard(r)
                touched.add(e)
        t[k] = (b, cc, d)
        t[h] = (cc, a, d)
        c[k] = c[h]
        flips += 1
        for r in (k, h):
            x, y, z = t[r].tolist()
            for e in ((x, y), (y, z), (z, x)):
                by_edge.setdefault(e, set()).add(r)
                touched.add(e)
        is_cap[[k, h]], L2[[k, h]] = _caps(v, t[[k, h]], rel, height)
        # a cap whose longest edge lies against a changed edge may flip (or not) now
        again = {k, h}.union(*(by_edge.get((y, x), ()) for x, y in touched))
        for r in again:
            if is_cap[r] and r not in queued:
                heapq.heappush(todo, r)
                queued.add(r)
    return t, c


def _caps(v: np.ndarray, t: np.ndarray, rel: float = 1e-9, height: float = CAP_HEIGHT
          ) -> tuple[np.ndarray, np.ndarray]:
    """Which triangles ``t`` ``(t, 3)`` over ``v`` ``(n, 3)`` are caps (:func:`flip_caps`), ``(t,)``
    bool, and their squared edge lengths ``(t, 3)`` (edges ab, bc, ca); row by row, so a
    triangle's verdict does not depend on the others in ``t``."""
    P = v[t]
    e = np.stack([P[:, 1] - P[:, 0], P[:, 2] - P[:, 1], P[:, 0] - P[:, 2]], axis=1)
    L2 = (e ** 2).sum(axis=2)
    a2 = np.linalg.norm(triangle_normals(v, t, unit=False), axis=1)  # 2 x area
    Lmax = np.sqrt(L2.max(axis=1))
    return a2 < np.maximum(rel * Lmax, height) * Lmax, L2


def _faces_with_caps(v: np.ndarray, face_tris: list[np.ndarray]) -> list[bool]:
    """For each face's triangles ``(t_i, 3)`` (none empty), whether one of them is a cap
    (:func:`_caps`, on all the faces' triangles at once)."""
    is_cap, _ = _caps(v, np.concatenate(face_tris).reshape(-1, 3))
    ends = np.cumsum([len(t) for t in face_tris])
    return np.logical_or.reduceat(is_cap, np.concatenate(([0], ends[:-1]))).tolist()


def cancel_fins(t: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Drop pairs of triangles on the same three vertices with opposite orientation.

    Two faces that share a short bent path a-b-c (a near-collinear bump on a shared edge)
    each cut off the ear (a, b, c) when triangulated: the two ears cancel each other and
    their diagonal a-c is then used by four triangles. Without both ears the faces meet
    along a-c and every edge is used twice again.

    Parameters
    ----------
    t : (t, 3) int
        Triangles (vertex indices).
    c : (t,) int
        A value per triangle (kept for the triangles that stay).

    Returns
    -------
    triangles (t', 3) int, values (t',) int
    """
    t = np.asarray(t, dtype=np.intp).reshape(-1, 3)
    c = np.asarray(c)
    while len(t):
        key = np.sort(t, axis=1)
        _, inv, counts = unique_rows(key, return_inverse=True, return_counts=True)
        inv = inv.ravel()
        pair = counts[inv] == 2
        if not pair.any():
            break
        # orientation sign: parity of the permutation that sorts the triangle
        r = np.argsort(t, axis=1)
        even = ((r[:, 0] == 0) & (r[:, 1] == 1)) | ((r[:, 0] == 1) & (r[:, 1] == 2)) | ((r[:, 0] == 2) & (r[:, 1] == 0))
        s = np.where(even, 1, -1)
        total = np.zeros(len(counts), dtype=np.intp)
        np.add.at(total, inv, s)
        drop = pair & (total[inv] == 0)
        if not drop.any():
            break
        t, c = t[~drop], c[~drop]
    return t, c


def merge_meshes(meshes: list[tuple[np.ndarray, np.ndarray, np.ndarray]], union: bool = True
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """Union (or plain concatenation) of closed meshes, keeping each triangle's class.

    Parameters
    ----------
    meshes : list of (vertices (n, 3) float, triangles (t, 3) int, class codes (t,) int)

    Returns
    -------
    vertices (n, 3) float, triangles (t, 3) int, codes (t,) int, warnings
    """
    warnings: list[str] = []
    if union and len(meshes) > 1:
        code_of: list[int] = []
        parts = []
        ok = True
        # weld nearly-coincident vertices of different parts first: the union would keep
        # them as micro-edges and sliver triangles
        allv = np.concatenate([m[0] for m in meshes])
        welded, idx = weld(allv, CROSS_WELD_TOL)
        k = 0
        snapped = []
        for v, t, c in meshes:
            snapped.append((welded[idx[k:k + len(v)]], t, c))
            k += len(v)
        for v, t, c in snapped:
            ids = np.arange(len(code_of), len(code_of) + len(t), dtype=np.uint64)
            code_of.extend(c.tolist())
            mf = m3.Manifold(m3.Mesh64(vert_properties=np.ascontiguousarray(v, dtype=np.float64),
                                       tri_verts=np.ascontiguousarray(t, dtype=np.uint64), face_id=ids))
            if mf.status() != m3.Error.NoError:
                ok = False
                warnings.append(f"a part is not a closed 2-manifold ({mf.status().name}); parts not merged")
                break
            parts.append(mf)
        if ok:
            # simplify removes the slivers left where coplanar faces of touching parts met; but
            # it can take whole percents off a stepped roof: the first clean-up that keeps the
            # union's volume and leaves no degenerate triangle is used (else the simplified one)
            union_ = m3.Manifold.batch_boolean(parts, m3.OpType.Add)
            v_union = abs(union_.volume())
            codes = np.asarray(code_of, dtype=np.intp)
            first = v, t, c = _cleaned(union_.simplify(SIMPLIFY_TOL), codes)
            if not _keeps(v, t, v_union):
                for tol in (SIMPLIFY_TOL / 10, SIMPLIFY_TOL / 100, 0.0):
                    cand = _cleaned(union_.simplify(tol) if tol else union_, codes, caps=True)
                    if _keeps(*cand[:2], v_union):
                        v, t, c = cand
                        warnings.append(f"the union simplified at {tol * 1000:g} mm, not {SIMPLIFY_TOL * 1000:g}: "
                                        "that would change its volume")
                        break
                else:
                    v, t, c = first
            v, moved = separate_touching(v, t)
            if moved:
                warnings.append(f"{moved} vertices where merged parts only touch were moved "
                                f"{SEPARATION * 1000:g} mm apart")
            return v, t, c, warnings
    vs, ts, cs, k = [], [], [], 0
    for v, t, c in meshes:
        vs.append(v)
        ts.append(t + k)
        cs.append(c)
        k += len(v)
    if not vs:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.intp), np.zeros(0, dtype=np.intp), warnings
    return np.concatenate(vs), np.concatenate(ts), np.concatenate(cs), warnings


def separate_touching(v: np.ndarray, t: np.ndarray, dist: float | None = None) -> tuple[np.ndarray, int]:
    """Move apart distinct vertices that share a position (bodies touching at an edge or point).

    A union keeps such vertices distinct, so the mesh is 2-manifold by its indices, but an
    STL stores positions only (as float32) and readers would merge them into non-manifold
    edges. Vertices closer than 1e-6 m or equal once rounded to float32 count as sharing a
    position. Each copy is moved ``dist`` (m) into its own sheet, towards the centroid of
    its triangles.

    Returns
    -------
    vertices (n, 3) float, number of vertices moved
    """
    dist = SEPARATION if dist is None else dist
    pairs = cKDTree(v).query_pairs(1e-6, output_type="ndarray")
    # distinct in float64 but one point once written as float32
    inv = same_position(np.asarray(v, dtype=np.float32))
    same32 = np.nonzero(np.bincount(inv)[inv] > 1)[0]
    if len(pairs) == 0 and len(same32) == 0:
        return v, 0
    v = v.copy()
    idx = np.union1d(np.unique(pairs.ravel()), same32)
    cent = v[t].mean(axis=1)
    for i in idx:
        tri = np.nonzero(np.any(t == i, axis=1))[0]
        if len(tri) == 0:
            continue
        d = cent[tri].mean(axis=0) - v[i]
        L = np.linalg.norm(d)
        if L > 0:
            v[i] = v[i] + d / L * dist
    return v, len(idx)


def _cleaned(u, codes: np.ndarray, caps: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A manifold3d union as arrays ``(vertices (n, 3), triangles (t, 3), class codes (t,))``, its
    short edges collapsed where that keeps it closed (and, with ``caps``, zero-area caps flipped)."""
    out = u.to_mesh64()
    v = np.asarray(out.vert_properties)[:, :3].astype(np.float64)
    t = np.asarray(out.tri_verts).astype(np.intp)
    c = codes[np.asarray(out.face_id).astype(np.intp)]
    v2, t2, c2 = collapse_short_edges(v, t, c, CROSS_WELD_TOL)
    if _closed_by_position(*separate_touching(v2, t2)[:1], t2):
        v, t, c = v2, t2, c2
    if caps and len(t):
        t, c = flip_caps(v, t, c)
    return v, t, c


def _keeps(v: np.ndarray, t: np.ndarray, volume: float) -> bool:
    """The cleaned union keeps ``volume`` (m3) within :data:`VOLUME_RTOL`, has no zero-area triangle and
    is closed once read back as float32 positions."""
    if not len(t):
        return False
    if abs(abs(signed_volume(v, t)) - volume) > VOLUME_RTOL * max(volume, 1e-9):
        return False
    return bool((triangle_areas(v, t) > 1e-10).all()) and _closed_by_position(*separate_touching(v, t)[:1], t)


def _closed_by_position(v: np.ndarray, t: np.ndarray) -> bool:
    """Closed and consistently wound once vertices are merged by float32 position (as STL readers do)."""
    tt = same_position(np.asarray(v, dtype=np.float32))[t]
    e = np.concatenate([tt[:, [0, 1]], tt[:, [1, 2]], tt[:, [2, 0]]])
    if np.any(e[:, 0] == e[:, 1]):
        return False
    keys = row_keys(e)
    if keys is None:
        fwd = {tuple(x) for x in e.tolist()}
        return len(fwd) == len(e) and all((b, a) in fwd for a, b in fwd)
    # every directed edge once, and its reverse among them
    return len(np.unique(keys)) == len(e) and bool(np.isin(row_keys(e[:, ::-1]), keys).all())


def write_ascii(path, v: np.ndarray, t: np.ndarray, codes: np.ndarray, root=None) -> None:
    """ASCII STL with one ``solid <class>`` per patch, to ``path`` (atomically, inside ``root``:
    :mod:`lod2energy.safe_write`) or into an open text file."""
    if not hasattr(path, "write"):
        with safe_write.atomic_write(path, "w", root=root, encoding="ascii") as f:
            return write_ascii(f, v, t, codes)
    for chunk in ascii_solids(v, t, codes):
        path.write(chunk)


def ascii_solids(v: np.ndarray, t: np.ndarray, codes: np.ndarray, names: tuple[str, ...] = PATCHES):
    """The text of an ASCII STL, chunk by chunk: one ``solid <name>`` per code present
    (``names[code]``), vertices ``v (n, 3) float`` m, triangles ``t (k, 3) int``, ``codes (k,) int``."""
    n = triangle_normals(v, t)
    for ci, name in enumerate(names):
        sel = np.nonzero(codes == ci)[0]
        if len(sel) == 0:
            continue
        yield f"solid {name}\n"
        for k in sel:
            a, b, c = v[t[k]]
            yield (f"  facet normal {n[k, 0]:.6e} {n[k, 1]:.6e} {n[k, 2]:.6e}\n    outer loop\n"
                   f"      vertex {a[0]:.6f} {a[1]:.6f} {a[2]:.6f}\n"
                   f"      vertex {b[0]:.6f} {b[1]:.6f} {b[2]:.6f}\n"
                   f"      vertex {c[0]:.6f} {c[1]:.6f} {c[2]:.6f}\n    endloop\n  endfacet\n")
        yield f"endsolid {name}\n"


def write_binary(path, v: np.ndarray, t: np.ndarray, codes: np.ndarray, root=None) -> None:
    """Binary STL; the attribute word of each triangle is its patch index; to ``path``
    (atomically, inside ``root``) or into an open binary file."""
    if not hasattr(path, "write"):
        with safe_write.atomic_write(path, "wb", root=root) as f:
            return write_binary(f, v, t, codes)
    order = np.argsort(codes, kind="stable")
    t, codes = t[order], codes[order]
    rec = np.zeros(len(t), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["n"] = triangle_normals(v, t)
    rec["v"] = v[t]
    rec["a"] = codes
    header = b"lod2energy STL; patches: " + ",".join(PATCHES).encode()
    path.write(header.ljust(80, b" ")[:80])
    path.write(struct.pack("<I", len(t)))
    path.write(rec.tobytes())


def write(buildings: Iterable[Building], outdir: str | Path, options: StlOptions | None = None,
          crs: str | None = None) -> list[ExportResult]:
    """Write STL files (and their sidecar JSON) and self-check them.

    Returns
    -------
    list of ExportResult
        One per STL file.
    """
    options = options or StlOptions()
    if options.mode not in ("building", "dataset"):
        raise ParameterError(f"--stl-mode must be 'building' or 'dataset', not {options.mode!r}")
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    blist = [b for b in buildings if b.type in BUILDING_TYPES and b.envelope(options.lod)]
    groups = [[b] for b in blist] if options.mode == "building" else ([blist] if blist else [])
    used: set[str] = set()
    results = []
    for g in groups:
        offset = local_origin(g)
        meshes, warnings = [], []
        try:
            for b in g:
                # a fine weld first (keeps sheets the repair separated by millimetres apart);
                # the exporters' usual 10 mm weld when that leaves a zone open
                zs = zone_shells(b, offset, options.lod, weld_tol=ZONE_WELD_TOL)
                ms = [_zone_mesh(z) for z in zs]
                if not all(_closed_by_position(v_, t_) for v_, t_, _ in ms):
                    zs = zone_shells(b, offset, options.lod)
                    ms = [_zone_mesh(z) for z in zs]
                for z, zm in zip(zs, ms):
                    warnings.extend(w for w in z.warnings if "uValue" not in w)
                    meshes.append(zm)
            v, t, c, w = merge_meshes(meshes, options.union)
        except Exception as e:  # noqa: BLE001 - one building's geometry never stops the batch
            results.append(ExportResult(tuple(b.id for b in g), "", False,
                                        (f"STL not written: {type(e).__name__}: {e}",),
                                        tuple(float(x) for x in offset), tuple(warnings), {}))
            continue
        warnings.extend(w)
        stem = safe_stem(g[0].id if len(g) == 1 else "dataset", used)
        path = output_path(out, stem, ".stl")
        sidecar = {
            "building_ids": [b.id for b in g],
            "offset": [float(x) for x in offset],
            "crs": crs,
            "units": "m",
            "format": "ascii" if options.ascii else "binary",
            "patches": {p: int((c == i).sum()) for i, p in enumerate(PATCHES) if (c == i).any()},
            "patch_index": {p: i for i, p in enumerate(PATCHES)},
            "merged": bool(options.union and not w),
        }
        stats = {"triangles": int(len(t)), "parts": len(meshes),
                 "volume_m3": round(signed_volume(v, t), 3) if len(t) else 0.0}
        try:  # the STL self-checked on its staged temporary: a failed one never gets the good name
            # its folder is synced after the STL's rename, just below (write_checked)
            sidecar_path = output_path(out, stem, ".stl.json")
            safe_write.write_text(sidecar_path, json.dumps(sidecar, indent=1), root=out,
                                  sync_folder=False)
            final, problems = safe_write.write_checked(
                path, lambda f: (write_ascii if options.ascii else write_binary)(f, v, t, c), self_check,
                "w" if options.ascii else "wb", root=out, **({"encoding": "ascii"} if options.ascii else {}))
        except OSError as e:  # a full disk, a link planted under the name: this file only
            results.append(ExportResult(tuple(b.id for b in g), "", False, (not_written(e, "STL"),),
                                        tuple(float(x) for x in offset), tuple(warnings), stats))
            continue
        if problems:
            problems = list(problems) + [f"failed its self-check: kept as {Path(final).name}" if final
                                         else "failed its self-check: removed"]
        results.append(ExportResult(tuple(b.id for b in g), final, not problems, tuple(problems),
                                    tuple(float(x) for x in offset), tuple(warnings), stats,
                                    sidecars=(str(sidecar_path),)))
    return results


def read_stl(path: str | Path) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """Triangles ``(t, 3, 3)``, their patch index ``(t,)`` and the patch names of an STL file."""
    data = Path(path).read_bytes()
    if len(data) >= 84:
        n = struct.unpack("<I", data[80:84])[0]
        if 84 + 50 * n == len(data):
            rec = np.frombuffer(data[84:], dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")], count=n)
            return rec["v"].astype(np.float64), rec["a"].astype(np.intp), list(PATCHES)
    tris, codes, names = [], [], []
    cur: list[list[float]] = []
    for line in data.decode("ascii", errors="replace").splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == "solid":
            names.append(w[1] if len(w) > 1 else f"patch{len(names)}")
        elif w[0] == "vertex":
            cur.append([float(x) for x in w[1:4]])
            if len(cur) == 3:
                tris.append(cur)
                codes.append(len(names) - 1)
                cur = []
    return np.asarray(tris, dtype=np.float64).reshape(-1, 3, 3), np.asarray(codes, dtype=np.intp), names


def self_check(path: str | Path) -> list[str]:
    """Re-read an STL and check it the way OpenFOAM's ``surfaceCheck`` reads it.

    The triangle corners are taken as float32 (what a binary STL stores and what OpenFOAM
    parses an ASCII STL into) and merged only when exactly equal (surfaceCheck merges
    points closer than 1e-14 m, not to a rounding grid). Then: no triangle with two equal
    corners or zero area (surfaceCheck's illegal triangles), every edge in exactly two
    triangles (closed), every directed edge once (consistent winding: one normal zone per
    connected part), positive volume (outward); patches named.

    Returns
    -------
    list of str
        Problems (empty when fine).
    """
    try:
        tris, codes, names = read_stl(path)
    except (OSError, ValueError) as e:
        return [f"cannot read {Path(path).name}: {e}"]
    if len(tris) == 0:
        return ["no triangles"]
    problems = []
    p32 = tris.astype(np.float32).reshape(-1, 3)
    pts, inv = np.unique(p32, axis=0, return_inverse=True)
    pts = pts.astype(np.float64)
    t = inv.reshape(-1, 3)
    repeated = (t[:, 0] == t[:, 1]) | (t[:, 1] == t[:, 2]) | (t[:, 0] == t[:, 2])
    if repeated.any():
        problems.append(f"{int(repeated.sum())} triangle(s) with coincident corners once read as float32 "
                        "(illegal for surfaceCheck; the surface is not closed)")
    area = triangle_areas(pts, t)
    flat = ~repeated & (area <= 1e-10)
    if flat.any():
        problems.append(f"{int(flat.sum())} degenerate triangle(s)")
    good = t[~repeated]
    e = np.concatenate([good[:, [0, 1]], good[:, [1, 2]], good[:, [2, 0]]])
    _, ecount = unique_rows(np.sort(e, axis=1), return_counts=True)
    if np.any(ecount != 2):
        problems.append(f"not closed: {int(np.sum(ecount == 1))} edge(s) in one triangle, "
                        f"{int(np.sum(ecount > 2))} in more than two")
    _, dcount = unique_rows(e, return_counts=True)
    if np.any(dcount > 1):
        problems.append(f"inconsistent winding: {int(np.sum(dcount > 1))} edge(s) traversed twice the same way")
    vol = signed_volume(pts, t)
    if not vol > 0:
        problems.append(f"not outward: volume {vol:.3f} m3")
    if len(set(codes.tolist())) and not names:
        problems.append("no patch names")
    return problems


def _write(buildings, outdir, options, *, crs=None, **_):
    return write(buildings, outdir, options, crs=crs)


register_writer("stl", _write, self_check, scope=lambda options: "dataset" if options.mode == "dataset" else "building",
                prepare=united_input_parts)
