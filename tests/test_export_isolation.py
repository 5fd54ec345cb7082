"""One building the IDF writer cannot take never stops the export of the others."""
from __future__ import annotations

import copy
import csv

from cityjson_docs import BOX_FACES, BOX_VERTICES, box_doc, write
from lod2energy.cli import main
from lod2energy.exporters import energyplus


def _two_boxes() -> dict:
    doc = box_doc()
    n = len(BOX_VERTICES)
    doc["vertices"] += [[int(round((x + 30.0) * 1000)), int(round(y * 1000)), int(round(z * 1000))]
                        for x, y, z in BOX_VERTICES]
    obj = copy.deepcopy(doc["CityObjects"]["b1"])
    obj["geometry"][0]["boundaries"] = [[[[i + n for i in r] for r in f] for f in BOX_FACES]]
    doc["CityObjects"]["bad"] = obj
    return doc


def test_writer_failure_is_reported_per_building(tmp_path, monkeypatch, capsys):
    real = energyplus.writer.write

    def picky(buildings, *args, **kw):
        if any(b.id == "bad" for b in buildings):
            raise ValueError("synthetic writer failure")
        return real(buildings, *args, **kw)
    monkeypatch.setattr(energyplus.writer, "write", picky)
    src = write(tmp_path, _two_boxes())
    out = tmp_path / "o"
    rc = main(["export", src, "-o", str(out), "--idf", "-q"])
    _, err = capsys.readouterr()
    assert rc == 1 and "Traceback" not in err and "synthetic writer failure" in err
    rows = {r["id"]: r for r in csv.DictReader((out / "report.csv").open())}
    assert rows["bad"]["idf_ok"] == "False"
    assert rows["b1"]["idf_ok"] == "True" and (out / "b1.idf").exists()
