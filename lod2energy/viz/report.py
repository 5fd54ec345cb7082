"""``report.html``: one self-contained page (inline CSS, JS and images) with the method's pictures.

Dataset tables and plots for every report shape (:mod:`lod2energy.viz.data`), a plan view of
the tile coloured by status (and by heating need when simulated) whose buildings link to their
panels, and per-building panels: input and repaired geometry side by side, the face-adjacency
graph, the defects with their val3dity codes and the stage that fixed them.

Panels: every building of a file with at most ``cap`` buildings; for a larger file the
defective and repaired ones only, most severe first (irreparable, repaired globally, repaired
locally, then other defective input), at most ``cap`` (the page says how many were left out).

City scale: the rows are read once, one at a time (:class:`PageRows`), into counters and a
bounded choice of panels. A file of at most ``plan_max`` buildings gets an SVG plan whose
footprints link to their panels and every row embedded as JSON; a larger one gets the plan as
a picture (PNG, coloured by status and by heating need), drawn from footprints kept in an
unnamed scratch file (:class:`FootprintSpill`), and the rows of its panels only (``report.csv``
has every building). Memory and page size then stay bounded however large the city.
"""
from __future__ import annotations

import base64
import io
import json
import os
import time
from array import array
from pathlib import Path
from typing import Iterable

import numpy as np

import lod2energy.graph  # noqa: F401 - the panels' face-adjacency graphs (warm_page loads it in a worker)
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.io import read
from lod2energy.io.seen_ids import id_key
from lod2energy.model import Building
from lod2energy.safe_write import write_text
from lod2energy.validate.checks import validate_building
from lod2energy.viz import data as D
from lod2energy.viz import figures as F
from lod2energy.viz import render as R
from lod2energy.viz.footprints import (MAX_PANEL_FACES, FootprintSpill, drawable, n_faces,
                                       plan_footprint)
from lod2energy.viz.warnings import WarningTally, study_warnings

#: Default panel cap (see the module docstring).
DEFAULT_CAP = 16
_SEVERITY = {"irreparable": 0, "repaired globally": 1, "repaired locally": 2, "not repaired": 3, "valid": 4}


#: Above this many buildings the plan view is a picture and only the panels' rows are embedded.
PLAN_SVG_MAX = 5000
#: Longer side of the plan picture of a large file, px.
PLAN_PX = 1600


class PageRows:
    """What the page needs of a report's rows, read once and one at a time.

    Keeps the counters of every figure (:class:`lod2energy.viz.data.Tally`), the candidates for
    the panels (at most ``cap`` per severity class), 17 bytes per building for the plan picture
    (a key of the id, the status, the heating need) and, while the file has at most
    ``plan_max`` buildings, the rows themselves.

    Parameters
    ----------
    rs : iterable of Row
    cap : int
        Panels of a large file (see the module docstring).
    plan_max : int, optional
        Largest file drawn as an SVG plan with every row embedded (default
        :data:`PLAN_SVG_MAX`).
    """

    def __init__(self, rs: Iterable[D.Row] = (), cap: int = DEFAULT_CAP, plan_max: int | None = None):
        self.cap = int(cap)
        self.plan_max = int(PLAN_SVG_MAX if plan_max is None else plan_max)
        self.tally = D.Tally()
        self.n = 0
        self.rows: list[D.Row] | None = []  # every row, until there are more than plan_max
        self._first: list[D.Row] = []  # the first ``cap`` rows (the panels of a small file)
        self._worst: dict[int, list[D.Row]] = {}  # severity -> the first ``cap`` deserving rows
        self._deserving = 0
        self.keys, self.status, self.heat = array("q"), array("B"), array("d")
        self.warnings = WarningTally()
        for r in rs:
            self.add(r)

    def add(self, r: D.Row) -> None:
        self.n += 1
        self.tally.add(r)
        if self.rows is not None:
            self.rows.append(r)
            if len(self.rows) > self.plan_max:
                self.rows = None
        if len(self._first) < self.cap:
            self._first.append(r)
        if r.repaired or r.invalid_input or r.status != "valid":
            self._deserving += 1
            worst = self._worst.setdefault(_SEVERITY.get(r.status, 5), [])
            if len(worst) < self.cap:
                worst.append(r)
        self.keys.append(id_key(r.id))
        self.status.append(D.STATUSES.index(r.status))
        self.heat.append(np.nan if r.heating_kwh_m2 is None else r.heating_kwh_m2)
        self.warnings.add(r.id, r.warnings)

    def warning_table(self, study: dict | None = None) -> list[dict]:
        """The warnings by kind (:meth:`lod2energy.viz.warnings.WarningTally.table`)."""
        return self.warnings.table(study)

    @property
    def large(self) -> bool:
        """More than ``plan_max`` buildings: a plan picture, the panels' rows only."""
        return self.n > self.plan_max

    def panel_rows(self) -> list[D.Row]:
        """Rows of the buildings that get a panel, in the order of the page."""
        if self.n <= self.cap:
            return list(self._first)
        return [r for s in sorted(self._worst) for r in self._worst[s]][:self.cap]

    @property
    def left_out(self) -> int:
        """Deserving buildings the cap left without a panel."""
        return 0 if self.n <= self.cap else max(0, self._deserving - self.cap)

    def embedded(self) -> list[D.Row]:
        """The rows embedded in the page: every row of a small file, the panels' of a large one."""
        return list(self.rows) if self.rows is not None and not self.large else self.panel_rows()

    def heating_range(self) -> tuple[float, float] | None:
        """5th and 95th percentile of the heating need, kWh/m2 (None: nothing simulated)."""
        h = np.frombuffer(self.heat, dtype=np.float64) if len(self.heat) else np.zeros(0)
        h = h[~np.isnan(h)]
        return (float(np.percentile(h, 5)), float(np.percentile(h, 95))) if len(h) else None


