"""Shared export plumbing: safe file names, local origin, zone shells, planar pieces, mesh checks.

Every exporter reads "energy-ready" buildings (closed, outward Solids with one semantic entry
per surface) and needs the same things: a file name that stays inside the output folder
whatever the building id holds, coordinates shifted to a local origin so that map
coordinates (1e5-1e6 m) keep millimetre precision, one welded vertex set per zone
(Building or BuildingPart), faces split into planar convex pieces or triangles, and a
check that a written shell is still closed and outward.
"""
from __future__ import annotations

import hashlib
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

import numpy as np

from lod2energy.errors import ExportError
from lod2energy.model import Building

#: Weld distance for zone vertices (m): EnergyPlus warns about vertices closer than 1 cm.
WELD_TOL = 0.01
#: Largest distance of a vertex to its face plane (m) for the face to be written as one piece.
PLANAR_TOL = 0.01
#: Vertices closer than this (m) to the line through their ring neighbours are dropped.
COLLINEAR_TOL = 0.01
#: Pieces at or under this area (m2) are dropped (they are sliver triangles of collapsed faces).
MIN_PIECE_AREA = 1e-4

#: Semantic surface type -> exporter class.
SEMANTIC_CLASS = {
    "RoofSurface": "roof",
    "OuterCeilingSurface": "roof",
    "WallSurface": "wall",
    "ClosureSurface": "wall",
    "GroundSurface": "ground",
    "OuterFloorSurface": "floor",
}
#: U-values (W/(m2 K)) used only when neither the surface nor ``provenance["thermal"]`` has one;
#: every use is reported as a warning of the export.
FALLBACK_U = {"roof": 0.4, "wall": 0.5, "ground": 0.5, "floor": 0.5, "window": 2.8}


@dataclass(frozen=True)
class ExportResult:
    """Outcome of writing one file.

    Parameters
    ----------
    building_ids : tuple of str
        Ids of the buildings written to ``path``.
    path : str
        The file written.
    ok : bool
        True when the self-check (and the simulation, after a run) found no problem.
    problems : tuple of str
        Self-check / simulation failures (one line each).
    offset : (3,) tuple of float, m
        Local origin: map coordinate = file coordinate + offset.
    warnings : tuple of str
        Things the user should know that do not make the file wrong (default U-values...).
    stats : mapping
        Counts (zones, surfaces, windows, shading surfaces, triangles ...).
    heating_kwh, cooling_kwh : float or None, kWh
        Annual ideal-loads heating / cooling demand (after an EnergyPlus run).
    severe_errors : int or None
        Severe errors in ``eplusout.err`` (after a run).
    not_enclosed : tuple of str or None
        Zones EnergyPlus found not fully enclosed (after a run).
    """

    building_ids: tuple[str, ...]
    path: str
    ok: bool
    problems: tuple[str, ...] = ()
    offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    warnings: tuple[str, ...] = ()
    stats: Mapping[str, Any] = field(default_factory=dict)
    heating_kwh: float | None = None
    cooling_kwh: float | None = None
    severe_errors: int | None = None
    not_enclosed: tuple[str, ...] | None = None

    def to_dict(self) -> dict:
        d = {k: getattr(self, k) for k in self.__dataclass_fields__}
        d["building_ids"] = list(self.building_ids)
        d["problems"] = list(self.problems)
        d["warnings"] = list(self.warnings)
        d["offset"] = list(self.offset)
        d["stats"] = dict(self.stats)
        if self.not_enclosed is not None:
            d["not_enclosed"] = list(self.not_enclosed)
        return d


# --------------------------------------------------------------------------- names and paths

_UNSAFE_FILE = re.compile(r"[^A-Za-z0-9._-]+")


def _short_hash(text: str, n: int = 8) -> str:
    return hashlib.sha1(text.encode("utf-8", "surrogatepass")).hexdigest()[:n]


