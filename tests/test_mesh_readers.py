"""POLY / OBJ / OFF readers, tu3djson and JSON-FG readers, on tiny files and val3dity's test files."""
from __future__ import annotations

import numpy as np
import pytest

from lod2energy.io import format_of, read
from lod2energy.model import Building, FeatureError
from lod2energy.validate.checks import validate_building

CUBE_V = ["0 0 0", "1 0 0", "1 1 0", "0 1 0", "0 0 1", "1 0 1", "1 1 1", "0 1 1"]
CUBE_F = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def _write(tmp_path, name, text) -> str:
    p = tmp_path / name
    p.write_text(text)
    return str(p)


def _one(path, **opts):
    model, feats = read(path, **opts)
    feats = list(feats)
    return model, feats


def _codes(feats) -> list[int]:
    codes = set()
    for f in feats:
        if isinstance(f, FeatureError):
            codes.add(f.code)
        else:
            codes.update(d.code for d in validate_building(f))
    return sorted(codes)


def cube_obj(faces=CUBE_F) -> str:
    return "\n".join([f"v {v}" for v in CUBE_V] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]) + "\n"


def cube_off(faces=CUBE_F) -> str:
    return "\n".join(["OFF", f"8 {len(faces)} 0"] + CUBE_V + [f"{len(f)} " + " ".join(map(str, f)) for f in faces]) + "\n"


def cube_poly(faces=CUBE_F) -> str:
    lines = ["8 3 0 0"] + [f"{i} {v}" for i, v in enumerate(CUBE_V)] + [f"{len(faces)} 0"]
    for f in faces:
        lines += ["1 0", f"{len(f)} " + " ".join(map(str, f))]
    return "\n".join(lines + ["0", "0"]) + "\n"


def test_formats_registered():
    assert format_of("a.poly") == "POLY"
    assert format_of("a.OBJ") == "OBJ"
    assert format_of("a.off") == "OFF"


@pytest.mark.parametrize("name,text", [("cube.obj", cube_obj()), ("cube.off", cube_off()), ("cube.poly", cube_poly())])
def test_valid_cube_in_each_format(tmp_path, name, text):
    model, feats = _one(_write(tmp_path, name, text))
    (b,) = feats
    assert isinstance(b, Building) and b.id == "cube" and b.type == "GenericCityObject"
    g = b.objects[0].geometries[0]
    assert g.type == "Solid" and g.n_surfaces == 6 and b.vertices.shape == (8, 3)
    assert model.format == name.split(".")[1].upper()
    assert _codes(feats) == []


@pytest.mark.parametrize("primitive", ["MultiSurface", "CompositeSurface"])
def test_primitive_option(tmp_path, primitive):
    _, (b,) = _one(_write(tmp_path, "c.off", cube_off()), primitive=primitive)
    assert b.objects[0].geometries[0].type == primitive


def test_bad_primitive_and_inner_shells_on_surface_are_903(tmp_path):
    p = _write(tmp_path, "c.poly", cube_poly())
    assert [f.code for f in _one(p, primitive="Polyhedron")[1]] == [903]
    assert [f.code for f in _one(p, primitive="CompositeSurface", inner_shells=[p])[1]] == [903]


def test_poly_inner_shell_becomes_interior_shell(tmp_path):
    outer = _write(tmp_path, "outer.poly", cube_poly())
    small = "\n".join(["8 3 0 0"] + [f"{i} " + " ".join(str(0.25 + 0.5 * float(c)) for c in v.split())
                                    for i, v in enumerate(CUBE_V)] + ["6 0"]
                      + sum((["1 0", "4 " + " ".join(map(str, f[::-1]))] for f in CUBE_F), []) + ["0", "0"])
    inner = _write(tmp_path, "inner.poly", small + "\n")
    _, (b,) = _one(outer, inner_shells=[inner])
    solid = b.objects[0].geometries[0].solids[0]
    assert len(solid.shells) == 2 and b.vertices.shape == (16, 3)
    assert int(solid.shells[1].surfaces[0].outer.min()) >= 8


