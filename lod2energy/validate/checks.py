"""Hierarchical ISO 19107 validation of a Building, as val3dity does it.

Levels: polygons (1xx, 2xx) -> shells (3xx) -> solids (4xx) -> Multi/CompositeSolids (5xx)
-> BuildingParts (601). A failed lower level stops the checks that depend on it.

Contracts of the level modules (each vectorised over many items, each returning one list of
plain tuples per item; this module adds locations):

- ``polygon.check_polygons([(vertices, shell)], tol) -> [[(face_index, code, info)]]``
- ``shell.check_shells([(vertices, shell, volumetric)], tol) -> [[(face_index|None, code, info)]]``
  (``volumetric`` False: CompositeSurface rules)
- ``solid.check_solids([(vertices, solid)], tol) -> [[(shell_index|None, code, info)]]``
  (interior shells: 401-405; 405 also for an exterior shell oriented inwards)
- ``solid.check_multisolid(vertices, geometry, tol) -> [(solid_index|None, code, info)]``
- ``solid.check_parts_overlap([building], tol) -> [[(location, code, info)]]``

As in val3dity 2.6, every geometry of every LoD is validated; MultiSurfaces get the polygon
checks only; 601 runs only when all the building's geometries are valid (reference
reports never show 601 next to another code in one feature). :func:`validate_buildings`
gives the same results as :func:`validate_building` per building, with the checks
vectorised across buildings (feed chunks of a few hundred for speed).
"""
from __future__ import annotations

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.errors import InputError
from lod2energy.io.cityjson import _Collector, _parse_geometry
from lod2energy.model import BUILDING_TYPES, MULTISOLID_TYPES, Building, Geometry
from lod2energy.validate import memo, polygon, shell as shell_checks, solid as solid_checks
from lod2energy.validate.codes import Defect


def validate_geometry(vertices, coid: str, gi: int, g: Geometry, tol: Tolerances = DEFAULT) -> list[Defect]:
    """Defects of one polygonal geometry (levels 1xx-5xx), through the geometry-level memory
    (:func:`memo.entry_key`): a geometry whose exact input was checked before in this process
    gets that answer.

    Parameters
    ----------
    vertices : (n, 3) float
        The building's vertices, m.
    coid : str
        CityObject id, for locations.
    gi : int
        Index of the geometry in the CityObject's ``geometry`` array.
    """
    return _validate_entries_remembered([(vertices, coid, gi, g)], tol)[0]


def _validate_entries_remembered(entries, tol: Tolerances) -> list[list[Defect]]:
    """:func:`_validate_entries` through the geometry-level memory."""
    keys = [memo.entry_key(v, coid, gi, g, tol) for v, coid, gi, g in entries]
    return memo.remembered(memo.GEOMETRIES, entries, keys, lambda todo: _validate_entries(todo, tol))


def _validate_entries(entries, tol: Tolerances) -> list[list[Defect]]:
    """Levels 1xx-5xx of ``(vertices, coid, geom_index, Geometry)`` entries.

    Each level runs in one vectorised batch over every entry, whichever building it belongs
    to. MultiSurfaces get polygon checks only; CompositeSurfaces the shell checks that need
    no closedness.
    """
    results: list[list[Defect]] = [[] for _ in entries]
    usable = [bool(g.solids) and all(so.shells and all(sh.surfaces for sh in so.shells) for so in g.solids)
              for _, _, _, g in entries]
    polygons = iter(polygon.check_polygons([(v, sh) for (v, _, _, g), u in zip(entries, usable) if u
                                            for _, _, sh in g.iter_shells()], tol))
    pending = []                                  # (entry, solid, shell, Shell, volumetric)
    ok: dict[tuple[int, int, int], bool] = {}
    for k, (vertices, coid, gi, g) in enumerate(entries):
        if not usable[k]:
            results[k].append(Defect(902, f"coid={coid}|geom={gi}", f"empty {g.type}"))
            continue
        for si, so in enumerate(g.solids):
            for hi, sh in enumerate(so.shells):
                found = [Defect(code, f"coid={coid}|" + g.location(gi, si, hi, f), info)
                         for f, code, info in next(polygons)]
                results[k].extend(found)
                ok[(k, si, hi)] = not found
                if not found and g.type != "MultiSurface":
                    pending.append((k, si, hi, sh, g.is_volumetric))
    if pending:
        found_all = shell_checks.check_shells([(entries[p[0]][0], p[3], p[4]) for p in pending], tol)
        for (k, si, hi, _, _), found in zip(pending, found_all):
            _, coid, gi, g = entries[k]
            results[k].extend(Defect(code, f"coid={coid}|" + g.location(gi, si, hi, f), info)
                              for f, code, info in found)
            ok[(k, si, hi)] = not found
    todo = [(k, si) for k, (_, _, _, g) in enumerate(entries) if usable[k] and g.is_volumetric
            for si, so in enumerate(g.solids) if all(ok[(k, si, hi)] for hi in range(len(so.shells)))]
    solid_found = dict(zip(todo, solid_checks.check_solids(
        [(entries[k][0], entries[k][3].solids[si]) for k, si in todo], tol)))
    for k, (vertices, coid, gi, g) in enumerate(entries):
        if not usable[k] or not g.is_volumetric:
            continue
        solids_ok = []
        for si, so in enumerate(g.solids):
            good = (k, si) in solid_found
            if good:
                found = [Defect(code, f"coid={coid}|" + g.location(gi, si, h, None), info)
                         for h, code, info in solid_found[(k, si)]]
                results[k].extend(found)
                good = not found
            solids_ok.append(good)
        if g.type in MULTISOLID_TYPES and all(solids_ok):
            results[k].extend(Defect(code, f"coid={coid}|geom={gi}" + ("" if s is None else f"|solid={s}"), info)
                              for s, code, info in solid_checks.check_multisolid(vertices, g, tol))
    return results


