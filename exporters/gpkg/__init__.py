"""GeoPackage of the building footprints: the GeoJSON's typed layer for GIS (``--gpkg``)."""
from lod2energy.exporters.gpkg.writer import SUFFIX, self_check, write  # noqa: F401
