"""The package's logger, ``logging.getLogger("lod2energy")``, and the CLI's console handler.

Library code logs errors, warnings and notes (INFO) to this logger; a caller who configures
nothing sees warnings and errors on stderr (logging's last resort). The CLI installs
:func:`console`, which writes each record as one ``lod2energy: <kind>: <message>`` line on
stderr at INFO, or DEBUG with ``-v``.
"""
from __future__ import annotations

import logging
import sys

log = logging.getLogger("lod2energy")

_KIND = {logging.DEBUG: "debug", logging.INFO: "note", logging.WARNING: "warning", logging.ERROR: "error",
         logging.CRITICAL: "error"}


class _Console(logging.Handler):
    """One line per record on the current ``sys.stderr`` (looked up at each record)."""

    def emit(self, record: logging.LogRecord) -> None:
        try:
            kind = _KIND.get(record.levelno, record.levelname.lower())
            sys.stderr.write(f"lod2energy: {kind}: {record.getMessage()}\n")
            sys.stderr.flush()
        except Exception:  # noqa: BLE001 - logging never raises into the caller
            self.handleError(record)


def console(verbose: bool = False) -> None:
    """Install the CLI's console handler (once) and set the level: INFO (notes, warnings,
    errors: what the CLI printed before it logged, ``-q`` included), DEBUG with ``verbose``."""
    if not any(isinstance(h, _Console) for h in log.handlers):
        log.addHandler(_Console())
    log.setLevel(logging.DEBUG if verbose else logging.INFO)
