"""Implausible coordinates (a vertex 2,000 km away, NaN): a clear per-building error, no hang.

A building whose vertices span kilometres (a no-data value in integer CityJSON coordinates,
as in real roofer output) used to reach the alpha wrap, whose work grows with the wrapped
area and which CGAL cannot interrupt: the process ran out of memory. Now the geometry is
left "irreparable" with the reason, and the rest of the batch is repaired and exported.
"""
from __future__ import annotations

import copy
import csv
import json
import time
from dataclasses import replace

import numpy as np

from lod2energy.cli import main
from lod2energy.model import Building
from lod2energy.repair import repair_features
from lod2energy.polymesh import Face, PolyMesh
from lod2energy.repair.alphashape import MAX_WRAP_AREA, alpha_wrap
from lod2energy.repair.plausible import MAX_EXTENT, implausible

from cityjson_docs import BOX_FACES, BOX_VERTICES, box_doc, write
from factories import box, open_box

FAR = -2_000_000.0  # m: a vertex 2,000 km below the others


def spike(id: str = "spike") -> Building:
    """The 10 x 8 x 6 m box with one ground corner 2,000 km down (still a closed shell)."""
    b = box(id=id)
    V = np.array(b.vertices)
    k = int(np.argmin(V.sum(axis=1)))  # the (0, 0, 0) corner
    V[k, 2] = FAR
    V.setflags(write=False)
    return replace(b, vertices=V)


def test_a_vertex_2000_km_away_is_irreparable_with_a_clear_message_and_the_batch_goes_on():
    out = list(repair_features([box(id="good"), spike(), open_box(id="open")], timeout=30.0))
    assert [b.id for b in out] == ["good", "spike", "open"]
    by = {b.id: b for b in out}
    r = by["spike"].provenance["repair"]
    assert r["stage"] == "irreparable"
    assert "coordinates implausible" in r["error"] and "2,000.0 km" in r["error"]
    assert "z from -2,000,000.0" in r["error"]
    (g,) = r["geometries"]
    assert g["stage"] == "irreparable" and g["log"] == [g["error"]]
    assert np.array_equal(by["spike"].vertices, spike().vertices)  # left as it is
    assert by["good"].provenance.get("repair", {"stage": "valid"})["stage"] == "valid"
    assert by["open"].provenance["repair"]["stage"] not in ("irreparable",)
    assert "error" not in by["open"].provenance["repair"]


def test_a_valid_but_kilometres_long_solid_is_reported_too():
    b = box(dx=MAX_EXTENT * 1.5, id="long")
    (r,) = list(repair_features([b]))
    rep = r.provenance["repair"]
    assert rep["stage"] == "irreparable" and "coordinates implausible" in rep["error"]
    # just under the limit it is an ordinary (valid) building
    (ok,) = list(repair_features([box(dx=MAX_EXTENT * 0.9, id="ok")]))
    assert ok.provenance.get("repair", {"stage": "valid"})["stage"] == "valid"


def test_non_finite_coordinates_are_irreparable_without_an_exception():
    b = box(id="nan")
    V = np.array(b.vertices)
    V[3, 1] = np.nan
    (r,) = list(repair_features([replace(b, vertices=V)]))
    rep = r.provenance["repair"]
    assert rep["stage"] == "irreparable" and "non-finite" in rep["error"]
    assert "Error:" not in rep["error"]  # not the catch-all exception record


def test_implausible_measures_the_largest_side():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    m = PolyMesh(V, (Face(((0, 2, 1),)), Face(((0, 1, 3),)), Face(((1, 2, 3),)), Face(((0, 3, 2),))))
    assert implausible(m) is None
    V2 = V.copy()
    V2[1, 0] = 7_500.0
    msg = implausible(PolyMesh(V2, m.faces))
    assert "7.5 km" in msg and "x from 0.0 to 7,500.0" in msg
    assert implausible(PolyMesh(V2, m.faces), max_extent=10_000.0) is None


def _open_box_mesh(L: float, W: float, H: float) -> PolyMesh:
    V = np.array([[0, 0, 0], [L, 0, 0], [L, W, 0], [0, W, 0], [0, 0, H], [L, 0, H], [L, W, H], [0, W, H]], float)
    faces = [(0, 3, 2, 1), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]  # no roof
    return PolyMesh(V, tuple(Face((f,), i) for i, f in enumerate(faces)))


def test_alpha_wrap_honours_the_deadline_and_the_area_limit():
    # an open 200 x 100 x 20 m box takes the wrap ~20 s (thin walls wrapped on both sides)
    m = _open_box_mesh(200.0, 100.0, 20.0)
    assert alpha_wrap(m, 8.0, deadline=time.monotonic() + 1.0) is None  # the child is killed
    big = _open_box_mesh(2_000.0, 1_000.0, 20.0)
    assert 2_000.0 * 1_000.0 > MAX_WRAP_AREA
    assert alpha_wrap(big, 8.0) is None  # no deadline: only the area limit stops it
    # a small wrap still works through the child process
    small = alpha_wrap(_open_box_mesh(10.0, 8.0, 6.0), 8.0, deadline=time.monotonic() + 30.0)
    assert small is not None and small.n_faces >= 4


def _two_building_doc() -> dict:
    """b1: the valid box; spike: the same box 20 m east with one corner 2,000 km down."""
    doc = box_doc()
    n = len(BOX_VERTICES)
    far = [[x + 20.0, y, z] for x, y, z in BOX_VERTICES]
    far[0][2] = FAR
    doc["vertices"] += [[int(round(x * 1000)), int(round(y * 1000)), int(round(z * 1000))] for x, y, z in far]
    obj = copy.deepcopy(doc["CityObjects"]["b1"])
    obj["geometry"][0]["boundaries"] = [[[[i + n for i in r] for r in f] for f in BOX_FACES]]
    doc["CityObjects"] = {"spike": obj, "b1": doc["CityObjects"]["b1"]}
    return doc


def test_export_reports_the_building_and_exports_the_others(tmp_path, capsys):
    src = write(tmp_path, _two_building_doc())
    out = tmp_path / "o"
    rc = main(["export", src, "-o", str(out), "--stl", "-q"])
    _, err = capsys.readouterr()
    assert rc == 1 and "Traceback" not in err
    assert "Building spike" in err and "coordinates implausible" in err
    rows = {r["id"]: r for r in csv.DictReader((out / "report.csv").open())}
    assert rows["spike"]["repair_stage"] == "irreparable" and "coordinates implausible" in rows["spike"]["message"]
    assert rows["spike"]["stl_ok"] == ""
    assert rows["spike"]["A_env_m2"] == "" and float(rows["b1"]["A_env_m2"]) > 0  # no absurd areas
    assert rows["b1"]["stl_ok"] == "True" and (out / "b1.stl").exists()
    rep = json.loads((out / "report.json").read_text())
    assert {b["id"] for b in rep["buildings"]} == {"b1", "spike"}
