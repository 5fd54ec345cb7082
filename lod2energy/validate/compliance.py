"""Energy compliance of a building: the five conditions an energy model needs.

(i) closed 2-manifold envelope (``N_b = N_nm = 0``, no 302/303/305);
(ii) normals consistently outward (coherent orientation, positive volume per shell, no 307/405);
(iii) no degenerate, self-intersecting or sliver face (area <= ``sliver_area``; 101/102/104/306);
(iv) every face labelled Roof/Wall/Ground (Closure, OuterCeiling, OuterFloor also accepted);
(v) every surface with a positive U-value.

(iv) and (v) are assessed only once labels and U-values have been assigned (``assess_labels``,
``assess_u_values``); until then they are reported as "not assessed" (``None``), never true.
"""
from __future__ import annotations

from typing import Iterable

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.graph import FaceGraph, building_graphs
from lod2energy.model import Building, lod_key
from lod2energy.validate.codes import Defect

LABELS = ("RoofSurface", "WallSurface", "GroundSurface", "ClosureSurface",
          "OuterCeilingSurface", "OuterFloorSurface", "Window", "Door")
_CLOSED_CODES = {300, 301, 302, 303, 305}
_ORIENT_CODES = {307, 405}
_DEGENERATE_CODES = {101, 102, 104, 306}
#: An envelope smaller than this in every direction (m) or enclosing less than
#: :data:`MIN_VOLUME` (m3) is no building: input collapsed to centimetres (a wrong scale or
#: CRS) must not be reported compliant, however closed and clean it is.
MIN_EXTENT = 0.5
MIN_VOLUME = 0.1


def envelope_extent(b: Building, lod: str | None) -> float:
    """Largest side (m) of the bounding box of the envelope's vertices at ``lod`` (0 without any)."""
    idx = [r for ref in b.shells(lod) for s in ref.shell.surfaces for r in s.rings]
    if not idx or not len(b.vertices):
        return 0.0
    p = b.vertices[np.unique(np.concatenate(idx))]
    if not len(p):  # rings without a vertex
        return 0.0
    return float((p.max(axis=0) - p.min(axis=0)).max())


def _energy_locations(b: Building, lod: str | None) -> set[str]:
    return {f"coid={o.id}|geom={gi}" for o, gi, _ in b.envelope(lod)}


def _codes_on(defects: Iterable[Defect], prefixes: set[str]) -> set[int]:
    out = set()
    for d in defects:
        for loc in d.location.split("&&"):
            head = "|".join(loc.split("|")[:2])
            if head in prefixes:
                out.add(d.code)
    return out


def labels_complete(b: Building, lod: str | None = None) -> bool:
    """Every envelope face carries one of :data:`LABELS`."""
    refs = b.shells(lod)
    return bool(refs) and all(r.geometry.semantic_type(s) in LABELS for r in refs for s in r.shell.surfaces)


def u_values_complete(b: Building, lod: str | None = None) -> bool:
    """Every envelope face's semantic surface has a positive ``uValue`` (W/(m2 K))."""
    refs = b.shells(lod)
    for r in refs:
        for s in r.shell.surfaces:
            if s.semantic is None or s.semantic >= len(r.geometry.semantic_surfaces):
                return False
            u = r.geometry.semantic_surfaces[s.semantic].get("uValue")
            if not isinstance(u, (int, float)) or not np.isfinite(u) or u <= 0:
                return False
    return bool(refs)


def energy_compliance(b: Building, defects: Iterable[Defect], graph: FaceGraph | None = None,
                      lod: str | None = None, tol: Tolerances = DEFAULT,
                      assess_labels: bool = False, assess_u_values: bool = False) -> dict:
    """The compliance block of the report for one building.

    Returns
    -------
    dict
        ``closed_2manifold``, ``outward_normals``, ``no_degenerate_faces``, ``labelled``,
        ``u_values`` (bool, or None when not assessed), ``compliant`` (True only when all five
        hold), ``N_b``, ``N_nm``, ``status``, ``lod``, ``volume`` (m3) and ``reasons``.
    """
    lod = lod if lod is not None else b.default_lod()
    graph = graph if graph is not None else building_graphs([b], lod, tol)[0]
    defects = list(defects)
    codes = _codes_on(defects, _energy_locations(b, lod))
    codes |= {d.code for d in defects if d.code in (901, 902)}
    reasons = []
    has_faces = graph.n_faces > 0
    # LoD0 (footprint, roof outline) is no volume: the repair ladder leaves it alone, so the
    # geometric failures below only restate that; say it once, plainly
    flat_lod = has_faces and lod is not None and lod_key(lod) < 1
    closed = has_faces and graph.n_boundary == 0 and graph.n_nonmanifold == 0 and not (codes & _CLOSED_CODES)
    if not has_faces:
        reasons.append("no envelope geometry")
    elif flat_lod:
        reasons.append(f"only LoD{lod} geometry (footprint or roof outline, not a volume): no LoD >= 1 "
                       "envelope to repair into a closed solid")
    elif not closed:
        reasons.append(f"not a closed 2-manifold (N_b={graph.n_boundary}, N_nm={graph.n_nonmanifold})")
    vols = graph.shell_volumes()
    outward = has_faces and graph.n_inconsistent == 0 and bool(len(vols)) and bool((vols > 0).all()) \
        and not (codes & _ORIENT_CODES)
    if has_faces and not outward and not flat_lod:
        reasons.append("normals not consistently outward")
    n_degen = int(graph.x[:, 5].sum()) if has_faces else 0
    clean = has_faces and n_degen == 0 and not (codes & _DEGENERATE_CODES)
    if has_faces and not clean and not flat_lod:
        reasons.append(f"degenerate, sliver or self-intersecting faces ({n_degen} degenerate/sliver)")
    volume = float(vols.sum()) if len(vols) else 0.0
    extent = envelope_extent(b, lod) if has_faces and not flat_lod else 0.0
    sized = has_faces and not flat_lod and extent >= MIN_EXTENT and volume >= MIN_VOLUME
    if has_faces and not flat_lod and not sized:
        reasons.append(f"envelope collapsed to {extent:.3g} m across, {volume:.3g} m3 "
                       f"(a building is at least {MIN_EXTENT} m and {MIN_VOLUME} m3: wrong scale or CRS?)")
    labelled = labels_complete(b, lod) if assess_labels else None
    if labelled is False:
        reasons.append("faces without a Roof/Wall/Ground label")
    uvals = u_values_complete(b, lod) if assess_u_values else None
    if uvals is False:
        reasons.append("surfaces without a U-value")
    if labelled is None or uvals is None:
        reasons.append("labels and U-values not assessed yet" if labelled is None and uvals is None
                       else ("labels not assessed yet" if labelled is None else "U-values not assessed yet"))
    compliant = bool(closed and outward and clean and sized and labelled is True and uvals is True)
    return {
        "lod": lod,
        "closed_2manifold": bool(closed),
        "outward_normals": bool(outward),
        "no_degenerate_faces": bool(clean),
        "labelled": labelled,
        "u_values": uvals,
        "compliant": compliant,
        "plausible_size": bool(sized),
        "geometry_ready": bool(closed and outward and clean and sized),
        "N_b": graph.n_boundary,
        "N_nm": graph.n_nonmanifold,
        "status": graph.status,
        "volume": volume,
        "reasons": reasons,
    }
