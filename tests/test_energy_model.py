"""The energy model stage (lod2energy.energy.model): floorless parts and simpler envelopes
are decided before the IDF writer, recorded in the building's provenance, and the writer writes
what it is given."""
from __future__ import annotations

import json
from dataclasses import replace
import re

import numpy as np
import pytest

from export_helpers import energy_ready, parts_with_semantics, shifted, steep_house_with_dormer, write_idf
from factories import box

from lod2energy import cache
from lod2energy.exporters import energyplus
from lod2energy.exporters.registry import writer
from lod2energy.energy.zones.shells import local_origin
from lod2energy.model import CityModel, frozen_mapping
from lod2energy.energy import model as energy_model

OPTIONS = energyplus.options.IdfOptions()


def dormer_house():
    """A steep house with a dormer part that has no face EnergyPlus can take as a floor."""
    house, ht, dormer, dt = steep_house_with_dormer()
    return energy_ready(parts_with_semantics([(house, ht), (dormer, dt)]))


def _zone_names(path) -> list[str]:
    return sorted(re.findall(r"\nZone,\s*([^,;]+?)\s*[,;]", open(path, encoding="ascii").read()))


def _idf_bytes(res) -> bytes:
    return open(res[0].path, "rb").read()


def test_the_stage_records_a_united_dormer_and_keeps_the_geometry():
    b = dormer_house()
    [staged] = energy_model.with_energy_model([b], OPTIONS)
    rec = staged.provenance["energy_model"]
    assert any("united with dormer_house-part0" in n for n in rec["notes"])
    assert rec["zones"] == ("dormer_house-part0",)
    assert isinstance(rec["model"], energy_model.EnergyModel)
    # the building's own geometry (what STL and CityJSON write) keeps both parts
    assert np.array_equal(staged.vertices, b.vertices) and staged.objects == b.objects
    assert [o.id for o, _, _ in staged.envelope()] == ["dormer_house-part0", "dormer_house-part1"]
    assert "energy_model" not in b.provenance


def test_the_writer_writes_the_recorded_model(tmp_path, monkeypatch):
    b = dormer_house()
    direct = write_idf([b], tmp_path / "direct", OPTIONS)
    staged = energy_model.with_energy_model([b], OPTIONS)

    def no_second_model(*a, **k):
        raise AssertionError("the writer made its own energy model")
    monkeypatch.setattr(energy_model, "prepare_energy_model", no_second_model)
    given = write_idf(staged, tmp_path / "given", OPTIONS)
    assert given[0].ok, given[0].problems
    assert _idf_bytes(given) == _idf_bytes(direct)
    assert _zone_names(given[0].path) == _zone_names(direct[0].path) and len(_zone_names(direct[0].path)) >= 1
    assert any("united with" in w for w in given[0].warnings)


def test_a_model_made_for_other_neighbours_is_refused_not_made_again(tmp_path):
    # the writer writes the model it is given: one made without the neighbour is an error
    b, nb = energy_ready(box(id="a")), energy_ready(box(origin=(10.0, 0.0, 0.0), id="n"))
    [staged] = energy_model.with_energy_model([b], OPTIONS)  # without the neighbour
    with pytest.raises(ValueError, match="other buildings, neighbours or options"):
        energy_model.model_of([staged], OPTIONS, [nb])
    with pytest.raises(ValueError):
        write_idf([staged], tmp_path, OPTIONS, context=[nb])
    assert energy_model.model_of([staged], OPTIONS) is staged.provenance["energy_model"]["model"]


