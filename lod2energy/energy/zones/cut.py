"""Thermal zones per storey: a closed zone envelope cut by horizontal planes into closed storey zones.

The input is the envelope of one Building / BuildingPart as EnergyPlus will see it: planar
convex polygons, counter-clockwise seen from outside, closed (every edge used once in each
direction), each with a tag the caller keeps (surface kind, boundary, U-value). Each polygon
is clipped to every slab ``cut[k] <= z <= cut[k + 1]`` (a convex polygon clipped by two
half-spaces stays convex, so nothing is re-triangulated and party walls stay party walls,
storey by storey); the edges the clipped polygons leave on a cut plane are chained into the
loops of the section, which close the slab below as its ceiling and the slab above as its
floor (the same convex pieces, reversed): an interzone pair. Volumes add up exactly (the
slabs partition the shell).

Cut heights (:func:`storey_cuts`): the storeys under the eave split ``eave - ground`` evenly;
a pitched roof space of at least ``attic_min`` metres is its own zone (cut at the eave); the
storeys above the eave of a zone that rises more than a storey above it (a tower on a podium)
split ``ridge - eave`` evenly.
A cut that would pass within :data:`CLEARANCE` of a vertex is moved to the nearest vertex
height within :data:`SNAP` (so that eaves and floor lines become cut lines instead of
slivers), else shifted by up to 0.4 m (:data:`SHIFTS`), and dropped when
every such height passes within :data:`CLEARANCE` of a vertex or through a horizontal
surface.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np
from shapely.geometry import Point, Polygon

from lod2energy.geometry.vectors import cross_rows, roll_next
from lod2energy.thermal.storeys import eave_and_pitch

#: A cut is moved to a vertex height this close (m).
SNAP = 0.4
#: No vertex may lie this close (m) to a cut (other than on it): it would make a sliver.
CLEARANCE = 0.05
#: Points within this distance (m) of a plane lie on it.
ON_PLANE = 1e-6
#: Section edges shorter than this (m) make the cut fail (EnergyPlus merges points 1.27 cm apart).
MIN_EDGE = 0.015
#: Shifts (m) tried for the storey cuts when a section fails (:func:`cut_variants`).
SHIFTS = (0.0, 0.2, -0.2, 0.4, -0.4)
DECIMALS = 4


@dataclass(frozen=True)
class Slab:
    """One storey zone.

    Attributes
    ----------
    polygons : list of ((k, 3) float, tag)
        The clipped envelope polygons of the storey (outward, convex).
    floor : list of (k, 3) float
        Interzone floor pieces (outward = down), empty for the lowest slab.
    ceiling : list of (k, 3) float
        Interzone ceiling pieces (outward = up), empty for the top slab; ``ceiling[i]`` of
        slab ``k`` is ``floor[i]`` of slab ``k + 1`` reversed.
    z_range : (float, float), m
    attic : bool
        The roof space above the eave.
    """
    polygons: list
    floor: list
    ceiling: list
    z_range: tuple[float, float]
    attic: bool = False


def _heights(z_values: np.ndarray) -> np.ndarray:
    """The zone's vertex heights (m), rounded to :data:`DECIMALS`, unique and sorted."""
    return np.unique(np.round(np.asarray(z_values, dtype=np.float64), DECIMALS))


def _clears(c: float, z: np.ndarray, horizontal_z: Sequence[float]) -> bool:
    """A cut at ``c`` (m) lies inside the zone and clears every vertex height ``z`` (but the
    ones on it) and every horizontal surface by :data:`CLEARANCE`."""
    d = np.abs(z - c)
    return (float(z[0]) + CLEARANCE < c < float(z[-1]) - CLEARANCE and not np.any((d > ON_PLANE) & (d < CLEARANCE))
            and not any(abs(h - c) < CLEARANCE for h in horizontal_z))


