"""Readers for the mesh formats val3dity accepts: POLY (TetGen), OBJ and OFF.

Each file becomes one :class:`~lod2energy.model.Building` of type "GenericCityObject"
whose id is the file stem, holding the file's shell(s) as the 3D primitive chosen with
``primitive`` ("Solid", the default, "CompositeSurface" or "MultiSurface"). An OBJ file
with several ``o`` groups gives one geometry per group, as val3dity does. POLY inner
shells (``inner_shells``, a list of POLY paths, normals pointing inwards) become interior
shells of the Solid.

Vertices are kept as read: val3dity's snapping happens in the checks, per shell. A file
that cannot be parsed gives a :class:`~lod2energy.model.FeatureError` 901 (invalid
input), an empty primitive 902 (from the checks, or from the OBJ reader as val3dity), a
wrong option combination 903.
"""
from __future__ import annotations

import os
from typing import Iterator

import numpy as np

from lod2energy.errors import EmptyPrimitiveError, InputError, ParameterError
from lod2energy.io.shape import read_bounded
from lod2energy.model import Building, CityModel, CityObject, FeatureError, Geometry, Shell, Solid, Surface

PRIMITIVES = ("Solid", "CompositeSurface", "MultiSurface")


# ----------------------------------------------------------------------------- helpers

def _stem(path: str) -> str:
    base = os.path.basename(path)
    for suffix in (".poly", ".obj", ".off"):
        if base.lower().endswith(suffix):
            return base[: -len(suffix)]
    return os.path.splitext(base)[0]


def _read_text(path: str) -> str:
    data = read_bounded(path)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def _geometry(primitive: str, shells: list[list[list[list[int]]]]) -> Geometry:
    """A geometry from shells given as faces of rings of vertex indices (first = exterior)."""
    built = [Shell(tuple(Surface.from_lists(face) for face in sh)) for sh in shells]
    if primitive == "Solid":
        return Geometry("Solid", None, (Solid(tuple(built)),))
    return Geometry(primitive, None, (Solid((built[0],)),))


def _building(path: str, vertices: np.ndarray, geometries: list[Geometry], fmt: str) -> Building:
    oid = _stem(path)
    obj = CityObject(oid, "GenericCityObject", tuple(geometries))
    return Building(oid, "GenericCityObject", vertices, (obj,), {"source_format": fmt})


def _check_primitive(primitive: str) -> None:
    if primitive not in PRIMITIVES:
        raise ParameterError(f"primitive must be one of {', '.join(PRIMITIVES)}, not {primitive!r}")


