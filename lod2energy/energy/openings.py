"""Windows and doors: insets of the outdoor wall pieces by the window-to-wall ratio, or the real
openings of LoD3 input (``FenestrationSurface:Detailed``)."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import shapely
from shapely.geometry import Point, Polygon

from lod2energy.energy.zones.shells import ZoneShell
from lod2energy.geometry.polygons import is_convex_2d, newell_normal, wall_basis, polygon_area3d, unit
from lod2energy.io.openings import polygon_rings


def window_for(piece: np.ndarray, wwr: float) -> np.ndarray | None:
    """Window polygon ``(3|4, 3)`` inside a planar convex wall piece with area ``wwr`` x area.

    Triangles get a copy scaled about their centroid; other pieces an upright rectangle
    centred on the area centroid (shrunk when the ratio cannot be reached: EnergyPlus turns
    non-rectangular quadrilateral windows into rectangles anyway).
    """
    if wwr <= 0:
        return None
    if len(piece) == 3:
        c = piece.mean(axis=0)
        return c + math.sqrt(wwr) * (piece - c)
    nn = newell_normal(piece)
    area = 0.5 * float(np.linalg.norm(nn))  # polygon_area3d(piece), from the one normal
    n = unit(nn)
    u, v = wall_basis(n)
    c0 = piece.mean(axis=0)
    xy = np.column_stack([(piece - c0) @ u, (piece - c0) @ v])
    poly = Polygon(xy)
    cen = np.asarray(poly.centroid.coords[0])
    w = xy[:, 0].max() - xy[:, 0].min()
    h = xy[:, 1].max() - xy[:, 1].min()

    def fits(t):  # the box of scale t about the centroid inside the piece
        # shapely.box: the ring of shapely.geometry.box, same coordinates, a fifth of its cost
        return poly.contains(shapely.box(cen[0] - t * w / 2, cen[1] - t * h / 2,
                                         cen[0] + t * w / 2, cen[1] + t * h / 2))

    s = math.sqrt(wwr * area / (w * h))
    # The scale is min(s, 0.95 lo) with lo the bisection's largest fitting scale (24 steps of
    # a dyadic bisection on [0, 1]). The boxes are nested (their corners move out with t), so
    # a box that fits has a scale below every scale that does not: when the box of
    # ``probe`` fits, the bisection ends with lo > probe - 2**-24 > s / 0.95, and the scale
    # is s whatever lo is. One containment test instead of 24.
    probe = s / 0.95 + 2.0 ** -22
    if probe < 1.0 - 2.0 ** -22 and fits(probe):
        t = s
    else:
        lo_t, hi_t = 0.0, 1.0
        for _ in range(24):
            t = (lo_t + hi_t) / 2
            if fits(t):
                lo_t = t
            else:
                hi_t = t
        t = min(s, 0.95 * lo_t)
    if t <= 0:
        return None
    hw, hh = t * w / 2, t * h / 2
    rect = np.array([[cen[0] - hw, cen[1] + hh], [cen[0] - hw, cen[1] - hh],
                     [cen[0] + hw, cen[1] - hh], [cen[0] + hw, cen[1] + hh]])
    return c0 + rect[:, :1] * u + rect[:, 1:2] * v


#: Semantic types of LoD3 openings and the EnergyPlus fenestration type each becomes.
OPENING_SURFACE_TYPE = {"Window": "Window", "Door": "Door"}


#: An opening is matched to a wall hole when its centroid is at most this far from the wall
#: plane (m): recessed windows sit behind the facade by their reveal depth.
OPENING_RECESS = 0.6


@dataclass(frozen=True)
class Opening:
    """A real window or door of a zone, in the plane of its parent wall.

    Parameters
    ----------
    points : (k, 3) float, m
        The wall hole it fills, counter-clockwise seen from outside, zone-local frame.
    kind : str
        "Window" or "Door" (the EnergyPlus fenestration type).
    wall_index : int
        ``ZoneFace.index`` (input face) of the parent wall; its pieces carry the same index.
    """
    points: np.ndarray
    kind: str
    wall_index: int


def _edges(rings) -> list[tuple[int, int]]:
    return [tuple(sorted((int(r[k]), int(r[(k + 1) % len(r)])))) for r in rings for k in range(len(r))]


def split_openings(zone: ZoneShell, recess: float = OPENING_RECESS) -> tuple[ZoneShell, tuple[Opening, ...], int]:
    """Close a zone's walls through their openings and take the openings out as fenestration.

    A wall hole (inner ring) is filled by the opening (Window / Door face) whose centroid lies
    within ``recess`` of the wall plane and inside the hole; the opening face and its reveal
    faces (faces whose vertices are all on the hole or on the opening) leave the zone, the hole
    leaves the wall, and the hole polygon becomes the :class:`Opening`. A candidate is taken
    only if the faces it removes are bounded exactly by the hole's edges, so the zone stays as
    closed as it was.

    Returns
    -------
    zone : ZoneShell
        Without the matched openings and reveals (the input when nothing matched).
    openings : tuple of Opening
    unmatched : int
        Opening faces left in the zone as opaque wall (no hole of a wall to fill).
    """
    v = zone.vertices
    faces = list(zone.faces)
    cand = [i for i, f in enumerate(faces) if f.semantic_type in OPENING_SURFACE_TYPE]
    if not cand:
        return zone, (), 0
    cents = {i: v[list(faces[i].rings[0])].mean(axis=0) for i in cand}
    drop: set[int] = set()
    new_rings: dict[int, list] = {}
    out: list[Opening] = []
    for wi, w in enumerate(faces):
        if w.kind != "wall" or w.semantic_type in OPENING_SURFACE_TYPE or len(w.rings) < 2:
            continue
        outer = v[list(w.rings[0])]
        n = unit(newell_normal(outer))
        c = outer.mean(axis=0)
        a, b = wall_basis(n)
        keep = [w.rings[0]]
        for hole in w.rings[1:]:
            hp = v[list(hole)]
            h2 = Polygon(np.column_stack([(hp - c) @ a, (hp - c) @ b]))
            best = None
            for oi in cand:
                if oi in drop:
                    continue
                d = cents[oi] - c
                if abs(float(d @ n)) <= recess and h2.buffer(0.01).contains(Point(float(d @ a), float(d @ b))):
                    best = oi
                    break
            if best is None:
                keep.append(hole)
                continue
            near = set(int(i) for i in hole) | set(int(i) for i in faces[best].rings[0])
            group = {best} | {j for j, f in enumerate(faces) if j not in (wi, best) and j not in drop
                              and f.semantic_type not in OPENING_SURFACE_TYPE
                              and all(int(i) in near for r in f.rings for i in r)}
            count: dict[tuple[int, int], int] = {}
            for j in group:
                for e in _edges(faces[j].rings):
                    count[e] = count.get(e, 0) + 1
            rim = {e for e, k in count.items() if k == 1}
            if rim != set(_edges([hole])) or any(k > 2 for k in count.values()):
                keep.append(hole)
                continue
            drop |= group
            pts = hp[::-1] if float(newell_normal(hp) @ n) < 0 else hp
            out.append(Opening(pts.copy(), OPENING_SURFACE_TYPE[faces[best].semantic_type], w.index))
        if len(keep) != len(w.rings):
            new_rings[wi] = keep
    for oi in cand:  # an opening in a notch of its wall's outline (a door down to the ground)
        if oi in drop:
            continue
        hit = _merge_notch(zone, faces, new_rings, oi, drop)
        if hit is not None:
            wi, rings, pts = hit
            new_rings[wi] = rings
            drop.add(oi)
            out.append(Opening(pts, OPENING_SURFACE_TYPE[faces[oi].semantic_type], faces[wi].index))
    if not out:
        return zone, (), len(cand)
    kept = [replace(f, rings=tuple(new_rings[i])) if i in new_rings else f
            for i, f in enumerate(faces) if i not in drop]
    return replace(zone, faces=tuple(kept)), tuple(out), sum(1 for i in cand if i not in drop)


def _merge_notch(zone: ZoneShell, faces, new_rings, oi: int, drop: set):
    """The wall whose outline an opening face completes: ``(wall, rings, opening points)``.

    The opening lies in the wall's plane and shares at least one edge with its outer ring;
    the wall's new rings are the union of the two, made of their vertices, whose edges are
    exactly the edges of either that the other does not use (so the zone stays as closed as
    it was). None when there is no such wall.
    """


    v = zone.vertices
    op = faces[oi]
    ring = list(op.rings[0])
    p = v[ring]
    n_o = newell_normal(p)
    if len(op.rings) != 1 or np.linalg.norm(n_o) < 1e-12:
        return None
    n_o = n_o / np.linalg.norm(n_o)
    mine = set(_edges([ring]))
    for wi, w in enumerate(faces):
        if wi == oi or wi in drop or w.kind != "wall" or w.semantic_type in OPENING_SURFACE_TYPE:
            continue
        rings = new_rings.get(wi, list(w.rings))
        theirs = set(_edges(rings[:1]))
        if not mine & theirs:
            continue
        outer = v[list(rings[0])]
        n = unit(newell_normal(outer))
        c = outer.mean(axis=0)
        if float(n @ n_o) < 0.999 or np.abs((p - c) @ n).max() > 0.01:
            continue
        a, b = wall_basis(n)
        to2 = lambda q: np.column_stack([(q - c) @ a, (q - c) @ b])  # noqa: E731
        try:
            union = Polygon(to2(outer), [to2(v[list(r)]) for r in rings[1:]]).union(Polygon(to2(p)))
        except Exception:  # noqa: BLE001 - shapely topology errors on degenerate input
            continue
        if union.geom_type != "Polygon":
            continue
        ids = np.unique(np.concatenate([np.asarray(r, dtype=np.intp) for r in rings] + [np.asarray(ring)]))
        merged = polygon_rings(union, ids, to2(v[ids]))
        if merged is None:
            continue
        whole = set(_edges(rings)) | mine
        if set(_edges(merged)) != whole - (set(_edges(rings)) & mine):
            continue
        return wi, [tuple(r) for r in merged], p.copy()
    return None


def opening_polygon(op: Opening, piece: np.ndarray) -> np.ndarray | None:
    """The fenestration polygon ``(3|4, 3)`` of an opening on its wall piece, or None.

    The hole is clipped to the piece; one of 3 or 4 corners is written as it is (EnergyPlus
    takes 3 or 4 vertices), any other shape (a round window) as the upright rectangle of the
    same area centred on its centroid, inside its bounding box in the wall plane.
    """
    n = unit(newell_normal(piece))
    up = np.array([0.0, 0.0, 1.0])
    a = np.cross(up, n)
    if np.linalg.norm(a) < 1e-6:
        a, _ = wall_basis(n)
    a = unit(a)
    b = np.cross(n, a)
    c = piece.mean(axis=0)
    to2 = lambda p: np.column_stack([(p - c) @ a, (p - c) @ b])  # noqa: E731
    try:
        clip = Polygon(to2(op.points)).buffer(0).intersection(Polygon(to2(piece)))
    except Exception:  # noqa: BLE001 - shapely topology errors on degenerate input
        return None
    if clip.geom_type != "Polygon" or clip.area < 0.01 or clip.area > 0.98 * polygon_area3d(piece):
        return None
    xy = np.asarray(clip.exterior.coords)[:-1]
    if len(xy) > 4 or not is_convex_2d(xy):
        (x0, y0, x1, y1), (cx, cy) = clip.bounds, clip.centroid.coords[0]
        t = math.sqrt(clip.area / max((x1 - x0) * (y1 - y0), 1e-12))
        hw, hh = t * (x1 - x0) / 2, t * (y1 - y0) / 2
        xy = np.array([[cx - hw, cy + hh], [cx - hw, cy - hh], [cx + hw, cy - hh], [cx + hw, cy + hh]])
    p3 = c + xy[:, :1] * a + xy[:, 1:2] * b
    return p3 if float(newell_normal(p3) @ n) > 0 else p3[::-1]
