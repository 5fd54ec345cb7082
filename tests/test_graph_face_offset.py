"""``face_graph(..., face_offset=)`` (issue 13: ``building_graphs`` no longer rebuilds every
Surface with shifted rings) gives the graph of the explicitly shifted surfaces, array for array:
boxes with holes, snapped duplicates, unused vertices, fins and empty rings, many buildings
stacked in one vertex array."""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.graph import face_graph
from lod2energy.model import Surface

from cityjson_docs import BOX_FACES, BOX_VERTICES


def _building(rng):
    v = np.asarray(BOX_VERTICES, dtype=float) * rng.uniform(0.5, 20, 3) + rng.uniform(-1e3, 1e3, 3)
    v = v + rng.normal(0, 10 ** rng.uniform(-6, -2), v.shape)  # near-duplicates and non-planarity
    faces = [[list(r) for r in f] for f in BOX_FACES]
    extra = len(v)
    v = np.vstack([v, v[:4] + 2e-4, rng.uniform(-5, 5, (3, 3))])  # snapping twins and unused vertices
    if rng.random() < 0.5:
        faces[0] = [faces[0][0], [extra + 2, extra + 1, extra]]  # a hole made of twins
    if rng.random() < 0.3:
        faces.append([[0, 1, extra + 3]])  # a fin on an edge
    if rng.random() < 0.3:
        faces.append([[]])  # an empty ring
    if rng.random() < 0.3:
        faces.pop(int(rng.integers(0, len(faces))))  # an open box
    return v, [Surface.from_lists(f) for f in faces]


@pytest.mark.parametrize("seed", range(8))
def test_face_offset_is_the_shifted_surfaces(seed):
    rng = np.random.default_rng(seed)
    blocks, plain, shifted, offs, groups, shell_of = [], [], [], [], [], []
    nv = 0
    for b in range(int(rng.integers(1, 6))):
        v, faces = _building(rng)
        blocks.append(v)
        plain += faces
        shifted += [Surface(tuple(r + nv for r in f.rings), f.semantic) for f in faces]
        offs += [nv] * len(faces)
        groups.append(np.full(len(v), b))
        shell_of += [b] * len(faces)
        nv += len(v)
    V = np.vstack(blocks)
    kw = dict(z_range=(float(V[:, 2].min()), float(V[:, 2].max())), shell_of_face=np.asarray(shell_of),
              vertex_groups=np.concatenate(groups))
    want = face_graph(V, shifted, **kw)
    got = face_graph(V, plain, face_offset=np.asarray(offs), **kw)
    for name in want.__dataclass_fields__:
        a, b = getattr(want, name), getattr(got, name)
        if isinstance(a, np.ndarray):
            assert a.dtype == b.dtype and a.shape == b.shape and np.array_equal(a, b, equal_nan=True), name
        else:
            assert a == b, name
    assert want.edge_index.shape[1] > 0  # the buildings were compared with their edges
