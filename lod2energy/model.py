"""Core immutable types: Surface, Shell, Solid, Geometry, CityObject, Building, CityModel.

One :class:`Building` (a first-level CityObject together with its descendants, e.g. a
Building with its BuildingParts, as a CityJSONFeature holds it) flows through every stage.
Stages never mutate it; they return a new one built with :func:`dataclasses.replace`.

Vertex indices in rings refer to ``Building.vertices`` (a feature-local array), so that a
building can be processed, parallelised and written on its own.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from collections.abc import Mapping
from typing import Any, Iterator

import numpy as np

SOLID_TYPES = ("Solid",)
MULTISOLID_TYPES = ("MultiSolid", "CompositeSolid")
SURFACE_TYPES = ("MultiSurface", "CompositeSurface")
POLYGONAL_TYPES = SOLID_TYPES + MULTISOLID_TYPES + SURFACE_TYPES
BUILDING_TYPES = ("Building", "BuildingPart")

_EMPTY: Mapping[str, Any] = MappingProxyType({})


def frozen_mapping(d: Mapping[str, Any] | None) -> Mapping[str, Any]:
    """Read-only view of ``d`` (``{}`` for None)."""
    if d is None:
        return _EMPTY
    if isinstance(d, MappingProxyType):
        return d
    return MappingProxyType(dict(d))


def _ring_array(ring) -> np.ndarray:
    a = np.asarray(ring, dtype=np.intp)
    a.setflags(write=False)
    return a


@dataclass(frozen=True, eq=False)
class Surface:
    """A polygon: outer ring first, then inner rings (holes).

    Parameters
    ----------
    rings : tuple of (k,) int arrays
        Vertex indices into the owning building's ``vertices``; rings are open (the first
        vertex is not repeated at the end), as in CityJSON.
    semantic : int or None
        Index into the owning geometry's ``semantic_surfaces``.
    """

    rings: tuple[np.ndarray, ...]
    semantic: int | None = None

    @staticmethod
    def from_lists(rings, semantic: int | None = None) -> "Surface":
        return Surface(tuple(_ring_array(r) for r in rings), semantic)

    @property
    def outer(self) -> np.ndarray:
        return self.rings[0]

    @property
    def inners(self) -> tuple[np.ndarray, ...]:
        return self.rings[1:]

    def to_lists(self) -> list[list[int]]:
        return [r.tolist() for r in self.rings]


@dataclass(frozen=True, eq=False)
class Shell:
    """A set of surfaces meant to bound a volume (or a plain surface set for Multi/CompositeSurface)."""

    surfaces: tuple[Surface, ...]


@dataclass(frozen=True, eq=False)
class Solid:
    """Exterior shell first, then interior shells (cavities)."""

    shells: tuple[Shell, ...]

    @property
    def exterior(self) -> Shell:
        return self.shells[0]


@dataclass(frozen=True, eq=False)
class Geometry:
    """One CityJSON geometry of a CityObject.

    Parameters
    ----------
    type : str
        CityJSON geometry type ("Solid", "MultiSolid", "CompositeSolid", "MultiSurface",
        "CompositeSurface", "MultiPoint", "MultiLineString", "GeometryInstance").
    lod : str or None
        Level of detail as a string ("2", "2.2"); None when the input has none.
    solids : tuple of Solid
        "Solid": one; "MultiSolid"/"CompositeSolid": one per member; surface types: one
        pseudo-solid with one shell holding every surface. Empty for other types.
    semantic_surfaces : tuple of mapping
        CityJSON ``semantics.surfaces`` (type, attributes, parent/children kept as given).
    raw : mapping or None
        The input JSON for types not modelled as polygons (points, lines, instances), with
        vertex indices already feature-local.
    extra : mapping
        Other keys of the input geometry (``texture``, ``material``), written back as they
        are; a stage that changes the boundaries builds a new Geometry without them.
    """

    type: str
    lod: str | None
    solids: tuple[Solid, ...] = ()
    semantic_surfaces: tuple[Mapping[str, Any], ...] = ()
    raw: Mapping[str, Any] | None = None
    extra: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)

    @property
    def is_polygonal(self) -> bool:
        return self.type in POLYGONAL_TYPES

    @property
    def is_volumetric(self) -> bool:
        return self.type in SOLID_TYPES + MULTISOLID_TYPES

    def iter_shells(self) -> Iterator[tuple[int, int, Shell]]:
        """Yield ``(solid_index, shell_index, shell)``."""
        for si, solid in enumerate(self.solids):
            for hi, shell in enumerate(solid.shells):
                yield si, hi, shell

    def iter_surfaces(self) -> Iterator[tuple[int, int, int, Surface]]:
        """Yield ``(solid_index, shell_index, face_index, surface)``."""
        for si, hi, shell in self.iter_shells():
            for fi, s in enumerate(shell.surfaces):
                yield si, hi, fi, s

    @property
    def n_surfaces(self) -> int:
        return sum(len(sh.surfaces) for _, _, sh in self.iter_shells())

    def semantic_type(self, surface: Surface) -> str | None:
        """Semantic type name ("RoofSurface", ...) of ``surface``, or None."""
        if surface.semantic is None or surface.semantic >= len(self.semantic_surfaces):
            return None
        return self.semantic_surfaces[surface.semantic].get("type")

    def location(self, geom_index: int, solid: int | None = None, shell: int | None = None,
                 face: int | None = None) -> str:
        """val3dity location string without the ``coid`` part, e.g. ``geom=0|shell=0|face=3``."""
        parts = [f"geom={geom_index}"]
        if self.type in MULTISOLID_TYPES:
            parts.append(f"solid={'' if solid is None else solid}")
        if self.type in SOLID_TYPES + MULTISOLID_TYPES:
            parts.append(f"shell={'' if shell is None else shell}")
        parts.append(f"face={'' if face is None else face}")
        return "|".join(parts)


def lod_key(lod: str | None) -> float:
    """Sortable number of a LoD string ("2.2" -> 2.2); None and junk sort lowest."""
    try:
        return float(lod)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return -1.0


@dataclass(frozen=True, eq=False)
class CityObject:
    """One CityJSON CityObject (geometry parsed, everything else kept for round trips)."""

    id: str
    type: str
    geometries: tuple[Geometry, ...] = ()
    attributes: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)
    parents: tuple[str, ...] = ()
    children: tuple[str, ...] = ()
    extra: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)

    @property
    def lods(self) -> tuple[str, ...]:
        return tuple(sorted({g.lod for g in self.geometries if g.lod is not None}, key=lod_key))


@dataclass(frozen=True, eq=False)
class ShellRef:
    """A shell of a building located as val3dity locates it."""

    object_id: str
    geom_index: int
    solid_index: int
    shell_index: int
    geometry: Geometry
    shell: Shell

    def location(self, face: int | None = None) -> str:
        loc = self.geometry.location(self.geom_index, self.solid_index, self.shell_index, face)
        return f"coid={self.object_id}|{loc}"


@dataclass(frozen=True, eq=False)
class Building:
    """A first-level CityObject with its descendants (a feature), with its own vertices.

    Parameters
    ----------
    id : str
        Id of the first-level CityObject.
    type : str
        Its CityJSON type ("Building", "Bridge", "TINRelief", ...).
    vertices : (n, 3) float
        Real-world coordinates (transform applied), metres in the input CRS.
    objects : tuple of CityObject
        ``objects[0]`` is the first-level object; the others are its descendants.
    provenance : mapping
        What the stages did (repair step, metrics, ...).
    """

    id: str
    type: str
    vertices: np.ndarray
    objects: tuple[CityObject, ...]
    provenance: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)

    def __post_init__(self):
        v = np.asarray(self.vertices, dtype=np.float64).reshape(-1, 3)
        if v.flags.writeable:
            v = v.copy()
            v.setflags(write=False)
        object.__setattr__(self, "vertices", v)

    @property
    def root(self) -> CityObject:
        return self.objects[0]

    @property
    def is_building(self) -> bool:
        return self.type == "Building"

    @functools.cached_property
    def object_index(self) -> Mapping[str, CityObject]:
        return MappingProxyType({o.id: o for o in self.objects})

    @functools.cached_property
    def envelope_objects(self) -> tuple[CityObject, ...]:
        """Objects whose geometry forms the envelope: for a Building, itself and its
        BuildingParts (not installations or other descendants); otherwise every object."""
        if self.type in BUILDING_TYPES:
            return tuple(o for o in self.objects if o.type in BUILDING_TYPES)
        return self.objects

    @functools.cached_property
    def lods(self) -> tuple[str, ...]:
        """LoDs present on the envelope objects' polygonal geometries, lowest first."""
        s = {g.lod for o in self.envelope_objects for g in o.geometries if g.is_polygonal and g.lod is not None}
        return tuple(sorted(s, key=lod_key))

    def default_lod(self) -> str | None:
        """Highest LoD >= 2 present, else the highest LoD, else None."""
        if not self.lods:
            return None
        return self.lods[-1]

    def envelope(self, lod: str | None = None) -> list[tuple[CityObject, int, Geometry]]:
        """The geometries that describe the building's envelope at ``lod``: the one choice.

        One ``(object, geom_index, geometry)`` per envelope object (the Building and its
        BuildingParts, see :attr:`envelope_objects`) that has a polygonal geometry at ``lod``
        (default :meth:`default_lod`): a volumetric (Solid-type) one first, since it describes
        the envelope better than a surface set; among several of the same kind the one with
        the most surfaces, then the first.
        """
        lod = lod if lod is not None else self.default_lod()
        out = []
        for o in self.envelope_objects:
            cands = [(gi, g) for gi, g in enumerate(o.geometries) if g.is_polygonal and g.lod == lod]
            if cands:
                gi, g = min(cands, key=lambda c: (not c[1].is_volumetric, -c[1].n_surfaces, c[0]))
                out.append((o, gi, g))
        return out

    def shells(self, lod: str | None = None, exterior_only: bool = True) -> list[ShellRef]:
        """Shells of the envelope at ``lod`` (see :meth:`envelope`)."""
        refs = []
        for o, gi, g in self.envelope(lod):
            for si, hi, sh in g.iter_shells():
                if exterior_only and hi > 0:
                    continue
                refs.append(ShellRef(o.id, gi, si, hi, g, sh))
        return refs

    def all_shells(self) -> list[ShellRef]:
        """Every shell of every polygonal geometry of every object (what val3dity checks)."""
        refs = []
        for o in self.objects:
            for gi, g in enumerate(o.geometries):
                if not g.is_polygonal:
                    continue
                for si, hi, sh in g.iter_shells():
                    refs.append(ShellRef(o.id, gi, si, hi, g, sh))
        return refs

    def replace_geometry(self, object_id: str, geom_index: int, geometry: Geometry,
                         vertices: np.ndarray | None = None) -> "Building":
        """New building with one geometry swapped (and optionally a new vertex array)."""
        objs = []
        for o in self.objects:
            if o.id == object_id:
                geoms = list(o.geometries)
                geoms[geom_index] = geometry
                o = replace(o, geometries=tuple(geoms))
            objs.append(o)
        return replace(self, objects=tuple(objs),
                       vertices=self.vertices if vertices is None else vertices)

    def with_provenance(self, **kw) -> "Building":
        p = dict(self.provenance)
        p.update(kw)
        return replace(self, provenance=frozen_mapping(p))


