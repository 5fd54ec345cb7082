"""The EnergyPlus writer: :func:`write` (one IDF per building, or one per dataset) and its self-check.

It writes the energy model it is given (``provenance["energy_model"]``, made by the stage
:mod:`lod2energy.energy.model` before the writer runs): zones, pieces and party walls
in their local frame. Called directly on buildings without one, it has the stage make it.
"""
from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from dataclasses import replace
from pathlib import Path
from typing import Iterable

import numpy as np

from lod2energy import safe_write, site as site_mod
from lod2energy.crs import no_crs_reason
from lod2energy.energy import downgrades as dg, model as energy_model
from lod2energy.energy.model import unglaze, with_energy_model
from lod2energy.energy.pieces import _face_frame, _pieces_from_points
from lod2energy.energy.surfaces import zone_pieces
from lod2energy.energy.zones.shells import local_origin
from lod2energy.energy.zones.storeys import _written_zones
from lod2energy.errors import ParameterError
from lod2energy.exporters.energyplus.check import self_check
from lod2energy.exporters.energyplus.options import IdfOptions
from lod2energy.exporters.energyplus.render import render_idf
from lod2energy.exporters.energyplus.run import _run
from lod2energy.exporters.energyplus.site import _group_site, read_epw_header
from lod2energy.exporters.paths import not_written, output_path, safe_stem, set_aside_failed
from lod2energy.geometry.polygons import polygon_area3d
from lod2energy.exporters.registry import register_writer
from lod2energy.exporters.result import ExportResult
from lod2energy.model import Building
from lod2energy.site import SiteError
from lod2energy.thermal.use import check_use


def _bbox(b: Building) -> np.ndarray:
    if len(b.vertices) == 0:
        return np.array([np.inf] * 3 + [-np.inf] * 3)
    return np.concatenate([b.vertices.min(axis=0), b.vertices.max(axis=0)])


