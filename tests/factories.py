"""Tiny named canonical geometries, built as :class:`lod2energy.model.Building`.

Shared by the tests (``from factories import box, gabled_house, ...``). Every factory
returns a new, valid-unless-named-otherwise Building whose outer shell is oriented
outwards (counter-clockwise seen from outside), with semantics when asked.

Polygons are given as lists of rings, each ring a ``(k, 3)`` array of coordinates; the
builder merges identical coordinates into shared vertices, as CityJSON files do.
"""
from __future__ import annotations

from typing import Iterable, Sequence

import numpy as np

from lod2energy.model import Building, CityObject, Geometry, Shell, Solid, Surface

Ring = np.ndarray          # (k, 3) float
Polygon = Sequence[Ring]   # outer ring first, then holes


def building_from_polygons(polys: Sequence[Polygon] | Sequence[Sequence[Polygon]], type: str = "Solid",
                           semantics: Sequence[str] | None = None, id: str = "b",
                           object_type: str = "Building", lod: str = "2") -> Building:
    """A one-object Building from coordinates.

    Parameters
    ----------
    polys : list of polygons, or list of shells (list of list of polygons)
        Each polygon is a list of rings, each ring a ``(k, 3)`` array-like, m. For a
        "Solid" a list of shells (exterior first) may be given; a plain list of polygons
        is one exterior shell.
    type : {"Solid", "MultiSurface", "CompositeSurface"}
    semantics : list of str, optional
        One semantic surface type per polygon (exterior shell only), e.g. "RoofSurface".
    id, object_type, lod : str
    """
    shells = _as_shells(polys)
    verts: list[tuple[float, float, float]] = []
    index: dict[tuple[float, float, float], int] = {}

    def vid(p) -> int:
        key = (float(p[0]), float(p[1]), float(p[2]))
        if key not in index:
            index[key] = len(verts)
            verts.append(key)
        return index[key]

    built = []
    n_sem = 0
    for hi, sh in enumerate(shells):
        faces = []
        for poly in sh:
            rings = [[vid(p) for p in np.asarray(r, dtype=float).reshape(-1, 3)] for r in poly]
            sem = None
            if semantics is not None and hi == 0:
                sem = n_sem
                n_sem += 1
            faces.append(Surface.from_lists(rings, sem))
        built.append(Shell(tuple(faces)))
    sem_surfaces = tuple({"type": t} for t in semantics) if semantics is not None else ()
    if type == "Solid":
        solids = (Solid(tuple(built)),)
    else:
        solids = (Solid((Shell(tuple(s for sh in built for s in sh.surfaces)),)),)
    geom = Geometry(type, lod, solids, sem_surfaces)
    obj = CityObject(id, object_type, (geom,))
    return Building(id, object_type, np.asarray(verts, dtype=float).reshape(-1, 3), (obj,))


def _as_shells(polys) -> list[list[Polygon]]:
    # a ring is (k, 3): depth of nesting tells polygons from shells
    def depth(x) -> int:
        d = 0
        while isinstance(x, (list, tuple)) or (isinstance(x, np.ndarray) and x.ndim >= 1):
            if isinstance(x, np.ndarray):
                return d + x.ndim
            if not x:
                return d + 1
            x = x[0]
            d += 1
        return d
    d = depth(polys)
    if d >= 5:
        return [list(sh) for sh in polys]
    return [list(polys)]


def box_polygons(dx: float = 10.0, dy: float = 8.0, dz: float = 6.0,
                 origin: Sequence[float] = (0.0, 0.0, 0.0)) -> list[Polygon]:
    """The 6 faces of an axis-aligned box, outward: ground, roof, 4 walls (S, E, N, W)."""
    x0, y0, z0 = origin
    x1, y1, z1 = x0 + dx, y0 + dy, z0 + dz
    p = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                  [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]])
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return [[p[f]] for f in faces]


BOX_SEMANTICS = ["GroundSurface", "RoofSurface", "WallSurface", "WallSurface", "WallSurface", "WallSurface"]


def box(dx: float = 10.0, dy: float = 8.0, dz: float = 6.0, origin=(0.0, 0.0, 0.0),
        semantics: bool = True, id: str = "box") -> Building:
    """A closed, outward box: the simplest valid building (volume ``dx*dy*dz`` m3)."""
    return building_from_polygons(box_polygons(dx, dy, dz, origin), "Solid",
                                  BOX_SEMANTICS if semantics else None, id=id)


