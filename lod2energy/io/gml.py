"""GML 3.1.1 / 3.2 surface geometry read into vertex-indexed rings (the CityGML readers' geometry part).

Elements are matched by local name, so any namespace prefix works. A surface is a polygon
(``gml:Polygon``, ``Triangle``, ``Rectangle``, ``PolygonPatch``), a set of them (``MultiSurface``,
``CompositeSurface``, ``Shell``, ``Surface``, ``TriangulatedSurface`` / ``Tin``,
``PolyhedralSurface``) or an ``OrientableSurface`` (orientation "-" reverses its rings);
a ``Tin`` given by its ``controlPoint`` only is their Delaunay triangulation in plan;
``surfaceMember`` holds an inline surface or an ``xlink:href`` to one (``#id`` or a bare ``id``)
in the id index the caller fills (:attr:`GmlGeometry.surfaces`).

Rings: ``gml:posList`` (``srsDimension`` on it or an enclosing geometry, default 3),
``gml:pos`` lists or ``gml:coordinates``; the repeated closing point is dropped, a ring that
is not closed is kept as given and recorded as 103 (RING_NOT_CLOSED) in
:attr:`GmlGeometry.issues`. Points are welded only where they are exactly equal.
Broken geometry raises :class:`~lod2energy.errors.InputError` with its location.
"""
from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

import numpy as np

from lod2energy.errors import InputError

XLINK_HREF = "{http://www.w3.org/1999/xlink}href"

POLYGONS = ("Polygon", "Triangle", "Rectangle", "PolygonPatch")
SURFACE_SETS = ("MultiSurface", "CompositeSurface", "Shell", "Surface", "TriangulatedSurface", "Tin",
                "PolyhedralSurface")
SURFACE_MEMBERS = ("surfaceMember", "surfaceMembers", "patches", "trianglePatches", "polygonPatches",
                   "baseSurface")
SURFACE_KINDS = POLYGONS + SURFACE_SETS + ("OrientableSurface",)
SOLID_MEMBERS = ("solidMember", "solidMembers")


def local_name(tag: Any) -> str:
    """The local name of an element tag (``{ns}Name`` -> ``Name``; a comment's tag -> "")."""
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


def gml_id(el: ET.Element) -> str | None:
    """The element's ``gml:id`` (any namespace), or None."""
    for k, v in el.attrib.items():
        if local_name(k) == "id":
            return v
    return None