def write(buildings: Iterable[Building], outdir: str | Path, options: IdfOptions | None = None,
          weather: str | Path | None = None, crs: str | None = None, frame=None,
          context: Iterable[Building] = ()) -> list[ExportResult]:
    """Write IDF files for energy-ready buildings and self-check them.

    Parameters
    ----------
    buildings : iterable of Building
    outdir : path
        Created if missing; every file is written inside it.
    options : IdfOptions
    weather : path, optional
        EPW file (overrides ``options.weather``).
    crs : str
        Written in the header comment; with ``frame``, what places the buildings on the Earth
        for ``Site:Location`` (:func:`lod2energy.site.site_of`). Required (any CRS pyproj
        reads) unless ``frame`` is a geographic file's local frame: there is no default site.
    frame : LocalFrame or ScaledFrame, optional
        The metric frame of a file in a geographic CRS or in feet (``CityModel.frame``).
    context : iterable of Building, optional
        Neighbours of ``buildings``: they make party walls and ``shading`` as they would in
        one call with all of them, but get no file of their own.

    Returns
    -------
    list of ExportResult
        One per file; ``ok`` is False when the self-check (or the run) failed, or when the
        file's buildings cannot be placed on the Earth (nothing written). ``stats``
        carries ``storeys``, ``use``, ``site`` and ``weather_distance_km`` (and, after a run,
        the per-zone results of :func:`_run`).
    """
    options = options or IdfOptions()
    if options.zoning not in ("storey", "building"):
        raise ParameterError(f"--zoning must be 'storey' or 'building', not {options.zoning!r}")
    if options.attic not in ("conditioned", "unconditioned"):
        raise ParameterError(f"--attic must be 'conditioned' or 'unconditioned', not {options.attic!r}")
    if options.use is not None:
        options = replace(options, use=check_use(options.use))
    if options.mode not in ("building", "dataset"):
        raise ParameterError(f"--idf-mode must be 'building' or 'dataset', not {options.mode!r}")
    if options.wwr is not None and not (0 <= options.wwr < 1):
        raise ParameterError(f"--wwr must be in [0, 1), not {options.wwr}")
    weather = str(weather) if weather else options.weather
    if options.run and not weather:
        raise ParameterError("an EnergyPlus run needs a weather file (EPW)")
    if weather and not (Path(weather).is_file() or Path(weather).is_dir()):
        raise ParameterError(f"weather file not found: {weather}")
    why = no_crs_reason(crs) if not getattr(frame, "geographic", False) else None
    if why:
        raise ParameterError(f"{why}: an IDF needs the buildings' position for its Site:Location "
                             "(give the CRS: crs=, --crs)")
    stations = site_mod.weather_stations(weather) if weather else []
    if weather and not stations:
        raise ParameterError(f"--weather {weather}: no EPW file with a LOCATION line in the folder")
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)

    model = energy_model.model_of(buildings, options, context)
    if model is None:
        return []
    blist, n_own, origin = list(model.buildings), model.n_own, model.origin
    zones, zones_of, openings, party, pieces = model.zones, model.zones_of, model.openings, model.party, model.pieces
    merge_notes = model.notes

    written_of, zone_notes, bstats, whole = _written_zones(blist[:n_own], zones, zones_of, pieces, options, openings)

    groups = [[bi] for bi in range(n_own)] if options.mode == "building" else [list(range(n_own))]
    bboxes = np.array([_bbox(b) for b in blist])
    used: set[str] = set()

    def render(g, path, split_pieces, simpler=None):
        """Write the IDF of buildings ``g``: ``(offset, stats, warnings, whole)``, ``whole`` the
        zones kept whole (downgrades) per building of ``g``."""
        gb = [blist[i] for i in g]
        kept_whole = {j: whole[j] for j in g}
        offset = local_origin(gb)
        zi = [z for i in g for z in zones_of[i]]
        shading = []
        if options.shading and options.mode == "building":
            shading = _shading_for(g[0], blist, bboxes, zones, zones_of, party, options.shading_radius)
        if split_pieces is None and options.zoning == "building":
            wl = [(zones[i], unglaze(zone_pieces(zones[i], i, party, False), i, model.unglazed), w[2], i)
                  for i, w in zip(zi, [w for j in g for w in written_of[j]])]
        elif split_pieces is None or simpler is not None:
            # storey zones cut again: from the zones with whole party walls, or from ``simpler``
            # (zone index -> a simpler envelope, :data:`energy_model.FALLBACKS`, no party walls)
            zs, ps = list(zones), list(pieces)
            for i in zi:
                if simpler is not None:
                    zs[i], ps[i] = simpler[i], zone_pieces(simpler[i], i, {}, False)
                else:
                    ps[i] = unglaze(zone_pieces(zones[i], i, party, False), i, model.unglazed)
            wo, _, _, wdg = _written_zones(gb, zs, [zones_of[j] for j in g], ps, options, openings)
            wl = [w for k in range(len(g)) for w in wo[k]]
            kept_whole = {j: wdg[k] for k, j in enumerate(g)}
        else:
            wl = [w for j in g for w in written_of[j]]
        g_site, g_warn, g_stats, epw = _group_site(gb, crs, frame, stations)
        ground = read_epw_header(epw)[1] if epw else None
        text, stats, warns = render_idf([w[0] for w in wl], [w[1] for w in wl], offset - origin, offset,
                                        options, [b.id for b in gb], shading, g_site, ground, crs,
                                        zone_info=[w[2] for w in wl],
                                        openings=[openings.get(w[3], ()) for w in wl],
                                        source_ids=[zones[w[3]].object_id for w in wl])
        stats.update(g_stats)
        stats["building_info"] = {blist[j].id: bstats[j] for j in g}
        if len(g) == 1:
            stats.update(bstats[g[0]])
        warns = list(warns) + g_warn + [n for j in g for n in zone_notes[j]]
        if epw and ground is None:
            warns.append("the weather file has no GROUND TEMPERATURES: 10 C under the ground floor all year")
        safe_write.write_text(path, text, root=out, encoding="ascii", errors="replace")
        return offset, stats, warns, kept_whole

    def downgrades_of(g, kept_whole, file_dg) -> dict:
        """Building id -> its downgrades as written (the stage's, zones kept whole, the file's
        simpler envelopes), for the buildings of ``g`` that have any."""
        down = {blist[j].id: [d.to_json() for d in (*model.downgrades.get(j, ()), *kept_whole.get(j, ()),
                                                      *file_dg.get(j, ()))] for j in g}
        return {k: v for k, v in down.items() if v}

    jobs = []
    for g in groups:
        stem = safe_stem(blist[g[0]].id if len(g) == 1 else "dataset", used)
        path = output_path(out, stem, ".idf")
        jobs.append((g, path))

    def finish(job):
        g, path = job
        ids = tuple(blist[i].id for i in g)
        try:
            return set_aside_failed(_finish(g, path, ids))
        except OSError as e:  # a full disk, a link planted under the name: this file only
            return ExportResult(ids, "", False, (not_written(e, "IDF"),), (0.0, 0.0, 0.0))
        except SiteError as e:  # placed nowhere: no IDF with a site the file did not give
            return ExportResult(ids, "", False, (f"IDF not written: {e}",), (0.0, 0.0, 0.0))

    def _finish(g, path, ids):
        offset, stats, warns, kept_whole = render(g, path, pieces)
        file_dg: dict[int, list] = {}
        problems = self_check(path)
        if (any("not fully enclosed" in p for p in problems) and options.party_split
                and stats.get("adiabatic_surfaces")):
            # the split party walls' extra vertices fail the enclosure test: whole faces
            offset, stats, warns, kept_whole = render(g, path, None)
            problems = self_check(path)
            warns = list(warns) + ["party walls not split: the split zone fails EnergyPlus's enclosure test"]
        if any("not fully enclosed" in p for p in problems):
            # the file's coordinates (rounded, in the file's frame) can fail the enclosure test
            # the zone's pieces passed: the first simpler envelope whose file passes
            for make in energy_model.FALLBACKS:
                simpler = {i: make(zones[i]) for j in g for i in zones_of[j]}
                if any(z is None for z in simpler.values()):
                    continue
                offset, stats, warns, kept_whole = render(g, path, None, simpler)
                problems = self_check(path)
                if not problems:
                    name = energy_model._fallback_name(make)
                    warns = list(warns) + [f"written with a simpler envelope ({name}, "
                                           "party walls as outdoor walls): the written zone failed EnergyPlus's "
                                           "enclosure test"]
                    file_dg = {j: _file_downgrades(zones, zones_of[j], simpler, party, name) for j in g}
                    break
        notes = [w for i in g for w in merge_notes[i]]
        warns = notes + list(warns)
        stats = {**stats, "downgrades": downgrades_of(g, kept_whole, file_dg)}
        record = _weather_record(stats)
        res = ExportResult(ids, str(path), not problems, tuple(problems),
                           tuple(float(x) for x in offset), tuple(warns), stats, record=record)
        if options.run:
            res = _run(res, path, stats.get("weather_file") or weather, options)
            if res.not_enclosed and options.party_split and stats.get("adiabatic_surfaces"):
                # EnergyPlus's enclosure test can reject the extra vertices of split party
                # walls: write the building again with whole-face party walls and re-run
                offset, stats, warns, kept_whole = render(g, path, None)
                problems = self_check(path)
                warns = notes + list(warns) + ["party walls not split: EnergyPlus found the split zone not enclosed"]
                stats = {**stats, "downgrades": downgrades_of(g, kept_whole, file_dg)}
                res = ExportResult(ids, str(path), not problems, tuple(problems),
                                   tuple(float(x) for x in offset), tuple(warns), stats, record=record)
                res = _run(res, path, stats.get("weather_file") or weather, options)
        return res

    if options.jobs > 1:
        with ThreadPoolExecutor(options.jobs) as ex:
            return list(ex.map(finish, jobs))
    return [finish(j) for j in jobs]


