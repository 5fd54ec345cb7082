"""Executors: where the per-building job runs (in this process, a process pool, a Dask cluster).

Every executor has one method, :meth:`Executor.map`, that applies a picklable module-level
function to a stream of arguments and yields ``(argument, result)`` **in input order**
(results that finish early wait in a bounded buffer), so that whatever runs the jobs the
pipeline writes the same files and reports in the same order. A result is the function's
return value, or

- :class:`Overrun` when the job ran past its time budget (``timeout``, s, of CPU time - so that
  a loaded machine does not time out jobs that only waited for a core - or ``WALL_FACTOR``
  times that of wall time, for jobs that block): the process pool kills the worker and starts a
  fresh one; in-process a ``SIGPROF`` / ``SIGALRM`` guard interrupts it; on Dask the task runs
  the job in a budget process of its worker (:func:`run_with_budget`), killed and replaced at
  the same budget (a Dask worker thread itself cannot be stopped);
- :class:`Failure` when the function raised (the message, one line) or its worker died.

At most ``window`` jobs are in flight or buffered, so memory stays bounded however long the
input stream is.
"""
from __future__ import annotations

import multiprocessing as mp
import os
import signal
import subprocess
import sys
import threading
import time
from collections import deque
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from typing import Any, Callable, Iterable, Iterator
import importlib
import pickle

import lod2energy.records  # noqa: F401 - makes Building picklable in every process
from lod2energy.run.blas_threads import one_blas_thread
from lod2energy.errors import ParameterError


@dataclass(frozen=True)
class Overrun:
    """The job did not finish within its budget (``seconds``, s)."""

    seconds: float


@dataclass(frozen=True)
class Failure:
    """The job raised (``message``: ``"Type: text"``) or its worker process died."""

    message: str


#: Jobs in flight or done but waiting for an earlier one, per worker: enough that one slow
#: building (a repair of seconds) does not leave the other workers idle behind it.
WINDOW_PER_JOB = 32

#: A job is stopped after ``timeout`` s of CPU time or ``WALL_FACTOR * timeout`` s of wall time.
WALL_FACTOR = 10.0


def _cpu_seconds(pid: int) -> float:
    """User + system CPU time (s) of process ``pid`` (0 when it cannot be read)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return 0.0


class BuildingTimeout(BaseException):
    """Raised inside an in-process job by the ``SIGALRM`` guard (a BaseException, so that no
    ``except Exception`` of the job swallows it)."""


def default_jobs() -> int:
    """All cores this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


class Executor:
    """Base class: runs ``fn(arg)`` for each ``arg`` and yields ``(arg, result)`` in order."""

    jobs: int = 1

    def map(self, fn: Callable[[Any], Any], args: Iterable[Any], timeout: float | None = None,
            tail: Callable[[Any], Any] | None = None) -> Iterator[tuple[Any, Any]]:
        """``(arg, result)`` of each ``fn(arg)``, in input order; ``tail`` (work for a worker
        left idle at the end of the stream) is a hint that executors may ignore."""
        raise NotImplementedError

    def close(self, kill: bool = False) -> None:
        """Stop every worker (idempotent); ``kill``: at once, without letting a job finish."""

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close(kill=exc[0] is not None)
        return False


def _one_line(e: BaseException) -> str:
    return f"{type(e).__name__}: {e}".splitlines()[0] if str(e) else type(e).__name__


# ----------------------------------------------------------------------------- in-process

