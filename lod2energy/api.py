"""The Python API: :func:`read`, :func:`validate`, :func:`repair` and :func:`export` on a path,
a file object or a CityJSON dict, with the CLI's options as keyword arguments.

Each function runs the command of the same name (:func:`lod2energy.run.driver.execute`) with the CLI's defaults
and returns what the CLI reports: the validation report, the repair report, the export's records.
Keyword arguments are the CLI's options with ``_`` for ``-`` (``idf=True``, ``jobs=1``,
``planarity_d2p_tol=0.02``); an unknown one is a ``TypeError``, a bad value a
:class:`~lod2energy.errors.ParameterError`. Messages go to the ``lod2energy`` logger.

``lod2energy.read`` and ``lod2energy.export`` are at the package's top level;
``lod2energy.validate`` and ``lod2energy.repair`` name the subpackages, so validation and repair
are methods of what :func:`read` returns (or :func:`lod2energy.api.validate` / ``repair``):

>>> import lod2energy
>>> data = lod2energy.read(city_json_dict)                     # doctest: +SKIP
>>> report = data.validate()                                   # doctest: +SKIP
>>> outcome = lod2energy.export(data, "out", idf=True, jobs=1)  # doctest: +SKIP
"""
from __future__ import annotations

import argparse
import os
import tempfile
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import cached_property

from lod2energy import cli
from lod2energy.errors import InputError, ParameterError
from lod2energy.io import read as read_file
from lod2energy.io.source import materialise, to_bytes
from lod2energy.model import Building, CityModel, FeatureError
from lod2energy.pipeline import EXPORT, ExportOutcome
from lod2energy.repair_file import REPAIR
from lod2energy.run.driver import execute
from lod2energy.validate_files import VALIDATE


@dataclass(frozen=True, eq=False)
class CityData:
    """An input as :func:`read` holds it: a file on disk (``path``) or the bytes of a document
    (``data``) written to a file of its own when a command runs on it.

    ``model`` and ``features`` are read on first use (a CityJSONSeq's features all at once).
    """

    name: str
    path: str | None = None
    data: bytes | None = field(default=None, repr=False)
    crs: str | None = None

    @contextmanager
    def on_disk(self, folder: str | None = None) -> Iterator[str]:
        """A path of this input: its own, or its bytes written into ``folder`` (a temporary
        folder, removed afterwards, when None)."""
        if self.path is not None:
            yield self.path
        elif folder is not None:
            yield materialise(self.data, folder, self.name)
        else:
            with tempfile.TemporaryDirectory(prefix="lod2energy-data-") as tmp:
                yield materialise(self.data, tmp, self.name)

    @cached_property
    def _read(self) -> tuple[CityModel | None, list[Building | FeatureError]]:
        with self.on_disk() as path:
            model, feats = read_file(path, crs=self.crs)
            return model, list(feats)

    @property
    def model(self) -> CityModel | None:
        """The file-level data (None when the input cannot be used: see :attr:`features`)."""
        return self._read[0]

    @property
    def features(self) -> list[Building | FeatureError]:
        """Every first-level object as read (a :class:`~lod2energy.model.FeatureError` for one that cannot be)."""
        return self._read[1]

    @property
    def buildings(self) -> list[Building]:
        """The readable objects of :attr:`features`."""
        return [f for f in self.features if isinstance(f, Building)]

    def validate(self, **options) -> dict:
        """:func:`validate` of this input."""
        return validate(self, **options)

    def repair(self, output: str, **options) -> dict:
        """:func:`repair` of this input into ``output``."""
        return repair(self, output, **options)

    def export(self, outdir: str, **options) -> ExportOutcome:
        """:func:`export` of this input into ``outdir``."""
        return export(self, outdir, **options)


