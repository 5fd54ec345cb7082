"""The repair ladder: least invasive stage first, re-validating after each, per building.

Stages (:data:`STAGES`): ``valid`` (untouched) -> ``cleanup`` (0) -> ``orientation`` (1) ->
``holefill`` (2, "Output A") -> ``refill`` (3, "Output A+", with :func:`unpinch` first) ->
``roofs`` (the input as a 2.5D model: prisms under every roof face, kept only when the input's
vertices lie within 10 cm of it on average) -> ``alphashape`` (4) -> ``footprint`` (5) ->
``hull`` (6) -> ``irreparable`` (7, the original is kept). ``roofs`` is a global
reconstruction but keeps every roof plane and wall line of a 2.5D building, so it moves the
geometry far less than an alpha wrap and is tried before it. The first
result that is a closed, outward 2-manifold without degenerate, sliver or crossing faces and
without a val3dity-level error (601 aside) is kept.

A Solid the validator finds valid (:mod:`lod2energy.repair.verdict`: the codes of
``lod2energy validate``) is kept as it is: only the project's energy codes (a sliver) let the
local stages touch it, and never a global one. A repaired BuildingPart that overlaps its
neighbour (601) where the input did not, and cannot be separated from it, is refused.

Every Building/BuildingPart geometry of LoD >= 1 (or of ``lod`` when given) that fails the
criterion is replaced by a closed Solid at the same LoD; faces derived from an input face keep
its semantic index, new faces have none. Parts stay separate solids unless ``merge_parts``.
"""
from __future__ import annotations

import time
from collections import Counter
from dataclasses import replace
from typing import Iterable, Iterator, Mapping

import numpy as np

from lod2energy import cache
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.model import (
    BUILDING_TYPES, Building, FeatureError, Geometry, frozen_mapping,
)
from lod2energy.polymesh import PolyMesh, compact, face_area, topology
from lod2energy.repair.accept import grid_rounding, is_repaired, output_grid, repair_verdict, val3dity_codes
from lod2energy.repair.alphashape import alpha_repair
from lod2energy.repair.cleanup import (
    clean_rings, cleanup, desliver, drop_degenerate, merge_slivers, snap_vertices,
)
from lod2energy.repair.convert import geometry_of_mesh, mesh_of_geometry
from lod2energy.repair.footprint import convex_hull, extrude_footprint
from lod2energy.repair.holefill import fill_holes
from lod2energy.repair.metrics import fidelity
from lod2energy.repair.orientation import orient
from lod2energy.repair.parts import keep_parts_apart, merge_overlapping_parts, overlapping_parts
from lod2energy.repair.plausible import closed_volume, implausible, not_hollow
from lod2energy.repair.verdict import (
    _bounds_volume, input_codes, refused, targets as _targets, verdicts,
)
from lod2energy.repair.refill import close, refill
from lod2energy.repair.roofs import ROOF_MODEL_MAX_DISPLACEMENT, roof_model
from lod2energy.repair.unpinch import unpinch
from lod2energy.validate.closed import shell_defects
from lod2energy.validate.checks import validate_building, validate_geometry
from lod2energy.validate.codes import val3dity_valid

STAGES = ("valid", "cleanup", "orientation", "holefill", "refill", "roofs", "alphashape", "footprint",
          "hull", "irreparable")
LOCAL = ("cleanup", "orientation", "holefill", "refill")
GLOBAL = ("roofs", "alphashape", "footprint", "hull")
DEFAULT_TIMEOUT = 30.0
#: Seconds the alpha-shape search gets after the budget is spent (the time limit escalates
#: to a bounded global reconstruction rather than straight to the convex hull).
GLOBAL_MIN_SECONDS = 25.0

#: Meshes of :func:`_once` kept per process (a building's few geometries, each a few steps).
KEPT_STEPS = 16