class InProcessExecutor(Executor):
    """Runs each job here, one after the other; ``timeout`` enforced by ``SIGALRM``
    (main thread only; elsewhere the job's own deadline is the only bound)."""

    jobs = 1

    def map(self, fn, args, timeout=None, tail=None):
        for arg in args:
            yield arg, self._run(fn, arg, timeout)

    @staticmethod
    def _run(fn, arg, timeout):
        guard = (timeout is not None and timeout > 0 and hasattr(signal, "setitimer")
                 and threading.current_thread() is threading.main_thread())
        if not guard:
            try:
                return fn(arg)
            except Exception as e:  # noqa: BLE001 - one job's failure never stops the batch
                return Failure(_one_line(e))

        def alarm(signum, frame):
            raise BuildingTimeout()

        old = signal.signal(signal.SIGALRM, alarm)
        old_prof = signal.signal(signal.SIGPROF, alarm)
        t0 = time.monotonic()
        try:
            signal.setitimer(signal.ITIMER_PROF, float(timeout))  # CPU time of this process
            signal.setitimer(signal.ITIMER_REAL, float(timeout) * WALL_FACTOR)
            try:
                return fn(arg)
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0)
                signal.setitimer(signal.ITIMER_PROF, 0)
        except BuildingTimeout:
            return Overrun(round(time.monotonic() - t0, 1))
        except Exception as e:  # noqa: BLE001
            return Failure(_one_line(e))
        finally:
            signal.signal(signal.SIGALRM, old)
            signal.signal(signal.SIGPROF, old_prof)


# ----------------------------------------------------------------------------- process pool

def _worker_loop(conn) -> None:
    """A pool worker: receive ``(index, fn, arg)``, send back ``(index, ok, result)``."""
    one_blas_thread()
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles ^C and stops us
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    while True:
        try:
            msg = conn.recv()
        except (EOFError, OSError):
            return
        if msg is None:
            return
        idx, fn, arg = msg
        try:
            out = (idx, True, fn(arg))
        except BaseException as e:  # noqa: BLE001 - reported to the parent as this job's failure
            out = (idx, False, _one_line(e))
        try:
            conn.send(out)
        except Exception as e:  # noqa: BLE001 - an unpicklable result
            conn.send((idx, False, f"result not sendable: {_one_line(e)}"))


class _Worker:
    def __init__(self, ctx):
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_worker_loop, args=(child,), daemon=True)
        self.proc.start()
        child.close()

    def stop(self, kill: bool = False) -> None:
        try:
            if kill:
                self.proc.kill()
            else:
                self.conn.send(None)
        except (OSError, ValueError, BrokenPipeError):
            pass
        self.proc.join(timeout=None if kill else 5)
        if self.proc.is_alive():
            self.proc.kill()
            self.proc.join()
        self.conn.close()