def storey_cuts(z_values: np.ndarray, ground: float, eave: float, ridge: float, n_below: int,
                attic: bool, horizontal_z: Sequence[float] = (),
                avoid: Sequence[tuple[float, float]] = (), above: int | None = None) -> tuple[list[float], bool]:
    """Cut heights (m) for ``n_below`` storeys under the eave and ``above`` storeys above it.

    Parameters
    ----------
    z_values : (n,) float
        Heights of every vertex of the zone.
    horizontal_z : sequence of float
        Heights of its horizontal surfaces (no cut through them).
    avoid : sequence of (lo, hi) float, m
        Height spans no cut may pass through (the zone's real windows and doors: a storey
        floor runs above or below an opening, as in the building), with :data:`CLEARANCE`.
    above : int, optional
        Storeys between the eave and the ridge, the attic included (the top one when
        ``attic``), each ``(ridge - eave) / above`` high
        (:func:`lod2energy.thermal.storeys.storeys_above_eave`); by default 1 with an attic, else 0.

    Returns
    -------
    cuts : list of float
        Increasing, strictly inside ``(min z, max z)``.
    attic : bool
        Whether the attic cut was kept.
    """
    z = _heights(z_values)
    targets = [ground + k * (eave - ground) / max(n_below, 1) for k in range(1, max(n_below, 1))]
    above = (1 if attic else 0) if above is None else above
    if above:
        targets += [eave + k * (ridge - eave) / above for k in range(above)]
    out, kept_attic = [], False
    for i, t in enumerate(targets):
        is_attic = attic and i == len(targets) - 1
        near = z[np.abs(z - t) <= SNAP]
        clear = [b for lo, hi in avoid for b in (lo - 2 * CLEARANCE, hi + 2 * CLEARANCE)]
        cands = sorted([float(t)] + [float(v) for v in near] + [t + d for d in SHIFTS[1:]] + clear,
                       key=lambda c: (abs(c - t), c))
        for c in cands:
            c = round(c, DECIMALS)
            if not _clears(c, z, horizontal_z) or any(lo - CLEARANCE < c < hi + CLEARANCE for lo, hi in avoid):
                continue
            if out and c - out[-1] < 1.0:
                continue
            out.append(c)
            kept_attic = kept_attic or is_attic
            break
    return out, kept_attic


def cut_variants(cuts: Sequence[float], attic: bool, z_values: np.ndarray,
                 horizontal_z: Sequence[float] = ()) -> list[tuple[list[float], bool]]:
    """Cut sets to try in turn: the cuts, then the storey cuts shifted by :data:`SHIFTS` (the
    attic cut stays at the eave), then the same without the attic cut; each kept only when
    it clears every vertex by :data:`CLEARANCE` and every horizontal surface."""
    z = _heights(z_values)

    def ok(cs):
        return all(_clears(c, z, horizontal_z) for c in cs) and all(b - a >= 1.0 for a, b in zip(cs, cs[1:]))

    out = []
    for with_attic in ((True, False) if attic else (False,)):
        base = list(cuts) if with_attic or not attic else list(cuts[:-1])
        n_storey = len(base) - (1 if with_attic else 0)
        for d in SHIFTS:
            cs = [round(c + d, DECIMALS) if i < n_storey else c for i, c in enumerate(base)]
            if cs and ok(cs) and (cs, with_attic) not in out:
                out.append((cs, with_attic))
    return out


