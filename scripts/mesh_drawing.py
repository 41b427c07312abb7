"""Drawing polygon meshes with matplotlib: cells coloured by their sides or by a cell field, the
figure with an optional close-up panel, and the side-count histogram of a regularized mesh."""
import math

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.patches import Rectangle

from plotting_common import plt, save_atomically

ZOOM_TARGET_CELLS = 250  # the default close-up window holds about this many cells
FIGURE_WIDTH = 12.0

# Light colours by number of sides, cool for the common hexagons and warm for the rest.
SIDE_COLOURS = {
    3: "#f8c8c4",
    4: "#fddcb8",
    5: "#fff3b8",
    6: "#d8efd2",
    7: "#cfe0f1",
    8: "#e0dcef",
    9: "#efd6ea",
}
OTHER_COLOUR = "#e0e0e0"


def side_colour(k):
    return SIDE_COLOURS.get(k, OTHER_COLOUR)


def edge_linewidth(n_cells_visible):
    # Thin enough that a dense mesh does not turn black, thick enough to be seen.
    if n_cells_visible <= 500:
        return 0.6
    if n_cells_visible <= 3000:
        return 0.35
    if n_cells_visible <= 20000:
        return 0.2
    return 0.1


def draw_cells(ax, polys, sides):
    """Cells with thin black edges, lightly coloured by their number of sides."""
    faces = [side_colour(int(k)) for k in sides]
    coll = PolyCollection(polys, facecolors=faces, edgecolors="black",
                          linewidths=edge_linewidth(len(polys)), antialiaseds=True)
    ax.add_collection(coll)
    ax.set_aspect("equal")


def field_edge_colour(n_cells_visible):
    """Cell edges for field pictures: dark but translucent, so dense meshes keep their colours."""
    alpha = 0.7 if n_cells_visible <= 500 else 0.45 if n_cells_visible <= 3000 else 0.3
    return (0.0, 0.0, 0.0, alpha)


def draw_field_cells(ax, polys, values, norm):
    """Cells coloured by `values` (viridis; masked values grey)."""
    n = len(polys)
    coll = PolyCollection(polys, array=values, cmap="viridis", norm=norm,
                          edgecolors=[field_edge_colour(n)], linewidths=0.6 * edge_linewidth(n),
                          antialiaseds=True)
    coll.cmap.set_bad("#bdbdbd")
    ax.add_collection(coll)
    ax.set_aspect("equal")
    return coll


def default_zoom_window(lo, hi, h):
    """A window at the lower-left corner (the corner and two sides are where meshes go wrong),
    about ZOOM_TARGET_CELLS cells, 2:1 if the domain is wide enough."""
    height = min(hi[1] - lo[1], math.sqrt(ZOOM_TARGET_CELLS / 2.0) * h)
    width = min(hi[0] - lo[0], 2.0 * height)
    return lo[0], lo[1], lo[0] + width, lo[1] + height


def mesh_figure(extent, zoom, min_height, title_height):
    """The whole mesh on top (its height from the aspect ratio, room on the right for a legend
    or colourbar), the close-up below when there is a zoom window. Returns (fig, ax, zoom ax or
    None, height of the top panel in inches)."""
    aspect = extent[1] / extent[0] if extent[0] > 0 else 1.0
    full_h = max(min_height, min(8.0, (FIGURE_WIDTH - 2.2) * aspect)) + title_height
    zoom_h = 0.0
    if zoom is not None:
        zaspect = (zoom[3] - zoom[1]) / (zoom[2] - zoom[0])
        zoom_h = max(2.5, min(6.0, (FIGURE_WIDTH - 2.2) * zaspect)) + 0.5
    fig = plt.figure(figsize=(FIGURE_WIDTH, full_h + zoom_h), layout="constrained")
    if zoom is None:
        return fig, fig.subplots(1, 1), None, full_h
    ax, zax = fig.subplots(2, 1, height_ratios=[full_h, zoom_h])
    return fig, ax, zax, full_h


def set_view(ax, lo, hi, pad):
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.tick_params(labelsize=8)


def cells_in_window(polys, window):
    """Indices of the polygons whose bounding box reaches into the window (fast for big meshes)."""
    x0, y0, x1, y1 = window
    if not polys:
        return np.zeros(0, dtype=np.int64)
    cmin = np.array([p.min(axis=0) for p in polys])
    cmax = np.array([p.max(axis=0) for p in polys])
    return np.nonzero((cmax[:, 0] >= x0) & (cmin[:, 0] <= x1) &
                      (cmax[:, 1] >= y0) & (cmin[:, 1] <= y1))[0]


def finish_close_up(ax, zax, window, zorder):
    """Limits and title of the close-up, and its window outlined in red on the whole mesh."""
    x0, y0, x1, y1 = window
    set_view(zax, (x0, y0), (x1, y1), 0.01 * max(x1 - x0, y1 - y0))
    zax.set_title(f"close-up [{x0:.3g}, {x1:.3g}] × [{y0:.3g}, {y1:.3g}]", fontsize=9)
    ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, edgecolor="tab:red",
                           linewidth=1.2, zorder=zorder))


def plot_side_histogram(before, after, stats, family, out, dpi):
    """Bars of the percentage of cells with k sides, raw Voronoi against regularized."""
    ks = list(range(min(min(before), min(after)), max(max(before), max(after)) + 1))
    nb, na = sum(before.values()), sum(after.values())
    fb = np.array([100.0 * before.get(k, 0) / nb for k in ks])
    fa = np.array([100.0 * after.get(k, 0) / na for k in ks])
    x = np.arange(len(ks))
    w = 0.4
    fig, ax = plt.subplots(figsize=(7.0, 4.2), layout="constrained")
    bars_b = ax.bar(x - w / 2, fb, w, label=f"raw Voronoi ({nb:,} cells)", color="#9ecae1",
                    edgecolor="black", linewidth=0.5)
    bars_a = ax.bar(x + w / 2, fa, w, label=f"regularized ({na:,} cells)", color="#fdae6b",
                    edgecolor="black", linewidth=0.5)
    for bars, values, counts in ((bars_b, fb, before), (bars_a, fa, after)):
        for bar, v, k in zip(bars, values, ks):
            n = counts.get(k, 0)
            if n:
                ax.annotate(f"{n:,}", (bar.get_x() + bar.get_width() / 2, v), xytext=(0, 2),
                            textcoords="offset points", ha="center", va="bottom", fontsize=7)
    ax.set_xticks(x, [str(k) for k in ks])
    ax.set_xlabel("sides per cell")
    ax.set_ylabel("cells (%)")
    ax.set_ylim(0, max(fb.max(), fa.max()) * 1.15)
    title = f"{family}: sides per cell before and after regularization"
    if stats.get("collapsed_edges") is not None:
        title += f"\n{stats['collapsed_edges']:,} edges collapsed"
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=9, frameon=False)
    ax.grid(axis="y", alpha=0.3)
    ax.set_axisbelow(True)
    save_atomically(fig, out, dpi)
