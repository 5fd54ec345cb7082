"""LoD3 openings drawn over their wall: the wall is cut where the opening is.

CityJSON (1.x, 2.0) encodes windows and doors as surfaces of the building's geometry with a
semantic surface typed ``Window`` / ``Door``, often with ``"parent"`` naming the semantic
surface of their wall. Two encodings occur:

- the wall has a hole (inner ring) and the opening fills it, as in CityGML (the envelope is
  closed; nothing to do here);
- the opening lies in the plane of its wall, inside it, and the wall has no hole: the two
  surfaces overlap and the opening's edges are used by one surface only.

:func:`cut_openings` turns the second into the first: the wall becomes the wall minus the
opening (a hole, or a notch when the opening reaches the wall's edge, as a door at the
ground does), made of the vertices already there, and a vertex of the opening that lies on
an edge of a neighbouring surface is inserted into that edge. The building then follows the
CityGML path: ``exporters.energyplus.openings.split_openings`` takes each opening out as a
``FenestrationSurface:Detailed`` on its wall, and the STL keeps it as part of the wall.
An opening that lies on no surface of its shell (a recessed window without a reveal) is
left as it is. What was cut is counted in ``provenance["openings_cut"]``.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

import numpy as np
from shapely.geometry import Polygon

from lod2energy.geometry import newell_normal, plane_basis, split_at_points
from lod2energy.model import BUILDING_TYPES, Building, Geometry, Shell, Solid, Surface, frozen_mapping

#: Semantic types of openings (CityJSON's spelling; the CityGML reader writes the same).
OPENING_TYPES = ("Window", "Door")
#: Largest distance (m) of an opening's vertices from its wall's plane.
PLANE_TOL = 0.01
#: Two points closer than this (m) in the wall's plane are the same vertex.
SNAP_TOL = 1e-4


def cut_openings(b: Building, plane_tol: float = PLANE_TOL) -> Building:
    """``b`` with every wall that an opening overlaps cut by it; ``b`` itself if none is.

    Parameters
    ----------
    b : Building
        Not modified.
    plane_tol : float, m
        An opening is on a surface when all its vertices are at most this far from the
        surface's plane (and it lies inside the surface).

    Returns
    -------
    Building
        New building; ``provenance["openings_cut"]`` counts the openings cut into their
        wall (per semantic type).
    """
    if b.type not in BUILDING_TYPES:
        return b
    counts: dict[str, int] = {}
    out = b
    for o in b.envelope_objects:
        for gi, g in enumerate(o.geometries):
            if not g.is_polygonal or not g.semantic_surfaces:
                continue
            kinds = {k: e.get("type") for k, e in enumerate(g.semantic_surfaces)
                     if isinstance(e, Mapping) and e.get("type") in OPENING_TYPES}
            if not kinds:
                continue
            changed = False
            solids = []
            for so in g.solids:
                shells = []
                for sh in so.shells:
                    faces, n = _cut_shell(b.vertices, g, list(sh.surfaces), kinds, plane_tol, counts)
                    changed |= n > 0
                    shells.append(Shell(tuple(faces)) if n else sh)
                solids.append(Solid(tuple(shells)))
            if changed:
                out = out.replace_geometry(o.id, gi, replace(g, solids=tuple(solids)))
    if not counts:
        return b
    return out.with_provenance(openings_cut=frozen_mapping(dict(sorted(counts.items()))))


def _parent(g: Geometry, s: Surface) -> int | None:
    e = g.semantic_surfaces[s.semantic] if s.semantic is not None else None
    p = e.get("parent") if isinstance(e, Mapping) else None
    return p if isinstance(p, int) and not isinstance(p, bool) else None


def _cut_shell(v: np.ndarray, g: Geometry, faces: list[Surface], kinds: Mapping[int, str],
               plane_tol: float, counts: dict[str, int]) -> tuple[list[Surface], int]:
    """Cut the walls of one shell by their openings; ``(faces, number cut)``."""
    holes = {frozenset(int(i) for i in r) for f in faces for r in f.inners}
    n_cut = 0
    for oi, op in enumerate(faces):
        if op.semantic not in kinds or len(op.outer) < 3 or frozenset(int(i) for i in op.outer) in holes:
            continue
        p = v[op.outer]
        n_o = newell_normal(p)
        if np.linalg.norm(n_o) < 1e-12:
            continue
        n_o = n_o / np.linalg.norm(n_o)
        parent = _parent(g, op)
        order = sorted((k for k, f in enumerate(faces) if k != oi and f.semantic not in kinds),
                       key=lambda k: faces[k].semantic != parent)  # the named wall first
        for k in order:
            new = _cut(v, faces[k], op, n_o, plane_tol)
            if new is None:
                continue
            faces[k] = new
            _insert_on_edges(v, faces, k, oi, [int(i) for i in op.outer])
            counts[kinds[op.semantic]] = counts.get(kinds[op.semantic], 0) + 1
            n_cut += 1
            break
    return faces, n_cut


def _cut(v: np.ndarray, wall: Surface, op: Surface, n_o: np.ndarray, plane_tol: float) -> Surface | None:
    """``wall`` minus ``op`` when ``op`` lies in it (same plane, inside), else None."""

    outer = v[wall.outer]
    n = newell_normal(outer)
    if len(outer) < 3 or np.linalg.norm(n) < 1e-12:
        return None
    n = n / np.linalg.norm(n)
    if abs(float(n @ n_o)) < 0.999:
        return None
    c = outer.mean(axis=0)
    p = v[op.outer]
    if np.abs((p - c) @ n).max() > plane_tol:
        return None
    a, bb = plane_basis(n)
    to2 = lambda q: np.column_stack([(q - c) @ a, (q - c) @ bb])  # noqa: E731
    try:
        w2 = Polygon(to2(outer), [to2(v[r]) for r in wall.inners])
        o2 = Polygon(to2(p))
        if not (w2.is_valid and o2.is_valid) or o2.area <= 0 or o2.area >= 0.99 * w2.area:
            return None
        if not w2.buffer(SNAP_TOL).contains(o2) or w2.intersection(o2).area < 0.99 * o2.area:
            return None
        rest = w2.difference(o2)
    except Exception:  # noqa: BLE001 - shapely topology errors on degenerate input
        return None
    if rest.geom_type != "Polygon" or rest.is_empty:
        return None
    ids = np.unique(np.concatenate([*wall.rings, op.outer]))
    rings = polygon_rings(rest, ids, to2(v[ids]))
    if rings is None:
        return None
    rings = [np.asarray(r, dtype=wall.outer.dtype) for r in rings]
    for r in rings:
        r.setflags(write=False)
    return Surface(tuple(rings), wall.semantic)


def polygon_rings(poly, ids: np.ndarray, pts2: np.ndarray) -> list[list[int]] | None:
    """The rings of a shapely ``poly`` as vertex indices, or None if a corner is no vertex.

    Parameters
    ----------
    poly : shapely Polygon
        In the plane's 2D frame.
    ids : (m,) int
        The vertex indices it may use.
    pts2 : (m, 2) float, m
        Their 2D coordinates.

    Returns
    -------
    list of list of int or None
        Outer ring counter-clockwise in the 2D frame, holes clockwise; each corner the index
        of the vertex within ``SNAP_TOL`` of it.
    """
    def ring(coords, ccw: bool):
        xy = np.asarray(coords)[:-1]
        d = np.linalg.norm(xy[:, None, :] - pts2[None, :, :], axis=2)
        j = d.argmin(axis=1)
        if (d[np.arange(len(xy)), j] > SNAP_TOL).any():
            return None
        r = [int(ids[x]) for x in j]
        r = [x for i, x in enumerate(r) if x != r[i - 1]]  # consecutive duplicates
        if len(r) < 3 or len(set(r)) != len(r):
            return None
        nxt = np.roll(xy, -1, axis=0)
        area2 = float((xy[:, 0] * nxt[:, 1] - nxt[:, 0] * xy[:, 1]).sum())
        return r if (area2 > 0) == ccw else r[::-1]

    rings = [ring(poly.exterior.coords, True)] + [ring(h.coords, False) for h in poly.interiors]
    return None if any(r is None for r in rings) else rings


def _insert_on_edges(v: np.ndarray, faces: list[Surface], host: int, op: int, ids: list[int]) -> None:
    """Put each vertex of ``ids`` that lies inside an edge of another face into that edge."""
    others = [k for k in range(len(faces)) if k not in (host, op)]
    flat = [[int(i) for i in r] for k in others for r in faces[k].rings]
    split = iter(split_at_points(v, flat, SNAP_TOL, candidates=ids))
    for k in others:
        f = faces[k]
        rings = [next(split) for _ in f.rings]
        if any(len(n) != len(r) for n, r in zip(rings, f.rings)):
            faces[k] = Surface(tuple(_ring(n, r.dtype) for n, r in zip(rings, f.rings)), f.semantic)


def _ring(idx: list[int], dtype) -> np.ndarray:
    arr = np.asarray(idx, dtype=dtype)
    arr.setflags(write=False)
    return arr
