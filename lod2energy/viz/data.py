"""What the HTML report plots: one normalised row per building and the numbers of every figure.

The report of ``lod2energy export`` (``report.json``: ``buildings[]`` rows with ``repair``,
``energy``, ``thermal``, ``exports``), of ``repair --report`` (``summary`` + ``buildings[]``
repair records) and of ``validate --report`` (val3dity's ``features[]``, or
``{"type": "lod2energy_reports", "reports": [...]}`` for several files) all become the same
:class:`Row` list; every figure and table of the page is a pure function of that list, and
the page embeds the returned numbers as JSON so that a browser test can compare them with
``report.json``.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from lod2energy.validate.codes import name as code_name

#: Repair stages in ladder order (as :data:`lod2energy.repair.pipeline.STAGES`).
STAGES = ("valid", "cleanup", "orientation", "holefill", "refill", "roofs", "alphashape", "footprint",
          "hull", "irreparable")
LOCAL = ("cleanup", "orientation", "holefill", "refill")
GLOBAL = ("roofs", "alphashape", "footprint", "hull")
#: Plan-view / panel status classes, in the order of the legend.
STATUSES = ("valid", "repaired locally", "repaired globally", "irreparable", "not repaired")
STATUS_COLOURS = {"valid": "#4daf4a", "repaired locally": "#377eb8", "repaired globally": "#ff7f00",
                  "irreparable": "#e41a1c", "not repaired": "#999999"}
#: Energy-compliance conditions of :func:`lod2energy.validate.compliance.energy_compliance`.
CONDITIONS = ("closed_2manifold", "outward_normals", "no_degenerate_faces", "labelled", "u_values")
#: Bin edges of the IoU histogram (1) and of the mean-displacement histogram (m).
IOU_BINS = tuple(np.round(np.linspace(0.0, 1.0, 21), 3).tolist())
DISPLACEMENT_BINS = (0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0)


@dataclass(frozen=True)
class Row:
    """One building of a report, whatever command wrote it.

    Attributes
    ----------
    id, type : str
    stage : str or None
        Repair stage (``None`` for a validation report: nothing was repaired).
    before, after : tuple of int
        val3dity codes found in the input / left in the output (``after`` is ``None`` for a
        validation report).
    iou : float or None
        Volumetric IoU input vs repaired (1).
    displacement : float or None
        Mean distance of input vertices to the repaired surface, m.
    compliant : bool or None
        Energy-compliant after the pipeline (validate: as read).
    conditions : dict
        Energy-compliance conditions (name -> bool) after the pipeline.
    typology : str or None
    heating_kwh_m2 : float or None
        Simulated annual heating need per m2 of footprint x storeys (or ground area), kWh/m2.
    exports : dict
        Format -> ``{"ok": bool, "problems": [...]}``.
    errors : tuple of dict
        val3dity error entries (code, description, id, info) when the report lists them.
    message : str
    """

    id: str
    type: str = "Building"
    stage: str | None = None
    before: tuple[int, ...] = ()
    after: tuple[int, ...] | None = None
    iou: float | None = None
    displacement: float | None = None
    compliant: bool | None = None
    conditions: dict = field(default_factory=dict)
    typology: str | None = None
    heating_kwh_m2: float | None = None
    exports: dict = field(default_factory=dict)
    errors: tuple = ()
    message: str = ""

    @property
    def status(self) -> str:
        """One of :data:`STATUSES`."""
        if self.stage is None:
            return "valid" if not [c for c in self.before if c != 601] else "not repaired"
        if self.stage == "irreparable" or any(c != 601 for c in (self.after or ())):
            return "irreparable"
        if self.stage in LOCAL:
            return "repaired locally"
        if self.stage in GLOBAL:
            return "repaired globally"
        return "valid"

    @property
    def repaired(self) -> bool:
        return self.stage not in (None, "valid")

    @property
    def invalid_input(self) -> bool:
        return any(c != 601 for c in self.before)


def _codes(v) -> tuple[int, ...]:
    """Codes from a list, a space-separated string (CSV-like rows) or None."""
    if v is None or v == "":
        return ()
    if isinstance(v, str):
        return tuple(sorted({int(t) for t in v.split() if t.strip().lstrip("-").isdigit()}))
    return tuple(sorted({int(c) for c in v}))


def _num(v) -> float | None:
    try:
        f = float(v)
    except (TypeError, ValueError):
        return None
    return f if np.isfinite(f) else None


def report_kind(report: dict) -> str:
    """``"export"``, ``"repair"`` or ``"validate"`` (the command that wrote ``report``)."""
    if report.get("type") in ("val3dity_report", "lod2energy_reports") or "features" in report:
        return "validate"
    if "summary" in report or "output_file" in report:
        return "repair"
    return "export"


def heating_per_m2(b: dict) -> float | None:
    """Annual heating need of an export row per m2 of floor (footprint x storeys), kWh/m2."""
    idf = (b.get("exports") or {}).get("idf") or {}
    h = _num(idf.get("heating_kwh", b.get("heating_kwh")))
    if h is None:
        return None
    th = b.get("thermal") or {}
    fp = _num(th.get("footprint")) or _num((th.get("areas") or {}).get("ground"))
    floors = _num(th.get("storeys")) or 1.0
    return h / (fp * floors) if fp else None


def rows(report: dict) -> list[Row]:
    """Normalised rows of a report of any of the three shapes (buildings only)."""
    kind = report_kind(report)
    if kind == "validate":
        reps = report.get("reports") if report.get("type") == "lod2energy_reports" else [report]
        out = []
        for rep in reps:
            for f in rep.get("features", []):
                if f.get("type") not in ("Building", None) and "energy" not in f:
                    continue
                en = f.get("energy") or {}
                out.append(Row(id=str(f["id"]), type=f.get("type", "Building"),
                               before=_codes(e["code"] for e in f.get("errors", [])),
                               compliant=en.get("compliant"),
                               conditions={k: en[k] for k in CONDITIONS if k in en},
                               errors=tuple(f.get("errors", []))))
        return out
    if kind == "repair":
        out = []
        for b in report.get("buildings", []):
            out.append(Row(id=str(b["id"]), stage=b.get("stage") or "valid",
                           before=_codes(b.get("defects_before")), after=_codes(b.get("defects_after")),
                           iou=_num(b.get("iou")), displacement=_num(b.get("mean_displacement")),
                           compliant=not [c for c in _codes(b.get("defects_after")) if c != 601],
                           message=b.get("error") or ""))
        return out
    out = []
    for b in report.get("buildings", []):
        rep = b.get("repair") or {}
        en = b.get("energy") or {}
        th = b.get("thermal") or {}
        if not rep and not en:  # an unreadable feature: its code is all there is
            out.append(Row(id=str(b["id"]), type=b.get("type", "unknown"), stage="irreparable",
                           before=_codes(b.get("input_errors")), after=_codes(b.get("input_errors")) or (999,),
                           compliant=False, message=b.get("message", "")))
            continue
        out.append(Row(id=str(b["id"]), type=b.get("type", "Building"), stage=rep.get("stage") or "valid",
                       before=_codes(rep.get("defects_before", b.get("input_errors"))),
                       after=_codes(rep.get("defects_after", b.get("output_errors"))),
                       iou=_num(rep.get("iou")), displacement=_num(rep.get("mean_displacement")),
                       compliant=en.get("compliant"), conditions={k: en[k] for k in CONDITIONS if k in en},
                       typology=th.get("typology") or None, heating_kwh_m2=heating_per_m2(b),
                       exports={k: {"ok": bool(v.get("ok")), "problems": list(v.get("problems") or [])}
                                for k, v in (b.get("exports") or {}).items()},
                       message=b.get("message", "")))
    return out


# --- figure data (pure functions of the rows) ---------------------------------------------------

def stage_distribution(rs: list[Row]) -> dict:
    """Buildings per repair stage in ladder order (the method's Figure 10); empty for validate."""
    c = Counter(r.stage for r in rs if r.stage is not None)
    return {s: c[s] for s in STAGES if c[s]}


def fixed(rs: list[Row]) -> list[Row]:
    """Buildings repaired by a stage and measured (the rows mIoU and mAP_v average)."""
    return [r for r in rs if r.stage not in (None, "valid", "irreparable") and r.iou is not None]


def histogram(values, edges) -> dict:
    """``{"edges": [...], "counts": [...]}`` (values above the last edge go to the last bin)."""
    v = np.clip(np.asarray([x for x in values if x is not None], float), edges[0], edges[-1])
    counts, _ = np.histogram(v, bins=np.asarray(edges, float))
    return {"edges": list(edges), "counts": counts.astype(int).tolist(), "n": int(len(v))}


def iou_histogram(rs: list[Row]) -> dict:
    """IoU of every repaired building (the method's Figure 11, left)."""
    return histogram([r.iou for r in fixed(rs)], IOU_BINS)


def displacement_histogram(rs: list[Row]) -> dict:
    """Mean vertex displacement of every repaired building, m (Figure 11, right)."""
    return histogram([r.displacement for r in fixed(rs) if r.displacement is not None], DISPLACEMENT_BINS)


def validity_by_code(rs: list[Row]) -> dict:
    """Buildings with each val3dity code before / after: ``{code: [before, after]}``."""
    b = Counter(c for r in rs for c in set(r.before))
    a = Counter(c for r in rs for c in set(r.after or ()))
    return {str(c): [b[c], a[c]] for c in sorted(set(b) | set(a))}


def compliance(rs: list[Row]) -> dict:
    """Energy-compliant buildings before (no val3dity error but 601) and after the pipeline."""
    n = len(rs)
    before = sum(1 for r in rs if not r.invalid_input)
    after = sum(1 for r in rs if r.compliant)
    conds = {k: sum(1 for r in rs if r.conditions.get(k)) for k in CONDITIONS
             if any(k in r.conditions for r in rs)}
    return {"total": n, "before": before, "after": after, "conditions": conds}


def heating_by_typology(rs: list[Row]) -> dict:
    """Mean simulated heating need per m2 by typology: ``{typology: [mean kWh/m2, n]}``."""
    by: dict[str, list[float]] = {}
    for r in rs:
        if r.heating_kwh_m2 is not None:
            by.setdefault(r.typology or "unknown", []).append(r.heating_kwh_m2)
    return {k: [round(float(np.mean(v)), 3), len(v)] for k, v in sorted(by.items())}


def summary(rs: list[Row]) -> dict:
    """Dataset table (the method's Tables 4 to 6 for this file)."""
    fx = fixed(rs)
    repaired_kind = any(r.stage is not None for r in rs)
    out = {"buildings": len(rs),
           "valid_before": sum(1 for r in rs if not r.invalid_input),
           "valid_after": sum(1 for r in rs if not any(c != 601 for c in (r.after or ()))) if repaired_kind else None,
           "compliant_after": sum(1 for r in rs if r.compliant),
           "local_repairs": sum(1 for r in rs if r.stage in LOCAL),
           "global_repairs": sum(1 for r in rs if r.stage in GLOBAL),
           "irreparable": sum(1 for r in rs if r.status == "irreparable"),
           "miou": round(float(np.mean([r.iou for r in fx])), 6) if fx else None,
           "map_v": round(float(np.mean([r.displacement for r in fx if r.displacement is not None])), 6)
           if [r for r in fx if r.displacement is not None] else None,
           "n_measured": len(fx),
           "status": {s: sum(1 for r in rs if r.status == s) for s in STATUSES}}
    return out


def exports_table(rs: list[Row]) -> dict:
    """Per export format: buildings written and self-checked ok / failed."""
    out: dict[str, dict] = {}
    for r in rs:
        for fmt, e in r.exports.items():
            d = out.setdefault(fmt, {"ok": 0, "failed": 0, "problems": []})
            d["ok" if e.get("ok") else "failed"] += 1
            if not e.get("ok") and len(d["problems"]) < 5:
                d["problems"].extend(f"{r.id}: {p}" for p in e.get("problems", [])[:1])
    return out


def code_names(codes) -> dict:
    """val3dity name of each code."""
    return {str(c): code_name(int(c)) for c in codes}


def figure_data(rs: list[Row]) -> dict:
    """Every number the report plots or tabulates (embedded in the page as JSON)."""
    v = validity_by_code(rs)
    return {"summary": summary(rs), "stages": stage_distribution(rs), "iou": iou_histogram(rs),
            "displacement": displacement_histogram(rs), "validity_by_code": v, "code_names": code_names(v),
            "compliance": compliance(rs), "heating_by_typology": heating_by_typology(rs),
            "exports": exports_table(rs)}
