"""``report.html``: one self-contained page (inline CSS, JS and images) with the method's pictures.

Dataset tables and plots for every report shape (:mod:`lod2energy.viz.data`), a plan view of
the tile coloured by status (and by heating need when simulated) whose buildings link to their
panels, and per-building panels: input and repaired geometry side by side, the face-adjacency
graph, the defects with their val3dity codes and the stage that fixed them.

Panels: every building of a file with at most ``cap`` buildings; for a larger file the
defective and repaired ones only, most severe first (irreparable, repaired globally, repaired
locally, then other defective input), at most ``cap`` (the page says how many were left out).
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.model import Building
from lod2energy.viz import data as D
from lod2energy.viz import figures as F
from lod2energy.viz import render as R

#: Default panel cap (see the module docstring).
DEFAULT_CAP = 16
_SEVERITY = {"irreparable": 0, "repaired globally": 1, "repaired locally": 2, "not repaired": 3, "valid": 4}


def panel_ids(rs: list[D.Row], cap: int = DEFAULT_CAP) -> tuple[list[str], int]:
    """Ids of the buildings that get a panel, and how many deserving ones the cap left out."""
    if len(rs) <= cap:
        return [r.id for r in rs], 0
    want = [r for r in rs if r.repaired or r.invalid_input or r.status != "valid"]
    want.sort(key=lambda r: _SEVERITY.get(r.status, 5))
    return [r.id for r in want[:cap]], max(0, len(want) - cap)


def _heat_colour(v: float, lo: float, hi: float) -> str:
    from matplotlib import colormaps
    from matplotlib.colors import to_hex
    t = 0.5 if hi <= lo else (v - lo) / (hi - lo)
    return to_hex(colormaps["YlOrRd"](0.15 + 0.85 * float(np.clip(t, 0, 1))))


def plan_footprint(b: Building) -> list[np.ndarray]:
    """The footprint of ``b`` on the plan view, ``[(k, 2) float, m]``: its ground faces
    (:func:`lod2energy.viz.render.footprint`), or for a mesh over ``MAX_PANEL_FACES`` faces (one
    that timed out, say) the convex hull of its vertices; empty when it cannot be drawn."""
    try:
        return R.footprint(b) if _n_faces(b) <= MAX_PANEL_FACES else _hull(b)
    except Exception:  # noqa: BLE001 - a building whose footprint cannot be drawn is left off the plan
        return []


def _plan(rs: list[D.Row], inputs: dict, outputs: dict, panels: set[str],
          footprints: dict | None = None) -> tuple[str, dict]:
    footprints = footprints or {}
    heat = [r.heating_kwh_m2 for r in rs if r.heating_kwh_m2 is not None]
    lo, hi = (float(np.percentile(heat, 5)), float(np.percentile(heat, 95))) if heat else (0.0, 0.0)
    items = []
    for r in rs:
        if r.id in footprints:
            fp = footprints[r.id]
        else:
            b = inputs.get(r.id) or outputs.get(r.id)
            if b is None:
                continue
            fp = plan_footprint(b)
        title = f"{r.id}: {r.status}" + (f", stage {r.stage}" if r.stage else "")
        it = {"id": r.id, "footprint": fp, "status": r.status, "fill": D.STATUS_COLOURS[r.status],
              "href": "#" + R.slug(r.id) if r.id in panels else None, "title": title}
        if r.heating_kwh_m2 is not None:
            it["value"] = r.heating_kwh_m2
            it["title"] += f", heating {r.heating_kwh_m2:.0f} kWh/m2"
        items.append(it)
    for it in items:
        if "value" in it:
            it["fill2"] = _heat_colour(it["value"], lo, hi)
    svg = R.plan_svg(items)
    return svg, {"heating_range": [round(lo, 3), round(hi, 3)] if heat else None,
                 "drawn": sum(1 for it in items if len(it["footprint"]))}


#: A building with more faces gets a panel of text only: drawing (and re-validating) it would
#: cost more than the rest of the page (a 100,000-face mesh that timed out, say).
MAX_PANEL_FACES = 5000


def _n_faces(b: Building | None) -> int:
    return 0 if b is None else sum(g.n_surfaces for o in b.objects for g in o.geometries if g.is_polygonal)


def _hull(b: Building) -> list[np.ndarray]:
    """The plan's footprint of a building over ``MAX_PANEL_FACES`` faces: the convex hull of its
    vertices projected on the ground, ``[(k, 2) float, m]``."""
    from scipy.spatial import ConvexHull
    pts = np.asarray(b.vertices, dtype=float)[:, :2]
    return [pts[ConvexHull(pts).vertices]]


def _panel(r: D.Row, before: Building | None, after: Building | None, tol: Tolerances) -> dict:
    from lod2energy.validate.checks import validate_building
    defects = []
    too_big = max(_n_faces(before), _n_faces(after)) > MAX_PANEL_FACES
    if too_big:
        before = after = None
    if before is not None:
        try:
            defects = validate_building(before, tol)
        except Exception:  # noqa: BLE001 - the panel shows what it can
            defects = []
    after_codes = set(r.after or ())
    rows = []
    for d in defects:
        fixed_by = None
        if r.stage is not None:
            fixed_by = "left" if d.code in after_codes else (r.stage if r.stage != "valid" else "-")
        rows.append({"code": d.code, "name": d.description, "location": d.location, "info": d.info,
                     "fixed_by": fixed_by})
    seen = {d["code"] for d in rows}
    for c in r.before:  # energy codes (1000+) of the repair record, not found by the val3dity checks
        if c not in seen and before is not None:
            rows.append({"code": c, "name": D.code_names([c])[str(c)], "location": "", "info": "from the repair record",
                         "fixed_by": None if r.stage is None else ("left" if c in after_codes else r.stage)})
    if before is None:  # no geometry at hand: the report's own error entries
        for e in r.errors:
            rows.append({"code": e.get("code"), "name": e.get("description", ""), "location": e.get("id", ""),
                         "info": e.get("info", ""), "fixed_by": None})
        if not r.errors:
            for c in r.before:
                rows.append({"code": c, "name": D.code_names([c])[str(c)], "location": "", "info": "",
                             "fixed_by": None if r.stage is None else ("left" if c in after_codes else r.stage)})
    geoms = []
    rep = (after.provenance.get("repair") if after is not None else None) or {}
    for e in rep.get("geometries", ()) or ():
        geoms.append({"object": e.get("object", e.get("coid", "")), "lod": e.get("lod"), "stage": e.get("stage"),
                      "before": list(e.get("defects_before", ())), "after": list(e.get("defects_after", ()))})
    pic, img = None, ""
    if before is not None or after is not None:
        try:
            pic = R.graph_picture(before if before is not None else after, defects, tol)
            img = R.panel_image(before, after, pic)
        except Exception as e:  # noqa: BLE001 - one bad render never stops the page
            img = ""
            pic = {"error": f"{type(e).__name__}: {e}", "counts": {}}
    if too_big:
        pic = {"error": f"not drawn: more than {MAX_PANEL_FACES} faces", "counts": {}}
    return {"id": r.id, "anchor": R.slug(r.id), "row": r, "status": r.status, "colour": D.STATUS_COLOURS[r.status],
            "defects": rows, "geometries": geoms, "image": img,
            "graph": {"status": (pic or {}).get("status"), "counts": (pic or {}).get("counts", {}),
                      "faces": len((pic or {}).get("nodes", []))}}


def _row_json(r: D.Row) -> dict:
    return {"id": r.id, "status": r.status, "stage": r.stage, "before": list(r.before),
            "after": None if r.after is None else list(r.after), "iou": r.iou, "displacement": r.displacement,
            "compliant": r.compliant, "typology": r.typology, "heating_kwh_m2": r.heating_kwh_m2}


def render_report_html(report: dict, *, inputs: dict | None = None, outputs: dict | None = None,
                       cap: int = DEFAULT_CAP, tol: Tolerances = DEFAULT, title: str | None = None,
                       footprints: dict | None = None) -> str:
    """The page as a string (see :func:`write_report_html`)."""
    import jinja2
    inputs, outputs, footprints = dict(inputs or {}), dict(outputs or {}), dict(footprints or {})
    rs = D.rows(report)
    fd = D.figure_data(rs)
    ids, left_out = panel_ids(rs, cap)
    by_id = {r.id: r for r in rs}
    panels = [_panel(by_id[i], inputs.get(i), outputs.get(i), tol) for i in ids]
    drawn = inputs or outputs or footprints
    plan, plan_info = _plan(rs, inputs, outputs, set(ids), footprints) if drawn else ("", {})
    plots = {"stages": F.plot_stages(fd["stages"]), "histograms": F.plot_histograms(fd["iou"], fd["displacement"]),
             "compliance": F.plot_compliance(fd["compliance"]), "validity": F.plot_validity(fd["validity_by_code"]),
             "heating": F.plot_heating(fd["heating_by_typology"])}
    kind = D.report_kind(report)
    src = report.get("input_file") or (report.get("reports") or [{}])[0].get("input_file", "")
    page_data = {"kind": kind, "input_file": src, "figures": fd, "cap": cap, "panels": ids, "left_out": left_out,
                 "plan": {k: v for k, v in plan_info.items()},
                 "graphs": {p["id"]: p["graph"] for p in panels},
                 "buildings": [_row_json(r) for r in rs],
                 "export_seconds": report.get("seconds")}
    env = jinja2.Environment(loader=jinja2.PackageLoader("lod2energy.templates", "."),
                             autoescape=jinja2.select_autoescape(["html", "j2"]), trim_blocks=True,
                             lstrip_blocks=True)
    env.filters["num"] = lambda v, f=".3f": "-" if v is None else format(v, f)
    tpl = env.get_template("report.html.j2")
    blob = json.dumps(page_data, default=_json_default, ensure_ascii=False).replace("</", "<\\/")
    return tpl.render(title=title or f"lod2energy report: {os.path.basename(src) or 'file'}", kind=kind,
                      src=src, src_name=os.path.basename(src), fd=fd, plots=plots, plan=plan, plan_info=plan_info, panels=panels,
                      left_out=left_out, cap=cap, n=len(rs), statuses=D.STATUSES, colours=D.STATUS_COLOURS,
                      graph_colours=R.GRAPH_COLOURS, data_json=blob, conditions=D.CONDITIONS,
                      has_geometry=bool(drawn))


def _json_default(o):
    if isinstance(o, np.generic):
        return o.item()
    if isinstance(o, D.Row):
        return _row_json(o)
    return str(o)


def write_report_html(report: dict, path, *, inputs: dict | None = None, outputs: dict | None = None,
                      cap: int = DEFAULT_CAP, tol: Tolerances = DEFAULT, root=None, input_files=(),
                      footprints: dict | None = None) -> Path:
    """Write ``report.html`` for a report of ``export``, ``repair --report`` or ``validate --report``.

    Parameters
    ----------
    report : dict
        The report as written to JSON (any of the three shapes).
    path : path-like
        The page to write (through :mod:`lod2energy.safe_write`, inside ``root``).
    inputs, outputs : dict of id -> Building, optional
        The buildings as read and as repaired/labelled; without them the page has tables and
        plots but no plan view and no renders.
    footprints : dict of id -> list of (k, 2) float, optional
        Plan footprints (:func:`plan_footprint`, m) of buildings not in ``inputs``: a large
        file's plan without all its buildings in memory (:func:`read_for_page`).
    cap : int
        Panels of a large file (see the module docstring).
    root : path-like, optional
        Folder the page must stay in (default: the page's folder).
    input_files : sequence of path-like
        Inputs the page must never overwrite.

    Returns
    -------
    Path of the written page.
    """
    from lod2energy.safe_write import write_text
    html = render_report_html(report, inputs=inputs, outputs=outputs, cap=cap, tol=tol, footprints=footprints)
    root = root if root is not None else os.path.dirname(os.path.abspath(path))
    return write_text(path, html, root=root, inputs=list(input_files))


def keep(features, into: dict):
    """Pass a feature stream through unchanged, storing its Buildings in ``into`` by id (for
    ``repair --html`` / ``validate --html``, whose streams are consumed by the command)."""
    for f in features:
        if isinstance(f, Building):
            into[f.id] = f
        yield f


def read_for_page(path: str, wanted: set[str]) -> tuple[dict[str, Building], dict[str, list]]:
    """The buildings of a file the page draws in full (ids in ``wanted``) and the plan footprint
    (:func:`plan_footprint`) of every other, read one at a time: memory grows with the panels
    and the footprints, not with the file."""
    from lod2energy.io import read
    model, feats = read(path)
    keep: dict[str, Building] = {}
    fps: dict[str, list] = {}
    if model is None:
        return keep, fps
    for f in feats:
        if not isinstance(f, Building):
            continue
        if f.id in wanted:
            keep[f.id] = f
            fps.pop(f.id, None)
        elif f.id not in keep:
            fps[f.id] = plan_footprint(f)
    return keep, fps


def read_buildings(path: str) -> dict[str, Building]:
    """Buildings of a file by id (unreadable features left out)."""
    from lod2energy.io import read
    model, feats = read(path)
    if model is None:
        return {}
    return {f.id: f for f in feats if isinstance(f, Building)}
