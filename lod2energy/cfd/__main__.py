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
from lod2energy.errors import Lod2EnergyError
from lod2energy.exporters.cfd.options import add_cli_arguments, options_from_args
from lod2energy.exporters.cfd.region import building_hull, make_region
from lod2energy.exporters.cfd.writer import export_case
from lod2energy.io import read
from lod2energy.model import FeatureError
from lod2energy.prepare import prepare
from lod2energy.safe_write import write_json


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m lod2energy.cfd", description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("-o", "--output", required=True, help="OUTDIR (the case goes to OUTDIR/cfd)")
    ap.add_argument("--lod", default=None)
    ap.add_argument("--iterations", type=int, default=1000, help="simpleFoam iterations in controlDict")
    ap.add_argument("--nice", type=int, default=10, help="nice level of the meshing tools")
    add_cli_arguments(ap)
    a = ap.parse_args(argv)

    try:
        opts = replace(options_from_args(a), iterations=a.iterations, nice=a.nice)
    except Lod2EnergyError as e:
        print(f"lod2energy: error: {e}", file=sys.stderr)
        return 2
    model, feats = read(a.input)
    if model is None:
        for fe in feats:
            print(f"lod2energy: error: {fe.message}", file=sys.stderr)
        return 2
    t0 = time.perf_counter()
    prepared, others, errors = [], [], []
    region_filter = _prefilter(opts)
    for item in feats:
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
            pb, rec = prepare(item, DEFAULT, a, model)
        except Exception as e:  # noqa: BLE001 - one building never stops the batch
            errors.append(f"{item.id}: pipeline failed: {type(e).__name__}: {e}")
            continue
        if not rec.energy.get("geometry_ready"):
            errors.append(f"{item.id}: not geometry-ready: {'; '.join(rec.energy.get('reasons', []))}")
            continue
        prepared.append(pb)
    t_prep = time.perf_counter() - t0
    os.makedirs(a.output, exist_ok=True)
    res = export_case(prepared + others, model, a.output, opts)
    report = {"input_file": a.input, "seconds_prepare": round(t_prep, 2), "input_errors": errors, "ok": res.ok, "path": res.path,
              "problems": list(res.problems), "stats": dict(res.stats), "building_ids": list(res.building_ids)}
    write_json(os.path.join(a.output, "cfd_report.json"), report, root=a.output, inputs=[a.input])
    for e in errors:
        print(f"lod2energy: error: {a.input}: {e}", file=sys.stderr)
    for p in res.problems:
        print(f"lod2energy: {'note' if p.startswith('building ') else 'error'}: {p}", file=sys.stderr)
    st = res.stats
    m = st.get("mesh", {})
    print(json.dumps({"ok": res.ok, "path": res.path, "buildings": st.get("buildings_included"),
                      "cells": m.get("cells"), "mesh_ok": m.get("check_mesh_ok"),
                      "carved_volume_error": m.get("carved_volume_error")}))
    if not res.path:
        return 2
    return 0 if res.ok else 1


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
