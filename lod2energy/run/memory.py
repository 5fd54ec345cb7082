"""Giving freed memory back to the system between the phases of a long process.

CPython frees its objects into glibc's heap, which keeps the pages when live objects are
scattered among them: a process that streamed 13,504 buildings keeps their high-water mark. The
one-file writers call :func:`give_back` between writing a file and re-reading it for the
self-check, so the self-check's reading does not stack on the writing's leftovers.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import gc

from lod2energy import cache


@cache.memoize("memory.malloc-trim", 1)
def _malloc_trim():
    name = ctypes.util.find_library("c")
    try:
        return getattr(ctypes.CDLL(name), "malloc_trim") if name else None
    except (OSError, AttributeError):  # not glibc (musl, macOS, Windows): nothing to trim
        return None


def give_back() -> bool:
    """Collect garbage and return the heap's free pages to the system (glibc ``malloc_trim``).

    Returns
    -------
    bool
        True when the C library could be asked (glibc), False elsewhere (nothing done but the
        garbage collection).
    """
    gc.collect()
    trim = _malloc_trim()
    if trim is None:
        return False
    trim(0)
    return True