def _heat_colour(v: float, lo: float, hi: float) -> str:
    from matplotlib import colormaps
    from matplotlib.colors import to_hex
    t = 0.5 if hi <= lo else (v - lo) / (hi - lo)
    return to_hex(colormaps["YlOrRd"](0.15 + 0.85 * float(np.clip(t, 0, 1))))


def _plan(rs: list[D.Row], inputs: dict, outputs: dict, panels: set[str],
          footprints: dict | None = None) -> tuple[str, dict]:
    """The SVG plan of a small file: a footprint per building, linked to its panel."""
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


def _plan_picture(page: PageRows, footprints, inputs: dict, outputs: dict) -> tuple[dict, dict]:
    """The plan of a large file as PNG pictures (data URLs): ``{"status": url, "heat": url or
    None}``, and the plan's facts. ``footprints``: a :class:`FootprintSpill` or a dict of id ->
    rings; the panels' buildings (``inputs``, ``outputs``) are drawn from their geometry."""
    from PIL import Image, ImageDraw
    given = footprints if isinstance(footprints, dict) else {}
    own = {}  # the panels' buildings not among the footprints of a dict
    for store in (inputs, outputs):
        for i, b in store.items():
            if i not in given and i not in own:
                own[i] = drawable(plan_footprint(b))

    def items():
        """``(key, rings)``: the footprints given, then the panels' own (drawn last, over the
        others, whether or not a spill holds theirs too)."""
        if isinstance(footprints, dict):
            for i, rings in footprints.items():
                yield id_key(i), drawable(rings)
        else:
            mine = {id_key(i) for i in own}
            yield from ((k, rings) for k, rings in footprints if k not in mine)
        for i, rings in own.items():
            yield id_key(i), rings

    lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
    if isinstance(footprints, FootprintSpill):
        lo, hi = footprints.lo.copy(), footprints.hi.copy()
        extra = own.values()
    else:
        extra = (rings for _, rings in items())
    for rings in extra:
        for r in rings:
            lo, hi = np.minimum(lo, r.min(axis=0)), np.maximum(hi, r.max(axis=0))
    if not np.all(np.isfinite(lo)):
        return {}, {"drawn": 0}
    span = max(float((hi - lo).max()), 1e-6)
    s = (PLAN_PX - 8) / span
    w, h = int(np.ceil((hi[0] - lo[0]) * s)) + 9, int(np.ceil((hi[1] - lo[1]) * s)) + 9
    order = np.argsort(np.frombuffer(page.keys, dtype=np.int64), kind="stable")
    keys = np.frombuffer(page.keys, dtype=np.int64)[order]
    status = np.frombuffer(page.status, dtype=np.uint8)[order]
    rng = page.heating_range()
    fills = [tuple(int(D.STATUS_COLOURS[st][j:j + 2], 16) for j in (1, 3, 5)) for st in D.STATUSES]
    pics = {"status": Image.new("RGB", (w, h), "white")}
    if rng is not None:  # the heating need as one of 255 colours of the plan's scale (255: none)
        from matplotlib import colormaps
        heat = np.frombuffer(page.heat, dtype=np.float64)[order]
        with np.errstate(invalid="ignore"):
            t = (heat - rng[0]) / (rng[1] - rng[0]) if rng[1] > rng[0] else np.where(np.isnan(heat), heat, 0.5)
            level = np.where(np.isnan(t), 255, np.round(np.clip(t, 0, 1) * 254)).astype(np.uint8)
        del heat, t
        lut = (np.asarray(colormaps["YlOrRd"](0.15 + 0.85 * np.arange(255) / 254))[:, :3] * 255).round().astype(int)
        heat_fills = [tuple(int(c) for c in rgb) for rgb in lut] + [(221, 221, 221)]
        pics["heat"] = Image.new("RGB", (w, h), "white")
    del order
    draws = {m: ImageDraw.Draw(im) for m, im in pics.items()}
    outline = (51, 51, 51) if s >= 2.0 else None  # outlines only where a metre is 2 px or more
    drawn = 0
    for k, rings in items():
        j = int(np.searchsorted(keys, k))
        if j >= len(keys) or keys[j] != k or not any(len(r) for r in rings):
            continue
        drawn += 1
        colour = {"status": fills[status[j]]}
        if "heat" in pics:
            colour["heat"] = heat_fills[level[j]]
        for r in rings:
            q = [(4 + (x - lo[0]) * s, 4 + (hi[1] - y) * s) for x, y in np.asarray(r)[:, :2]]
            for m, d in draws.items():
                if len(q) >= 3 and np.ptp([p[0] for p in q]) + np.ptp([p[1] for p in q]) >= 1.0:
                    d.polygon(q, fill=colour[m], outline=outline)
                else:  # smaller than a pixel: a dot
                    d.point(q[0], fill=colour[m])
    urls = {}
    for m, im in pics.items():
        buf = io.BytesIO()
        im.save(buf, format="PNG", optimize=True)
        urls[m] = "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")
    return urls, {"drawn": drawn, "picture": [w, h], "metres_per_px": round(1.0 / s, 3),
                  "heating_range": [round(rng[0], 3), round(rng[1], 3)] if rng else None}


