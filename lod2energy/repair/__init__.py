"""Repair ladder: turn defective building geometry into closed, outward, clean Solids.

One module per stage (cleanup, orientation, holefill, refill, alphashape, footprint, hull),
the ladder in :mod:`~lod2energy.repair.pipeline`, fidelity in :mod:`~lod2energy.repair.metrics`;
the energy model the IDF writer writes (floorless parts, simpler zone envelopes) in
:mod:`~lod2energy.exporters.energyplus.model`.
"""
from lod2energy.repair.pipeline import (  # noqa: F401
    DEFAULT_TIMEOUT, STAGES, dataset_table, repair_attributes, repair_building, repair_features, repair_info,
)

__all__ = ["DEFAULT_TIMEOUT", "STAGES", "dataset_table", "repair_building", "repair_features", "repair_info",
           "repair_attributes"]
