"""Acceptance: when a repaired shell counts as valid.

- :func:`is_repaired`, the ladder's test: a result is kept when it is a closed, outward
  2-manifold without degenerate, sliver or crossing faces
  (:func:`lod2energy.validate.closed.shell_defects`) and the project's val3dity-grade
  validator finds no error on it as a Solid, both as computed and, inside
  :func:`output_grid`, once its vertices are rounded to the grid the building will be written
  on (the final check's judgement): a result the grid spoils goes further up the ladder
  (:func:`repair_verdict` says why one was rejected).

When a building may be called compliant and written: :func:`lod2energy.validate.closed.export_problem`.
"""
from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from typing import Callable, Iterator

import numpy as np

from lod2energy.config import Tolerances
from lod2energy.io.cityjson_grid import building_grid, file_coordinates
from lod2energy.model import Building, Geometry, Shell, Solid, Surface
from lod2energy.polymesh import PolyMesh
from lod2energy.validate.checks import validate_geometry
from lod2energy.validate.closed import shell_defects

__all__ = ["val3dity_codes", "is_repaired", "repair_verdict", "output_grid", "grid_rounding"]


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