def _panel(r: D.Row, before: Building | None, after: Building | None, tol: Tolerances) -> dict:
    defects = []
    too_big = max(n_faces(before), n_faces(after)) > MAX_PANEL_FACES
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


def page_job(job: tuple) -> dict:
    """One picture job of the page: ``("plots", figure_data)`` -> the plots (SVG data URLs by
    name), ``("panel", (row, before, after, tol))`` -> a panel (:func:`_panel`). Pure and
    picklable: a process pool renders the page's pictures side by side (``mapper`` of
    :func:`render_report_html`), into the same bytes as here."""
    kind, arg = job
    if kind == "plots":
        fd = arg
        return {"stages": F.plot_stages(fd["stages"]), "histograms": F.plot_histograms(fd["iou"], fd["displacement"]),
                "compliance": F.plot_compliance(fd["compliance"]), "validity": F.plot_validity(fd["validity_by_code"]),
                "heating": F.plot_heating(fd["heating_by_typology"])}
    return _panel(*arg)


def warm_page(_=None, after: int | None = None) -> None:
    """Load what :func:`page_job` loads (matplotlib, its fonts, the checks), in a pool worker
    left without a job at the end of the export's last pass, so that the page's jobs do not
    wait for it. ``after``: first wait for that process to end (the one-file writers beside
    the pool), so that the two are not at their largest memory at once."""
    while after is not None:
        try:
            with open(f"/proc/{after}/stat", "rb") as f:
                if f.read().rsplit(b")", 1)[1].split()[0] in (b"Z", b"X"):
                    break
        except (OSError, IndexError):
            break
        time.sleep(0.05)

    from matplotlib.collections import EllipseCollection, LineCollection, PolyCollection  # noqa: F401
    fig = F.new_figure(1.0, 1.0)
    fig.add_subplot().plot([0, 1], [0, 1])
    for fmt in ("svg", "png"):  # the first figure drawn loads the fonts and the backends
        fig.savefig(io.BytesIO(), format=fmt)


def _row_json(r: D.Row) -> dict:
    return {"id": r.id, "status": r.status, "stage": r.stage, "before": list(r.before),
            "after": None if r.after is None else list(r.after), "iou": r.iou, "displacement": r.displacement,
            "compliant": r.compliant, "typology": r.typology, "heating_kwh_m2": r.heating_kwh_m2}