def test_poly_facet_with_hole_and_hole_points(tmp_path):
    text = "\n".join(["8 3 0 0", "0 0 0 0", "1 1 0 0", "2 1 1 0", "3 0 1 0",
                      "4 .2 .2 0", "5 .8 .2 0", "6 .8 .8 0", "7 .2 .8 0",
                      "2 0", "2 1 0", "4 0 1 2 3", "4 4 7 6 5", "1 0.5 0.5 0",
                      "1 0", "3 0 1 2", "0", "0"]) + "\n"
    _, (b,) = _one(_write(tmp_path, "h.poly", text), primitive="MultiSurface")
    faces = b.objects[0].geometries[0].solids[0].shells[0].surfaces
    assert [len(s.rings) for s in faces] == [2, 1]
    assert faces[0].rings[1].tolist() == [4, 7, 6, 5]


def test_poly_unclosed_ring_marker_is_103(tmp_path):
    text = cube_poly().replace("1 0\n4 0 3 2 1", "1 0\n-1", 1)
    _, feats = _one(_write(tmp_path, "u.poly", text))
    assert 103 in _codes(feats)


@pytest.mark.parametrize("name,text,code", [
    ("zero.obj", cube_obj().replace("f 1 4 3 2", "f 1 4 3 0"), 901),
    ("past.obj", cube_obj().replace("f 1 4 3 2", "f 1 4 3 9"), 901),
    ("noface.obj", "\n".join(f"v {v}" for v in CUBE_V) + "\n", 902),
    ("empty.obj", "", 902),
    ("empty.off", "", 901),
    ("novert.off", "OFF\n0 0 0\n", 901),
    ("emptyface.off", cube_off().replace("4 0 3 2 1", "0"), 901),
    ("badindex.off", cube_off().replace("4 0 3 2 1", "4 0 3 2 8"), 901),
    ("text.poly", "hello world\n", 901),
    ("short.poly", "8 3 0 0\n0 0 0 0\n", 901),
    ("badindex.poly", cube_poly().replace("4 0 3 2 1", "4 0 3 2 8"), 901),
])
def test_bad_files_are_reported_not_raised(tmp_path, name, text, code):
    model, feats = _one(_write(tmp_path, name, text))
    assert model is None and [(f.id, f.code) for f in feats] == [(None, code)]
    assert "\n" not in feats[0].message


def test_missing_file_is_901(tmp_path):
    for suffix in (".poly", ".obj", ".off"):
        assert [f.code for f in _one(str(tmp_path / f"nope{suffix}"))[1]] == [901]


def test_empty_poly_primitive_is_902(tmp_path):
    text = "\n".join(["8 3 0 0"] + [f"{i} {v}" for i, v in enumerate(CUBE_V)] + ["0 0", "0", "0"]) + "\n"
    assert _codes(_one(_write(tmp_path, "e.poly", text))[1]) == [902]


def test_obj_groups_give_one_geometry_each_and_extras_are_ignored(tmp_path):
    text = ("# a comment\no first\n" + cube_obj() + "vn 0 0 1\no second\n"
            + "\n".join("f " + " ".join(f"{i + 1}//1" for i in f) for f in CUBE_F) + "\n")
    _, (b,) = _one(_write(tmp_path, "two.obj", text))
    assert [g.type for g in b.objects[0].geometries] == ["Solid", "Solid"]
    assert _codes([b]) == []


def test_obj_negative_indices_and_line_continuation(tmp_path):
    text = "\n".join(f"v {v}" for v in CUBE_V) + "\n"
    text += "\n".join("f " + " ".join(str(i - 8) for i in f) for f in CUBE_F[:5]) + "\n"
    text += "f 4 1 \\\n 5 8\n"
    _, (b,) = _one(_write(tmp_path, "neg.obj", text))
    faces = b.objects[0].geometries[0].solids[0].shells[0].surfaces
    assert [s.outer.tolist() for s in faces] == CUBE_F
    assert _codes([b]) == []


def test_off_with_comments_and_header_on_one_line(tmp_path):
    text = cube_off().replace("OFF\n8 6 0", "OFF 8 6 0 # counts").replace("0 0 0\n", "0 0 0 # origin\n", 1)
    assert _codes(_one(_write(tmp_path, "c.off", text))[1]) == []


def test_reading_does_not_merge_vertices(tmp_path):
    text = cube_off().replace("8 6 0", "9 6 0").replace("0 1 1\n", "0 1 1\n0 1 1\n", 1)
    _, (b,) = _one(_write(tmp_path, "dup.off", text))
    assert b.vertices.shape == (9, 3)


