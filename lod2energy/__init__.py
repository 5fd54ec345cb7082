"""lod2energy: LoD2 city models to simulation-ready geometry.

Pipeline: read (``lod2energy.io``) -> validate (``lod2energy.validate``) ->
repair (``lod2energy.repair``) -> label and assign U-values (``lod2energy.semantics``,
``lod2energy.thermal``) -> export (``lod2energy.exporters``).

The Python API (:mod:`lod2energy.api`): ``lod2energy.read(obj)`` of a path, a file object or a
CityJSON dict gives a :class:`~lod2energy.api.CityData` whose ``validate()``, ``repair(out)``
and ``export(outdir)`` run the CLI's commands; ``lod2energy.export`` too. They are loaded on
first access (module ``__getattr__``), so that ``import lod2energy`` and the CLI's ``--help``
stay light. (``lod2energy.validate`` and ``lod2energy.repair`` are the subpackages.)
"""
__version__ = "0.1.0"

from lod2energy.errors import Lod2EnergyError, InputError  # noqa: F401

#: The API's names, loaded from :mod:`lod2energy.api` on first access.
_API = ("read", "export", "CityData")

__all__ = ["Lod2EnergyError", "InputError", *_API]


def __getattr__(name: str):
    if name in _API:
        from lod2energy import api
        return getattr(api, name)
    raise AttributeError(f"module 'lod2energy' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_API))
