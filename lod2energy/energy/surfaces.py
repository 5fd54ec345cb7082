"""Zone surfaces: party walls (faces shared with another zone or building) and a zone's written pieces.

Faces shared with another zone or building (coplanar, opposite, overlapping) are split into
an ``Adiabatic`` party-wall piece and the ``Outdoors`` rest, or classified whole.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np
import shapely
from scipy.spatial import cKDTree
from shapely.geometry import GeometryCollection, MultiPolygon, Polygon

from lod2energy.energy.conform import clean_piece, conform, eplus_enclose, keep_corners
from lod2energy.energy.pieces import Piece, _as_written, _face_frame, _outer_boundary, _pieces_from_points, _planar
from lod2energy.energy.zones.shells import MIN_PIECE_AREA, WELD_TOL, ZoneFace, ZoneShell
from lod2energy.geometry.polygons import wall_basis, polygon_area3d


#: Party-wall / outdoor parts of a split face thinner than 2 x THIN (m) join the other part:
#: EnergyPlus merges vertices closer than about 1.3 cm and would lose such slivers.
THIN = 0.015


def _shapely_poly(pts: np.ndarray, ends: Sequence[int], c: np.ndarray, u: np.ndarray, v: np.ndarray):

    xy = np.column_stack([(pts - c) @ u, (pts - c) @ v])
    rings = np.split(xy, ends[:-1])
    poly = Polygon(rings[0], rings[1:])
    if not poly.is_valid:
        poly = shapely.make_valid(poly)
    return poly


def find_party_faces(zones: Sequence[ZoneShell], plane_tol: float = 0.05, min_area: float = 0.01,
                     angle_cos: float = 0.985, first: int | None = None
                     ) -> dict[tuple[int, int], list[tuple[int, object]]]:
    """Faces shared between different zones: coplanar, opposite normals, overlapping.

    Parameters
    ----------
    zones : sequence of ZoneShell
        In one common frame.
    plane_tol : float, m
        Largest distance between the two planes.
    min_area : float, m2
        Smallest overlap that counts.
    first : int, optional
        Only pairs with a zone of index below ``first`` (the zones of the buildings being
        written, which come first): their entries are the same as without it; pairs of two
        later zones (neighbours touching each other) are not looked at. Default: every pair.

    Returns
    -------
    dict
        ``{(zone_index, face_index): [(other_zone_index, overlap polygon in the face's
        (u, v) plane frame), ...]}``.
    """
    boxes = np.array([[*z.vertices.min(axis=0), *z.vertices.max(axis=0)] if len(z.vertices)
                      else [np.inf] * 3 + [-np.inf] * 3 for z in zones])
    frames: dict[int, list] = {}

    def zone_frames(zi):
        if zi not in frames:
            fr = []
            for f in zones[zi].faces:
                pts, ends, n, c = _face_frame(zones[zi], f)
                fr.append((pts, ends, n, c, float(n @ c), pts.min(axis=0), pts.max(axis=0)))
            # the faces' normals and boxes stacked, for the pair filter below
            stacked = (np.array([x[2] for x in fr]).reshape(-1, 3), np.array([x[5] for x in fr]).reshape(-1, 3),
                       np.array([x[6] for x in fr]).reshape(-1, 3))
            frames[zi] = (fr, stacked)
        return frames[zi]

    out: dict[tuple[int, int], list] = {}
    lo, hi = boxes[:, :3], boxes[:, 3:]
    for a in range(len(zones) if first is None else min(first, len(zones))):
        cand = np.nonzero(np.all(lo[a] <= hi + plane_tol, axis=1) & np.all(hi[a] >= lo - plane_tol, axis=1))[0]
        for b in cand[cand > a]:
            if zones[a].building_id == zones[b].building_id and zones[a].object_id == zones[b].object_id:
                continue
            (fa_list, (NA, LA, HA)), (fb_list, (NB, LB, HB)) = zone_frames(a), zone_frames(int(b))
            # the face pairs that can pass the tests below, all at once: the normals' dot
            # products with a margin for their summation order (the test itself follows),
            # the boxes with the same comparisons as below
            near = ~(NA @ NB.T > -angle_cos + 1e-9) \
                & ~np.any(LA[:, None, :] > HB[None, :, :] + plane_tol, axis=2) \
                & ~np.any(HA[:, None, :] < LB[None, :, :] - plane_tol, axis=2)
            for ia, ib in zip(*np.nonzero(near)):  # row-major: the order of the loops over ia, ib
                pa, ea, na, ca, da, mina, maxa = fa_list[ia]
                pb, eb, nb, cb, db, minb, maxb = fb_list[ib]
                ia, ib = int(ia), int(ib)
                if float(na @ nb) > -angle_cos:
                    continue
                if np.any(mina > maxb + plane_tol) or np.any(maxa < minb - plane_tol):
                    continue
                if abs(da + db) > plane_tol or np.max(np.abs((pb - ca) @ na)) > plane_tol:
                    continue
                u, v = wall_basis(na)
                sa = _shapely_poly(pa, ea, ca, u, v)
                sb = _shapely_poly(pb, eb, ca, u, v)
                inter = shapely.intersection(sa, sb)
                if inter.area < min_area:
                    continue
                out.setdefault((a, ia), []).append((int(b), inter))
                ub, vb = wall_basis(nb)
                sa2 = _shapely_poly(pa, ea, cb, ub, vb)
                sb2 = _shapely_poly(pb, eb, cb, ub, vb)
                out.setdefault((int(b), ib), []).append((a, shapely.intersection(sb2, sa2)))
    return out


def _polygons_of(geom) -> list:

    if isinstance(geom, Polygon):
        return [geom] if not geom.is_empty else []
    if isinstance(geom, (MultiPolygon, GeometryCollection)):
        out = []
        for g in geom.geoms:
            out.extend(_polygons_of(g))
        return out
    return []


def _split_face(zone: ZoneShell, face: ZoneFace, overlaps: list, min_area: float = 0.01) -> list[tuple[np.ndarray, str]]:
    """(points, boundary) pieces of a face partly shared with other zones."""
    pts, ends, n, c = _face_frame(zone, face)
    outer = _outer_boundary(face.kind)
    u, v = wall_basis(n)
    whole = _shapely_poly(pts, ends, c, u, v)
    shared = _opening(shapely.intersection(whole, shapely.union_all([g for _, g in overlaps])))
    rest = _opening(shapely.difference(whole, shared))
    shared = shapely.difference(whole, rest)
    if rest.area < min_area:
        return [(p, "Adiabatic") for p in _pieces_from_points(pts, ends, n, c)]
    if shared.area < min_area or not _planar(pts, n, c):
        return [(p, outer) for p in _pieces_from_points(pts, ends, n, c)]
    out = []
    tree = cKDTree(zone.vertices)
    edges = [(pts[k], pts[(k + 1 - s0) % (e - s0) + s0]) for s0, e in zip((0,) + tuple(ends[:-1]), ends)
             for k in range(s0, e)]
    for geom, boundary in ((shared, "Adiabatic"), (rest, outer)):
        geom = shapely.set_precision(geom, 1e-6)
        for poly in _polygons_of(geom):
            if poly.area <= MIN_PIECE_AREA:
                continue
            rings = [np.asarray(poly.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in poly.interiors]
            xy = np.concatenate(rings)
            p3 = c + xy[:, :1] * u + xy[:, 1:2] * v
            p3 = _snap(p3, zone.vertices, tree, edges)
            e = np.cumsum([len(r) for r in rings]).tolist()
            for piece in _pieces_from_points(p3, e, n, c):
                out.append((piece, boundary))
    return out


def _opening(geom, width: float = 2 * THIN):
    """Remove the parts of a polygon narrower than ``width`` (m), keeping square corners."""
    if geom.is_empty:
        return geom
    opened = shapely.buffer(shapely.buffer(geom, -width / 2, join_style="mitre"), width / 2, join_style="mitre")
    return shapely.intersection(geom, opened)


def _snap(p3: np.ndarray, vertices: np.ndarray, tree, edges, tol: float = 2 * WELD_TOL) -> np.ndarray:
    """Move points onto a zone vertex, else onto a face edge, when within ``tol`` (m)."""
    p3 = p3.copy()
    d, i = tree.query(p3)
    for k in range(len(p3)):
        if d[k] <= tol:
            p3[k] = vertices[i[k]]
            continue
        best, bd = None, tol
        for a, b in edges:
            ab = b - a
            L2 = float(ab @ ab)
            if L2 == 0:
                continue
            t = min(max(float((p3[k] - a) @ ab) / L2, 0.0), 1.0)
            q = a + t * ab
            dist = float(np.linalg.norm(q - p3[k]))
            if dist <= bd:
                best, bd = q, dist
        if best is not None:
            p3[k] = best
    return p3


def zone_pieces(zone: ZoneShell, zi: int, party: dict, split: bool = True) -> list[Piece]:
    """Every written piece of a zone.

    Faces shared with another zone are split into Adiabatic + outer parts (``split``), or
    classified whole (Adiabatic when at least half is shared).
    """
    pieces = []
    for fi, f in enumerate(zone.faces):
        ov = party.get((zi, fi))
        if ov and not split:
            parts = _whole_face(zone, f, ov)
        elif ov:
            parts = _split_face(zone, f, ov)
            if len({b for _, b in parts}) > 1 and not all(clean_piece(p) for p, _ in parts):
                # a split that leaves slivers EnergyPlus would mangle: classify the whole face
                parts = _whole_face(zone, f, ov)
        else:
            pts, ends, n, c = _face_frame(zone, f)
            parts = [(p, _outer_boundary(f.kind)) for p in _pieces_from_points(pts, ends, n, c)]
        for p, boundary in parts:
            if polygon_area3d(p) > MIN_PIECE_AREA:
                pieces.append(Piece(p, f.kind, boundary, f.u_value, f.index))
    if split and any(party.get((zi, fi)) for fi in range(len(zone.faces))):
        pieces = conform(pieces)
    # after the enclosure candidates too: merging vertices can bend a piece out of plane;
    # keep_corners of its own output is that output (a piece it keeps passes its test again, a
    # fan triangle it wrote is a non-degenerate triangle, which it keeps), so pieces that
    # passed the enclosure test as they were are not tested a second time
    kept = keep_corners(_as_written(pieces))
    enclosed = eplus_enclose(kept)
    return _as_written(kept if enclosed is kept else keep_corners(enclosed))


def _whole_face(zone: ZoneShell, face: ZoneFace, overlaps: list) -> list[tuple[np.ndarray, str]]:
    """Unsplit pieces of a face, Adiabatic when at least half of it is shared."""
    pts, ends, n, c = _face_frame(zone, face)
    u, v = wall_basis(n)
    whole = _shapely_poly(pts, ends, c, u, v)
    shared = shapely.intersection(whole, shapely.union_all([g for _, g in overlaps])).area
    boundary = "Adiabatic" if shared >= 0.5 * whole.area else _outer_boundary(face.kind)
    return [(p, boundary) for p in _pieces_from_points(pts, ends, n, c)]
