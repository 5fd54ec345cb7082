"""The IDF's simpler envelopes keep the zone's volume (issue 16: zone volumes sum to the shell's).

A zone whose written pieces would fail EnergyPlus's enclosure test is written as an LoD1
block (:func:`lod2energy.energy.fallback.block_zone`). Extruded to the
area-weighted mean roof height, a hipped house's block holds more than the house: the roof's
trapezoids count with the mean of their vertex heights, above their centroids.
"""
from __future__ import annotations

from functools import partial

import numpy as np
import pytest

from factories import building_from_polygons
from export_helpers import energy_ready

from lod2energy.energy.zones import shells as zones
from lod2energy.energy import fallback
from lod2energy.energy import model as energy_model
from lod2energy.energy.enclosure import enclosure_defects
from lod2energy.energy.pieces import _pieces_volume
from lod2energy.energy.surfaces import zone_pieces
from lod2energy.validate.closed import check_closed_outward


def hipped_house(dx: float = 10.0, dy: float = 6.0, eaves: float = 3.0, rise: float = 2.0,
                 inset: float = 3.0):
    """A hipped house: a ``dx`` x ``dy`` m box to ``eaves`` m, a ridge ``rise`` m higher
    along x, ``inset`` m in from each gable end (two trapezoid and two triangle roof faces).

    Volume ``dx*dy*eaves + rise*dy/6*(2*dx + (dx - 2*inset))`` m3 (228 m3 by default).
    """
    g = [(0, 0, 0), (dx, 0, 0), (dx, dy, 0), (0, dy, 0)]
    e = [(x, y, eaves) for x, y, _ in g]
    r0, r1 = (inset, dy / 2, eaves + rise), (dx - inset, dy / 2, eaves + rise)
    faces = [([*g[::-1]], "GroundSurface")]
    faces += [([g[i], g[(i + 1) % 4], e[(i + 1) % 4], e[i]], "WallSurface") for i in range(4)]
    faces += [([e[0], e[1], r1, r0], "RoofSurface"), ([e[1], e[2], r1], "RoofSurface"),
              ([e[2], e[3], r0, r1], "RoofSurface"), ([e[3], e[0], r0], "RoofSurface")]
    return building_from_polygons([[np.array(p, float)] for p, _ in faces], "Solid",
                                  [s for _, s in faces], id="hipped")


def _hipped_volume(dx=10.0, dy=6.0, eaves=3.0, rise=2.0, inset=3.0) -> float:
    return dx * dy * eaves + rise * dy / 6 * (2 * dx + (dx - 2 * inset))


BLOCKS = [fallback.block_zone, partial(fallback.block_zone, opening=0.1), partial(fallback.block_zone, hull=True)]


@pytest.mark.parametrize("make", BLOCKS, ids=["block", "opened", "hull"])
def test_block_envelope_keeps_the_shell_volume(make):
    z = zones.zone_shells(energy_ready(hipped_house()), np.zeros(3))[0]
    shell = _pieces_volume(zone_pieces(z, 0, {}, False))
    assert shell == pytest.approx(_hipped_volume(), rel=1e-9)
    nz = make(z)
    assert nz is not None and "LoD1 block" in nz.warnings[-1]
    pieces = zone_pieces(nz, 0, {}, False)
    pts = [p.points for p in pieces]
    assert check_closed_outward(pts) == [] and enclosure_defects(pts) == []
    assert _pieces_volume(pieces) == pytest.approx(shell, rel=1e-3)
    # the block stands on the footprint from the lowest point: only its height changed
    ground = [p.points for p in pieces if p.kind == "ground"]
    assert all(np.allclose(q[:, 2], 0.0) for q in ground)


def test_a_zone_that_falls_back_to_a_block_keeps_its_volume(monkeypatch):
    # the mechanism of 3DBAG NL.IMBAG.Pand.0503100000004459: its repaired shell fails the
    # emulated enclosure test, no earlier fallback passes, the LoD1 block is written
    z = zones.zone_shells(energy_ready(hipped_house()), np.zeros(3))[0]
    pieces = zone_pieces(z, 0, {}, True)
    original = {id(p.points) for p in pieces}
    real = energy_model.enclosure_defects

    def reject_original(polys, *a, **k):
        return ["x"] if {id(p) for p in polys} == original else real(polys, *a, **k)
    monkeypatch.setattr(energy_model, "enclosure_defects", reject_original)
    monkeypatch.setattr(energy_model, "FALLBACKS", tuple(BLOCKS))
    nz, written, how = energy_model.enclosable(z, 0, pieces)
    assert how == "block_zone"
    assert _pieces_volume(written) == pytest.approx(_pieces_volume(pieces), rel=1e-3)


def test_block_top_falls_back_to_the_mean_roof_height_without_a_volume():
    m = fallback._mesh(zones.zone_shells(energy_ready(hipped_house()), np.zeros(3))[0])
    flipped = type(m)(m.vertices, tuple(type(f)(tuple(tuple(reversed(r)) for r in f.rings)) for f in m.faces))
    assert fallback.block_top(m, 0.0, 4.0, 60.0) == pytest.approx(_hipped_volume() / 60.0)
    assert fallback.block_top(flipped, 0.0, 4.0, 60.0) == 4.0
