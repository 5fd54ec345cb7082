"""The integer grid a CityJSON file stores its vertices on (``transform``: scale, translate).

A CityJSON writer rounds every vertex to ``translate + k * scale``; a building checked before
it is written must be checked on that grid (:func:`on_grid`), or a face within a tolerance
before rounding can be over it in the file.
"""
from __future__ import annotations

from dataclasses import replace
from collections.abc import Mapping

import numpy as np

from lod2energy.model import Building


def file_coordinates(vertices: np.ndarray, frame=None) -> np.ndarray:
    """Vertices in the file's CRS: moved back from the metric frame of a geographic input or of
    one in feet (:func:`lod2energy.io.to_local_frame`), unchanged otherwise."""
    if frame is None or not len(vertices):
        return vertices
    return frame.to_file(vertices)


def quantise(vertices: np.ndarray, transform: Mapping, frame=None) -> list:
    vertices = file_coordinates(vertices, frame)
    scale = np.asarray(transform["scale"], dtype=np.float64)
    translate = np.asarray(transform["translate"], dtype=np.float64)
    q = np.rint((vertices - translate) / scale).astype(np.int64)
    return q.tolist()


def default_transform(vertices: np.ndarray, scale: float = 0.001) -> dict:
    lo = vertices.min(axis=0) if len(vertices) else np.zeros(3)
    return {"scale": [scale] * 3, "translate": [float(round(x, 3)) for x in lo]}


def on_grid(b: Building, transform: Mapping, frame=None) -> Building:
    """``b`` with its vertices rounded to the grid of ``transform`` (scale, translate), as a
    CityJSON file stores them (for a geographic input, on the file's grid in degrees:
    ``frame`` moves them there and back)."""
    scale = np.asarray(transform["scale"], dtype=np.float64)
    translate = np.asarray(transform["translate"], dtype=np.float64)
    fv = file_coordinates(b.vertices, frame)
    v = np.rint((fv - translate) / scale) * scale + translate
    if frame is not None and len(v):
        v = frame.to_local(v)
    if np.array_equal(v, b.vertices):
        return b
    return replace(b, vertices=v)


#: Scale of the grid a geographic file (degrees) is written on: ~0.1 mm horizontally, 1 mm in height.
GEOGRAPHIC_SCALE = (1e-9, 1e-9, 0.001)


def building_grid(b: Building) -> tuple[Mapping, object]:
    """The grid ``b`` will be written on: ``(transform, frame)``.

    The input file's ``transform`` when the reader recorded one (``provenance["file_transform"]``,
    which a CityJSON writer keeps), else the writer's default for ``b``'s own coordinates: a
    millimetre grid whose translation is rounded to the millimetre, so its nodes are those of the
    default grid of any file ``b`` is written into. ``frame`` is the local metric frame of a
    geographic input (``provenance["file_frame"]``), else None.
    """
    frame = b.provenance.get("file_frame")
    t = b.provenance.get("file_transform")
    if isinstance(t, Mapping) and "scale" in t and "translate" in t:
        return t, frame
    t = default_transform(file_coordinates(np.asarray(b.vertices, dtype=np.float64), frame))
    if getattr(frame, "geographic", False):
        t["scale"] = list(GEOGRAPHIC_SCALE)
    return t, frame
