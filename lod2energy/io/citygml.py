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
from lod2energy.crs import cityjson_reference_system
from lod2energy.model import Building, CityModel, FeatureError, frozen_mapping

XLINK_HREF = "{http://www.w3.org/1999/xlink}href"
ROOTS = ("CityModel", "FeatureCollection")  # a CityGML file, or a WFS answer holding city objects

#: Top-level city objects read as features (CityGML local name -> CityJSON type).
TOP_LEVEL = {"Building": "Building", "Bridge": "Bridge", "Tunnel": "Tunnel",
             "CityFurniture": "CityFurniture", "GenericCityObject": "GenericCityObject",
             "WaterBody": "WaterBody", "LandUse": "LandUse",
             "SolitaryVegetationObject": "SolitaryVegetationObject", "PlantCover": "PlantCover"}
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
_POLYGONS = ("Polygon", "Triangle", "Rectangle", "PolygonPatch")
_SURFACE_SETS = ("MultiSurface", "CompositeSurface", "Shell", "Surface", "TriangulatedSurface", "Tin",
                 "PolyhedralSurface")
_SURFACE_MEMBERS = ("surfaceMember", "surfaceMembers", "patches", "trianglePatches", "polygonPatches",
                    "baseSurface")
_SURFACE_KINDS = _POLYGONS + _SURFACE_SETS + ("OrientableSurface",)
_SOLID_MEMBERS = ("solidMember", "solidMembers")

#: Attributes read from the object's own properties (local name -> parser).
_INT_ATTRS = ("yearOfConstruction", "yearOfDemolition", "storeysAboveGround", "storeysBelowGround")
_FLOAT_ATTRS = ("measuredHeight",)
_TEXT_ATTRS = ("function", "usage", "class", "roofType", "storeyHeightsAboveGround",
               "storeyHeightsBelowGround")
_GENERIC = {"stringAttribute": str, "intAttribute": int, "doubleAttribute": float,
            "measureAttribute": float, "dateAttribute": str, "uriAttribute": str}
#: CityGML 3.0 generic attributes (inside ``gen:genericAttribute``; ``gen:name`` and ``gen:value``).
_GENERIC3 = {"StringAttribute": str, "IntAttribute": int, "DoubleAttribute": float,
             "MeasureAttribute": float, "DateAttribute": str, "UriAttribute": str, "CodeAttribute": str}


def _local(tag: Any) -> str:
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


def _gml_id(el: ET.Element) -> str | None:
    for k, v in el.attrib.items():
        if _local(k) == "id":
            return v
    return None


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
    try:
        for ev, el in ET.iterparse(path, events=("start", "end")):
            if ev == "start":
                stack.append(el)
                continue
            stack.pop()
            name = _local(el.tag)
            if name in TOP_LEVEL and not any(_local(a.tag) in _OBJECT_NAMES for a in stack):
                n += 1
                yield _feature_or_error(el, TOP_LEVEL[name], n)
                if stack:
                    stack[-1].remove(el)  # release it: the tile is streamed
            elif len(stack) == 1:
                stack[0].remove(el)  # a direct child of the root, read (or not needed)
    except ET.ParseError as e:  # the file changed since it was checked
        yield FeatureError(None, 901, f"{path} is not well-formed XML: {e}")
    except OSError as e:
        yield FeatureError(None, 901, f"cannot read {path}: {e.strerror}")


def _feature_or_error(el: ET.Element, ctype: str, n: int) -> Building | FeatureError:
    oid = _gml_id(el) or f"{ctype}_{n}"
    try:
        return _Feature(el, ctype, oid).build()
    except InputError as e:
        return FeatureError(oid, e.code, str(e), ctype)
    except RecursionError:
        return FeatureError(oid, 901, f"coid={oid}: geometry nested too deeply (or an xlink cycle)", ctype)


# ----------------------------------------------------------------------------- one feature

