"""semantics.face_metrics remembers polygons by their coordinates: never a stale answer."""
import numpy as np

from lod2energy import cache, semantics
from lod2energy.model import Surface


def _square(z=0.0, s=1.0):
    return np.array([[0, 0, z], [s, 0, z], [s, s, z], [0, s, z]], dtype=float)


def test_same_surface_moved_vertices_gives_new_answer():
    cache.clear(semantics.FACE_METRICS)
    surf = Surface.from_lists([[0, 1, 2, 3]])
    v = _square()
    a1, n1, c1 = semantics.face_metrics(v, surf)
    v2 = v.copy()
    v2[:, :2] *= 2.0  # same Surface, same indices, other coordinates
    a2, n2, c2 = semantics.face_metrics(v2, surf)
    assert a1 == 1.0 and a2 == 4.0
    np.testing.assert_allclose(c2, [1.0, 1.0, 0.0])
    v[:, 2] = 5.0  # the first array changed in place: its answer changes too
    a3, _, c3 = semantics.face_metrics(v, surf)
    assert a3 == 1.0 and c3[2] == 5.0


def test_cached_answer_equals_uncached_and_is_not_shared():
    cache.clear(semantics.FACE_METRICS)
    rng = np.random.default_rng(3)
    v = np.vstack([_square(s=4.0), _square(s=1.0) + [1, 1, 0]]) + rng.normal(0, 1e-4, (8, 3))
    surf = Surface.from_lists([[0, 1, 2, 3], [7, 6, 5, 4]])
    fresh = semantics._face_metrics([v[r] for r in surf.rings])
    first = semantics.face_metrics(v, surf)
    second = semantics.face_metrics(v, surf)
    for x in (first, second):
        assert x[0] == fresh[0]
        assert x[1].tobytes() == fresh[1].tobytes() and x[2].tobytes() == fresh[2].tobytes()
    first[1][:] = 0.0  # a caller writing into its result cannot change the next answer
    first[2][:] = 0.0
    third = semantics.face_metrics(v, surf)
    assert third[1].tobytes() == fresh[1].tobytes() and third[2].tobytes() == fresh[2].tobytes()


def test_ring_split_is_part_of_the_key():
    cache.clear(semantics.FACE_METRICS)
    v = np.vstack([_square(s=4.0), _square(s=1.0) + [1, 1, 0]])
    with_hole = semantics.face_metrics(v, Surface.from_lists([[0, 1, 2, 3], [7, 6, 5, 4]]))
    assert with_hole[0] == 15.0
    # the same coordinates in the same order, but as one ring: not the cached polygon's answer
    one_ring = semantics.face_metrics(v, Surface.from_lists([[0, 1, 2, 3, 7, 6, 5, 4]]))
    assert one_ring[0] != with_hole[0]


def test_cache_is_bounded(monkeypatch):
    cache.clear(semantics.FACE_METRICS)
    monkeypatch.setattr(semantics, "KEPT_FACES", 5)
    surf = Surface.from_lists([[0, 1, 2, 3]])
    for k in range(20):
        semantics.face_metrics(_square(z=float(k)), surf)
        assert cache.sizes()[semantics.FACE_METRICS][0] <= 5