def validate_building(b: Building, tol: Tolerances = DEFAULT) -> list[Defect]:
    """All val3dity-level defects of a building (its own and its parts' geometries).

    Input problems found while reading (``b.provenance["input_errors"]``) come first.
    Never raises on geometry, however broken.
    """
    return validate_buildings([b], tol)[0]


def validate_buildings(buildings, tol: Tolerances = DEFAULT) -> list[list[Defect]]:
    """:func:`validate_building` for many buildings, with shell checks batched across them.

    Same results as calling :func:`validate_building` on each; much faster on tiles of
    many small buildings (feed chunks of a few hundred).

    Parameters
    ----------
    buildings : sequence of Building

    Returns
    -------
    list (one per building) of list of Defect

    Notes
    -----
    A building whose geometry was validated before at ``tol`` (in this process, or in the job
    whose spooled building this process read) gets that verdict without a second validation
    (:mod:`lod2energy.validate.memo`).
    """
    buildings = list(buildings)
    keys = [memo.verdict_key(b, tol) for b in buildings]
    return memo.remembered(memo.BUILDINGS, buildings, keys, lambda todo: _validate_all(todo, tol))


def _validate_all(buildings: list, tol: Tolerances) -> list[list[Defect]]:
    """:func:`validate_buildings` without the memory: every building validated here."""
    entries, owner = [], []
    for bi, b in enumerate(buildings):
        for o in b.objects:
            for gi, g in enumerate(o.geometries):
                if g.is_polygonal:
                    entries.append((b.vertices, o.id, gi, g))
                    owner.append(bi)
    batch = iter(_validate_entries_remembered(entries, tol))
    outs, ok_parts = [], []
    for b in buildings:
        out = [Defect(int(c), loc, msg) for c, loc, msg in b.provenance.get("input_errors", ())]
        geom_ok = True
        for o in b.objects:
            for gi, g in enumerate(o.geometries):
                if g.type == "GeometryInstance":
                    found = check_instance(b, o, gi, g, tol)
                elif not g.is_polygonal:
                    continue
                else:
                    found = next(batch)
                if found:
                    # val3dity reports installations etc. as features of their own: their
                    # errors do not stop the BuildingPart overlap check
                    if o is b.root or o.type in BUILDING_TYPES:
                        geom_ok = False
                    out.extend(found)
        outs.append(out)
        ok_parts.append(geom_ok)
    overlaps = solid_checks.check_parts_overlap([b for b, ok in zip(buildings, ok_parts) if ok], tol)
    found = iter(overlaps)
    for out, ok in zip(outs, ok_parts):
        if ok:
            out.extend(Defect(code, loc, info) for loc, code, info in next(found))
    return outs


def check_instance(building, obj, gi, geometry, tol: Tolerances = DEFAULT) -> list:
    """Defects of a GeometryInstance: its template validated in template coordinates.

    val3dity validates the template geometry itself (``vertices-templates``, no
    transformation) once per instance. The template comes from
    ``building.provenance["geometry_templates"]`` (set by the CityJSON reader); an instance
    whose template cannot be found gives no defect (nothing to validate).

    Returns
    -------
    list of Defect
    """
    t = (geometry.raw or {}).get("template")
    templates = (building.provenance or {}).get("geometry_templates")
    if not isinstance(t, int) or isinstance(t, bool) or not templates:
        return []
    try:
        tv = np.asarray(templates.get("vertices-templates") or [], dtype=np.float64).reshape(-1, 3)
        g = dict((templates.get("templates") or [])[t])
        g.setdefault("lod", "0")
        tgeom = _parse_geometry(g, _Collector(len(tv)), f"template={t}")  # the reader's own parser
    except (TypeError, ValueError, IndexError, AttributeError, InputError):
        return []
    return validate_geometry(tv, obj.id, gi, tgeom, tol) if tgeom.is_polygonal else []
