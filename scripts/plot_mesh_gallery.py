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

Reads the .vtu files with meshio (any encoding the program writes); draws with numpy and
matplotlib (Agg), all three from Debian.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import matplotlib  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

from mesh_drawing import (  # noqa: E402
    cells_in_window, default_zoom_window, draw_cells, draw_field_cells, finish_close_up,
    mesh_figure, plot_side_histogram, set_view, side_colour)
from mesh_files import (  # noqa: E402
    MeshFile, default_stats_path, histogram, mentions_array, parse_mesh_argument, read_stats,
    stem_of)
from plotting_common import InputError, save_atomically  # noqa: E402

ZOOM_CELL_THRESHOLD = 2000  # draw a close-up panel by default above this many cells
AUTO_DEFORM_FRACTION = 0.05  # --deform auto: largest displacement / domain width


# --------------------------------------------------------------------------------------------
# Arguments


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


def read_mesh(vtu, stats_path):
    mesh = MeshFile(vtu)
    if not mesh.cells:
        raise InputError(f"{vtu}: the mesh has no cells")
    stats = read_stats(stats_path)
    return mesh, stats, stats.get("family", stem_of(vtu))


# --------------------------------------------------------------------------------------------
# The mesh and its side counts


def mesh_details(stats):
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
    return details


def side_legend(ax, sides):
    n_cells = len(sides)
    counts = {int(k): int((sides == k).sum()) for k in np.unique(sides)}
    handles = [Patch(facecolor=side_colour(k), edgecolor="black", linewidth=0.5,
                     label=f"{k} sides: {n:,} ({100.0 * n / n_cells:.1f}%)")
               for k, n in sorted(counts.items())]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8,
              frameon=False, title="cells", title_fontsize=8, borderaxespad=0.0)
    return counts


def plot_mesh(vtu, stats_path, outdir, zoom, want_zoom, dpi):
    """OUTDIR/<name>.png, and OUTDIR/<name>.sides.png for a regularized rcp mesh."""
    mesh, stats, family = read_mesh(vtu, stats_path)
    pts, n_cells = mesh.points, len(mesh.cells)
    sides = mesh.sides()
    polys = [pts[c] for c in mesh.cells]
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    extent = hi - lo
    h_avg = stats.get("h_avg") or math.sqrt(extent[0] * extent[1] / n_cells)
    if zoom is None and want_zoom and n_cells > ZOOM_CELL_THRESHOLD:
        zoom = default_zoom_window(lo, hi, h_avg)

    fig, ax, zax, _ = mesh_figure(extent, zoom, 1.6, 0.9)
    draw_cells(ax, polys, sides)
    set_view(ax, lo, hi, 0.01 * max(extent))
    title = f"{family}: {n_cells:,} cells, h_avg = {h_avg:.4g}"
    details = mesh_details(stats)
    ax.set_title(title + ("\n" + ", ".join(details) if details else ""), fontsize=10)
    counts = side_legend(ax, sides)
    if zax is not None:
        inside = cells_in_window(polys, zoom)
        draw_cells(zax, [polys[i] for i in inside], sides[inside])
        used = np.unique(np.concatenate([mesh.cells[i] for i in inside])) if len(inside) else []
        visible = pts[used]
        zax.plot(visible[:, 0], visible[:, 1], "o", ms=1.2, color="black", zorder=3)
        finish_close_up(ax, zax, zoom, 4)
    stem = stem_of(vtu)
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


# --------------------------------------------------------------------------------------------
# Fields on the (deformed) mesh


def displaced_points(mesh, deform, domain):
    """The points drawn (displaced by the scale times the point data "displacement") and the
    scale, or the points and None without --deform."""
    if deform is None:
        return mesh.points, None
    disp = mesh.array("PointData", "displacement")
    if disp.shape[1] < 2:
        raise InputError(f"{mesh.path}: PointData 'displacement' has {disp.shape[1]} component, need 2")
    disp = disp[:, :2]
    if not np.all(np.isfinite(disp)):
        raise InputError(f"{mesh.path}: PointData 'displacement' holds NaN or infinite values")
    max_disp = float(np.sqrt((disp ** 2).sum(axis=1)).max()) if len(disp) else 0.0
    if deform == "auto":
        scale = AUTO_DEFORM_FRACTION * (domain[2] - domain[0]) / max_disp if max_disp > 0 else 0.0
    else:
        scale = float(deform)
    return mesh.points + scale * disp, scale


