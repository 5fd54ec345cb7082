"""The repair's input verdict: which geometries the ladder looks at, and the codes it starts from.

The val3dity codes are the validator's own (:func:`lod2energy.validate.checks.validate_geometry`,
the verdict of ``lod2energy validate`` and of the final check), so a geometry gets one verdict on
every path; the ladder adds only the project's energy codes (1001-1003). A geometry without any
code is kept as it is.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.model import BUILDING_TYPES, SURFACE_TYPES, Building, Geometry, lod_key
from lod2energy.repair.cleanup import snap_vertices
from lod2energy.repair.convert import mesh_of_geometry
from lod2energy.repair.plausible import flat, implausible
from lod2energy.polymesh import topology
from lod2energy.validate.checks import validate_geometry
from lod2energy.validate.closed import energy_codes, invalid_surfaces, shell_defects

__all__ = ["MIN_VOLUME_FACES", "input_codes", "refused", "targets", "verdicts"]


#: A surface-type geometry (MultiSurface, CompositeSurface) of fewer faces beside a Solid of
#: the same object and LoD is an extra, not an envelope.
MIN_VOLUME_FACES = 4


def _bounds_volume(g: Geometry, siblings: Sequence[Geometry] = ()) -> bool:
    """Is ``g`` meant to enclose a volume: LoD >= 1 (or a Solid-type geometry whose 'lod' is
    missing or junk, 901), and not a surface set of fewer than :data:`MIN_VOLUME_FACES` faces
    next to a Solid-type geometry of the same LoD among ``siblings`` (Euromast's lone wall
    beside its Solid). LoD0 footprints and roof outlines are not volumes."""
    if g.is_volumetric:
        return g.lod is None or lod_key(g.lod) >= 1
    if lod_key(g.lod) < 1:
        return False
    n = sum(len(sh.surfaces) for so in g.solids for sh in so.shells)
    extra = any(s is not g and s.is_volumetric and s.lod == g.lod for s in siblings)
    return not (extra and 0 < n < MIN_VOLUME_FACES)


def targets(b: Building, lod: str | None) -> list[tuple[int, int, Geometry]]:
    """(object index, geometry index, geometry) of the geometries the ladder looks at."""
    out = []
    for oi, o in enumerate(b.objects):
        if o.type not in BUILDING_TYPES:
            continue
        solid_lods = {g.lod for g in o.geometries if g.is_volumetric and g.solids}
        for gi, g in enumerate(o.geometries):
            if not g.is_polygonal or not g.solids:
                continue
            if lod is not None and g.lod != lod:
                continue
            if g.type in SURFACE_TYPES and g.lod in solid_lods:
                # the object's surfaces beside its own solid of the same LoD (another encoding
                # of that volume): made into a second solid they would overlap it (601)
                continue
            if lod is None and not _bounds_volume(g, o.geometries):
                continue
            out.append((oi, gi, g))
    # the highest LoD first: it is the one energy models use, so it gets the time budget first
    return sorted(out, key=lambda t: -lod_key(t[2].lod))


def refused(m, tol: Tolerances, codes: Sequence[int], solid: bool) -> str | None:
    """Why the ladder leaves the shell ``m`` as it is, or None: misplaced coordinates
    (:func:`implausible`), or no volume (:func:`flat`) - unless ``m`` is a Solid (``solid``)
    whose input ``codes`` hold no val3dity code, which encloses a volume however thin."""
    if not m.faces:
        return None
    why = implausible(m)
    if why is None and not (solid and all(c >= 1000 for c in codes)):
        why = flat(m, tol.planarity_d2p_tol)
    return why


def _input_defects(V: np.ndarray, items, tol: Tolerances) -> list[list[int]]:
    """The input verdict of each geometry ``(g, coid, gi, m)`` of a building (vertices ``V``):
    the validator's val3dity codes (:func:`validate_geometry`, the very verdict of
    ``lod2energy validate`` and of the final check), plus the ladder's energy codes
    (1001-1003) of ``m``, its mesh, once snapped.

    The ladder's closedness test (:func:`shell_defects`) only adds the project's range: it
    triangulates and snaps in its own way, so its val3dity-range findings (a crossing of its
    own ear-clipping triangles, shell codes under a failed polygon) are no verdict of their
    own; crossings are the validator's call (as for every candidate, :func:`repair_verdict`).
    """
    codes, shells = [], []
    for g, coid, gi, m in items:
        codes.append({d.code for d in validate_geometry(V, coid, gi, g, tol)})
        s = snap_vertices(m, tol.snap_tol)
        invalid = None
        if s is m and len(g.solids) == 1 and len(g.solids[0].shells) == 1:
            # m is this one shell as it is (renumbered in order): the validator's polygon
            # verdict on it, just computed, is the one shell_defects asks for
            invalid = invalid_surfaces(V, g.solids[0].shells[0], tol)
        shells.append((s, invalid))
    out = []
    found = shell_defects([s for s, _ in shells], tol, self_intersection=False,
                          invalid=[inv for _, inv in shells])
    for (g, _, _, m), c, (s, _), sd in zip(items, codes, shells, found):
        if g.is_volumetric and c:
            # an invalid Solid: the validator's codes say what is wrong; slivers are news
            own = {1003} if any(x == 1003 for _, x, _ in sd) else set()
        else:
            own = {x for x in energy_codes(sd) if x >= 1000}
        c |= own
        # closed only once vertices are snapped (exporters need shared vertices); when
        # snapping left m as it is, shell_defects found no boundary edge of m
        if not sd and s is not m and topology(m).boundary:
            c.add(1001)
        out.append(sorted(c))
    return out


def verdicts(b: Building, todo, meshes, whys, tol: Tolerances) -> list[list[int]]:
    """Input codes of each geometry of ``todo`` (:func:`targets`, with their meshes and
    :func:`implausible` reasons): :func:`_input_defects`, or the validator's codes alone for a
    geometry with non-finite coordinates."""
    checked = [k for k, (m, why) in enumerate(zip(meshes, whys))
               if not (why is not None and not np.isfinite(m.vertices).all())]
    found = dict(zip(checked, _input_defects(
        b.vertices, [(todo[k][2], b.objects[todo[k][0]].id, todo[k][1], meshes[k]) for k in checked], tol)))
    return [found[k] if k in found else
            sorted({d.code for d in validate_geometry(b.vertices, b.objects[oi].id, gi, g, tol)})
            for k, (oi, gi, g) in enumerate(todo)]


def input_codes(b: Building, tol: Tolerances = DEFAULT, lod: str | None = None) -> list[tuple[str, int, list[int]]]:
    """The repair's input verdict: ``(object id, geometry index, codes)`` of every geometry the
    ladder looks at, the codes its record reports as ``defects_before`` (val3dity codes exactly
    as :func:`lod2energy.validate.checks.validate_geometry` finds them, plus the energy codes
    1001-1003)."""
    todo = targets(b, lod)
    meshes = [mesh_of_geometry(b.vertices, g) for _, _, g in todo]
    whys = [implausible(m) if m.faces else None for m in meshes]
    return [(b.objects[oi].id, gi, codes)
            for (oi, gi, _), codes in zip(todo, verdicts(b, todo, meshes, whys, tol))]
