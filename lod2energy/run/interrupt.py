"""Exit codes and interruptions: SIGTERM ends a command as SIGINT does, and an export finishes
its report with what is done (exit codes 130 / 143)."""
from __future__ import annotations

import signal
import threading

EXIT_OK, EXIT_INVALID, EXIT_UNUSABLE = 0, 1, 2
EXIT_SIGINT, EXIT_SIGTERM = 130, 143


class Interrupted(BaseException):
    """SIGTERM (or SIGINT) arrived: finish the report with what is done."""

    def __init__(self, name: str, code: int):
        super().__init__(name)
        self.name, self.code = name, code


class Signals:
    """While active (main thread only), SIGTERM raises :class:`Interrupted` and SIGINT
    :class:`KeyboardInterrupt`; the previous handlers come back on exit."""

    def __enter__(self):
        self._old = None
        if threading.current_thread() is threading.main_thread():
            def term(signum, frame):
                raise Interrupted("SIGTERM", EXIT_SIGTERM)
            self._old = signal.signal(signal.SIGTERM, term)
        return self

    def __exit__(self, *exc):
        if self._old is not None:
            signal.signal(signal.SIGTERM, self._old)
        return False
