"""Inputs built in code for the spine / executor tests: rows of boxes, a huge building, subsets."""
from __future__ import annotations

import json
from pathlib import Path

from cityjson_docs import BOX_FACES, BOX_SEMANTICS
from factories import millimetre_vertices


def _box_object(i: int, x0: float, y0: float, dx: float = 10.0, dy: float = 8.0, dz: float = 6.0,
                year: int = 1975) -> tuple[dict, list]:
    v = [[x0, y0, 0], [x0 + dx, y0, 0], [x0 + dx, y0 + dy, 0], [x0, y0 + dy, 0],
         [x0, y0, dz], [x0 + dx, y0, dz], [x0 + dx, y0 + dy, dz], [x0, y0 + dy, dz]]
    co = {"type": "Building", "attributes": {"yearOfConstruction": year},
          "geometry": [{"type": "Solid", "lod": "2.2", "boundaries": [BOX_FACES],
                        "semantics": BOX_SEMANTICS}]}
    return co, v


def row_of_boxes_seq(path: Path, n: int = 6, touching: bool = True, extra_lines: list[str] = ()) -> str:
    """CityJSONSeq of ``n`` boxes in a row (sharing walls when ``touching``: party walls)."""
    header = {"type": "CityJSON", "version": "2.0",
              "transform": {"scale": [0.001, 0.001, 0.001], "translate": [85000.0, 447000.0, 0.0]},
              "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
              "CityObjects": {}, "vertices": []}
    lines = [json.dumps(header)]
    step = 10.0 if touching else 14.0
    for i in range(n):
        co, v = _box_object(i, i * step, 0.0, dz=6.0 + (i % 3))
        lines.append(json.dumps({"type": "CityJSONFeature", "id": f"b{i}", "CityObjects": {f"b{i}": co},
                                 "vertices": [[round(c * 1000) for c in p] for p in v]}))
    lines.extend(extra_lines)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return str(path)


def huge_building_line(n: int = 129, id: str = "huge") -> str:
    """A CityJSONFeature line: a 10 m box tessellated into ``6 n^2`` quads (n=129: ~100,000
    faces), one quad missing (an open shell, so the repair has work to do)."""
    verts, vid = millimetre_vertices()

    L = 10.0
    faces = []
    h = L / n
    for axis in range(3):
        for side in (0.0, L):
            for i in range(n):
                for j in range(n):
                    a, b = i * h, j * h
                    quad = []
                    for (u, w) in ((a, b), (a + h, b), (a + h, b + h), (a, b + h)):
                        p = [0.0, 0.0, 0.0]
                        p[axis] = side
                        p[(axis + 1) % 3] = u
                        p[(axis + 2) % 3] = w
                        quad.append(vid(p))
                    if side == 0.0:
                        quad = quad[::-1]
                    faces.append([quad])
    faces.pop(len(faces) // 2)
    co = {"type": "Building", "attributes": {"yearOfConstruction": 1975},
          "geometry": [{"type": "MultiSurface", "lod": "2.2", "boundaries": faces}]}
    return json.dumps({"type": "CityJSONFeature", "id": id, "CityObjects": {id: co}, "vertices": verts})


def terraced_subset(src: Path, dst: Path, k: int = 6) -> str | None:
    """The ``k`` features of a CityJSONSeq tile nearest to the feature with the most
    neighbours within 5 cm (a terraced row: party walls), written as a CityJSONSeq."""
    import numpy as np
    lines = src.read_text(encoding="utf-8").splitlines()
    head, feats = lines[0], [ln for ln in lines[1:] if ln.strip()]
    boxes = []
    for ln in feats:
        v = np.asarray(json.loads(ln)["vertices"], dtype=float)
        boxes.append(np.concatenate([v.min(axis=0), v.max(axis=0)]) if len(v) else np.full(6, np.nan))
    boxes = np.array(boxes)
    gap = 0.05 / json.loads(head)["transform"]["scale"][0]
    counts = []
    for i, b in enumerate(boxes):
        touch = np.all(boxes[:, :2] <= b[3:5] + gap, axis=1) & np.all(boxes[:, 3:5] >= b[:2] - gap, axis=1)
        touch[i] = False
        counts.append(int(touch.sum()))
    if not counts or max(counts) == 0:
        return None
    b = boxes[int(np.argmax(counts))]
    c = (boxes[:, :2] + boxes[:, 3:5]) / 2
    d = np.linalg.norm(c - (b[:2] + b[3:5]) / 2, axis=1)
    pick = sorted(int(j) for j in np.argsort(d)[:k])
    dst.write_text("\n".join([head] + [feats[j] for j in pick]) + "\n", encoding="utf-8")
    return str(dst)


def tree_bytes(root: Path, skip=(".lod2energy",)) -> dict[str, bytes]:
    """Every file under ``root`` (relative path -> bytes), but the spool."""
    out = {}
    for p in sorted(root.rglob("*")):
        rel = p.relative_to(root)
        if p.is_file() and not any(part in skip for part in rel.parts):
            out[str(rel)] = p.read_bytes()
    return out