def _clip(poly: np.ndarray, c: float, keep_above: bool) -> np.ndarray:
    """``poly`` clipped to ``z >= c`` (``keep_above``) or ``z <= c`` (Sutherland-Hodgman)."""
    out = []
    n = len(poly)
    s = (poly[:, 2] - c) if keep_above else (c - poly[:, 2])
    s = np.where(np.abs(s) <= ON_PLANE, 0.0, s)
    if n and poly.dtype == np.float64 and bool(np.all(s > 0)):
        # every vertex on the kept side: the loop below would keep each one as it is
        o = poly.copy()
        keep = ~np.all(np.abs(o - np.concatenate((o[-1:], o[:-1]))) < 1e-9, axis=1)  # o[i] - o[i - 1]
        o = o[keep]
        return o if len(o) >= 3 else np.zeros((0, 3))
    # the walk on Python floats: the same IEEE operations as on numpy scalars, a fifth of the
    # cost; the new points are rounded together (np.round works element by element)
    pts, sl, c = poly.tolist(), s.tolist(), float(c)
    out, cut = [], []
    for i in range(n):
        a, b = pts[i], pts[(i + 1) % n]
        sa, sb = sl[i], sl[(i + 1) % n]
        if sa >= 0:
            out.append(a if sa > 0 else [a[0], a[1], c])
        if (sa > 0 > sb) or (sa < 0 < sb):
            # canonical order so both polygons sharing the edge compute the same point
            p, q = (a, b) if a <= b else (b, a)
            t = (c - p[2]) / (q[2] - p[2])
            cut.append(len(out))
            out.append([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), c])
    if len(out) < 3:
        return np.zeros((0, 3))
    o = np.array(out, dtype=np.float64)
    if cut:
        o[cut] = np.round(o[cut], DECIMALS)
    keep = ~np.all(np.abs(o - np.concatenate((o[-1:], o[:-1]))) < 1e-9, axis=1)  # o[i] - o[i - 1]
    o = o[keep]
    return o if len(o) >= 3 else np.zeros((0, 3))


def _area(p: np.ndarray) -> float:
    """Area (m2) of a polygon (k, 3): half the length of the summed cross products about its
    first vertex."""
    if len(p) < 3:
        return 0.0
    if not (type(p) is np.ndarray and p.dtype == np.float64 and p.ndim == 2 and p.shape[1] == 3):
        return 0.5 * float(np.linalg.norm(np.cross(p - p[0], np.roll(p, -1, axis=0) - p[0]).sum(axis=0)))
    # the norm as np.linalg.norm takes it (sqrt of the dot product): the same bits
    s = _cross_sum(p)
    return 0.5 * math.sqrt(float(s.dot(s)))


def _cross_sum(p: np.ndarray) -> np.ndarray:
    """``np.cross(p - p[0], np.roll(p, -1, axis=0) - p[0]).sum(axis=0)`` of a (k, 3) float64
    array, (3,): np.cross's operations in its order, np.roll as one concatenation (same bits)."""
    a = p - p[0]
    b = roll_next(p) - p[0]
    return cross_rows(a, b).sum(axis=0)


def _key(p: np.ndarray) -> tuple:
    return tuple(np.round(p, DECIMALS - 1).tolist())


def _section_loops(polys: Sequence[np.ndarray], c: float) -> list[np.ndarray] | None:
    """Loops closing the top of the slab below ``c`` (counter-clockwise seen from above for an
    outer boundary, clockwise for a hole); None when the edges on the plane do not chain."""
    nxt: dict[tuple, list] = {}
    pts: dict[tuple, np.ndarray] = {}
    for p in polys:
        on = np.abs(p[:, 2] - c) <= ON_PLANE
        for i in range(len(p)):
            j = (i + 1) % len(p)
            if on[i] and on[j]:
                a, b = _key(p[i]), _key(p[j])
                if a == b:
                    continue
                pts[a], pts[b] = p[i], p[j]
                nxt.setdefault(b, []).append(a)  # reversed: the cap runs the other way
    # cancel edges used in both directions (a horizontal fold on the plane)
    for a in list(nxt):
        for b in list(nxt.get(a, [])):
            if a in nxt.get(b, []) and b in nxt[a]:
                nxt[a].remove(b)
                nxt[b].remove(a)
    loops = []
    todo = {a for a, v in nxt.items() if v}
    while todo:
        start = todo.pop()
        loop, cur = [start], start
        while True:
            succ = nxt.get(cur, [])
            if len(succ) != 1:
                return None
            cur = succ[0]
            if cur == start:
                break
            if cur in loop:
                return None
            loop.append(cur)
            todo.discard(cur)
        if len(loop) >= 3:
            lp = np.array([[*pts[k][:2], c] for k in loop])
            if np.min(np.linalg.norm(lp - roll_next(lp), axis=1)) < MIN_EDGE:
                return None  # EnergyPlus would merge the two ends: the cap would not match its walls
            loops.append(lp)
    return loops


