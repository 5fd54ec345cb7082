"""Typed records of what happened to one building, stage by stage (one row of the dataset report).

Every record is a frozen dataclass that travels between processes (picklable) and to the
JSON Lines journal and back (:meth:`to_json` / :meth:`from_json`), so that ``report.json``
and ``report.csv`` can be assembled from the journal alone. Nothing here carries a timing:
the same input gives the same records, byte for byte, on any executor.

Importing this module also makes :class:`lod2energy.model.Building` picklable (its
read-only mappings are ``types.MappingProxyType``, which :mod:`pickle` cannot take by itself).
"""
from __future__ import annotations

import copyreg
import hashlib
import os
import types
from collections.abc import Mapping as _Mapping
from dataclasses import dataclass, field, replace
from typing import Any, Mapping

from lod2energy.energy.downgrades import Downgrade, summed
from lod2energy.energy.figures import with_model_figures
from lod2energy.safe_write import json_default


# ----------------------------------------------------------------------------- pickling

def _mapping(d: dict) -> Mapping:
    """Rebuild a read-only mapping (the pickle constructor of ``MappingProxyType``)."""
    return types.MappingProxyType(d)


def _reduce_mapping(m: types.MappingProxyType):
    return _mapping, (dict(m),)


copyreg.pickle(types.MappingProxyType, _reduce_mapping)


#: Keys never written to a report: they hold timings, so they would make two runs differ.
TIMING_KEYS = frozenset({"seconds", "elapsed", "time_s"})


def _untimed(obj: Any) -> Any:
    """``obj`` (JSON-ready) without timing keys, recursively; tuples become lists."""
    t = type(obj)
    if t in _LEAF:  # the common leaves, decided by their exact type (no ABC check)
        return obj
    if t is dict or t is types.MappingProxyType or isinstance(obj, _Mapping):
        return {str(k): _untimed(v) for k, v in obj.items() if k not in TIMING_KEYS}
    if t is list or t is tuple or isinstance(obj, (list, tuple)):
        return [_untimed(v) for v in obj]
    if type(obj).__module__ == "numpy":
        return json_default(obj)
    return obj


#: Exact types :func:`_untimed` returns as they are (no Mapping, list, tuple or numpy type).
_LEAF = frozenset({str, int, float, bool, type(None)})


# ----------------------------------------------------------------------------- stage records

class _Detail:
    """Read access to a record's report block by key (``rec.energy["lod"]``)."""

    def __getitem__(self, key):
        return self.detail[key]

    def get(self, key, default=None):
        return self.detail.get(key, default)

    def __contains__(self, key):
        return key in self.detail


@dataclass(frozen=True)
class RepairRecord(_Detail):
    """Result of the repair ladder for one building.

    Parameters
    ----------
    stage : str
        Highest ladder stage used ("valid", "cleanup", ... "hull", "irreparable"); "" when
        the repair did not run.
    iou : float or None
        Volume IoU of the result with the input.
    mean_displacement : float or None, m
        Mean vertex-to-surface distance input -> result (mAP_v).
    error : str or None
        Why the building could not be repaired at all (e.g. implausible coordinates).
    detail : dict
        The ladder's whole summary (JSON-ready, timings removed, without the per-geometry list).
    """

    stage: str = ""
    iou: float | None = None
    mean_displacement: float | None = None
    error: str | None = None
    detail: Mapping = field(default_factory=dict)

    @classmethod
    def from_info(cls, info: Mapping) -> "RepairRecord":
        d = _untimed({k: v for k, v in dict(info).items() if k != "geometries"})
        return cls(str(d.get("stage") or ""), d.get("iou"), d.get("mean_displacement"), d.get("error"), d)

    def to_json(self) -> dict:
        return dict(self.detail)