def _once(step, m: PolyMesh, tol: Tolerances) -> PolyMesh:
    """``step(m, tol)`` (:func:`cleanup`, :func:`close`) once per content of ``m``: the ladder, the
    global stages it may be re-entered at and the fidelity's envelope (:func:`_envelope`, the
    ladder's hole-filled input again) all clean the same input; kept in ``cache``'s table
    ``repair.ladder-steps``."""
    key = (step.__name__, cache.digest(m.vertices, m.faces, tol))
    return cache.remember("repair.ladder-steps", key, lambda: step(m, tol), KEPT_STEPS)


def _valid_or_none(m: PolyMesh | None, lod, tol: Tolerances) -> PolyMesh | None:
    return m if is_repaired(m, lod, tol) else None


# ----------------------------------------------------------------------------- the ladder

def ladder(m: PolyMesh, lod, tol: Tolerances, deadline: float,
           keep: bool = False) -> tuple[str, PolyMesh | None, list[str]]:
    """Run the stages on one shell.

    ``keep``: ``m`` is valid as it is (no val3dity code, only the project's energy codes such
    as a sliver): only the local stages may improve it, and when none does the answer is
    ``("valid", None, log)``, the input kept; a valid input is never replaced.

    Returns
    -------
    stage : str
    result : PolyMesh or None
        None for "irreparable".
    log : list of str
        One line per stage tried.
    """
    log: list[str] = []

    def ok(name, r):
        why = repair_verdict(r, lod, tol)
        log.append(f"{name}: {why or 'ok'}")
        return why is None

    def late():
        return time.monotonic() > deadline

    m0 = _once(cleanup, m, tol)
    if ok("cleanup", m0):
        return "cleanup", m0, log
    m1 = orient(m0)
    if ok("orientation", m1):
        return "orientation", m1, log
    m2 = _once(close, m1, tol)
    if not topology(m2).boundary and shell_defects([m2], tol, first_only=True)[0]:
        # filled faces may leave new slivers or T-junctions: one more clean-up round
        m2b = _once(close, _once(cleanup, m2, tol), tol)
        if ok("holefill", m2b):
            return "holefill", m2b, log
    if ok("holefill", m2):
        return "holefill", m2, log
    if not late():
        def accept(r):
            return is_repaired(r, lod, tol)
        # sheets touching at a non-manifold edge or vertex: separate them (or join them by
        # a thin bridge) by a few millimetres before cutting anything out
        m3 = first = None
        for bridge in (False, True):
            u = unpinch(m2, tol, bridge=bridge)
            if u is None:
                continue
            first = first or u
            for cand in (u, _once(close, _once(cleanup, u, tol), tol)):
                if accept(cand):
                    m3 = cand
                    break
            if m3 is not None:
                break
        if m3 is None:
            m3 = refill(m2, tol, accept=accept)
        if m3 is None and first is not None and not late():
            m3 = refill(close(first, tol), tol, accept=accept)
        if m3 is None and not late():
            m3 = refill(m1, tol, accept=accept)
        if ok("refill", m3):
            return "refill", m3, log
    # a sliver is an energy-compliance defect, not a val3dity one: rather than trading a
    # 1 cm2 face for a global reconstruction, keep the least invasive closed, valid result
    # and report the sliver (1003); the input itself comes first when only slivers fail it
    soft = replace(tol, sliver_area=0.0)
    raw = orient(snap_vertices(m, tol.snap_tol))
    kept = None
    for name, cand in (("cleanup", m0), ("orientation", raw), ("orientation", m1), ("holefill", m2)):
        if not is_repaired(cand, lod, soft):
            continue
        fixed = desliver(cand, tol, lambda r: is_repaired(r, lod, tol)) if not late() else None
        if fixed is not None:
            log.append(f"{name}: ok once its slivers are collapsed")
            return name, fixed, log
        n = sum(face_area(cand.vertices, f) <= tol.sliver_area for f in cand.faces)
        if kept is None or n < kept[0]:
            kept = (n, name, cand)
    if kept is not None:
        log.append(f"{kept[1]}: ok except {kept[0]} sliver(s) (1003 kept)")
        return kept[1], kept[2], log
    if keep:
        log.append("valid: kept as it is (a valid input is never replaced)")
        return "valid", None, log
    return global_stages(m0, lod, tol, deadline, log)


