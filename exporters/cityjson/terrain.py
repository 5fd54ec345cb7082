"""The input's terrain in the energy CityJSON: its ``TINRelief`` city objects, carried as read.

A terrain is no part of the energy model, but it is part of the city model the user exports
(issue 19). Both readers yield a ``TINRelief`` as one feature (the CityJSON one as it is in
the file; CityGML's ``dem:TINRelief`` with its ``dem:tin`` as a CompositeSurface of
triangles, :mod:`lod2energy.io.citygml`). The energy CityJSON writer
(:func:`lod2energy.exporters.cityjson.writer.write`) writes each such feature after the buildings,
one object at a time from the spool as it writes the buildings, through the same
``transform`` (the file's grid), with its attributes and at its own LoD(s): no ``+energy``
attribute, so the self-check validates it against the official schema (and re-reads it) but
does not judge it as an envelope.

The official schemas (CityJSON 1.0, 1.1, 2.0) allow a ``TINRelief`` CompositeSurface
geometries only: a MultiSurface (a TIN given as ``gml:MultiSurface``) is written as a
CompositeSurface of the same faces; a terrain with any other geometry (points, lines, solids,
a template instance) or a geometry without a LoD is left out, with the reason, as the other
non-buildings are.
"""
from __future__ import annotations

from dataclasses import replace

from lod2energy.model import SURFACE_TYPES, Building

#: First-level CityObject types carried into the energy CityJSON as terrain.
TERRAIN_TYPES = ("TINRelief",)


def is_terrain(b: Building) -> bool:
    """``b`` is a terrain feature the energy CityJSON carries (its root is a ``TINRelief``)."""
    return b.type in TERRAIN_TYPES


def terrain_problem(b: Building) -> str | None:
    """Why terrain ``b`` cannot be written schema-valid (None when it can), located as
    val3dity locates a geometry (``coid=...|geom=...``)."""
    for o in b.objects:
        for gi, g in enumerate(o.geometries):
            where = f"coid={o.id}|geom={gi}"
            if g.type not in SURFACE_TYPES:
                return f"{where}: a {g.type} in a terrain; CityJSON allows a TINRelief CompositeSurfaces only"
            if g.lod is None:
                return f"{where}: terrain geometry without a LoD"
    return None


def prepare_terrain(b: Building) -> Building:
    """Terrain ``b`` as written: every MultiSurface a CompositeSurface of the same faces (the
    one geometry type the schemas allow a TINRelief); nothing else changed."""
    objs = []
    for o in b.objects:
        geoms = tuple(replace(g, type="CompositeSurface") if g.type == "MultiSurface" else g for g in o.geometries)
        objs.append(o if geoms == o.geometries else replace(o, geometries=geoms))
    objs_t = tuple(objs)
    return b if all(a is c for a, c in zip(objs_t, b.objects)) else replace(b, objects=objs_t)


def n_faces(b: Building) -> int:
    """Faces (the triangles of a TIN) of terrain ``b``'s geometries."""
    return sum(len(sh.surfaces) for o in b.objects for g in o.geometries for _si, _hi, sh in g.iter_shells())
