"""The neighbour index of ``export``'s second pass: for each building, the others whose box comes
within a halo (party walls, ``--shading``), as compressed rows that stay small at city scale."""
from __future__ import annotations

import numpy as np
import shapely


class Neighbours:
    """For the buildings of the neighbour pass (seqs ascending, ``(k,)`` int), the seqs of the
    others whose box comes within the halo of each one's own: compressed rows (``indptr``
    ``(k + 1,)``, ``indices`` into ``seqs``, int32), about 16 bytes a building and 4 a neighbour
    instead of a dict of lists of ints (54,016 buildings, halo 1 m: 1.0 MB of Python objects held,
    against 26.6 MB for the dict and the list of box tuples)."""

    def __init__(self, seqs: np.ndarray, indptr: np.ndarray, indices: np.ndarray):
        self.seqs, self.indptr, self.indices = seqs, indptr, indices

    def __len__(self) -> int:
        return len(self.seqs)

    def of(self, k: int) -> list[int]:
        """The neighbours of the ``k``-th building (seqs, ascending)."""
        return self.seqs[self.indices[self.indptr[k]:self.indptr[k + 1]]].tolist()


#: Buildings whose neighbours are looked up at once (bounds the pairs held with a large halo).
NEIGHBOUR_QUERY_CHUNK = 4096


def neighbours_within(seqs, boxes, halo: float, chunk: int | None = None) -> Neighbours:
    """For each building (``seqs`` ascending, ``(k,)`` int; ``boxes`` its record's box, ``(k, 6)``
    float, m), the seqs of the others whose box comes within ``halo`` (m) of its own, in input
    order: a spatial index over the boxes' plan views, queried ``chunk`` buildings at a time."""
    seqs = np.asarray(seqs, dtype=np.int64)
    boxes = np.asarray(boxes, dtype=np.float64).reshape(-1, 6)
    step = int(chunk or NEIGHBOUR_QUERY_CHUNK)
    if len(seqs) == 0:
        return Neighbours(seqs, np.zeros(1, np.int64), np.zeros(0, np.int32))
    tree = shapely.STRtree(shapely.box(boxes[:, 0], boxes[:, 1], boxes[:, 3], boxes[:, 4]))
    counts, parts = [], []
    for lo in range(0, len(seqs), step):
        b = boxes[lo:lo + step]
        i, j = tree.query(shapely.box(b[:, 0] - halo, b[:, 1] - halo, b[:, 3] + halo, b[:, 4] + halo))
        keep = j != i + lo
        i, j = i[keep], j[keep]
        order = np.lexsort((seqs[j], i))
        parts.append(j[order].astype(np.int32))
        counts.append(np.bincount(i, minlength=len(b)))
    indptr = np.zeros(len(seqs) + 1, dtype=np.int64)
    np.cumsum(np.concatenate(counts), out=indptr[1:])
    return Neighbours(seqs, indptr, np.concatenate(parts))


def _spread(x: np.ndarray) -> np.ndarray:
    """The 16 low bits of ``x`` (uint64) spread to the even bits (Morton code half)."""
    x = x & np.uint64(0xFFFF)
    for shift, mask in ((8, 0x00FF00FF), (4, 0x0F0F0F0F), (2, 0x33333333), (1, 0x55555555)):
        x = (x | (x << np.uint64(shift))) & np.uint64(mask)
    return x


def spatial_order(boxes) -> np.ndarray:
    """The order (indices, ``(k,)`` int) of the boxes (``(k, 6)`` float, m) along a Z-order
    (Morton) curve of their plan centres on a 65,536 x 65,536 grid over their extent, ties in
    input order: near boxes come near each other. The neighbour pass runs its jobs in this
    order (the same for every executor), so that the neighbours a job needs were often just
    needed by the jobs before it (:func:`lod2energy.exporters.energyplus.model._neighbour_zones`
    remembers the last 64 of a process); input order is often not spatial (Den Haag's is not:
    9 % of neighbours found again against 70 % in this order)."""
    b = np.asarray(boxes, dtype=np.float64).reshape(-1, 6)
    if len(b) == 0:
        return np.zeros(0, dtype=np.int64)
    c = (b[:, :2] + b[:, 3:5]) / 2
    c = np.where(np.isfinite(c), c, 0.0)
    span = float(np.ptp(c, axis=0).max()) or 1.0
    q = np.clip((c - c.min(axis=0)) / span * 65535.0, 0, 65535).astype(np.uint64)
    code = _spread(q[:, 0]) | (_spread(q[:, 1]) << np.uint64(1))
    return np.argsort(code, kind="stable")