class _Feature:
    """One top-level city object and its children, turned into CityJSON-like dicts."""

    def __init__(self, el: ET.Element, ctype: str, oid: str):
        self.el = el
        self.ctype = ctype
        self.oid = oid
        self.surfaces: dict[str, ET.Element] = {}  # gml:id -> surface element (for xlinks)
        self.dims: dict[ET.Element, int] = {}  # coordinate element -> srsDimension in force
        self.semantic_of: dict[ET.Element, ET.Element] = {}  # polygon -> its thematic surface
        self._index(el, 3)
        self.vertex_ids: dict[tuple[float, float, float], int] = {}
        self.vertices: list[tuple[float, float, float]] = []
        self.issues: list[tuple[int, str, str]] = []
        self.used: set[ET.Element] = set()
        self.left_out: dict[str, int] = {}  # interior detail not read as envelope: kind -> count

    def _index(self, el: ET.Element, dim: int) -> None:
        """Ids of surfaces, the srsDimension of every coordinate list, thematic polygons."""
        todo = [(el, dim, None)]
        while todo:
            e, d, theme = todo.pop()
            name = _local(e.tag)
            sd = e.get("srsDimension")
            if sd is not None:
                try:
                    d = int(sd)
                except ValueError:
                    d = -1
            if name in _SURFACE_KINDS:
                gid = _gml_id(e)
                if gid is not None:
                    self.surfaces.setdefault(gid, e)
                if theme is not None:
                    self.semantic_of[e] = theme
            elif name in ("posList", "pos", "coordinates"):
                self.dims[e] = d
            if name in THEMATIC:
                theme = e
            todo.extend((c, d, theme) for c in reversed(e))

    def build(self) -> Building:
        objects: list[tuple[str, str, ET.Element, str | None]] = []  # id, type, element, parent
        self._collect(self.el, self.ctype, self.oid, None, objects)
        cos: dict[str, dict] = {}
        explicit: dict[str, list[dict]] = {}
        for oid, _t, el, _p in objects:  # explicit geometries first: they claim their polygons
            geoms = [g for g in (self._explicit(oid, prop, lod) for prop, lod in self._geometry_properties(el))
                     if g is not None]
            explicit[oid] = [self._finish(oid, gi, g) for gi, g in enumerate(geoms)]
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
        if errors:
            prov["input_errors"] = errors
        return b.with_provenance(**prov)

    def _collect(self, el, otype, oid, parent, out) -> None:
        out.append((oid, otype, el, parent))
        k = 0
        for prop in el:
            if _local(prop.tag) in INTERIOR_PROPERTIES:
                for child in prop:
                    self.left_out[_local(child.tag)] = self.left_out.get(_local(child.tag), 0) + 1
            if _local(prop.tag) not in CHILD_PROPERTIES:
                continue
            for child in prop:
                k += 1
                name = _local(child.tag)
                cid = _gml_id(child) or f"{oid}_{name}_{k}"
                if any(o[0] == cid for o in out):  # ids must be unique within the feature
                    cid = f"{cid}_{k}"
                self._collect(child, _CHILD_TYPES.get(name, name), cid, oid, out)

    # -- geometry properties of the object itself

    @staticmethod
    def _geometry_properties(el: ET.Element):
        for prop in el:
            m = _GEOMETRY_PROPERTY.match(_local(prop.tag))
            if m:
                yield prop, m.group(1)

    def _target(self, prop: ET.Element, where: str) -> ET.Element | None:
        href = prop.get(XLINK_HREF)
        if href is not None:
            return self._resolve(href, where)
        return next(iter(prop), None)

    def _explicit(self, oid: str, prop: ET.Element, lod: str) -> dict | None:
        where = f"coid={oid}|{_local(prop.tag)}"
        g = self._target(prop, where)
        if g is None:
            return None
        name = _local(g.tag)
        if name == "Solid":
            out = {"type": "Solid", "lod": lod, "_shells": self._solid(g, where)}
            faces = [f for sh in out["_shells"] for f in sh]
        elif name in ("MultiSolid", "CompositeSolid"):
            out = {"type": name, "lod": lod,
                   "_solids": [self._solid(s, where) for s in self._members(g, _SOLID_MEMBERS, where)]}
            faces = [f for so in out["_solids"] for sh in so for f in sh]
        elif name in _SURFACE_KINDS:
            gtype = name if name in ("MultiSurface", "CompositeSurface") else (
                "CompositeSurface" if name == "Shell" else "MultiSurface")
            out = {"type": gtype, "lod": lod, "_faces": self._surface(g, where)}
            faces = out["_faces"]
        else:
            return None  # points, curves, implicit geometry: nothing to validate as a surface
        self.used.update(p for p, _ in faces)
        return out

    def _thematic(self, oid: str, el: ET.Element, first_gi: int) -> list[dict]:
        """One MultiSurface per LoD of the thematic-surface polygons no geometry used."""
        by_lod: dict[str, list[tuple[ET.Element, bool]]] = {}
        for prop in el:
            if _local(prop.tag) not in BOUNDARY_PROPERTIES:
                continue
            for ts in prop:
                if _local(ts.tag) not in THEMATIC:
                    continue
                if _local(ts.tag) in INTERIOR_SURFACES:  # interior detail: not envelope, counted
                    n = sum(len(f) for _, f in self._theme_faces(ts, f"coid={oid}|{_local(ts.tag)}"))
                    self.left_out[_local(ts.tag)] = self.left_out.get(_local(ts.tag), 0) + n
                    continue
                for lod, faces in self._theme_faces(ts, f"coid={oid}|{_local(ts.tag)}"):
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
            name = _local(prop.tag)
            m = _THEMATIC_GEOMETRY.match(name)
            if m:
                g = self._target(prop, where)
                if g is not None and _local(g.tag) in _SURFACE_KINDS:
                    yield m.group(1), self._surface(g, where)
            elif name in OPENING_PROPERTIES:
                for op in prop:
                    if _local(op.tag) in THEMATIC:
                        yield from self._theme_faces(op, where)

    # -- GML geometry

    def _resolve(self, href: str, where: str) -> ET.Element:
        key = href.rsplit("#", 1)[-1].strip()
        target = self.surfaces.get(key)
        if target is None:
            raise InputError(f"{where}: xlink:href {href!r} points to no surface of this building")
        return target

    def _members(self, el: ET.Element, names: tuple[str, ...], where: str) -> list[ET.Element]:
        out = []
        for m in el:
            if _local(m.tag) not in names:
                continue
            href = m.get(XLINK_HREF)
            if href is not None:
                out.append(self._resolve(href, where))
            else:
                out.extend(m)
        return out

    def _solid(self, solid: ET.Element, where: str) -> list[list[tuple[ET.Element, bool]]]:
        shells = []
        for part in solid:
            if _local(part.tag) in ("exterior", "interior"):
                href = part.get(XLINK_HREF)
                surf = [self._resolve(href, where)] if href is not None else list(part)
                faces = []
                for s in surf:
                    faces.extend(self._surface(s, where))
                if _local(part.tag) == "exterior":
                    shells.insert(0, faces)
                else:
                    shells.append(faces)
        return shells

    def _surface(self, el: ET.Element, where: str, reverse: bool = False,
                 depth: int = 0) -> list[tuple[ET.Element, bool]]:
        """The polygons of a surface element: ``[(polygon element, reversed), ...]``."""
        if depth > 50:
            raise InputError(f"{where}: surfaces nested more than 50 deep (an xlink cycle?)")
        name = _local(el.tag)
        if name in _POLYGONS:
            return [(el, reverse)]
        if name == "OrientableSurface":
            reverse = reverse ^ (el.get("orientation", "+").strip() == "-")
        elif name not in _SURFACE_SETS:
            raise InputError(f"{where}: unsupported surface type gml:{name}")
        out = []
        for m in self._members(el, _SURFACE_MEMBERS, where):
            out.extend(self._surface(m, where, reverse, depth + 1))
        return out

    def _finish(self, oid: str, gi: int, g: dict) -> dict:
        """Rings -> vertex indices; semantics from the thematic surfaces."""
        sem_index: dict[ET.Element, int] = {}
        surfaces: list[dict] = []

        def face(poly: ET.Element, rev: bool, loc: str):
            theme = self.semantic_of.get(poly)
            if theme is not None and theme not in sem_index:
                sem_index[theme] = len(surfaces)
                tid = _gml_id(theme)
                kind = _local(theme.tag)
                surfaces.append({"type": SEMANTIC_TYPE.get(kind, kind), **({"id": tid} if tid else {})})
            return self._polygon(poly, rev, loc), (sem_index[theme] if theme is not None else None)

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

    def _polygon(self, poly: ET.Element, reverse: bool, loc: str) -> list[list[int]]:
        rings = []
        for part in poly:
            name = _local(part.tag)
            if name not in ("exterior", "interior", "outerBoundaryIs", "innerBoundaryIs"):
                continue
            for ring in part:
                r = self._ring(ring, loc)
                if reverse:
                    r = r[:1] + r[1:][::-1]
                if name in ("exterior", "outerBoundaryIs"):
                    rings.insert(0, r)
                else:
                    rings.append(r)
        if not rings:
            raise InputError(f"{loc}: polygon without rings")
        return rings

    def _ring(self, ring: ET.Element, loc: str) -> list[int]:
        if _local(ring.tag) != "LinearRing":
            raise InputError(f"{loc}: unsupported ring type gml:{_local(ring.tag)} (LinearRing expected)")
        pts = self._points(ring, loc)
        if len(pts) >= 2 and pts[0] == pts[-1]:
            pts = pts[:-1]
        else:
            self.issues.append((103, loc, "first and last points of a GML ring must be the same"))
        out = []
        for p in pts:
            i = self.vertex_ids.get(p)
            if i is None:
                i = self.vertex_ids[p] = len(self.vertices)
                self.vertices.append(p)
            out.append(i)
        return out

    def _points(self, ring: ET.Element, loc: str) -> list[tuple[float, float, float]]:
        pos_list = [e for e in ring if _local(e.tag) == "posList"]
        if pos_list:
            values: list[str] = []
            dim = self.dims.get(pos_list[0], 3)
            for e in pos_list:
                values.extend((e.text or "").split())
            return _xyz(values, dim, loc)
        pos = [e for e in ring.iter() if _local(e.tag) == "pos"]
        if pos:
            pts = []
            for e in pos:
                pts.extend(_xyz((e.text or "").split(), self.dims.get(e, 3), loc))
            return pts
        coords = [e for e in ring if _local(e.tag) == "coordinates"]
        if coords:
            e = coords[0]
            cs, ts = e.get("cs", ","), e.get("ts", " ")
            text = (e.text or "").replace(ts, " ") if ts.strip() else (e.text or "")
            pts = []
            for t in text.split():
                pts.extend(_xyz(t.split(cs), len(t.split(cs)), loc))
            return pts
        raise InputError(f"{loc}: ring has no gml:posList, gml:pos or gml:coordinates")


