"""Agreement of our per-feature validation with a val3dity report.

A feature agrees on the *verdict* when both say valid or both say invalid, and on the
*code set* when both report the same set of distinct error codes. Helpers of
``test_reference_agreement.py``; nothing here special-cases a file.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, Mapping

from lod2energy.config import DEFAULT, Tolerances
from lod2energy.io import read
from lod2energy.validate.checks import validate_buildings


@dataclass(frozen=True)
class Agreement:
    """Outcome of a comparison.

    Parameters
    ----------
    n : int
        Features compared (those of the selected types in the reference).
    verdict : float
        Share of them with the same valid/invalid verdict (1.0 when ``n == 0``).
    codes : float
        Share with the same set of error codes.
    disagreements : list of (id, our codes, reference codes)
        Features whose code sets differ (sorted code lists).
    missing : list of str
        Reference features we did not report at all (counted as disagreeing).
    """

    n: int
    verdict: float
    codes: float
    disagreements: list = field(default_factory=list)
    missing: list = field(default_factory=list)


def reference_features(report: Mapping, types: Iterable[str] | None = ("Building",)) -> dict[str, tuple[bool, frozenset, str]]:
    """``{id: (valid, codes, type)}`` of a val3dity report's features of ``types`` (None: all)."""
    types = None if types is None else set(types)
    out = {}
    for f in report.get("features", []):
        if types is not None and f.get("type") not in types:
            continue
        codes = frozenset(int(e["code"]) for e in f.get("errors", []))
        out[str(f.get("id"))] = (bool(f.get("validity", not codes)), codes, f.get("type", ""))
    return out


def compare(ours: Mapping[str, Iterable[int]], report: Mapping,
            types: Iterable[str] | None = ("Building",)) -> Agreement:
    """Compare our codes per feature id with a val3dity report.

    Parameters
    ----------
    ours : mapping id -> iterable of int
        Distinct error codes we found per first-level feature (empty = valid).
    report : mapping
        A parsed val3dity JSON report.
    types : iterable of str or None
        Reference feature types compared (default Buildings; None = every type).

    Returns
    -------
    Agreement
    """
    ref = reference_features(report, types)
    same_v = same_c = 0
    dis, missing = [], []
    for fid, (valid, rcodes, _) in ref.items():
        if fid not in ours:
            missing.append(fid)
            dis.append((fid, None, sorted(rcodes)))
            continue
        oc = frozenset(int(c) for c in ours[fid])
        same_v += (not oc) == valid
        if oc == rcodes:
            same_c += 1
        else:
            dis.append((fid, sorted(oc), sorted(rcodes)))
    n = len(ref)
    return Agreement(n, same_v / n if n else 1.0, same_c / n if n else 1.0, dis, missing)


OWN_FEATURE_TYPES = ("Building", "BuildingPart")
"""Descendants of these types belong to their parent's feature; val3dity reports other
descendants (BuildingInstallation, ...) as features of their own."""


def split_by_feature(building, defects) -> dict[str, set[int]]:
    """Distinct val3dity codes per feature as val3dity reports them.

    A Building and its BuildingParts form one feature; any other descendant (e.g. a
    BuildingInstallation) is a feature of its own, with the defects located on it.

    Parameters
    ----------
    building : Building
    defects : iterable of Defect

    Returns
    -------
    dict id -> set of int (every feature present, empty set = valid)
    """
    owner = {o.id: (building.id if (o.type in OWN_FEATURE_TYPES or o.id == building.id) else o.id)
             for o in building.objects}
    out: dict[str, set[int]] = {fid: set() for fid in owner.values()}
    out.setdefault(building.id, set())
    for d in defects:
        if d.code >= 1000:
            continue
        coid = d.location.split("|", 1)[0]
        coid = coid[5:] if coid.startswith("coid=") else ""
        out[owner.get(coid, building.id)].add(d.code)
    return out


def validate_codes(path: str, tol: Tolerances = DEFAULT, chunk_size: int = 256) -> dict[str, set[int]]:
    """Read a file and validate every feature: ``{first-level id: set of codes}``.

    Features are validated in chunks of ``chunk_size`` (shell checks batched across
    them). Unreadable features count with their reader code (901/902/904).
    """
    _, feats = read(path)
    out: dict[str, set[int]] = {}
    chunk: list = []

    def flush():
        for b, defects in zip(chunk, validate_buildings(chunk, tol)):
            for fid, codes in split_by_feature(b, defects).items():
                out[fid] = codes
        chunk.clear()
    for b in feats:
        if hasattr(b, "objects"):
            chunk.append(b)
            if len(chunk) >= chunk_size:
                flush()
        elif b.id is not None:
            out.setdefault(b.id, set()).add(int(b.code))
    flush()
    return out


def report_tolerances(report: Mapping) -> Tolerances:
    """The tolerances a val3dity report was made with (its ``parameters``)."""
    p = report.get("parameters", {}) or {}
    return Tolerances(snap_tol=p.get("snap_tol", DEFAULT.snap_tol),
                      planarity_d2p_tol=p.get("planarity_d2p_tol", DEFAULT.planarity_d2p_tol),
                      planarity_n_tol=p.get("planarity_n_tol", DEFAULT.planarity_n_tol),
                      overlap_tol=p.get("overlap_tol", DEFAULT.overlap_tol))
