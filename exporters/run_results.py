"""Simulation results back in the city model: a run's per-building and per-zone figures as Energy-ADE-style attributes.

``export --run`` simulates each IDF; :func:`lod2energy.exporters.idf.demand_stats` puts the
figures in the writer's ``stats`` (``building_results``, ``zone_results``, ``zone_building``).
The flow to the CityJSON, which is written after every IDF (the dataset pass):

1. :func:`record_results` keeps one building's figures in its IDF export record (and so in
   ``report.json``, under ``exports.idf.results``);
2. :func:`with_run_results` hands them to the building the CityJSON writer receives
   (``provenance["run_results"]``);
3. :func:`result_attributes` makes the ``+energy...`` attributes of the first-level Building,
   declared in the shipped Extension (``energy.ext.json``).

Units: demand kWh per year, demand per conditioned floor area kWh/(m2 a), peak loads W,
floor area m2. A figure EnergyPlus did not give (no hourly rates, no floor area) is null.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Iterable

if TYPE_CHECKING:
    from lod2energy.model import Building

#: Result key -> attribute name (per building; a zone's entry drops the ``+energy`` prefix
#: and starts lower case).
ATTRIBUTES = {
    "heating_kwh": "+energyHeatingDemand",
    "cooling_kwh": "+energyCoolingDemand",
    "heating_kwh_m2": "+energyHeatingDemandPerFloorArea",
    "cooling_kwh_m2": "+energyCoolingDemandPerFloorArea",
    "heating_peak_w": "+energyHeatingPeakLoad",
    "cooling_peak_w": "+energyCoolingPeakLoad",
    "floor_area_m2": "+energyConditionedFloorArea",
}
ZONES_ATTRIBUTE = "+energyThermalZones"


def _zone_key(attribute: str) -> str:
    name = attribute[len("+energy"):]
    return name[0].lower() + name[1:]


def record_results(stats: Mapping[str, Any], building_id: str) -> dict | None:
    """One building's run figures from an IDF writer's ``stats``.

    Returns
    -------
    dict or None
        ``{"building": {heating_kwh, ...}, "zones": {zone name: {heating_kwh, ...}}}`` (the
        keys of :data:`ATTRIBUTES`); None when the run gave no figures for this building.
    """
    b = (stats.get("building_results") or {}).get(building_id)
    if b is None:
        return None
    owner = stats.get("zone_building") or {}
    zones = {z: dict(d) for z, d in (stats.get("zone_results") or {}).items() if owner.get(z) == building_id}
    return {"building": dict(b), "zones": zones}


def with_run_results(b: Building, idf_record: Any) -> Building:
    """``b`` carrying the run figures of its IDF export record (unchanged without any)."""
    results = (getattr(idf_record, "extra", None) or {}).get("results") if idf_record is not None else None
    if not isinstance(results, Mapping) or not isinstance(results.get("building"), Mapping):
        return b
    return b.with_provenance(run_results={"building": dict(results["building"]),
                                          "zones": {str(z): dict(d) for z, d in (results.get("zones") or {}).items()}})


def _figures(d: Mapping[str, Any], names: Iterable[tuple[str, str]]) -> dict[str, Any]:
    out = {}
    for key, name in names:
        v = d.get(key)
        out[name] = None if v is None else float(v)
    return out


def result_attributes(b: Building) -> dict[str, Any]:
    """The ``+energy...`` result attributes of ``b`` (empty when it was not simulated)."""
    r = b.provenance.get("run_results")
    if not isinstance(r, Mapping) or not isinstance(r.get("building"), Mapping):
        return {}
    attrs = _figures(r["building"], ATTRIBUTES.items())
    zone_names = [(k, _zone_key(a)) for k, a in ATTRIBUTES.items()]
    attrs[ZONES_ATTRIBUTE] = {str(z): _figures(d, zone_names) for z, d in sorted((r.get("zones") or {}).items())}
    return attrs