def test_a_simpler_envelope_is_recorded_and_written(tmp_path, monkeypatch):
    # a zone whose pieces the enclosure emulation rejects: the stage swaps in the first
    # fallback that passes, says which, and the writer writes that zone
    b = energy_ready(box())
    real = energy_model.enclosure_defects
    calls = []

    def reject_first(polys, *a, **k):
        calls.append(len(polys))
        return ["x"] if len(calls) == 1 else real(polys, *a, **k)
    monkeypatch.setattr(energy_model, "enclosure_defects", reject_first)
    [staged] = energy_model.with_energy_model([b], OPTIONS)
    [simpler] = staged.provenance["energy_model"]["simpler_zones"]
    names = {energy_model._fallback_name(f) for f in energy_model.FALLBACKS}
    assert simpler["zone"] == staged.provenance["energy_model"]["zones"][0] and simpler["envelope"] in names
    model = staged.provenance["energy_model"]["model"]
    assert "fails EnergyPlus's enclosure test" in model.zones[0].warnings[-1]
    res = write_idf([staged], tmp_path, OPTIONS)
    assert res[0].ok, res[0].problems
    assert any("fails EnergyPlus's enclosure test" in w for w in res[0].warnings)
    # without the stage's verdict the same building is written as it is, without that warning
    monkeypatch.setattr(energy_model, "enclosure_defects", real)
    plain = write_idf([b], tmp_path / "plain", OPTIONS)
    assert not any("fails EnergyPlus's enclosure test" in w for w in plain[0].warnings)


def test_no_energy_ready_building_passes_unchanged():
    b = replace(box(), type="SolitaryVegetationObject")  # not a building: no zone of its own
    assert energy_model.with_energy_model([b], OPTIONS) == [b]
    assert energy_model.prepare_energy_model([b], OPTIONS) is None


def test_the_registry_runs_the_stage_before_the_idf_writer_only():
    b = dormer_house()
    [idf] = writer("idf").prepare([b], OPTIONS)
    assert "energy_model" in idf.provenance
    assert writer("stl").prepare([b], None) == [b] and writer("cityjson").prepare([b], None) == [b]


def test_the_cityjson_writer_leaves_the_energy_model_out(tmp_path):
    from lod2energy.exporters.cityjson import writer as cityjson
    [staged] = energy_model.with_energy_model([dormer_house()], OPTIONS)
    model = CityModel(version="2.0", metadata=frozen_mapping({"referenceSystem": "urn:ogc:def:crs:EPSG::7415"}))
    res = cityjson.write(str(tmp_path / "out.city.json"), model, [staged])
    text = open(res.path, encoding="utf-8").read()
    assert json.loads(text)["CityObjects"] and "energy_model" not in text and "frame_origin" not in text


@pytest.mark.parametrize("make", [dormer_house, lambda: energy_ready(box())], ids=["dormer", "box"])
def test_the_frame_is_the_writers(make, tmp_path):
    b = shifted(make())
    [staged] = energy_model.with_energy_model([b], OPTIONS)
    origin = np.asarray(staged.provenance["energy_model"]["frame_origin"])
    res = write_idf([staged], tmp_path, OPTIONS)
    # building mode: the file's offset is the frame the model was made in, that of the IDF's
    # geometry (a united dormer can reach a hair below the input's lowest point)
    assert np.array_equal(origin, local_origin(staged.provenance["energy_model"]["model"].buildings))
    assert np.all(np.abs(origin - np.floor(b.vertices.min(axis=0))) <= 1)
    assert np.array_equal(np.asarray(res[0].offset), origin)


def _row_of_three(dx=0.0):
    """Three 10 m boxes side by side in map coordinates far from 0 (their frames differ by whole
    metres), the third moved ``dx`` m."""
    x0, y0 = 85000.3, 445000.7
    return [energy_ready(box(10, 8, 6 + i, origin=(x0 + 10 * i + (dx if i == 2 else 0.0), y0 + 0.4 * i, 1.2),
                             id=f"b{i}")) for i in range(3)]


def _own_party(m):
    n = sum(len(m.zones_of[bi]) for bi in range(m.n_own))
    return {k: [(m.zones[o].building_id, round(g.area, 9)) for o, g in v] for k, v in m.party.items() if k[0] < n}


