"""Zones: the shells of Buildings/BuildingParts (``shells``), a shell cut into storeys
(``cut``) and the zones as written, one per storey or per part (``storeys``)."""
