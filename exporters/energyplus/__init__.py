"""EnergyPlus in one package: the IDF writer, its self-check and running EnergyPlus.

Energy-ready buildings become one IDF per building, or one per dataset
(:func:`exporters.energyplus.writer.write`). Each Building / BuildingPart becomes a Zone (or
one per storey) with an ideal-loads air system. Every input face becomes one or more
``BuildingSurface:Detailed`` (planar convex pieces, counter-clockwise seen from outside,
upper-left corner first, in a local frame whose offset is written in the IDF header and
returned). Faces shared with another zone or building (coplanar, opposite, overlapping) are
split into an ``Adiabatic`` party-wall piece and the ``Outdoors`` rest. Constructions are
single no-mass layers whose resistance R = 1/U - Rsi - Rse (EnergyPlus's own film
resistances, so that EnergyPlus reports the input U-value "with film"). Windows are
``FenestrationSurface:Detailed`` insets of the outdoor wall pieces sized by the
window-to-wall ratio, with a simple glazing system. Neighbours can be added as
``Shading:Building:Detailed``.

One module per concept, in the order the writer uses them:

- ``options``: :class:`~exporters.energyplus.options.IdfOptions` and the written precision;
- ``names``: IDF-safe unique names and comments;
- ``pieces``: :class:`~lod2energy.energy.pieces.Piece` and the convex decomposition of a face;
- ``surfaces``: party walls (``find_party_faces``) and a zone's written pieces (``zone_pieces``);
- ``enclosure``: EnergyPlus's zone enclosure test, emulated;
- ``conform``: pieces conformed to that test (``keep_corners``, ``eplus_enclose``, ``eplus_conform``);
- ``openings``: windows by the window-to-wall ratio, LoD3 windows and doors;
- ``constructions``: layer build-ups from U-values;
- ``site``: ``Site:Location`` and ground temperatures;
- ``zones``: storey zones, zone information, floors;
- ``model``: the energy model, the stage before the writer (floorless parts united, zone shells
  in the writer's frame, party walls, pieces), with ``fallback``: simpler envelopes for a zone
  the enclosure test rejects;
- ``render``: the IDF text (jinja2 template ``templates/building.idf.j2``);
- ``writer``: ``write()``;
- ``check``: the self-check of a written file (``self_check``, ``read_checked_idf``, eppy);
- ``run``: locating and running EnergyPlus and reading its results.

Every string from the input (ids, names) is sanitised before it reaches the IDF: names
keep ``[A-Za-z0-9_.-]`` only, are unique case-insensitively (EnergyPlus compares names
without case) and at most 100 characters; ids in comments are JSON-escaped on one line.
"""

# the modules, so that ``energyplus.writer.write``, ``energyplus.run.binary`` ... are reachable
# from the package
from lod2energy.exporters.energyplus import check, constructions, idd, names, options, render, run, site, writer  # noqa: F401
