"""The README's "Run a study" samples (attribute map and --buildings table) go through the real
parsers and the export of the bundled example, so the samples cannot rot."""
from __future__ import annotations

import csv
import json
import re
from pathlib import Path

from lod2energy.cli import main
from lod2energy.thermal.attributes import parse_map
from lod2energy.thermal.table import parse_buildings

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "delft_subset.city.jsonl"


def _block(lang: str) -> str:
    """The one ``lang`` code block of the README's "Run a study" section."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("## Run a study", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(rf"```{lang}\n(.*?)```", section, flags=re.S)
    assert len(blocks) == 1, f"README 'Run a study': {len(blocks)} {lang} blocks"
    return blocks[0]


def test_the_readme_samples_parse():
    amap = parse_map(_block("toml"), "README.md", "readme")
    assert amap.name == "my-city"
    assert {"year", "storeys", "use", "conditioned"} <= set(amap.fields)
    assert amap.field("use").translate("woonfunctie") is not None
    rows = parse_buildings(_block("csv"), "README.md")
    assert len(rows) == 3 and all(r for r in rows.values())


def test_the_readme_samples_steer_the_bundled_example(tmp_path, capsys):
    (tmp_path / "city.toml").write_text(_block("toml"), encoding="utf-8")
    (tmp_path / "buildings.csv").write_text(_block("csv"), encoding="utf-8")
    rows = parse_buildings(_block("csv"), "README.md")
    out = tmp_path / "study"
    assert main(["export", str(EXAMPLE), "-o", str(out), "--geojson", "--no-html", "-q", "-j", "1",
                 "--attribute-map", str(tmp_path / "city.toml"),
                 "--buildings", str(tmp_path / "buildings.csv")]) in (0, 1)
    study = json.loads((out / "report.json").read_text())["study"]
    assert study["attribute_map"] == "my-city" and study["buildings_table"] == {"rows": len(rows)}
    assert not study.get("buildings_table_not_in_input"), "the README's ids are the example's"
    with open(out / "report.csv", newline="", encoding="utf-8") as f:
        report = {r["id"]: r for r in csv.DictReader(f)}
    for bid, row in rows.items():
        for col, value in row.items():
            if col in ("year", "storeys", "use", "conditioned"):
                got = report[bid][col]
                assert got.lower() == str(value).lower() and report[bid][f"{col}_source"] == "table", (bid, col)
    others = [r for bid, r in report.items() if bid not in rows]
    assert others and all(r["year_source"] == "map" for r in others)  # the map's year attribute
