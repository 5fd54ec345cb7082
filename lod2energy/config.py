"""Frozen tolerances shared by every stage (val3dity's names and defaults)."""
from __future__ import annotations

from dataclasses import dataclass


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
    """

    snap_tol: float = 0.001
    planarity_d2p_tol: float = 0.01
    planarity_n_tol: float = 20.0
    overlap_tol: float = -1.0
    ignore204: bool = False
    sliver_area: float = 1e-4


DEFAULT = Tolerances()
