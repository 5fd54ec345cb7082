"""A CityJSON document made valid for the version it is written in (1.0, 1.1, 2.0).

The input's header (metadata, extensions, CRS spelling) and some object details (addresses,
numeric LoDs, null attributes in 1.0) differ between versions; the writer keeps what the target
version's schema accepts and says what it changed.
"""
from __future__ import annotations

import re
from dataclasses import replace
from collections.abc import Mapping

from lod2energy.crs import cityjson_reference_system
from lod2energy.io.cityjson_write import _plain
from lod2energy.model import CityModel, frozen_mapping

from lod2energy.exporters.cityjson.schema import EXTENSION_FILE, EXTENSION_NAME, EXTENSION_VERSION, _validators


def _crs_for_version(crs: str, version: str) -> str:
    return cityjson_reference_system(crs, version) or crs


def _header_fixes(md: dict, ext: dict, version: str) -> list[str]:
    """Make the input's metadata / extension declarations valid for ``version`` (in place).

    Metadata keys the target schema rejects are dropped; an extension version "1.1.0" is
    written "1.1" where the schema wants major.minor. Returns notes on what changed.
    """
    notes: list[str] = []
    if "referenceSystem" in md:
        new = _crs_for_version(str(md["referenceSystem"]), version)
        if new != md["referenceSystem"]:
            notes.append(f"metadata.referenceSystem written as {new}")
            md["referenceSystem"] = new
    schemas = _validators(version)
    for _ in range(5):
        probe = {"type": "CityJSON", "version": version, "CityObjects": {}, "vertices": [],
                 "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]}, "metadata": md, "extensions": ext}
        errs = list(schemas.document.iter_errors(probe))
        if not errs:
            break
        changed = False
        for e in errs:
            path = list(e.absolute_path)
            if path[:1] == ["metadata"]:
                if len(path) >= 2 and path[1] in md:
                    notes.append(f"metadata.{path[1]} dropped (not valid in CityJSON {version})")
                    md.pop(path[1])
                    changed = True
                elif e.validator == "additionalProperties" and isinstance(e.instance, Mapping):
                    allowed = set((e.schema.get("properties") or {}))
                    for k in [k for k in md if k not in allowed]:
                        notes.append(f"metadata.{k} dropped (not defined in CityJSON {version})")
                        md.pop(k)
                        changed = True
            elif path[:1] == ["extensions"] and len(path) >= 2 and path[1] in ext:
                name_ = path[1]
                v = str((ext[name_] or {}).get("version", ""))
                m = re.match(r"^(\d+)\.(\d+)", v)
                if path[-1] == "version" and m and m.group(0) != v:
                    ext[name_] = {**ext[name_], "version": m.group(0)}
                    notes.append(f"extensions.{name_}.version {v!r} written as {m.group(0)!r}")
                else:
                    ext.pop(name_)
                    notes.append(f"extensions.{name_} dropped (not valid in CityJSON {version})")
                changed = True
        if not changed:
            break
    return notes


def model_for(model: CityModel, version: str) -> tuple[CityModel, list[str]]:
    ext = dict(_plain(model.extensions) or {})
    ext[EXTENSION_NAME] = {"url": EXTENSION_FILE, "version": EXTENSION_VERSION}
    md = dict(_plain(model.metadata) or {})
    notes = _header_fixes(md, ext, version)
    extra = dict(model.extra)
    if model.version != version:
        extra = {k: v for k, v in extra.items() if k.startswith("+")}
    # textures / materials refer to surfaces by index: after relabelling they are not kept
    return replace(model, extensions=frozen_mapping(ext), metadata=frozen_mapping(md),
                   extra=frozen_mapping(extra), appearance=None, version=version), notes


def _fix_address(co: dict, version: str) -> None:
    """Addresses: an object in CityJSON 1.0, an array of objects later. Their ``location``
    (a MultiPoint with vertex indices) is dropped: the energy export does not carry it."""
    addr = co.get("address")
    if addr is None:
        return
    items = addr if isinstance(addr, list) else [addr]
    items = [{k: v for k, v in a.items() if k != "location"} for a in items if isinstance(a, dict)]
    if not items:
        co.pop("address")
    elif version == "1.0":
        co["address"] = items[0]
    else:
        co["address"] = items


def fix_cityobject(co: dict, version: str) -> dict:
    """Version-specific details of one CityObject's JSON the shared writer leaves generic (in place)."""
    _fix_address(co, version)
    if version == "1.0" and isinstance(co.get("attributes"), dict):
        # CityJSON 1.0 types its standard attributes (class, function, ...) as strings
        # without a null: an attribute without a value is left out
        co["attributes"] = {k: v for k, v in co["attributes"].items() if v is not None}
    for g in co.get("geometry", []) or []:
        if version == "1.0" and isinstance(g.get("lod"), str):
            lod = float(g["lod"])
            g["lod"] = int(lod) if lod.is_integer() else lod
        g.pop("material", None)
        g.pop("texture", None)
    return co


def fix_header(doc: dict, version: str) -> dict:
    """Version-specific details of the document's head (in place)."""
    if version == "1.0":
        doc.get("metadata", {}).pop("title", None)
    return doc


