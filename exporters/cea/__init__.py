"""City Energy Analyst zone table (zone.shp): footprints, storeys, heights, year, construction and use."""
from lod2energy.exporters.cea.writer import FIELDS, USE_TYPE, self_check, write  # noqa: F401
