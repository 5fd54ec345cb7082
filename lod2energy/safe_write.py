"""The one path by which every command writes a file: inside its folder, atomically, never over an input.

Every file lod2energy writes (reports, IDF, STL, CityJSON, sidecars, extension files, HTML)
goes through :func:`atomic_write` (or :func:`write_text` / :func:`write_bytes` /
:func:`write_json` over it):

- the target is checked first (:func:`check_target`): it must not be one of the command's
  inputs, must not be a symbolic link, and must stay inside ``root`` (the command's OUTDIR)
  once every link of its folder is resolved;
- the content goes to a temporary file in the target's folder whose name is unique per
  process and call (``.<name>.<pid>.<n>.part``, created with ``O_EXCL | O_NOFOLLOW``), is
  flushed and fsync'ed, then renamed over the target (``os.replace``, atomic on POSIX);
- on any exception (a full disk, a signal, a failed self-check raised by the caller) the
  temporary is removed and nothing is left under the target's name.

A file that was written but then failed its self-check is moved aside by
:func:`set_aside` to ``<name>.invalid`` (or removed), so that a bad file never keeps the
name of a good one.
"""
from __future__ import annotations

import contextlib
import itertools
import json
import os
import re
import sys
from pathlib import Path
from typing import IO, Any, Callable, Iterable, Iterator

from lod2energy.errors import Lod2EnergyError

#: Suffix of a file kept after it failed its self-check.
INVALID_SUFFIX = ".invalid"
_COUNTER = itertools.count()


class UnsafeWriteError(Lod2EnergyError, PermissionError):
    """A write that would overwrite an input, follow a link or leave the output folder (usage error, 903)."""

    code = 903


def _same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.abspath(a) == os.path.abspath(b)


def check_target(path: str | os.PathLike, root: str | os.PathLike | None = None,
                 inputs: Iterable[str | os.PathLike] = ()) -> Path:
    """The absolute target path, or :class:`UnsafeWriteError` when writing it would be unsafe.

    Parameters
    ----------
    path : path
        The file to be written.
    root : path, optional
        The folder every output must stay in (OUTDIR); its own links are resolved once, the
        target's folder must resolve inside it.
    inputs : iterable of path
        Files the command reads; none of them may be the target (also through a hard or
        symbolic link).
    """
    p = Path(os.path.abspath(path))
    for src in inputs:
        if src is not None and _same_file(p, Path(src)):
            raise UnsafeWriteError(f"refusing to write {p}: it is an input of this command")
    if p.is_symlink():
        raise UnsafeWriteError(f"refusing to write {p}: it is a symbolic link")
    if p.exists() and not p.is_file():
        raise UnsafeWriteError(f"refusing to write {p}: it exists and is not a regular file")
    if root is not None:
        r = Path(root).resolve()
        parent = p.parent.resolve()
        if parent != r and r not in parent.parents:
            raise UnsafeWriteError(f"refusing to write {p}: outside the output folder {r}")
    return p


def _temp_for(p: Path) -> tuple[Path, int]:
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
    while True:
        tmp = p.with_name(f".{p.name}.{os.getpid()}.{next(_COUNTER)}.part")
        try:
            return tmp, os.open(tmp, flags, 0o644)
        except FileExistsError:  # left by a killed process with a recycled pid
            continue
        except BaseException:  # a signal between the open and the return: the name is ours alone
            with contextlib.suppress(OSError):
                os.unlink(tmp)
            raise


_TEMP_NAME = re.compile(r"^\..+\.(\d+)\.\d+\.(part|staged|tmp\.json|tmp\.jsonl)$")


def sweep_stale(folder: str | os.PathLike) -> list[str]:
    """Remove the temporaries (``.<name>.<pid>.<n>.part`` / ``.staged``) that processes no longer
    running left in ``folder`` (a run killed mid-write); returns their names. Never follows a link."""
    removed = []
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return removed
    for e in entries:
        m = _TEMP_NAME.match(e.name)
        if not m or e.is_symlink() or not e.is_file(follow_symlinks=False):
            continue
        pid = int(m.group(1))
        if pid == os.getpid():
            continue
        try:
            os.kill(pid, 0)
            continue  # still running: its own file
        except ProcessLookupError:
            pass
        except PermissionError:
            continue
        with contextlib.suppress(OSError):
            os.unlink(e.path)
            removed.append(e.name)
    return removed


@contextlib.contextmanager
def atomic_write(path: str | os.PathLike, mode: str = "w", *, root: str | os.PathLike | None = None,
                 inputs: Iterable[str | os.PathLike] = (), encoding: str | None = "utf-8",
                 errors: str | None = None, newline: str | None = None, fsync: bool = True,
                 sync_folder: bool | None = None) -> Iterator[IO]:
    """Open a temporary beside ``path`` for writing; rename it to ``path`` when the block ends.

    Parameters
    ----------
    path : path
        Final name.
    mode : {"w", "wb"}
    root, inputs :
        See :func:`check_target`.
    encoding, errors, newline :
        For text mode, as :func:`open`.
    fsync : bool
        fsync the file before the rename (and the folder after it), so that a crash leaves
        either the old file or the whole new one.
    sync_folder : bool, optional
        fsync the folder after the rename (default: as ``fsync``); False when a later write
        into the same folder syncs it (:func:`write_checked` after its final rename).

    Yields
    ------
    file object
        Write into it; when the block raises, the temporary is removed and ``path`` is untouched.
    """
    if mode not in ("w", "wb"):
        raise ValueError(f"atomic_write mode must be 'w' or 'wb', not {mode!r}")
    p = check_target(path, root, inputs)
    p.parent.mkdir(parents=True, exist_ok=True)
    tmp, fd = _temp_for(p)
    try:
        if mode == "wb":
            f = os.fdopen(fd, "wb")
        else:
            f = os.fdopen(fd, "w", encoding=encoding, errors=errors, newline=newline)
        with f:
            yield f
            f.flush()
            if fsync:
                os.fsync(f.fileno())
        check_target(p, root, inputs)  # nothing planted a link there while we wrote
        os.replace(tmp, p)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    if fsync if sync_folder is None else sync_folder:
        _sync_folder(p.parent)