class ProcessPoolExecutor(Executor):
    """``jobs`` worker processes; a job past its ``timeout`` has its worker killed and replaced.

    Parameters
    ----------
    jobs : int
        Worker processes (default: all cores).
    window : int, optional
        Jobs in flight or waiting to be yielded in order (default ``WINDOW_PER_JOB * jobs``).
    """

    def __init__(self, jobs: int | None = None, window: int | None = None):
        self.jobs = max(1, int(jobs or default_jobs()))
        self.window = max(self.jobs, int(window or WINDOW_PER_JOB * self.jobs))
        self._ctx = mp.get_context("fork" if "fork" in mp.get_all_start_methods() else "spawn")
        self._workers: list[_Worker] = []
        self._tailed: set[_Worker] = set()  # workers that ran a map's ``tail``
        self._tail_busy: set[_Worker] = set()  # ... and are running it now

    def _spawn(self) -> _Worker:
        w = _Worker(self._ctx)
        self._workers.append(w)
        return w

    def _retire(self, w: _Worker, kill: bool) -> None:
        self._tail_busy.discard(w)
        if w in self._workers:
            self._workers.remove(w)
        w.stop(kill=kill)

    def map(self, fn, args, timeout=None, tail=None):
        """As :meth:`Executor.map`. The next argument is read while the workers run theirs.

        ``tail``: a picklable function that each worker left without a job while others still
        run theirs (the end of the stream) calls once per pool as ``tail(None)``, its result
        dropped: work of the next map that would otherwise wait for it (e.g. its imports).
        """
        it = iter(args)
        exhausted = False
        ahead: deque = deque()  # the next argument, read ahead while the workers work
        idle: deque[_Worker] = deque(w for w in self._workers if w not in self._tail_busy)
        while len(self._workers) < self.jobs:
            idle.append(self._spawn())
        busy: dict[_Worker, tuple[int, float, float]] = {}  # index, wall and CPU clock at start
        held: dict[int, Any] = {}  # index -> argument, until yielded
        done: dict[int, Any] = {}
        nxt = 0
        sent = 0
        while True:
            while idle and len(held) < self.window and (ahead or not exhausted):
                if not ahead:
                    try:
                        ahead.append(next(it))
                    except StopIteration:
                        exhausted = True
                        break
                arg = ahead.popleft()
                w = idle.popleft()
                held[sent] = arg
                try:
                    w.conn.send((sent, fn, arg))
                    busy[w] = (sent, time.monotonic(), _cpu_seconds(w.proc.pid))
                except Exception as e:  # noqa: BLE001 - an argument that does not pickle
                    done[sent] = Failure(f"job not sendable: {_one_line(e)}")
                    idle.append(w)
                sent += 1
            if busy and not ahead and not exhausted and len(held) < self.window:
                try:
                    ahead.append(next(it))
                except StopIteration:
                    exhausted = True
            if tail is not None and exhausted and not ahead and busy:
                for w in [w for w in idle if w not in self._tailed]:
                    idle.remove(w)
                    self._tailed.add(w)
                    self._tail_busy.add(w)
                    w.conn.send((-1, tail, None))
            while nxt in done:
                yield held.pop(nxt), done.pop(nxt)
                nxt += 1
            if not busy:
                if exhausted and not held and not ahead:
                    return
                if not self._tail_busy:
                    continue
            wait_for = None
            if timeout is not None and timeout > 0:
                now = time.monotonic()
                # CPU time is polled: at most every 0.25 s, at least by the wall deadline
                wait_for = max(0.0, min(0.25, min((t0 + timeout * WALL_FACTOR - now for _, t0, _ in busy.values()),
                                                  default=0.25)))
            by_conn = {w.conn: w for w in list(busy) + list(self._tail_busy)}
            for c in wait(list(by_conn), timeout=wait_for):
                w = by_conn[c]
                idx = -1 if w in self._tail_busy else busy.pop(w)[0]
                self._tail_busy.discard(w)
                try:
                    ridx, ok, res = c.recv()
                    if idx >= 0:
                        done[idx] = res if ok else Failure(res)
                    idle.append(w)
                except (EOFError, OSError) as e:  # the worker died (e.g. out of memory)
                    code = w.proc.exitcode
                    if idx >= 0:
                        done[idx] = Failure(f"worker process died (exit code {code})" if code is not None
                                            else f"worker process lost: {_one_line(e)}")
                    self._retire(w, kill=True)
                    idle.append(self._spawn())
            if timeout is not None and timeout > 0:
                now = time.monotonic()
                for w, (idx, t0, c0) in list(busy.items()):
                    if now - t0 >= timeout * WALL_FACTOR or _cpu_seconds(w.proc.pid) - c0 >= timeout:
                        busy.pop(w)
                        self._retire(w, kill=True)
                        done[idx] = Overrun(round(now - t0, 1))
                        idle.append(self._spawn())

    def close(self, kill: bool = False) -> None:
        for w in list(self._workers):
            self._retire(w, kill=kill)


# ----------------------------------------------------------------------------- budget process

_CHILD_CODE = "import sys; from lod2energy.run.executor import _budget_child_main; _budget_child_main(int(sys.argv[1]))"
#: Wall time (s) a fresh budget process may take to start and import the job's module.
START_TIMEOUT = 120.0


def _budget_child_main(fd: int) -> None:
    """A budget process: take ``sys.path`` and the modules to import, say ready, then serve
    jobs exactly as a pool worker does (:func:`_worker_loop`)."""
    conn = Connection(fd)
    try:
        _, path, modules = conn.recv()
    except (EOFError, OSError):
        return
    sys.path[:] = path
    for m in modules:
        try:
            importlib.import_module(m)
        except Exception:  # noqa: BLE001 - the job itself reports what cannot be imported
            pass
    conn.send("ready")
    _worker_loop(conn)