def cell_values(mesh, field, log):
    """The masked values of the chosen cell field, their label and colour norm."""
    name, comp, _ = field
    data = mesh.array("CellData", name)
    ncomp = data.shape[1]
    if comp is not None and comp >= ncomp:
        raise InputError(f"{mesh.path}: CellData {name!r} has {ncomp} component{'s' if ncomp > 1 else ''},"
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
        raise InputError(f"{mesh.path}: CellData {name!r} has no {kind} value to draw")
    vmin, vmax = float(values.min()), float(values.max())
    if log:
        norm = matplotlib.colors.LogNorm(vmin=vmin, vmax=vmax if vmax > vmin else vmin * 10)
    else:
        norm = matplotlib.colors.Normalize(vmin=vmin, vmax=vmax if vmax > vmin else vmin + 1)
    return values, label, norm


def field_title(family, n_cells, stats, label, values, deform, scale):
    if label is None:
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
    if label is not None:
        details.append(f"{label} in [{float(values.min()):.4g}, {float(values.max()):.4g}]")
    return title + "\n" + ", ".join(details)


def plot_field(vtu, stats_path, outdir, field, deform, zoom, log, dpi):
    """OUTDIR/<name>.<field>.png: cells coloured by a cell field (and/or drawn displaced by
    `deform` x the point data "displacement"); OUTDIR/<name>.deformed.png with --deform alone."""
    mesh, stats, family = read_mesh(vtu, stats_path)
    n_cells = len(mesh.cells)
    lo0, hi0 = mesh.points.min(axis=0), mesh.points.max(axis=0)
    domain = mesh.domain() or (lo0[0], lo0[1], hi0[0], hi0[1])
    shown, scale = displaced_points(mesh, deform, domain)
    polys = [shown[c] for c in mesh.cells]
    values = norm = label = None
    if field is not None:
        values, label, norm = cell_values(mesh, field, log)
    sides = mesh.sides()

    def draw(ax, subset):
        if field is None:
            draw_cells(ax, [polys[i] for i in subset], sides[subset])
            return None
        return draw_field_cells(ax, [polys[i] for i in subset], values[subset], norm)

    lo = np.minimum(shown.min(axis=0), [domain[0], domain[1]])
    hi = np.maximum(shown.max(axis=0), [domain[2], domain[3]])
    extent = hi - lo
    fig, ax, zax, full_h = mesh_figure(extent, zoom, 2.0, 1.0)
    coll = draw(ax, np.arange(n_cells))
    if deform is not None and scale != 0.0:
        ax.add_patch(Rectangle((domain[0], domain[1]), domain[2] - domain[0], domain[3] - domain[1],
                               fill=False, edgecolor="0.45", linestyle="--", linewidth=0.9, zorder=4,
                               label="undeformed domain"))
        ax.legend(loc="upper left", fontsize=8, frameon=False)
    set_view(ax, lo, hi, 0.02 * max(extent))
    ax.set_title(field_title(family, n_cells, stats, label, values, deform, scale), fontsize=10)
    if coll is not None:
        cbar = fig.colorbar(coll, ax=ax, location="right", fraction=0.04, pad=0.01,
                            aspect=max(8.0, 18.0 * min(1.0, full_h / 5.0)))
        cbar.set_label(label + (" (log scale)" if log else ""), fontsize=9)
        cbar.ax.tick_params(labelsize=8)
    if zax is not None:
        draw(zax, cells_in_window(polys, zoom))
        finish_close_up(ax, zax, zoom, 5)
    stem = stem_of(vtu)
    out = os.path.join(outdir, f"{stem}.{field[2]}.png" if field else f"{stem}.deformed.png")
    save_atomically(fig, out, dpi)
    return [out]


# --------------------------------------------------------------------------------------------


def find_jobs(outdir, field, deform, suffixes):
    """(vtu, stats) of every OUTDIR/*.vtu worth drawing: with the arrays asked for, or (meshes)
    with their statistics. Exits with a message when there is none."""
    vtus = sorted(os.path.join(outdir, f) for f in os.listdir(outdir) if f.endswith(".vtu"))
    if field is not None or deform is not None:
        wanted = ([field[0]] if field else []) + (["displacement"] if deform is not None else [])
        jobs = [(v, default_stats_path(v, suffixes)) for v in vtus
                if all(mentions_array(v, n) for n in wanted)]
        need = f"data {', '.join(repr(n) for n in wanted)}"
    else:
        jobs = [(v, default_stats_path(v)) for v in vtus]
        jobs = [(v, s) for v, s in jobs if s is not None]
        need = "a matching *.stats.json"
    if not jobs:
        print(f"plot_mesh_gallery: no *.vtu with {need} in {outdir}", file=sys.stderr)
    return jobs


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

    os.makedirs(args.outdir, exist_ok=True)
    if args.meshes:
        jobs = [parse_mesh_argument(m, suffixes) for m in args.meshes]
    else:
        jobs = find_jobs(args.outdir, args.field, args.deform, suffixes)
        if not jobs:
            return 1
    failures = 0
    for vtu, stats in jobs:
        try:
            if field_mode:
                plot_field(vtu, stats, args.outdir, args.field, args.deform, args.zoom, args.log,
                           args.dpi)
            else:
                plot_mesh(vtu, stats, args.outdir, args.zoom, not args.no_zoom, args.dpi)
        except InputError as e:
            print(f"plot_mesh_gallery: {e}", file=sys.stderr)
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