def global_stages(m0: PolyMesh, lod, tol: Tolerances, deadline: float,
                  log: list[str]) -> tuple[str, PolyMesh | None, list[str]]:
    """The global end of the ladder on a cleaned shell: 2.5D roof model, alpha shapes,
    footprint extrusion, convex hull; "irreparable" when none is valid."""
    def ok(name, r):
        why = repair_verdict(r, lod, tol)
        log.append(f"{name}: {why or 'ok'}")
        return why is None

    if time.monotonic() <= deadline:
        m4r = roof_model(m0, lod, tol)
        if m4r is not None and ok("roofs", m4r):
            return "roofs", m4r, log
    # escalation: even when the local stages used up the budget, one bounded alpha search
    # runs before the convex hull (which fills courtyards and L-shapes)
    alpha_deadline = max(deadline, time.monotonic() + GLOBAL_MIN_SECONDS)
    m4 = alpha_repair(m0, tol, deadline=alpha_deadline,
                      accept=lambda r: not val3dity_codes(r, lod, tol))
    if ok("alphashape", m4):
        return "alphashape", m4, log
    m5 = extrude_footprint(m0)
    if ok("footprint", m5):
        return "footprint", m5, log
    m6 = convex_hull(m0)
    if ok("hull", m6):
        return "hull", m6, log
    return "irreparable", None, log


#: A remove-and-refill result whose volumetric IoU with the input is below this has cut out
#: more than a corrupted neighbourhood: the global stages are tried too and the closer result
#: is kept.
REFILL_MIN_IOU = 0.9

def _clean_surfaces(b: Building, lod: str | None, tol: Tolerances, lookup: dict, extra: list,
                    objs: list) -> list[dict]:
    """Polygon-level clean-up (snap, repeated points, degenerate faces) of the surface
    geometries that bound no volume (LoD0, a lone wall: :func:`_bounds_volume`).

    LoD0 footprints and roof outlines are not volumes: they keep their type and only lose
    what val3dity rejects at polygon level (101/102). Returns one log entry per change.
    """
    out = []
    if lod is not None:
        return out
    for oi, o in enumerate(objs):
        if o.type not in BUILDING_TYPES:
            continue
        for gi, g in enumerate(o.geometries):
            if not g.is_polygonal or not g.solids or _bounds_volume(g, o.geometries):
                continue
            codes = sorted({d.code for d in validate_geometry(b.vertices, o.id, gi, g, tol)})
            if not codes:
                continue
            m = mesh_of_geometry(b.vertices, g)
            c = drop_degenerate(clean_rings(snap_vertices(m, tol.snap_tol)))
            if not c.faces:
                continue
            ng = geometry_of_mesh(c, g, lookup, extra, len(b.vertices))
            ng = Geometry(g.type, g.lod, ng.solids, g.semantic_surfaces)
            geoms = list(objs[oi].geometries)
            geoms[gi] = ng
            objs[oi] = replace(objs[oi], geometries=tuple(geoms))
            out.append({"object": o.id, "geometry": gi, "lod": g.lod, "defects_before": codes,
                        "stage": "cleanup", "n_faces_before": m.n_faces, "n_faces_after": c.n_faces})
    return out


