"""The alpha wrap runs in a child process, in a pool worker too.

pymeshlab (Qt and its filter plugins) costs a process about 50 MB that it never gives back; a
pool worker that wrapped in-process jumped from ~130 to ~190 MB at its first alpha-shape repair
(Den Haag x4, ``export -j 2``). In a daemonic single-threaded process (a pool worker) the wrap is
now forked with :func:`os.fork`: the worker never imports pymeshlab, gets the same wrap, and a
wrap past its deadline is abandoned there as it is in ``-j 1``.
"""
from __future__ import annotations

import time

import numpy as np

from factories import box_polygons, building_from_polygons
from lod2energy.run.executor import Failure, ProcessPoolExecutor
from lod2energy.repair import alphashape
from lod2energy.repair.pipeline import mesh_of_geometry


def _open_box():
    """A 10 x 6 x 4 m box without its roof: a wrap has something to close."""
    polys = box_polygons(10, 6, 4)
    del polys[1]
    b = building_from_polygons(polys, "MultiSurface")
    return mesh_of_geometry(b.vertices, b.root.geometries[0])


def _wrap_in_worker(deadline_s: float):
    """Runs in a pool worker: the wrap with a deadline; whether it ran in another process."""
    import multiprocessing as mp
    import os
    wrap = alphashape._wrap_arrays

    def recorded(*args):  # the process the wrap runs in, with its result
        return os.getpid(), wrap(*args)

    alphashape._wrap_arrays = recorded
    m = _open_box()
    P, F, _ = alphashape._soup(m)
    diag = float(np.linalg.norm(P.max(axis=0) - P.min(axis=0)))
    try:
        out = alphashape._wrap_until((P, F, 100 * 2.0 / diag, 100 * alphashape.OFFSET / diag, 400),
                                     time.monotonic() + deadline_s)
    finally:
        alphashape._wrap_arrays = wrap
    elsewhere = out is None or out[0] != os.getpid()
    try:
        os.waitpid(-1, os.WNOHANG)  # no child may be left to reap
        left_child = True
    except ChildProcessError:
        left_child = False
    return mp.current_process().daemon, elsewhere, None if out is None else out[1], left_child


def test_a_pool_worker_wraps_in_a_child_with_the_same_result():
    with ProcessPoolExecutor(1) as ex:
        [(_, res)] = list(ex.map(_wrap_in_worker, [60.0]))
    assert not isinstance(res, Failure), res
    daemon, elsewhere, out, left_child = res
    assert daemon  # the case this is about: multiprocessing refuses children here
    assert elsewhere  # in a child: pymeshlab's memory went with it
    m = _open_box()
    P, F, _ = alphashape._soup(m)
    diag = float(np.linalg.norm(P.max(axis=0) - P.min(axis=0)))
    here = alphashape._wrap_arrays(P, F, 100 * 2.0 / diag, 100 * alphashape.OFFSET / diag, 400)
    assert here is not None
    assert not left_child
    assert out is not None
    np.testing.assert_array_equal(out[0], here[0])
    np.testing.assert_array_equal(out[1], here[1])


def test_a_pool_worker_abandons_a_wrap_past_its_deadline():
    with ProcessPoolExecutor(1) as ex:
        [(_, res)] = list(ex.map(_wrap_in_worker, [1e-4]))
    assert not isinstance(res, Failure), res
    daemon, elsewhere, out, left_child = res
    assert daemon
    assert out is None  # over budget: the child was killed (and reaped)
    assert not left_child