@dataclass(frozen=True)
class FeatureError:
    """A feature (or the whole file) that could not be read: reported, never raised.

    Parameters
    ----------
    id : str or None
        CityObject id, or None for a file-level problem.
    code : int
        val3dity code (901 INVALID_INPUT_FILE, 902 EMPTY_PRIMITIVE, 904 FORMAT_NOT_SUPPORTED).
    message : str
        One line for the user.
    type : str
        CityObject type when known.
    """

    id: str | None
    code: int
    message: str
    type: str = ""


@dataclass(frozen=True, eq=False)
class CityModel:
    """File-level CityJSON data other than the CityObjects (kept for round trips).

    Parameters
    ----------
    version : str
        CityJSON version of the input ("1.0", "1.1", "2.0"), or the mesh format for
        non-CityJSON inputs.
    transform : mapping or None
        Input ``transform`` (scale, translate), reused on write.
    metadata, extensions, appearance, geometry_templates, extra : mapping
        As in the input; ``extra`` holds other root properties.
    source : str
        Path of the input.
    format : str
        "CityJSON", "CityJSONSeq", "POLY", "OBJ", "OFF", ...
    frame : LocalFrame or None
        For a geographic CRS (degrees): the local metric frame the buildings' vertices were
        moved into on reading (:mod:`lod2energy.geodesy`); writers move them back.
    """

    version: str = "2.0"
    transform: Mapping[str, Any] | None = None
    metadata: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)
    extensions: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)
    appearance: Mapping[str, Any] | None = None
    geometry_templates: Mapping[str, Any] | None = None
    extra: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)
    source: str = ""
    format: str = "CityJSON"
    frame: Any = None

    @property
    def crs(self) -> str | None:
        md = self.metadata or {}
        return md.get("referenceSystem") or md.get("crs", {}).get("epsg") if isinstance(md, Mapping) else None