def render_report_html(report: dict, *, inputs: dict | None = None, outputs: dict | None = None,
                       cap: int = DEFAULT_CAP, tol: Tolerances = DEFAULT, title: str | None = None,
                       footprints=None, page: PageRows | None = None, plan_max: int | None = None,
                       mapper=None) -> str:
    """The page as a string (see :func:`write_report_html`)."""
    inputs, outputs = dict(inputs or {}), dict(outputs or {})
    if not isinstance(footprints, FootprintSpill):
        footprints = dict(footprints or {})
    if page is None:
        page = PageRows(D.iter_rows(report), cap, plan_max)
    fd = page.tally.figure_data()
    panel_rows = page.panel_rows()
    ids = [r.id for r in panel_rows]
    jobs = [("plots", fd)] + [("panel", (r, inputs.get(r.id), outputs.get(r.id), tol)) for r in panel_rows]
    done = list(mapper(page_job, jobs)) if mapper is not None else []
    done = [d if isinstance(d, dict) else page_job(j) for d, j in zip(done, jobs)] or [page_job(j) for j in jobs]
    plots, panels = done[0], done[1:]
    drawn = bool(inputs or outputs or (footprints.n if isinstance(footprints, FootprintSpill) else footprints))
    plan, picture, plan_info = "", {}, {}
    if drawn and page.large:
        picture, plan_info = _plan_picture(page, footprints, inputs, outputs)
    elif drawn:
        plan, plan_info = _plan(page.rows or [], inputs, outputs, set(ids), footprints)
    kind = D.report_kind(report)
    src = report.get("input_file") or (report.get("reports") or [{}])[0].get("input_file", "")
    embedded = page.embedded()
    warnings = page.warning_table(study_warnings(report))
    page_data = {"kind": kind, "input_file": src, "figures": fd, "cap": cap, "panels": ids, "left_out": page.left_out,
                 "warnings": warnings,
                 "plan": {k: v for k, v in plan_info.items()},
                 "graphs": {p["id"]: p["graph"] for p in panels},
                 "buildings": [_row_json(r) for r in embedded],
                 "buildings_embedded": "all" if len(embedded) == page.n else "panels",
                 "export_seconds": report.get("seconds")}
    import jinja2
    env = jinja2.Environment(loader=jinja2.PackageLoader("lod2energy.templates", "."),
                             autoescape=jinja2.select_autoescape(["html", "j2"]), trim_blocks=True,
                             lstrip_blocks=True)
    env.filters["num"] = lambda v, f=".3f": "-" if v is None else format(v, f)
    tpl = env.get_template("report.html.j2")
    blob = json.dumps(page_data, default=_json_default, ensure_ascii=False).replace("</", "<\\/")
    return tpl.render(title=title or f"lod2energy report: {os.path.basename(src) or 'file'}", kind=kind,
                      src=src, src_name=os.path.basename(src), fd=fd, plots=plots, plan=plan, picture=picture,
                      plan_info=plan_info, panels=panels, plan_max=page.plan_max,
                      left_out=page.left_out, cap=cap, n=page.n, statuses=D.STATUSES, colours=D.STATUS_COLOURS,
                      graph_colours=R.GRAPH_COLOURS, data_json=blob, conditions=D.CONDITIONS, warnings=warnings,
                      has_geometry=drawn)


def _json_default(o):
    if isinstance(o, np.generic):
        return o.item()
    if isinstance(o, D.Row):
        return _row_json(o)
    return str(o)


