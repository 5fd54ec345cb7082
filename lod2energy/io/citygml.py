"""Reader for CityGML 1.0 / 2.0 / 3.0 (GML 3.1.1 / 3.2) building tiles, building by building.

Elements are matched by local name, so any namespace prefix and any of the three CityGML
versions works. CityGML 3.0 is read as 2.0: its ``core:boundary`` is 2.0's ``boundedBy``,
``bldg:buildingPart`` / ``buildingInstallation`` are ``consistsOfBuildingPart`` /
``outerBuildingInstallation``, ``con:WallSurface`` ... the same thematic surfaces, and the
openings of a wall (``con:fillingSurface`` holding ``con:WindowSurface`` / ``con:DoorSurface``,
or ``con:filling`` holding ``con:Window`` / ``con:Door``) are 2.0's ``bldg:opening``; the
semantic type is written as CityJSON spells it ("Window", "Door"). 3.0's ``gen:genericAttribute``
``con:dateOfConstruction`` (its year, as ``yearOfConstruction``) and ``con:height`` (as
``measuredHeight``) are read too.

A ``dem:TINRelief`` (in a ``dem:ReliefFeature``) is one feature of type "TINRelief" whose
``dem:tin`` (``gml:TriangulatedSurface`` / ``gml:Tin``: triangle patches, or control points
triangulated) is a CompositeSurface of LoD ``dem:lod``, as the CityJSON reader yields one: the
terrain of a CFD case (:func:`lod2energy.cfd.terrain.tin_of`).

LoD3/4 interior detail is not envelope: the polygons of InteriorWallSurface / CeilingSurface /
FloorSurface and the rooms, furniture, interior installations (and 3.0 constructive elements)
are left out of the building's geometries and counted in ``provenance["interior_left_out"]``
(kind -> polygons or objects).

Each top-level city object (a ``bldg:Building`` with its BuildingParts and
installations; bridges, tunnels, furniture, generic objects the same way) becomes one
feature: it is converted into a CityJSON-like ``CityObjects`` / ``vertices`` dict and built
by the CityJSON reader (:func:`lod2energy.io.cityjson.build_feature`), so the two readers
agree on everything downstream.

Geometry, per object:

- every ``lodXSolid`` / ``lodXMultiSolid`` / ``lodXMultiSurface`` / ``lodXCompositeSurface``
  / ``lodXGeometry`` (and LoD0 ``lod0FootPrint`` / ``lod0RoofEdge``) is one geometry of LoD X;
  ``surfaceMember`` holds an inline polygon or ``xlink:href`` to a surface anywhere in the
  same feature (``#id`` or a bare ``id``); ``gml:OrientableSurface`` with orientation "-"
  reverses its rings;
- the polygons of the thematic surfaces (``boundedBy/RoofSurface|WallSurface|...``, their
  openings as Window / Door) that no such geometry uses are collected into one MultiSurface
  per LoD (how Berlin stores LoD2);
- a polygon's semantic surface is the thematic surface that holds it, also when a Solid
  refers to it by xlink (one semantic surface per thematic surface, ``id`` its gml:id).

The GML geometry itself (surfaces, xlinks, rings, coordinates) is read by
:mod:`lod2energy.io.gml`, the attributes by :mod:`lod2energy.io.citygml_attributes`.

Rings: ``gml:posList`` (``srsDimension`` on it or an enclosing geometry, default 3),
``gml:pos`` lists or ``gml:coordinates``; the repeated closing point is dropped, a ring that
is not closed is kept as given and reported as 103 (RING_NOT_CLOSED).

CRS: the ``srsName`` of the document's ``gml:Envelope``, else the first ``srsName`` in the
file, as ``metadata.referenceSystem`` in CityJSON's spelling (:mod:`lod2energy.crs`: OGC URNs
and AdV names become ``https://www.opengis.net/def/crs/EPSG/0/<code>``). The model's ``version`` is the CityJSON version the
data are written back as ("2.0"); ``format`` is "CityGML".

Bad input never raises: XML that is not well-formed is one file-level error 901 (the file is
checked whole before any building is yielded), another root is 904, and a
broken building (non-numeric coordinate, dangling xlink, coordinate count not a multiple of
the dimension) is a :class:`~lod2energy.model.FeatureError` for that building alone. A
CityGML version other than 1.0, 2.0 and 3.0 is 904.
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from typing import Any, Iterator
from xml.parsers import expat

import numpy as np

from lod2energy.errors import FormatNotSupportedError, InputError
from lod2energy.io.cityjson import build_feature
from lod2energy.io.seen_ids import SeenIds
from lod2energy.io.citygml_attributes import attributes as _attributes
from lod2energy.io.gml import (SOLID_MEMBERS, SURFACE_KINDS, XLINK_HREF,
                               GmlGeometry, gml_id, local_name)
from lod2energy.crs import cityjson_reference_system
from lod2energy.model import Building, CityModel, FeatureError, frozen_mapping

ROOTS = ("CityModel", "FeatureCollection")  # a CityGML file, or a WFS answer holding city objects

#: Top-level city objects read as features (CityGML local name -> CityJSON type).
TOP_LEVEL = {"Building": "Building", "Bridge": "Bridge", "Tunnel": "Tunnel",
             "CityFurniture": "CityFurniture", "GenericCityObject": "GenericCityObject",
             "WaterBody": "WaterBody", "LandUse": "LandUse",
             "SolitaryVegetationObject": "SolitaryVegetationObject", "PlantCover": "PlantCover",
             # a component of a dem:ReliefFeature: the terrain (a CFD case's ground)
             "TINRelief": "TINRelief"}
#: Properties that hold a child city object (the child's local name gives its type).
CHILD_PROPERTIES = ("consistsOfBuildingPart", "outerBuildingInstallation", "consistsOfBridgePart",
                    "outerBridgeInstallation", "outerBridgeConstruction", "consistsOfTunnelPart",
                    "outerTunnelInstallation",
                    # CityGML 3.0 (an installation may be inside or outside: the envelope code decides)
                    "buildingPart", "buildingInstallation", "bridgePart", "bridgeInstallation",
                    "tunnelPart", "tunnelInstallation")
_CHILD_TYPES = {"BridgeConstructionElement": "BridgeConstructiveElement"}
_OBJECT_NAMES = set(TOP_LEVEL) | {"BuildingPart", "BuildingInstallation", "BridgePart",
                                  "BridgeInstallation", "BridgeConstructionElement", "TunnelPart",
                                  "TunnelInstallation"}

THEMATIC = ("RoofSurface", "WallSurface", "GroundSurface", "ClosureSurface", "OuterCeilingSurface",
            "OuterFloorSurface", "InteriorWallSurface", "CeilingSurface", "FloorSurface", "Window", "Door",
            "WindowSurface", "DoorSurface")
#: Properties of a thematic surface that hold its openings (2.0 ``opening``; 3.0 ``fillingSurface``
#: with Window/DoorSurface, ``filling`` with Window/Door).
OPENING_PROPERTIES = ("opening", "fillingSurface", "filling")
#: Properties of a city object that hold its thematic surfaces (2.0 ``boundedBy``, 3.0 ``boundary``).
BOUNDARY_PROPERTIES = ("boundedBy", "boundary")
#: CityGML thematic surface -> CityJSON semantic surface type, where the names differ.
SEMANTIC_TYPE = {"WindowSurface": "Window", "DoorSurface": "Door"}
#: Thematic surfaces inside the building (LoD3/4 interior detail), not part of the envelope.
INTERIOR_SURFACES = ("InteriorWallSurface", "CeilingSurface", "FloorSurface")
#: Properties holding interior city objects (rooms, furniture, interior installations, 3.0's
#: constructive elements and storeys): not read as envelope, counted.
INTERIOR_PROPERTIES = ("interiorRoom", "interiorFurniture", "interiorBuildingInstallation",
                       "buildingRoom", "buildingFurniture", "buildingConstructiveElement",
                       "buildingSubdivision")
#: CityGML versions read (another version is 904).
VERSIONS = ("1.0", "2.0", "3.0")

_GEOMETRY_PROPERTY = re.compile(r"^lod([0-4])(Solid|MultiSolid|MultiSurface|CompositeSurface|Geometry|"
                                r"FootPrint|RoofEdge)$")
_THEMATIC_GEOMETRY = re.compile(r"^lod([0-4])(MultiSurface|Geometry)$")


# ----------------------------------------------------------------------------- the file

def _scan(path: str) -> tuple[str, str | None, str]:
    """Check the whole file is well-formed XML; return (root name, CRS, CityGML version).

    Raises
    ------
    InputError
        Unreadable or not well-formed (901).
    """
    state: dict[str, Any] = {"root": None, "depth": 0, "crs_doc": None, "crs_any": None, "ns": [],
                             "stack": []}

    def start(name, attrs):
        local = name.rsplit(" ", 1)[-1]
        d = state["depth"]
        if d == 0:
            state["root"] = (local, name.rsplit(" ", 1)[0] if " " in name else "")
        stack = state["stack"]
        srs = next((v for k, v in attrs.items() if k.rsplit(" ", 1)[-1] == "srsName"), None)
        if srs:
            state["crs_any"] = state["crs_any"] or srs
            # the document's own envelope: root / boundedBy / Envelope
            if local == "Envelope" and d == 2 and stack[-1] == "boundedBy" and state["crs_doc"] is None:
                state["crs_doc"] = srs
        stack.append(local)
        state["depth"] = d + 1

    def end(_name):
        state["depth"] -= 1
        state["stack"].pop()

    p = expat.ParserCreate(namespace_separator=" ")
    p.StartElementHandler = start
    p.EndElementHandler = end
    p.StartNamespaceDeclHandler = lambda _prefix, uri: state["ns"].append(uri or "")
    try:
        with open(path, "rb") as f:
            p.ParseFile(f)
    except OSError as e:
        raise InputError(f"cannot read {path}: {e.strerror}") from None
    except expat.ExpatError as e:
        raise InputError(f"{path} is not well-formed XML: {expat.ErrorString(e.code)} "
                         f"at line {e.lineno} column {e.offset + 1}") from None
    if state["root"] is None:
        raise InputError(f"{path} is empty")
    root, root_ns = state["root"]
    return root, state["crs_doc"] or state["crs_any"], _version([root_ns] + state["ns"])


def _version(namespaces: list[str]) -> str:
    for ns in namespaces:
        m = re.search(r"opengis\.net/citygml/(?:[a-z]+/)?(\d\.\d)", ns or "")
        if m:
            return m.group(1)
    return ""


def read(path: str, **_) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Open a CityGML file.

    Returns
    -------
    model : CityModel or None
        None when the file cannot be used (the iterator then yields one file-level error).
    features : iterator of Building or FeatureError
        Streamed (``iterparse``): each top-level city object is built and released in turn.
    """
    try:
        root, crs, version = _scan(path)
        if root not in ROOTS:
            raise FormatNotSupportedError(f"{path}: XML root is {root!r}, not a CityGML CityModel")
        if version and version not in VERSIONS:
            raise FormatNotSupportedError(f"{path}: CityGML {version} is not supported (1.0, 2.0 and 3.0 are)")
    except InputError as e:
        return None, iter([FeatureError(None, e.code, str(e))])
    # CityJSON's spelling of the CRS (AdV names such as urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH
    # become their EPSG code), the srsName as written when no EPSG code is recognised
    md = {"referenceSystem": cityjson_reference_system(crs)} if crs else {}
    model = CityModel(version="2.0", metadata=frozen_mapping(md), source=path, format="CityGML")
    return model, _features(path)


