"""The snapshots of a dynamics run (plots/<id>_snapshots.png, drawn by dynamics_plots.py): the
deformed mesh at each snapshot time, the cells of each fragment of two or more cells in a colour of
their own, single-cell fragments grey, and the rigid plane (wall.point, wall.normal of
summary.json) shaded. Needs meshio for the .vtu frames.
"""
import json
import os

import numpy as np

from plotting_common import number, plt, read_table, save_atomically


def read_wall(outdir):
    """The rigid plane of the run's scene, (point, unit normal), or None."""
    try:
        with open(os.path.join(outdir, "summary.json")) as f:
            settings = json.load(f).get("settings", {})
        point, normal = settings.get("wall.point"), settings.get("wall.normal")
        if not point or point == "none" or not normal or normal == "none":
            return None
        p, n = np.array(json.loads(point), float), np.array(json.loads(normal), float)
        return p, n / np.linalg.norm(n)
    except (OSError, ValueError):
        return None


def draw_wall(ax, wall, lo, hi):
    """The plane's trace across the frame, its solid side shaded."""
    p, n = wall
    t = np.array([-n[1], n[0]])
    span = 2.0 * np.linalg.norm(hi - lo) + np.linalg.norm(p - lo)
    a, b = p - span * t, p + span * t
    ax.fill([a[0], b[0], b[0] - span * n[0], a[0] - span * n[0]],
            [a[1], b[1], b[1] - span * n[1], a[1] - span * n[1]], color="0.8", zorder=0)
    ax.plot([a[0], b[0]], [a[1], b[1]], color="0.3", linewidth=0.8, zorder=1)


def fragment_colours(fragment):
    """Per cell: its fragment's colour index (0..19) for fragments of two or more cells, -1 for
    a fragment of one cell (drawn grey)."""
    ids, counts = np.unique(fragment, return_counts=True)
    size = dict(zip(ids, counts))
    return np.array([f % 20 if size[f] > 1 else -1 for f in fragment])


def plot_snapshots(outdir, run, dpi):
    """The deformed mesh at each snapshot, cells coloured by fragment, the plane shaded."""
    table = read_table(os.path.join(outdir, "snapshots", run["id"] + ".csv"))
    if not table:
        return
    import meshio  # only here: a slow import that runs without snapshots do not need
    from matplotlib.collections import PolyCollection
    frames = [meshio.read(os.path.join(outdir, "vtu", f)) for f in table["file"]]
    wall = read_wall(outdir)
    lo = np.min([m.points[:, :2].min(axis=0) for m in frames], axis=0)
    hi = np.max([m.points[:, :2].max(axis=0) for m in frames], axis=0)
    wide = (hi - lo)[0] > (hi - lo)[1]
    n = len(frames)
    fig, axes = plt.subplots(n if wide else 1, 1 if wide else n, squeeze=False,
                             figsize=(10, 1.2 + 10 * n * (hi - lo)[1] / (hi - lo)[0]) if wide
                             else (1.2 + 2.6 * n, 7), layout="constrained")
    for ax, mesh, t in zip(axes.ravel(), frames, table["time"]):
        points = mesh.points[:, :2]
        polygons = [points[c] for block in mesh.cells for c in block.data]
        fragment = np.concatenate([np.ravel(v) for v in mesh.cell_data.get("fragment", [])])
        cells = PolyCollection(polygons, edgecolor="k", linewidth=0.1, zorder=2)
        if fragment.size == len(polygons):
            colour = fragment_colours(fragment)
            tab = plt.get_cmap("tab20")
            cells.set_facecolor([tab(c) if c >= 0 else (0.6, 0.6, 0.6, 1.0) for c in colour])
        ax.add_collection(cells)
        if wall is not None:
            draw_wall(ax, wall, lo, hi)
        ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), aspect="equal",
               title=f"t = {1e3 * number(t):.3g} ms")
        ax.tick_params(labelsize=7)
    fig.suptitle(f"{run['id']}: cells coloured by fragment (single cells grey)"
                 + (", the rigid plane shaded" if wall is not None else ""), fontsize=10)
    save_atomically(fig, os.path.join(outdir, "plots", run["id"] + "_snapshots.png"), dpi)