class _BudgetChild:
    """One persistent ``python`` subprocess (fork + exec: safe from a multi-threaded, daemonic
    Dask worker, where ``multiprocessing`` may not start children), jobs over a socket pair."""

    def __init__(self, modules: list[str]):
        self.conn, child = mp.Pipe(duplex=True)
        try:
            self.proc = subprocess.Popen([sys.executable, "-c", _CHILD_CODE, str(child.fileno())],
                                         pass_fds=(child.fileno(),), stdin=subprocess.DEVNULL,
                                         env={**os.environ, "PYTHONPATH": os.pathsep.join(p for p in sys.path if p)})
        finally:
            child.close()
        try:
            self.conn.send(("init", list(sys.path), modules))
            ready = self.conn.poll(START_TIMEOUT) and self.conn.recv() == "ready"
        except (EOFError, OSError):
            ready = False
        if not ready:
            self.stop()
            raise OSError(f"the budget process did not start within {START_TIMEOUT:g} s "
                          f"(exit code {self.proc.returncode})")

    def stop(self) -> None:
        try:
            self.proc.kill()
            self.proc.wait()
        except OSError:
            pass
        self.conn.close()


_CHILDREN: dict[int, _BudgetChild] = {}  # worker thread id -> its budget process
_CHILDREN_LOCK = threading.Lock()


def _dumps(obj) -> bytes:
    try:
        import cloudpickle  # a dask dependency: sends functions of __main__ by value
        return cloudpickle.dumps(obj)
    except ImportError:  # pragma: no cover - cloudpickle ships with dask
        return pickle.dumps(obj)


def run_with_budget(fn: Callable[[Any], Any], arg: Any, timeout: float | None) -> Any:
    """``fn(arg)`` in this thread's budget process, stopped at ``timeout`` (s) of its CPU time
    or ``WALL_FACTOR * timeout`` of wall time, like a pool worker.

    The Dask task of :class:`DaskExecutor`. Each thread of the calling process keeps one
    persistent budget process (started on first use, its start not counted in the budget); a
    process that overruns is killed, reaped and replaced at the next call.

    Returns
    -------
    object
        ``fn(arg)``, :class:`Overrun` or :class:`Failure` (``fn`` raised, the budget process
        died or could not start). Without a budget ``fn(arg)`` runs in this thread.
    """
    if timeout is None or timeout <= 0:
        try:
            return fn(arg)
        except Exception as e:  # noqa: BLE001 - one job's failure never stops the batch
            return Failure(_one_line(e))
    key = threading.get_ident()
    with _CHILDREN_LOCK:
        child = _CHILDREN.get(key)
    if child is not None and child.proc.poll() is not None:
        _drop(key, child)
        child = None
    if child is None:
        mods = ["lod2energy.records"]
        mod = getattr(fn, "__module__", None)
        if mod and mod not in ("__main__", "__mp_main__"):
            mods.append(mod)
        try:
            child = _BudgetChild(mods)
        except (OSError, ValueError, EOFError) as e:
            return Failure(f"budget process not started: {_one_line(e)}")
        with _CHILDREN_LOCK:
            _CHILDREN[key] = child
    try:
        msg = _dumps((0, fn, arg))
    except Exception as e:  # noqa: BLE001 - an argument that does not pickle
        return Failure(f"job not sendable: {_one_line(e)}")
    pid = child.proc.pid
    t0, c0 = time.monotonic(), _cpu_seconds(pid)
    try:
        child.conn.send_bytes(msg)
        while True:
            left = t0 + timeout * WALL_FACTOR - time.monotonic()
            if child.conn.poll(max(0.0, min(0.25, left))):  # CPU time polled every 0.25 s
                _, ok, res = child.conn.recv()
                return res if ok else Failure(res)
            if time.monotonic() - t0 >= timeout * WALL_FACTOR or _cpu_seconds(pid) - c0 >= timeout:
                _drop(key, child)
                return Overrun(round(time.monotonic() - t0, 1))
    except (EOFError, OSError) as e:  # the budget process died (e.g. out of memory) or was stopped
        code = child.proc.poll()
        _drop(key, child)
        return Failure(f"worker process died (exit code {code})" if code is not None
                       else f"worker process lost: {_one_line(e)}")


