"""Stage 4 of the repair ladder: alpha-shape reconstruction with a search over alpha.

Candidates are CGAL's 3D alpha wrap (through pymeshlab's ``generate_alpha_wrap``, fed a
triangle soup so that no face is silently skipped) at several alphas, each decimated with
planar quadric edge collapse and its coplanar triangles merged back into polygons, and our
own alpha complex of the building's points (Delaunay tetrahedra whose circumradius is under
alpha). Among the valid candidates that are not hollow (volume at least a third of the
convex hull's) the one closest to the input (two-way mean vertex-to-surface distance) wins.
"""
from __future__ import annotations

import multiprocessing as mp
import os
import resource
import signal
import threading
import time
from multiprocessing.connection import Connection

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.polymesh import PolyMesh, face_area, merge_coplanar, signed_volume, triangles_to_mesh, triangulate_mesh
from lod2energy.repair.cleanup import fix_nonplanar
from lod2energy.repair.metrics import point_triangle_distance
from lod2energy.validate.closed import shell_defects

ALPHAS = (8.0, 4.0, 2.0)  # m: 8 and 4 bridge missing party walls; 2 follows closed but tangled shells closer (hollow skins are rejected below)
OFFSET = DEFAULT.wrap_offset  # m, default of Tolerances.wrap_offset

MAX_WRAP_AREA = 1.0e6
"""Largest surface area handed to the alpha wrap, m2.

CGAL refines the wrap until it lies within :data:`OFFSET` of the input, so its size grows with
the wrapped area, up to about 3 triangles per m2 where it wraps both sides of thin walls
(measured: an open 200 x 100 x 20 m box, 5e4 m2, gives 1.4e5 triangles in 18 s). 1e6 m2 covers
the largest real buildings (a 1 km x 0.5 km hall) while keeping the worst case within a few GB;
larger inputs skip the wrap (the alpha complex, footprint and hull stages remain).
"""

WRAP_MEMORY = 4 * 1024 ** 3
"""Address space one alpha wrap may add to the process, bytes (a wrap over it fails cleanly)."""


def _soup(m: PolyMesh) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    tris, _ = triangulate_mesh(m)
    origin = m.vertices[np.unique(tris)].mean(axis=0) if len(tris) else np.zeros(3)
    P = m.vertices[tris.ravel()] - origin
    F = np.arange(len(P)).reshape(-1, 3)
    return P, F, origin


def _wrap_arrays(P: np.ndarray, F: np.ndarray, alpha_pct: float, offset_pct: float,
                 target_faces: int | None) -> tuple[np.ndarray, np.ndarray] | None:
    """pymeshlab's alpha wrap (+ planar decimation) of a soup; (V, T) or None on failure."""
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=P, face_matrix=F))
    try:
        ms.generate_alpha_wrap(alpha=pymeshlab.PercentageValue(alpha_pct),
                               offset=pymeshlab.PercentageValue(offset_pct))
        if target_faces is not None and ms.current_mesh().face_number() > target_faces:
            ms.meshing_decimation_quadric_edge_collapse(targetfacenum=target_faces, preservetopology=True,
                                                        planarquadric=True, preservenormal=True,
                                                        qualitythr=0.3, autoclean=True)
    except Exception:  # noqa: BLE001 - pymeshlab raises its own error types
        return None
    cm = ms.current_mesh()
    return np.asarray(cm.vertex_matrix(), dtype=np.float64), np.asarray(cm.face_matrix(), dtype=np.int64)


def _wrap_child(conn, args) -> None:  # pragma: no cover - runs in the forked child
    try:
        with open("/proc/self/statm") as f:
            vm = int(f.read().split()[0]) * resource.getpagesize()
        resource.setrlimit(resource.RLIMIT_AS, (vm + WRAP_MEMORY, vm + WRAP_MEMORY))
    except (OSError, ValueError, ImportError):
        pass
    try:
        conn.send(_wrap_arrays(*args))
    except BaseException:  # noqa: BLE001 - MemoryError included: the parent sees None
        try:
            conn.send(None)
        except BaseException:  # noqa: BLE001
            pass
    finally:
        conn.close()
        os._exit(0)


