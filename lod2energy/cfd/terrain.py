"""The file's own terrain for a CFD case: a CityJSON ``TINRelief`` as a triangle set."""
from __future__ import annotations

import numpy as np


def tin_of(features) -> tuple[np.ndarray, np.ndarray] | None:
    """Triangles of the ``TINRelief`` features ``(vertices (n, 3), triangles (t, 3))`` in map
    coordinates, or None when there is none."""
    from lod2energy.geometry import triangulate_surface
    vs, ts, k = [], [], 0
    for f in features:
        if f.type != "TINRelief":
            continue
        v = np.asarray(f.vertices, dtype=np.float64)
        for o in f.objects:
            for g in o.geometries:
                for si, sh, shell in g.iter_shells():
                    for s in shell.surfaces:
                        ring = [int(i) for i in s.rings[0]]
                        if len(ring) == 3:
                            ts.append(np.array(ring) + k)
                        elif len(ring) > 3:
                            tri = triangulate_surface(v, s)
                            ts.extend(np.asarray(tri) + k)
        vs.append(v)
        k += len(v)
    if not ts:
        return None
    return np.concatenate(vs), np.asarray(ts, dtype=np.intp).reshape(-1, 3)


def local_tin(tin, offset) -> tuple[np.ndarray, np.ndarray]:
    """``tin`` moved into the case's local frame."""
    v, t = tin
    return np.asarray(v) - np.asarray(offset), t