@dataclass(frozen=True)
class ComplianceRecord(_Detail):
    """The final check: energy compliance and whether the building may be exported.

    Parameters
    ----------
    compliant : bool or None
        All five compliance conditions hold and the writers' acceptance check passed.
    geometry_ready : bool
        The geometry may go to the writers (closed, outward, no degenerate face, final check).
    status : str
        watertight / open / non-manifold ("" without faces).
    reasons : tuple of str
        Why not compliant / not ready.
    detail : dict
        The whole compliance block of the report.
    """

    compliant: bool | None = None
    geometry_ready: bool = False
    status: str = ""
    reasons: tuple[str, ...] = ()
    detail: Mapping = field(default_factory=dict)

    @classmethod
    def from_block(cls, block: Mapping) -> "ComplianceRecord":
        d = _untimed(dict(block))
        return cls(d.get("compliant"), bool(d.get("geometry_ready")), str(d.get("status") or ""),
                   tuple(d.get("reasons") or ()), d)

    def rejected(self, reason: str) -> "ComplianceRecord":
        """This record with the building rejected by the final check for ``reason``."""
        d = dict(self.detail)
        reasons = [reason] + [r for r in self.reasons if r != reason]
        d.update(compliant=False, geometry_ready=False, reasons=reasons)
        return ComplianceRecord(False, False, self.status, tuple(reasons), d)

    def unwritten(self, reason: str) -> "ComplianceRecord":
        """This record with the building not compliant because a requested writer did not write
        it or its file failed the writer's self-check (``reason`` says which); the geometry
        stays ready for the other writers."""
        d = dict(self.detail)
        reasons = [reason] + [r for r in self.reasons if r != reason]
        d.update(compliant=False, reasons=reasons)
        return ComplianceRecord(False, self.geometry_ready, self.status, tuple(reasons), d)

    def to_json(self) -> dict:
        return dict(self.detail)


@dataclass(frozen=True)
class ThermalRecord(_Detail):
    """Typology, areas (m2), volume (m3) and UA (W/K) of one building (empty when not assessed)."""

    typology: str = ""
    construction_period: str = ""
    areas: Mapping = field(default_factory=dict)
    A_env: float | None = None
    volume: float | None = None
    UA: float | None = None
    detail: Mapping = field(default_factory=dict)

    @classmethod
    def from_block(cls, block: Mapping | None) -> "ThermalRecord":
        d = _untimed(dict(block or {}))
        return cls(str(d.get("typology") or ""), str(d.get("construction_period") or ""),
                   dict(d.get("areas") or {}), d.get("A_env"), d.get("volume"), d.get("UA"), d)

    def to_json(self) -> dict:
        return dict(self.detail)


@dataclass(frozen=True)
class FileRecord:
    """One written file: path as the writer gave it, size (bytes) and SHA-256 of its content."""

    path: str
    size: int
    sha256: str

    @classmethod
    def of(cls, path: str) -> "FileRecord | None":
        try:
            h = hashlib.sha256()
            with open(path, "rb") as f:
                for chunk in iter(lambda: f.read(1 << 20), b""):
                    h.update(chunk)
            return cls(str(path), os.path.getsize(path), h.hexdigest())
        except OSError:
            return None

    def intact(self) -> bool:
        """The file is still there with the same size and content."""
        try:
            if os.path.getsize(self.path) != self.size:
                return False
        except OSError:
            return False
        now = FileRecord.of(self.path)
        return now is not None and now.sha256 == self.sha256


#: Figures of an IDF record derived from its ``results`` (a run's per-building figures and
#: per-zone list, :func:`lod2energy.exporters.run_results.record_results`) for report.json,
#: report.csv and the footprints: stored once, as ``results``.
RESULT_FIGURES = ("heating_kwh_m2", "cooling_kwh_m2", "heating_peak_w", "cooling_peak_w",
                  "conditioned_floor_area_m2", "zones")


def run_figures(results: Mapping) -> dict:
    """The report's figures of a run's ``results`` (``{"building": {...}, "zones": {...}}``):
    the building's demand per m2 and peaks, its conditioned floor area (m2) and ``zones``, one
    entry per conditioned zone."""
    b = results.get("building") or {}
    fig = {k: b.get(k) for k in RESULT_FIGURES[:4]}
    fig["conditioned_floor_area_m2"] = b.get("floor_area_m2")
    fig["zones"] = [{"zone": z, **dict(zd)} for z, zd in (results.get("zones") or {}).items()]
    return fig


#: How the first problem of a writer's by-design refusal of a building begins: left out of the
#: file, or carried in it but not accepted as an energy model (issue 19). A decision of the final
#: check, reported as a note - not a written file that failed its self-check.
LEFT_OUT = "left out: "
NOT_COMPLIANT = "in the file, not energy-compliant: "


