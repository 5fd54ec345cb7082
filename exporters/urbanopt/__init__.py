"""URBANopt FeatureFile (GeoJSON): one Building feature per building, with our heights and storeys."""
from lod2energy.exporters.urbanopt.writer import BUILDING_TYPE, SUFFIX, self_check, write  # noqa: F401
