"""A building with only an LoD0 footprint: not a volume, reported with that reason, never exported.

The repair ladder looks at LoD >= 1 geometries only, so such a building stays "valid" for the
repair while the energy check (at its only LoD, 0) finds an open surface; the report must say
why instead of "not a closed 2-manifold".
"""
from __future__ import annotations

import argparse
import json

import numpy as np

from cityjson_docs import box_doc, write
from factories import box, building_from_polygons, square

from lod2energy.cli import main
from lod2energy.config import DEFAULT
from lod2energy.model import Building
from lod2energy.prepare import prepare
from lod2energy.validate.checks import validate_building
from lod2energy.validate.compliance import energy_compliance


def footprint_only(id: str = "fp") -> Building:
    return building_from_polygons([[square(0.0, 5.0)]], "MultiSurface", ["GroundSurface"], id=id, lod="0")


def test_compliance_names_the_missing_volume():
    b = footprint_only()
    e = energy_compliance(b, validate_building(b, DEFAULT))
    assert e["lod"] == "0" and not e["geometry_ready"] and not e["compliant"]
    assert len(e["reasons"]) == 2  # the LoD0 reason, and labels/U-values not assessed
    assert "LoD0" in e["reasons"][0] and "not a volume" in e["reasons"][0]
    assert not any("closed 2-manifold" in r or "outward" in r for r in e["reasons"])


def test_open_lod2_surface_keeps_the_manifold_reason():
    b = building_from_polygons([[square(0.0, 5.0)]], "MultiSurface", id="open2", lod="2")
    e = energy_compliance(b, validate_building(b, DEFAULT))
    assert any(r.startswith("not a closed 2-manifold") for r in e["reasons"])
    assert not any("LoD0" in r for r in e["reasons"])


def test_prepare_reports_lod0_reason():
    tb, rec = prepare(footprint_only(), DEFAULT, argparse.Namespace())
    assert rec.energy["lod"] == "0" and not rec.energy["geometry_ready"]
    assert any("LoD0" in r for r in rec.energy["reasons"])
    tb, rec = prepare(box(id="bx"), DEFAULT, argparse.Namespace())
    assert rec.energy["geometry_ready"], rec.energy["reasons"]


def test_export_skips_footprint_only_building_with_its_reason(tmp_path, capsys):
    fp = {"type": "Building", "attributes": {"yearOfConstruction": 2010},
          "geometry": [{"type": "MultiSurface", "lod": "0", "boundaries": [[[0, 3, 2, 1]]]}]}
    doc = box_doc(extra_objects={"fp": fp})
    out = tmp_path / "o"
    main(["export", "-q", write(tmp_path, doc), "-o", str(out), "--stl"])
    capsys.readouterr()
    assert sorted(p.name for p in out.glob("*.stl")) == ["b1.stl"]
    rep = {b["id"]: b for b in json.loads((out / "report.json").read_text())["buildings"]}
    assert rep["b1"]["energy"]["geometry_ready"]
    msg = rep["fp"]["message"]
    assert "not exported" in msg and "LoD0" in msg and "closed 2-manifold" not in msg
    assert np.isclose(rep["fp"]["energy"]["volume"], 0.0)
