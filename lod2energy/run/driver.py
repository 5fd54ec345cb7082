"""The one driver of every command: a command is a declared list of stages (:class:`Command`),
and :func:`execute` runs them in order over one :class:`Run`.

The commands declare themselves where their work lives: ``validate`` in
:mod:`lod2energy.validate_files`, ``repair`` in :mod:`lod2energy.repair_file`, ``export`` in
:mod:`lod2energy.pipeline`, ``view`` in :mod:`lod2energy.viz.view`, the CFD case in
:mod:`lod2energy.cfd.__main__`. :func:`drive` is the command line's side: the logger's level,
one BLAS thread, SIGTERM as SIGINT, one line and an exit code for every error, the time taken.
"""
from __future__ import annotations

import argparse
import sys
import tempfile
import time
from contextlib import ExitStack
from dataclasses import dataclass, field
from typing import Any, Callable

from lod2energy.errors import Lod2EnergyError
from lod2energy.logs import console, log
from lod2energy.run.blas_threads import one_blas_thread
from lod2energy.run.interrupt import EXIT_OK, EXIT_INVALID, EXIT_SIGINT, EXIT_UNUSABLE, Interrupted, Signals
from lod2energy.safe_write import UnsafeWriteError


def no_writers(args: argparse.Namespace) -> tuple[str, ...]:
    """The writers of a command that writes through no registered writer."""
    return ()


@dataclass(frozen=True)
class Command:
    """A command: its stages, each a function of the :class:`Run`, called in order, and the
    registered writers (:mod:`lod2energy.exporters.registry`) it needs for given arguments."""

    name: str
    stages: tuple[Callable[["Run"], None], ...]
    writers: Callable[[argparse.Namespace], tuple[str, ...]] = no_writers


class _Stop(Exception):
    """Raised by :meth:`Run.stop`: the stages after this one are skipped."""


@dataclass
class Run:
    """What the stages of one command share: the parsed arguments, the writers, the exit code
    so far and what each stage made (``made``, by the names the command's module documents)."""

    args: argparse.Namespace
    writers: tuple[str, ...] = ()
    code: int = EXIT_OK
    made: dict[str, Any] = field(default_factory=dict)
    _cleanup: ExitStack = field(default_factory=ExitStack, repr=False)

    def worse(self, code: int) -> None:
        """Raise the exit code to ``code`` (0 < 1 < 2)."""
        self.code = max(self.code, code)

    def stop(self, code: int) -> None:
        """End the command now with exit code ``code`` (its messages are logged already)."""
        self.code = code
        raise _Stop

    def scratch(self) -> str:
        """A temporary folder, removed when the command ends (standard input is written there)."""
        return self._cleanup.enter_context(tempfile.TemporaryDirectory(prefix="lod2energy-stdin-"))


def execute(command: Command, args: argparse.Namespace) -> Run:
    """Load the writers of ``command``, run its stages over ``args``; the :class:`Run` holds the
    exit code and what the stages made. Errors propagate (:func:`drive` turns them into exit codes)."""
    run = Run(args, command.writers(args))
    if run.writers:  # loaded (seconds) before a stage writes: a signal after that finds what it needs
        from lod2energy.exporters.registry import writers
        writers(run.writers)
    with run._cleanup:
        try:
            for stage in command.stages:
                stage(run)
        except _Stop:
            pass
    return run


def progress(quiet: bool, desc: str, total: int | None = None, unit: str = " buildings"):
    """``(tick, close)`` of a progress bar on stderr (no-ops when ``quiet``); with ``total`` it
    shows the share done and an ETA. ``tick`` takes any arguments and ignores them."""
    if quiet:
        return lambda *_: None, lambda: None
    from tqdm import tqdm
    bar = tqdm(desc=desc, unit=unit, file=sys.stderr, disable=None, leave=False, total=total)
    return (lambda *_: bar.update(1)), bar.close


def drive(command: Command, args: argparse.Namespace) -> int:
    """Run ``command`` for the command line: the exit code (0, 1, 2; 130 / 143 when interrupted),
    every error one ``lod2energy: error:`` line, "done in" on stderr unless ``-q``."""
    console(getattr(args, "verbose", False))
    t0 = time.perf_counter()
    one_blas_thread()  # parallel across buildings, not inside one
    try:
        with Signals():  # SIGTERM ends every command as ^C does: one line, exit 143
            code = execute(command, args).code
    except Interrupted as e:
        log.error("interrupted by %s", e.name)
        return e.code
    except UnsafeWriteError as e:  # an output that is an input, a link, outside OUTDIR
        log.error("%s", e)
        return EXIT_UNUSABLE
    except Lod2EnergyError as e:
        log.error("%s", e)
        return EXIT_UNUSABLE if 900 <= e.code < 950 else EXIT_INVALID
    except KeyboardInterrupt:
        log.error("interrupted")
        return EXIT_SIGINT
    except OSError as e:
        log.error("%s: %s", e.filename or "", e.strerror)
        return EXIT_UNUSABLE
    if not getattr(args, "quiet", False):
        print(f"done in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    return code
