"""A defect: a small frozen record (code, location, info), as val3dity reports errors."""
from __future__ import annotations

from dataclasses import dataclass

from lod2energy.validate.codes import name


@dataclass(frozen=True, order=True)
class Defect:
    """One error found by a check.

    Parameters
    ----------
    code : int
        val3dity code (101-904) or a project code (1001+).
    location : str
        val3dity-style ``coid=..|geom=..|shell=..|face=..``.
    info : str
        Free text (measured value and tolerance, where the hole is, ...).
    """

    code: int
    location: str = ""
    info: str = ""

    @property
    def description(self) -> str:
        return name(self.code)

    def to_json(self) -> dict:
        return {"code": self.code, "description": self.description, "id": self.location, "info": self.info}
