"""Zone shells: the closed envelope of each Building / BuildingPart in the writers' local frame.

Every writer reads "energy-ready" buildings (closed, outward Solids with one semantic entry per
surface) and needs the same thing from them: coordinates shifted to a local origin, so that map
coordinates (1e5-1e6 m) keep millimetre precision, and one welded vertex set per zone with each
face's class ("roof", "wall", "ground", "floor") and U-value.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from itertools import accumulate
from collections.abc import Mapping
from typing import Any, Iterable

import numpy as np

from lod2energy.model import Building
from lod2energy.semantics import DEFAULT_RULES

from lod2energy.geometry.polygons import newell_normal, polygon_area3d, triangulate, unit
from lod2energy.geometry import signed_volume
from lod2energy.geometry.vectors import vector_length
from lod2energy.geometry.snap import drop_repeats, weld
from lod2energy.energy.uvalues import face_u_value, positive_number, window_u_value

#: Weld distance for zone vertices (m): EnergyPlus warns about vertices closer than 1 cm.
WELD_TOL = 0.01
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
        return self.vertices[_face_index(face)], tuple(accumulate(map(len, face.rings)))

    def face_triangles(self, face: ZoneFace) -> np.ndarray:
        """Triangles ``(t, 3)`` of one face (indices into ``vertices``)."""
        idx = _face_index(face)
        t = triangulate(self.vertices[idx], tuple(accumulate(map(len, face.rings))))
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


def _face_index(face: ZoneFace) -> np.ndarray:
    """The vertex indices of a face's rings, concatenated, (k,) int."""
    if len(face.rings) == 1:
        return np.array(face.rings[0], dtype=np.intp)
    return np.concatenate([np.asarray(r, dtype=np.intp) for r in face.rings])


def _drop_shared_collinear(faces: list, v: np.ndarray, tol: float) -> list:
    """Drop vertices within ``tol`` (m) of the segment joining their neighbours in every ring
    that uses them.

    EnergyPlus deletes such vertices itself (with a warning) and then sees slivers and
    T-junctions within its own ~1.3 cm point tolerance; doing it here keeps what is written
    and what EnergyPlus uses the same. A vertex collinear in one face but a corner of another
    is kept everywhere: dropping it from one face only would leave a T-junction.
    """
    def collinear_in(ring, k):
        a, b, c = v[ring[k - 1]], v[ring[k]], v[ring[(k + 1) % len(ring)]]
        ac = c - a
        L2 = float(ac @ ac)
        if L2 == 0:
            return False
        t = float((b - a) @ ac) / L2
        return 0 < t < 1 and vector_length(a + t * ac - b) < tol

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
        out.append(replace(f, rings=tuple(rings)))
    return out


def classify(semantic_type: str | None, normal: np.ndarray) -> str:
    """Exporter class of a surface: its semantic type, else which way it faces.

    Without a class from its type, a surface facing up by more than the labelling rules'
    facing threshold (:attr:`lod2energy.semantics.LabelRules.check_facing_nz`, the one that
    says a roof faces down or a ground faces up) is a roof, facing down by more a ground,
    else a wall. A surface facing down by more than that threshold is never a roof, whatever
    its type: a roof facing down (an overhang's underside labelled RoofSurface) is an outdoor
    floor, which EnergyPlus takes as it is (a Roof facing down is "upside down" to it).
    """
    facing = DEFAULT_RULES.check_facing_nz
    nz = unit(normal)[2] if np.any(normal) else 0.0
    k = SEMANTIC_CLASS.get(semantic_type or "")
    if k == "roof" and nz < -facing:
        return "floor"
    if k is not None:
        return k
    if nz > facing:
        return "roof"
    if nz < -facing:
        return "ground"
    return "wall"


def _thermal(b: Building) -> Mapping[str, Any]:
    t = b.provenance.get("thermal") if b.provenance else None
    return t if isinstance(t, Mapping) else {}


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
        Drop ring vertices this close to their neighbours' segment (:func:`_drop_shared_collinear`);
        0 keeps them (needed for triangle meshes, where dropping makes T-junctions).
    """
    thermal = _thermal(b)
    u_table = thermal.get("u_values") if isinstance(thermal.get("u_values"), Mapping) else {}
    out = []
    for obj, gi, g in b.envelope(lod):
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
            faces, face_sem = [], []
            missing_u = set()
            for fi, s in enumerate(shell.surfaces):
                rings = []
                for ri, r in enumerate(s.rings):
                    cr = drop_repeats([remap[int(i)] for i in r])
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
                outer = welded[list(rings[0])]
                normal = newell_normal(outer)
                if polygon_area3d(outer, normal) <= MIN_PIECE_AREA:
                    continue
                faces.append(ZoneFace(tuple(rings), classify(stype, normal), stype, 0.0, fi))
                face_sem.append((sem, normal))
            zs = ZoneShell(b.id, obj.id, welded, tuple(faces), 0.0, 0.0, ())
            tris, _ = zs.triangles()
            flip = bool(len(tris) and signed_volume(welded, tris) < 0)
            if flip:  # classified by their outward normals
                faces = [ZoneFace(tuple(tuple(r[::-1]) for r in f.rings), classify(f.semantic_type, -n),
                                  f.semantic_type, 0.0, f.index) for f, (_, n) in zip(faces, face_sem)]
            for k, (f, (sem, _)) in enumerate(zip(faces, face_sem)):
                u, fallback = face_u_value(sem, f.kind, u_table)
                if fallback:
                    missing_u.add(f.kind)
                faces[k] = replace(f, u_value=u)
            if collinear_tol > 0:
                faces = _drop_shared_collinear(faces, welded, collinear_tol)
            if missing_u:
                warnings.append(f"{obj.id}: no uValue for {', '.join(sorted(missing_u))}; "
                                f"fallback U-values used")
            if flip:
                warnings.append(f"{obj.id}: shell was inward oriented; flipped")
            zs = ZoneShell(b.id, obj.id if len(g.solids) == 1 else f"{obj.id}_s{si}", welded,
                           tuple(faces), 0.0, 0.0, ())
            u_win = window_u_value(u_table)
            w = wwr if wwr is not None else positive_number(thermal.get("wwr"))
            w = float(min(max(w or 0.0, 0.0), 0.9))
            out.append(ZoneShell(b.id, zs.object_id, welded, tuple(faces), u_win, w, tuple(warnings)))
    return out