def _sync_folder(folder: Path) -> None:
    """fsync a folder (its renames reach the disk); best effort."""
    with contextlib.suppress(OSError):
        dfd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(dfd)
        finally:
            os.close(dfd)


def write_text(path: str | os.PathLike, text: str, *, root=None, inputs=(), encoding: str = "utf-8",
               errors: str | None = None, fsync: bool = True, sync_folder: bool | None = None) -> Path:
    """Write ``text`` to ``path`` through :func:`atomic_write`; returns the path."""
    with atomic_write(path, "w", root=root, inputs=inputs, encoding=encoding, errors=errors, fsync=fsync,
                      sync_folder=sync_folder) as f:
        f.write(text)
    return Path(os.path.abspath(path))


def write_bytes(path: str | os.PathLike, data: bytes, *, root=None, inputs=(), fsync: bool = True) -> Path:
    """Write ``data`` to ``path`` through :func:`atomic_write`; returns the path."""
    with atomic_write(path, "wb", root=root, inputs=inputs, fsync=fsync) as f:
        f.write(data)
    return Path(os.path.abspath(path))


def json_default(o: Any) -> Any:
    """``json`` fallback for numpy scalars/arrays, mappings, sets and tuples."""
    try:
        import numpy as np
        if isinstance(o, np.generic):
            return o.item()
        if isinstance(o, np.ndarray):
            return o.tolist()
    except ImportError:  # pragma: no cover
        pass
    if hasattr(o, "items"):
        return dict(o.items())
    if isinstance(o, (set, frozenset, tuple)):
        return list(o)
    return str(o)


def write_json(path: str | os.PathLike, obj: Any, *, root=None, inputs=(), indent: int | None = 1,
               fsync: bool = True) -> Path:
    """Write ``obj`` as JSON (UTF-8, numpy-aware) through :func:`atomic_write`; returns the path."""
    with atomic_write(path, "w", root=root, inputs=inputs, fsync=fsync) as f:
        json.dump(obj, f, indent=indent, ensure_ascii=False, default=json_default)
    return Path(os.path.abspath(path))


def write_json_or_stdout(path: str | os.PathLike, obj: Any, *, inputs=()) -> Path | None:
    """:func:`write_json`, or with ``path`` ``-`` the JSON on standard output (then returns None)."""
    if str(path) == "-":
        json.dump(obj, sys.stdout, indent=1, ensure_ascii=False, default=json_default)
        sys.stdout.write("\n")
        sys.stdout.flush()
        return None
    return write_json(path, obj, inputs=inputs)


def set_aside(path: str | os.PathLike, keep: bool = True) -> str:
    """Move a file that failed its self-check away from its good name.

    Returns the new path (``<path>.invalid``) when ``keep``, else removes it and returns "".
    """
    p = Path(path)
    if not p.exists() or p.is_symlink():
        return ""
    if not keep:
        p.unlink()
        return ""
    bad = p.with_name(p.name + INVALID_SUFFIX)
    if bad.is_symlink():
        bad.unlink()
    os.replace(p, bad)
    return str(bad)


def write_checked(path: str | os.PathLike, write: Callable[[IO], None], check: Callable[[Path], list[str]],
                  mode: str = "w", *, root=None, inputs=(), keep_invalid: bool = True,
                  **open_kw) -> tuple[str, list[str]]:
    """Write through a temporary, self-check the temporary, and give it the good name only if it passes.

    Parameters
    ----------
    write : callable(file)
        Writes the content.
    check : callable(path) -> list of str
        The self-check, run on the written temporary; an empty list means it passed.
    keep_invalid : bool
        A file that fails is kept as ``<path>.invalid`` (True) or removed.

    Returns
    -------
    (final path, problems)
        ``final path`` is ``path`` when the check passed, ``path + ".invalid"`` or "" otherwise.
    """
    p = check_target(path, root, inputs)
    staged = p.with_name(f".{p.name}.{os.getpid()}.{next(_COUNTER)}.staged")
    # the folder is synced once, after the final rename (the staged name never needs to last)
    with atomic_write(staged, mode, root=root, inputs=inputs, sync_folder=False, **open_kw) as f:
        write(f)
    try:
        problems = list(check(staged))
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(staged)
        raise
    target = p if not problems else p.with_name(p.name + INVALID_SUFFIX)
    if problems and not keep_invalid:
        os.unlink(staged)
        return "", problems
    check_target(target, root, inputs)
    os.replace(staged, target)
    if problems and p.exists() and not p.is_symlink():
        p.unlink()  # an older good-looking file of this name would now be a lie
    if open_kw.get("fsync", True):
        _sync_folder(target.parent)
    return str(target), problems
