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
from typing import Iterable, Iterator

import numpy as np

from lod2energy.site import MAX_WEATHER_KM
from lod2energy.viz.warnings import warning_kinds
from lod2energy.validate.codes import name as code_name, val3dity_valid
from lod2energy.energy.downgrades import KINDS as DOWNGRADE_KINDS

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
    downgrades : tuple of str
        Kinds of the energy model's downgrades (:data:`lod2energy.energy.downgrades.KINDS`).
    warnings : tuple of str
        Kinds of its warnings (:func:`lod2energy.viz.warnings.warning_kinds`).
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
    downgrades: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

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
        """A val3dity error other than 601 in the input: ``validate``'s verdict (the project's
        energy codes, 1001+, are no val3dity error)."""
        return not val3dity_valid(self.before)


def _input_codes(b: dict, rep: dict) -> tuple[int, ...]:
    """The input's codes of an export row: the validator's (``input_errors``, the verdict of
    ``lod2energy validate``) and the repair's energy codes (1001+)."""
    if "input_errors" not in b:
        return _codes(rep.get("defects_before"))
    return tuple(sorted(set(_codes(b["input_errors"])) | {c for c in _codes(rep.get("defects_before")) if c >= 1000}))


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
    """Annual heating need of an export row per m2 of floor (footprint x storeys), kWh/m2; None
    for an unconditioned building."""
    idf = (b.get("exports") or {}).get("idf") or {}
    h = _num(idf.get("heating_kwh", b.get("heating_kwh")))
    if h is None:
        return None
    th = b.get("thermal") or {}
    if ((th.get("facts") or {}).get("conditioned") or {}).get("value") is False:
        return None  # unconditioned: out of the per-m2 figures
    fp = _num(th.get("footprint")) or _num((th.get("areas") or {}).get("ground"))
    floors = _num(th.get("storeys")) or 1.0
    return h / (fp * floors) if fp else None


def rows(report: dict) -> list[Row]:
    """Normalised rows of a report of any of the three shapes (buildings only)."""
    return list(iter_rows(report))


def iter_rows(report: dict) -> Iterator[Row]:
    """:func:`rows` one at a time (``report["buildings"]`` may itself be read lazily)."""
    kind = report_kind(report)
    if kind == "validate":
        reps = report.get("reports") if report.get("type") == "lod2energy_reports" else [report]
        for rep in reps:
            for f in rep.get("features", []):
                if f.get("type") not in ("Building", None) and "energy" not in f:
                    continue
                en = f.get("energy") or {}
                yield Row(id=str(f["id"]), type=f.get("type", "Building"),
                          before=_codes(e["code"] for e in f.get("errors", [])),
                          compliant=en.get("compliant"),
                          conditions={k: en[k] for k in CONDITIONS if k in en},
                          errors=tuple(f.get("errors", [])))
        return
    if kind == "repair":
        for b in report.get("buildings", []):
            yield Row(id=str(b["id"]), stage=b.get("stage") or "valid",
                      before=_codes(b.get("defects_before")), after=_codes(b.get("defects_after")),
                      iou=_num(b.get("iou")), displacement=_num(b.get("mean_displacement")),
                      compliant=not [c for c in _codes(b.get("defects_after")) if c != 601],
                      message=b.get("error") or "")
        return
    for b in report.get("buildings", []):
        rep = b.get("repair") or {}
        en = b.get("energy") or {}
        th = b.get("thermal") or {}
        if not rep and not en:  # an unreadable feature: its code is all there is
            yield Row(id=str(b["id"]), type=b.get("type", "unknown"), stage="irreparable",
                      before=_codes(b.get("input_errors")), after=_codes(b.get("input_errors")) or (999,),
                      compliant=False, message=b.get("message", ""))
            continue
        yield Row(id=str(b["id"]), type=b.get("type", "Building"), stage=rep.get("stage") or "valid",
                  before=_input_codes(b, rep),
                  after=_codes(rep.get("defects_after", b.get("output_errors"))),
                  iou=_num(rep.get("iou")), displacement=_num(rep.get("mean_displacement")),
                  compliant=en.get("compliant"), conditions={k: en[k] for k in CONDITIONS if k in en},
                  typology=th.get("typology") or None, heating_kwh_m2=heating_per_m2(b),
                  exports={k: {"ok": bool(v.get("ok")), "problems": list(v.get("problems") or []),
                               **({"weather": v["weather"]} if v.get("weather") else {})}
                           for k, v in (b.get("exports") or {}).items()},
                  message=b.get("message", ""),
                  downgrades=tuple(str(d.get("kind")) for d in b.get("energy_downgrades") or ()),
                  warnings=warning_kinds(b))


# --- figure data (pure functions of the rows) ---------------------------------------------------

def _measured(r: Row) -> bool:
    return r.stage not in (None, "valid", "irreparable") and r.iou is not None


class _Histogram:
    """``{"edges", "counts", "n"}`` of values given one at a time (memory: one chunk of values);
    values outside the edges count in the first / last bin."""

    CHUNK = 4096

    def __init__(self, edges):
        self.edges = tuple(edges)
        self.counts = np.zeros(len(self.edges) - 1, dtype=np.int64)
        self.n = 0
        self._buf: list[float] = []

    def add(self, x) -> None:
        if x is not None:
            self._buf.append(x)
            if len(self._buf) >= self.CHUNK:
                self._flush()

    def _flush(self) -> None:
        if self._buf:
            v = np.clip(np.asarray(self._buf, float), self.edges[0], self.edges[-1])
            self.counts += np.histogram(v, bins=np.asarray(self.edges, float))[0]
            self.n += len(v)
            self._buf = []

    def result(self) -> dict:
        self._flush()
        return {"edges": list(self.edges), "counts": self.counts.astype(int).tolist(), "n": int(self.n)}