def _features(path: str) -> Iterator[Building | FeatureError]:
    stack: list[ET.Element] = []
    n = 0
    seen = SeenIds()  # gml:id of every city object read -> the feature it came in
    try:
        for ev, el in ET.iterparse(path, events=("start", "end")):
            if ev == "start":
                stack.append(el)
                continue
            stack.pop()
            name = local_name(el.tag)
            if name in TOP_LEVEL and not any(local_name(a.tag) in _OBJECT_NAMES for a in stack):
                n += 1
                yield _once(_feature_or_error(el, TOP_LEVEL[name], n), gml_id(el), n, seen)
                if stack:
                    stack[-1].remove(el)  # release it: the tile is streamed
            elif len(stack) == 1:
                stack[0].remove(el)  # a direct child of the root, read (or not needed)
    except ET.ParseError as e:  # the file changed since it was checked
        yield FeatureError(None, 901, f"{path} is not well-formed XML: {e}")
    except OSError as e:
        yield FeatureError(None, 901, f"cannot read {path}: {e.strerror}")


def _once(f: Building | FeatureError, gid: str | None, n: int, seen: SeenIds) -> Building | FeatureError:
    """``f``, or a per-building error 901 when a city object of it has a gml:id an earlier
    feature of the file already had (the first is kept, as the CityJSON reader does)."""
    ids = [o.id for o in f.objects] if isinstance(f, Building) else ([gid] if gid else [])
    again = next((i for i in ids if i in seen), None)
    if again is not None:
        rtype = f.type or ""
        return FeatureError(seen.duplicate_id(ids[0]), 901,
                            f"coid={again}: gml:id {again!r} was already read (feature {seen.where(again)}); "
                            f"the first is kept, this one (feature {n}) is not read", rtype)
    for i in ids:
        seen.add(i, n)
    return f


