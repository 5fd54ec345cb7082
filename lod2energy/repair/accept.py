"""Acceptance: when a repaired shell counts as valid, and when a building may be called compliant and written.

- :func:`is_repaired`, the ladder's test: a result is kept when it is a closed, outward
  2-manifold without degenerate, sliver or crossing faces
  (:func:`lod2energy.validate.closed.shell_defects`) and the project's val3dity-grade
  validator finds no error on it as a Solid, both as computed and, inside
  :func:`output_grid`, once its vertices are rounded to the grid the building will be written
  on (the final check's judgement, :func:`export_problem`): a result the grid spoils goes
  further up the ladder (:func:`repair_verdict` says why one was rejected).
- :func:`acceptance_problem` and :func:`envelope_problems`: what an energy building needs
  besides val3dity validity (thermal data; an envelope that is closed, outward, labelled and
  has U-values). The pipeline's final check and the CityJSON writer's check both use them.
"""
from __future__ import annotations

from lod2energy.config import Tolerances
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import replace
from typing import Callable, Iterable, Iterator, Mapping

import numpy as np

from lod2energy.model import Building, Geometry, Shell, Solid, Surface
from lod2energy.polymesh import PolyMesh
from lod2energy.validate.closed import shell_defects
from lod2energy.semantics import ENVELOPE_TYPES, envelope_objects, face_metrics
from lod2energy.io.cityjson_grid import building_grid, file_coordinates, on_grid
from lod2energy.validate.checks import validate_building, validate_geometry

__all__ = ["val3dity_codes", "is_repaired", "repair_verdict", "output_grid", "grid_rounding", "TOLERATED_CODES", "acceptance_problem", "envelope_problems",
           "export_problem", "strip_to_energy", "energy_defects"]

#: Overlapping BuildingParts (601) are reported by the validator but do not stop an export:
#: each part is still a closed, outward shell (the repair ladder's own criterion); use
#: ``--merge-parts`` to union them.
TOLERATED_CODES = frozenset({601})
#: At most this many envelope problems are listed for one building.
MAX_PROBLEMS = 50


def _probe_geometry(m: PolyMesh, lod) -> Geometry:
    surfaces = tuple(Surface.from_lists([list(r) for r in f.rings]) for f in m.faces)
    return Geometry("Solid", lod, (Solid((Shell(surfaces),)),))


def val3dity_codes(m: PolyMesh, lod, tol: Tolerances, coid: str = "probe") -> list[int]:
    """Codes the project's validator finds on ``m`` as a Solid (601 cannot occur here)."""
    return sorted({d.code for d in validate_geometry(m.vertices, coid, 0, _probe_geometry(m, lod), tol)})


#: The rounding of the output grid the ladder's results are judged on (None: as computed).
_GRID: ContextVar[Callable[[np.ndarray], np.ndarray] | None] = ContextVar("lod2energy_output_grid", default=None)


def grid_rounding(b: Building) -> Callable[[np.ndarray], np.ndarray]:
    """``f(vertices (n, 3)) -> (n, 3)``: coordinates (m, ``b``'s frame) rounded to the grid ``b``
    will be written on (:func:`lod2energy.io.cityjson_grid.building_grid`), exactly as
    :func:`lod2energy.io.cityjson_grid.on_grid` rounds them."""
    transform, frame = building_grid(b)
    scale = np.asarray(transform["scale"], dtype=np.float64)
    translate = np.asarray(transform["translate"], dtype=np.float64)

    def f(vertices: np.ndarray) -> np.ndarray:
        if not len(vertices):
            return vertices
        v = np.rint((file_coordinates(vertices, frame) - translate) / scale) * scale + translate
        return frame.to_local(v) if frame is not None else v
    return f


@contextmanager
def output_grid(rounding: Callable[[np.ndarray], np.ndarray] | None) -> Iterator[None]:
    """Inside this block :func:`is_repaired` also judges each result on ``rounding``'s grid
    (:func:`grid_rounding`), every stage of the ladder alike."""
    token = _GRID.set(rounding)
    try:
        yield
    finally:
        _GRID.reset(token)


def repair_verdict(m: PolyMesh | None, lod, tol: Tolerances) -> str | None:
    """Why ``m`` is not a repaired shell (None when it is): "no result", "failed" (a defect as
    computed) or "rejected on the output grid (val3dity codes [...])"."""
    if m is None or not m.faces:
        return "no result"
    # crossings are the project validator's call (val3dity semantics: touching counts)
    if shell_defects([m], tol, first_only=True, self_intersection=False)[0]:
        return "failed"
    if val3dity_codes(m, lod, tol):
        return "failed"
    rounding = _GRID.get()
    if rounding is not None:
        v = rounding(m.vertices)
        if not np.array_equal(v, m.vertices):
            codes = val3dity_codes(PolyMesh(v, m.faces), lod, tol)
            if codes:
                return f"rejected on the output grid (val3dity codes {codes})"
    return None


def is_repaired(m: PolyMesh | None, lod, tol: Tolerances) -> bool:
    """The ladder's stopping criterion (:func:`repair_verdict` is None)."""
    return repair_verdict(m, lod, tol) is None


# ----------------------------------------------------------------------------- energy buildings

def acceptance_problem(b: Building, lod: str | None) -> str | None:
    """The checks of an energy building besides its val3dity validity: a Building with thermal
    data and an envelope at ``lod`` that is closed, outward, labelled and has U-values; the first
    problem, or None. The pipeline's final check and this writer's both start with it."""
    if b.type != "Building":
        return f"not a Building (type {b.type!r})"
    if "thermal" not in b.provenance:
        return "no thermal data (labels / U-values not assigned)"
    energy = envelope_objects(b, lod)
    if not energy:
        return "no polygonal geometry at the energy LoD"
    probs = envelope_problems(b, energy)
    return probs[0] if probs else None