def write_report_html(report: dict, path, *, inputs: dict | None = None, outputs: dict | None = None,
                      cap: int = DEFAULT_CAP, tol: Tolerances = DEFAULT, root=None, input_files=(),
                      footprints=None, page: PageRows | None = None, plan_max: int | None = None,
                      mapper=None) -> Path:
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
    footprints : dict of id -> list of (k, 2) float, or FootprintSpill, optional
        Plan footprints (:func:`plan_footprint`, m) of buildings not in ``inputs``: a large
        file's plan without all its buildings in memory (:func:`read_for_page`).
    page : PageRows, optional
        The report's rows already read (default: read from ``report``).
    plan_max : int, optional
        Largest file drawn as an SVG plan with every row embedded (default
        :data:`PLAN_SVG_MAX`); a larger one gets a plan picture and its panels' rows (see the
        module docstring).
    cap : int
        Panels of a large file (see the module docstring).
    root : path-like, optional
        Folder the page must stay in (default: the page's folder).
    input_files : sequence of path-like
        Inputs the page must never overwrite.
    mapper : callable, optional
        ``mapper(page_job, jobs)`` -> the results of :func:`page_job` for ``jobs``, in order
        (e.g. over a process pool); a result that is not a dict (a failed job) is computed
        here. Default: every picture here.

    Returns
    -------
    Path of the written page.
    """
    html = render_report_html(report, inputs=inputs, outputs=outputs, cap=cap, tol=tol, footprints=footprints,
                              page=page, plan_max=plan_max, mapper=mapper)
    root = root if root is not None else os.path.dirname(os.path.abspath(path))
    return write_text(path, html, root=root, inputs=list(input_files))


def write_report_for_files(report: dict, path, files, *, tol: Tolerances = DEFAULT, outputs=None,
                           cap: int = DEFAULT_CAP, plan_max: int | None = None, root=None, input_files=(),
                           read_options: dict | None = None, page: PageRows | None = None,
                           footprints: FootprintSpill | None = None, mapper=None) -> Path:
    """``report.html`` for a report of ``files``, reading them again for the page: the panels'
    buildings whole, the others' footprints only (in a scratch file beside the page over
    ``plan_max`` buildings), so that memory does not grow with the files. The one way every
    command writes its page (``export``, ``validate --html``, ``lod2energy view``).

    Parameters
    ----------
    outputs : dict or callable, optional
        The repaired buildings of the panels, or ``outputs(ids, inputs) -> dict`` called with
        the panels' ids (in page order) and their buildings as read.
    page : PageRows, optional
        The report's rows already read (default: read from ``report``).
    read_options : dict, optional
        For :func:`lod2energy.io.read` (``primitive``, ``inner_shells``).
    footprints : FootprintSpill, optional
        The plan footprints of every object of ``files`` as read, in file order (``export``'s
        workers draw them as they go): then only the panels' buildings are read again, and
        nothing else is built.
    mapper : callable, optional
        Renders the page's pictures (:func:`write_report_html`).
    """
    page = page if page is not None else PageRows(D.iter_rows(report), cap, plan_max)
    ids = [r.id for r in page.panel_rows()]
    given = footprints is not None
    spill = None if given else FootprintSpill(os.path.dirname(os.path.abspath(path))) if page.large else None
    inputs: dict[str, Building] = {}
    fps: dict[str, list] = {}
    try:
        for f in files:
            if f and os.path.isfile(f):
                if given:
                    inputs.update((b.id, b) for b in read(f, only=set(ids), **(read_options or {}))[1])
                    continue
                i, fp = read_for_page(f, set(ids), spill, **(read_options or {}))
                inputs.update(i)
                fps.update(fp)
        if given:
            spill = None  # the caller's to close
            fps = footprints if page.large else footprints.by_id(r.id for r in page.rows or ())
        if callable(outputs):
            outputs = outputs(ids, inputs)
        return write_report_html(report, path, inputs=inputs, outputs=outputs, cap=cap, tol=tol, root=root,
                                 input_files=input_files, footprints=spill if spill is not None else fps,
                                 page=page, mapper=mapper)
    finally:
        if spill is not None:
            spill.close()


def keep(features, into: dict):
    """Pass a feature stream through unchanged, storing its Buildings in ``into`` by id (for
    ``repair --html`` / ``validate --html``, whose streams are consumed by the command)."""
    for f in features:
        if isinstance(f, Building):
            into[f.id] = f
        yield f


def read_for_page(path: str, wanted: set[str], spill: FootprintSpill | None = None, **read_options
                  ) -> tuple[dict[str, Building], dict[str, list]]:
    """The buildings of a file the page draws in full (ids in ``wanted``) and the plan footprint
    (:func:`plan_footprint`) of every other, read one at a time: memory grows with the panels
    and the footprints, not with the file; with a ``spill`` the footprints go to it (the dict
    returned is then empty) and memory grows with the panels only. ``read_options`` go to
    :func:`lod2energy.io.read` (``primitive``, ``inner_shells``)."""
    model, feats = read(path, **read_options)
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
        elif spill is not None:
            spill.add(f.id, plan_footprint(f))
        elif f.id not in keep:
            fps[f.id] = plan_footprint(f)
    return keep, fps
