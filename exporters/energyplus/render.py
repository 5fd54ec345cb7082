"""IDF text of zones and their pieces (the jinja2 template ``templates/building.idf.j2``)."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Sequence

import jinja2
import numpy as np

import lod2energy.templates as tpl
from lod2energy import __version__, cache
from lod2energy.energy.figures import boundary_of, envelope_figures, shared_faces
from lod2energy.energy.openings import Opening, opening_polygon, window_for
from lod2energy.energy.pieces import Piece, WRITE_DECIMALS, _pieces_volume
from lod2energy.energy.zones.shells import ZoneShell
from lod2energy.energy.zones.storeys import ZoneInfo, with_floor
from lod2energy.errors import ExportError, ParameterError
from lod2energy.exporters.energyplus.constructions import (
    INTERZONE_SLAB, MASS, _KIND_TYPE, _construction_name, construction_layers,
)
from lod2energy.exporters.energyplus.names import NameRegistry, _IDF_NAME_BAD, comment_text
from lod2energy.exporters.energyplus.options import ATTIC_ACH, IdfOptions
from lod2energy.geometry.polygons import newell_normal, polygon_area3d, unit
from lod2energy.geometry.vectors import vector_length
from lod2energy.thermal.use import use_conditions


def upper_left_first(points: np.ndarray) -> np.ndarray:
    """Rotate a ring so that it starts at its upper-left vertex seen from outside.

    "Up" is world +z projected on the plane (+y on horizontal planes), "right" = up x normal.
    """
    n = unit(newell_normal(points))
    if n.dtype != np.float64 or n.shape != (3,) or points.ndim != 2:
        return _upper_left_first_ref(points, n)
    # [0, 0, 1] - n[2] * n on floats (the same products and differences); its length once,
    # for the test and for unit()
    n0, n1, n2 = n.tolist()
    up = np.array([0.0 - n2 * n0, 0.0 - n2 * n1, 1.0 - n2 * n2])
    length = vector_length(up)
    if length < 1e-6:
        up = np.array([0.0 - n1 * n0, 1.0 - n1 * n1, 0.0 - n1 * n2])
        length = vector_length(up)
    if length > 0:
        up = up / length
    # np.cross(up, n) written out on floats in its operation order (same bits)
    u0, u1, u2 = up.tolist()
    right = np.array([u1 * n2 - u2 * n1, u2 * n0 - u0 * n2, u0 * n1 - u1 * n0])
    h = points @ up
    cand = np.nonzero(h >= h.max() - 1e-3)[0]
    start = int(cand[np.argmin(points[cand] @ right)])
    return np.concatenate((points[start:], points[:start]))  # np.roll(points, -start, axis=0)


def _upper_left_first_ref(points: np.ndarray, n: np.ndarray) -> np.ndarray:
    """:func:`upper_left_first` as first written (numpy throughout), for any input; ``n`` is
    the unit Newell normal of ``points``."""
    up = np.array([0.0, 0.0, 1.0]) - n[2] * n
    if np.linalg.norm(up) < 1e-6:
        up = np.array([0.0, 1.0, 0.0]) - n[1] * n
    up = unit(up)
    right = np.cross(up, n)
    h = points @ up
    cand = np.nonzero(h >= h.max() - 1e-3)[0]
    start = int(cand[np.argmin(points[cand] @ right)])
    return np.roll(points, -start, axis=0)


def _fmt(x: float, nd: int = WRITE_DECIMALS) -> str:
    s = f"{x:.{nd}f}"
    return "0" if s.lstrip("-") == "0." + "0" * nd else s.rstrip("0").rstrip(".")


def _vertex_lines(points: np.ndarray) -> list[str]:
    """``x, y, z`` lines of (k, 3) points as the IDF writes them (on Python floats: the same text)."""
    if not (isinstance(points, np.ndarray) and points.dtype == np.float64):
        return [f"{_fmt(p[0])}, {_fmt(p[1])}, {_fmt(p[2])}" for p in points]
    # a coordinate is written by every surface at that vertex: its text is remembered by its
    # value (a pure function of the Python float; 0.0 and -0.0, the only equal floats of
    # different bits, both write "0")
    out = []
    for row in points.tolist():
        t = []
        for x in row:
            s = cache.recall(COORD_TEXT, x)
            if s is None:
                s = cache.keep(COORD_TEXT, x, _fmt(x), COORD_TEXT_KEPT)
            t.append(s)
        out.append(", ".join(t))
    return out


#: The :mod:`lod2energy.cache` table of coordinate texts (:data:`WRITE_DECIMALS` decimals) by value.
COORD_TEXT = "idf.coordinate_text"
COORD_TEXT_KEPT = 1 << 16


def _vertex_block(points: np.ndarray) -> dict:
    """Template fields of a polygon's vertices: their number and their lines as the IDF
    writes them (``"  x, y, z,"`` per vertex, the last ending in ``;``, each with its line
    break), joined once instead of looped over in the template."""
    lines = _vertex_lines(points)
    if not lines:
        return {"n_vertices": 0, "vertex_block": ""}
    return {"n_vertices": len(lines), "vertex_block": "  " + ",\n  ".join(lines) + ";\n"}


#: Attribute names of a plain ``dict`` (its methods): ``{{ d.name }}`` gives these, not the item.
_DICT_ATTRS = frozenset(dir(dict))


@cache.memoize("idf.template", 1)
def _template():
    """The IDF template of one building (``building.idf.j2``), loaded once per process."""

    class _Environment(jinja2.Environment):
        """jinja2's environment whose ``{{ d.key }}`` on a plain dict reads the item directly.

        jinja2 tries ``getattr(d, "key")`` first, which on a ``dict`` succeeds only for the
        names of its methods (a dict has no instance attributes), and only then ``d["key"]``:
        the template's fields were an AttributeError raised and caught each. The same values
        (method names and missing keys go the default way)."""
        def getattr(self, obj, attribute):
            if type(obj) is dict and attribute not in _DICT_ATTRS:
                try:
                    return obj[attribute]
                except KeyError:
                    pass
            return super().getattr(obj, attribute)

    loader = jinja2.FileSystemLoader(str(Path(tpl.__file__).resolve().parent))
    env = _Environment(loader=loader, undefined=jinja2.StrictUndefined, autoescape=False,
                       trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True)
    return env.get_template("building.idf.j2")


def render_idf(zones: Sequence[ZoneShell], pieces: Sequence[list[Piece]], delta: np.ndarray,
               offset: np.ndarray, options: IdfOptions, building_ids: Sequence[str],
               shading: Sequence[np.ndarray] = (), site: dict | None = None,
               ground: Sequence[float] | None = None, crs: str | None = None,
               zone_info: Sequence["ZoneInfo"] | None = None,
               openings: Sequence[Sequence["Opening"]] | None = None,
               source_ids: Sequence[str] | None = None) -> tuple[str, dict, list[str]]:
    """IDF text for zones whose pieces are in a frame ``delta`` away from the file frame.

    Each ``Zone``'s Floor Area is written (EnergyPlus's per-area loads and the reported
    kWh/m2a use it): the area of its floor surfaces, plus, for a zone kept whole over several
    storeys, the floor area of its upper storeys (:attr:`ZoneInfo.upper_floor_area`).

    ``zone_info`` (one per zone) gives each zone's use and whether it is conditioned: with
    ``options.use_loads`` its People, Lights, ElectricEquipment, schedules, setpoints,
    infiltration and ventilation come from :func:`lod2energy.thermal.use.use_conditions`; an
    unconditioned zone (attic) gets no HVAC and no loads. Interzone pieces (``boundary ==
    "Surface"``) are written with the name of their partner as the boundary object.

    ``openings`` (per zone, :func:`split_openings`): a zone with real windows / doors gets
    them as ``FenestrationSurface:Detailed`` on their wall pieces instead of the WWR rule.

    ``source_ids`` (one per zone): the id of the zone shell each written zone was cut from (its
    storey zones share it), which names the input faces in ``stats["envelope"]``'s
    ``shared_faces``; default the zone's own id.

    ``site`` (``Site:Location`` fields, :meth:`lod2energy.site.Site.as_idf`) is required: there
    is no default site.

    Returns
    -------
    text : str
    stats : dict
    warnings : list of str
    """
    if site is None:
        raise ParameterError("an IDF needs its Site:Location (the buildings' position): no site given")
    reg = NameRegistry()
    warnings: list[str] = []
    constructions: dict[str, dict] = {}
    win_constructions: dict[str, dict] = {}
    zone_ctx, surf_ctx, win_ctx = [], [], []
    wall_area = win_area = 0.0
    n_real = {"Window": 0, "Door": 0}
    b_name = reg.name(building_ids[0] if len(building_ids) == 1 else "Dataset", 80)
    links: dict[str, dict] = {}
    uses: dict[str, object] = {}
    infos = list(zone_info) if zone_info is not None else [None] * len(zones)
    unplaced: dict[int, tuple] = {}  # openings no outdoor wall piece of a zone took, by identity
    placed: set[int] = set()
    written: dict[str, list] = {}  # surface name -> [building, class, area m2, U, window area m2]
    face_classes: dict[str, dict] = {}  # building -> zone -> input face index -> its pieces' classes
    glazed: list[tuple[str, float, float]] = []  # windows: (building, area m2, U)
    for zk, (z, zp, info) in enumerate(zip(zones, pieces, infos)):
        zop = tuple(openings[zk]) if openings and zk < len(openings) else ()
        zp, floored = with_floor(zp)
        if floored:
            warnings.append(f"zone {z.object_id}: no floor surface; its {floored} most downward-facing "
                            "surface(s) written as Floor (EnergyPlus needs a floor in every zone)")
        zname = reg.name(z.object_id, 60)
        conditioned = info is None or info.conditioned
        floor_area = sum(polygon_area3d(p.points) for p in zp if p.kind in ("ground", "floor"))
        if info is not None and info.upper_floor_area > 0:
            floor_area += info.upper_floor_area  # a whole zone over several storeys: their gross floor area
        zc = {"name": zname, "comment": comment_text(z.object_id),
              "volume": _fmt(max(_pieces_volume(zp), 0.0), 3),
              "floor_area": _fmt(floor_area, 3),
              "conditioned": conditioned, "use": None, "infiltration": None,
              "building": info.building_id if info is not None else z.building_id}
        if options.use_loads and info is not None:
            if conditioned:
                uc = use_conditions(info.use)
                uses[uc.use] = uc
                zc["use"] = uc.use
                zc["infiltration"] = _fmt(uc.infiltration_ach, 4)
            else:
                zc["infiltration"] = _fmt(ATTIC_ACH, 4)
        zone_ctx.append(zc)
        warnings.extend(z.warnings)
        counters: dict[str, int] = {}
        # windows go on walls of at least min_window_wall_area; their ratio is raised so the
        # zone's window area stays wwr x its outdoor wall area (few windows = fast runs)
        wall_of = [polygon_area3d(p.points) if p.kind == "wall" and p.boundary == "Outdoors" else None for p in zp]
        walls = [a for a, p in zip(wall_of, zp) if a is not None and p.glazed]
        eligible = sum(a for a in walls if a >= options.min_window_wall_area)
        ratio = min(z.wwr * sum(walls) / eligible, 0.85) if eligible > 0 and not zop else 0.0
        hosts: list[tuple[Piece, str, str]] = []  # outdoor wall pieces: piece, surface, construction
        for p, a in zip(zp, wall_of):
            stype = _KIND_TYPE[p.kind]
            if p.boundary == "Surface":
                counters[stype] = counters.get(stype, 0) + 1
                sname = reg.name(f"{zname}_{stype}{counters[stype]}", 90)
                sc = {"name": sname, "type": stype, "construction": INTERZONE_SLAB["name"], "zone": zname,
                      "boundary": "Surface", "boundary_object": "", "sun": "NoSun", "wind": "NoWind",
                      **_vertex_block(upper_left_first(p.points - delta))}
                surf_ctx.append(sc)
                links[p.link] = sc
                continue
            cname = _construction_name(p.kind, p.boundary, p.u_value)
            if cname not in constructions:
                r, thick, note = construction_layers(p.kind, p.boundary, p.u_value, options.thermal_mass)
                if note:
                    warnings.append(note)
                constructions[cname] = {"name": cname, "resistance": _fmt(r, 5), "mass_thickness": _fmt(thick, 4)
                                        if thick else None,
                                        "comment": f"{stype}, {p.boundary}, U = {p.u_value:.4g} W/(m2 K) with films"}
            counters[stype] = counters.get(stype, 0) + 1
            sname = reg.name(f"{zname}_{stype}{counters[stype]}", 90)
            pts = upper_left_first(p.points - delta)
            outdoor = p.boundary == "Outdoors"
            surf_ctx.append({"name": sname, "type": stype, "construction": cname, "zone": zname,
                             "boundary": p.boundary, "boundary_object": "", "sun": "SunExposed" if outdoor else "NoSun",
                             "wind": "WindExposed" if outdoor else "NoWind",
                             **_vertex_block(pts)})
            written[sname] = [zc["building"], boundary_of(stype, p.boundary), polygon_area3d(pts),
                              _own_u(constructions[cname]), 0.0]
            face_classes.setdefault(zc["building"], {}).setdefault(
                source_ids[zk] if source_ids is not None else z.object_id, {}).setdefault(
                p.face_index, set()).add(written[sname][1])
            if p.kind == "wall" and outdoor:  # a: its area, found above
                wall_area += a
                hosts.append((p, sname, cname))
                if ratio > 0 and p.glazed and a >= options.min_window_wall_area:
                    w = window_for(p.points - delta, ratio)
                    if w is not None and (wa := polygon_area3d(w)) > 0.01:
                        wc = f"Window_U{z.u_window:.3f}_G{options.shgc:.2f}".replace(".", "p")
                        win_constructions.setdefault(wc, {"name": wc, "u_value": _fmt(min(z.u_window, 7.0), 4),
                                                          "shgc": _fmt(options.shgc, 3), "vt": _fmt(options.shgc, 3)})
                        win_ctx.append({"name": reg.name(f"{sname}_Win", 99), "construction": wc, "base": sname,
                                        **_vertex_block(upper_left_first(w))})
                        win_area += wa
                        written[sname][4] += wa
                        glazed.append((zc["building"], wa, float(win_constructions[wc]["u_value"])))
        for op in zop:  # real windows and doors, each on the outdoor piece of its wall it overlaps most
            best = None
            for p, sname, cname in hosts:
                if p.face_index != op.wall_index:
                    continue
                w = opening_polygon(replace(op, points=op.points), p.points)
                if w is not None and (best is None or polygon_area3d(w) > polygon_area3d(best[0])):
                    best = (w, sname, cname)
            if best is None:
                # a storey zone holds only its storey's part of the wall: the opening may be
                # written by another storey of its source zone, so the warning waits for the end
                unplaced.setdefault(id(op), (op, z.object_id))
                continue
            placed.add(id(op))
            w, sname, cname = best
            if op.kind == "Window":
                cons = f"Window_U{z.u_window:.3f}_G{options.shgc:.2f}".replace(".", "p")
                win_constructions.setdefault(cons, {"name": cons, "u_value": _fmt(min(z.u_window, 7.0), 4),
                                                    "shgc": _fmt(options.shgc, 3), "vt": _fmt(options.shgc, 3)})
                win_area += polygon_area3d(w)
                written[sname][4] += polygon_area3d(w)
                glazed.append((zc["building"], polygon_area3d(w), float(win_constructions[cons]["u_value"])))
            else:
                cons = cname  # a door: the opaque construction of its wall
            n_real[op.kind] += 1
            win_ctx.append({"name": reg.name(f"{sname}_{op.kind}{n_real[op.kind]}", 99), "type": op.kind,
                            "construction": cons, "base": sname,
                            **_vertex_block(upper_left_first(w - delta))})
    for k, (op, zone_id) in unplaced.items():
        if k not in placed:
            warnings.append(f"zone {zone_id}: a {op.kind.lower()} lies on no outdoor piece of its wall; "
                            "not written (the wall is closed)")
    for key, sc in links.items():
        other = links.get(key[:-1] + ("f" if key.endswith("c") else "c"))
        if other is None:
            raise ExportError(f"interzone surface {sc['name']} has no partner")
        sc["boundary_object"] = other["name"]
    shade_ctx = [{"name": reg.name(f"Shade{i + 1}", 40), **_vertex_block(upper_left_first(s - delta))}
                 for i, s in enumerate(shading)]
    ctx = {
        "lod2energy_version": __version__,
        "comment_ids": comment_text(building_ids[0]) if len(building_ids) == 1
        else f"{len(building_ids)} buildings, first {comment_text(building_ids[0])}",
        "offset": [_fmt(float(x), 3) for x in offset],
        "crs": comment_text(crs) if crs else None,
        "version": _IDF_NAME_BAD.sub("", str(options.version)) or "25.2",
        "building_name": b_name,
        "terrain": "City",
        "solar_distribution": options.solar_distribution or (
            "FullExterior" if options.shading else "MinimalShadowing"),
        "timesteps_per_hour": int(options.timesteps_per_hour),
        "run_period": [int(x) for x in options.run_period],
        "site": {k: (v if k == "name" else _fmt(float(v), 4)) for k, v in site.items()},
        "ground_temperatures": [_fmt(float(t), 2) for t in (ground or [10.0] * 12)],
        "heating_setpoint": _fmt(options.heating_setpoint, 2),
        "cooling_setpoint": _fmt(options.cooling_setpoint, 2),
        "constructions": list(constructions.values()),
        "mass": {k: _fmt(v, 3) for k, v in MASS.items()},
        "window_constructions": list(win_constructions.values()),
        "zones": zone_ctx,
        "infiltration_ach": float(options.infiltration_ach),
        "internal_gains": float(options.internal_gains),
        "surfaces": surf_ctx,
        "windows": win_ctx,
        "shading": shade_ctx,
        "use_loads": bool(options.use_loads and zone_info is not None),
        "uses": [_use_ctx(u) for u in uses.values()],
        "interzone": ({k: _fmt(v, 4) if k != "name" else v for k, v in INTERZONE_SLAB.items()}
                      if links else None),
    }
    ctx["infiltration_ach"] = _fmt(options.infiltration_ach, 4) if options.infiltration_ach > 0 else 0
    ctx["internal_gains"] = _fmt(options.internal_gains, 4) if options.internal_gains > 0 else 0
    text = _template().render(**ctx)
    stats = {"zones": len(zone_ctx), "surfaces": len(surf_ctx), "windows": len(win_ctx),
             "shading_surfaces": len(shade_ctx),
             "adiabatic_surfaces": sum(1 for s in surf_ctx if s["boundary"] == "Adiabatic"),
             "interzone_surfaces": len(links),
             "zone_floor_area_m2": {z["name"]: float(z["floor_area"]) for z in zone_ctx},
             "zone_volume_m3": {z["name"]: float(z["volume"]) for z in zone_ctx},
             "conditioned_zones": [z["name"] for z in zone_ctx if z["conditioned"]],
             "zone_building": {z["name"]: z["building"] for z in zone_ctx},
             "input_windows": n_real["Window"], "input_doors": n_real["Door"],
             "wwr_achieved": round(win_area / wall_area, 4) if wall_area > 0 else 0.0,
             "envelope": {bid: envelope_figures([tuple(w[1:]) for w in written.values() if w[0] == bid],
                                                [(a, u) for b, a, u in glazed if b == bid])
                          for bid in dict.fromkeys(z["building"] for z in zone_ctx)}}
    for bid, fig in stats["envelope"].items():
        fig["shared_faces"] = shared_faces(face_classes.get(bid, {}))
    return text, stats, warnings


def _own_u(construction: dict) -> float:
    """The U-value (W/(m2 K)) of a written opaque construction without films: 1 / its layers'
    R summed, from the values as written."""
    r = float(construction["resistance"])
    if construction.get("mass_thickness"):
        r += float(construction["mass_thickness"]) / float(_fmt(MASS["conductivity"], 3))
    return 1.0 / r


def _compact(values: Sequence[float], nd: int = 3) -> list[str]:
    """``Schedule:Compact`` fields of 24 hourly values (equal neighbours merged)."""
    out = []
    for h, v in enumerate(values):
        if h + 1 < len(values) and _fmt(values[h + 1], nd) == _fmt(v, nd):
            continue
        out += [f"Until: {h + 1:02d}:00", _fmt(float(v), nd)]
    return out


def _use_ctx(uc) -> dict:
    """Template fields of one use's loads and schedules (read only: remembered by the values
    they are made of, a pure function of them, so never stale)."""
    key = (uc.use, uc.teaser_entry, uc.people_per_m2, uc.activity_w_per_person, uc.sensible_fraction,
           uc.lighting_w_per_m2, uc.equipment_w_per_m2, uc.ventilation_m3h_per_m2,
           tuple((k, tuple(v)) for k, v in uc.schedules.items()))
    return cache.remember("idf.use_fields", key, lambda: _use_ctx_of(uc), 64)


def _use_ctx_of(uc) -> dict:
    """Template fields of one use's loads and schedules."""
    on = [1.0 if x > 0 else 0.0 for x in uc.schedules["occupancy"]]
    name = uc.use.capitalize()
    return {"name": name, "use": uc.use, "teaser_entry": comment_text(uc.teaser_entry),
            "occupancy": _compact(uc.schedules["occupancy"]), "lighting": _compact(uc.schedules["lighting"]),
            "equipment": _compact(uc.schedules["equipment"]), "heating": _compact(uc.schedules["heating"], 2),
            "cooling": _compact(uc.schedules["cooling"], 2), "ventilation_on": _compact(on),
            "people_per_m2": _fmt(uc.people_per_m2, 5), "activity": _fmt(uc.activity_w_per_person, 2),
            "sensible_fraction": _fmt(uc.sensible_fraction, 4), "lighting_w_m2": _fmt(uc.lighting_w_per_m2, 3),
            "equipment_w_m2": _fmt(uc.equipment_w_per_m2, 3),
            "ventilation_m3s_m2": _fmt(uc.ventilation_m3h_per_m2 / 3600.0, 8)}