class Tally:
    """Every number of the report's figures (:meth:`figure_data`), gathered one row at a time: a report of any size in
    memory that does not grow with its buildings (counters, sums and histogram bins only).

    Parameters
    ----------
    rs : iterable of Row, optional
        Rows to add now (more with :meth:`add`).
    """

    def __init__(self, rs: Iterable[Row] = ()):
        self.n = 0
        self.stages: Counter = Counter()
        self.iou = _Histogram(IOU_BINS)
        self.displacement = _Histogram(DISPLACEMENT_BINS)
        self.before: Counter = Counter()
        self.after: Counter = Counter()
        self.valid_before = self.valid_after = self.compliant = 0
        self.conditions: Counter = Counter()
        self.conditions_seen: set[str] = set()
        self.heating: dict[str, list[float]] = {}  # typology -> [sum of kWh/m2, n]
        self.local = self.global_ = 0
        self.status: Counter = Counter()
        self.repaired_kind = False
        self.iou_sum = 0.0
        self.n_measured = 0
        self.displacement_sum = 0.0
        self.n_displacement = 0
        self.exports: dict[str, dict] = {}
        self.downgraded = 0
        self.downgrades: Counter = Counter()  # kind -> buildings
        self.weather: dict[str, list] = {}  # station -> [buildings, farthest km]
        for r in rs:
            self.add(r)

    def add(self, r: Row) -> None:
        """Count one building."""
        self.n += 1
        if r.stage is not None:
            self.stages[r.stage] += 1
            self.repaired_kind = True
        if _measured(r):
            self.iou.add(r.iou)
            self.iou_sum += r.iou
            self.n_measured += 1
            if r.displacement is not None:
                self.displacement.add(r.displacement)
                self.displacement_sum += r.displacement
                self.n_displacement += 1
        self.before.update(set(r.before))
        self.after.update(set(r.after or ()))
        self.valid_before += not r.invalid_input
        self.valid_after += val3dity_valid(r.after or ())
        self.compliant += bool(r.compliant)
        for k in CONDITIONS:
            if k in r.conditions:
                self.conditions_seen.add(k)
                self.conditions[k] += bool(r.conditions[k])
        if r.heating_kwh_m2 is not None:
            h = self.heating.setdefault(r.typology or "unknown", [0.0, 0])
            h[0] += r.heating_kwh_m2
            h[1] += 1
        self.local += r.stage in LOCAL
        self.global_ += r.stage in GLOBAL
        self.status[r.status] += 1
        self.downgraded += bool(r.downgrades)
        self.downgrades.update(set(r.downgrades))
        for fmt, e in r.exports.items():
            w = e.get("weather")
            if w and w.get("distance_km") is not None:
                st = self.weather.setdefault(f"{w.get('station')} ({w.get('file')})", [0, 0.0])
                st[0] += 1
                st[1] = max(st[1], float(w["distance_km"]))
            d = self.exports.setdefault(fmt, {"ok": 0, "failed": 0, "problems": []})
            d["ok" if e.get("ok") else "failed"] += 1
            if not e.get("ok") and len(d["problems"]) < 5:
                d["problems"].extend(f"{r.id}: {p}" for p in e.get("problems", [])[:1])

    def stage_distribution(self) -> dict:
        return {s: self.stages[s] for s in STAGES if self.stages[s]}

    def validity_by_code(self) -> dict:
        b, a = self.before, self.after
        return {str(c): [b[c], a[c]] for c in sorted(set(b) | set(a))}

    def compliance(self) -> dict:
        return {"total": self.n, "before": self.valid_before, "after": self.compliant,
                "conditions": {k: self.conditions[k] for k in CONDITIONS if k in self.conditions_seen}}

    def heating_by_typology(self) -> dict:
        return {k: [round(v[0] / v[1], 3), v[1]] for k, v in sorted(self.heating.items())}

    def summary(self) -> dict:
        return {"buildings": self.n, "valid_before": self.valid_before,
                "valid_after": self.valid_after if self.repaired_kind else None,
                "compliant_after": self.compliant, "local_repairs": self.local, "global_repairs": self.global_,
                "irreparable": self.status["irreparable"],
                "miou": round(self.iou_sum / self.n_measured, 6) if self.n_measured else None,
                "map_v": round(self.displacement_sum / self.n_displacement, 6) if self.n_displacement else None,
                "n_measured": self.n_measured,
                "status": {s: self.status[s] for s in STATUSES},
                "energy_downgraded": self.downgraded,
                "energy_downgrades": {k: self.downgrades[k] for k in DOWNGRADE_KINDS if self.downgrades[k]}}

    def weather_table(self) -> dict:
        """Weather station -> ``[buildings, farthest distance (km), farther than 50 km]``."""
        return {k: [v[0], round(v[1], 1), v[1] > MAX_WEATHER_KM] for k, v in sorted(self.weather.items())}

    def exports_table(self) -> dict:
        return {k: dict(d, problems=list(d["problems"])) for k, d in self.exports.items()}

    def figure_data(self) -> dict:
        """Every number the report plots or tabulates (embedded in the page as JSON)."""
        v = self.validity_by_code()
        return {"summary": self.summary(), "stages": self.stage_distribution(), "iou": self.iou.result(),
                "displacement": self.displacement.result(), "validity_by_code": v, "code_names": code_names(v),
                "compliance": self.compliance(), "heating_by_typology": self.heating_by_typology(),
                "exports": self.exports_table(),
                **({"weather": self.weather_table()} if self.weather else {})}


def code_names(codes) -> dict:
    """val3dity name of each code."""
    return {str(c): code_name(int(c)) for c in codes}
