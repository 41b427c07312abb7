#!/usr/bin/python3
"""Draws PNGs of polygon meshes written by `vorodg mesh` and of cell fields of `vorodg solve` results.

Usage:
  plot_mesh_gallery.py OUTDIR                                 # every OUTDIR/*.vtu with a *.stats.json
  plot_mesh_gallery.py OUTDIR mesh1.vtu[:stats1.json] mesh2.vtu ...
Options:
  --zoom x0,y0,x1,y1   window of the close-up panel (default: a corner window of about 250 cells,
                       drawn for meshes with more than 2000 cells)
  --no-zoom            never draw a close-up panel
  --dpi N              resolution of the PNGs (default 150)
  --field NAME         colour the cells by the cell data NAME (viridis, with a colourbar), e.g. the
                       von_mises of a `vorodg solve` result; NAME:K picks component K of a
                       multi-component array, NAME:mag (the default for those) its magnitude
  --log                logarithmic colour scale (with --field; cells with values <= 0 are grey)
  --deform SCALE       draw the mesh displaced by SCALE x the point data "displacement", with the
                       undeformed domain dashed; SCALE "auto" makes the largest displacement 5% of
                       the domain width (the domain from the file's field data)

For each mesh it writes OUTDIR/<name>.png: the cells with thin black edges, lightly coloured by
their number of sides, with a legend. For rcp meshes (stats with `side_counts_before`) it also
writes OUTDIR/<name>.sides.png, the side-count histogram before and after regularization. A mesh
named X.vtu has its statistics in X.stats.json (found automatically when no :stats is given).

With --field or --deform it writes OUTDIR/<name>.<field>.png instead (<name>.<field>.K.png,
<name>.<field>.mag.png for a component or magnitude; <name>.deformed.png for --deform alone,
cells coloured by their sides), with no close-up unless --zoom is given (a window in the drawn,
deformed coordinates). The title takes family, h_avg and errors from X.stats.json or
X.metrics.json beside X.vtu. Without MESH arguments, every OUTDIR/*.vtu carrying the arrays.
PNGs are written atomically (temporary file in OUTDIR, then renamed); the paths are printed.

Only the Python standard library, numpy and matplotlib (Agg) are used.
"""
import argparse
import json
import math
import os
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from plotting_common import save_atomically  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

# VTK cell types we can draw as polygons.
VTK_TRIANGLE, VTK_POLYGON, VTK_PIXEL, VTK_QUAD = 5, 7, 8, 9
ZOOM_CELL_THRESHOLD = 2000  # draw a close-up panel by default above this many cells
ZOOM_TARGET_CELLS = 250  # the default close-up window holds about this many cells

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


class GalleryError(Exception):
    pass


# --------------------------------------------------------------------------------------------
# Input


def read_vtu(path):
    """Points (n x 2) and a list of cells (vertex index arrays) of an ASCII VTK UnstructuredGrid."""
    pts, cells, _ = read_vtu_piece(path)
    return pts, cells


