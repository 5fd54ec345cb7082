"""Hierarchical ISO 19107 validation of a Building, as val3dity does it.

Levels: polygons (1xx, 2xx) -> shells (3xx) -> solids (4xx) -> Multi/CompositeSolids (5xx)
-> BuildingParts (601). A failed lower level stops the checks that depend on it.

Contracts of the level modules (each returns plain tuples; this module adds locations):

- ``polygon.check_polygons(vertices, shell, tol) -> list[(face_index, code, info)]``
- ``shell.check_shell(vertices, shell, tol, volumetric) -> list[(face_index|None, code, info)]``
- ``solid.check_solid(vertices, solid, tol) -> list[(shell_index|None, code, info)]``
  (interior shells: 401-405; 405 also for an exterior shell oriented inwards)
- ``solid.check_multisolid(vertices, geometry, tol) -> list[(solid_index|None, code, info)]``
- ``solid.check_parts_overlap(building, tol) -> list[(location, code, info)]``
"""
from __future__ import annotations

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.model import MULTISOLID_TYPES, Building, Geometry
from lod2energy.validate import polygon, shell as shell_checks, solid as solid_checks
from lod2energy.validate.defect import Defect


def validate_geometry(vertices, coid: str, gi: int, g: Geometry, tol: Tolerances = DEFAULT) -> list[Defect]:
    """Defects of one polygonal geometry (levels 1xx-5xx).

    Parameters
    ----------
    vertices : (n, 3) float
        The building's vertices, m.
    coid : str
        CityObject id, for locations.
    gi : int
        Index of the geometry in the CityObject's ``geometry`` array.
    """
    out: list[Defect] = []
    if not g.solids or any(not so.shells for so in g.solids) or any(
            not sh.surfaces for so in g.solids for sh in so.shells):
        return [Defect(902, f"coid={coid}|geom={gi}", f"empty {g.type}")]
    volumetric = g.is_volumetric
    solids_ok = []
    for si, so in enumerate(g.solids):
        shells_ok = True
        for hi, sh in enumerate(so.shells):
            found = [Defect(code, f"coid={coid}|" + g.location(gi, si, hi, f), info)
                     for f, code, info in polygon.check_polygons(vertices, sh, tol)]
            if not found:
                found = [Defect(code, f"coid={coid}|" + g.location(gi, si, hi, f), info)
                         for f, code, info in shell_checks.check_shell(vertices, sh, tol, volumetric or g.type == "CompositeSurface")]
            if found:
                shells_ok = False
                out.extend(found)
        if shells_ok and volumetric:
            found = [Defect(code, f"coid={coid}|" + g.location(gi, si, h, None), info)
                     for h, code, info in solid_checks.check_solid(vertices, so, tol)]
            out.extend(found)
            shells_ok = not found
        solids_ok.append(shells_ok)
    if g.type in MULTISOLID_TYPES and all(solids_ok):
        out.extend(Defect(code, f"coid={coid}|geom={gi}" + ("" if s is None else f"|solid={s}"), info)
                   for s, code, info in solid_checks.check_multisolid(vertices, g, tol))
    return out


def validate_building(b: Building, tol: Tolerances = DEFAULT) -> list[Defect]:
    """All val3dity-level defects of a building (its own and its parts' geometries).

    Input problems found while reading (``b.provenance["input_errors"]``) come first.
    Never raises on geometry, however broken.
    """
    out = [Defect(int(c), loc, msg) for c, loc, msg in b.provenance.get("input_errors", ())]
    geom_ok = True
    for o in b.objects:
        for gi, g in enumerate(o.geometries):
            if g.type == "GeometryInstance":
                found = polygon.check_instance(b, o, gi, g, tol)
            elif not g.is_polygonal:
                continue
            else:
                found = validate_geometry(b.vertices, o.id, gi, g, tol)
            if found:
                geom_ok = False
                out.extend(found)
    if geom_ok:
        out.extend(Defect(code, loc, info) for loc, code, info in solid_checks.check_parts_overlap(b, tol))
    return out
