"""``lod2energy view FILE [--id ID]``: the report panel of one building, written and opened.

The building is validated, repaired, labelled and given U-values by
:func:`lod2energy.prepare.prepare`, as ``export`` does; the page has the same panel as
``report.html`` (input and repaired renders, face-adjacency graph, defects and stages).
"""
from __future__ import annotations

import os
import sys
import tempfile
import time
import webbrowser
from pathlib import Path
from types import SimpleNamespace

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.errors import InputError
from lod2energy.io import read
from lod2energy.io.source import is_stdin, materialise, read_stdin
from lod2energy.model import Building, FeatureError
from lod2energy.prepare import prepare
from lod2energy.reports import report_lazily
from lod2energy.run.driver import Command, Run
from lod2energy.viz.render import slug
from lod2energy.viz.report import DEFAULT_CAP, write_report_for_files, write_report_html


class ViewError(InputError):
    """The file cannot be read, or has no such building."""


def _pick(path: str, building_id: str | None):
    """``(model, building)``: the building ``building_id`` (or the first) of the file."""
    model, feats = read(path)
    if model is None:
        msgs = [f.message for f in feats if isinstance(f, FeatureError)]
        raise ViewError(f"{path}: cannot read: {msgs[0] if msgs else 'unknown format'}")
    for f in feats:
        if not isinstance(f, Building):
            continue
        if building_id is None and f.is_building:
            return model, f
        if building_id is not None and (f.id == building_id or building_id in {o.id for o in f.objects}):
            return model, f
    if building_id is None:
        raise ViewError(f"{path}: no building in this file")
    raise ViewError(f"{path}: no building with id {building_id!r}")


def has_display() -> bool:
    """A browser window can be opened (a display on Linux; macOS and Windows always)."""
    if sys.platform in ("darwin", "win32"):
        return True
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def view(path, building_id: str | None = None, outdir=".", *, tol: Tolerances = DEFAULT, options=None,
         open_browser: bool = True) -> Path:
    """Write ``OUTDIR/view-<id>.html`` with the panel of one building (the first if no id) and
    open it in a browser when a display is present.

    Parameters
    ----------
    path : path-like
        Any file ``lod2energy`` reads; ``-`` or ``/dev/stdin``: CityJSON or CityJSONSeq on standard input.
    building_id : str, optional
        Id of the building or of one of its BuildingParts.
    outdir : path-like
        Folder of the page (created).
    options : object, optional
        Pipeline options as :func:`lod2energy.prepare.prepare` takes them (``lod``,
        ``timeout``, ``merge_parts``, U-value overrides).

    Returns
    -------
    Path of the page.
    """
    path = os.fspath(path)
    if is_stdin(path):
        with tempfile.TemporaryDirectory(prefix="lod2energy-stdin-") as tmp:
            return view(materialise(read_stdin(), tmp), building_id, outdir, tol=tol, options=options,
                        open_browser=open_browser)
    model, b = _pick(path, building_id)
    a = options or SimpleNamespace(lod=None, timeout=30.0, merge_parts=False)
    pb, rec = prepare(b, tol, a, model)
    row = {**rec.row(), "repair": rec.repair, "energy": rec.energy, "thermal": rec.thermal, "exports": {}}
    report = {"input_file": path, "buildings": [row]}
    os.makedirs(outdir, exist_ok=True)
    out = write_report_html(report, Path(outdir) / f"view-{slug(b.id)[2:]}.html", inputs={b.id: b},
                            outputs={b.id: pb}, cap=1, tol=tol, input_files=[path])
    if open_browser and has_display():
        webbrowser.open(out.as_uri())
    return out


def show(run: Run) -> None:
    """Write (and open) the page of ``run.args``' building and print its path (``made["page"]``)."""
    a = run.args
    run.made["page"] = view(a.input, a.id, a.output, options=SimpleNamespace(
        lod=getattr(a, "lod", None), timeout=getattr(a, "timeout", 30.0), merge_parts=False),
        open_browser=not getattr(a, "no_open", False))
    print(run.made["page"])


#: ``lod2energy view``: exit 0 when the page is written, 2 on unusable input (:class:`ViewError`).
VIEW = Command("view", (show,))


def prepare_outputs(ids, inputs: dict[str, Building], tol: Tolerances = DEFAULT, options=None) -> dict:
    """Repaired, labelled buildings for ``ids`` by :func:`lod2energy.prepare.prepare`."""
    a = options or SimpleNamespace(lod=None, timeout=30.0, merge_parts=False)
    out = {}
    for i in ids:
        b = inputs.get(i)
        if b is not None and b.is_building:
            try:
                out[i] = prepare(b, tol, a)[0]
            except Exception:  # noqa: BLE001 - its panel shows the input only
                pass
    return out


def write_report_for(report_json, html_path=None, input_path: str | None = None, cap: int = DEFAULT_CAP,
                     tol: Tolerances = DEFAULT, plan_max: int | None = None) -> tuple[Path, dict]:
    """``report.html`` next to an existing ``report.json``: reads the input file the report names
    (or ``input_path``), re-prepares only the buildings that get a panel, writes the page (a
    report of more than ``plan_max`` buildings: its plan as a picture, see
    :mod:`lod2energy.viz.report`). Memory: the panels' buildings, not the file's.

    Returns the page's path and timings (s): ``read``, ``prepare``, ``html`` (wall clock) and
    ``html_cpu`` (CPU time of this process writing the page: what an export would add).
    """
    rep = report_lazily(str(report_json))  # its buildings read one at a time, when iterated
    src = input_path or rep.get("input_file") or ""
    html_path = html_path or Path(report_json).with_name("report.html")
    t0 = time.perf_counter()
    marks: list = []

    def outputs(ids, inputs) -> dict:  # the panels' buildings prepared again (timed)
        marks.append((time.perf_counter(), time.process_time()))
        out = prepare_outputs(ids, inputs, tol)
        marks.append((time.perf_counter(), time.process_time()))
        return out
    out = write_report_for_files(rep, html_path, [src], tol=tol, outputs=outputs, cap=cap, plan_max=plan_max,
                                 input_files=[src] if src else [])
    (t1, _), (t2, c2) = marks
    t3, c3 = time.perf_counter(), time.process_time()
    return out, {"read": round(t1 - t0, 3), "prepare": round(t2 - t1, 3), "html": round(t3 - t2, 3),
                 "html_cpu": round(c3 - c2, 3)}
