"""The figures the hand-off writers (URBANopt, CEA) give each building, from our own stages.

One :class:`HandoffFacts` per prepared building, in metres and square metres, taken from what
the energy model uses rather than from an extrusion of the footprint:

- **storeys** and the storey height: :func:`lod2energy.thermal.storeys.storeys` (the
  ``--buildings`` row, the attributes, else the LoD2 geometry), the same count the IDF zones;
- **footprint**: :func:`lod2energy.exporters.footprint.footprint` (the union of the
  envelope's projections), its area and perimeter;
- **height**: ridge minus ground of the envelope (:class:`lod2energy.thermal.storeys.RoofLevels`);
- **volume**: the thermal stage's (``provenance["thermal"]["volume"]``);
- **floor area**: the gross floor area of the storeys as the IDF's storey zoning counts them,
  per Building/BuildingPart: its section at its own ground level plus the floors of its upper
  storeys (:func:`lod2energy.energy.zones.storeys.upper_floor_area`: each the horizontal
  section of the real envelope at the storey's floor level, so a set-back top storey or a
  lower wing counts only where it is; the attic floor only with ``--attic conditioned``);
- **use** and **year**: :func:`lod2energy.thermal.use.recorded_use` and the thermal stage's year.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from lod2energy.energy.pieces import Piece
from lod2energy.energy.zones.cut import section_area
from lod2energy.energy.zones.shells import classify
from lod2energy.energy.zones.storeys import upper_floor_area
from lod2energy.exporters.footprint import footprint, footprint_geometry
from lod2energy.geometry import newell_normal
from lod2energy.model import Building
from lod2energy.site import SiteError
from lod2energy.thermal.storeys import Storeys, storeys
from lod2energy.thermal.use import recorded_use


@dataclass(frozen=True)
class HandoffFacts:
    """What the hand-off writers say of one building.

    Attributes
    ----------
    id : str
    use, use_source : str
        Our use type (:data:`lod2energy.config.USE_TYPES`) and where it came from.
    storeys : int
        Storeys above ground, a tall attic included (:class:`~lod2energy.thermal.storeys.Storeys`).
    storeys_source : str
    storey_height : float, m
    attic : bool
        The roof space counts as a storey.
    ground, ridge : float, m
        Lowest and highest point of the envelope (input vertical datum).
    footprint : shapely Polygon or MultiPolygon
        In the building's xy coordinates (m).
    footprint_area : float, m2
    footprint_perimeter : float, m
        Of the outer rings (courtyards not counted).
    volume : float or None, m3
    floor_area : float, m2
        Gross floor area of the storeys (see the module docstring).
    year : int or None
        Year of construction (None: unknown).
    year_source : str or None
    """

    id: str
    use: str
    use_source: str
    storeys: int
    storeys_source: str
    storey_height: float
    attic: bool
    ground: float
    ridge: float
    footprint: Any
    footprint_area: float
    footprint_perimeter: float
    volume: float | None
    floor_area: float
    year: int | None
    year_source: str | None

    @property
    def height(self) -> float:
        """Ridge over ground, m."""
        return self.ridge - self.ground

    @property
    def prism_height(self) -> float:
        """Height of the prism on the footprint with the building's volume, m (the height when
        the volume is unknown)."""
        if self.volume and self.footprint_area > 0:
            return min(self.volume / self.footprint_area, self.height)
        return self.height


def part_pieces(b: Building, lod: str | None = None) -> list[tuple[str, list[Piece]]]:
    """The faces of each envelope object's exterior shells as :class:`Piece` s (outer rings,
    m, kinds by :func:`lod2energy.energy.zones.shells.classify`): ``(object id, pieces)`` per object."""
    v = np.asarray(b.vertices, dtype=np.float64)
    out = []
    for o, _, g in b.envelope(lod):
        pieces = []
        for _, hi, fi, s in g.iter_surfaces():
            if hi > 0 or len(s.rings[0]) < 3:
                continue
            pts = v[np.asarray(s.rings[0], dtype=np.intp)]
            if np.all(np.isfinite(pts)):
                pieces.append(Piece(pts, classify(g.semantic_type(s), newell_normal(pts)), "Outdoors", 0.0, fi))
        if pieces:
            out.append((o.id, pieces))
    return out


def floor_area(parts: list[tuple[str, list[Piece]]], storey_height: float, attic_mode: str = "unconditioned",
               plan: Storeys | None = None) -> float:
    """Gross floor area (m2) of the storeys of envelope objects ``parts`` (:func:`part_pieces`):
    each object's section at its ground level plus its upper floors as the IDF's storey zoning
    counts them (:func:`lod2energy.energy.zones.storeys.upper_floor_area`, with each object's
    storeys of the building's ``plan``)."""
    total = 0.0
    for oid, pieces in parts:
        polys = [p.points for p in pieces]
        ground = float(min(p[:, 2].min() for p in polys))
        part = plan.part(oid) if plan is not None else None
        total += section_area(polys, ground) + upper_floor_area(pieces, storey_height, attic_mode, part)
    return float(total)


def facts(b: Building, use: str | None = None, lod: str | None = None,
          attic_mode: str = "unconditioned", fp=None) -> HandoffFacts | None:
    """The :class:`HandoffFacts` of a prepared building; None when it has no footprint.

    Parameters
    ----------
    b : Building
        Prepared (``provenance["thermal"]``), coordinates in metres.
    use : str, optional
        The ``--use`` override.
    lod : str, optional
    attic_mode : {"unconditioned", "conditioned"}
        ``--attic``: whether the attic floor counts in the floor area.
    fp : shapely Polygon or MultiPolygon, optional
        :func:`~lod2energy.exporters.footprint.footprint` of ``b`` when the caller has it.
    """
    fp = footprint(b, lod) if fp is None else fp
    if fp is None:
        return None
    u = recorded_use(b, use)
    st = storeys(b, u.type, lod)
    parts = part_pieces(b, lod)
    if not parts:
        return None
    allz = np.concatenate([p.points[:, 2] for _, ps in parts for p in ps])
    ground = st.levels.ground if st.levels is not None else float(allz.min())
    ridge = st.levels.ridge if st.levels is not None else float(allz.max())
    floor = floor_area(parts, float(st.storey_height), attic_mode, st)
    thermal = b.provenance.get("thermal") or {}
    vol = thermal.get("volume")
    year_fact = ((thermal.get("facts") or {}).get("year") or {})
    year = thermal.get("year_of_construction")
    return HandoffFacts(str(b.id), u.type, u.source, int(st.count), st.source, float(st.storey_height),
                        bool(st.attic), float(ground), float(ridge), fp, float(fp.area),
                        float(sum(p.exterior.length for p in getattr(fp, "geoms", [fp]))),
                        float(vol) if vol else None, floor, int(year) if year is not None else None,
                        year_fact.get("source") if year is not None else None)


#: Why a building without a footprint is left out of a hand-off.
NO_FOOTPRINT = "no face with a projected area"


def placed(b: Building, crs: Any = None, frame=None, lod: str | None = None, use: str | None = None,
           attic_mode: str = "unconditioned") -> tuple[dict | None, HandoffFacts | None, str | None]:
    """``(footprint geometry in WGS84, facts, None)`` of ``b``, or ``(None, None, why)`` when it
    cannot be placed on the Earth or has no footprint (:func:`footprint_geometry`, :func:`facts`)."""
    fp = footprint(b, lod)  # once, for the geometry and the facts
    try:
        geom = footprint_geometry(b, crs, frame, lod, fp=fp)
    except SiteError as e:
        return None, None, str(e)
    h = facts(b, use, lod, attic_mode, fp=fp) if geom is not None else None
    return (geom, h, None) if h is not None else (None, None, NO_FOOTPRINT)