def safe_stem(text: str, used: set[str] | None = None, max_len: int = 80) -> str:
    """File-name stem for an arbitrary id: ``[A-Za-z0-9._-]`` only, never hidden, unique.

    Any change (replaced characters, truncation) or a clash with ``used`` (compared
    case-insensitively, for case-insensitive file systems) appends a hash of the original,
    so two different ids never share a file. ``used`` is updated.
    """
    text = str(text)
    stem = _UNSAFE_FILE.sub("_", text).strip("._-") or "building"
    changed = stem != text or len(stem) > max_len
    stem = stem[:max_len]
    if changed:
        stem = f"{stem}_{_short_hash(text)}"
    if used is not None:
        base, k = stem, 1
        while stem.lower() in used:
            stem = f"{base}_{_short_hash(text + str(k))}"
            k += 1
        used.add(stem.lower())
    return stem


def output_path(outdir: str | Path, stem: str, suffix: str) -> Path:
    """``outdir/stem+suffix``, refusing any name that would leave ``outdir``.

    The name itself is not resolved: a link planted under it is refused when the file is
    written (:func:`lod2energy.safe_write.check_target`), for that file only.
    """
    root = Path(outdir).resolve()
    name = f"{stem}{suffix}"
    if "/" in name or "\\" in name or name in (".", "..") or "\0" in name:
        raise ExportError(f"refusing to write outside {root}: {stem!r}")
    return root / name


def not_written(e: OSError, what: str) -> str:
    """One line for a file that could not be written (full disk, refused link ...)."""
    return f"{what} not written: {e.strerror or e}" + (f" ({e.filename})" if e.filename else "")


def set_aside_failed(res: ExportResult) -> ExportResult:
    """``res`` with its file moved to ``<name>.invalid`` when it failed its self-check.

    A file that did not pass is never left under the name of a good one: the result's
    ``path`` becomes the ``.invalid`` name and a problem line says so.
    """
    from lod2energy.safe_write import set_aside

    if res.ok or not res.path or not Path(res.path).exists():
        return res
    bad = set_aside(res.path)
    note = f"failed its self-check: kept as {Path(bad).name}" if bad else "failed its self-check: removed"
    return ExportResult(res.building_ids, bad, False, tuple(res.problems) + (note,), res.offset, res.warnings,
                        res.stats, res.heating_kwh, res.cooling_kwh, res.severe_errors, res.not_enclosed)


# --------------------------------------------------------------------------- local origin

def local_origin(buildings: Iterable[Building]) -> np.ndarray:
    """Origin of the local frame: the floor (to whole metres) of the bounding-box minimum.

    Returns
    -------
    (3,) float, m
        Subtract from map coordinates to get file coordinates.
    """
    lo = None
    for b in buildings:
        if len(b.vertices) == 0:
            continue
        m = np.nanmin(b.vertices, axis=0)
        lo = m if lo is None else np.minimum(lo, m)
    if lo is None or not np.all(np.isfinite(lo)):
        return np.zeros(3)
    return np.floor(lo)


# --------------------------------------------------------------------------- polygon geometry

# Kept apart from lod2energy.geometry on purpose (issue 14): geometry.newell_normal centres the
# ring and sums cross products - equal in exact arithmetic, different in the last bits (1,922 of
# 2,000 random rings) - and the exporters' thresholds (piece area, planarity, collinearity) and
# their written IDF/STL bytes are made with this classic uncentred Newell sum. Swapping changes
# output bytes; exporter coordinates are local (small), so this form loses no precision here.
def newell_normal(points: np.ndarray) -> np.ndarray:
    """Area-weighted normal of a polygon (Newell), length = 2 x area.

    Parameters
    ----------
    points : (k, 3) float
    """
    p = np.asarray(points, dtype=np.float64)
    q = np.roll(p, -1, axis=0)
    return np.array([
        np.sum((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])),
        np.sum((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])),
        np.sum((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])),
    ])


def unit(v: np.ndarray) -> np.ndarray:
    n = float(np.linalg.norm(v))
    return v / n if n > 0 else v


