"""Geometry templates of CityJSON GeometryInstances, resolved for validation.

val3dity validates the template geometry itself (``vertices-templates``, no transformation)
once per instance; :func:`template_geometry` finds and parses it (with the reader's own
geometry parser), :func:`lod2energy.validate.checks.check_instance` validates it.
"""
from __future__ import annotations

import numpy as np

from lod2energy.errors import InputError
from lod2energy.io.cityjson import _Collector, _parse_geometry  # the reader's own parser

__all__ = ["template_geometry", "parse_template"]


def template_geometry(building, geometry):
    """``(vertices (n, 3), Geometry)`` of the template an instance refers to, or None."""
    raw = geometry.raw or {}
    t = raw.get("template")
    templates = (building.provenance or {}).get("geometry_templates")
    if not isinstance(t, int) or isinstance(t, bool) or not templates:
        return None
    return parse_template(templates, t)


def parse_template(templates, index: int):
    """Parse template ``index`` of a CityJSON ``geometry-templates`` object, or None."""
    try:
        tlist = templates.get("templates") or []
        tv = np.asarray(templates.get("vertices-templates") or [], dtype=np.float64).reshape(-1, 3)
        g = dict(tlist[index])
    except (TypeError, ValueError, IndexError, AttributeError):
        return None
    g.setdefault("lod", "0")
    try:
        geom = _parse_geometry(g, _Collector(len(tv)), f"template={index}")
    except InputError:
        return None
    if not geom.is_polygonal:
        return None
    return tv, geom