@dataclass(frozen=True)
class ExportRecord:
    """What one writer did for one building.

    Parameters
    ----------
    format : str
        Writer name ("idf", "stl", "cityjson").
    ok : bool
        Written and self-checked.
    path : str
        The file ("" when none was written).
    problems : tuple of str
    extra : dict
        Writer-specific values kept in the report (offset, heating_kwh, cooling_kwh,
        severe_errors, not_enclosed, warnings).
    files : tuple of FileRecord
        The files the writer produced for this building (for ``--resume``); journal only.
    """

    format: str
    ok: bool
    path: str = ""
    problems: tuple[str, ...] = ()
    extra: Mapping = field(default_factory=dict)
    files: tuple[FileRecord, ...] = ()

    def values(self) -> dict:
        """``extra`` as the report has it: with the run figures its ``results`` give
        (:func:`run_figures`), just before ``results``."""
        results = self.extra.get("results")
        if not isinstance(results, Mapping):
            return dict(self.extra)
        out = {}
        for k, v in self.extra.items():
            if k == "results":
                out.update(run_figures(results))
            out[k] = v
        return out

    @property
    def refused(self) -> bool:
        """Not ok by the writer's design (:data:`LEFT_OUT`, :data:`NOT_COMPLIANT`), not by a failure."""
        return not self.ok and bool(self.problems) and self.problems[0].startswith((LEFT_OUT, NOT_COMPLIANT))

    @property
    def failed_check(self) -> bool:
        """Not ok because the file it wrote failed its self-check (not: no file, or refused)."""
        head = f"{self.format.upper()} NOT WRITTEN"
        return not self.ok and bool(self.path) and not (self.problems and self.problems[0].upper().startswith(head))

    def message(self, bid: str) -> str:
        """The user's line for an export of building ``bid`` that is not ok: a written file that
        failed its self-check, or an export that wrote no file (and why)."""
        fmt = self.format.upper()
        head = f"{fmt} NOT WRITTEN"
        if self.failed_check:
            return f"{fmt} export {self.path} failed its self-check: {'; '.join(self.problems[:3])}"
        why = [q[len(head) + 2:] if q.upper().startswith(head + ": ") else q for q in self.problems[:3]]
        return f"{fmt} export {bid} not written: {'; '.join(why) or 'no file'}"

    def to_json(self) -> dict:
        """The report's block (the energy model's downgrades and envelope figures are the
        building record's own fields)."""
        d = {"ok": self.ok, "path": self.path, "problems": list(self.problems)}
        d.update(_untimed({k: v for k, v in self.values().items() if k not in ("downgrades", "envelope")}))
        return d

    def journal(self) -> dict:
        down = {k: _untimed(self.extra[k]) for k in ("downgrades", "envelope") if k in self.extra}
        return {"format": self.format, **self.to_json(), **down, "files": [vars(f) for f in self.files]}

    @classmethod
    def from_journal(cls, d: Mapping) -> "ExportRecord":
        extra = {k: v for k, v in d.items() if k not in ("format", "ok", "path", "problems", "files")}
        if isinstance(extra.get("results"), Mapping):  # figures the results give: stored once
            extra = {k: v for k, v in extra.items() if k not in RESULT_FIGURES}
        return cls(str(d["format"]), bool(d["ok"]), str(d.get("path") or ""), tuple(d.get("problems") or ()),
                   extra, tuple(FileRecord(**f) for f in d.get("files") or ()))

    def intact(self) -> bool:
        """Written, self-checked and every file still as the journal recorded it."""
        return self.ok and bool(self.files) and all(f.intact() for f in self.files)


# ----------------------------------------------------------------------------- the building record

#: Columns of report.csv, in order (the report's flat row; extended, never reduced).
#: Study inputs with their source (:mod:`lod2energy.thermal.facts`), a value and a ``_source`` column each.
FACTS = ("year", "storeys", "use", "conditioned")
FACT_COLUMNS = tuple(c for f in FACTS for c in (f, f"{f}_source"))
CSV_FIELDS = ["id", "type", "input_errors", "output_errors", "repair_stage", "iou", "mean_displacement_m",
              "compliant", "status", "typology", "construction_period", *FACT_COLUMNS, "roof_m2", "wall_m2", "ground_m2",
              "floor_exposed_m2", "window_m2", "adiabatic_m2", "A_env_m2", "volume_m3", "UA_W_per_K", "cityjson_ok", "idf_ok", "stl_ok", "cfd_ok", "heating_kwh",
              "cooling_kwh", "heating_kwh_m2", "cooling_kwh_m2", "heating_peak_w", "cooling_peak_w",
              "conditioned_floor_area_m2", "geojson_ok", "downgrades", "downgrade_d_height_m",
              "downgrade_d_volume_m3", "downgrade_d_floor_area_m2", "message", "outcome"]
