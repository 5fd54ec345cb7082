"""The names the writers used to import from here, re-exported from their own modules.

Each concept has its module now (issue 14):

- :mod:`.result`: :class:`ExportResult`, the one result type of every writer;
- :mod:`.paths`: safe file names inside the output folder, failed files set aside;
- :mod:`.polygons`: normals, areas, the wall-aligned plane basis, triangles, convex pieces;
- :mod:`.weld`: welding close vertices into their mean;
- :mod:`.zones`: the local origin and the zone shells (one closed envelope per part);
- :mod:`.uvalues`: the U-value a written face gets, and the fallback values;
- :mod:`.shellcheck`: the closed-and-outward check of a written zone.

Import from those modules in new code; this one keeps the older imports working.
"""
from __future__ import annotations

from .paths import _short_hash, not_written, output_path, safe_stem, set_aside_failed
from .polygons import (
    PLANAR_TOL, STRICT_SIN, _insert_dropped, _is_convex_2d, merge_convex, newell_normal, plane_basis,
    polygon_area3d, triangulate, unit,
)
from .result import ExportResult
from .shellcheck import _split_t_junctions, check_closed_outward, signed_volume
from .uvalues import FALLBACK_U
from .uvalues import positive_number as _number
from .weld import _clean_ring, weld
from .zones import (
    COLLINEAR_TOL, MIN_PIECE_AREA, SEMANTIC_CLASS, WELD_TOL, ZoneFace, ZoneShell, _drop_shared_collinear,
    _thermal, classify, drop_collinear, local_origin, zone_shells,
)

__all__ = [
    "WELD_TOL", "PLANAR_TOL", "COLLINEAR_TOL", "MIN_PIECE_AREA", "STRICT_SIN", "SEMANTIC_CLASS", "FALLBACK_U",
    "ExportResult", "safe_stem", "output_path", "not_written", "set_aside_failed", "local_origin",
    "newell_normal", "unit", "plane_basis", "polygon_area3d", "triangulate", "merge_convex", "ZoneFace",
    "ZoneShell", "weld", "drop_collinear", "classify", "zone_shells", "signed_volume", "check_closed_outward",
    # private names other modules and tests import
    "_short_hash", "_insert_dropped", "_is_convex_2d", "_clean_ring", "_drop_shared_collinear", "_thermal",
    "_number", "_split_t_junctions",
]
