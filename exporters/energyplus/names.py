"""IDF-safe object names and comments: every string from the input is sanitised before it reaches the IDF.

Names keep ``[A-Za-z0-9_.-]`` only, are unique case-insensitively (EnergyPlus compares names
without case) and at most 100 characters; ids in comments are JSON-escaped on one line.
"""
from __future__ import annotations

import json
import re

from lod2energy.exporters.paths import _short_hash


_IDF_NAME_BAD = re.compile(r"[^A-Za-z0-9_.-]+")


class NameRegistry:
    """Unique, IDF-safe object names (case-insensitive uniqueness, bounded length)."""

    def __init__(self):
        self._used: set[str] = set()

    def name(self, text: str, max_len: int = 60) -> str:
        """Sanitised unique name for ``text``: ``[A-Za-z0-9_.-]``, at most ``max_len`` chars."""
        text = str(text)
        base = _IDF_NAME_BAD.sub("_", text).strip("_") or "x"
        changed = base != text or len(base) > max_len
        if changed:
            base = f"{base[:max_len - 9]}_{_short_hash(text)}"
        n, k = base, 1
        while n.lower() in self._used:
            suffix = f"_{k}"
            n = base[:max_len - len(suffix)] + suffix
            k += 1
        self._used.add(n.lower())
        return n


def sanitize_name(text: str, max_len: int = 100) -> str:
    """One IDF-safe name (no uniqueness): see :class:`NameRegistry`."""
    return NameRegistry().name(text, max_len)


def comment_text(text: str, max_len: int = 200) -> str:
    """A string safe inside an IDF ``!`` comment: JSON-escaped, one line, ASCII."""
    s = json.dumps(str(text), ensure_ascii=True)
    return s if len(s) <= max_len else s[:max_len - 4] + '..."'