def read_vtu_piece(path):
    """read_vtu, plus the parsed XML root for the data arrays (see data_array)."""
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError) as e:
        raise GalleryError(f"{path}: cannot parse XML: {e}") from None
    if root.tag != "VTKFile" or root.get("type") != "UnstructuredGrid":
        raise GalleryError(f"{path}: not a VTKFile of type UnstructuredGrid")
    piece = root.find("UnstructuredGrid/Piece")
    if piece is None:
        raise GalleryError(f"{path}: no UnstructuredGrid/Piece element")
    n_points = int(piece.get("NumberOfPoints", "-1"))
    n_cells = int(piece.get("NumberOfCells", "-1"))

    def array(parent_tag, name=None, dtype=float):
        da = find_data_array(path, piece, parent_tag, name)
        return da, ascii_values(path, da, dtype)

    pts_da, pts = array("Points")
    ncomp = int(pts_da.get("NumberOfComponents", "3"))
    if ncomp < 2 or pts.size != n_points * ncomp:
        raise GalleryError(f"{path}: {pts.size} point coordinates for {n_points} points x {ncomp}")
    pts = pts.reshape(n_points, ncomp)[:, :2]

    _, conn = array("Cells", "connectivity", np.int64)
    _, offsets = array("Cells", "offsets", np.int64)
    _, types = array("Cells", "types", np.int64)
    if offsets.size != n_cells or types.size != n_cells:
        raise GalleryError(f"{path}: {offsets.size} offsets and {types.size} types for {n_cells} cells")
    if n_cells and (offsets[-1] != conn.size or np.any(np.diff(offsets) <= 0)):
        raise GalleryError(f"{path}: cell offsets do not match the connectivity")
    if conn.size and (conn.min() < 0 or conn.max() >= n_points):
        raise GalleryError(f"{path}: connectivity refers to a point that does not exist")
    bad = ~np.isin(types, [VTK_TRIANGLE, VTK_POLYGON, VTK_PIXEL, VTK_QUAD])
    if np.any(bad):
        raise GalleryError(f"{path}: cell {int(np.argmax(bad))} has unsupported VTK type {int(types[bad][0])}")

    cells = np.split(conn, offsets[:-1])
    for c in np.nonzero(types == VTK_PIXEL)[0]:  # pixels are numbered row by row
        cells[c] = cells[c][[0, 1, 3, 2]]
    return pts, cells, root


def find_data_array(path, parent, parent_tag, name=None):
    """The first DataArray (named `name`, if given) under parent/parent_tag."""
    node = parent.find(parent_tag)
    if node is None:
        raise GalleryError(f"{path}: no <{parent_tag}> element")
    for da in node.findall("DataArray"):
        if name is None or da.get("Name") == name:
            return da
    raise GalleryError(f"{path}: no DataArray {name!r} in <{parent_tag}>")


def ascii_values(path, da, dtype=float):
    fmt = da.get("format", "ascii")
    if fmt != "ascii":
        raise GalleryError(f"{path}: DataArray {da.get('Name')!r} is {fmt}, only ascii is read")
    try:
        return np.array((da.text or "").split(), dtype=dtype)
    except ValueError:
        raise GalleryError(f"{path}: DataArray {da.get('Name')!r} holds a value that is not a number") from None


def array_names(root, section):
    node = root.find("UnstructuredGrid/Piece/" + section)
    return [] if node is None else [da.get("Name") for da in node.findall("DataArray")]


def data_array(path, root, section, name):
    """PointData or CellData array `name` as (n x components), n = points or cells of the piece."""
    piece = root.find("UnstructuredGrid/Piece")
    count = int(piece.get("NumberOfPoints" if section == "PointData" else "NumberOfCells", "-1"))
    if name not in array_names(root, section):
        other = "CellData" if section == "PointData" else "PointData"
        where = f" (it is {other})" if name in array_names(root, other) else ""
        have = ", ".join(array_names(root, section)) or "none"
        raise GalleryError(f"{path}: no {section} array {name!r}{where}; {section} arrays: {have}")
    da = find_data_array(path, piece, section, name)
    values = ascii_values(path, da)
    ncomp = int(da.get("NumberOfComponents", "1"))
    if ncomp < 1 or values.size != count * ncomp:
        raise GalleryError(f"{path}: {section} {name!r} has {values.size} values for {count} x {ncomp}")
    return values.reshape(count, ncomp)


def domain_of(root):
    """The domain rectangle (x0, y0, x1, y1) from the FieldData, or None."""
    da = root.find("UnstructuredGrid/FieldData/DataArray[@Name='domain']")
    if da is None:
        return None
    try:
        values = [float(v) for v in (da.text or "").split()]
    except ValueError:
        return None
    return tuple(values) if len(values) == 4 else None


