"""Vertex snapping of a shell's ring indices as val3dity does it (per primitive, insertion order).

The point clustering itself is :func:`lod2energy.geometry.snap.snap_points`.
"""
from __future__ import annotations

import numpy as np

from lod2energy.geometry.snap import first_occurrence, snap_points

__all__ = ["snapped_ids", "snap_points", "first_occurrence"]


def snapped_ids(vertices: np.ndarray, ids: np.ndarray, snap_tol: float) -> np.ndarray:
    """Vertex indices after snapping, for vertex indices listed in insertion order.

    Parameters
    ----------
    vertices : (n, 3) float
        All vertices, m.
    ids : (k,) int
        Vertex indices in the order val3dity would add them (rings of a shell, concatenated).
    snap_tol : float, m

    Returns
    -------
    (k,) int
        For each entry of ``ids``, the vertex index of its representative.
    """
    ids = np.asarray(ids, dtype=np.intp)
    order = first_occurrence(ids)
    if len(order) < 2:
        return ids.copy()
    rep = snap_points(vertices[order], snap_tol)
    if (rep == np.arange(len(order))).all():
        return ids.copy()
    lut = {int(v): int(order[r]) for v, r in zip(order.tolist(), rep.tolist())}
    return np.fromiter((lut[i] for i in ids.tolist()), dtype=np.intp, count=len(ids))