def gabled_house(dx: float = 10.0, dy: float = 8.0, eaves: float = 6.0, ridge: float = 9.0,
                 semantics: bool = True, id: str = "house") -> Building:
    """A closed, outward gabled house: ridge along x at ``y = dy/2``.

    Faces: ground, 2 roof planes, 2 eaves walls (quads), 2 gable walls (pentagons).
    """
    h = dy / 2
    g = np.array([[0, 0, 0], [dx, 0, 0], [dx, dy, 0], [0, dy, 0]], float)
    e = np.array([[0, 0, eaves], [dx, 0, eaves], [dx, dy, eaves], [0, dy, eaves]], float)
    r0, r1 = np.array([0, h, ridge], float), np.array([dx, h, ridge], float)
    polys = [
        [g[[0, 3, 2, 1]]],                                   # ground (down)
        [np.array([e[0], e[1], r1, r0])],                    # roof south
        [np.array([e[2], e[3], r0, r1])],                    # roof north
        [np.array([g[0], g[1], e[1], e[0]])],                # wall south
        [np.array([g[2], g[3], e[3], e[2]])],                # wall north
        [np.array([g[1], g[2], e[2], r1, e[1]])],            # gable east
        [np.array([g[3], g[0], e[0], r0, e[3]])],            # gable west
    ]
    sem = ["GroundSurface", "RoofSurface", "RoofSurface", "WallSurface", "WallSurface", "WallSurface",
           "WallSurface"]
    return building_from_polygons(polys, "Solid", sem if semantics else None, id=id)


def open_box(missing: int = 1, id: str = "open_box") -> Building:
    """A box with face ``missing`` removed (default: the roof): not closed (302)."""
    polys = box_polygons()
    sem = list(BOX_SEMANTICS)
    del polys[missing], sem[missing]
    return building_from_polygons(polys, "Solid", sem, id=id)


def flipped_wall(face: int = 2, id: str = "flipped_wall") -> Building:
    """A box with one face's orientation reversed (307)."""
    polys = box_polygons()
    polys[face] = [polys[face][0][::-1]]
    return building_from_polygons(polys, "Solid", BOX_SEMANTICS, id=id)


def inward_box(id: str = "inward_box") -> Building:
    """A box with every face reversed: a valid shell oriented inwards (405 as exterior)."""
    polys = [[p[0][::-1]] for p in box_polygons()]
    return building_from_polygons(polys, "Solid", BOX_SEMANTICS, id=id)


def square(z: float = 0.0, size: float = 1.0) -> np.ndarray:
    """A counter-clockwise (seen from +z) square ring at height ``z``: (4, 3)."""
    s = size
    return np.array([[0, 0, z], [s, 0, z], [s, s, z], [0, s, z]], float)


def polygon_building(rings: Iterable[np.ndarray], type: str = "MultiSurface", id: str = "poly") -> Building:
    """A MultiSurface holding one polygon (outer ring first), for polygon-level tests."""
    return building_from_polygons([[np.asarray(r, float) for r in rings]], type, id=id)


def stepped_tower(sizes: Sequence[float] = (40.0, 28.0, 16.0), tops: Sequence[float] = (30.0, 75.0, 120.0),
                  semantics: bool = True, id: str = "tower") -> Building:
    """A closed, outward tower of square blocks stacked on a common centre: block ``k`` has
    side ``sizes[k]`` (m, decreasing) and its flat roof at ``tops[k]`` (m, increasing). Each
    set-back is a horizontal ring-shaped roof (the lower block's square with the upper block's
    as a hole). Volume ``sum(sizes[k]**2 * (tops[k] - tops[k - 1]))`` m3.
    """
    def square(s, z):
        h = s / 2
        return np.array([[-h, -h, z], [h, -h, z], [h, h, z], [-h, h, z]], float)

    polys, sem = [[square(sizes[0], 0.0)[::-1]]], ["GroundSurface"]
    z0 = 0.0
    for k, (s, top) in enumerate(zip(sizes, tops)):
        lo, hi = square(s, z0), square(s, top)
        for i in range(4):
            j = (i + 1) % 4
            polys.append([np.array([lo[i], lo[j], hi[j], hi[i]])])
            sem.append("WallSurface")
        if k + 1 < len(sizes):
            polys.append([hi, square(sizes[k + 1], top)[::-1]])  # the set-back: a ring
        else:
            polys.append([hi])
        sem.append("RoofSurface")
        z0 = top
    return building_from_polygons(polys, "Solid", sem if semantics else None, id=id)


