"""``lod2energy validate FILE...``: every file read and validated (val3dity's codes, energy
compliance), the table printed, the JSON report and the HTML page written.

The run's ``made``: ``reports`` (one JSON report per file), ``rows`` (the table's), ``paths``
(the files read; standard input written to a scratch folder).
"""
from __future__ import annotations

import os
import sys
from collections import Counter

from lod2energy import crs as crs_
from lod2energy import safe_write
from lod2energy.config import tolerances
from lod2energy.errors import ParameterError
from lod2energy.io import read
from lod2energy.io.source import is_stdin, materialise, read_stdin
from lod2energy.logs import log
from lod2energy.run.driver import Command, Run, progress
from lod2energy.run.interrupt import EXIT_INVALID, EXIT_UNUSABLE
from lod2energy.validate.report import validate_features


def check_targets(run: Run) -> None:
    """Standard input read once at most; the report and the page never written over an input."""
    a = run.args
    run.made["tol"] = tolerances(a)
    if sum(is_stdin(f) for f in a.files) > 1:
        raise ParameterError("standard input (- or /dev/stdin) can be read only once")
    for target in (a.report, getattr(a, "html", None)):
        if target and target != "-":
            safe_write.check_target(target, None, [f for f in a.files if not is_stdin(f)])


def validate_each(run: Run) -> None:
    """Read and validate every file: its report, its row of the table, the exit code."""
    a = run.args
    reports, rows, paths = run.made.setdefault("reports", []), run.made.setdefault("rows", []), []
    run.made["paths"] = paths
    for shown in a.files:
        path = materialise(read_stdin(), run.scratch()) if is_stdin(shown) else shown
        paths.append(path)
        model, feats = read(path, primitive=a.primitive, inner_shells=a.inner_shell, crs=a.crs)
        geographic = getattr(model, "frame", None) is not None
        if geographic:  # the export side (records, options, writers) loads only for such a file
            from lod2energy.reports import frame_entry, note_frame
            note_frame(shown, model)
        elif model is not None and crs_.metres_note(shown, model.crs):
            log.info(crs_.metres_note(shown, model.crs))
        tick, close = progress(a.quiet, os.path.basename(shown), unit=" features")
        try:
            rep = validate_features(model, feats, shown, run.made["tol"], a.lod, tick)
        finally:
            close()
        if geographic:
            rep.update(frame_entry(model))
        reports.append(rep)
        for e in rep["dataset_errors"]:
            log.error("%s", e["info"] if shown in e["info"] else f"{shown}: {e['info']}")
        if model is None or rep["dataset_errors"]:
            run.worse(EXIT_UNUSABLE)
        elif not rep["validity"]:
            run.worse(EXIT_INVALID)
        codes = Counter(e["code"] for f in rep["features"] for e in f["errors"])
        rows.append({"file": shown, "features": len(rep["features"]),
                     "valid": sum(f["validity"] for f in rep["features"]),
                     "invalid": sum(not f["validity"] for f in rep["features"]),
                     "ready": rep["energy_overview"]["geometry_ready"],
                     "codes": " ".join(f"{c}x{n}" for c, n in sorted(codes.items())) or "-"})


def _one_report(reports: list[dict]) -> dict:
    return reports[0] if len(reports) == 1 else {"type": "lod2energy_reports", "reports": reports}


def write_page(run: Run) -> None:
    """``--html``: the page of the reports (a page that fails is one error line, not the run's)."""
    a = run.args
    if not getattr(a, "html", None):
        return
    from lod2energy.reports import json_ready
    from lod2energy.viz.report import write_report_for_files
    paths = run.made["paths"]
    try:
        # the files read again for the page: the panels' buildings and every footprint only
        write_report_for_files(json_ready(_one_report(run.made["reports"])), a.html, paths, tol=run.made["tol"],
                               input_files=paths, read_options={"primitive": a.primitive,
                                                                "inner_shells": a.inner_shell, "crs": a.crs})
    except Exception as e:  # noqa: BLE001 - the page is a view of the report
        log.error("%s not written: %s: %s", a.html, type(e).__name__, e)


def print_table(run: Run) -> None:
    """The table of files, on stdout (stderr when the report goes to stdout); none with ``-q``."""
    if run.args.quiet:
        return
    out = sys.stderr if run.args.report == "-" else sys.stdout
    hdr = f"{'file':<44} {'features':>8} {'valid':>6} {'invalid':>7} {'E-ready':>7}  errors"
    print(hdr, file=out)
    print("-" * len(hdr), file=out)
    for r in run.made["rows"]:
        print(f"{r['file'][-44:]:<44} {r['features']:>8} {r['valid']:>6} {r['invalid']:>7} {r['ready']:>7}  {r['codes']}",
              file=out)


def write_report(run: Run) -> None:
    """``--report``: the JSON report (``-``: on standard output)."""
    a = run.args
    if a.report:
        safe_write.write_json_or_stdout(a.report, _one_report(run.made["reports"]),
                                        inputs=[f for f in a.files if not is_stdin(f)])


VALIDATE = Command("validate", (check_targets, validate_each, write_page, print_table, write_report))