def repair_building(b: Building, tol: Tolerances = DEFAULT, timeout: float = DEFAULT_TIMEOUT,
                    merge_parts: bool = False, lod: str | None = None) -> Building:
    """Repair every defective Building/BuildingPart geometry of ``b`` (see the module docstring).

    Every stage's result is judged as computed and on the grid ``b`` will be written on
    (:func:`lod2energy.repair.accept.output_grid`, the final check's grid): a result that
    rounding to it spoils goes on up the ladder, and the geometry's ``log`` says at which
    stage and with which val3dity codes.

    Parameters
    ----------
    b : Building
    tol : Tolerances
    timeout : float, s
        Budget for the whole building; once spent, remaining geometries jump to the convex
        hull (or stay as they are, "irreparable").
    merge_parts : bool
        Union overlapping BuildingParts (601) into one solid on the Building.
    lod : str or None
        Only repair geometries at this LoD (None: every LoD >= 1).

    Returns
    -------
    Building
        ``b`` itself when nothing needed a repair (with provenance when it carried none);
        else a new building with ``provenance["repair"]`` set.
    """
    with output_grid(grid_rounding(b)):
        return _repair_building(b, tol, timeout, merge_parts, lod)


def _repair_building(b: Building, tol: Tolerances, timeout: float, merge_parts: bool,
                     lod: str | None) -> Building:
    t0 = time.monotonic()
    deadline = t0 + timeout
    targets = _targets(b, lod)
    lookup = {}
    for i, p in enumerate(b.vertices):
        lookup.setdefault((float(p[0]), float(p[1]), float(p[2])), i)
    extra: list = []
    objs = list(b.objects)
    per_geom = []
    defects_before: set[int] = set()
    changed = False
    meshes = [mesh_of_geometry(b.vertices, g) for _, _, g in targets]
    whys = [implausible(m) if m.faces else None for m in meshes]
    found = verdicts(b, targets, meshes, whys, tol)
    for k, (oi, gi, g) in enumerate(targets):
        o = b.objects[oi]
        m, codes = meshes[k], found[k]
        # misplaced coordinates, or no volume at all (flat): refused as they are, with the reason
        why = refused(m, tol, codes, g.type == "Solid")
        defects_before |= set(codes)
        entry = {"object": o.id, "geometry": gi, "lod": g.lod, "type": g.type,
                 "n_faces_before": m.n_faces, "defects_before": codes}
        # the ladder starts with "valid as is -> keep": no val3dity code, a Solid, believable
        valid = g.type == "Solid" and why is None and bool(m.faces) and all(c >= 1000 for c in codes)
        if valid and not codes:
            entry.update(stage="valid", n_faces_after=m.n_faces, iou=1.0, mean_displacement=0.0,
                         mean_displacement_back=0.0, hausdorff=0.0, closure="closed", seconds=0.0)
            per_geom.append(entry)
            continue
        t1 = time.monotonic()
        if valid and time.monotonic() > deadline:
            stage, res, log = "valid", None, ["timeout: valid as it is, kept"]
        elif not m.faces:
            stage, res, log = "irreparable", None, ["empty geometry"]
        elif why is not None:
            # misplaced coordinates or no volume: no stage can recover a shape that is not there
            stage, res, log = "irreparable", None, [why]
            entry["error"] = why
        elif time.monotonic() > deadline:
            res = convex_hull(_once(cleanup, m, tol))
            verdict = repair_verdict(res, g.lod, tol)
            stage = "hull" if verdict is None else "irreparable"
            res = res if stage == "hull" else None
            log = ["timeout: jumped to the convex hull"] + ([f"hull: {verdict}"] if verdict else [])
        elif valid:
            stage, res, log = ladder(m, g.lod, tol, deadline, keep=True)
        else:
            stage, res, log = ladder(m, g.lod, tol, deadline)
            stage, res, log = not_hollow(  # a hollow result goes further up the ladder
                m, stage, res, log, lambda: global_stages(_once(cleanup, m, tol), g.lod, tol, deadline, []),
                lambda: _valid_or_none(convex_hull(_once(cleanup, m, tol)), g.lod, tol),
                closed_volume(snap_vertices(m, tol.snap_tol)))
        entry["log"] = log
        if stage == "valid":
            entry.update(stage="valid", n_faces_after=m.n_faces, iou=1.0, mean_displacement=0.0,
                         mean_displacement_back=0.0, hausdorff=0.0, closure="closed",
                         defects_after=codes)
        elif res is None:
            entry.update(stage="irreparable", n_faces_after=m.n_faces, iou=None,
                         mean_displacement=None, mean_displacement_back=None, hausdorff=None,
                         closure=None)
        else:
            res = compact(res)
            input_closed, env = _envelope(m, res, stage, tol)
            fid = fidelity(m, res, input_closed, env)
            if stage == "refill" and fid["iou"] < REFILL_MIN_IOU and not valid:
                # the cut took a large part of the shell with it: a global stage may keep more
                gstage, gres, glog = global_stages(_once(cleanup, m, tol), g.lod, tol, deadline, [])
                if gres is not None:
                    gres = compact(gres)
                    gclosed, genv = _envelope(m, gres, gstage, tol)
                    gfid = fidelity(m, gres, gclosed, genv)
                    entry["log"] = log + [f"refill: IoU {fid['iou']:.3f}, global stages tried"] + glog
                    if gfid["iou"] > fid["iou"]:
                        stage, res, fid, input_closed, env = gstage, gres, gfid, gclosed, genv
            entry.update(stage=stage, n_faces_after=res.n_faces, **fid)
            if any(face_area(res.vertices, f) <= tol.sliver_area for f in res.faces):
                entry["defects_after"] = [1003]
            # per output face: the input surface it derives from (-1: made by the repair)
            entry["source_faces"] = [int(f.source) for f in res.faces]
            ng = geometry_of_mesh(res, g, lookup, extra, len(b.vertices))
            geoms = list(objs[oi].geometries)
            geoms[gi] = ng
            objs[oi] = replace(objs[oi], geometries=tuple(geoms))
            changed = True
        entry["seconds"] = round(time.monotonic() - t1, 4)
        per_geom.append(entry)
    surfaces_log = _clean_surfaces(b, lod, tol, lookup, extra, objs)
    changed = changed or bool(surfaces_log)
    if not changed and all(e["stage"] == "valid" and not e["defects_before"] for e in per_geom):
        if not merge_parts:
            return b  # untouched: the same object
        nb = merge_overlapping_parts(b, tol, lod)
        if nb is b:
            return b
        return nb.with_provenance(repair=_summary(nb, per_geom, sorted(defects_before), tol,
                                                  time.monotonic() - t0))
    V = np.vstack([b.vertices, np.asarray(extra).reshape(-1, 3)]) if extra else b.vertices
    nb = replace(b, objects=tuple(objs), vertices=V)
    nb, parts_rec = keep_parts_apart(b, nb, tol, lod)  # no BuildingPart overlap made by the repair
    if parts_rec.get("left") and not merge_parts:
        nb = _refuse_overlaps(b, nb, per_geom, parts_rec["left"], lod if lod is not None else nb.default_lod())
    overlaps = overlapping_parts(nb, lod)
    if merge_parts and overlaps:
        nb = merge_overlapping_parts(nb, tol, lod)
    summary = _summary(nb, per_geom, sorted(defects_before), tol, time.monotonic() - t0)
    summary["overlapping_parts"] = [list(p) for p in overlaps]
    if parts_rec:
        summary["parts_overlap"] = parts_rec
    errors = [f"{e['object']}: {e['error']}" for e in per_geom if e.get("error")]
    if errors:
        summary["error"] = "; ".join(errors)
    summary["surfaces_cleaned"] = surfaces_log
    return nb.with_provenance(repair=summary)