def _signed_xy(loop: np.ndarray) -> float:
    x, y = loop[:, 0], loop[:, 1]
    return 0.5 * float(np.dot(x, roll_next(y)) - np.dot(roll_next(x), y))


def cap_polygons(loops: list[np.ndarray]) -> list[list[np.ndarray]]:
    """Loops grouped into polygons ``[outer, hole, ...]`` (outer counter-clockwise from above)."""
    outers = [lp for lp in loops if _signed_xy(lp) > 0]
    holes = [lp for lp in loops if _signed_xy(lp) < 0]
    groups = [[o] for o in outers]
    shp = [Polygon(o[:, :2]) for o in outers]
    for h in holes:
        pt = Point(*h[:, :2].mean(axis=0)) if Polygon(h[:, :2]).is_valid else Point(*h[0, :2])
        inside = [i for i, s in enumerate(shp) if s.buffer(1e-6).contains(pt)]
        if not inside:
            return []
        i = min(inside, key=lambda i: shp[i].area)
        groups[i].append(h)
    return groups


def split_storeys(polygons: Sequence[tuple[np.ndarray, Any]], cuts: Sequence[float], decompose,
                  attic_top: bool = False) -> list[Slab] | None:
    """Cut a closed envelope into one closed :class:`Slab` per storey.

    Parameters
    ----------
    polygons : sequence of ((k, 3) float, tag)
        Planar convex polygons, outward, closed shell.
    cuts : sequence of float, m
        Increasing cut heights (:func:`storey_cuts`).
    decompose : callable
        ``decompose(points (k, 3), ring ends, normal (3,), centre (3,)) -> list of (m, 3)``:
        planar convex pieces of a polygon with holes (the exporter's own).
    attic_top : bool
        The top slab is the attic.

    Returns
    -------
    list of Slab, or None
        None when a section does not close (the caller keeps one zone).
    """
    cuts = [float(c) for c in cuts]
    if not cuts:
        return None
    polys = [(np.asarray(p, dtype=np.float64), tag) for p, tag in polygons]
    bounds = [-np.inf] + cuts + [np.inf]
    slabs_polys = []
    for k in range(len(bounds) - 1):
        lo, hi = bounds[k], bounds[k + 1]
        sp = []
        for p, tag in polys:
            if p[:, 2].min() >= hi - ON_PLANE or p[:, 2].max() <= lo + ON_PLANE:
                continue  # beyond the slab or touching it along a line (horizontal surfaces on a cut were refused)
            q = p
            if np.isfinite(lo):
                q = _clip(q, lo, True)
            if len(q) and np.isfinite(hi):
                q = _clip(q, hi, False)
            if len(q) >= 3 and _area(q) > 1e-6:
                sp.append((q, tag))
        slabs_polys.append(sp)
    caps = []
    for k, c in enumerate(cuts):
        loops = _section_loops([p for p, _ in slabs_polys[k]], c)
        if not loops:
            return None
        groups = cap_polygons(loops)
        if not groups:
            return None
        pieces = []
        up = np.array([0.0, 0.0, 1.0])
        for g in groups:
            pts = np.concatenate(g)
            ends = np.cumsum([len(r) for r in g]).tolist()
            for piece in decompose(pts, ends, up, g[0].mean(axis=0)):
                if _area(piece) > 1e-4:
                    pieces.append(np.round(piece, DECIMALS))
        if not pieces:
            return None
        caps.append(pieces)
    out = []
    for k, sp in enumerate(slabs_polys):
        ceiling = caps[k] if k < len(cuts) else []
        floor = [c[::-1].copy() for c in caps[k - 1]] if k > 0 else []
        zr = (bounds[k] if np.isfinite(bounds[k]) else min(float(p[:, 2].min()) for p, _ in sp),
              bounds[k + 1] if np.isfinite(bounds[k + 1]) else max(float(p[:, 2].max()) for p, _ in sp))
        out.append(Slab(sp, floor, ceiling, zr, attic_top and k == len(slabs_polys) - 1))
    return out


