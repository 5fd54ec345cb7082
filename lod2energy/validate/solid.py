"""Solid-level checks (401-405, 501-503, 601). STUB: to be implemented."""


def check_solid(vertices, solid, tol):
    return []


def check_multisolid(vertices, geometry, tol):
    return []


def check_parts_overlap(building, tol):
    return []
