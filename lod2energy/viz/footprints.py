"""Plan footprints: a building's outline on the report page's plan (:func:`plan_footprint`), and
those of a whole file kept out of memory while the page is written (:class:`FootprintSpill`)."""
from __future__ import annotations

import os
import struct
import tempfile
from typing import Iterable, Iterator

import numpy as np

from lod2energy.io.seen_ids import id_key
from lod2energy.viz.render import footprint

#: A building with more faces gets a panel of text only: drawing (and re-validating) it would
#: cost more than the rest of the page (a 100,000-face mesh that timed out, say).
MAX_PANEL_FACES = 5000


def n_faces(b) -> int:
    """Polygons of the polygonal geometries of building ``b`` (0 for None)."""
    return 0 if b is None else sum(g.n_surfaces for o in b.objects for g in o.geometries if g.is_polygonal)


def _hull(b) -> list[np.ndarray]:
    """The plan's footprint of a building over ``MAX_PANEL_FACES`` faces: the convex hull of its
    vertices projected on the ground, ``[(k, 2) float, m]``."""
    from scipy.spatial import ConvexHull
    pts = np.asarray(b.vertices, dtype=float)[:, :2]
    return [pts[ConvexHull(pts).vertices]]


def plan_footprint(b) -> list[np.ndarray]:
    """The footprint of building ``b`` on the plan view, ``[(k, 2) float, m]``: its ground faces
    (:func:`lod2energy.viz.render.footprint`), or for a mesh over ``MAX_PANEL_FACES`` faces (one
    that timed out, say) the convex hull of its vertices; empty when it cannot be drawn."""
    try:
        return footprint(b) if n_faces(b) <= MAX_PANEL_FACES else _hull(b)
    except Exception:  # noqa: BLE001 - a building whose footprint cannot be drawn is left off the plan
        return []


def drawable(rings) -> list[np.ndarray]:
    """The rings of a footprint that can be drawn: ``(k, 2)`` float64, ``k >= 1``, finite."""
    out = []
    for r in rings:
        a = np.ascontiguousarray(np.asarray(r, dtype="<f8").reshape(len(r), -1)[:, :2]) if len(r) else None
        if a is not None and a.shape[1] == 2 and np.isfinite(a).all():
            out.append(a)
    return out


class FootprintSpill:
    """Plan footprints of a large file, kept in an unnamed scratch file as they are read and
    given back in the same order: nothing per building stays in memory. Without a scratch file
    (it cannot be made, or the disk fills) they stay in memory.

    Parameters
    ----------
    scratch_dir : str, optional
        Folder of the scratch file (the output folder: nothing is written elsewhere, and the
        file has no name, so nothing is left behind).
    """

    _HEAD = struct.Struct("<qI")
    #: Bytes read at a time when the footprints are given back.
    READ = 1 << 18

    def __init__(self, scratch_dir: str | None = None):
        self.n = 0
        self.lo, self.hi = np.full(2, np.inf), np.full(2, -np.inf)
        self._mem: list[tuple[int, list[np.ndarray]]] | None = None
        try:
            self._f = tempfile.TemporaryFile(dir=scratch_dir)
        except OSError:
            self._f, self._mem = None, []

    def add(self, id: str, rings: list[np.ndarray]) -> None:
        """Keep the footprint of building ``id`` (``[(k, 2) float]``, m)."""
        rings = drawable(rings)
        k = id_key(id)
        for r in rings:
            self.lo = np.minimum(self.lo, r.min(axis=0))
            self.hi = np.maximum(self.hi, r.max(axis=0))
        self.n += 1
        if self._f is not None:
            rec = (self._HEAD.pack(k, len(rings)) + np.array([len(r) for r in rings], "<u4").tobytes()
                   + b"".join(r.tobytes() for r in rings))
            try:
                self._f.write(rec)
                return
            except OSError:  # a full disk: what is written comes back to memory
                self._f.seek(0)
                self._mem = [(k_, r_) for k_, r_, _ in self._records(self._f.read())]
                self._f.close()
                self._f = None
        self._mem.append((k, rings))

    def _records(self, data: bytes) -> Iterator[tuple[int, list[np.ndarray], int]]:
        """The whole records at the start of ``data``: ``(key, rings, offset past it)``."""
        pos, end = 0, len(data)
        while pos + self._HEAD.size <= end:
            k, m = self._HEAD.unpack_from(data, pos)
            q = pos + self._HEAD.size
            if q + 4 * m > end:
                return
            lens = np.frombuffer(data, "<u4", m, q).astype(np.int64)
            q += 4 * m
            if q + 16 * int(lens.sum()) > end:
                return
            rings = []
            for n in lens:
                rings.append(np.frombuffer(data, "<f8", 2 * int(n), q).reshape(-1, 2))
                q += 16 * int(n)
            yield k, rings, q
            pos = q

    def __iter__(self) -> Iterator[tuple[int, list[np.ndarray]]]:
        """``(key of the id, rings)`` in the order they were added."""
        if self._f is None:
            yield from self._mem
            return
        self._f.flush()
        self._f.seek(0)
        rest = b""
        try:
            while True:
                chunk = self._f.read(self.READ)
                if not chunk:
                    return
                data = rest + chunk
                pos = 0
                for k, rings, pos in self._records(data):
                    yield k, rings
                rest = data[pos:]
        finally:
            self._f.seek(0, os.SEEK_END)

    def by_id(self, ids: Iterable[str]) -> dict[str, list[np.ndarray]]:
        """The footprints of ``ids`` (those held), by id: for a page small enough to keep them."""
        of = {id_key(i): i for i in ids}
        return {of[k]: rings for k, rings in self if k in of}

    def close(self) -> None:
        if self._f is not None:
            self._f.close()
            self._f = None
        self._mem = None