def _wrap_until(args, deadline: float | None):
    """:func:`_wrap_arrays` in a forked child killed at ``deadline`` (CGAL cannot be interrupted).

    The child also keeps this process small: pymeshlab (Qt and its filter plugins, about 50 MB a
    process) is imported there, not here, so a pool worker's memory does not jump at its first
    alpha wrap. The child is forked with :func:`os.fork` (a daemonic pool worker may not start
    ``multiprocessing`` children); a daemonic process with more than one thread (e.g. a Dask
    worker, where fork is unsafe) wraps in-process. Without a deadline, or where fork is
    unavailable, the wrap runs in this process.
    """
    if deadline is None or not hasattr(os, "fork"):
        return _wrap_arrays(*args)
    if mp.current_process().daemon and threading.active_count() > 1:
        return _wrap_arrays(*args)
    left = deadline - time.monotonic()
    if left <= 0:
        return None
    return _wrap_forked(args, left)


def _wrap_forked(args, left: float):
    """:func:`_wrap_arrays` in a child of :func:`os.fork`, killed after ``left`` seconds; None
    when it fails or overruns."""
    r, w = os.pipe()
    try:
        pid = os.fork()
    except OSError:
        os.close(r)
        os.close(w)
        return _wrap_arrays(*args)
    if pid == 0:  # pragma: no cover - the child
        try:
            os.close(r)
            _wrap_child(Connection(w, readable=False), args)
        finally:
            os._exit(0)
    os.close(w)
    recv = Connection(r, writable=False)
    try:
        if not recv.poll(max(left, 0.0)):
            return None  # over budget
        try:
            return recv.recv()
        except (EOFError, OSError):
            return None
    finally:
        recv.close()
        try:
            if os.waitpid(pid, os.WNOHANG) == (0, 0):  # still running: over budget
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
        except ChildProcessError:
            pass


def alpha_wrap(m: PolyMesh, alpha: float, offset: float = OFFSET, target_faces: int | None = 400,
               deadline: float | None = None) -> PolyMesh | None:
    """CGAL alpha wrap of ``m`` (alpha and offset in m), decimated and merged into polygons.

    Parameters
    ----------
    deadline : float or None
        ``time.monotonic()`` value after which the wrap is abandoned (None: no limit).

    Returns
    -------
    PolyMesh or None
        None when the wrap fails, runs past ``deadline`` or the input's surface exceeds
        :data:`MAX_WRAP_AREA`.
    """
    P, F, origin = _soup(m)
    if len(F) == 0:
        return None
    diag = float(np.linalg.norm(P.max(axis=0) - P.min(axis=0)))
    if not np.isfinite(diag) or diag <= 0:
        return None
    T3 = P[F]
    area = 0.5 * float(np.linalg.norm(np.cross(T3[:, 1] - T3[:, 0], T3[:, 2] - T3[:, 0]), axis=1).sum())
    if area > MAX_WRAP_AREA:
        return None
    out = _wrap_until((P, F, 100 * alpha / diag, 100 * offset / diag, target_faces), deadline)
    if out is None:
        return None
    V, T = out
    V = V + origin
    if len(T) < 4:
        return None
    return fix_nonplanar(merge_coplanar(triangles_to_mesh(V, T), angle_tol=1e-5, dist_tol=1e-3), DEFAULT)


