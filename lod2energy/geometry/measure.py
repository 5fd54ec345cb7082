"""Measures: triangle normals and areas, signed volume, planarity (distance to the least-squares plane).

Coordinates are metres; areas m2, volumes m3.
"""
from __future__ import annotations

import numpy as np

from lod2energy.geometry.vectors import cross_rows

__all__ = ["triangle_normals", "triangle_areas", "signed_volume", "plane_distance",
           "ring_area_2d"]


def triangle_normals(vertices: np.ndarray, tris: np.ndarray, unit: bool = True) -> np.ndarray:
    """Normals of triangles.

    Parameters
    ----------
    vertices : (n, 3) float
    tris : (T, 3) int
    unit : bool
        Normalise (zero stays zero); else length = 2 x area.

    Returns
    -------
    (T, 3) float
    """
    v = vertices[tris]
    n = cross_rows(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    if unit:
        ln = np.linalg.norm(n, axis=1, keepdims=True)
        n = np.divide(n, ln, out=np.zeros_like(n), where=ln > 0)
    return n


def triangle_areas(vertices: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Areas of triangles, m2, shape (T,)."""
    return 0.5 * np.linalg.norm(triangle_normals(vertices, tris, unit=False), axis=1)


def signed_volume(vertices: np.ndarray, tris: np.ndarray, origin: str = "centroid") -> float:
    """Signed volume enclosed by triangles (divergence theorem), m3: the one formula.

    Positive when a closed surface's normals point outwards. Computed about a point of the
    surface, so large real-world coordinates do not cost precision.

    Parameters
    ----------
    vertices : (n, 3) float
    tris : (T, 3) int
    origin : {"centroid", "first"}
        The point the tetrahedra share: the mean of the vertices the triangles use (the repair
        ladder's and the writers' choice), or the first triangle's first corner (the
        validator's).

    Returns
    -------
    float
    """
    tris = np.asarray(tris, dtype=np.intp)
    if len(tris) == 0:
        return 0.0
    vertices = np.asarray(vertices, dtype=np.float64)
    if origin == "centroid":
        c = vertices[np.unique(tris)].mean(axis=0)
        a, b, d = vertices[tris[:, 0]] - c, vertices[tris[:, 1]] - c, vertices[tris[:, 2]] - c
        return float(np.einsum("ij,ij->i", a, cross_rows(b, d)).sum() / 6.0)
    v = vertices[tris]
    v = v - v[0, 0]
    return float(np.einsum("ij,ij->i", v[:, 0], cross_rows(v[:, 1], v[:, 2])).sum() / 6.0)


def plane_distance(points: np.ndarray) -> float:
    """Largest distance of points to their least-squares plane, m (0 for 3 points or fewer).

    Parameters
    ----------
    points : (k, 3) float
    """
    P = np.asarray(points, dtype=np.float64)
    if len(P) <= 3:
        return 0.0
    c = P.mean(axis=0)
    _, _, vt = np.linalg.svd(P - c, full_matrices=False)
    return float(np.abs((P - c) @ vt[2]).max())


def ring_area_2d(P2: np.ndarray) -> float:
    """Signed area of a 2D ring (shoelace), m2: positive counter-clockwise.

    Parameters
    ----------
    P2 : (k, 2) float
    """
    return 0.5 * np.sum(P2[:, 0] * np.roll(P2[:, 1], -1) - np.roll(P2[:, 0], -1) * P2[:, 1])