def _drop(key: int, child: _BudgetChild) -> None:
    """Kill and reap ``child`` and forget it (the next call of thread ``key`` starts one)."""
    with _CHILDREN_LOCK:
        if _CHILDREN.get(key) is child:
            del _CHILDREN[key]
    child.stop()


def stop_budget_processes() -> int:
    """Kill every budget process of this process (a task running in one then returns
    :class:`Failure`); returns how many. Run on each Dask worker by :meth:`DaskExecutor.close`."""
    with _CHILDREN_LOCK:
        kids = list(_CHILDREN.values())
        _CHILDREN.clear()
    for c in kids:
        c.stop()
    return len(kids)


# ----------------------------------------------------------------------------- Dask

class DaskExecutor(Executor):
    """Jobs as tasks of a ``dask.distributed`` cluster, with the pool's hard time budget.

    Parameters
    ----------
    client : dask.distributed.Client or str
        A client, or the scheduler address (``tcp://host:8786``) to connect to.
    window : int, optional
        Tasks in flight (default ``4 *`` the cluster's threads).

    Notes
    -----
    The workers must see the same file system as this process (they write the output files
    and the spool); ``lod2energy`` must be importable on them. With a ``timeout`` each task
    is :func:`run_with_budget`: the job runs in a persistent ``python`` subprocess of the Dask
    worker thread (started with ``subprocess``, so it works in daemonic worker processes,
    ``LocalCluster(processes=True)``, and in worker threads of this process,
    ``processes=False``); at ``timeout`` s of its CPU time (or ``WALL_FACTOR`` times that of
    wall time) it is killed and reaped, the task returns :class:`Overrun` and the thread goes
    on with the next task. The budget counts from the moment the job starts on its worker,
    not from its submission. Without a ``timeout`` the job runs in the worker thread itself.
    :meth:`close` stops the budget processes on every worker (left idle, they exit with their
    worker process).
    """

    def __init__(self, client, window: int | None = None):
        try:
            from dask.distributed import Client
        except ImportError as e:  # pragma: no cover - the dask extra missing
            raise ParameterError("--dask needs dask.distributed: pip install 'lod2energy[dask]'") from e
        self._own = isinstance(client, str)
        self.client = Client(client) if self._own else client
        try:
            threads = sum(self.client.nthreads().values())
        except Exception:  # noqa: BLE001
            threads = 1
        self.jobs = max(1, threads)
        self.window = int(window or 4 * self.jobs)
        self._pending: deque = deque()  # futures submitted and not yet yielded

    def map(self, fn, args, timeout=None, tail=None):
        it = iter(args)
        queue = self._pending = deque()  # (arg, future)
        budget = float(timeout) if timeout is not None and timeout > 0 else None
        exhausted = False
        while True:
            while not exhausted and len(queue) < self.window:
                try:
                    arg = next(it)
                except StopIteration:
                    exhausted = True
                    break
                queue.append((arg, self.client.submit(run_with_budget, fn, arg, budget, pure=False)))
            if not queue:
                return
            arg, fut = queue.popleft()
            try:
                res = fut.result()  # the task enforces the budget itself
            except Exception as e:  # noqa: BLE001 - the task raised or its worker was lost
                res = Failure(_one_line(e))
            yield arg, res

    def close(self, kill: bool = False) -> None:
        pending = [f for _, f in self._pending]
        self._pending = deque()
        try:
            if pending:
                self.client.cancel(pending)
            self.client.run(stop_budget_processes)  # idle ones would exit with their worker
        except Exception:  # noqa: BLE001 - a cluster already gone
            pass
        if self._own:
            try:
                self.client.close()
            except Exception:  # noqa: BLE001
                pass
            self._own = False


def make_executor(jobs: int | None = None, dask=None) -> Executor:
    """The executor for ``--jobs`` / ``--dask``: Dask when ``dask`` (a Client or an address)
    is given, in-process for ``jobs == 1``, else a process pool of ``jobs`` (None: all cores)."""
    if dask is not None:
        return DaskExecutor(dask)
    n = default_jobs() if jobs is None or jobs <= 0 else int(jobs)
    return InProcessExecutor() if n == 1 else ProcessPoolExecutor(n)

