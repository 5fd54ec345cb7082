"""Energy-ADE CityJSON: the writer (``writer``), its streamed self-check (``check``), the schemas
(``schema``), the version conversion (``version``) and the input's terrain (``terrain``)."""
from lod2energy.exporters.cityjson.writer import self_check, write  # noqa: F401
