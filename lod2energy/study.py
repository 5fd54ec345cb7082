"""The study's choices about which buildings a run covers and what it knows of them.

``--buildings`` joins a table row to each building before the thermal stage (:func:`joined`);
``--ids`` and ``--region`` select the buildings every writer writes (:func:`selector`), while
the buildings within a neighbour writer's reach of a selected one are still prepared as
neighbours (:func:`selection_reach`); report.json's ``study`` block says what was used.
"""
from __future__ import annotations


import numpy as np

from lod2energy.exporters.cfd.region import building_hull
from lod2energy.io import read
from lod2energy.logs import log
from lod2energy.model import Building
from lod2energy.options import ExportOptions
from lod2energy.thermal.facts import TABLE_KEY, attribute_map


def joined(b: Building, table, input_ids: set) -> Building:
    """``b`` with its ``--buildings`` row (:data:`lod2energy.thermal.facts.TABLE_KEY`), its id noted."""
    bid = str(b.id)
    input_ids.add(bid)
    row = table.get(bid) if table else None
    return b.with_provenance(**{TABLE_KEY: row}) if row else b


def study_entry(options: ExportOptions) -> dict:
    """report.json's ``study``: the attribute map, the table's size and the selection."""
    out: dict = {"attribute_map": attribute_map(getattr(options.prepare.thermal, "attribute_map", None)).name}
    if options.buildings is not None:
        out["buildings_table"] = {"rows": len(options.buildings)}
    if options.ids is not None:
        out["ids"] = len(options.ids)
    if options.region is not None:
        out["region"] = options.region.as_dict()
    return out


def report_unknown_ids(input_path: str, input_ids: set, table, selection) -> dict:
    """A warning for the ids of ``--buildings`` and ``--ids`` that are no building of the file;
    ``{"buildings_table_not_in_input" | "ids_not_in_input": [ids]}`` for the report."""
    out = {}
    for what, key, ids in (("--buildings", "buildings_table_not_in_input", table or ()),
                           ("--ids", "ids_not_in_input", selection or ())):
        missing = sorted(set(ids) - input_ids)
        if missing:
            first = ", ".join(missing[:5]) + (", ..." if len(missing) > 5 else "")
            log.warning(f"{what}: {len(missing)} of {len(ids)} ids are not buildings of "
                  f"{input_path} ({first})")
            out[key] = missing[:1000]
    return out


def selector(ids, region):
    """``item -> bool`` of the buildings chosen by ``--ids`` and ``--region`` (None: all)."""
    if ids is None and region is None:
        return None
    shape = region.shape() if region is not None else None

    def chosen(item) -> bool:
        if ids is not None and str(item.id) not in ids:
            return False
        if shape is None:
            return True
        hull = building_hull(item)
        return hull is not None and hull.intersects(shape)
    return chosen


def selection_reach(input_path: str, selected, chosen, scope, options: ExportOptions):
    """``item -> bool``: whether a building outside the selection (``selected``) can be a
    neighbour of a selected one (its box, as read, within the writers' halo of a selected
    box, plus :data:`REACH_MARGIN`). Without a selection or a neighbour writer: never."""
    ctx = [w for w in chosen if scope[w.name] in ("context", "dataset") and w.halo(options.writer_options(w.name)) > 0]
    if selected is None or not ctx:
        return lambda item: False
    halo = max(w.halo(options.writer_options(w.name)) for w in ctx) + REACH_MARGIN
    boxes = []
    # only the selected ids are built when the selection is by id (the CityJSON readers skip the others)
    _, feats = read(input_path, only=options.ids) if options.ids is not None else read(input_path)
    for item in feats:
        if isinstance(item, Building) and item.is_building and selected(item):
            box = raw_box(item)
            if box is not None:
                boxes.append(box)
    if not boxes:
        return lambda item: False
    sel = np.array(boxes)

    def near(item) -> bool:
        box = raw_box(item)
        if box is None:
            return False
        return bool(np.any(np.all(sel[:, :3] - halo <= box[3:], axis=1) & np.all(box[:3] <= sel[:, 3:] + halo, axis=1)))
    return near


#: How far (m) a building's box as read may move in its repair and still be taken as a neighbour.
REACH_MARGIN = 1.0


def raw_box(b: Building):
    v = np.asarray(b.vertices, dtype=float)
    v = v[np.isfinite(v).all(axis=1)] if len(v) else v
    return np.concatenate([v.min(axis=0), v.max(axis=0)]) if len(v) else None
