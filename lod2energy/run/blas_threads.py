"""Threads inside one process: lod2energy is parallel across buildings, not inside one."""
from __future__ import annotations

import os
import sys

#: The thread-count variables of the BLAS / OpenMP libraries numpy and scipy load.
_BLAS_THREAD_VARS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def one_blas_thread() -> None:
    """Limit this process's BLAS / OpenMP thread pools to one thread, unless the user chose.

    lod2energy runs in parallel across buildings (a process a core); its linear algebra is on
    small arrays, where extra BLAS threads only spin and take the other workers' cores. Before
    numpy is imported the environment does it (for every library loaded later, scipy's own
    OpenBLAS too, and every child); after, ``threadpoolctl`` limits the libraries loaded by then,
    and the environment still limits those loaded later (OpenBLAS and OpenMP read it when they
    load), so scipy is not imported here just to limit it.
    Called by the CLI, every pool worker (:mod:`lod2energy.run.executor`) and the one-file
    writers' process. A thread count the user set in the environment is left alone.
    """
    if any(v in os.environ for v in _BLAS_THREAD_VARS):
        return
    for v in _BLAS_THREAD_VARS:
        os.environ[v] = "1"
    if "numpy" in sys.modules:
        try:
            from threadpoolctl import threadpool_limits
        except ImportError:  # pragma: no cover - declared dependencies
            return
        threadpool_limits(limits=1)
