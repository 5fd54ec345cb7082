"""``lod2energy.idd.parse_idd`` as it was before its classes were built on first use (the
reference :mod:`tests.test_idf_fast_paths` compares the lazy classes with)."""
from __future__ import annotations

import re

from lod2energy.idd import ClassDef, FieldDef, Idd, _FIELD_ID, _num


def parse_idd_reference(text: str) -> Idd:
    """Parse the text of an ``Energy+.idd``."""
    m = re.search(r"!IDD_Version\s+(\S+)", text)
    version = m.group(1) if m else ""
    classes: dict[str, ClassDef] = {}
    cur: dict | None = None
    fld: dict | None = None

    def close_field():
        nonlocal fld
        if fld is not None and cur is not None:
            cur["fields"].append(fld)
        fld = None

    def close_class():
        nonlocal cur
        close_field()
        if cur is not None:
            fields = tuple(FieldDef(
                name=f["name"], numeric=f["numeric"],
                type=f.get("type") or ("real" if f["numeric"] else "alpha"),
                required=f.get("required", False), keys=tuple(f.get("keys", ())),
                minimum=f.get("minimum"), maximum=f.get("maximum"),
                min_exclusive=f.get("min_exclusive", False), max_exclusive=f.get("max_exclusive", False),
                autosizable=f.get("autosizable", False), autocalculatable=f.get("autocalculatable", False),
                default=f.get("default")) for f in cur["fields"])
            first = next((i for i, f in enumerate(cur["fields"]) if f.get("begin_ext")), len(fields))
            classes[cur["name"].upper()] = ClassDef(cur["name"], fields, cur.get("extensible", 0), first,
                                                    cur.get("unique", False), cur.get("required", False))
        cur = None

    def attribute(attr: str):
        target = fld if fld is not None else cur
        if target is None:
            return
        key, _, value = attr.partition(" ")
        value = value.strip()
        low = key.lower()
        if fld is not None:
            if low == "field":
                fld["name"] = value
            elif low == "required-field":
                fld["required"] = True
            elif low == "type":
                fld["type"] = value.lower()
            elif low == "key":
                fld.setdefault("keys", []).append(value.upper())
            elif low in ("minimum", "minimum>"):
                fld["minimum"] = _num(value)
                fld["min_exclusive"] = low.endswith(">")
            elif low in ("maximum", "maximum<"):
                fld["maximum"] = _num(value)
                fld["max_exclusive"] = low.endswith("<")
            elif low == "autosizable":
                fld["autosizable"] = True
            elif low == "autocalculatable":
                fld["autocalculatable"] = True
            elif low == "default":
                fld["default"] = value
            elif low == "begin-extensible":
                fld["begin_ext"] = True
        else:
            if low.startswith("extensible:"):
                cur["extensible"] = int(re.match(r"\d+", low.split(":", 1)[1]).group(0))
            elif low == "unique-object":
                cur["unique"] = True
            elif low == "required-object":
                cur["required"] = True

    for raw in text.splitlines():
        line = raw.split("!", 1)[0].strip()
        if not line:
            continue
        if line.startswith("\\"):
            if line.lower().startswith("\\group"):
                continue
            attribute(line[1:])
            continue
        code, sep, attr = line.partition("\\")
        for tok in (t.strip() for t in re.split(r"[,;]", code)):
            if not tok:
                continue
            if _FIELD_ID.match(tok) and cur is not None:
                close_field()
                fld = {"name": tok, "numeric": tok[0] == "N"}
            else:
                close_class()
                cur = {"name": tok, "fields": []}
        if sep:
            attribute(attr)
    close_class()
    return Idd(version, classes)
