"""The BuildingParts' solids as meshes, for the stages that keep parts apart (``repair/parts.py``).

Each part's mesh is built once per building state: :class:`PartMeshes` holds the Solid mesh of
the Building and of each of its parts at one LoD, and when a stage replaces one part it rebuilds
that part's mesh only, so that a building of ``n`` parts with ``k`` overlapping pairs costs
``n + k`` mesh builds, not ``n k``. The manifold3d solids the booleans use are made about one
origin per building state (the mean of all the parts' mesh vertices, as float32 coordinates).
"""
from __future__ import annotations

import manifold3d as m3d
import numpy as np

from lod2energy.model import Building, Geometry
from lod2energy.polymesh import PolyMesh, triangulate_mesh
from lod2energy.repair.convert import geometry_of_mesh, mesh_of_geometry

__all__ = ["PartMeshes", "part_mesh", "part_meshes", "solid_manifold", "with_part"]


def solid_manifold(m: PolyMesh, origin: np.ndarray):
    """manifold3d solid of the closed mesh ``m`` about ``origin`` ((3,) float, m), in float32;
    None when manifold3d rejects it."""
    tris, _ = triangulate_mesh(m)
    man = m3d.Manifold(m3d.Mesh(vert_properties=np.ascontiguousarray(m.vertices - origin, dtype=np.float32),
                                tri_verts=np.ascontiguousarray(tris, dtype=np.uint32)))
    return None if man.status() != m3d.Error.NoError else man


def part_mesh(b: Building, o, lod) -> tuple[int, Geometry, PolyMesh] | None:
    """``(geometry index, geometry, PolyMesh)`` of the first polygonal Solid of object ``o`` of
    ``b`` at ``lod``, None when it has none."""
    for gi, g in enumerate(o.geometries):
        if g.is_polygonal and g.lod == lod and g.type == "Solid" and g.solids:
            return gi, g, mesh_of_geometry(b.vertices, g)
    return None


def part_meshes(b: Building, lod) -> list[tuple]:
    """``(object, geom index, geometry, PolyMesh)`` of the Solid of the Building and each part at
    ``lod``, in the building's order (:attr:`Building.envelope_objects`)."""
    out = []
    for o in b.envelope_objects:
        found = part_mesh(b, o, lod)
        if found is not None:
            out.append((o, *found))
    return out


class PartMeshes:
    """The Solid meshes of a building's envelope objects at one LoD (:func:`part_meshes`), built
    once; :meth:`replaced` gives those of a building that differs in a few objects.

    Parameters
    ----------
    b : Building
    lod : str
    """

    def __init__(self, b: Building, lod, parts: dict | None = None):
        self.building, self.lod = b, lod
        self.parts: dict[str, tuple] = parts if parts is not None else {p[0].id: p for p in part_meshes(b, lod)}
        self._origin: np.ndarray | None = None

    def __len__(self) -> int:
        return len(self.parts)

    def mesh(self, object_id: str) -> PolyMesh | None:
        p = self.parts.get(object_id)
        return None if p is None else p[3]

    def replaced(self, b: Building, object_ids) -> PartMeshes:
        """The meshes of ``b``, a building that differs from this one only in the geometries of
        ``object_ids`` (their meshes are built again, in the building's order; the others kept)."""
        ids = set(object_ids)
        parts = {}
        for o in b.envelope_objects:
            if o.id not in ids:
                if o.id in self.parts:
                    parts[o.id] = (o, *self.parts[o.id][1:])
                continue
            found = part_mesh(b, o, self.lod)
            if found is not None:
                parts[o.id] = (o, *found)
        return PartMeshes(b, self.lod, parts)

    def origin(self) -> np.ndarray:
        """Mean of all the meshes' vertices ((3,) float, m): the origin of the booleans."""
        if self._origin is None:
            ms = [p[3].vertices for p in self.parts.values()]
            self._origin = np.vstack(ms).mean(axis=0) if ms else np.zeros(3)
        return self._origin


def with_part(b: Building, object_id: str, gi: int, g: Geometry, m: PolyMesh) -> Building:
    """``b`` with geometry ``gi`` of ``object_id`` replaced by the mesh ``m`` (new vertices appended)."""
    lookup = {(float(p[0]), float(p[1]), float(p[2])): i for i, p in enumerate(b.vertices)}
    extra: list = []
    ng = geometry_of_mesh(m, g, lookup, extra, len(b.vertices))
    V = np.vstack([b.vertices, np.asarray(extra).reshape(-1, 3)]) if extra else b.vertices
    return b.replace_geometry(object_id, gi, ng, vertices=V)
