"""Oracles of the IDD module's fast paths: the IDD read whole at once (the lazy classes are
compared with it) and ``check_idf`` without its per-object memo."""
from __future__ import annotations

import re

from lod2energy.exporters.energyplus.idd import Idd, _class_def, _read_classes


def parse_idd_reference(text: str) -> Idd:
    """The IDD ``text`` with every class read and built at once."""
    m = re.search(r"!IDD_Version\s+(\S+)", text)
    return Idd(m.group(1) if m else "", {k: _class_def(c) for k, c in _read_classes(text).items()})


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
