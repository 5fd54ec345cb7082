"""Where a writer may put a file: safe names inside the output folder, and failed files set aside.

A building id can hold anything (slashes, dots, control characters, names that differ only by
case): :func:`safe_stem` makes a file-name stem of it that stays inside the output folder and
never collides with another id's; :func:`output_path` refuses any name that would leave it.
"""
from __future__ import annotations

import hashlib
import re
from dataclasses import replace
from pathlib import Path

from lod2energy.errors import ExportError
from lod2energy.exporters.result import ExportResult
from lod2energy.safe_write import set_aside

_UNSAFE_FILE = re.compile(r"[^A-Za-z0-9._-]+")


def _short_hash(text: str, n: int = 8) -> str:
    return hashlib.sha1(text.encode("utf-8", "surrogatepass")).hexdigest()[:n]


def safe_stem(text: str, used: set[str] | None = None, max_len: int = 80) -> str:
    """File-name stem for an arbitrary id: ``[A-Za-z0-9._-]`` only, never hidden, unique.

    Any change (replaced characters, truncation) or a clash with ``used`` (compared
    case-insensitively, for case-insensitive file systems) appends a hash of the original,
    so two different ids never share a file. ``used`` is updated.
    """
    text = str(text)
    stem = _UNSAFE_FILE.sub("_", text).strip("._-") or "building"
    changed = stem != text or len(stem) > max_len
    stem = stem[:max_len]
    if changed:
        stem = f"{stem}_{_short_hash(text)}"
    if used is not None:
        base, k = stem, 1
        while stem.lower() in used:
            stem = f"{base}_{_short_hash(text + str(k))}"
            k += 1
        used.add(stem.lower())
    return stem


def output_path(outdir: str | Path, stem: str, suffix: str) -> Path:
    """``outdir/stem+suffix``, refusing any name that would leave ``outdir``.

    The name itself is not resolved: a link planted under it is refused when the file is
    written (:func:`lod2energy.safe_write.check_target`), for that file only.
    """
    root = Path(outdir).resolve()
    name = f"{stem}{suffix}"
    if "/" in name or "\\" in name or name in (".", "..") or "\0" in name:
        raise ExportError(f"refusing to write outside {root}: {stem!r}")
    return root / name


def not_written(e: OSError, what: str) -> str:
    """One line for a file that could not be written (full disk, refused link ...)."""
    return f"{what} not written: {e.strerror or e}" + (f" ({e.filename})" if e.filename else "")


def set_aside_failed(res: ExportResult) -> ExportResult:
    """``res`` with its file moved to ``<name>.invalid`` when it failed its self-check.

    A file that did not pass is never left under the name of a good one: the result's
    ``path`` becomes the ``.invalid`` name and a problem line says so.
    """
    if res.ok or not res.path or not Path(res.path).exists():
        return res
    bad = set_aside(res.path)
    note = f"failed its self-check: kept as {Path(bad).name}" if bad else "failed its self-check: removed"
    return replace(res, path=bad, ok=False, problems=tuple(res.problems) + (note,))