def read_stats(path):
    if path is None:
        return {}
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        raise GalleryError(f"{path}: cannot read statistics: {e}") from None


def histogram(value):
    """A side-count histogram from the stats JSON: {"k": count} (or [[k, count], ...])."""
    if not value:
        return {}
    items = value.items() if isinstance(value, dict) else value
    return {int(k): int(n) for k, n in items}


def stem_of(vtu_path):
    name = os.path.basename(vtu_path)
    return name[:-4] if name.endswith(".vtu") else name


def default_stats_path(vtu_path, suffixes=(".stats.json",)):
    base = vtu_path[:-4] if vtu_path.endswith(".vtu") else vtu_path
    for suffix in suffixes:
        candidate = base + suffix
        if os.path.exists(candidate):
            return candidate
    return None


def parse_mesh_argument(arg, suffixes=(".stats.json",)):
    """'mesh.vtu[:stats.json]' -> (vtu, stats or None). Only a trailing ':...json' is split off."""
    head, sep, tail = arg.rpartition(":")
    if sep and tail.endswith(".json") and head:
        return head, tail
    return arg, default_stats_path(arg, suffixes)


def parse_field(text):
    """'NAME', 'NAME:K' (component K) or 'NAME:mag' -> (name, component or None, file tag)."""
    name, sep, comp = text.partition(":")
    if not name or "/" in name:
        raise argparse.ArgumentTypeError(f"expected a cell data name, got {text!r}")
    if not sep:
        return name, None, name
    if comp == "mag":
        return name, None, name + ".mag"
    try:
        k = int(comp)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected NAME, NAME:K or NAME:mag, got {text!r}") from None
    if k < 0:
        raise argparse.ArgumentTypeError(f"component index must be >= 0, got {text!r}")
    return name, k, f"{name}.{k}"


def parse_scale(text):
    if text == "auto":
        return "auto"
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number or 'auto', got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"the scale must be finite, got {text!r}")
    return value


def parse_window(text):
    try:
        x0, y0, x1, y1 = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected x0,y0,x1,y1, got {text!r}") from None
    if not (x0 < x1 and y0 < y1):
        raise argparse.ArgumentTypeError(f"empty window {text!r}: need x0 < x1 and y0 < y1")
    return x0, y0, x1, y1


# --------------------------------------------------------------------------------------------
# Output




def side_colour(k):
    return SIDE_COLOURS.get(k, OTHER_COLOUR)


def draw_cells(ax, pts, cells, sides, linewidth):
    polys = [pts[c] for c in cells]
    faces = [side_colour(int(k)) for k in sides]
    coll = PolyCollection(polys, facecolors=faces, edgecolors="black", linewidths=linewidth,
                          antialiaseds=True)
    ax.add_collection(coll)
    ax.set_aspect("equal")


def default_zoom_window(lo, hi, h):
    """A window at the lower-left corner (the corner and two sides are where meshes go wrong),
    about ZOOM_TARGET_CELLS cells, 2:1 if the domain is wide enough."""
    height = min(hi[1] - lo[1], math.sqrt(ZOOM_TARGET_CELLS / 2.0) * h)
    width = min(hi[0] - lo[0], 2.0 * height)
    return lo[0], lo[1], lo[0] + width, lo[1] + height


def edge_linewidth(n_cells_visible):
    # Thin enough that a dense mesh does not turn black, thick enough to be seen.
    if n_cells_visible <= 500:
        return 0.6
    if n_cells_visible <= 3000:
        return 0.35
    if n_cells_visible <= 20000:
        return 0.2
    return 0.1


