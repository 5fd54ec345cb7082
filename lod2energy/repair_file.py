"""``lod2energy repair IN -o OUT``: the repair ladder over a file, every building held to its
time budget by an executor, written back as CityJSON / CityJSONSeq with a report."""
from __future__ import annotations

import argparse
import os
import sys
from dataclasses import replace

from lod2energy.config import Tolerances, tolerances
from lod2energy.run.executor import Failure, Overrun, make_executor
from lod2energy.run.interrupt import EXIT_INVALID, EXIT_UNUSABLE
from lod2energy.io import cityjson_write, read
from lod2energy.model import Building, FeatureError, frozen_mapping
from lod2energy.options import hard_budget
from lod2energy.repair import dataset_table, repair_attributes, repair_features, repair_info
from lod2energy.reports import err, frame_entry, json_ready, note_frame, refuse_overwriting_inputs
from lod2energy.run.driver import Command, Run, progress
from lod2energy.io.source import is_stdin, materialise, read_stdin
from lod2energy.safe_write import UnsafeWriteError, check_target, write_json_or_stdout
from lod2energy.validate.report import error_json
from lod2energy.viz.report import keep, write_report_html


def with_repair_attributes(b: Building) -> Building:
    """``b`` with its repair record as flat attributes of the root CityObject."""
    if not b.is_building:
        return b
    attrs = dict(b.root.attributes)
    attrs.update({k: v for k, v in repair_attributes(b).items() if v is not None})
    root = replace(b.root, attributes=frozen_mapping(attrs))
    return replace(b, objects=(root,) + b.objects[1:])


#: Output suffixes of ``lod2energy repair`` (the writer picks CityJSON or CityJSONSeq by them).
REPAIR_SUFFIXES = (".json", ".jsonl", ".cjseq")


def _repair_job(task):
    b, tol, timeout, merge_parts, lod = task
    return next(iter(repair_features([b], tol, timeout, merge_parts, lod)))


def _repaired(feats, tol: Tolerances, timeout: float, merge_parts: bool, lod, jobs: int | None):
    """``repair_features`` on an executor that holds each building to its time budget: a building
    still running ``max(2 s, 20 %)`` past ``timeout`` is stopped and kept as read, reported
    ``timeout`` (the ladder's own deadline is cooperative and cannot interrupt one long step)."""
    limit = hard_budget(timeout)
    with make_executor(jobs, None) as ex:
        for task, res in ex.map(_repair_job, ((f, tol, timeout, merge_parts, lod) for f in feats), limit):
            b = task[0]
            if isinstance(res, (Overrun, Failure)):
                why = f"timeout after {res.seconds:.0f} s" if isinstance(res, Overrun) else res.message
                stage = "timeout" if isinstance(res, Overrun) else "irreparable"
                res = b.with_provenance(repair={"stage": stage, "error": f"{stage}: {why}; kept as read",
                                                "iou": None, "mean_displacement": None, "hausdorff": None,
                                                "defects_before": [], "defects_after": [999]})
            yield res


def read_input(run: Run) -> None:
    """Standard input written to a scratch file; the output's suffix and targets checked; the file read."""
    a = run.args
    run.made["tol"] = tolerances(a)
    if is_stdin(a.input):
        path = materialise(read_stdin(), run.scratch())  # the report names the input as given (``shown``)
        a = run.args = argparse.Namespace(**{**vars(a), "input": path, "shown": a.input})
    if not a.output.lower().endswith(REPAIR_SUFFIXES):
        err(f"repair writes CityJSON (.json, .city.json) or CityJSONSeq (.jsonl, .city.jsonl): "
            f"cannot write {a.output!r}")
        run.stop(EXIT_UNUSABLE)
    refuse_overwriting_inputs([a.output, a.report if a.report != "-" else None], [a.input])
    if a.report and a.report != "-" and os.path.abspath(a.report) == os.path.abspath(a.output):
        raise UnsafeWriteError(f"--report {a.report} is the output file")
    model, feats = read(a.input, crs=getattr(a, "crs", None))
    if model is None:
        for fe in feats:
            err(fe.message)
        run.stop(EXIT_UNUSABLE)
    note_frame(a.input, model)
    run.made["html_inputs"] = {}
    if getattr(a, "html", None):
        check_target(a.html, None, [a.input, a.output])
        feats = keep(feats, run.made["html_inputs"])
    run.made.update(model=model, feats=feats)


