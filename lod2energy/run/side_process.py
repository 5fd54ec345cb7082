"""A job beside the pool: one long job in a forked process of its own (:class:`Beside`), started
now and waited for later - the export's one-file writers while the pool runs pass 2."""
from __future__ import annotations

import multiprocessing as mp
import signal
import sys
from typing import Any, Callable

from lod2energy.run.executor import Failure, _one_line
from lod2energy.run.blas_threads import one_blas_thread


def _beside_main(conn, fn, arg) -> None:
    """The process of a :class:`Beside` job: ``fn(arg)``, then ``(ok, result)`` to the parent."""
    one_blas_thread()
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles ^C and stops us
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    try:
        out = (True, fn(arg))
    except BaseException as e:  # noqa: BLE001 - reported to the parent
        out = (False, _one_line(e))
    try:
        conn.send(out)
    except Exception as e:  # noqa: BLE001 - an unpicklable result
        conn.send((False, f"result not sendable: {_one_line(e)}"))
    conn.close()


class Beside:
    """One long job in a process of its own, started now and waited for later.

    The export's one-file writers (CityJSON, GeoJSON) need no neighbour pass: with a process
    pool they run beside it, so that no core idles while one process writes the file at the
    end. The process is forked: ``arg`` is not pickled (the result is); no time budget.

    Parameters
    ----------
    fn : callable
        ``fn(arg)``; its return value must pickle.
    arg : object
    """

    def __init__(self, fn: Callable[[Any], Any], arg: Any):
        ctx = mp.get_context("fork" if "fork" in mp.get_all_start_methods() else "spawn")
        self._conn, child = ctx.Pipe(duplex=False)
        for stream in (sys.stdout, sys.stderr):  # nothing buffered here is written twice
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        self.proc = ctx.Process(target=_beside_main, args=(child, fn, arg), daemon=True)
        self.proc.start()
        child.close()
        self._done = False

    def result(self) -> Any:
        """``fn(arg)`` once it has finished, or :class:`Failure` (it raised, or its process died)."""
        try:
            ok, res = self._conn.recv()
        except (EOFError, OSError):
            self.proc.join()
            ok, res = False, f"worker process died (exit code {self.proc.exitcode})"
        self._close()
        return res if ok else Failure(res)

    def cancel(self) -> bool:
        """Stop the job now if it has not been waited for (idempotent); True when it was stopped."""
        stopped = not self._done and self.proc.is_alive()
        if stopped:
            self.proc.kill()
        self._close()
        return stopped

    def _close(self) -> None:
        if not self._done:
            self._done = True
            self.proc.join()
            self._conn.close()
