"""Defects: val3dity's numbers and names, plus the project's own ranges, and the :class:`Defect` record.

val3dity codes (101-904) keep their meaning exactly. lod2energy's own checks use:
1001-1099 energy compliance, 1101-1199 semantics, 1201-1299 thermal values.
"""
from __future__ import annotations

from dataclasses import dataclass

VAL3DITY = {
    101: "TOO_FEW_POINTS",
    102: "CONSECUTIVE_POINTS_SAME",
    103: "RING_NOT_CLOSED",
    104: "RING_SELF_INTERSECTION",
    201: "INTERSECTION_RINGS",
    202: "DUPLICATED_RINGS",
    203: "NON_PLANAR_POLYGON_DISTANCE_PLANE",
    204: "NON_PLANAR_POLYGON_NORMALS_DEVIATION",
    205: "POLYGON_INTERIOR_DISCONNECTED",
    206: "INNER_RING_OUTSIDE",
    207: "INNER_RINGS_NESTED",
    208: "ORIENTATION_RINGS_SAME",
    300: "NOT_VALID_2_MANIFOLD",
    301: "TOO_FEW_POLYGONS",
    302: "SHELL_NOT_CLOSED",
    303: "NON_MANIFOLD_CASE",
    304: "NON_MANIFOLD_EDGE",
    305: "MULTIPLE_CONNECTED_COMPONENTS",
    306: "SHELL_SELF_INTERSECTION",
    307: "POLYGON_WRONG_ORIENTATION",
    401: "INTERSECTION_SHELLS",
    402: "DUPLICATED_SHELLS",
    403: "INNER_SHELL_OUTSIDE",
    404: "SOLID_INTERIOR_DISCONNECTED",
    405: "WRONG_ORIENTATION_SHELL",
    501: "INTERSECTION_SOLIDS",
    502: "DUPLICATED_SOLIDS",
    503: "DISCONNECTED_SOLIDS",
    601: "BUILDINGPARTS_OVERLAP",
    901: "INVALID_INPUT_FILE",
    902: "EMPTY_PRIMITIVE",
    903: "WRONG_INPUT_PARAMETERS",
    904: "FORMAT_NOT_SUPPORTED",
    999: "UNKNOWN_ERROR",
}

OWN = {
    1001: "ENERGY_NOT_CLOSED_2_MANIFOLD",
    1002: "ENERGY_NORMALS_NOT_OUTWARD",
    1003: "ENERGY_DEGENERATE_OR_SLIVER_FACE",
    1101: "SEMANTIC_ROOF_FACING_DOWN",
    1102: "SEMANTIC_GROUND_NOT_AT_BOTTOM",
    1103: "SEMANTIC_WALL_ABOVE_ROOF",
    1104: "SEMANTIC_FLOOR_FACING_UP",
    1201: "THERMAL_U_VALUE_MISSING",
    1202: "THERMAL_U_VALUE_OUT_OF_RANGE",
}

NAMES = {**VAL3DITY, **OWN}


def name(code: int) -> str:
    """Name of ``code`` ("UNKNOWN_ERROR" for codes nobody defined)."""
    return NAMES.get(int(code), "UNKNOWN_ERROR")


def val3dity_valid(codes) -> bool:
    """No val3dity error but 601 among ``codes`` (as ``lod2energy validate`` counts valid)."""
    return all(c == 601 or c >= 1000 for c in codes)


@dataclass(frozen=True, order=True)
class Defect:
    """One error found by a check.

    Parameters
    ----------
    code : int
        val3dity code (101-904) or a project code (1001+).
    location : str
        val3dity-style ``coid=..|geom=..|shell=..|face=..``.
    info : str
        Free text (measured value and tolerance, where the hole is, ...).
    """

    code: int
    location: str = ""
    info: str = ""

    @property
    def description(self) -> str:
        return name(self.code)

    def to_json(self) -> dict:
        return {"code": self.code, "description": self.description, "id": self.location, "info": self.info}
