"""Stage 6 of the repair ladder: the convex hull of the building's points.

Coplanar hull triangles are merged back into convex polygons so the face count stays low.
"""
from __future__ import annotations

import numpy as np

from lod2energy.polymesh import PolyMesh, merge_coplanar, triangles_to_mesh

# scipy (0.4 s to import) is imported where it is used: validation never needs it


def convex_hull(m: PolyMesh) -> PolyMesh | None:
    """Outward convex hull of the vertices used by ``m`` (None if they span no volume)."""
    used = np.unique([i for f in m.faces for r in f.rings for i in r])
    if len(used) < 4:
        return None
    from scipy.spatial import ConvexHull, QhullError
    P = m.vertices[used]
    try:
        h = ConvexHull(P)
    except (QhullError, ValueError):
        return None
    tris = h.simplices.copy()
    # Qhull does not orient simplices: make each one face away from the centroid
    c = P[h.vertices].mean(axis=0)
    T = P[tris]
    n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    flip = np.einsum("ij,ij->i", n, T[:, 0] - c) < 0
    tris[flip] = tris[flip][:, ::-1]
    keep = np.unique(tris)
    lut = np.full(len(P), -1)
    lut[keep] = np.arange(len(keep))
    hm = triangles_to_mesh(P[keep], lut[tris])
    return merge_coplanar(hm, angle_tol=1e-9, dist_tol=1e-6)