class GmlGeometry:
    """Surface elements -> rings of vertex indices into one shared vertex list.

    Attributes
    ----------
    surfaces : dict of str to Element
        gml:id -> surface element, the targets of xlinks (filled by the caller).
    dims : dict of Element to int
        coordinate element -> the ``srsDimension`` in force there (filled by the caller).
    vertices : list of (3,) tuple of float
        The points read so far, in input units.
    issues : list of (int, str, str)
        Non-fatal defects found (code, location, message).
    """

    def __init__(self) -> None:
        self.surfaces: dict[str, ET.Element] = {}
        self.dims: dict[ET.Element, int] = {}
        self.vertex_ids: dict[tuple[float, float, float], int] = {}
        self.vertices: list[tuple[float, float, float]] = []
        self.issues: list[tuple[int, str, str]] = []

    def resolve(self, href: str, where: str) -> ET.Element:
        key = href.rsplit("#", 1)[-1].strip()
        target = self.surfaces.get(key)
        if target is None:
            raise InputError(f"{where}: xlink:href {href!r} points to no surface of this building")
        return target

    def members(self, el: ET.Element, names: tuple[str, ...], where: str) -> list[ET.Element]:
        out = []
        for m in el:
            if local_name(m.tag) not in names:
                continue
            href = m.get(XLINK_HREF)
            if href is not None:
                out.append(self.resolve(href, where))
            else:
                out.extend(m)
        return out

    def solid(self, solid: ET.Element, where: str) -> list[list[tuple[ET.Element, bool]]]:
        shells = []
        for part in solid:
            if local_name(part.tag) in ("exterior", "interior"):
                href = part.get(XLINK_HREF)
                surf = [self.resolve(href, where)] if href is not None else list(part)
                faces = []
                for s in surf:
                    faces.extend(self.surface(s, where))
                if local_name(part.tag) == "exterior":
                    shells.insert(0, faces)
                else:
                    shells.append(faces)
        return shells

    def surface(self, el: ET.Element, where: str, reverse: bool = False,
                 depth: int = 0) -> list[tuple[ET.Element, bool]]:
        """The polygons of a surface element: ``[(polygon element, reversed), ...]``."""
        if depth > 50:
            raise InputError(f"{where}: surfaces nested more than 50 deep (an xlink cycle?)")
        name = local_name(el.tag)
        if name in POLYGONS:
            return [(el, reverse)]
        if name == "OrientableSurface":
            reverse = reverse ^ (el.get("orientation", "+").strip() == "-")
        elif name not in SURFACE_SETS:
            raise InputError(f"{where}: unsupported surface type gml:{name}")
        members = self.members(el, SURFACE_MEMBERS, where)
        if not members and name == "Tin":
            members = self.tin_triangles(el, where)
        out = []
        for m in members:
            out.extend(self.surface(m, where, reverse, depth + 1))
        return out

    def tin_triangles(self, tin: ET.Element, where: str) -> list[ET.Element]:
        """The triangles of a ``gml:Tin`` given by its ``gml:controlPoint`` only: the Delaunay
        triangulation of the points in plan, each triangle counter-clockwise seen from above
        (upward), as ``gml:Triangle`` elements of the Tin's namespace."""
        pts: list[tuple[float, float, float]] = []
        for cp in tin:
            if local_name(cp.tag) != "controlPoint":
                continue
            for e in cp.iter():
                if local_name(e.tag) in ("posList", "pos"):
                    pts.extend(_xyz((e.text or "").split(), self.dims.get(e, 3), where))
        pts = list(dict.fromkeys(pts))
        if len(pts) < 3:
            raise InputError(f"{where}: gml:Tin without triangle patches and fewer than 3 control points")
        from scipy.spatial import Delaunay, QhullError
        p = np.asarray(pts, dtype=np.float64)
        try:
            tri = Delaunay(p[:, :2]).simplices
        except (QhullError, ValueError):
            raise InputError(f"{where}: the control points of a gml:Tin lie on one line in plan") from None
        ns = tin.tag[: tin.tag.index("}") + 1] if tin.tag.startswith("{") else ""
        out = []
        for t in tri:
            a, b, c = p[t]
            if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0:
                t = t[[0, 2, 1]]
            el = ET.Element(f"{ns}Triangle")
            ring = ET.SubElement(ET.SubElement(el, f"{ns}exterior"), f"{ns}LinearRing")
            ET.SubElement(ring, f"{ns}posList").text = " ".join(repr(float(x)) for i in list(t) + [t[0]] for x in p[i])
            out.append(el)
        return out

    def polygon(self, poly: ET.Element, reverse: bool, loc: str) -> list[list[int]]:
        rings = []
        for part in poly:
            name = local_name(part.tag)
            if name not in ("exterior", "interior", "outerBoundaryIs", "innerBoundaryIs"):
                continue
            for ring in part:
                r = self.ring(ring, loc)
                if reverse:
                    r = r[:1] + r[1:][::-1]
                if name in ("exterior", "outerBoundaryIs"):
                    rings.insert(0, r)
                else:
                    rings.append(r)
        if not rings:
            raise InputError(f"{loc}: polygon without rings")
        return rings

    def ring(self, ring: ET.Element, loc: str) -> list[int]:
        if local_name(ring.tag) != "LinearRing":
            raise InputError(f"{loc}: unsupported ring type gml:{local_name(ring.tag)} (LinearRing expected)")
        pts = self.points(ring, loc)
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

    def points(self, ring: ET.Element, loc: str) -> list[tuple[float, float, float]]:
        pos_list = [e for e in ring if local_name(e.tag) == "posList"]
        if pos_list:
            values: list[str] = []
            dim = self.dims.get(pos_list[0], 3)
            for e in pos_list:
                values.extend((e.text or "").split())
            return _xyz(values, dim, loc)
        pos = [e for e in ring.iter() if local_name(e.tag) == "pos"]
        if pos:
            pts = []
            for e in pos:
                pts.extend(_xyz((e.text or "").split(), self.dims.get(e, 3), loc))
            return pts
        coords = [e for e in ring if local_name(e.tag) == "coordinates"]
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
