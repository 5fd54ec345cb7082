"""Surfaces facing down (overhangs, soffits, floors over passages) are exterior floors, never roofs.

A block whose upper storey cantilevers (:func:`factories.cantilever`): the overhang's
underside faces down. Labelled RoofSurface in the input (as some producers do), unlabelled,
or OuterFloorSurface, it is labelled OuterFloorSurface, classified ``floor`` by the energy
model and written as a Floor with an Outdoors boundary: EnergyPlus gives no "Roof/Ceiling is
upside down" warning.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from export_helpers import EPW, eppy_idf, energy_ready, shifted
from factories import cantilever, gabled_house
from lod2energy.energy.zones.shells import classify, local_origin, zone_shells
from lod2energy.exporters import energyplus
from lod2energy.geometry import newell_normal
from lod2energy.semantics import DEFAULT_RULES, OUTER_FLOOR, ROOF, check_labels, label_building

SOFFITS = ["RoofSurface", None, "OuterFloorSurface"]


def _types(b):
    g = b.objects[0].geometries[0]
    return [g.semantic_type(s) for s in g.solids[0].shells[0].surfaces]


def _soffit_index(b) -> int:
    """Index of the face facing straight down above the ground (the overhang's underside)."""
    for i, s in enumerate(b.objects[0].geometries[0].solids[0].shells[0].surfaces):
        p = b.vertices[list(s.outer)]
        n = newell_normal(p)
        if n[2] < -0.99 * np.linalg.norm(n) and p[:, 2].min() > 1.0:
            return i
    raise AssertionError("no soffit")


@pytest.mark.parametrize("soffit", SOFFITS)
def test_soffit_is_labelled_an_exterior_floor(soffit):
    b = cantilever(soffit=soffit)
    i = _soffit_index(b)
    lab = label_building(b)
    types = _types(lab)
    assert types[i] == OUTER_FLOOR
    assert ROOF in types and types.count(OUTER_FLOOR) == 1  # the real roof stays a roof
    entry = lab.objects[0].geometries[0].semantic_surfaces[i]
    assert entry["labelSource"] == {"RoofSurface": "facing", None: "rule", "OuterFloorSurface": "input"}[soffit]
    if soffit == "RoofSurface":
        assert entry["inputType"] == "RoofSurface"
        assert any(d.code == 1101 for d in check_labels(b)) and not any(d.code == 1101 for d in check_labels(lab))


def test_a_roof_facing_down_is_never_classified_roof():
    down, up = np.array([0.0, 0.0, -1.0]), np.array([0.0, 0.0, 1.0])
    assert classify("RoofSurface", down) == "floor" and classify("OuterCeilingSurface", down) == "floor"
    assert classify("RoofSurface", up) == "roof"
    facing = DEFAULT_RULES.check_facing_nz
    slant = np.array([np.sqrt(1 - (facing / 2) ** 2), 0.0, -facing / 2])  # within the threshold: still a roof
    assert classify("RoofSurface", slant) == "roof"
    # the writer called on unlabelled stages' output: the zone takes the face as a floor
    b = cantilever(soffit="RoofSurface")
    (z,) = zone_shells(b, local_origin([b]))
    kinds = {f.index: f.kind for f in z.faces}
    assert kinds[_soffit_index(b)] == "floor"
    assert sorted(kinds.values()).count("roof") == 1


def test_inward_shell_faces_are_classified_by_their_outward_normals():
    from dataclasses import replace
    from lod2energy.model import Shell, Solid, Surface
    b = cantilever(soffit="RoofSurface")
    g = b.objects[0].geometries[0]
    flipped = tuple(Surface(tuple(r[::-1] for r in s.rings), s.semantic) for s in g.solids[0].shells[0].surfaces)
    g = replace(g, solids=(Solid((Shell(flipped),)),))
    inward = replace(b, objects=(replace(b.objects[0], geometries=(g,)),))
    (z,) = zone_shells(inward, local_origin([inward]))
    assert any("flipped" in w for w in z.warnings)
    assert {f.index: f.kind for f in z.faces}[_soffit_index(b)] == "floor"


def _downward_roofs(path: Path) -> list[str]:
    """Names of the Roof/Ceiling surfaces of an IDF whose outward normal faces down."""
    out = []
    for s in eppy_idf(path).idfobjects["BUILDINGSURFACE:DETAILED"]:
        n = int(s.Number_of_Vertices)
        p = np.array([[float(s[f"Vertex_{i}_{a}coordinate"]) for a in "XYZ"] for i in range(1, n + 1)])
        if s.Surface_Type in ("Roof", "Ceiling") and newell_normal(p)[2] < 0:
            out.append(s.Name)
    return out


@pytest.mark.parametrize("soffit", SOFFITS)
def test_soffit_written_as_an_outdoor_floor(tmp_path, soffit):
    b = energy_ready(shifted(cantilever(soffit=soffit)))
    res = energyplus.writer.write([b], tmp_path, energyplus.options.IdfOptions(), crs="EPSG:28992")[0]
    assert res.ok, res.problems
    assert _downward_roofs(Path(res.path)) == []
    floors = [s for s in eppy_idf(res.path).idfobjects["BUILDINGSURFACE:DETAILED"]
              if s.Surface_Type == "Floor" and s.Outside_Boundary_Condition == "Outdoors"]
    assert sum(float(s.area) for s in floors) == pytest.approx(10.0 * 4.0)  # the overhang: 10 m x 4 m
    assert sum(res.stats["zone_volume_m3"].values()) == pytest.approx(10.0 * 3.0 * 20.0, rel=1e-6)


@pytest.mark.external
def test_energyplus_finds_nothing_upside_down(tmp_path):
    if energyplus.run.binary() is None:
        pytest.skip("EnergyPlus not installed")
    bs = [energy_ready(shifted(cantilever(soffit="RoofSurface"), (212000.0, 490000.0, 0.0))),
          energy_ready(shifted(gabled_house(), (212050.0, 490000.0, 0.0)))]
    res = energyplus.writer.write(bs, tmp_path, energyplus.options.IdfOptions(run=True, weather=str(EPW),
                                                                            timesteps_per_hour=2),
                                  crs="EPSG:28992")
    for r in res:
        assert r.ok and r.severe_errors == 0, r.problems
        err = Path(r.path).with_name(Path(r.path).stem + "_eplus") / "eplusout.err"  # run._run's folder
        assert "upside down" not in err.read_text(errors="replace")


def test_real_roofs_facing_down_are_written_as_outdoor_floors(tmp_path):
    """Den Haag buildings whose input labels RoofSurface faces that face down (1101)."""
    from conftest import shared_path
    from lod2energy import io
    from lod2energy.model import Building

    _, feats = io.read(str(shared_path("denhaag", "DenHaag_01.city.json")))
    down = [b for b in feats if isinstance(b, Building) and b.type == "Building"
            and any(d.code == 1101 for d in check_labels(b))][:4]
    assert down
    for b in down:
        lab = label_building(b)
        assert not any(d.code == 1101 for d in check_labels(lab))
        res = energyplus.writer.write([energy_ready(b)], tmp_path / b.id, energyplus.options.IdfOptions(),
                                      crs="EPSG:7415")[0]
        assert res.ok, res.problems
        assert _downward_roofs(Path(res.path)) == []
