"""The repair ladder's acceptance test: when a repaired shell counts as valid.

A result is kept when it is a closed, outward 2-manifold without degenerate, sliver or
crossing faces (:func:`lod2energy.repair.validity.shell_defects`) and the project's
val3dity-grade validator finds no error on it as a Solid.
"""
from __future__ import annotations

from lod2energy.config import Tolerances
from lod2energy.model import Geometry, Shell, Solid, Surface
from lod2energy.polymesh import PolyMesh
from lod2energy.repair.validity import shell_defects
from lod2energy.validate.checks import validate_geometry

__all__ = ["val3dity_codes", "is_repaired"]


def _probe_geometry(m: PolyMesh, lod) -> Geometry:
    surfaces = tuple(Surface.from_lists([list(r) for r in f.rings]) for f in m.faces)
    return Geometry("Solid", lod, (Solid((Shell(surfaces),)),))


def val3dity_codes(m: PolyMesh, lod, tol: Tolerances, coid: str = "probe") -> list[int]:
    """Codes the project's validator finds on ``m`` as a Solid (601 cannot occur here)."""
    return sorted({d.code for d in validate_geometry(m.vertices, coid, 0, _probe_geometry(m, lod), tol)})


def is_repaired(m: PolyMesh | None, lod, tol: Tolerances) -> bool:
    """The ladder's stopping criterion."""
    if m is None or not m.faces:
        return False
    # crossings are the project validator's call (val3dity semantics: touching counts)
    if shell_defects(m, tol, first_only=True, self_intersection=False):
        return False
    return not val3dity_codes(m, lod, tol)