def plot_mesh(vtu, stats_path, outdir, zoom, want_zoom, dpi):
    pts, cells = read_vtu(vtu)
    stats = read_stats(stats_path)
    n_cells = len(cells)
    if n_cells == 0:
        raise GalleryError(f"{vtu}: the mesh has no cells")
    stem = stem_of(vtu)
    family = stats.get("family", stem)
    sides = np.fromiter((len(c) for c in cells), dtype=np.int64, count=n_cells)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    extent = hi - lo
    h_avg = stats.get("h_avg") or math.sqrt(extent[0] * extent[1] / n_cells)

    if zoom is None and want_zoom and n_cells > ZOOM_CELL_THRESHOLD:
        zoom = default_zoom_window(lo, hi, h_avg)

    # Layout: the whole mesh on top (with the legend to its right), the close-up below.
    fig_w = 12.0
    aspect = extent[1] / extent[0] if extent[0] > 0 else 1.0
    full_h = max(1.6, min(8.0, (fig_w - 2.2) * aspect)) + 0.9
    zoom_h = 0.0
    if zoom is not None:
        zaspect = (zoom[3] - zoom[1]) / (zoom[2] - zoom[0])
        zoom_h = max(2.5, min(6.0, (fig_w - 2.2) * zaspect)) + 0.5
    fig = plt.figure(figsize=(fig_w, full_h + zoom_h), layout="constrained")
    if zoom is not None:
        ax, zax = fig.subplots(2, 1, height_ratios=[full_h, zoom_h])
    else:
        ax, zax = fig.subplots(1, 1), None

    draw_cells(ax, pts, cells, sides, edge_linewidth(n_cells))
    pad = 0.01 * max(extent)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.tick_params(labelsize=8)

    title = f"{family}: {n_cells:,} cells, h_avg = {h_avg:.4g}"
    details = []
    if "vertices" in stats:
        details.append(f"{stats['vertices']:,} vertices")
    if "min_edge_over_h_avg" in stats:
        details.append(f"min edge / h_avg = {stats['min_edge_over_h_avg']:.3g}")
    if "min_interior_angle_deg" in stats:
        details.append(f"interior angles {stats['min_interior_angle_deg']:.1f}"
                       f"–{stats.get('max_interior_angle_deg', float('nan')):.1f}°")
    if stats.get("covered_fraction") is not None:
        details.append(f"covered fraction {stats['covered_fraction']:.3f}")
    ax.set_title(title + ("\n" + ", ".join(details) if details else ""), fontsize=10)

    counts = {int(k): int((sides == k).sum()) for k in np.unique(sides)}
    handles = [Patch(facecolor=side_colour(k), edgecolor="black", linewidth=0.5,
                     label=f"{k} sides: {n:,} ({100.0 * n / n_cells:.1f}%)")
               for k, n in sorted(counts.items())]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8,
              frameon=False, title="cells", title_fontsize=8, borderaxespad=0.0)

    if zax is not None:
        x0, y0, x1, y1 = zoom
        # Only the cells that reach into the window (fast for big meshes).
        cmin = np.array([pts[c].min(axis=0) for c in cells])
        cmax = np.array([pts[c].max(axis=0) for c in cells])
        inside = np.nonzero((cmax[:, 0] >= x0) & (cmin[:, 0] <= x1) &
                            (cmax[:, 1] >= y0) & (cmin[:, 1] <= y1))[0]
        draw_cells(zax, pts, [cells[i] for i in inside], sides[inside], edge_linewidth(len(inside)))
        visible = pts[np.unique(np.concatenate([cells[i] for i in inside]))] if len(inside) else pts[:0]
        zax.plot(visible[:, 0], visible[:, 1], "o", ms=1.2, color="black", zorder=3)
        zpad = 0.01 * max(x1 - x0, y1 - y0)
        zax.set_xlim(x0 - zpad, x1 + zpad)
        zax.set_ylim(y0 - zpad, y1 + zpad)
        zax.tick_params(labelsize=8)
        zax.set_title(f"close-up [{x0:.3g}, {x1:.3g}] × [{y0:.3g}, {y1:.3g}]", fontsize=9)
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, edgecolor="tab:red",
                               linewidth=1.2, zorder=4))

    out = os.path.join(outdir, stem + ".png")
    save_atomically(fig, out, dpi)
    written = [out]

    before = histogram(stats.get("side_counts_before"))
    if before:
        after = histogram(stats.get("side_counts_after")) or counts
        out = os.path.join(outdir, stem + ".sides.png")
        plot_side_histogram(before, after, stats, family, out, dpi)
        written.append(out)
    return written


