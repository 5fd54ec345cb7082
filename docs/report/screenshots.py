"""Screenshots of report.html for the must-show tiles (first screen, plan view, one building panel).

Usage (from the repository root, after ``lod2energy export TILE -o OUT/NAME --stl -q``)::

    python docs/report/screenshots.py OUT NAME [NAME ...]

writes ``OUT/NAME/report.html`` by :func:`lod2energy.viz.view.write_report_for` (re-preparing only
the buildings that get a panel) and ``docs/report/NAME-{first,plan,panel}.png`` from a headless
Chromium (PNG, each < 300 KB), and prints the timings.
"""
from __future__ import annotations

import io
import sys
from pathlib import Path

from PIL import Image

from lod2energy.safe_write import write_bytes
from lod2energy.viz.view import write_report_for

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "tests"))
from chromium import open_page  # noqa: E402 - the tests' headless Chromium


def small_png(png: bytes, limit: int = 300_000) -> bytes:
    """``png`` re-encoded under ``limit`` bytes: as it is, else as a 256-colour palette PNG
    (octree: rare legend colours survive), else scaled down."""
    img = Image.open(io.BytesIO(png)).convert("RGB")
    buf = io.BytesIO()
    img.save(buf, "PNG", optimize=True)
    while buf.tell() >= limit and img.width >= 400:
        buf = io.BytesIO()
        img.quantize(colors=256, method=Image.Quantize.FASTOCTREE).save(buf, "PNG", optimize=True)
        img = img.resize((img.width * 3 // 4, img.height * 3 // 4), Image.LANCZOS)
    return buf.getvalue()


def shoot(out: Path, name: str) -> None:
    page, t = write_report_for(out / name / "report.json")
    print(name, "timings (s):", t, flush=True)
    with open_page(page, 1280, 860) as (p, log):
        assert not (log.console_errors or log.page_errors or log.blocked), log
        write_bytes(HERE / f"{name}-first.png", small_png(p.screenshot()), root=HERE)
        write_bytes(HERE / f"{name}-plan.png", small_png(p.locator("#planview").screenshot()), root=HERE)
        write_bytes(HERE / f"{name}-panel.png", small_png(p.locator(".panel").first.screenshot()), root=HERE)


if __name__ == "__main__":
    for n in sys.argv[2:]:
        shoot(Path(sys.argv[1]), n)