# ----------------------------------------------------------------------------- tu3djson / JSON-FG

def test_tu3djson_features(val3dity_suite):
    model, feats = _one(str(val3dity_suite / "test_tu3djson" / "cube.json"))
    assert model.format == "tu3djson"
    assert [f.id for f in feats] == [str(i) for i in range(len(feats))]
    assert all(isinstance(f, Building) for f in feats)


def test_jsonfg_rings_closing_point_dropped_and_vertices_shared(val3dity_suite):
    model, feats = _one(str(val3dity_suite / "test_jsonfg" / "cubes.fg.json"))
    assert model.format == "JSON-FG"
    cube = feats[0]
    assert cube.id == "a cube" and cube.vertices.shape == (8, 3)
    assert all(len(s.outer) == 4 for s in cube.objects[0].geometries[0].solids[0].shells[0].surfaces)
    assert feats[1].objects[0].geometries[0].type == "MultiSolid"


def test_jsonfg_open_ring_103_and_plain_geojson_904(val3dity_suite):
    _, feats = _one(str(val3dity_suite / "test_jsonfg" / "e103.fg.json"))
    assert _codes(feats) == [103]
    _, feats = _one(str(val3dity_suite / "test_jsonfg" / "geojson.json"))
    assert [f.code for f in feats] == [904]


def test_json_sniffing_keeps_cityjson(val3dity_suite):
    model, _ = _one(str(val3dity_suite / "test_cityjson" / "cube_v11.city.json"))
    assert model.format == "CityJSON"


def test_val3dity_poly_holes_parse(val3dity_suite):
    _, (b,) = _one(str(val3dity_suite / "parse_poly" / "parse_ok1.poly"), primitive="MultiSurface")
    (face,) = b.objects[0].geometries[0].solids[0].shells[0].surfaces
    assert [r.tolist() for r in face.rings] == [[0, 3, 2, 1], [4, 5, 6, 7]]
    assert np.allclose(b.vertices[4], [0.2, 0.2, 0.0])


def test_json_sniffing_skips_non_document_types(tmp_path):
    import json
    doc = {"links": [{"type": "application/geo+json", "href": "x"}], "type": "Feature",
           "geometry": {"type": "Point", "coordinates": [0, 0]}}
    p = _write(tmp_path, "f.json", json.dumps(doc))
    model, feats = _one(p)
    assert model.format == "JSON-FG" and [f.code for f in feats] == [904]


def test_off_colours_at_line_ends_are_ignored(tmp_path):
    text = cube_off().replace("0 0 0\n", "0 0 0 255 0 0\n", 1).replace("4 0 3 2 1", "4 0 3 2 1 255 255 0")
    _, (b,) = _one(_write(tmp_path, "col.off", text))
    assert [s.outer.tolist() for s in b.objects[0].geometries[0].solids[0].shells[0].surfaces] == CUBE_F


# ----------------------------------------------------------------------------- round trips

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

coords = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(coords, coords, coords), min_size=3, max_size=12), st.data())
def test_write_read_round_trip_all_formats(tmp_path_factory, verts, data):
    n = len(verts)
    faces = data.draw(st.lists(st.lists(st.integers(0, n - 1), min_size=3, max_size=6), min_size=1, max_size=5))
    d = tmp_path_factory.mktemp("rt")
    vtxt = [" ".join(repr(c) for c in v) for v in verts]
    obj = "\n".join([f"v {t}" for t in vtxt] + ["f " + " ".join(str(i + 1) for i in f) for f in faces])
    off = "\n".join(["OFF", f"{n} {len(faces)} 0"] + vtxt + [f"{len(f)} " + " ".join(map(str, f)) for f in faces])
    poly = "\n".join([f"{n} 3 0 0"] + [f"{i} {t}" for i, t in enumerate(vtxt)] + [f"{len(faces)} 0"]
                     + sum((["1 0", f"{len(f)} " + " ".join(map(str, f))] for f in faces), []) + ["0", "0"])
    for name, text in (("m.obj", obj), ("m.off", off), ("m.poly", poly)):
        _, (b,) = _one(_write(d, name, text + "\n"), primitive="MultiSurface")
        assert np.array_equal(b.vertices, np.asarray(verts, float))
        got = [s.outer.tolist() for s in b.objects[0].geometries[0].solids[0].shells[0].surfaces]
        assert got == faces