def _feature_or_error(el: ET.Element, ctype: str, n: int) -> Building | FeatureError:
    oid = gml_id(el) or f"{ctype}_{n}"
    try:
        return _Feature(el, ctype, oid).build()
    except InputError as e:
        return FeatureError(oid, e.code, str(e), ctype)
    except RecursionError:
        return FeatureError(oid, 901, f"coid={oid}: geometry nested too deeply (or an xlink cycle)", ctype)


def _faces(g: dict) -> list[tuple[ET.Element, bool]]:
    """Every ``(polygon, reversed)`` of a raw explicit geometry (:meth:`_Feature._explicit`)."""
    if "_faces" in g:
        return list(g["_faces"])
    if "_shells" in g:
        return [f for sh in g["_shells"] for f in sh]
    return [f for so in g["_solids"] for sh in so for f in sh]


def _relief_lod(el: ET.Element) -> str:
    """The ``dem:lod`` of a relief component (0-4; "1" when missing or not a number)."""
    for prop in el:
        if local_name(prop.tag) == "lod":
            text = (prop.text or "").strip()
            if text.isdigit() and 0 <= int(text) <= 4:
                return text
    return "1"


# ----------------------------------------------------------------------------- one feature

class _Feature(GmlGeometry):
    """One top-level city object and its children, turned into CityJSON-like dicts."""

    def __init__(self, el: ET.Element, ctype: str, oid: str):
        super().__init__()
        self.el = el
        self.ctype = ctype
        self.oid = oid
        self.semantic_of: dict[ET.Element, ET.Element] = {}  # polygon -> its thematic surface
        self.duplicates: dict[str, int] = {}  # gml:id of more than one surface -> how many
        self._index(el, 3)
        self.used: set[ET.Element] = set()
        self.left_out: dict[str, int] = {}  # interior detail not read as envelope: kind -> count

    def _index(self, el: ET.Element, dim: int) -> None:
        """Ids of surfaces, the srsDimension of every coordinate list, thematic polygons."""
        todo = [(el, dim, None)]
        while todo:
            e, d, theme = todo.pop()
            name = local_name(e.tag)
            sd = e.get("srsDimension")
            if sd is not None:
                try:
                    d = int(sd)
                except ValueError:
                    d = -1
            if name in SURFACE_KINDS:
                gid = gml_id(e)
                if gid is not None:
                    if self.surfaces.setdefault(gid, e) is not e:
                        self.duplicates.setdefault(gid, 1)
                        self.duplicates[gid] += 1
                if theme is not None:
                    self.semantic_of[e] = theme
            elif name in ("posList", "pos", "coordinates"):
                self.dims[e] = d
            if name in THEMATIC:
                theme = e
            todo.extend((c, d, theme) for c in reversed(e))

    def build(self) -> Building:
        if self.duplicates:
            gid, k = next(iter(self.duplicates.items()))
            raise InputError(f"coid={self.oid}: gml:id {gid!r} is the id of {k} surfaces (gml:id must be "
                             f"unique: an xlink to it is ambiguous); {len(self.duplicates)} such id(s)")
        objects: list[tuple[str, str, ET.Element, str | None]] = []  # id, type, element, parent
        self._collect(self.el, self.ctype, self.oid, None, objects)
        cos: dict[str, dict] = {}
        raw: dict[str, list[dict]] = {}
        for oid, _t, el, _p in objects:  # explicit geometries first: they claim their polygons
            raw[oid] = [g for g in (self._explicit(oid, prop, lod) for prop, lod in self._geometry_properties(el))
                        if g is not None]
        replaced = []
        for oid, _t, el, _p in objects:  # an unusable one gives way to the thematic surfaces of its LoD
            for g in list(raw[oid]):
                why = self._unusable(oid, el, g)
                if why:
                    raw[oid].remove(g)
                    self.used.difference_update(p for p, _ in _faces(g) if self._area(p) > 0.0)
                    replaced.append(f"{oid}: {why}")
        explicit = {oid: [self._finish(oid, gi, g) for gi, g in enumerate(gs)] for oid, gs in raw.items()}
        for oid, otype, el, parent in objects:
            geoms = explicit[oid] + self._thematic(oid, el, len(explicit[oid]))
            co: dict[str, Any] = {"type": otype, "geometry": geoms}
            attrs = _attributes(el)
            if attrs:
                co["attributes"] = attrs
            if parent is not None:
                co["parents"] = [parent]
            kids = [o[0] for o in objects if o[3] == oid]
            if kids:
                co["children"] = kids
            cos[oid] = co
        verts = np.asarray(self.vertices, dtype=np.float64).reshape(-1, 3)
        b = build_feature(self.oid, [o[0] for o in objects], cos, verts)
        errors = tuple(b.provenance.get("input_errors", ())) + tuple(self.issues)
        prov: dict[str, Any] = {"source_format": "CityGML"}
        if self.left_out:
            prov["interior_left_out"] = frozen_mapping(dict(sorted(self.left_out.items())))
        if replaced:
            prov["geometry_replaced"] = tuple(replaced)
        if errors:
            prov["input_errors"] = errors
        return b.with_provenance(**prov)

    def _collect(self, el, otype, oid, parent, out) -> None:
        out.append((oid, otype, el, parent))
        k = 0
        for prop in el:
            if local_name(prop.tag) in INTERIOR_PROPERTIES:
                for child in prop:
                    self.left_out[local_name(child.tag)] = self.left_out.get(local_name(child.tag), 0) + 1
            if local_name(prop.tag) not in CHILD_PROPERTIES:
                continue
            for child in prop:
                k += 1
                name = local_name(child.tag)
                cid = gml_id(child) or f"{oid}_{name}_{k}"
                if any(o[0] == cid for o in out):  # ids must be unique within the feature
                    cid = f"{cid}_{k}"
                self._collect(child, _CHILD_TYPES.get(name, name), cid, oid, out)

    # -- geometry properties of the object itself

    @staticmethod
    def _geometry_properties(el: ET.Element):
        for prop in el:
            m = _GEOMETRY_PROPERTY.match(local_name(prop.tag))
            if m:
                yield prop, m.group(1)
            elif local_name(prop.tag) == "tin" and local_name(el.tag) == "TINRelief":
                yield prop, _relief_lod(el)

    def _target(self, prop: ET.Element, where: str) -> ET.Element | None:
        href = prop.get(XLINK_HREF)
        if href is not None:
            return self.resolve(href, where)
        return next(iter(prop), None)

    def _explicit(self, oid: str, prop: ET.Element, lod: str) -> dict | None:
        where = f"coid={oid}|{local_name(prop.tag)}"
        g = self._target(prop, where)
        if g is None:
            return None
        name = local_name(g.tag)
        if name == "Solid":
            out = {"type": "Solid", "lod": lod, "_shells": self.solid(g, where)}
            faces = [f for sh in out["_shells"] for f in sh]
        elif name in ("MultiSolid", "CompositeSolid"):
            out = {"type": name, "lod": lod,
                   "_solids": [self.solid(s, where) for s in self.members(g, SOLID_MEMBERS, where)]}
            faces = [f for so in out["_solids"] for sh in so for f in sh]
        elif name in SURFACE_KINDS:
            # a TIN (TINRelief's dem:tin) is a CompositeSurface of triangles, as in CityJSON
            gtype = name if name in ("MultiSurface", "CompositeSurface") else (
                "CompositeSurface" if name in ("Shell", "TriangulatedSurface", "Tin") else "MultiSurface")
            out = {"type": gtype, "lod": lod, "_faces": self.surface(g, where)}
            faces = out["_faces"]
        else:
            return None  # points, curves, implicit geometry: nothing to validate as a surface
        self.used.update(p for p, _ in faces)
        return out

    def _area(self, poly: ET.Element) -> float:
        """Area of a polygon's exterior ring in the file's units (0 when it has none or it
        cannot be read)."""
        for part in poly:
            if local_name(part.tag) in ("exterior", "outerBoundaryIs"):
                for ring in part:
                    try:
                        p = np.asarray(self.points(ring, ""), dtype=np.float64)
                    except InputError:
                        return 0.0
                    if len(p) < 3 or not np.all(np.isfinite(p)):
                        return 0.0
                    c = p - p[0]  # Newell's normal about the first point: half its length
                    return float(np.linalg.norm(np.cross(c[:-1], c[1:]).sum(axis=0))) / 2
        return 0.0

    def _unusable(self, oid: str, el: ET.Element, g: dict) -> str | None:
        """Why the explicit geometry ``g`` of object ``oid`` is unusable while the thematic
        surfaces of its LoD hold a shell (at least 4 polygons with an area no geometry uses):
        a solid with fewer than 4 polygons with an area, a surface set with none; else None."""
        spare = [p for lod, faces in self._theme_faces_of(oid, el) if lod == g["lod"]
                 for p, _ in faces if p not in self.used]
        areas = [a for a in (self._area(p) for p in spare) if a > 0.0]
        if len(areas) < 4:
            return None
        tiny = 1e-9 * sum(areas)
        real = sum(self._area(p) > tiny for p, _ in _faces(g))
        need = 4 if g["type"] in ("Solid", "MultiSolid", "CompositeSolid") else 1
        if real >= need:
            return None
        return (f"lod{g['lod']} {g['type']} unusable ({len(_faces(g))} polygon(s), {real} with an area): "
                f"the {len(areas)} polygons of its thematic LoD{g['lod']} surfaces are used instead")

    def _theme_faces_of(self, oid: str, el: ET.Element):
        for prop in el:
            if local_name(prop.tag) not in BOUNDARY_PROPERTIES:
                continue
            for ts in prop:
                if local_name(ts.tag) in THEMATIC and local_name(ts.tag) not in INTERIOR_SURFACES:
                    yield from self._theme_faces(ts, f"coid={oid}|{local_name(ts.tag)}")

    def _thematic(self, oid: str, el: ET.Element, first_gi: int) -> list[dict]:
        """One MultiSurface per LoD of the thematic-surface polygons no geometry used."""
        by_lod: dict[str, list[tuple[ET.Element, bool]]] = {}
        for prop in el:
            if local_name(prop.tag) not in BOUNDARY_PROPERTIES:
                continue
            for ts in prop:
                if local_name(ts.tag) not in THEMATIC:
                    continue
                if local_name(ts.tag) in INTERIOR_SURFACES:  # interior detail: not envelope, counted
                    n = sum(len(f) for _, f in self._theme_faces(ts, f"coid={oid}|{local_name(ts.tag)}"))
                    self.left_out[local_name(ts.tag)] = self.left_out.get(local_name(ts.tag), 0) + n
                    continue
                for lod, faces in self._theme_faces(ts, f"coid={oid}|{local_name(ts.tag)}"):
                    by_lod.setdefault(lod, []).extend(f for f in faces if f[0] not in self.used)
        out = []
        for lod in sorted(by_lod):
            faces = by_lod[lod]
            if faces:
                out.append(self._finish(oid, first_gi + len(out), {"type": "MultiSurface", "lod": lod,
                                                                   "_faces": faces}))
        return out

    def _theme_faces(self, ts: ET.Element, where: str):
        for prop in ts:
            name = local_name(prop.tag)
            m = _THEMATIC_GEOMETRY.match(name)
            if m:
                g = self._target(prop, where)
                if g is not None and local_name(g.tag) in SURFACE_KINDS:
                    yield m.group(1), self.surface(g, where)
            elif name in OPENING_PROPERTIES:
                for op in prop:
                    if local_name(op.tag) in THEMATIC:
                        yield from self._theme_faces(op, where)

    def _finish(self, oid: str, gi: int, g: dict) -> dict:
        """Rings -> vertex indices; semantics from the thematic surfaces."""
        sem_index: dict[ET.Element, int] = {}
        surfaces: list[dict] = []

        def face(poly: ET.Element, rev: bool, loc: str):
            theme = self.semantic_of.get(poly)
            if theme is not None and theme not in sem_index:
                sem_index[theme] = len(surfaces)
                tid = gml_id(theme)
                kind = local_name(theme.tag)
                surfaces.append({"type": SEMANTIC_TYPE.get(kind, kind), **({"id": tid} if tid else {})})
            return self.polygon(poly, rev, loc), (sem_index[theme] if theme is not None else None)

        base = f"coid={oid}|geom={gi}"
        out: dict[str, Any] = {"type": g["type"], "lod": g["lod"]}
        if "_faces" in g:
            pairs = [face(p, r, f"{base}|face={fi}") for fi, (p, r) in enumerate(g["_faces"])]
            out["boundaries"] = [b for b, _ in pairs]
            values: Any = [s for _, s in pairs]
        elif "_shells" in g:
            shells = [[face(p, r, f"{base}|shell={hi}|face={fi}") for fi, (p, r) in enumerate(sh)]
                      for hi, sh in enumerate(g["_shells"])]
            out["boundaries"] = [[b for b, _ in sh] for sh in shells]
            values = [[s for _, s in sh] for sh in shells]
        else:
            solids = [[[face(p, r, f"{base}|solid={si}|shell={hi}|face={fi}") for fi, (p, r) in enumerate(sh)]
                       for hi, sh in enumerate(so)] for si, so in enumerate(g["_solids"])]
            out["boundaries"] = [[[b for b, _ in sh] for sh in so] for so in solids]
            values = [[[s for _, s in sh] for sh in so] for so in solids]
        if surfaces:
            out["semantics"] = {"surfaces": surfaces, "values": values}
        return out