def _xyz(values: list[str], dim: int, loc: str) -> list[tuple[float, float, float]]:
    if dim != 3:
        raise InputError(f"{loc}: srsDimension {dim}: a 3D building needs x y z coordinates")
    if len(values) % 3:
        raise InputError(f"{loc}: {len(values)} coordinates do not make x y z triples")
    try:
        f = [float(v) for v in values]
    except ValueError:
        bad = next(v for v in values if not _is_float(v))
        raise InputError(f"{loc}: non-numeric coordinate {bad[:40]!r}") from None
    return [(f[i], f[i + 1], f[i + 2]) for i in range(0, len(f), 3)]


def _is_float(v: str) -> bool:
    try:
        float(v)
    except ValueError:
        return False
    return True


# ----------------------------------------------------------------------------- attributes

def _number(text: str, kind):
    try:
        return kind(text)
    except ValueError:
        if kind is int:
            try:
                x = float(text)
                return int(x) if x.is_integer() else x
            except ValueError:
                pass
        return text


def _attributes(el: ET.Element) -> dict[str, Any]:
    """Standard building attributes and generic attributes of ``el`` (its own properties)."""
    attrs: dict[str, Any] = {}
    standard: dict[str, Any] = {}
    for prop in el:
        name = _local(prop.tag)
        text = (prop.text or "").strip()
        if name in _GENERIC or name == "genericAttributeSet":
            k, v = _generic(prop)
            if k:
                attrs[k] = v
        elif name == "genericAttribute":
            for g in prop:
                k, v = _generic3(g)
                if k:
                    attrs[k] = v
        elif name == "dateOfConstruction" and re.match(r"^\d{4}", text):
            standard.setdefault("yearOfConstruction", int(text[:4]))
        elif name == "height":  # CityGML 3.0 con:height / con:Height: its value as measuredHeight
            v = next((e for e in prop.iter() if _local(e.tag) == "value"), None)
            if v is not None and (v.text or "").strip():
                standard.setdefault("measuredHeight", _number(v.text.strip(), float))
        elif name in _INT_ATTRS and text:
            standard[name] = _number(text, int)
        elif name in _FLOAT_ATTRS and text:
            standard[name] = _number(text, float)
        elif name in _TEXT_ATTRS and text:
            if name in standard:  # CityGML allows several function / usage values
                prev = standard[name]
                standard[name] = (prev if isinstance(prev, list) else [prev]) + [text]
            else:
                standard[name] = text
    attrs.update(standard)
    return attrs


def _generic(el: ET.Element) -> tuple[str | None, Any]:
    name = el.get("name")
    kind = _local(el.tag)
    if kind == "genericAttributeSet":
        members = dict(_generic(c) for c in el if _local(c.tag) in _GENERIC or _local(c.tag) == "genericAttributeSet")
        members.pop(None, None)
        return name, members
    value = next((c for c in el if _local(c.tag) == "value"), None)
    text = (value.text or "").strip() if value is not None else ""
    return name, _number(text, _GENERIC[kind]) if text else text


def _generic3(el: ET.Element) -> tuple[str | None, Any]:
    """A CityGML 3.0 generic attribute: ``gen:XAttribute`` with ``gen:name`` and ``gen:value``."""
    kind = _local(el.tag)
    name = next(((c.text or "").strip() for c in el if _local(c.tag) == "name"), None)
    if kind == "GenericAttributeSet":
        members = dict(_generic3(c) for m in el if _local(m.tag) == "genericAttribute" for c in m)
        members.pop(None, None)
        return name, members
    if kind not in _GENERIC3:
        return None, None
    value = next((c for c in el if _local(c.tag) == "value"), None)
    text = (value.text or "").strip() if value is not None else ""
    return name, _number(text, _GENERIC3[kind]) if text else text