def _refuse_overlaps(b: Building, nb: Building, per_geom: list[dict], left: list, lod: str | None) -> Building:
    """``nb`` with the repair of every part refused that overlaps a neighbour (601) where the
    input did not, or more than in the input, once :func:`keep_parts_apart` could not separate
    them (at ``lod``): like any failed candidate. The part keeps its input geometry and its entry in
    ``per_geom`` becomes "irreparable" with the reason (the building is then not compliant)."""
    objs = list(nb.objects)
    index = {o.id: i for i, o in enumerate(objs)}
    for e in per_geom:
        hit = [(x, y, v) for x, y, v in left if e["object"] in (x, y)]
        if not hit or e["stage"] in ("valid", "irreparable") or e["lod"] != lod:
            continue
        x, y, v = hit[0]
        other = y if x == e["object"] else x
        why = (f"repair ({e['stage']}) makes it overlap {other} (601"
               + (f", {v:g} m3" if v is not None else "") + "): refused")
        i = index[e["object"]]
        geoms = list(objs[i].geometries)
        geoms[e["geometry"]] = b.objects[i].geometries[e["geometry"]]
        objs[i] = replace(objs[i], geometries=tuple(geoms))
        e.update(stage="irreparable", n_faces_after=e["n_faces_before"], iou=None, mean_displacement=None,
                 mean_displacement_back=None, hausdorff=None, closure=None, error=why,
                 log=list(e.get("log", ())) + [why])
        e.pop("source_faces", None)
        e.pop("defects_after", None)
    return replace(nb, objects=tuple(objs))


