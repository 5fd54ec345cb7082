"""CFD case export: a region of a city model as an OpenFOAM v1912 case ready to mesh and run.

``lod2energy export --cfd``: :mod:`~lod2energy.exporters.cfd.options` (:class:`CfdOptions`, the
command-line flags), :mod:`~lod2energy.exporters.cfd.writer` (:func:`export_case`, registered as
the "cfd" writer), :mod:`~lod2energy.exporters.cfd.domain` (guideline domain),
:mod:`~lod2energy.exporters.cfd.region` (region selection), :mod:`~lod2energy.exporters.cfd.surfaces`
(united buildings, ground), :mod:`~lod2energy.exporters.cfd.terrain`, :mod:`~lod2energy.exporters.cfd.case`
(the case folder), :mod:`~lod2energy.exporters.cfd.mesh` and :mod:`~lod2energy.exporters.cfd.openfoam`
(running and checking the mesh).
"""
from lod2energy.exporters.cfd.options import CfdOptions, add_cli_arguments, options_from_args  # noqa: F401