def _file_downgrades(zones, zone_ids, simpler, party, name: str) -> list:
    """Downgrades of zones ``zone_ids`` written as the envelopes ``simpler`` (zone index -> zone)
    because the written file failed its enclosure check."""
    why = "the written file failed EnergyPlus's enclosure test"
    out = []
    for i in zone_ids:
        out.append(dg.replaced(dg.fallback_kind(name), zones[i], simpler[i], f"{name}: {why}"))
        walls = dg.party_area(party, i, zones[i])
        if walls > 0:
            out.append(dg.party_walls_dropped(zones[i].object_id, walls, f"a simpler envelope ({name})"))
    return out


def _weather_record(stats: dict) -> dict:
    """The report's ``weather`` entry of an IDF: the EPW, its station and distance (km)."""
    if not stats.get("weather_file"):
        return {}
    return {"weather": {"file": Path(stats["weather_file"]).name, "station": stats.get("weather_station"),
                        "distance_km": stats.get("weather_distance_km")}}


def _shading_for(bi: int, blist, bboxes, zones, zones_of, party, radius: float) -> list[np.ndarray]:
    box = bboxes[bi]
    near = np.nonzero(np.all(bboxes[:, :2] <= box[3:5] + radius, axis=1)
                      & np.all(bboxes[:, 3:5] >= box[:2] - radius, axis=1))[0]
    own = set(zones_of[bi])
    out = []
    for nb in near:
        if nb == bi:
            continue
        for zi in zones_of[int(nb)]:
            z = zones[zi]
            for fi, f in enumerate(z.faces):
                if f.kind not in ("roof", "wall"):
                    continue
                if any(o in own for o, _ in party.get((zi, fi), [])):
                    continue
                pts, ends, n, c = _face_frame(z, f)
                out.extend(p for p in _pieces_from_points(pts, ends, n, c) if polygon_area3d(p) > 0.01)
    return out


def _scope(options) -> str:
    return "dataset" if options.mode == "dataset" else "context"


def _halo(options) -> float:
    # party walls are faces within a few cm of each other; shading reaches shading_radius
    return float(options.shading_radius) if options.shading else 1.0


def _write(buildings, outdir, options, *, crs=None, context=(), frame=None, **_):
    return write(buildings, outdir, options, crs=crs, context=context, frame=frame)


register_writer("idf", _write, self_check, scope=_scope, halo=_halo, prepare=with_energy_model)
