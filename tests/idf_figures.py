"""Areas by thermal boundary and UA recomputed from a written IDF's own surfaces and constructions.

Independent of the writer: the IDF is parsed with eppy (a test dependency), each surface's
area is its polygon's, each opaque construction's U is 1 / (its layers' R summed: a no-mass
layer's R, a material's thickness / conductivity), surface films left out, and a window's U
is its simple glazing system's U-factor.
"""
from __future__ import annotations

import numpy as np

from export_helpers import eppy_idf

AREA_KEYS = ("roof", "wall", "ground", "floor_exposed", "window", "adiabatic")


def _area(obj) -> float:
    pts = np.array([[float(c) for c in v] for v in obj.coords])
    n = np.zeros(3)
    for a, b in zip(pts, np.roll(pts, -1, axis=0)):
        n += np.cross(a, b)
    return 0.5 * float(np.linalg.norm(n))


def _u_values(idf) -> dict[str, float]:
    r = {}
    for m in idf.idfobjects["MATERIAL:NOMASS"]:
        r[m.Name.upper()] = float(m.Thermal_Resistance)
    for m in idf.idfobjects["MATERIAL"]:
        r[m.Name.upper()] = float(m.Thickness) / float(m.Conductivity)
    glazing = {m.Name.upper(): float(m.UFactor) for m in idf.idfobjects["WINDOWMATERIAL:SIMPLEGLAZINGSYSTEM"]}
    out = {}
    for c in idf.idfobjects["CONSTRUCTION"]:
        layers = [f.upper() for f in c.fieldvalues[2:] if str(f).strip()]
        if len(layers) == 1 and layers[0] in glazing:
            out[c.Name.upper()] = glazing[layers[0]]
        else:
            out[c.Name.upper()] = 1.0 / sum(r[x] for x in layers)
    return out


def idf_figures(path) -> dict:
    """``{"areas": {roof, wall, ground, floor_exposed, window, adiabatic}, "UA": W/K}`` of
    every surface of the IDF at ``path`` (one building's file)."""
    idf = eppy_idf(path)
    u = _u_values(idf)
    areas = dict.fromkeys(AREA_KEYS, 0.0)
    ua = 0.0
    glazed: dict[str, float] = {}
    for w in idf.idfobjects["FENESTRATIONSURFACE:DETAILED"]:
        if str(w.Surface_Type).upper() != "WINDOW":
            continue
        a = _area(w)
        areas["window"] += a
        ua += u[w.Construction_Name.upper()] * a
        glazed[w.Building_Surface_Name.upper()] = glazed.get(w.Building_Surface_Name.upper(), 0.0) + a
    for s in idf.idfobjects["BUILDINGSURFACE:DETAILED"]:
        b, t = s.Outside_Boundary_Condition.upper(), s.Surface_Type.upper()
        if b == "SURFACE":
            continue
        a = _area(s)
        cls = ("adiabatic" if b == "ADIABATIC" else "ground" if b.startswith("GROUND") else
               "roof" if t in ("ROOF", "CEILING") else "floor_exposed" if t == "FLOOR" else "wall")
        areas[cls] += a
        if cls != "adiabatic":
            ua += u[s.Construction_Name.upper()] * (a - glazed.get(s.Name.upper(), 0.0))
    return {"areas": areas, "UA": ua}