def cantilever(dx: float = 10.0, depth: float = 8.0, reach: float = 4.0, storey: float = 3.0,
               soffit: str | None = "RoofSurface", semantics: bool = True, id: str = "cantilever") -> Building:
    """A closed, outward block of two storeys whose upper storey cantilevers ``reach`` m past
    the lower one (depth ``depth`` m): an L-section (y, z) extruded along x over ``dx`` m. The
    overhang's underside (a soffit, facing down, at ``z = storey``) is labelled ``soffit``
    (RoofSurface as some producers label it; None: unlabelled). Volume
    ``dx * storey * (2 * depth + reach)`` m3.
    """
    yz = np.array([[0, 0], [depth, 0], [depth, storey], [depth + reach, storey],
                   [depth + reach, 2 * storey], [0, 2 * storey]], float)
    kinds = ["GroundSurface", "WallSurface", soffit, "WallSurface", "RoofSurface", "WallSurface"]
    a = np.column_stack([np.zeros(len(yz)), yz])
    b = np.column_stack([np.full(len(yz), dx), yz])
    polys, sem = [[a[::-1]], [b]], ["WallSurface", "WallSurface"]  # the L-shaped end walls
    for i in range(len(yz)):
        j = (i + 1) % len(yz)
        polys.append([np.array([a[i], a[j], b[j], b[i]])])
        sem.append(kinds[i])
    if not semantics:
        return building_from_polygons(polys, "Solid", None, id=id)
    keep = [k for k, t in enumerate(sem) if t is not None]
    if len(keep) < len(sem):  # an unlabelled face: no semantic entry of its own
        built = building_from_polygons(polys, "Solid", [t or "WallSurface" for t in sem], id=id)
        g = built.objects[0].geometries[0]
        from dataclasses import replace
        faces = tuple(Surface(s.rings, s.semantic if sem[i] is not None else None)
                      for i, s in enumerate(g.solids[0].shells[0].surfaces))
        g = replace(g, solids=(Solid((Shell(faces),)),))
        return replace(built, objects=(replace(built.objects[0], geometries=(g,)),))
    return building_from_polygons(polys, "Solid", sem, id=id)


def millimetre_vertices():
    """``(verts, vid)``: a CityJSON vertex list in mm (scale 0.001) and ``vid(point in m)``, which
    gives the point's index, appending it the first time it is seen."""
    verts: list[list[int]] = []
    index: dict[tuple, int] = {}

    def vid(p):
        k = tuple(round(c * 1000) for c in p)
        if k not in index:
            index[k] = len(verts)
            verts.append(list(k))
        return index[k]
    return verts, vid


#: Every this many parts, one reaches 5 cm into its eastern neighbour (a 601 overlap to clip).
OVERLAP_EVERY = 3
#: In an ``open`` block, every this many parts has no ground face.
OPEN_EVERY = 4


def terraced_block(n: int, kind: str = "solid", width: float = 6.0, depth: float = 9.0) -> dict:
    """A CityJSON document of one Building of ``n`` BuildingParts: a grid of terraced houses
    with gable roofs (ridge along y), of varying eave and ridge heights, sharing their side
    walls (in full or in part) and their gable ends.

    Parameters
    ----------
    n : int
        Number of parts.
    kind : {"solid", "open"}
        ``solid``: each part a closed Solid; ``open``: each a MultiSurface, every
        :data:`OPEN_EVERY` th one without its ground face.
    width, depth : float, m
        Footprint of a part (x, y).
    """
    cols = max(1, int(np.ceil(np.sqrt(n))))
    verts, vid = millimetre_vertices()

    cos: dict = {"blk": {"type": "Building", "children": []}}
    for k in range(n):
        i, j = k % cols, k // cols
        x0, y0 = i * width, j * depth
        x1, y1 = x0 + width, y0 + depth
        if k % OVERLAP_EVERY == OVERLAP_EVERY - 1 and i < cols - 1 and k + 1 < n:
            x1 += 0.05
        eave = 5.0 + ((i * 5 + j * 3) % 4) * 1.0
        ridge = eave + 2.0 + (k % 3) * 0.5
        xm = (x0 + x1) / 2
        g = [vid((x0, y0, 0)), vid((x0, y1, 0)), vid((x1, y1, 0)), vid((x1, y0, 0))]
        e = [vid((x0, y0, eave)), vid((x1, y0, eave)), vid((x1, y1, eave)), vid((x0, y1, eave))]
        r0, r1 = vid((xm, y0, ridge)), vid((xm, y1, ridge))
        faces = [[g],                                     # ground
                 [[e[0], r0, r1, e[3]]],                  # roof, west slope
                 [[e[1], e[2], r1, r0]],                  # roof, east slope
                 [[g[0], g[3], e[1], r0, e[0]]],          # south gable
                 [[g[2], g[1], e[3], r1, e[2]]],          # north gable
                 [[g[1], g[0], e[0], e[3]]],              # west wall
                 [[g[3], g[2], e[2], e[1]]]]              # east wall
        sem = [0, 1, 1, 2, 2, 2, 2]
        if kind == "open" and k % OPEN_EVERY == OPEN_EVERY - 1:
            faces, sem = faces[1:], sem[1:]
        semantics = {"surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface"}, {"type": "WallSurface"}],
                     "values": [sem] if kind == "solid" else sem}
        geom = ({"type": "Solid", "lod": "2.2", "boundaries": [faces], "semantics": semantics} if kind == "solid"
                else {"type": "MultiSurface", "lod": "2.2", "boundaries": faces, "semantics": semantics})
        pid = f"blk-p{k:03d}"
        cos[pid] = {"type": "BuildingPart", "parents": ["blk"], "geometry": [geom]}
        cos["blk"]["children"].append(pid)
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [0.001] * 3, "translate": [85000.0, 446000.0, 0.0]},
            "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
            "CityObjects": cos, "vertices": verts}
