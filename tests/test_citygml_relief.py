"""dem:TINRelief in CityGML: read into the terrain feature the CityJSON reader yields, and used
as the ground of a CFD case (``export --cfd``)."""
from __future__ import annotations

import json

import numpy as np
import pytest

from test_citygml import CORNERS, box_body, building, city_model, read_all, run_cli, write
from lod2energy.exporters.cfd.terrain import height_function, tin_of
from lod2energy.model import Building

DEM = "http://www.opengis.net/citygml/relief/2.0"
X0, Y0 = CORNERS[0][0], CORNERS[0][1]
SLOPE = (0.01, -0.02)


def z_of(x, y):
    """The test terrain: a plane through the box's ground corner, m."""
    return 34.0 + SLOPE[0] * (x - X0) + SLOPE[1] * (y - Y0)


def grid_points(n: int = 4, size: float = 200.0):
    xs = X0 - size / 2 + np.arange(n + 1) * size / n
    ys = Y0 - size / 2 + np.arange(n + 1) * size / n
    return [[(x, y, z_of(x, y)) for y in ys] for x in xs]


def pl(pts) -> str:
    return " ".join(repr(float(c)) for p in pts for c in p)


def triangulated(n: int = 4, patches: str = "trianglePatches") -> str:
    """A gml:TriangulatedSurface of 2 n^2 upward triangles over the grid (GML 3.1.1
    ``trianglePatches``, GML 3.2 ``patches``)."""
    g = grid_points(n)
    tris = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = g[i][j], g[i + 1][j], g[i + 1][j + 1], g[i][j + 1]
            for t in ((a, b, c), (a, c, d)):
                tris.append(f"<gml:Triangle><gml:exterior><gml:LinearRing><gml:posList>{pl(list(t) + [t[0]])}"
                            "</gml:posList></gml:LinearRing></gml:exterior></gml:Triangle>")
    return f"<gml:TriangulatedSurface><gml:{patches}>{''.join(tris)}</gml:{patches}></gml:TriangulatedSurface>"


def control_points(n: int = 4) -> str:
    """A gml:Tin given by its control points only."""
    pts = [p for row in grid_points(n) for p in row]
    return f'<gml:Tin><gml:controlPoint><gml:posList srsDimension="3">{pl(pts)}</gml:posList></gml:controlPoint></gml:Tin>'


def relief(tin: str, lod: int = 2) -> str:
    return (f'<dem:ReliefFeature xmlns:dem="{DEM}" gml:id="rf"><dem:lod>{lod}</dem:lod><dem:reliefComponent>'
            f'<dem:TINRelief gml:id="tin1"><dem:lod>{lod}</dem:lod><dem:tin>{tin}</dem:tin></dem:TINRelief>'
            "</dem:reliefComponent></dem:ReliefFeature>")


@pytest.mark.parametrize("tin,n_tri,gml", [(triangulated(), 32, "3.1.1"), (triangulated(patches="patches"), 32, "3.2"),
                                           (control_points(), 32, "3.2")])
def test_tin_relief_is_read_as_the_terrain_feature(tmp_path, tin, n_tri, gml):
    _, feats = read_all(write(tmp_path, city_model(building("B", box_body()), relief(tin), gml=gml)))
    assert [type(f).__name__ for f in feats] == ["Building", "Building"]
    b, t = feats
    assert (b.type, t.type, t.id) == ("Building", "TINRelief", "tin1")
    (g,) = t.objects[0].geometries
    assert (g.type, g.lod) == ("CompositeSurface", "2")
    assert not [i for i in t.provenance.get("input_errors", ())]
    v, tris = tin_of([b, t])
    assert len(tris) == n_tri
    # every triangle upward, and the height function is the plane
    P = v[tris]
    up = (P[:, 1, 0] - P[:, 0, 0]) * (P[:, 2, 1] - P[:, 0, 1]) - (P[:, 2, 0] - P[:, 0, 0]) * (P[:, 1, 1] - P[:, 0, 1])
    assert (up > 0).all()
    xy = np.array([[X0 + 5.0, Y0 + 4.0], [X0 - 60.0, Y0 + 70.0]])
    assert height_function((v, tris))(xy) == pytest.approx(z_of(xy[:, 0], xy[:, 1]), abs=1e-6)


def test_without_a_relief_there_is_no_terrain(tmp_path):
    _, feats = read_all(write(tmp_path, city_model(building("B", box_body()))))
    assert tin_of(feats) is None


def test_export_cfd_on_citygml_uses_the_tin_as_ground(tmp_path, capsys):
    src = write(tmp_path, city_model(building("B", box_body()), relief(triangulated())))
    out = tmp_path / "out"
    rc, _, err = run_cli(["export", src, "-o", str(out), "--cfd", "--centre", f"{X0 + 5},{Y0 + 4}", "--radius", "60", "-q"], capsys)
    assert rc == 0, err
    rep = json.loads((out / "report.json").read_text())
    text = json.dumps(rep)
    assert '"ground": "terrain"' in text