def envelope_problems(b: Building, energy=None) -> list[str]:
    """Closed, outward, labelled, with U-values: problems of the energy geometries of ``b``."""
    out = []
    energy = energy if energy is not None else envelope_objects(b)
    # identical coordinates = same vertex, whatever the index
    _, inv = np.unique(b.vertices, axis=0, return_inverse=True)
    inv = inv.reshape(-1)
    origin = b.vertices.mean(axis=0) if len(b.vertices) else np.zeros(3)
    for o, gi, g in energy:
        where = f"coid={o.id}|geom={gi}"
        if not g.is_volumetric:
            out.append(f"{where}: {g.type} is not a solid")
            continue
        for si, so in enumerate(g.solids):
            for hi, sh in enumerate(so.shells):
                edges: dict[tuple[int, int], int] = {}
                vol = 0.0
                for s in sh.surfaces:
                    for r in s.rings:
                        ids = inv[r].tolist()
                        for e in zip(ids, ids[1:] + ids[:1]):
                            if e[0] != e[1]:
                                edges[e] = edges.get(e, 0) + 1
                    ar, n, cen = face_metrics(b.vertices, s)
                    vol += float((cen - origin) @ (n * ar)) / 3.0
                bad = [e for e, k in edges.items() if k != 1 or edges.get((e[1], e[0]), 0) != 1]
                if bad:
                    out.append(f"{where}|solid={si}|shell={hi}: not closed or not consistently oriented "
                               f"({len(bad)} bad edges)")
                elif hi == 0 and vol <= 0:
                    out.append(f"{where}|solid={si}|shell={hi}: exterior shell oriented inwards (volume {vol:.3f} m3)")
        for si, hi, fi, s in g.iter_surfaces():
            loc = f"{where}|shell={hi}|face={fi}"
            if s.semantic is None or s.semantic >= len(g.semantic_surfaces):
                out.append(f"{loc}: no semantic surface")
                continue
            e = g.semantic_surfaces[s.semantic]
            if e.get("type") not in ENVELOPE_TYPES:
                out.append(f"{loc}: semantic type {e.get('type')!r} is not an envelope type")
            u = e.get("uValue")
            if not isinstance(u, (int, float)) or isinstance(u, bool) or not u > 0:
                out.append(f"{loc}: no positive uValue")
        if len(out) > MAX_PROBLEMS:
            break
    return out


def strip_to_energy(b: Building, lod: str | None, keep_other_lods: bool = False) -> Building:
    """``b`` with only its envelope geometries at ``lod`` (all of them when ``keep_other_lods``)."""
    if keep_other_lods:
        return b
    keep = {(o.id, gi) for o, gi, _ in envelope_objects(b, lod)}
    objs = []
    for o in b.objects:
        geoms = tuple(g for gi, g in enumerate(o.geometries) if (o.id, gi) in keep)
        objs.append(replace(o, geometries=geoms))
    return replace(b, objects=tuple(objs))


def energy_defects(b: Building, defects: Iterable, lod: str | None) -> list:
    """The ``defects`` of ``b`` that concern its envelope at ``lod`` (or the building as a whole),
    without the tolerated ones (:data:`TOLERATED_CODES`)."""
    energy = envelope_objects(b, lod)
    heads = {f"coid={o.id}|geom={gi}" for o, gi, _ in energy}
    ids = {f"coid={o.id}" for o, _, _ in energy}
    bad = []
    for d in defects:
        if d.code in TOLERATED_CODES:
            continue
        locs = str(d.location).split("&&")
        if any("|".join(loc.split("|")[:2]) in heads or loc in ids or "geom=" not in loc for loc in locs):
            bad.append(d)
    return bad


def export_problem(b: Building, lod: str | None, tol: Tolerances, *, defects: Iterable | None = None,
                   transform: Mapping | None = None, frame=None, keep_other_lods: bool = False) -> str | None:
    """Why ``b`` may not be called compliant nor written (None when it may): the one final check.

    Judged on what a writer writes: the vertices are first rounded to the output file's grid
    (:func:`lod2energy.io.cityjson_grid.on_grid`, the function the CityJSON writer uses), then
    :func:`acceptance_problem` and the val3dity checks at the user's tolerances ``tol`` run on
    the envelope at ``lod`` (overlapping parts, 601, tolerated).

    Parameters
    ----------
    b : Building
        Labelled, with U-values (``provenance["thermal"]``).
    lod : str or None
        Energy LoD (None: the building's own).
    tol : Tolerances
    defects : iterable of Defect, optional
        Already computed defects of ``b`` at ``tol``: used when the grid leaves ``b`` as it is.
    transform, frame : optional
        The file's grid (scale, translate) and, for a geographic file, its local frame;
        default: :func:`lod2energy.io.cityjson_grid.building_grid`.
    keep_other_lods : bool
        Judge every geometry, not only the envelope at ``lod``.
    """
    if transform is None:
        transform, frame = building_grid(b)
    snapped = on_grid(b, transform, frame)
    why = acceptance_problem(snapped, lod)
    if why is not None:
        return why
    if snapped is b and defects is not None and not keep_other_lods:
        bad = energy_defects(b, defects, lod)
    else:
        bad = [d for d in validate_building(strip_to_energy(snapped, lod, keep_other_lods), tol)
               if d.code not in TOLERATED_CODES]
    if bad:
        codes = sorted({d.code for d in bad})
        return f"invalid geometry (val3dity codes {codes}), e.g. {bad[0].location}"
    return None
