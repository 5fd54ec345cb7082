"""Attributes of a CityGML city object: the standard building attributes and generic attributes.

CityGML 1.0/2.0 ``gen:stringAttribute`` ... and ``genericAttributeSet``; 3.0's
``gen:genericAttribute`` (``gen:name`` / ``gen:value``), ``con:dateOfConstruction`` (its year, as
``yearOfConstruction``) and ``con:height`` (as ``measuredHeight``). Numbers that do not parse
are kept as text.
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from typing import Any

from lod2energy.io.gml import local_name

#: Attributes read from the object's own properties (local name -> parser).
_INT_ATTRS = ("yearOfConstruction", "yearOfDemolition", "storeysAboveGround", "storeysBelowGround")
_FLOAT_ATTRS = ("measuredHeight",)
_TEXT_ATTRS = ("function", "usage", "class", "roofType", "storeyHeightsAboveGround",
               "storeyHeightsBelowGround", "creationDate")  # core:creationDate bounds the year of construction
_GENERIC = {"stringAttribute": str, "intAttribute": int, "doubleAttribute": float,
            "measureAttribute": float, "dateAttribute": str, "uriAttribute": str}
#: CityGML 3.0 generic attributes (inside ``gen:genericAttribute``; ``gen:name`` and ``gen:value``).
_GENERIC3 = {"StringAttribute": str, "IntAttribute": int, "DoubleAttribute": float,
             "MeasureAttribute": float, "DateAttribute": str, "UriAttribute": str, "CodeAttribute": str}


def _number(text: str, kind):
    try:
        return kind(text)
    except ValueError:
        if kind is int:
            try:
                x = float(text)
                return int(x) if x.is_integer() else x
            except ValueError:
                pass
        return text


def attributes(el: ET.Element) -> dict[str, Any]:
    """Standard building attributes and generic attributes of ``el`` (its own properties)."""
    attrs: dict[str, Any] = {}
    standard: dict[str, Any] = {}
    for prop in el:
        name = local_name(prop.tag)
        text = (prop.text or "").strip()
        if name in _GENERIC or name == "genericAttributeSet":
            k, v = _generic(prop)
            if k:
                attrs[k] = v
        elif name == "genericAttribute":
            for g in prop:
                k, v = _generic3(g)
                if k:
                    attrs[k] = v
        elif name == "dateOfConstruction" and re.match(r"^\d{4}", text):
            standard.setdefault("yearOfConstruction", int(text[:4]))
        elif name == "height":  # CityGML 3.0 con:height / con:Height: its value as measuredHeight
            v = next((e for e in prop.iter() if local_name(e.tag) == "value"), None)
            if v is not None and (v.text or "").strip():
                standard.setdefault("measuredHeight", _number(v.text.strip(), float))
        elif name in _INT_ATTRS and text:
            standard[name] = _number(text, int)
        elif name in _FLOAT_ATTRS and text:
            standard[name] = _number(text, float)
        elif name in _TEXT_ATTRS and text:
            if name in standard:  # CityGML allows several function / usage values
                prev = standard[name]
                standard[name] = (prev if isinstance(prev, list) else [prev]) + [text]
            else:
                standard[name] = text
    attrs.update(standard)
    return attrs


def _generic(el: ET.Element) -> tuple[str | None, Any]:
    name = el.get("name")
    kind = local_name(el.tag)
    if kind == "genericAttributeSet":
        members = dict(_generic(c) for c in el if local_name(c.tag) in _GENERIC or local_name(c.tag) == "genericAttributeSet")
        members.pop(None, None)
        return name, members
    value = next((c for c in el if local_name(c.tag) == "value"), None)
    text = (value.text or "").strip() if value is not None else ""
    return name, _number(text, _GENERIC[kind]) if text else text


def _generic3(el: ET.Element) -> tuple[str | None, Any]:
    """A CityGML 3.0 generic attribute: ``gen:XAttribute`` with ``gen:name`` and ``gen:value``."""
    kind = local_name(el.tag)
    name = next(((c.text or "").strip() for c in el if local_name(c.tag) == "name"), None)
    if kind == "GenericAttributeSet":
        members = dict(_generic3(c) for m in el if local_name(m.tag) == "genericAttribute" for c in m)
        members.pop(None, None)
        return name, members
    if kind not in _GENERIC3:
        return None, None
    value = next((c for c in el if local_name(c.tag) == "value"), None)
    text = (value.text or "").strip() if value is not None else ""
    return name, _number(text, _GENERIC3[kind]) if text else text