def plot_side_histogram(before, after, stats, family, out, dpi):
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



# --------------------------------------------------------------------------------------------
# Fields on the (deformed) mesh

AUTO_DEFORM_FRACTION = 0.05  # --deform auto: largest displacement = this fraction of the domain width


def field_edge_colour(n_cells_visible):
    """Cell edges for field pictures: dark but translucent, so dense meshes keep their colours."""
    alpha = 0.7 if n_cells_visible <= 500 else 0.45 if n_cells_visible <= 3000 else 0.3
    return (0.0, 0.0, 0.0, alpha)


def draw_field_cells(ax, polys, values, norm, n_visible):
    coll = PolyCollection(polys, array=values, cmap="viridis", norm=norm,
                          edgecolors=[field_edge_colour(n_visible)],
                          linewidths=0.6 * edge_linewidth(n_visible), antialiaseds=True)
    coll.cmap.set_bad("#bdbdbd")
    ax.add_collection(coll)
    ax.set_aspect("equal")
    return coll


def plot_field(vtu, stats_path, outdir, field, deform, zoom, log, dpi):
    """OUTDIR/<name>.<field>.png: cells coloured by a cell field (and/or drawn displaced by
    `deform` x the point data "displacement"); OUTDIR/<name>.deformed.png with --deform alone."""
    pts, cells, root = read_vtu_piece(vtu)
    stats = read_stats(stats_path)
    n_cells = len(cells)
    if n_cells == 0:
        raise GalleryError(f"{vtu}: the mesh has no cells")
    stem = stem_of(vtu)
    family = stats.get("family", stem)
    domain = domain_of(root)
    lo0, hi0 = pts.min(axis=0), pts.max(axis=0)
    if domain is None:
        domain = (lo0[0], lo0[1], hi0[0], hi0[1])

    # Where the points are drawn.
    scale = None
    shown = pts
    if deform is not None:
        disp = data_array(vtu, root, "PointData", "displacement")
        if disp.shape[1] < 2:
            raise GalleryError(f"{vtu}: PointData 'displacement' has {disp.shape[1]} component, need 2")
        disp = disp[:, :2]
        if not np.all(np.isfinite(disp)):
            raise GalleryError(f"{vtu}: PointData 'displacement' holds NaN or infinite values")
        max_disp = float(np.sqrt((disp ** 2).sum(axis=1)).max()) if len(disp) else 0.0
        if deform == "auto":
            width = domain[2] - domain[0]
            scale = AUTO_DEFORM_FRACTION * width / max_disp if max_disp > 0 else 0.0
        else:
            scale = float(deform)
        shown = pts + scale * disp
    polys = [shown[c] for c in cells]

    # What colours the cells.
    if field is not None:
        name, comp, tag = field
        data = data_array(vtu, root, "CellData", name)
        ncomp = data.shape[1]
        if comp is not None and comp >= ncomp:
            raise GalleryError(f"{vtu}: CellData {name!r} has {ncomp} component{'s' if ncomp > 1 else ''},"
                               f" asked for component {comp} (counted from 0)")
        if comp is not None:
            values, label = data[:, comp].copy(), f"{name}[{comp}]"
        elif ncomp == 1:
            values, label = data[:, 0].copy(), name
        else:
            values, label = np.sqrt((data ** 2).sum(axis=1)), f"|{name}|"
        values = np.ma.masked_invalid(values)
        if log:
            values = np.ma.masked_less_equal(values, 0.0)
        if values.count() == 0:
            kind = "positive finite" if log else "finite"
            raise GalleryError(f"{vtu}: CellData {name!r} has no {kind} value to draw")
        vmin, vmax = float(values.min()), float(values.max())
        if log:
            norm = matplotlib.colors.LogNorm(vmin=vmin, vmax=vmax if vmax > vmin else vmin * 10)
        else:
            norm = matplotlib.colors.Normalize(vmin=vmin, vmax=vmax if vmax > vmin else vmin + 1)
        out = os.path.join(outdir, f"{stem}.{tag}.png")
    else:
        values = norm = label = None
        out = os.path.join(outdir, f"{stem}.deformed.png")

    # Layout: the whole mesh on top with the colourbar on its right, an optional close-up below.
    lo = np.minimum(shown.min(axis=0), [domain[0], domain[1]])
    hi = np.maximum(shown.max(axis=0), [domain[2], domain[3]])
    extent = hi - lo
    fig_w = 12.0
    aspect = extent[1] / extent[0] if extent[0] > 0 else 1.0
    full_h = max(2.0, min(8.0, (fig_w - 2.2) * aspect)) + 1.0
    zoom_h = 0.0
    if zoom is not None:
        zaspect = (zoom[3] - zoom[1]) / (zoom[2] - zoom[0])
        zoom_h = max(2.5, min(6.0, (fig_w - 2.2) * zaspect)) + 0.5
    fig = plt.figure(figsize=(fig_w, full_h + zoom_h), layout="constrained")
    if zoom is not None:
        ax, zax = fig.subplots(2, 1, height_ratios=[full_h, zoom_h])
    else:
        ax, zax = fig.subplots(1, 1), None

    if field is not None:
        coll = draw_field_cells(ax, polys, values, norm, n_cells)
    else:
        sides = np.fromiter((len(c) for c in cells), dtype=np.int64, count=n_cells)
        draw_cells(ax, shown, cells, sides, edge_linewidth(n_cells))
    if deform is not None and scale != 0.0:
        ax.add_patch(Rectangle((domain[0], domain[1]), domain[2] - domain[0], domain[3] - domain[1],
                               fill=False, edgecolor="0.45", linestyle="--", linewidth=0.9, zorder=4,
                               label="undeformed domain"))
        ax.legend(loc="upper left", fontsize=8, frameon=False)
    pad = 0.02 * max(extent)
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.tick_params(labelsize=8)

    if field is None:
        title = f"{family}: deformed mesh"
    else:
        title = f"{family}: {label}" + (" on the deformed mesh" if deform is not None else "")
    if deform is not None:
        title += f" (displacement × {scale:.3g}" + (", auto)" if deform == "auto" else ")")
    details = [f"{n_cells:,} cells"]
    if stats.get("h_avg") is not None:
        details.append(f"h_avg = {stats['h_avg']:.4g}")
    if stats.get("problem"):
        details.append(f"problem {stats['problem']}")
    if stats.get("l2_error") is not None:
        details.append(f"L2 error {stats['l2_error']:.3g}")
    if stats.get("energy_error") is not None:
        details.append(f"energy error {stats['energy_error']:.3g}")
    if field is not None:
        details.append(f"{label} in [{vmin:.4g}, {vmax:.4g}]")
    ax.set_title(title + "\n" + ", ".join(details), fontsize=10)

    if field is not None:
        cbar = fig.colorbar(coll, ax=ax, location="right", fraction=0.04, pad=0.01,
                            aspect=max(8.0, 18.0 * min(1.0, full_h / 5.0)))
        cbar.set_label(label + (" (log scale)" if log else ""), fontsize=9)
        cbar.ax.tick_params(labelsize=8)

    if zax is not None:
        x0, y0, x1, y1 = zoom
        cmin = np.array([p.min(axis=0) for p in polys])
        cmax = np.array([p.max(axis=0) for p in polys])
        inside = np.nonzero((cmax[:, 0] >= x0) & (cmin[:, 0] <= x1) &
                            (cmax[:, 1] >= y0) & (cmin[:, 1] <= y1))[0]
        if field is not None:
            draw_field_cells(zax, [polys[i] for i in inside], values[inside], norm, len(inside))
        else:
            sides = np.fromiter((len(c) for c in cells), dtype=np.int64, count=n_cells)
            draw_cells(zax, shown, [cells[i] for i in inside], sides[inside], edge_linewidth(len(inside)))
        zpad = 0.01 * max(x1 - x0, y1 - y0)
        zax.set_xlim(x0 - zpad, x1 + zpad)
        zax.set_ylim(y0 - zpad, y1 + zpad)
        zax.tick_params(labelsize=8)
        zax.set_title(f"close-up [{x0:.3g}, {x1:.3g}] × [{y0:.3g}, {y1:.3g}]", fontsize=9)
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, edgecolor="tab:red",
                               linewidth=1.2, zorder=5))

    save_atomically(fig, out, dpi)
    return [out]

