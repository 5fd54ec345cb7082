"""GeoJSON of building footprints in WGS84 with the energy model's figures."""
from lod2energy.exporters.geojson.writer import SUFFIX, self_check, write  # noqa: F401
