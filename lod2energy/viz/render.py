"""Pictures of buildings: footprints for the plan view, axonometric renders and the face-adjacency graph.

Geometry is projected by a fixed orthographic axonometry (:func:`project`) and drawn with
matplotlib (Agg) as shaded polygons in depth order; the face-adjacency graph is drawn in the
same projection over a faint copy of the building, as the method draws it (its Figure 5): a
node per face at the face's centroid, valid and defective faces, boundary and non-manifold
mesh edges in the colours of :data:`GRAPH_COLOURS`. Renders are cached by geometry digest, so
an unchanged (valid) building is drawn once for its input and output.
"""
from __future__ import annotations

import base64
import hashlib
import io
import re

import numpy as np
from markupsafe import escape

from lod2energy import cache
from lod2energy.config import DEFAULT, Tolerances
from lod2energy.geometry.polygons import newell_normal
from lod2energy.geometry.vectors import unit
from lod2energy.graph import building_graphs
from lod2energy.model import Building
from lod2energy.viz.figures import new_figure

#: Colours of the graph picture (the method's Figure 5 legend: valid faces, defective faces,
#: non-manifold edges, boundary edges; adjacencies in grey).
GRAPH_COLOURS = {"valid_face": "#1a9850", "defective_face": "#d73027", "nonmanifold_edge": "#7b3294",
                 "boundary_edge": "#fd8d3c", "adjacency": "#9e9e9e", "inconsistent_adjacency": "#d73027"}
#: Fill colour per semantic surface type of the renders.
SURFACE_COLOURS = {"RoofSurface": "#c0504d", "WallSurface": "#e6e0d4", "GroundSurface": "#6e6e6e",
                   "ClosureSurface": "#9fc5e8", None: "#b7c4cf"}
AZIMUTH, ELEVATION = np.radians(-55.0), np.radians(30.0)
LIGHT = np.array([0.35, -0.55, 0.76])


# --- faces and footprints -------------------------------------------------------------------------

def faces(b: Building, lod: str | None = None) -> list[tuple[np.ndarray, str | None]]:
    """Outer rings of the envelope faces at ``lod`` as ``[((k, 3) coordinates m, semantic type)]``.

    Falls back to every polygonal shell of the building when it has no envelope at ``lod``.
    """
    refs = b.shells(lod) or b.all_shells()
    out = []
    for r in refs:
        for s in r.shell.surfaces:
            if len(s.outer) >= 3:
                out.append((b.vertices[s.outer], r.geometry.semantic_type(s)))
    return out


def footprint(b: Building) -> list[np.ndarray]:
    """Plan footprint as rings ``[(k, 2) float, m]``: the ground faces projected on the ground
    plane; else the downward faces; else the convex hull of the vertices. Empty when the
    building has no usable geometry. Drawn as one SVG path (no polygon union needed)."""
    refs = b.shells() or b.all_shells()
    V = b.vertices
    rings = [V[s.outer][:, :2] for r in refs for s in r.shell.surfaces
             if len(s.outer) >= 3 and r.geometry.semantic_type(s) == "GroundSurface"]
    if rings:
        return rings
    fs = faces(b)
    rings = [p[:, :2] for p, _ in fs if unit(newell_normal(p))[2] < -0.7]
    if rings or not fs:
        return rings
    pts = np.vstack([p for p, _ in fs])[:, :2]
    try:
        from scipy.spatial import ConvexHull
        return [pts[ConvexHull(pts).vertices]]
    except Exception:  # noqa: BLE001 - collinear or too few points: nothing to draw
        return []


def _svg_path(rings: list[np.ndarray], x0: float, y1: float, s: float) -> str:
    """SVG path data of rings, y flipped (north up)."""
    parts = []
    for c in rings:
        q = np.column_stack([(c[:, 0] - x0) * s, (y1 - c[:, 1]) * s])
        parts.append("M" + " ".join(f"{x:.1f},{y:.1f}" for x, y in q) + "Z")
    return "".join(parts)


