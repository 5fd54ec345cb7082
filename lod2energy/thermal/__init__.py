"""Thermal properties: typology tables (country x period x building type) and U-values / UA.

``assign_u_values(b, ThermalOptions(...))`` is the stage; tables and their sources live in
``lod2energy/thermal/data`` (see ``SOURCES.md`` there).
"""
from lod2energy.thermal.typology import Typology, classify, country_from_crs  # noqa: F401
from lod2energy.thermal.uvalues import (  # noqa: F401
    ThermalOptions, assign_u_values, builtin_rows, check_u_values, load_table, lookup,
)
