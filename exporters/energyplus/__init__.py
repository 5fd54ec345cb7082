"""EnergyPlus: the IDF writer, its self-check and running EnergyPlus.

The writer (:func:`~lod2energy.exporters.energyplus.writer.write`, one IDF per building or
per dataset) writes the energy model the stage before it made
(:mod:`lod2energy.energy.model`): a Zone per Building/BuildingPart or storey with an
ideal-loads air system, each face as planar convex ``BuildingSurface:Detailed`` pieces in a
local frame whose offset is in the header, party walls ``Adiabatic``, no-mass constructions of
resistance R = 1/U - Rsi - Rse, windows by the window-to-wall ratio, neighbours as
``Shading:Building:Detailed``. One module per concept:

- ``options``: :class:`~lod2energy.exporters.energyplus.options.IdfOptions`;
- ``names``: IDF-safe unique names (``[A-Za-z0-9_.-]``, unique without case, at most 100
  characters) and JSON-escaped comments;
- ``constructions``: layer build-ups from U-values; ``site``: ``Site:Location`` and ground
  temperatures;
- ``render``: the IDF text (jinja2 template ``templates/building.idf.j2``);
- ``writer``: ``write()``, registered as the "idf" writer;
- ``check``: the self-check of a written file, with ``idd`` (reading ``Energy+.idd`` and
  checking an IDF against it);
- ``run``: locating and running EnergyPlus and reading its results.
"""
from lod2energy.exporters.energyplus import check, constructions, idd, names, options, render, run, site, writer  # noqa: F401