def plan_svg(items: list[dict], width: float = 900.0) -> str:
    """Inline SVG plan view of the tile.

    Parameters
    ----------
    items : list of dict
        ``{"id", "footprint" (rings, see :func:`footprint`), "fill" (CSS colour), "status", "href" (or None),
        "title"}`` per building, plus ``"value"`` (heating need, kWh/m2) and ``"fill2"`` (its
        colour) when simulated.
    width : float
        Width of the picture, px.
    """
    items = [it for it in items if len(it.get("footprint") or ())]
    if not items:
        return ""
    bounds = np.array([np.concatenate([np.vstack(it["footprint"]).min(axis=0), np.vstack(it["footprint"]).max(axis=0)])
                       for it in items])
    x0, y0 = bounds[:, 0].min(), bounds[:, 1].min()
    x1, y1 = bounds[:, 2].max(), bounds[:, 3].max()
    span = max(x1 - x0, y1 - y0, 1e-6)
    s = width / span
    w, h = (x1 - x0) * s, (y1 - y0) * s
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" id="plan" viewBox="-4 -4 {w + 8:.0f} {h + 8:.0f}" '
           f'width="{w + 8:.0f}" height="{h + 8:.0f}" role="img" aria-label="plan view">']
    for it in items:
        d = _svg_path(it["footprint"], x0, y1, s)
        if not d:
            continue
        attrs = (f'class="fp" data-id="{escape(it["id"])}" data-status="{escape(it["status"])}" '
                 f'fill="{it["fill"]}"')
        if it.get("value") is not None:
            attrs += f' data-value="{it["value"]:.3f}" data-heat-fill="{it["fill2"]}"'
        shape = f'<path d="{d}" {attrs}><title>{escape(it.get("title", it["id"]))}</title></path>'
        if it.get("href"):
            shape = f'<a href="{escape(it["href"])}">{shape}</a>'
        out.append(shape)
    out.append("</svg>")
    return "".join(out)


# --- projection and renders ------------------------------------------------------------------------

def project(points: np.ndarray, azim: float = AZIMUTH, elev: float = ELEVATION) -> tuple[np.ndarray, np.ndarray]:
    """Orthographic axonometric projection.

    Parameters
    ----------
    points : (n, 3) float, m

    Returns
    -------
    xy : (n, 2) float
        Picture coordinates, m.
    depth : (n,) float
        Distance along the view direction (larger is nearer the viewer), m.
    """
    p = np.asarray(points, float)
    ca, sa, ce, se = np.cos(azim), np.sin(azim), np.cos(elev), np.sin(elev)
    x = p[:, 0] * ca - p[:, 1] * sa
    yv = p[:, 0] * sa + p[:, 1] * ca
    y = p[:, 2] * ce - yv * se
    depth = yv * ce + p[:, 2] * se
    return np.column_stack([x, y]), depth


def _shade(hex_colour: str, n: np.ndarray) -> tuple[float, float, float]:
    from matplotlib.colors import to_rgb
    k = 0.55 + 0.45 * abs(float(np.dot(n, LIGHT / np.linalg.norm(LIGHT))))
    return tuple(min(1.0, c * k) for c in to_rgb(hex_colour))


class Canvas:
    """Where a drawing goes: a figure region mapped from picture coordinates (m) to pixels.

    Artists are added to the figure itself with an affine transform (no matplotlib Axes:
    their ticks and layout cost more than the drawing).
    """

    def __init__(self, fig, box: tuple[float, float, float, float], bounds: np.ndarray):
        from matplotlib.transforms import Affine2D
        self.fig = fig
        W, H = fig.get_size_inches() * fig.dpi
        x0, y0, w, h = box[0] * W, box[1] * H, box[2] * W, box[3] * H
        (lx, ly), (hx, hy) = bounds if len(bounds) else (np.zeros(2), np.ones(2))
        span = max(hx - lx, hy - ly, 1e-6) * 1.06
        s = min(w, h) / span
        cx, cy = (lx + hx) / 2, (ly + hy) / 2
        self.transform = Affine2D().translate(-cx, -cy).scale(s).translate(x0 + w / 2, y0 + h / 2)

    def add(self, artist):
        artist.set_transform(self.transform)
        self.fig.add_artist(artist)
        return artist


