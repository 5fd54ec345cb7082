"""The energy model: what EnergyPlus is given, built as a stage before the IDF writer.

One module per concept:

- ``zones``: zone shells (the closed envelope of each Building/BuildingPart in a local frame),
  the storey cut and the storey zones;
- ``pieces``: planar convex pieces of a face, as written;
- ``surfaces``: party walls and a zone's written pieces;
- ``enclosure``: EnergyPlus's zone enclosure test, emulated; ``conform``: pieces conformed to it;
- ``openings``: windows by the window-to-wall ratio, LoD3 windows and doors;
- ``uvalues``: the U-value of a face;
- ``fallback``: simpler envelopes for a zone the enclosure test rejects;
- ``model``: the stage (:func:`~lod2energy.energy.model.with_energy_model`) and its
  :class:`~lod2energy.energy.model.EnergyModel`.
"""
