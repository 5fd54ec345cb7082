"""Honeybee Model JSON (HBJSON) per building, written as plain JSON (honeybee itself is not imported)."""
from lod2energy.exporters.hbjson.writer import SUFFIX, model_dict, self_check, write  # noqa: F401
