"""Geometry <-> PolyMesh: the shell a repair stage works on, and the Solid it becomes.

:func:`mesh_of_geometry` gathers a geometry's exterior-shell surfaces into one
:class:`~lod2energy.polymesh.PolyMesh` (``Face.source`` numbers them); :func:`geometry_of_mesh`
turns a repaired mesh back into a Solid with indices into the building's vertex array.
"""
from __future__ import annotations

import numpy as np

from lod2energy.model import Geometry, Shell, Solid, Surface
from lod2energy.polymesh import Face, PolyMesh, compact

__all__ = ["mesh_of_geometry", "geometry_of_mesh"]


def mesh_of_geometry(vertices: np.ndarray, g: Geometry) -> PolyMesh:
    """All exterior-shell surfaces of ``g`` as one PolyMesh with its own vertices.

    ``Face.source`` numbers the surfaces in :meth:`Geometry.iter_surfaces` order (exterior
    shells only).
    """
    faces = []
    k = 0
    for si, hi, fi, s in g.iter_surfaces():
        if hi > 0:
            continue
        faces.append(Face(tuple(tuple(int(i) for i in r) for r in s.rings), k, s.semantic))
        k += 1
    m = PolyMesh(np.asarray(vertices, dtype=np.float64), tuple(faces))
    return compact(m)


def geometry_of_mesh(m: PolyMesh, g: Geometry, lookup: dict, extra: list, base: int) -> Geometry:
    """A Solid geometry at ``g``'s LoD from ``m``; vertex indices into the building's array.

    ``lookup`` maps coordinate tuples of the building's vertices to their index; vertices not
    found are appended to ``extra`` (their index is ``base + position``).
    """
    idx = np.empty(len(m.vertices), dtype=np.int64)
    for i, p in enumerate(m.vertices):
        key = (float(p[0]), float(p[1]), float(p[2]))
        j = lookup.get(key)
        if j is None:
            j = base + len(extra)
            extra.append(p)
            lookup[key] = j
        idx[i] = j
    sem_ok = len(g.semantic_surfaces)
    surfaces = tuple(Surface.from_lists([[int(idx[v]) for v in r] for r in f.rings],
                                        f.semantic if (f.semantic is not None and f.semantic < sem_ok) else None)
                     for f in m.faces)
    return Geometry("Solid", g.lod, (Solid((Shell(surfaces),)),), g.semantic_surfaces)