def draw_building(cv: Canvas, fs: list[tuple[np.ndarray, str | None]], origin: np.ndarray, alpha: float = 1.0,
                  edge: str = "#333333") -> None:
    """Draw faces (see :func:`faces`) in depth order (painter's algorithm)."""
    from matplotlib.collections import PolyCollection
    polys, cols, keys = [], [], []
    for p, t in fs:
        xy, depth = project(p - origin)
        polys.append(xy)
        cols.append(_shade(SURFACE_COLOURS.get(t, SURFACE_COLOURS[None]), unit(newell_normal(p))))
        keys.append(depth.mean())
    order = np.argsort(keys)
    cv.add(PolyCollection([polys[i] for i in order], facecolors=[cols[i] for i in order],
                          edgecolors=edge, linewidths=0.4, alpha=alpha))


def _location_key(loc: str) -> tuple | None:
    """``(coid, geom, shell, face)`` of a val3dity location naming a face, else None."""
    d = dict(kv.split("=", 1) for kv in loc.split("|") if "=" in kv)
    if not d.get("face", "").isdigit() or not d.get("geom", "").isdigit():
        return None
    return d.get("coid", ""), int(d["geom"]), int(d["shell"]) if d.get("shell", "").isdigit() else 0, int(d["face"])


def graph_picture(b: Building, defects=(), tol: Tolerances = DEFAULT, lod: str | None = None) -> dict:
    """The face-adjacency graph of ``b`` as drawn in the report (picture coordinates, colours).

    A face is defective when its graph features flag it (degenerate, non-planar beyond
    ``planarity_d2p_tol``, on a boundary or non-manifold edge) or a defect's location names it.

    Returns
    -------
    dict
        ``nodes``: ``[{"face", "xy" (2,), "kind", "colour"}]``; ``edges``: ``[{"kind", "colour",
        "xy" ((2, 2))}]`` with kinds ``adjacency``, ``inconsistent_adjacency``, ``boundary_edge``,
        ``nonmanifold_edge``; ``counts``: elements per kind; ``status``: the graph's status.
    """
    g = building_graphs([b], lod, tol)[0]
    n = g.n_faces
    out = {"nodes": [], "edges": [], "counts": {}, "status": g.status, "colours": dict(GRAPH_COLOURS)}
    if n == 0:
        return out
    origin = _origin(b)
    named = {k for d in defects for loc in d.location.split("&&") if (k := _location_key(loc)) is not None}
    bad = (g.x[:, 5] > 0) | (g.x[:, 6] > tol.planarity_d2p_tol) | (g.x[:, 7] > 0) | (g.x[:, 8] > 0)
    for i, (oid, gi, si, hi, fi) in enumerate(g.face_ids):
        if (oid, gi, hi, fi) in named:
            bad[i] = True
    xy, _ = project(g.centroids - origin)
    for i in range(n):
        kind = "defective_face" if bad[i] else "valid_face"
        out["nodes"].append({"face": i, "xy": xy[i].round(3).tolist(), "kind": kind, "colour": GRAPH_COLOURS[kind]})
    ei = g.edge_index
    keep = ei[0] < ei[1]
    for (a, c), nm, ok in zip(ei[:, keep].T, g.edge_attr[keep, 2], g.consistent[keep]):
        kind = "nonmanifold_edge" if nm > 0 else ("adjacency" if ok else "inconsistent_adjacency")
        if kind == "nonmanifold_edge":
            kind = "adjacency"  # the non-manifold mesh edge itself is drawn below
        out["edges"].append({"kind": kind, "colour": GRAPH_COLOURS[kind], "xy": [xy[a].round(3).tolist(),
                                                                                 xy[c].round(3).tolist()]})
    V, _ = project(b.vertices - origin)
    for (u, v), c in zip(g.mesh_edges, g.incidence):
        if c == 1 or c > 2:
            kind = "boundary_edge" if c == 1 else "nonmanifold_edge"
            out["edges"].append({"kind": kind, "colour": GRAPH_COLOURS[kind],
                                 "xy": [V[u].round(3).tolist(), V[v].round(3).tolist()]})
    kinds = [e["kind"] for e in out["edges"]] + [nd["kind"] for nd in out["nodes"]]
    out["counts"] = {k: kinds.count(k) for k in GRAPH_COLOURS if kinds.count(k)}
    return out