def plane_basis(normal: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    # no counterpart in lod2energy.geometry (project_2d drops a coordinate instead): the
    # exporters need a horizontal u so that walls are written with "up" = v
    """Orthonormal (u, v) in the plane of unit ``normal`` with u x v = normal.

    u is horizontal (so for walls v points up), except on horizontal planes where u = +x.
    """
    n = unit(np.asarray(normal, dtype=np.float64))
    up = np.array([0.0, 0.0, 1.0])
    u = np.cross(up, n)
    if np.linalg.norm(u) < 1e-6:
        u = np.array([1.0, 0.0, 0.0]) - n[0] * n
    u = unit(u)
    v = np.cross(n, u)
    return u, v


def polygon_area3d(points: np.ndarray) -> float:
    """Area (m2) of a planar polygon, (k, 3) points: half the length of :func:`newell_normal`
    (the exporters' Newell sum, see the note above it)."""
    return 0.5 * float(np.linalg.norm(newell_normal(points)))


def triangulate(points: np.ndarray, ring_ends: Sequence[int], normal: np.ndarray | None = None) -> np.ndarray:
    """Triangulate a 3D polygon with holes (earcut in its plane).

    Parameters
    ----------
    points : (k, 3) float
        Outer ring then holes, concatenated, rings open.
    ring_ends : sequence of int
        End index (exclusive) of each ring in ``points``.
    normal : (3,) float, optional
        Orientation of the result; defaults to the outer ring's Newell normal.

    Returns
    -------
    (t, 3) int
        Indices into ``points``, each triangle counter-clockwise seen from ``normal``.
    """
    import mapbox_earcut

    p = np.asarray(points, dtype=np.float64)
    if normal is None:
        normal = newell_normal(p[: ring_ends[0]])
    n = unit(normal)
    if not np.any(n):
        return np.zeros((0, 3), dtype=np.intp)
    u, v = plane_basis(n)
    c = p.mean(axis=0)
    xy = np.column_stack([(p - c) @ u, (p - c) @ v])
    tri = mapbox_earcut.triangulate_float64(xy, np.asarray(ring_ends, dtype=np.uint32))
    tri = np.asarray(tri, dtype=np.intp).reshape(-1, 3)
    if len(tri) == 0:
        return tri
    a, b, cc = xy[tri[:, 0]], xy[tri[:, 1]], xy[tri[:, 2]]
    cross = (b[:, 0] - a[:, 0]) * (cc[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (cc[:, 0] - a[:, 0])
    flip = cross < 0
    tri[flip] = tri[flip][:, ::-1]
    missing = np.setdiff1d(np.arange(len(p)), tri.ravel())
    if len(missing):
        tri = _insert_dropped(tri, xy, missing)
    return tri


def _insert_dropped(tri: np.ndarray, xy: np.ndarray, missing: np.ndarray) -> np.ndarray:
    """Put back ring vertices earcut skipped (collinear ones) by splitting the triangle edge
    they lie on, so that neighbouring faces still share every vertex (no T-junction)."""
    tris = [list(t) for t in tri]
    for m in missing:
        q = xy[m]
        best, bd = None, np.inf
        for ti, t in enumerate(tris):
            for k in range(3):
                a, b = t[k], t[(k + 1) % 3]
                ab = xy[b] - xy[a]
                L2 = float(ab @ ab)
                if L2 == 0:
                    continue
                u = float((q - xy[a]) @ ab) / L2
                if not 0 < u < 1:
                    continue
                d = float(np.linalg.norm(xy[a] + u * ab - q))
                if d < bd:
                    best, bd = (ti, k), d
        if best is None:
            continue
        ti, k = best
        t = tris[ti]
        a, b, c = t[k], t[(k + 1) % 3], t[(k + 2) % 3]
        tris[ti] = [a, int(m), c]
        tris.append([int(m), b, c])
    return np.asarray(tris, dtype=np.intp).reshape(-1, 3)


#: Smallest sine of the turn at a vertex of a written convex piece: EnergyPlus removes
#: (near-)collinear vertices, which would leave T-junctions with the neighbouring surfaces.
STRICT_SIN = 2e-3


def _is_convex_2d(xy: np.ndarray, eps: float = 1e-9, strict: bool = False) -> bool:
    """Counter-clockwise polygon ``(k, 2)`` convex?

    Collinear corners are allowed unless ``strict`` (then every turn must have a sine of
    at least :data:`STRICT_SIN`).
    """
    d1 = np.roll(xy, -1, axis=0) - xy
    d2 = np.roll(d1, -1, axis=0)
    cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    scale = np.maximum(np.linalg.norm(d1, axis=1) * np.linalg.norm(d2, axis=1), 1e-12)
    if strict:
        return bool(np.all(cross >= STRICT_SIN * scale))
    return bool(np.all(cross >= -eps * scale))


def merge_convex(tris: np.ndarray, xy: np.ndarray, strict: bool = False) -> list[list[int]]:
    """Hertel-Mehlhorn: merge counter-clockwise triangles into convex polygons.

    Parameters
    ----------
    tris : (t, 3) int
        Triangles (indices into ``xy``) of one planar polygon.
    xy : (k, 2) float
        Vertex coordinates in the polygon's plane.

    Returns
    -------
    list of list of int
        Convex counter-clockwise polygons covering the same area, using only the
        triangles' vertices (so shared edges with other faces are kept).
    """
    polys: list[list[int] | None] = [list(map(int, t)) for t in tris]
    changed = True
    while changed:
        changed = False
        edge_owner: dict[tuple[int, int], int] = {}
        for pi, poly in enumerate(polys):
            if poly is None:
                continue
            for k in range(len(poly)):
                edge_owner[(poly[k], poly[(k + 1) % len(poly)])] = pi
        for (a, b), pi in list(edge_owner.items()):
            qi = edge_owner.get((b, a))
            if qi is None or qi == pi or polys[pi] is None or polys[qi] is None:
                continue
            p, q = polys[pi], polys[qi]
            if (a, b) not in {(p[k], p[(k + 1) % len(p)]) for k in range(len(p))}:
                continue
            i = p.index(b)
            p_rot = p[i:] + p[:i]          # b ... a
            j = q.index(a)
            q_rot = q[j:] + q[:j]          # a ... b
            merged = p_rot + q_rot[1:-1]   # b ... a ... (before b)
            if len(set(merged)) != len(merged):
                continue
            if _is_convex_2d(xy[merged], strict=strict):
                polys[pi] = merged
                polys[qi] = None
                changed = True
                break
    return [p for p in polys if p is not None]


# --------------------------------------------------------------------------- zones

@dataclass(frozen=True)
class ZoneFace:
    """One input surface of a zone, as rings of indices into the zone's vertices.

    Parameters
    ----------
    rings : tuple of tuple of int
        Outer ring first, then holes, indices into :attr:`ZoneShell.vertices`.
    kind : str
        "roof", "wall", "ground" or "floor" (outdoor floor).
    semantic_type : str or None
        The CityJSON semantic type.
    u_value : float, W/(m2 K)
    index : int
        Position of the surface in the input shell.
    """

    rings: tuple[tuple[int, ...], ...]
    kind: str
    semantic_type: str | None
    u_value: float
    index: int


@dataclass(frozen=True)
class ZoneShell:
    """The closed envelope of one Building / BuildingPart in local coordinates.

    Parameters
    ----------
    building_id, object_id : str
    vertices : (n, 3) float, m
        Welded local coordinates (map coordinates minus the export offset).
    faces : tuple of ZoneFace
    u_window : float, W/(m2 K)
    wwr : float
        Window-to-wall ratio (0..1).
    warnings : tuple of str
    """

    building_id: str
    object_id: str
    vertices: np.ndarray
    faces: tuple[ZoneFace, ...]
    u_window: float
    wwr: float
    warnings: tuple[str, ...] = ()

    def face_points(self, face: ZoneFace) -> tuple[np.ndarray, tuple[int, ...]]:
        """Concatenated ring coordinates ``(k, 3)`` and ring end indices."""
        pts = np.concatenate([self.vertices[list(r)] for r in face.rings])
        ends = tuple(np.cumsum([len(r) for r in face.rings]).tolist())
        return pts, ends

    def face_triangles(self, face: ZoneFace) -> np.ndarray:
        """Triangles ``(t, 3)`` of one face (indices into ``vertices``)."""
        idx = np.concatenate([np.asarray(r, dtype=np.intp) for r in face.rings])
        pts, ends = self.face_points(face)
        t = triangulate(pts, ends)
        return idx[t] if len(t) else np.zeros((0, 3), dtype=np.intp)

    def triangles(self) -> tuple[np.ndarray, list[str]]:
        """Triangles of every face ``(t, 3)`` (vertex indices) and the face kind of each."""
        tris, kinds = [], []
        for f in self.faces:
            t = self.face_triangles(f)
            if len(t):
                tris.append(t)
                kinds.extend([f.kind] * len(t))
        if not tris:
            return np.zeros((0, 3), dtype=np.intp), []
        return np.concatenate(tris), kinds


def weld(points: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    # not lod2energy.geometry.snap_map on purpose: snap_map keeps each cluster's first point
    # (val3dity's rule, so validation sees the input's coordinates), the exporters write each
    # cluster's mean (a zone's corner between the welded inputs)
    """Merge points closer than ``tol`` (transitively).

    Returns
    -------
    welded : (m, 3) float
        One point per cluster (the mean).
    index : (n,) int
        Cluster of each input point.
    """
    from scipy.cluster.hierarchy import DisjointSet
    from scipy.spatial import cKDTree

    p = np.asarray(points, dtype=np.float64)
    if len(p) == 0:
        return p.reshape(0, 3), np.zeros(0, dtype=np.intp)
    pairs = cKDTree(p).query_pairs(tol, output_type="ndarray")
    if len(pairs) == 0:
        return p.copy(), np.arange(len(p))
    ds = DisjointSet(range(len(p)))
    for a, b in pairs:
        ds.merge(int(a), int(b))
    roots = np.array([ds[i] for i in range(len(p))])
    _, index = np.unique(roots, return_inverse=True)
    welded = np.zeros((index.max() + 1, 3))
    np.add.at(welded, index, p)
    welded /= np.bincount(index)[:, None]
    return welded, index


def _clean_ring(ring: Sequence[int]) -> list[int]:
    out: list[int] = []
    for i in ring:
        if not out or out[-1] != i:
            out.append(int(i))
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return out


def drop_collinear(ring: list[int], v: np.ndarray, tol: float = COLLINEAR_TOL) -> list[int]:
    """Remove ring vertices lying within ``tol`` (m) of the segment joining their neighbours.

    EnergyPlus deletes such vertices itself (with a warning) and then sees slivers and
    T-junctions within its own ~1.3 cm point tolerance; doing it here keeps what is written
    and what EnergyPlus uses the same.
    """
    ring = list(ring)
    changed = True
    while changed and len(ring) > 3:
        changed = False
        for k in range(len(ring)):
            a, b, c = v[ring[k - 1]], v[ring[k]], v[ring[(k + 1) % len(ring)]]
            ac = c - a
            L2 = float(ac @ ac)
            if L2 == 0:
                continue
            t = float((b - a) @ ac) / L2
            if 0 < t < 1 and np.linalg.norm(a + t * ac - b) < tol:
                del ring[k]
                changed = True
                break
    return ring


def _drop_shared_collinear(faces: list, v: np.ndarray, tol: float) -> list:
    """Drop vertices that are within ``tol`` of collinear in EVERY ring using them.

    A vertex collinear in one face but a corner of another is kept everywhere: dropping it
    from one face only would leave a T-junction.
    """
    from dataclasses import replace as _replace

    def collinear_in(ring, k):
        a, b, c = v[ring[k - 1]], v[ring[k]], v[ring[(k + 1) % len(ring)]]
        ac = c - a
        L2 = float(ac @ ac)
        if L2 == 0:
            return False
        t = float((b - a) @ ac) / L2
        return 0 < t < 1 and float(np.linalg.norm(a + t * ac - b)) < tol

    status: dict[int, bool] = {}
    for f in faces:
        for r in f.rings:
            for k, i in enumerate(r):
                status[i] = status.get(i, True) and collinear_in(r, k)
    drop = {i for i, ok in status.items() if ok}
    if not drop:
        return faces
    out = []
    for f in faces:
        rings = []
        for ri, r in enumerate(f.rings):
            nr = tuple(i for i in r if i not in drop)
            if len(nr) < 3:
                nr = r
            rings.append(nr)
        out.append(_replace(f, rings=tuple(rings)))
    return out


def classify(semantic_type: str | None, normal: np.ndarray) -> str:
    """Exporter class of a surface: its semantic type, else its orientation."""
    k = SEMANTIC_CLASS.get(semantic_type or "")
    if k is not None:
        return k
    nz = unit(normal)[2] if np.any(normal) else 0.0
    if nz > 0.17:
        return "roof"
    if nz < -0.17:
        return "ground"
    return "wall"


def _thermal(b: Building) -> Mapping[str, Any]:
    t = b.provenance.get("thermal") if b.provenance else None
    return t if isinstance(t, Mapping) else {}


def _number(x) -> float | None:
    try:
        f = float(x)
    except (TypeError, ValueError):
        return None
    return f if math.isfinite(f) and f > 0 else None


def zone_shells(b: Building, origin: np.ndarray, lod: str | None = None,
                weld_tol: float = WELD_TOL, wwr: float | None = None,
                collinear_tol: float = 0.0) -> list[ZoneShell]:
    """One :class:`ZoneShell` per Building/BuildingPart solid at ``lod`` (default: highest).

    Vertices are shifted by ``-origin`` and welded at ``weld_tol``; consecutive duplicates
    are removed and faces collapsed to fewer than 3 vertices are dropped. A shell whose
    signed volume is negative is flipped (with a warning).

    Parameters
    ----------
    b : Building
    origin : (3,) float, m
    wwr : float, optional
        Overrides ``provenance["thermal"]["wwr"]``.
    collinear_tol : float, m
        Drop ring vertices this close to their neighbours' segment (:func:`drop_collinear`);
        0 keeps them (needed for triangle meshes, where dropping makes T-junctions).
    """
    thermal = _thermal(b)
    u_table = thermal.get("u_values") if isinstance(thermal.get("u_values"), Mapping) else {}
    out = []
    for obj, gi, g in b.energy_objects(lod):
        for si, solid in enumerate(g.solids):
            if not solid.shells:
                continue
            shell = solid.exterior
            warnings: list[str] = []
            used = sorted({int(i) for s in shell.surfaces for r in s.rings for i in r})
            if not used:
                continue
            used_arr = np.asarray(used)
            pts = b.vertices[used_arr] - origin
            welded, cluster = weld(pts, weld_tol)
            remap = dict(zip(used, cluster.tolist()))
            faces = []
            missing_u = set()
            for fi, s in enumerate(shell.surfaces):
                rings = []
                for ri, r in enumerate(s.rings):
                    cr = _clean_ring([remap[int(i)] for i in r])
                    if len(set(cr)) >= 3:
                        rings.append(tuple(cr))
                    elif ri == 0:
                        rings = []
                        break
                if not rings:
                    continue
                sem = g.semantic_surfaces[s.semantic] if (
                    s.semantic is not None and 0 <= s.semantic < len(g.semantic_surfaces)) else {}
                stype = sem.get("type") if isinstance(sem, Mapping) else None
                normal = newell_normal(welded[list(rings[0])])
                if polygon_area3d(welded[list(rings[0])]) <= MIN_PIECE_AREA:
                    continue
                kind = classify(stype, normal)
                u = _number(sem.get("uValue")) if isinstance(sem, Mapping) else None
                if u is None:
                    u = _number(u_table.get(kind if kind != "floor" else "ground"))
                if u is None:
                    u = FALLBACK_U[kind]
                    missing_u.add(kind)
                faces.append(ZoneFace(tuple(rings), kind, stype, u, fi))
            if collinear_tol > 0:
                faces = _drop_shared_collinear(faces, welded, collinear_tol)
            if missing_u:
                warnings.append(f"{obj.id}: no uValue for {', '.join(sorted(missing_u))}; "
                                f"fallback U-values used")
            zs = ZoneShell(b.id, obj.id if len(g.solids) == 1 else f"{obj.id}_s{si}", welded,
                           tuple(faces), 0.0, 0.0, ())
            tris, _ = zs.triangles()
            if len(tris) and signed_volume(welded, tris) < 0:
                faces = [ZoneFace(tuple(tuple(r[::-1]) for r in f.rings), f.kind, f.semantic_type,
                                  f.u_value, f.index) for f in faces]
                warnings.append(f"{obj.id}: shell was inward oriented; flipped")
            u_win = _number(u_table.get("window"))
            if u_win is None:
                u_win = FALLBACK_U["window"]
            w = wwr if wwr is not None else _number(thermal.get("wwr"))
            w = float(min(max(w or 0.0, 0.0), 0.9))
            out.append(ZoneShell(b.id, zs.object_id, welded, tuple(faces), u_win, w, tuple(warnings)))
    return out


# --------------------------------------------------------------------------- mesh checks

def signed_volume(vertices: np.ndarray, tris: np.ndarray) -> float:
    # kept apart from lod2energy.geometry.signed_volume (issue 14): that one is taken about the
    # first vertex, this one about the vertices' mean; they differ in the last bits, and the
    # zone shells' orientation flips and the STL self-check's volume test use this one
    """Signed volume (m3) of a triangle mesh; positive when outward oriented."""
    if len(tris) == 0:
        return 0.0
    v = np.asarray(vertices, dtype=np.float64)
    c = v[np.asarray(tris).ravel()].mean(axis=0)
    a, b, cc = v[tris[:, 0]] - c, v[tris[:, 1]] - c, v[tris[:, 2]] - c
    return float(np.einsum("ij,ij->i", a, np.cross(b, cc)).sum() / 6.0)


def _split_t_junctions(v: np.ndarray, polys: list[list[int]], tol: float,
                       only_unmatched: bool = False) -> list[list[int]]:
    """Insert into polygon edges the vertices lying on them (T-junctions), in order.

    With ``only_unmatched`` only edges without a reversed twin are split (as EnergyPlus
    does when a zone is not enclosed), so that shared edges and diagonals stay untouched.
    """
    from scipy.spatial import cKDTree

    tree = cKDTree(v)
    directed = {(poly[k], poly[(k + 1) % len(poly)]) for poly in polys for k in range(len(poly))}
    out = []
    for poly in polys:
        new = []
        for k in range(len(poly)):
            a, b = poly[k], poly[(k + 1) % len(poly)]
            new.append(a)
            if only_unmatched and (b, a) in directed:
                continue
            pa, pb = v[a], v[b]
            d = pb - pa
            L = float(np.linalg.norm(d))
            if L <= tol:
                continue
            cand = tree.query_ball_point((pa + pb) / 2, L / 2 + tol)
            on = []
            for c in cand:
                if c in (a, b):
                    continue
                t = float(np.dot(v[c] - pa, d) / (L * L))
                if tol / L < t < 1 - tol / L and np.linalg.norm(pa + t * d - v[c]) <= tol:
                    on.append((t, c))
            new.extend(c for _, c in sorted(on))
        out.append(new)
    return out


def check_closed_outward(polygons: Sequence[np.ndarray], tol: float = 1e-3,
                         t_tol: float = 0.0127) -> list[str]:
    """Is a set of 3D polygons (one zone's written surfaces) a closed, outward shell?

    Vertices are welded at ``tol``, T-junctions within ``t_tol`` (EnergyPlus's point
    tolerance, 1.27 cm) are split, then every undirected edge must
    be used exactly twice, once in each direction (closed, 2-manifold, consistent winding),
    and the enclosed signed volume must be positive (outward).

    Parameters
    ----------
    polygons : sequence of (k, 3) float
        Polygons as written, counter-clockwise seen from outside.

    Returns
    -------
    list of str
        Problems found (empty when the shell is fine).
    """
    if not polygons:
        return ["no surfaces"]
    allp = np.concatenate([np.asarray(p, dtype=np.float64) for p in polygons])
    v, idx = weld(allp, tol)
    polys, k = [], 0
    for p in polygons:
        ring = _clean_ring(idx[k:k + len(p)].tolist())
        k += len(p)
        if len(set(ring)) >= 3:
            polys.append(ring)
    polys = _split_t_junctions(v, polys, t_tol, only_unmatched=True)
    directed: dict[tuple[int, int], int] = {}
    for poly in polys:
        for i in range(len(poly)):
            e = (poly[i], poly[(i + 1) % len(poly)])
            directed[e] = directed.get(e, 0) + 1
    problems = []
    boundary = sum(1 for (a, b), n in directed.items() if (b, a) not in directed)
    dup = sum(1 for n in directed.values() if n > 1)
    if boundary:
        problems.append(f"not closed: {boundary} edge(s) used by one surface only")
    if dup:
        problems.append(f"inconsistent winding or non-manifold: {dup} edge(s) used twice in one direction")
    tris = []
    for poly in polys:
        pts = v[poly]
        t = triangulate(pts, [len(poly)])
        tris.extend([[poly[i] for i in tt] for tt in t])
    vol = signed_volume(v, np.asarray(tris, dtype=np.intp).reshape(-1, 3))
    if vol <= 0:
        problems.append(f"not outward: signed volume {vol:.3f} m3")
    return problems