def test_neighbour_zones_made_in_their_own_frame_give_the_job_frames_party_walls():
    bs = _row_of_three()
    cache.clear(energy_model.NEIGHBOUR_ZONES)
    m = energy_model.prepare_energy_model([bs[1]], OPTIONS, [bs[0], bs[2]])
    # the reference: every zone made in the job's frame (the shading path, which pairs all zones)
    ref = energy_model.prepare_energy_model([bs[1]], replace(OPTIONS, shading=True), [bs[0], bs[2]])
    assert np.array_equal(m.origin, ref.origin) and len(m.zones) == len(ref.zones)
    for z, r in zip(m.zones, ref.zones):
        assert z.faces == r.faces and np.allclose(z.vertices, r.vertices, rtol=0, atol=1e-9)
    assert _own_party(m) == _own_party(ref) and len(_own_party(m)) == 2  # the two shared walls
    own = m.zones_of[0][0]
    assert [(p.boundary, p.kind) for p in m.pieces[own]] == [(p.boundary, p.kind) for p in ref.pieces[own]]
    assert all(np.allclose(p.points, q.points, rtol=0, atol=1e-9) for p, q in zip(m.pieces[own], ref.pieces[own]))


def test_remembered_neighbour_zones_are_those_made_anew_and_follow_the_buildings_content():
    bs = _row_of_three()
    cache.clear(energy_model.NEIGHBOUR_ZONES)
    cold = energy_model.prepare_energy_model([bs[1]], OPTIONS, [bs[0], bs[2]])
    assert cache.sizes()[energy_model.NEIGHBOUR_ZONES][0] == 2
    warm = energy_model.prepare_energy_model([bs[1]], OPTIONS, [bs[0], bs[2]])
    for a, b in zip(cold.zones, warm.zones):
        assert a.faces == b.faces and np.array_equal(a.vertices, b.vertices)
    assert _own_party(cold) == _own_party(warm)
    # the same id, another geometry: made anew, not taken for the one remembered
    moved = _row_of_three(dx=0.5)
    m = energy_model.prepare_energy_model([moved[1]], OPTIONS, [moved[0], moved[2]])
    assert cache.sizes()[energy_model.NEIGHBOUR_ZONES][0] == 3
    right = m.zones[m.zones_of[2][0]]
    assert right.vertices[:, 0].min() + m.origin[0] == pytest.approx(85020.3 + 0.5, abs=1e-6)
    assert len(_own_party(m)) == 1  # the moved box no longer touches
    for i in range(energy_model.NEIGHBOUR_ZONES_KEPT + 5):  # bounded
        energy_model._neighbour_zones(shifted(bs[0], (i, 0, 0)), OPTIONS.lod, OPTIONS.wwr)
    assert cache.sizes()[energy_model.NEIGHBOUR_ZONES][0] == energy_model.NEIGHBOUR_ZONES_KEPT


def test_spatial_order_puts_near_boxes_next_to_each_other():
    from lod2energy.neighbours import spatial_order
    rng = np.random.default_rng(7)
    cells = [(x, y) for x in range(8) for y in range(8)]
    perm = rng.permutation(len(cells))
    boxes = np.array([[x * 20.0, y * 20.0, 0, x * 20.0 + 10, y * 20.0 + 10, 6] for x, y in (cells[i] for i in perm)])
    order = spatial_order(boxes)
    assert sorted(order.tolist()) == list(range(len(boxes)))
    c = (boxes[order, :2] + boxes[order, 3:5]) / 2
    steps = np.linalg.norm(np.diff(c, axis=0), axis=1)
    shuffled = np.linalg.norm(np.diff((boxes[:, :2] + boxes[:, 3:5]) / 2, axis=0), axis=1)
    assert np.median(steps) == pytest.approx(20.0) and steps.mean() < 0.5 * shuffled.mean()
    assert spatial_order(boxes[:1]).tolist() == [0] and len(spatial_order(np.zeros((0, 6)))) == 0