def draw_graph(cv: Canvas, pic: dict, fs, origin) -> None:
    """Draw :func:`graph_picture` output over a faint copy of the building."""
    from matplotlib.collections import EllipseCollection, LineCollection
    if fs:
        draw_building(cv, fs, origin, alpha=0.18, edge="#bbbbbb")
    for kind, lw in (("adjacency", 0.6), ("inconsistent_adjacency", 1.2), ("boundary_edge", 2.4),
                     ("nonmanifold_edge", 2.8)):
        segs = [e["xy"] for e in pic["edges"] if e["kind"] == kind]
        if segs:
            cv.add(LineCollection(segs, colors=GRAPH_COLOURS[kind], linewidths=lw))
    for kind, size in (("valid_face", 6.0), ("defective_face", 8.0)):
        pts = np.array([nd["xy"] for nd in pic["nodes"] if nd["kind"] == kind]).reshape(-1, 2)
        if len(pts):
            c = EllipseCollection(size, size, 0.0, units="dots", offsets=pts, facecolors=GRAPH_COLOURS[kind],
                                  edgecolors="white", linewidths=0.4)
            c.set_offset_transform(cv.transform)
            c.set_transform(_identity())
            cv.fig.add_artist(c)


def _identity():
    from matplotlib.transforms import IdentityTransform
    return IdentityTransform()


def _origin(b: Building) -> np.ndarray:
    v = b.vertices
    return v.min(axis=0) if len(v) else np.zeros(3)


def geometry_digest(b: Building | None) -> str:
    """Digest of a building's vertices and envelope rings (the render cache key)."""
    h = hashlib.sha1()
    if b is None:
        return "none"
    h.update(np.ascontiguousarray(b.vertices).tobytes())
    for r in b.shells() or b.all_shells():
        for s in r.shell.surfaces:
            for ring in s.rings:
                h.update(np.asarray(ring, np.int64).tobytes())
                h.update(b"|")
            h.update(str(r.geometry.semantic_type(s)).encode())
    return h.hexdigest()


def png_data_url(fig, dpi: int = 80, compress_level: int = 6) -> str:
    """``data:image/png;base64,...`` of a matplotlib figure."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, pil_kwargs={"compress_level": compress_level})
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def panel_image(before: Building | None, after: Building | None, pic: dict) -> str:
    """One PNG (data URL) with input, repaired geometry and the input's face graph, side by side
    (captions are the page's: input | repaired | face-adjacency graph).

    Kept (:mod:`lod2energy.cache`) by the digests of both buildings.
    """
    key = geometry_digest(before) + geometry_digest(after)
    return cache.remember("viz.panels", key, lambda: _panel_image(before, after, pic), KEPT_PANELS)


#: Panel pictures kept per process.
KEPT_PANELS = 2048


def _panel_image(before: Building | None, after: Building | None, pic: dict) -> str:
    """:func:`panel_image` without the cache."""
    fig = new_figure(9.6, 3.0)
    fig.dpi = 72
    f_in = faces(before) if before is not None else []
    f_out = faces(after) if after is not None else []
    origin = _origin(before if before is not None and len(before.vertices) else after)
    pts = [project(p - origin)[0] for p, _ in f_in + f_out]
    allp = np.vstack(pts) if pts else np.zeros((0, 2))
    bounds = np.array([allp.min(axis=0), allp.max(axis=0)]) if len(allp) else np.zeros((0, 2))
    for k, (fs, title) in enumerate(((f_in, "input"), (f_out, "repaired"), (None, "face-adjacency graph"))):
        cv = Canvas(fig, (k / 3 + 0.005, 0.01, 1 / 3 - 0.01, 0.98), bounds)
        if fs is None:
            draw_graph(cv, pic, f_in, origin)
        elif fs:
            draw_building(cv, fs, origin)
        else:
            fig.text(k / 3 + 1 / 6, 0.45, "not repaired" if k == 1 and f_in else "no geometry",
                     ha="center", va="center")
    return png_data_url(fig, dpi=72, compress_level=1)


def slug(s: str) -> str:
    """An HTML id fragment for a building id."""
    return "b-" + re.sub(r"[^A-Za-z0-9_-]", "_", str(s))
