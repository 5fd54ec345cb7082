"""``python -m lod2energy.cfd IN -o OUTDIR [options]``: read, prepare and write an OpenFOAM case.

Buildings are validated, repaired and labelled by :func:`lod2energy.prepare.prepare` (as
``lod2energy export`` does); the case goes to ``OUTDIR/cfd`` and a summary to
``OUTDIR/cfd_report.json``. Exit status 0 when the case (and the mesh, with ``--mesh``) passed
its checks, 1 when it was written with problems, 2 when nothing could be written.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from dataclasses import replace

from lod2energy.config import DEFAULT
from lod2energy.exporters.cfd.options import CfdOptions, add_cli_arguments, options_from_args
from lod2energy.exporters.cfd.region import building_hull, make_region
from lod2energy.exporters.cfd.writer import export_case
from lod2energy.io import read
from lod2energy.logs import log
from lod2energy.model import FeatureError
from lod2energy.prepare import prepare
from lod2energy.run.driver import Command, Run, drive
from lod2energy.run.interrupt import EXIT_INVALID, EXIT_OK, EXIT_UNUSABLE
from lod2energy.safe_write import write_json


def parser() -> argparse.ArgumentParser:
    """The command's arguments: ``IN -o OUTDIR`` and the case's options."""
    ap = argparse.ArgumentParser(prog="python -m lod2energy.cfd", description=__doc__.splitlines()[0])
    ap.add_argument("input", help="input file (any format validate reads)")
    ap.add_argument("-o", "--output", required=True, help="OUTDIR (the case goes to OUTDIR/cfd)")
    ap.add_argument("--lod", default=None, help="LoD of the envelope (default: the highest)")
    ap.add_argument("--iterations", type=int, default=1000, help="simpleFoam iterations in controlDict")
    ap.add_argument("--nice", type=int, default=10, help="nice level of the meshing tools")
    add_cli_arguments(ap)
    return ap


def read_input(run: Run) -> None:
    """The case's options and the file read (exit 2 when it cannot be)."""
    a = run.args
    run.made["options"] = replace(options_from_args(a), iterations=a.iterations, nice=a.nice)
    model, feats = read(a.input)
    if model is None:
        for fe in feats:
            log.error("%s", fe.message)
        run.stop(EXIT_UNUSABLE)
    run.made.update(model=model, feats=feats)


def prepare_buildings(run: Run) -> None:
    """Every building that can meet the region validated, repaired and labelled, as ``export`` does."""
    a, m = run.args, run.made
    t0 = time.perf_counter()
    prepared, others, errors = m["prepared"], m["others"], m["errors"] = [], [], []
    region_filter = _prefilter(m["options"])
    for item in m["feats"]:
        if isinstance(item, FeatureError):
            errors.append(item.message)
            continue
        if not item.is_building:
            others.append(item)
            continue
        if region_filter is not None and not region_filter(item):
            prepared.append(item)  # outside the region: left out by export_case, not worth repairing
            continue
        try:
            pb, rec = prepare(item, DEFAULT, a, m["model"])
        except Exception as e:  # noqa: BLE001 - one building never stops the batch
            errors.append(f"{item.id}: pipeline failed: {type(e).__name__}: {e}")
            continue
        if not rec.energy.get("geometry_ready"):
            errors.append(f"{item.id}: not geometry-ready: {'; '.join(rec.energy.get('reasons', []))}")
            continue
        prepared.append(pb)
    m["seconds_prepare"] = time.perf_counter() - t0


def write_case(run: Run) -> None:
    """The case, ``OUTDIR/cfd_report.json``, the problems logged and a JSON summary on stdout."""
    a, m = run.args, run.made
    os.makedirs(a.output, exist_ok=True)
    res = export_case(m["prepared"] + m["others"], m["model"], a.output, m["options"])
    report = {"input_file": a.input, "seconds_prepare": round(m["seconds_prepare"], 2), "input_errors": m["errors"],
              "ok": res.ok, "path": res.path, "problems": list(res.problems), "stats": dict(res.stats),
              "building_ids": list(res.building_ids)}
    write_json(os.path.join(a.output, "cfd_report.json"), report, root=a.output, inputs=[a.input])
    for e in m["errors"]:
        log.error("%s: %s", a.input, e)
    for p in res.problems:
        (log.info if p.startswith("building ") else log.error)("%s", p)
    st = res.stats
    mesh = st.get("mesh", {})
    print(json.dumps({"ok": res.ok, "path": res.path, "buildings": st.get("buildings_included"),
                      "cells": mesh.get("cells"), "mesh_ok": mesh.get("check_mesh_ok"),
                      "carved_volume_error": mesh.get("carved_volume_error")}))
    run.code = EXIT_UNUSABLE if not res.path else EXIT_OK if res.ok else EXIT_INVALID


#: The CFD case's command: read -> prepare -> the case.
CFD = Command("cfd", (read_input, prepare_buildings, write_case), writers=lambda a: ("cfd",))


def main(argv: list[str] | None = None) -> int:
    """``python -m lod2energy.cfd``: the exit code."""
    return drive(CFD, parser().parse_args(argv))


def _prefilter(opts: CfdOptions):
    """A cheap test of whether a raw building can meet the region (None: every building)."""
    shape = make_region(opts.region, opts.centre, opts.radius).shape()
    if shape is None:
        return None

    def meets(b) -> bool:
        h = building_hull(b)
        return h is not None and h.intersects(shape)
    return meets


if __name__ == "__main__":
    sys.exit(main())