def repair_each(run: Run) -> None:
    """Every building by the ladder on an executor; the report's records, the exit code."""
    a = run.args
    out_b, records, lost = run.made["buildings"], run.made["records"], run.made["unreadable"] = [], [], []
    tick, close = progress(a.quiet, os.path.basename(a.input))
    try:
        for item in _repaired(run.made["feats"], run.made["tol"], a.timeout, a.merge_parts, a.lod,
                              getattr(a, "jobs", None)):
            tick()
            if isinstance(item, FeatureError):
                err(f"{a.input}: {item.message}")
                if item.id is None:
                    run.worse(EXIT_UNUSABLE)
                lost.append({"id": item.id, "type": item.type, "errors": [error_json(item.code, "", item.message)]})
                run.worse(EXIT_INVALID)
                continue
            if item.is_building:
                rep = {"id": item.id, **{k: v for k, v in repair_info(item).items() if k != "geometries"}}
                records.append(rep)
                if rep.get("error"):
                    err(f"{a.input}: {item.type} {item.id}: {rep['error']}")
                after = rep.get("defects_after") or []
                if rep.get("stage") == "irreparable" or any(c != 601 for c in after):
                    run.worse(EXIT_INVALID)
            out_b.append(with_repair_attributes(item))
    finally:
        close()


def write_output(run: Run) -> None:
    """The repaired file, the report (``doc``) and the page."""
    a, m = run.args, run.made
    os.makedirs(os.path.dirname(os.path.abspath(a.output)), exist_ok=True)
    check_target(a.output, None, [a.input])
    cityjson_write.write(a.output, m["model"], m["buildings"])
    m["table"] = dataset_table(m["buildings"])
    doc = m["doc"] = {"input_file": getattr(a, "shown", a.input), "output_file": a.output, **frame_entry(m["model"]),
                      "summary": m["table"], "buildings": m["records"], "unreadable": m["unreadable"]}
    if a.report:
        write_json_or_stdout(a.report, doc, inputs=[a.input, a.output])
    if getattr(a, "html", None):
        try:
            write_report_html(json_ready(doc), a.html, inputs=m["html_inputs"],
                              outputs={b.id: b for b in m["buildings"]}, tol=m["tol"], input_files=[a.input, a.output])
        except Exception as e:  # noqa: BLE001 - the page is a view of the report
            err(f"{a.html} not written: {type(e).__name__}: {e}")


def print_summary(run: Run) -> None:
    """The summary line and the stages; with ``--report -`` on stderr; none with ``-q``."""
    if run.args.quiet:
        return
    table, out = run.made["table"], sys.stderr if run.args.report == "-" else sys.stdout  # stdout: the JSON alone
    keys = ("total", "valid_before", "valid_after", "compliant_before", "compliant_after", "local_repairs",
            "global_repairs", "left", "miou", "map_v")
    print("  ".join(f"{k}={table[k]:.3g}" if isinstance(table.get(k), float) else f"{k}={table.get(k)}"
                    for k in keys if k in table), file=out)
    print("stages: " + ", ".join(f"{k}: {v}" for k, v in (table.get("stages") or {}).items()), file=out)


#: ``lod2energy repair IN -o OUT``: every CityObject kept, defective buildings replaced by solids;
#: ``IN`` ``-`` reads standard input, ``--report -`` writes the report on standard output. The
#: run's ``made``: ``doc`` (the report; absent for an unusable input), ``buildings``, ``table``.
REPAIR = Command("repair", (read_input, repair_each, write_output, print_summary))