def _result(path: str, fmt: str, make) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Run ``make() -> Building`` and wrap it (or its error) as a reader result."""
    model = CityModel(version=fmt, source=path, format=fmt)
    try:
        b = make()
    except InputError as e:
        return None, iter([FeatureError(None, e.code, str(e))])
    except ParameterError as e:
        return None, iter([FeatureError(None, e.code, str(e))])
    return model, iter([b])


def _finite(v: np.ndarray, path: str) -> np.ndarray:
    if v.size and not np.isfinite(v).all():
        raise InputError(f"{path}: non-finite (NaN/inf) coordinates")
    return v


# ----------------------------------------------------------------------------- POLY

class _Tokens:
    """Whitespace tokens of a text, line-aware (POLY facet headers end at the newline)."""

    def __init__(self, text: str, path: str):
        self.lines = [ln.split() for ln in text.splitlines()]
        self.li = 0
        self.ti = 0
        self.path = path

    def _skip_empty(self) -> None:
        while self.li < len(self.lines) and self.ti >= len(self.lines[self.li]):
            self.li += 1
            self.ti = 0

    def next(self, what: str) -> str:
        self._skip_empty()
        if self.li >= len(self.lines):
            raise InputError(f"{self.path}: unexpected end of file while reading {what}")
        tok = self.lines[self.li][self.ti]
        self.ti += 1
        return tok

    def int(self, what: str) -> int:
        tok = self.next(what)
        try:
            return int(tok)
        except ValueError:
            try:
                f = float(tok)
            except ValueError:
                raise InputError(f"{self.path}: expected an integer for {what}, found {tok!r}") from None
            if not f.is_integer():
                raise InputError(f"{self.path}: expected an integer for {what}, found {tok!r}") from None
            return int(f)

    def float(self, what: str) -> float:
        tok = self.next(what)
        try:
            return float(tok)
        except ValueError:
            raise InputError(f"{self.path}: expected a number for {what}, found {tok!r}") from None

    def rest_of_line(self) -> list[str]:
        if self.li >= len(self.lines):
            return []
        rest = self.lines[self.li][self.ti:]
        self.li += 1
        self.ti = 0
        return rest


def parse_poly(path: str) -> tuple[np.ndarray, list[list[list[int]]], list[int]]:
    """Vertices and faces of a TetGen POLY file, read as val3dity reads it.

    Facet lines are ``<#polygons> [#holes] [boundary marker]`` (TetGen manual); the hole
    point lines that follow the rings are skipped. (val3dity 2.6 takes the *last* number of
    that line as the number of holes, so it misreads a facet with both holes and a
    boundary marker; files without boundary markers read the same.) A ring given with
    ``-1`` points is a ring that is not closed (103).

    Returns
    -------
    vertices : (n, 3) float
    faces : list of faces, each a list of rings (lists of vertex indices; the indices are
        positions in the vertex list, as val3dity uses them)
    unclosed : list of int
        Faces with a ring marked ``-1`` (val3dity 103).

    Raises
    ------
    InputError
        Unparseable file or a vertex index out of range.
    """
    tk = _Tokens(_read_text(path), path)
    n = tk.int("the number of vertices")
    tk.rest_of_line()
    if n < 0:
        raise InputError(f"{path}: negative number of vertices")
    verts = np.empty((n, 3))
    for i in range(n):
        tk.int("a vertex id")
        verts[i] = (tk.float("x"), tk.float("y"), tk.float("z"))
        tk.rest_of_line()  # attributes / boundary marker
    nf = tk.int("the number of facets")
    tk.rest_of_line()
    faces: list[list[list[int]]] = []
    unclosed: list[int] = []
    for fi in range(nf):
        nrings = tk.int(f"the number of polygons of facet {fi}")
        header = tk.rest_of_line()
        try:
            nholes = int(header[0]) if header else 0
        except ValueError:
            raise InputError(f"{path}: bad facet header for facet {fi}: {header[0]!r}") from None
        rings = []
        bad = False
        for ri in range(max(nrings, 0)):
            k = tk.int(f"the number of points of a ring of facet {fi}")
            if k == -1:
                bad = True
                continue
            if k < 0:
                raise InputError(f"{path}: negative number of points in facet {fi}")
            rings.append([tk.int(f"a vertex index of facet {fi}") for _ in range(k)])
        for _ in range(max(nholes, 0)):
            tk.int("a hole id")
            tk.float("a hole x"), tk.float("a hole y"), tk.float("a hole z")
        if bad:
            unclosed.append(fi)
            continue
        for r in rings:
            for i in r:
                if i < 0 or i >= n:
                    raise InputError(f"{path}: facet {fi} uses vertex {i}, the file has {n} vertices")
        faces.append(rings)
    return _finite(verts, path), faces, unclosed


def read_poly(path: str, primitive: str = "Solid", inner_shells=()) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Read a POLY file (and optional POLY inner shells) as one building.

    Parameters
    ----------
    path : str
    primitive : {"Solid", "CompositeSurface", "MultiSurface"}
    inner_shells : sequence of str
        POLY files of interior shells (Solid only; 903 otherwise, as val3dity).
    """
    def make():
        _check_primitive(primitive)
        if inner_shells and primitive != "Solid":
            raise ParameterError("POLY files having inner shells can only be validated as Solid")
        verts, faces, unclosed = parse_poly(path)
        all_v = [verts]
        shells = [faces]
        errors = [(103, f"coid={_stem(path)}|geom=0|shell=0|face={fi}", "ring not closed") for fi in unclosed]
        offset = len(verts)
        for si, ipath in enumerate(inner_shells or (), start=1):
            iv, ifaces, iunclosed = parse_poly(ipath)
            shells.append([[[i + offset for i in r] for r in f] for f in ifaces])
            errors += [(103, f"coid={_stem(path)}|geom=0|shell={si}|face={fi}", "ring not closed") for fi in iunclosed]
            all_v.append(iv)
            offset += len(iv)
        b = _building(path, np.vstack(all_v), [_geometry(primitive, shells)], "POLY")
        if errors:
            b = b.with_provenance(input_errors=tuple(errors))
        return b
    return _result(path, "POLY", make)


# ----------------------------------------------------------------------------- OFF

