"""The report's plots (matplotlib, Agg): stage distribution, IoU / displacement, compliance, validity, heating.

Each ``plot_*`` takes the numbers of :mod:`lod2energy.viz.data` (the same numbers the page
embeds as JSON) and returns an SVG data URL (an ``<img>`` source: its ids never clash with
the page's), or ``""`` when there is nothing to plot.
"""
from __future__ import annotations

import base64
import io

import numpy as np

from lod2energy.viz.data import GLOBAL, STATUS_COLOURS

BAR = "#4a7fb5"
AFTER = "#1a9850"
BEFORE = "#d73027"


def new_figure(w: float, h: float, **adjust):
    """A matplotlib Figure on an Agg canvas (no pyplot, no display), ``w x h`` inches; fixed
    margins (``subplotpars``: left, right, bottom, top, wspace) instead of a layout engine."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    pars = dict(left=0.11, right=0.98, bottom=0.24, top=0.88, wspace=0.3)
    pars.update(adjust)
    fig = Figure(figsize=(w, h))
    fig.subplots_adjust(**pars)
    FigureCanvasAgg(fig)
    return fig


def _url(fig) -> str:
    """``data:image/svg+xml;base64,...`` of a plot (text kept as text: small and fast)."""

    from matplotlib import rc_context
    buf = io.BytesIO()
    with rc_context({"svg.fonttype": "none", "svg.hashsalt": "lod2energy"}):
        fig.savefig(buf, format="svg", metadata={"Date": None})  # no timestamp: same bytes every run
    return "data:image/svg+xml;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def _label_bars(ax, bars, values) -> None:
    for b, v in zip(bars, values):
        ax.annotate(str(v), (b.get_x() + b.get_width() / 2, b.get_height()), ha="center", va="bottom",
                    fontsize=7, xytext=(0, 1), textcoords="offset points")


def plot_stages(stages: dict) -> str:
    """Buildings per repair stage (the method's Figure 10)."""
    if not stages:
        return ""
    fig = new_figure(5.2, 2.6, left=0.13, bottom=0.3)
    ax = fig.add_subplot()
    names, vals = list(stages), list(stages.values())
    cols = [STATUS_COLOURS["valid"] if s == "valid" else STATUS_COLOURS["irreparable"] if s == "irreparable"
            else STATUS_COLOURS["repaired globally"] if s in GLOBAL
            else STATUS_COLOURS["repaired locally"] for s in names]
    bars = ax.bar(names, vals, color=cols)
    _label_bars(ax, bars, vals)
    ax.set_ylabel("buildings")
    ax.set_ylim(0, max(vals) * 1.12)
    ax.set_title("buildings per repair stage", fontsize=9)
    ax.tick_params(axis="x", labelsize=7)
    for t in ax.get_xticklabels():
        t.set_rotation(30)
        t.set_ha("right")
    return _url(fig)


def plot_histograms(iou: dict, disp: dict) -> str:
    """IoU and mean displacement of the repaired buildings (the method's Figure 11)."""
    if not iou.get("n") and not disp.get("n"):
        return ""
    fig = new_figure(7.4, 2.6, left=0.09, right=0.97, bottom=0.3, wspace=0.5)
    for k, (h, title, xl) in enumerate(((iou, "IoU input vs repaired", "IoU"),
                                        (disp, "mean vertex displacement", "m (bin index; edges below)"))):
        ax = fig.add_subplot(1, 2, k + 1)
        counts = h.get("counts", [])
        if k == 0:
            e = np.asarray(h["edges"])
            ax.bar(e[:-1], counts, width=np.diff(e), align="edge", color=BAR, edgecolor="white")
            nz = np.nonzero(counts)[0]
            ax.set_xlim(float(e[max(int(nz[0]) - 1, 0)]) if len(nz) else 0.0, 1.0)
            ax.set_xlabel(xl, fontsize=8)
        else:
            bars = ax.bar(range(len(counts)), counts, color=BAR, edgecolor="white")
            ax.set_xticks(range(len(counts)))
            ax.set_xticklabels([f"{a:g}-{b:g}" for a, b in zip(h["edges"][:-1], h["edges"][1:])],
                               fontsize=6, rotation=45)
            ax.set_xlabel("m", fontsize=8)
            _label_bars(ax, bars, counts)
        ax.set_title(f"{title} (n={h.get('n', 0)})", fontsize=9)
        ax.set_ylabel("buildings", fontsize=8)
    return _url(fig)


def plot_compliance(comp: dict) -> str:
    """Energy-compliant buildings before / after, and per compliance condition after."""
    if not comp.get("total"):
        return ""
    fig = new_figure(6.4, 2.5)
    ax = fig.add_axes([0.08, 0.12, 0.25, 0.76])
    vals = [comp["before"], comp["after"]]
    bars = ax.bar(["before", "after"], vals, color=[BEFORE, AFTER])
    ax.axhline(comp["total"], color="#555555", lw=0.8, ls="--")
    _label_bars(ax, bars, vals)
    ax.set_title(f"compliant of {comp['total']}", fontsize=9)
    conds = comp.get("conditions") or {}
    if conds:
        ax2 = fig.add_axes([0.6, 0.12, 0.33, 0.76])
        bars = ax2.barh(list(conds), list(conds.values()), color=AFTER)
        ax2.set_xlim(0, comp["total"] * 1.15)
        for b, v in zip(bars, conds.values()):
            ax2.annotate(str(v), (b.get_width(), b.get_y() + b.get_height() / 2), va="center", fontsize=7,
                         xytext=(2, 0), textcoords="offset points")
        ax2.tick_params(axis="y", labelsize=7)
        ax2.set_title("conditions met (after)", fontsize=9)
    return _url(fig)


def plot_validity(by_code: dict) -> str:
    """Buildings per val3dity code before / after."""
    if not by_code:
        return ""
    codes = list(by_code)
    b = [by_code[c][0] for c in codes]
    a = [by_code[c][1] for c in codes]
    fig = new_figure(max(3.5, 0.55 * len(codes) + 1.5), 2.5, left=0.16)
    ax = fig.add_subplot()
    x = np.arange(len(codes))
    _label_bars(ax, ax.bar(x - 0.2, b, 0.4, color=BEFORE, label="before"), b)
    _label_bars(ax, ax.bar(x + 0.2, a, 0.4, color=AFTER, label="after"), a)
    ax.set_xticks(x)
    ax.set_xticklabels(codes, fontsize=7)
    ax.set_ylabel("buildings", fontsize=8)
    ax.legend(fontsize=7)
    ax.set_title("buildings per val3dity error code", fontsize=9)
    return _url(fig)


def plot_heating(by_typ: dict) -> str:
    """Mean simulated heating need per m2 of floor by typology."""
    if not by_typ:
        return ""
    fig = new_figure(5.0, 2.6, left=0.14, bottom=0.3)
    ax = fig.add_subplot()
    names = list(by_typ)
    vals = [by_typ[k][0] for k in names]
    bars = ax.bar(names, vals, color="#e6550d")
    _label_bars(ax, bars, [f"{v:.0f} (n={by_typ[k][1]})" for v, k in zip(vals, names)])
    ax.set_ylabel("kWh/m2 a", fontsize=8)
    ax.tick_params(axis="x", labelsize=7, rotation=20)
    ax.set_title("heating need per m2 by typology", fontsize=9)
    return _url(fig)