#: Per-building figures of an EnergyPlus run (the IDF export's), in report.csv and report.json.
RUN_FIELDS = ("heating_kwh", "cooling_kwh", "heating_kwh_m2", "cooling_kwh_m2", "heating_peak_w", "cooling_peak_w",
              "conditioned_floor_area_m2")


@dataclass(frozen=True)
class BuildingRecord:
    """Everything the report says about one input object.

    Parameters
    ----------
    seq : int
        Position of the object in the input (0-based); orders the report.
    id, type : str
    outcome : {"done", "timeout", "failed", "unreadable"}
    input_errors, output_errors : tuple of int
        val3dity / project codes before and after the repair.
    repair, energy, thermal : RepairRecord, ComplianceRecord, ThermalRecord
    exports : tuple of ExportRecord
        In writer order; at most one per format.
    message : str
        One line for the user ("" when all went well).
    bbox : tuple of 6 float or None, m
        ``(xmin, ymin, zmin, xmax, ymax, zmax)`` of the prepared building (spatial index of
        the neighbour pass).
    downgrades : tuple of Downgrade
        Where its energy model (the IDF) is simpler than its repaired shell, and what that
        cost (:mod:`lod2energy.energy.downgrades`); set from the IDF export's record.
    """

    seq: int
    id: str
    type: str
    outcome: str = "done"
    input_errors: tuple[int, ...] = ()
    output_errors: tuple[int, ...] = ()
    repair: RepairRecord = RepairRecord()
    energy: ComplianceRecord = ComplianceRecord()
    thermal: ThermalRecord = ThermalRecord()
    exports: tuple[ExportRecord, ...] = ()
    message: str = ""
    bbox: tuple[float, ...] | None = None
    downgrades: tuple[Downgrade, ...] = ()

    # -- building a record up
    def with_export(self, er: ExportRecord) -> "BuildingRecord":
        """This record with ``er`` replacing any earlier result of the same writer.

        The energy model's downgrades the record of a writer carries (``extra["downgrades"]``,
        building id -> list, for every building of its file) become this building's
        :attr:`downgrades` (the export record keeps this building's only, for the journal).

        Compliant means written: a compliant building whose writer ``er`` did not write it, or
        whose file failed that writer's self-check, is not compliant any more; its compliance
        reasons and its message say which writer and check.
        """
        if isinstance(er.extra.get("downgrades"), Mapping):
            own = list(er.extra["downgrades"].get(self.id) or ())
            extra = {k: v for k, v in er.extra.items() if k != "downgrades"}
            er = replace(er, extra={**extra, "downgrades": {self.id: own}} if own else extra)
            self = replace(self, downgrades=tuple(Downgrade.from_json(d) for d in own))
        if isinstance(er.extra.get("envelope"), Mapping):  # the written model's figures: this building's
            own = er.extra["envelope"].get(self.id)
            extra = {k: v for k, v in er.extra.items() if k != "envelope"}
            er = replace(er, extra={**extra, "envelope": {self.id: own}} if own else extra)
            if own and self.thermal.detail:
                self = replace(self, thermal=ThermalRecord.from_block(with_model_figures(self.thermal.detail, own)))
        ex = tuple(e for e in self.exports if e.format != er.format) + (er,)
        rec = replace(self, exports=ex)
        if er.ok or not self.energy.compliant:
            return rec
        why = f"{er.format.upper()} export {self.id}: {er.problems[0]}" if er.refused else er.message(self.id)
        return replace(rec, energy=self.energy.unwritten(why)).with_message(f"not compliant: {why}")

    def with_message(self, text: str) -> "BuildingRecord":
        return replace(self, message=(self.message + " " + text).strip() if text else self.message)

    def export(self, fmt: str) -> ExportRecord | None:
        return next((e for e in self.exports if e.format == fmt), None)

    @property
    def assessed(self) -> bool:
        """The building went through the compliance stage (it is a building of the report)."""
        return bool(self.energy.detail)

    # -- the report
    def row(self) -> dict:
        """The flat row of report.csv (and the first keys of the report.json entry)."""
        th = self.thermal
        areas = th.areas or {}
        r = {"id": self.id, "type": self.type,
             "input_errors": " ".join(map(str, sorted(set(self.input_errors)))),
             "output_errors": " ".join(map(str, sorted(set(self.output_errors)))),
             "repair_stage": self.repair.detail.get("stage", ""),
             "iou": self.repair.detail.get("iou", ""),
             "mean_displacement_m": self.repair.detail.get("mean_displacement", ""),
             "compliant": self.energy.detail.get("compliant", ""), "status": self.energy.detail.get("status", ""),
             "typology": th.detail.get("typology", ""), "construction_period": th.detail.get("construction_period", ""),
             **self.fact_columns(),
             "roof_m2": areas.get("roof", ""), "wall_m2": areas.get("wall", ""), "ground_m2": areas.get("ground", ""),
             **{f"{k}_m2": areas.get(k, "") for k in ("floor_exposed", "window", "adiabatic")},
             "A_env_m2": th.detail.get("A_env", ""), "volume_m3": th.detail.get("volume", ""),
             "UA_W_per_K": th.detail.get("UA", "")}
        for e in sorted(self.exports, key=lambda e: e.format):
            r[f"{e.format}_ok"] = e.ok
            values = e.values()
            for k in RUN_FIELDS:
                if k in values:
                    r[k] = values[k]
        r["message"] = self.message
        r["outcome"] = self.outcome
        dh, dv, da = summed(self.downgrades)
        r["downgrades"] = " ".join(f"{d.kind}:{d.zone}" for d in self.downgrades)
        r["downgrade_d_height_m"] = dh if self.downgrades else ""
        r["downgrade_d_volume_m3"] = dv if self.downgrades else ""
        r["downgrade_d_floor_area_m2"] = da if self.downgrades else ""
        return r

    def fact_columns(self) -> dict:
        """``{year, year_source, storeys, ...}`` of :data:`FACTS` ("" when not assessed)."""
        facts = self.thermal.detail.get("facts") or {}
        out = {}
        for f in FACTS:
            v = facts.get(f) or {}
            out[f] = "" if v.get("value") is None else v["value"]
            out[f"{f}_source"] = v.get("source", "")
        return out

    def report_entry(self) -> dict:
        """The building's entry of report.json."""
        exports = {e.format: e.to_json() for e in sorted(self.exports, key=lambda e: e.format)}
        zones = exports.get("idf", {}).pop("zones", None)  # per zone figures of a run: the building's own key
        return {**self.row(), **({"zones": zones} if zones is not None else {}), "repair": self.repair.to_json(),
                "energy": self.energy.to_json(), "thermal": self.thermal.to_json(), "exports": exports,
                "energy_downgrades": [d.to_json() for d in self.downgrades]}

    # -- the journal
    def to_json(self) -> dict:
        """Everything, for one line of the journal (:meth:`from_json` inverts it)."""
        return {"seq": self.seq, "id": self.id, "type": self.type, "outcome": self.outcome,
                "input_errors": list(self.input_errors), "output_errors": list(self.output_errors),
                "repair": self.repair.to_json(), "energy": self.energy.to_json(),
                "thermal": self.thermal.to_json(), "exports": [e.journal() for e in self.exports],
                "message": self.message, "bbox": list(self.bbox) if self.bbox is not None else None,
                "downgrades": [d.to_json() for d in self.downgrades]}

    @classmethod
    def from_json(cls, d: Mapping) -> "BuildingRecord":
        return cls(int(d["seq"]), str(d["id"]), str(d["type"]), str(d.get("outcome") or "done"),
                   tuple(d.get("input_errors") or ()), tuple(d.get("output_errors") or ()),
                   RepairRecord.from_info(d.get("repair") or {}) if d.get("repair") else RepairRecord(),
                   ComplianceRecord.from_block(d.get("energy") or {}) if d.get("energy") else ComplianceRecord(),
                   ThermalRecord.from_block(d.get("thermal")),
                   tuple(ExportRecord.from_journal(e) for e in d.get("exports") or ()),
                   str(d.get("message") or ""), tuple(d["bbox"]) if d.get("bbox") is not None else None,
                   tuple(Downgrade.from_json(x) for x in d.get("downgrades") or ()))
