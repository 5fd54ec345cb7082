"""``lod2energy.exporters.energyplus.idd.parse_idd`` as it was before its classes were built on first use (the
reference :mod:`tests.test_idf_fast_paths` compares the lazy classes with)."""
from __future__ import annotations

import re

from lod2energy.exporters.energyplus.idd import ClassDef, FieldDef, Idd, _FIELD_ID, _num


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


def check_idf_reference(objects, idd: Idd, max_problems: int = 20) -> list[str]:
    """``lod2energy.exporters.energyplus.idd.check_idf`` as it was before its per-object memo and its one-pass test
    of coordinate lists (every field through ``_field_problem``)."""
    from lod2energy.exporters.energyplus.idd import _class_flags, _field_problem

    problems: list[str] = []
    seen: dict[str, int] = {}
    for o in objects:
        if len(problems) >= max_problems:
            break
        c = idd.classes.get(o.cls.upper())
        if c is None:
            problems.append(f"line {o.line}: unknown object {o.cls!r}")
            continue
        seen[c.name] = seen.get(c.name, 0) + 1
        if not c.extensible and len(o.fields) > len(c.fields):
            problems.append(f"line {o.line}: {c.name} has {len(o.fields)} fields, the IDD defines {len(c.fields)}")
            continue
        if c.extensible and len(o.fields) > c.first_extensible and (len(o.fields) - c.first_extensible) % c.extensible:
            problems.append(f"line {o.line}: {c.name} ends inside a group of {c.extensible} extensible fields")
        for i, f in enumerate(c.fields[:c.first_extensible]):
            v = o.fields[i] if i < len(o.fields) else ""
            if f.required and not v and f.default is None:
                problems.append(f"line {o.line}: {c.name}: required field {f.name!r} is empty")
        for i, v in enumerate(o.fields):
            if not v:
                continue
            f = c.field(i)
            why = _field_problem(f, v)
            if why:
                problems.append(f"line {o.line}: {c.name}, {f.name}: {why}")
                if len(problems) >= max_problems:
                    break
        if c.name == "Version" and o.fields and idd.version:
            want = ".".join(idd.version.split(".")[:2])
            got = ".".join(o.fields[0].split(".")[:2])
            if got != want:
                problems.append(f"line {o.line}: Version {o.fields[0]} but the IDD is {idd.version}")
    for name, unique, required in _class_flags(idd):
        if unique and seen.get(name, 0) > 1:
            problems.append(f"{name} appears {seen[name]} times (a unique object)")
        if required and not seen.get(name):
            problems.append(f"required object {name} is missing")
    return problems[:max_problems]
