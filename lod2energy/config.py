"""Frozen tolerances shared by every stage (val3dity's names and defaults), and the use types.

Nothing here imports numpy: the command line builds its parser from this module alone.
"""
from __future__ import annotations

from dataclasses import dataclass

from lod2energy.errors import ParameterError


@dataclass(frozen=True)
class Tolerances:
    """Validation and repair tolerances.

    Parameters
    ----------
    snap_tol : float, m
        Vertices closer than this are the same vertex (val3dity ``--snap_tol``).
    planarity_d2p_tol : float, m
        Largest distance of a polygon vertex to its fitted plane (203).
    planarity_n_tol : float, degrees
        Largest deviation between normals of a polygon's triangles (204).
    overlap_tol : float, m
        Tolerance for overlap of solids / BuildingParts (401, 501, 601); ``-1`` (val3dity's
        default, "off") means any volume shared by two interiors counts.
    ignore204 : bool
        Skip the 204 check (val3dity ``--ignore204``).
    sliver_area : float, m2
        Faces with an area at or under this are slivers (energy compliance).
    volume_eps : float, m3
        Shared volumes at or under this count as touching, not overlapping (401, 501, 601
        and the inner-shell tests; absorbs round-off of coplanar shared walls).
    area_eps : float, m2
        Shared boundary area at or under this counts as no shared face (inner shells, 601).
    tjunction_tol : float, m
        Repair clean-up: a vertex this close to another polygon's edge is inserted into it
        (at least ``snap_tol``; half the planarity tolerance, so the polygon stays planar).
    unpinch_offset : float, m
        Repair: how far each copy of a pinch vertex moves into its own fan's material.
    wrap_offset : float, m
        Repair: distance the alpha wrap keeps from the input surfaces.
    skin_depth : float, m
        Repair: an alpha result whose volume per surface area is under this (while it fills
        under a third of the input's convex hull) is a skin around the surfaces, refused.
    roof_snap : float, m
        Repair ``roofs`` stage: roof outlines closer than this in plan share their vertices
        and edges (5 x the default snap tolerance).
    roof_max_displacement : float, m
        Repair ``roofs`` stage: the 2.5D model is kept only when the input's vertices lie
        this close to it on average.
    """

    snap_tol: float = 0.001
    planarity_d2p_tol: float = 0.01
    planarity_n_tol: float = 20.0
    overlap_tol: float = -1.0
    ignore204: bool = False
    sliver_area: float = 1e-4
    volume_eps: float = 1e-6
    area_eps: float = 1e-6
    tjunction_tol: float = 0.005
    unpinch_offset: float = 0.008
    wrap_offset: float = 0.01
    skin_depth: float = 0.25
    roof_snap: float = 5e-3
    roof_max_displacement: float = 0.10


DEFAULT = Tolerances()


def tolerances(a) -> Tolerances:
    """The :class:`Tolerances` of a command's parsed arguments (ParameterError for a bad one)."""
    for k in ("snap_tol", "planarity_d2p_tol", "planarity_n_tol"):
        v = getattr(a, k)
        if not (v >= 0) or v != v or v == float("inf"):
            raise ParameterError(f"--{k.replace('_', '-')} must be a finite number >= 0, got {v}")
    return Tolerances(snap_tol=a.snap_tol, planarity_d2p_tol=a.planarity_d2p_tol,
                      planarity_n_tol=a.planarity_n_tol, overlap_tol=a.overlap_tol, ignore204=a.ignore204)

USE_TYPES = ("residential", "office", "retail", "education", "health", "hospitality", "industry", "other")
"""Building use types: the choices of ``export --use`` and the results of
:func:`lod2energy.thermal.use.building_use` (which documents how attributes map to them)."""