def _envelope(m: PolyMesh, res: PolyMesh, stage: str, tol: Tolerances) -> tuple[bool, PolyMesh | None]:
    """Is the input closed by itself, and else its envelope closed by boundary-loop filling."""
    s = snap_vertices(m, tol.snap_tol)
    t = topology(s)
    if not t.boundary and not t.nonmanifold:
        return True, orient(s)
    if stage in ("cleanup", "orientation", "holefill"):
        return False, res  # the result is the input with its holes filled
    env = _once(close, orient(_once(cleanup, m, tol)), tol)
    t = topology(env)
    if t.boundary or t.nonmanifold or t.nm_vertices:
        return False, None
    return False, env


def _summary(b: Building, per_geom: list, before: list[int], tol: Tolerances, seconds: float) -> dict:
    after = set()
    for d in validate_building(b, tol):
        after.add(d.code)
    for e in per_geom:
        if e["stage"] == "irreparable":
            after |= set(e["defects_before"])
        after |= set(e.get("defects_after", ()))
    rank = {s: i for i, s in enumerate(STAGES)}
    stage = max((e["stage"] for e in per_geom), key=lambda s: rank[s]) if per_geom else "valid"
    main_lod = b.default_lod()
    main = [e for e in per_geom if e["lod"] == main_lod and e["iou"] is not None] or \
        [e for e in per_geom if e["iou"] is not None]
    nv = [max(e["n_faces_before"], 1) for e in main]
    out = {
        "stage": stage,
        "iou": float(np.average([e["iou"] for e in main], weights=nv)) if main else None,
        "mean_displacement": float(np.average([e["mean_displacement"] for e in main], weights=nv)) if main else None,
        "mean_displacement_back": float(np.average([e["mean_displacement_back"] for e in main], weights=nv)) if main else None,
        "hausdorff": float(max(e["hausdorff"] for e in main)) if main else None,
        "closure": ",".join(sorted({e["closure"] for e in main if e["closure"]})) or None,
        "n_faces_before": int(sum(e["n_faces_before"] for e in per_geom if e["lod"] == main_lod)),
        "n_faces_after": int(sum(e["n_faces_after"] for e in per_geom if e["lod"] == main_lod)),
        "seconds": round(seconds, 4),
        "defects_before": before,
        "defects_after": sorted(after),
        "geometries": per_geom,
    }
    return out


def repair_features(features: Iterable[Building | FeatureError], tol: Tolerances = DEFAULT,
                    timeout: float = DEFAULT_TIMEOUT, merge_parts: bool = False,
                    lod: str | None = None) -> Iterator[Building | FeatureError]:
    """Repair each Building of a feature stream; everything else passes through in order."""
    for f in features:
        if isinstance(f, Building) and f.objects and any(o.type in BUILDING_TYPES for o in f.objects):
            try:
                yield repair_building(f, tol, timeout, merge_parts, lod)
            except Exception as e:  # noqa: BLE001 - one broken building never stops the stream
                yield f.with_provenance(repair={"stage": "irreparable", "error": f"{type(e).__name__}: {e}",
                                                "iou": None, "mean_displacement": None, "hausdorff": None,
                                                "defects_before": [], "defects_after": [999]})
        else:
            yield f