def zone_levels(polygons: Sequence[tuple[np.ndarray, str]], faces: Sequence[int] | None = None
                ) -> tuple[float, float, float, bool]:
    """``(ground, eave, ridge, pitched)`` (m) of a zone from its polygons tagged by kind
    ("roof", "wall", "ground", "floor"): as :func:`lod2energy.thermal.storeys.roof_levels`.
    ``faces``: the face each polygon is a piece of (>= 0), whose lowest point is each piece's
    eave, so that a roof face written as several convex pieces has the eave of the face."""
    allz = np.concatenate([p[:, 2] for p, _ in polygons])
    low: dict[int, float] = {}
    if faces is not None:
        for (p, kind), f in zip(polygons, faces):
            if kind == "roof" and f >= 0:
                low[f] = min(low.get(f, math.inf), float(p[:, 2].min()))
    roofs = []
    for i, (p, kind) in enumerate(polygons):
        if kind != "roof":
            continue
        n = _cross_sum(p) / 2
        a = math.sqrt(float(n.dot(n)))  # np.linalg.norm(n), the same bits
        if a <= 1e-9:
            continue
        nz = float(n[2]) / a
        f = faces[i] if faces is not None else -1
        roofs.append((low.get(f, float(p[:, 2].min())), float(p[:, 2].max()), a * max(nz, 0.0),
                      float(np.degrees(np.arccos(np.clip(nz, -1, 1))))))
    ground = float(allz.min())
    if not roofs:
        return ground, float(allz.max()), float(allz.max()), False
    eave, pitched = eave_and_pitch(roofs)
    return ground, max(eave, ground), float(allz.max()), pitched


#: Offsets (m) tried above a storey's floor level for the plane of its section (one that passes
#: through no vertex, so that every edge crossing it crosses it properly).
SECTION_OFFSETS = (1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2)


def section_area(polygons: Sequence[np.ndarray], z: float) -> float:
    """Area (m2) of the horizontal section of a closed shell just above height ``z``.

    The plane is put :data:`SECTION_OFFSETS` above ``z`` (the first offset no vertex lies on),
    so a horizontal surface at ``z`` (a lower roof, a step) is below it: the figure is the
    floor area of a storey whose floor is at ``z``. Each polygon crossing the plane adds the
    segment it leaves on it, from where its boundary comes down through the plane to where it
    went up (the cap that would close the part below, as :func:`split_storeys` builds it), and
    the area is the shoelace sum of those segments: no loops are chained, so a section that
    would not close as a cap (what makes a storey cut fail) still has its area.

    Parameters
    ----------
    polygons : sequence of (k, 3) float
        The shell's planar polygons, counter-clockwise seen from outside, closed.
    z : float, m

    Returns
    -------
    float, m2
        0 when the plane misses the shell.
    """
    polys = [np.asarray(p, dtype=np.float64) for p in polygons if len(p) >= 3]
    if not polys:
        return 0.0
    allz = np.concatenate([p[:, 2] for p in polys])
    c = float(z) + SECTION_OFFSETS[-1]
    for d in SECTION_OFFSETS:
        if not np.any(np.abs(allz - (float(z) + d)) < 1e-7):
            c = float(z) + d
            break
    ref = np.concatenate([p[:, :2] for p in polys]).mean(axis=0)
    area = 0.0
    for p in polys:
        above = p[:, 2] > c
        if above.all() or not above.any():
            continue
        q = np.roll(p, -1, axis=0)
        cross = np.nonzero(above != np.roll(above, -1))[0]
        pts = [p[i, :2] + (c - p[i, 2]) / (q[i, 2] - p[i, 2]) * (q[i, :2] - p[i, :2]) - ref for i in cross]
        ups = [not above[i] for i in cross]  # the boundary goes up through the plane here
        k0 = ups.index(True)
        order = list(range(k0, len(cross))) + list(range(k0))
        for a, b in zip(order[::2], order[1::2]):  # (up, next down) pairs along the boundary
            up, down = pts[a], pts[b]
            area += 0.5 * float(down[0] * up[1] - up[0] * down[1])
    return max(area, 0.0)
