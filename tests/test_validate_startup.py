"""What ``lod2energy validate`` loads (issue 13): a CityJSON file in a projected CRS does not load
the export-side modules (``lod2energy.reports`` and its records, options, spool); they load once
a file needs them.
"""
from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import pytest

_CUBE = [[0, 0, 0], [1000, 0, 0], [1000, 1000, 0], [0, 1000, 0],
         [0, 0, 1000], [1000, 0, 1000], [1000, 1000, 1000], [0, 1000, 1000]]
_FACES = [[[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]]]


def _city(path, epsg: int, parts: int = 1) -> str:
    """A CityJSON file of one Building of ``parts`` unit-cube BuildingParts side by side (+0.5 m)."""
    verts, objs = [], {"b": {"type": "Building", "children": []}}
    for k in range(parts):
        off = len(verts)
        verts += [[x + 500 * k, y, z] for x, y, z in _CUBE]
        objs["b"]["children"].append(f"p{k}")
        objs[f"p{k}"] = {"type": "BuildingPart", "parents": ["b"], "geometry": [{
            "type": "Solid", "lod": "2.2",
            "boundaries": [[[[i + off for i in r] for r in f] for f in _FACES]]}]}
    doc = {"type": "CityJSON", "version": "2.0", "CityObjects": objs, "vertices": verts,
           "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0.0, 0.0, 0.0]},
           "metadata": {"referenceSystem": f"https://www.opengis.net/def/crs/EPSG/0/{epsg}"}}
    path.write_text(json.dumps(doc), encoding="utf-8")
    return str(path)


def _loaded_by_validate(path: str, tmp_path) -> set[str]:
    probe = textwrap.dedent(f"""
        import json, sys
        from lod2energy.cli import main
        rc = main(["validate", {path!r}, "-q", "--report", {str(tmp_path / "r.json")!r}])
        print(json.dumps([rc] + sorted(m for m in sys.modules
                                       if m in ("lod2energy.reports", "lod2energy.records", "lod2energy.run.spool"))))
    """)
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    rc, *mods = json.loads(out.stdout.strip().splitlines()[-1])
    return rc, set(mods)


def test_validate_of_a_plain_file_loads_no_export_modules(tmp_path):
    rc, loaded = _loaded_by_validate(_city(tmp_path / "one.city.json", 7415), tmp_path)
    assert rc == 0
    assert loaded == set(), loaded
    rep = json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))
    assert rep["validity"] is True and "local_frame" not in rep


@pytest.mark.parametrize("parts, epsg, want", [
    (1, 4979, {"lod2energy.reports", "lod2energy.records", "lod2energy.run.spool"}),  # geographic: local frame
])
def test_they_load_when_the_file_needs_them(tmp_path, parts, epsg, want):
    rc, loaded = _loaded_by_validate(_city(tmp_path / "f.city.json", epsg, parts), tmp_path)
    assert want <= loaded, loaded
    if epsg == 4979:
        rep = json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))
        assert "local_frame" in rep