# --------------------------------------------------------------------------------------------


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n".join(__doc__.split("\n")[1:]))
    ap.add_argument("outdir")
    ap.add_argument("meshes", nargs="*", metavar="MESH.vtu[:STATS.json]")
    ap.add_argument("--zoom", type=parse_window, metavar="x0,y0,x1,y1")
    ap.add_argument("--no-zoom", action="store_true")
    ap.add_argument("--dpi", type=int, default=150)
    ap.add_argument("--field", type=parse_field, metavar="NAME[:K|:mag]")
    ap.add_argument("--deform", type=parse_scale, metavar="SCALE|auto")
    ap.add_argument("--log", action="store_true")
    args = ap.parse_args(argv)
    if args.dpi <= 0:
        ap.error(f"--dpi must be positive, got {args.dpi}")
    if args.log and args.field is None:
        ap.error("--log needs --field")
    field_mode = args.field is not None or args.deform is not None
    # A solver result X.vtu keeps its numbers in X.metrics.json; a mesh in X.stats.json.
    suffixes = (".stats.json", ".metrics.json") if field_mode else (".stats.json",)

    outdir = args.outdir
    os.makedirs(outdir, exist_ok=True)
    if args.meshes:
        jobs = [parse_mesh_argument(m, suffixes) for m in args.meshes]
    else:
        vtus = sorted(os.path.join(outdir, f) for f in os.listdir(outdir) if f.endswith(".vtu"))
        if field_mode:
            wanted = [args.field[0]] if args.field else []
            if args.deform is not None:
                wanted.append("displacement")
            vtus = [v for v in vtus if all(names_array(v, n) for n in wanted)]
            jobs = [(v, default_stats_path(v, suffixes)) for v in vtus]
        else:
            jobs = [(v, default_stats_path(v)) for v in vtus]
            jobs = [(v, s) for v, s in jobs if s is not None]
        if not jobs:
            need = (f"data {', '.join(repr(n) for n in wanted)}" if field_mode
                    else "a matching *.stats.json")
            print(f"plot_mesh_gallery: no *.vtu with {need} in {outdir}", file=sys.stderr)
            return 1

    failures = 0
    for vtu, stats in jobs:
        try:
            if field_mode:
                plot_field(vtu, stats, outdir, args.field, args.deform, args.zoom, args.log, args.dpi)
            else:
                plot_mesh(vtu, stats, outdir, args.zoom, not args.no_zoom, args.dpi)
        except GalleryError as e:
            print(f"plot_mesh_gallery: {e}", file=sys.stderr)
            failures += 1
    return 1 if failures else 0


def names_array(path, name):
    """Whether the file mentions a DataArray called `name` (a cheap test before parsing)."""
    try:
        with open(path, "rb") as f:
            return f'Name="{name}"'.encode() in f.read()
    except OSError:
        return False


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
