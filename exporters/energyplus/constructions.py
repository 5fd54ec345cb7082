"""Constructions: single no-mass layers (with an optional inside mass layer) giving the input U-value.

The layer resistance is R = 1/U - Rsi - Rse (EnergyPlus's own film resistances, so that
EnergyPlus reports the input U-value "with film").
"""
from __future__ import annotations


#: EnergyPlus inside film resistances (m2 K/W) by surface class, and the outside film for
#: outdoor surfaces (DataHeatBalance::ComputeNominalUwithConvCoeffs).
R_SI = {"Wall": 0.1197548, "Floor": 0.1620212, "Roof": 0.1074271}


R_SE = {"Outdoors": 0.0299387, "Ground": 0.0, "Adiabatic": 0.0299387}


R_MIN = 0.001


#: Interzone floor/ceiling between storeys: one symmetric concrete slab layer (so that the
#: construction is its own reverse, as EnergyPlus wants for the two sides of a pair).
INTERZONE_SLAB = {"name": "Interzone_Slab", "thickness": 0.2, "conductivity": 2.0, "density": 2400.0,
                  "specific_heat": 1000.0}


_KIND_TYPE = {"roof": "Roof", "wall": "Wall", "ground": "Floor", "floor": "Floor", "ceiling": "Ceiling"}


#: Inside mass layer (brick/concrete-like): conductivity W/(m K), density kg/m3, specific heat J/(kg K).
MASS = {"conductivity": 1.1, "density": 2000.0, "specific_heat": 1000.0}


MASS_THICKNESS = 0.1


def construction_layers(kind: str, boundary: str, u: float, mass: bool = True) -> tuple[float, float, str]:
    """Layer build-up giving ``u`` (W/(m2 K)) "with films" in EnergyPlus.

    Returns
    -------
    r_nomass : float, m2 K/W
        Resistance of the outside no-mass layer (at least 0.001).
    mass_thickness : float, m
        Thickness of the inside mass layer (0 for none); its resistance is at most half of
        1/U - Rsi - Rse.
    note : str
        Non-empty when U was too high to be reached.
    """
    stype = _KIND_TYPE[kind]
    r_avail = 1.0 / u - R_SI[stype] - R_SE[boundary]
    r_mass = min(MASS_THICKNESS / MASS["conductivity"], 0.5 * r_avail) if mass else 0.0
    thick = r_mass * MASS["conductivity"]
    if thick < 0.01:
        thick, r_mass = 0.0, 0.0
    r = r_avail - r_mass
    note = ""
    if r < R_MIN:
        note = f"U={u:g} too high for {stype}/{boundary}: layer R clamped to {R_MIN}"
        r = R_MIN
    return r, thick, note


def _construction_name(kind: str, boundary: str, u: float) -> str:
    return f"{_KIND_TYPE[kind]}_{boundary}_U{u:.3f}".replace(".", "p")