def read(obj, name: str = "data", crs: str | None = None) -> CityData:
    """An input for :func:`validate`, :func:`repair` and :func:`export`.

    Parameters
    ----------
    obj : str, os.PathLike, dict, list of dict, bytes or file object
        A path (any format the CLI reads), a CityJSON document as a dict, a CityJSONSeq as a
        list of dicts (the header first), or a file object / bytes of a CityJSON, CityJSONSeq
        or CityGML document.
    name : str
        Stem of the file a document is written to; names the dataset outputs
        (``<name>.energy.city.json``). A path keeps its own name.
    crs : str, optional
        The CRS of the coordinates, replacing the file's (the CLI's ``--crs``).

    Raises
    ------
    InputError
        For an object of another type or a stream larger than the input limit.
    """
    if isinstance(obj, CityData):
        return obj
    if isinstance(obj, (str, os.PathLike)) and not (isinstance(obj, str) and obj.lstrip()[:1] in ("{", "[", "<")):
        return CityData(os.path.basename(os.fspath(obj)), path=os.fspath(obj), crs=crs)
    if isinstance(obj, (str, Mapping, list, tuple, bytes, bytearray)) or hasattr(obj, "read"):
        return CityData(name, data=to_bytes(obj), crs=crs)
    raise InputError(f"cannot read a {type(obj).__name__}: give a path, a file object or a CityJSON dict")


def _arguments(command: str, positional: list[str], options: dict) -> argparse.Namespace:
    """The parsed arguments of ``lod2energy command positional...`` with ``options`` set by name."""
    a = cli.build_parser().parse_args([command, *positional])
    known = vars(a)
    for k, v in options.items():
        if k not in known or k in ("command", "input", "output", "files"):
            raise TypeError(f"{command}() got an unexpected option {k!r} (the options of "
                            f"'lod2energy {command} --help', with _ for -)")
        setattr(a, k, v)
    return a


def validate(data, **options) -> dict:
    """Validate ``data`` (what :func:`read` takes or returns) as ``lod2energy validate`` does.

    Returns
    -------
    dict
        The JSON report (``validate --report``: val3dity's shape plus the energy blocks),
        with ``exit_code`` (0 valid, 1 some building invalid, 2 unusable input) added.
    """
    data = read(data)
    with data.on_disk() as path:
        a = _arguments("validate", [path], {"quiet": True, "crs": data.crs, **options})
        run = execute(VALIDATE, a)
    return {**run.made["reports"][0], "input_file": data.path or data.name, "exit_code": run.code}


def repair(data, output: str, **options) -> dict:
    """Repair ``data`` into ``output`` (CityJSON ``.json`` or CityJSONSeq ``.jsonl``) as
    ``lod2energy repair`` does.

    Returns
    -------
    dict
        The repair report (``repair --report``) with ``exit_code``; for an unusable input only
        ``exit_code`` (2).
    """
    data = read(data)
    with data.on_disk() as path:
        a = _arguments("repair", [path, "-o", os.fspath(output)], {"quiet": True, "crs": data.crs, **options})
        run = execute(REPAIR, a)
    return {**run.made.get("doc", {}), "exit_code": run.code}


def export(data, outdir: str, **options) -> ExportOutcome:
    """Export ``data`` into ``outdir`` as ``lod2energy export`` does (choose formats with
    ``idf=True``, ``stl=True``, ``cityjson=True``, ``geojson=True``, ``gpkg=True``, ``cfd=True``).

    A document held in memory is written to ``outdir/.lod2energy/input/<name>.city.json[l]``
    first, as the CLI does with standard input.

    Returns
    -------
    ExportOutcome
        ``exit_code`` and ``records`` (one :class:`~lod2energy.records.BuildingRecord` per
        object, in input order: the rows of ``report.csv``).
    """
    data = read(data)
    outdir = os.fspath(outdir)
    if os.path.exists(outdir) and not os.path.isdir(outdir):
        raise ParameterError(f"{outdir}: exists and is not a folder")
    with data.on_disk(os.path.join(outdir, ".lod2energy", "input")) as path:
        a = _arguments("export", [path, "-o", outdir], {"quiet": True, "crs": data.crs, **options})
        return execute(EXPORT, a).made["outcome"]
