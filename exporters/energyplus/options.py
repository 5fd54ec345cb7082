"""Options of the EnergyPlus writer (:class:`IdfOptions`) and what every written number shares."""
from __future__ import annotations

import datetime
import re
from dataclasses import dataclass

from lod2energy.errors import ParameterError


#: Infiltration of an unconditioned attic (1/h): a ventilated roof space.
ATTIC_ACH = 1.0


@dataclass(frozen=True)
class IdfOptions:
    """Options of :func:`write`.

    Parameters
    ----------
    mode : {"building", "dataset"}
        One IDF per building, or one IDF for all buildings.
    version : str
        EnergyPlus version written in ``Version`` ("25.2").
    wwr : float, optional
        Window-to-wall ratio for every building (default: ``provenance["thermal"]["wwr"]``).
    shading : bool
        Add neighbours within ``shading_radius`` (m) as ``Shading:Building:Detailed``
        (building mode; in dataset mode the other buildings' zones already shade).
    run : bool
        Run EnergyPlus on each IDF (needs ``weather``) and read demand back.
    weather : str, optional
        EPW file: used for the run, ``Site:Location`` and ground temperatures.
    heating_setpoint, cooling_setpoint : float, C
    infiltration_ach : float, 1/h
    internal_gains : float, W/m2 floor
    shgc : float
        Solar heat gain coefficient of the glazing.
    lod : str, optional
        LoD to export (default: each building's highest).
    party_walls : bool
        Faces shared with other zones/buildings become Adiabatic.
    party_split : bool
        Split partly shared faces into an Adiabatic and an outdoor part (default: the
        whole face is Adiabatic when at least half of it is shared). EnergyPlus's
        enclosure test rejects some split zones (about 1 in 6 buildings of terraced 3DBAG
        rows); with ``run`` such a building is re-written unsplit and re-run.
    min_window_wall_area : float, m2
        Wall pieces smaller than this get no window.
    solar_distribution : str, optional
        EnergyPlus ``Building`` solar distribution; default "FullExterior" with
        ``shading`` (neighbours must cast shadows), else "MinimalShadowing" (several times
        faster on buildings with hundreds of surfaces).
    thermal_mass : bool
        Put a 10 cm brick/concrete-like layer inside every opaque construction (the
        insulation layer is reduced so that U is unchanged).
    jobs : int
        Parallel EnergyPlus runs.
    zoning : {"storey", "building"}
        One zone per storey of each Building/BuildingPart (:mod:`lod2energy.energy.zones.cut`; floors
        between storeys are interzone ``Surface`` pairs), or one zone per Building/BuildingPart.
    attic : {"unconditioned", "conditioned"}
        The space under a pitched roof (its own zone with ``zoning="storey"`` when at least
        :data:`lod2energy.thermal.storeys.ATTIC_MIN_HEIGHT` high): without or with HVAC and loads.
    use : str, optional
        Use type for every building (:data:`lod2energy.thermal.use.USE_TYPES`); default: from
        the attributes (:func:`lod2energy.thermal.use.building_use`).
    use_loads : bool
        People, lights, equipment, setpoints with setbacks, infiltration and ventilation of the
        use (:func:`lod2energy.thermal.use.use_conditions`); False: ``heating_setpoint`` /
        ``cooling_setpoint`` all year, ``infiltration_ach`` and ``internal_gains`` as before.
    run_period : tuple of 4 int
        ``(begin month, begin day, end month, end day)`` of the IDF's RunPeriod (default the
        whole year; :func:`parse_run_period`).
    """

    mode: str = "building"
    version: str = "25.2"
    wwr: float | None = None
    shading: bool = False
    shading_radius: float = 50.0
    # the simulation: its run, weather and the conditions of the zones
    run: bool = False
    weather: str | None = None
    heating_setpoint: float = 20.0
    cooling_setpoint: float = 26.0
    infiltration_ach: float = 0.5
    internal_gains: float = 0.0
    shgc: float = 0.6
    lod: str | None = None
    # the geometry of the zones and their constructions
    party_walls: bool = True
    party_split: bool = False
    min_window_wall_area: float = 4.0
    thermal_mass: bool = True
    solar_distribution: str | None = None
    timesteps_per_hour: int = 4
    jobs: int = 1
    run_timeout: float = 900.0
    zoning: str = "storey"
    attic: str = "unconditioned"
    use: str | None = None
    use_loads: bool = True
    run_period: tuple[int, int, int, int] = (1, 1, 12, 31)


def parse_run_period(text: str) -> tuple[int, int, int, int]:
    """``"MM-DD:MM-DD"`` -> ``(begin month, begin day, end month, end day)`` (ParameterError when
    not two real days of a year, the end not before the begin)."""
    m = re.fullmatch(r"\s*(\d{1,2})-(\d{1,2})\s*:\s*(\d{1,2})-(\d{1,2})\s*", str(text))
    if not m:
        raise ParameterError(f"--run-period {text!r}: expected MM-DD:MM-DD, e.g. 01-01:03-31")
    bm, bd, em, ed = (int(x) for x in m.groups())
    try:  # a leap year: 02-29 is a day EnergyPlus accepts
        begin, end = datetime.date(2024, bm, bd), datetime.date(2024, em, ed)
    except ValueError as e:
        raise ParameterError(f"--run-period {text!r}: {e}") from None
    if end < begin:
        raise ParameterError(f"--run-period {text!r}: ends before it begins (one period within a year)")
    return bm, bd, em, ed

