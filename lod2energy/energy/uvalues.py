"""The U-value a written face gets: its own, else the building's table, else a fallback.

The thermal stage (:mod:`lod2energy.thermal`) puts a ``uValue`` on every semantic surface and
a table of U-values per element class in ``provenance["thermal"]``; a writer falls back to
:data:`FALLBACK_U` only when both are missing, and reports every such use as a warning.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

#: U-values (W/(m2 K)) used only when neither the surface nor ``provenance["thermal"]`` has one;
#: every use is reported as a warning of the export.
FALLBACK_U = {"roof": 0.4, "wall": 0.5, "ground": 0.5, "floor": 0.5, "window": 2.8}


def positive_number(x: Any) -> float | None:
    """``x`` as a finite positive float, else None."""
    try:
        f = float(x)
    except (TypeError, ValueError):
        return None
    return f if math.isfinite(f) and f > 0 else None


def face_u_value(semantic: Any, kind: str, u_table: Mapping) -> tuple[float, bool]:
    """U-value of one face, W/(m2 K), and whether it is the fallback.

    Parameters
    ----------
    semantic : mapping or None
        The face's semantic surface (its ``uValue``).
    kind : {"roof", "wall", "ground", "floor"}
        The face's exporter class (an outdoor floor takes the ground's table value).
    u_table : mapping
        ``provenance["thermal"]["u_values"]``: W/(m2 K) per class.
    """
    u = positive_number(semantic.get("uValue")) if isinstance(semantic, Mapping) else None
    if u is None:
        u = positive_number(u_table.get(kind if kind != "floor" else "ground"))
    if u is None:
        return FALLBACK_U[kind], True
    return u, False


def window_u_value(u_table: Mapping) -> float:
    """The window U-value of a building's table, W/(m2 K), else the fallback."""
    u = positive_number(u_table.get("window"))
    return FALLBACK_U["window"] if u is None else u