def alpha_complex(m: PolyMesh, alpha: float) -> PolyMesh | None:
    """Boundary of the union of Delaunay tetrahedra with circumradius <= alpha (m)."""
    from scipy.spatial import Delaunay, QhullError
    used = np.unique([i for f in m.faces for r in f.rings for i in r])
    if len(used) < 4:
        return None
    P = m.vertices[used]
    o = P.mean(axis=0)
    Q = P - o
    try:
        d = Delaunay(Q)
    except (QhullError, ValueError):
        return None
    S = d.simplices
    A = Q[S]
    # circumradius of each tetrahedron
    a = A[:, 1:] - A[:, :1]
    rhs = 0.5 * np.einsum("ijk,ijk->ij", a, a)
    det = np.linalg.det(a)
    ok = np.abs(det) > 1e-12
    c = np.zeros((len(S), 3))
    c[ok] = np.linalg.solve(a[ok], rhs[ok][..., None])[..., 0]
    R = np.where(ok, np.linalg.norm(c, axis=1), np.inf)
    keep = S[R <= alpha]
    if len(keep) == 0:
        return None
    faces = np.concatenate([keep[:, [1, 2, 3]], keep[:, [0, 3, 2]], keep[:, [0, 1, 3]], keep[:, [0, 2, 1]]])
    # orient each face away from its tetrahedron's fourth vertex
    opp = np.concatenate([keep[:, 0], keep[:, 1], keep[:, 2], keep[:, 3]])
    T = Q[faces]
    n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    flip = np.einsum("ij,ij->i", n, Q[opp] - T[:, 0]) > 0
    faces[flip] = faces[flip][:, ::-1]
    key = np.sort(faces, axis=1)
    _, inv, cnt = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    bnd = faces[cnt[inv.ravel()] == 1]
    if len(bnd) < 4:
        return None
    vid = np.unique(bnd)
    lut = np.full(len(P), -1)
    lut[vid] = np.arange(len(vid))
    return merge_coplanar(triangles_to_mesh(P[vid], lut[bnd]), angle_tol=1e-6, dist_tol=1e-4)


def _hull_volume(m: PolyMesh) -> float:
    from scipy.spatial import ConvexHull, QhullError
    used = np.unique([i for f in m.faces for r in f.rings for i in r])
    try:
        return float(ConvexHull(m.vertices[used]).volume)
    except (QhullError, ValueError):
        return 0.0


def _area(m: PolyMesh) -> float:
    return float(sum(face_area(m.vertices, f) for f in m.faces))


def alpha_repair(m: PolyMesh, tol: Tolerances = DEFAULT, deadline: float | None = None,
                 alphas=ALPHAS, accept=None) -> PolyMesh | None:
    """Stage 4: the best valid alpha reconstruction of ``m`` (None if no candidate is valid).

    Parameters
    ----------
    accept : callable or None
        Extra validity test (the pipeline passes its full criterion).
    """
    tris, _ = triangulate_mesh(m)
    if len(tris) == 0:
        return None
    hv = _hull_volume(m)
    pts = m.vertices[np.unique(tris)]
    best, best_score = None, None
    cands = [("complex", 2 * a) for a in alphas]
    for a in alphas:
        cands += [("wrap", a, 400), ("wrap", a, 1500), ("wrap", a, None)]
    for kind, a, *target in cands:
        if deadline is not None and time.monotonic() > deadline:
            break
        if best is not None and kind == "wrap" and target[0] != 400:
            continue  # a coarser valid wrap is already in hand
        r = alpha_complex(m, a) if kind == "complex" else alpha_wrap(m, a, tol.wrap_offset, target_faces=target[0],
                                                                            deadline=deadline)
        if r is None or shell_defects([r], tol, first_only=True)[0]:
            continue
        if accept is not None and not accept(r):
            continue
        vol = signed_volume(r)
        if vol < hv / 3 and vol < tol.skin_depth * _area(r):
            continue  # a hollow skin around missing walls, not a building (a slender tower
            # fills a third of its hull neither, but its volume per area is metres)
        rt, _ = triangulate_mesh(r)
        score = point_triangle_distance(pts, r.vertices, rt).mean() + \
            point_triangle_distance(r.vertices, m.vertices, tris).mean()
        if best_score is None or score < best_score - 1e-9:
            best, best_score = r, score
    return best