def parse_off(path: str) -> tuple[np.ndarray, list[list[int]]]:
    """Vertices and faces of an OFF file.

    Line-based after the header, so that per-vertex or per-face colours (extra numbers at
    the end of a line) are ignored; ``#`` starts a comment. The header is ``OFF`` (also
    ``COFF``, ``NOFF``...), with the counts on the same or the next line.

    Raises
    ------
    InputError
        No ``OFF`` header, no vertex (val3dity: "not a valid OFF file"), a face without
        vertices, an index out of range, a truncated file.
    """
    lines = [ln.split("#", 1)[0].split() for ln in _read_text(path).splitlines()]
    lines = [ln for ln in lines if ln]
    if not lines or not lines[0][0].upper().endswith("OFF"):
        raise InputError(f"{path}: not a valid OFF file (no 'OFF' header)")
    head, li = lines[0][1:], 1
    if not head:
        if len(lines) < 2:
            raise InputError(f"{path}: not a valid OFF file (no counts line)")
        head, li = lines[1], 2
    try:
        n, nf = int(head[0]), int(head[1])
    except (ValueError, IndexError):
        raise InputError(f"{path}: not a valid OFF file (bad counts line)") from None
    if n <= 0:
        raise InputError(f"{path}: not a valid OFF file (no vertex)")
    if len(lines) < li + n:
        raise InputError(f"{path}: the file ends before its {n} vertices")
    try:
        verts = np.asarray([ln[:3] for ln in lines[li:li + n]], dtype=np.float64)
    except ValueError:
        raise InputError(f"{path}: bad vertex coordinates") from None
    if verts.shape != (n, 3):
        raise InputError(f"{path}: a vertex line has fewer than 3 coordinates")
    li += n
    if len(lines) < li + nf:
        raise InputError(f"{path}: the file ends before its {nf} faces")
    faces = []
    for fi, ln in enumerate(lines[li:li + nf]):
        try:
            k = int(ln[0])
            ring = [int(t) for t in ln[1:1 + k]]
        except ValueError:
            raise InputError(f"{path}: bad face {fi}") from None
        if k <= 0:
            raise InputError(f"{path}: some surfaces are not defined correctly or are empty (face {fi})")
        if len(ring) != k:
            raise InputError(f"{path}: face {fi} announces {k} vertices and has {len(ring)}")
        for i in ring:
            if i < 0 or i >= n:
                raise InputError(f"{path}: face {fi} uses vertex {i}, the file has {n} vertices")
        faces.append(ring)
    return _finite(verts, path), faces


def read_off(path: str, primitive: str = "Solid", inner_shells=()) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Read an OFF file as one building (one shell).

    val3dity: a file that does not start with ``OFF`` or has no vertex is invalid (901);
    a face with no vertex is invalid (901); no face at all is an empty primitive (902).
    """
    def make():
        _check_primitive(primitive)
        verts, faces = parse_off(path)
        return _building(path, verts, [_geometry(primitive, [[[f] for f in faces]])], "OFF")
    return _result(path, "OFF", make)


# ----------------------------------------------------------------------------- OBJ

def read_obj(path: str, primitive: str = "Solid", inner_shells=()) -> "tuple[CityModel | None, Iterator[Building | FeatureError]]":
    """Read an OBJ file as one building; each ``o`` group after faces starts a new geometry.

    Face indices are 1-based (negative ones count from the last vertex read); 0 or an
    index past the vertices read so far is invalid (901), as in val3dity. A file (or its
    last group) without faces is an empty primitive (902).
    """
    def make():
        _check_primitive(primitive)
        text = _read_text(path)
        verts: list[tuple[float, float, float]] = []
        groups: list[list[list[list[int]]]] = []
        cur: list[list[list[int]]] = []
        lines = text.splitlines()
        li = 0
        while li < len(lines):
            line = lines[li]
            li += 1
            if line.startswith("v "):
                parts = line.split()
                try:
                    verts.append((float(parts[1]), float(parts[2]), float(parts[3])))
                except (ValueError, IndexError):
                    raise InputError(f"{path} line {li}: bad vertex") from None
            elif line.startswith("o "):
                if cur:
                    groups.append(cur)
                    cur = []
            elif line.startswith("f "):
                toks = line.split()[1:]
                while toks and toks[-1] == "\\" and li < len(lines):
                    toks = toks[:-1] + lines[li].split()
                    li += 1
                ring = []
                for t in toks:
                    try:
                        idx = int(t.split("/", 1)[0])
                    except ValueError:
                        raise InputError(f"{path} line {li}: bad face index {t!r}") from None
                    if idx == 0:
                        raise InputError(f"{path} line {li}: OBJ files are 1-indexed, vertex '0' found")
                    if idx < 0:
                        idx = len(verts) + idx + 1
                        if idx <= 0:
                            raise InputError(f"{path} line {li}: relative vertex {t} does not exist")
                    if idx > len(verts):
                        raise InputError(f"{path} line {li}: vertex #{idx} doesn't exist in the input file")
                    ring.append(idx - 1)
                cur.append([ring])
        if not cur:
            raise EmptyPrimitiveError(f"{path}: some surfaces are not defined correctly or are empty")
        groups.append(cur)
        v = np.asarray(verts, dtype=np.float64).reshape(-1, 3)
        return _building(path, _finite(v, path), [_geometry(primitive, [g]) for g in groups], "OBJ")
    return _result(path, "OBJ", make)


def register(register_format) -> None:
    """Register the POLY, OBJ and OFF readers with :func:`lod2energy.io.register_format`."""
    register_format("POLY", (".poly",), read_poly)
    register_format("OBJ", (".obj",), read_obj)
    register_format("OFF", (".off",), read_off)