def repair_info(b: Building) -> Mapping:
    """``b.provenance["repair"]``, or the record of an untouched valid building."""
    r = b.provenance.get("repair")
    if r is not None:
        return r
    return {"stage": "valid", "iou": 1.0, "mean_displacement": 0.0, "hausdorff": 0.0,
            "defects_before": [], "defects_after": []}


def repair_attributes(b: Building) -> dict:
    """Flat CityJSON attributes recording the repair of ``b`` (for the root CityObject).

    Returns
    -------
    dict
        ``repair_stage``, ``repair_iou``, ``repair_mean_displacement`` (m),
        ``repair_hausdorff`` (m), ``repair_defects_before``, ``repair_defects_after``.
    """
    r = repair_info(b)

    def num(x):
        return None if x is None else round(float(x), 6)
    return {"repair_stage": r["stage"], "repair_iou": num(r.get("iou")),
            "repair_mean_displacement": num(r.get("mean_displacement")),
            "repair_hausdorff": num(r.get("hausdorff")),
            "repair_defects_before": list(r.get("defects_before", [])),
            "repair_defects_after": list(r.get("defects_after", []))}


def dataset_table(buildings: Iterable[Building]) -> dict:
    """Per-dataset summary like the method's Tables 5/6.

    Returns
    -------
    dict
        ``total``, ``invalid`` (val3dity-level error other than 601, or not energy-compliant),
        ``valid_before``/``valid_after`` (no val3dity-level error other than 601),
        ``compliant_before``/``compliant_after`` (also closed, outward, no sliver),
        ``local_repairs``, ``global_repairs``, ``left``, ``repaired_share``, ``miou``,
        ``map_v`` (m), ``mean_hausdorff`` (m), ``stages`` (histogram).
    """
    rows = [repair_info(b) for b in buildings if isinstance(b, Building) and b.is_building]
    n = len(rows)

    def compliant(codes):
        return all(c == 601 for c in codes)

    stages = Counter(r["stage"] for r in rows)
    invalid = sum(1 for r in rows if not compliant(r["defects_before"]))
    local = sum(stages[s] for s in LOCAL)
    glob = sum(stages[s] for s in GLOBAL)
    left = stages["irreparable"] + sum(1 for r in rows if r["stage"] not in ("irreparable",)
                                       and not compliant(r["defects_after"]))
    fixed = [r for r in rows if r["stage"] not in ("valid", "irreparable") and r.get("iou") is not None]
    return {
        "total": n,
        "invalid": invalid,
        "valid_before": sum(1 for r in rows if val3dity_valid(r["defects_before"])),
        "valid_after": sum(1 for r in rows if val3dity_valid(r["defects_after"])),
        "compliant_before": n - invalid,
        "compliant_after": sum(1 for r in rows if compliant(r["defects_after"])),
        "local_repairs": local,
        "global_repairs": glob,
        "left": left,
        "repaired_share": (invalid - left) / invalid if invalid else 1.0,
        "miou": float(np.mean([r["iou"] for r in fixed])) if fixed else None,
        "map_v": float(np.mean([r["mean_displacement"] for r in fixed])) if fixed else None,
        "mean_hausdorff": float(np.mean([r["hausdorff"] for r in fixed])) if fixed else None,
        "n_measured": len(fixed),
        "stages": {s: stages[s] for s in STAGES if stages[s]},
    }


__all__ = ["STAGES", "DEFAULT_TIMEOUT", "repair_building", "input_codes", "repair_features", "dataset_table",
           "repair_info", "repair_attributes", "ladder", "mesh_of_geometry", "geometry_of_mesh", "is_repaired", "roof_model",
           "ROOF_MODEL_MAX_DISPLACEMENT", "merge_slivers", "fill_holes",
           "frozen_mapping"]
