"""Polygon-level checks (101-104, 201-208). STUB: to be implemented."""


def check_polygons(vertices, shell, tol):
    return []


def check_instance(building, obj, gi, geometry, tol):
    return []
