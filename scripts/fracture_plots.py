#!/usr/bin/python3
"""Draws the plots of one fracture study from OUTDIR (written by `vorodg run` on a fracture scene).

Usage:
  fracture_plots.py OUTDIR [--dpi N]

Reads results.csv, curves/<id>.csv, cracks/<id>.csv and summary.json in OUTDIR and writes there,
each atomically (temporary file beside it, then renamed), printing its path:
  load_displacement.png  a panel per mesh label: every run's load (N) against displacement (mm),
                         coloured by level (coarse dark to fine light), incomplete runs dashed.
  load_cmod.png          the same against the crack mouth opening (mm).
  crack_paths.png        a panel per (mesh, level): all its runs' crack faces overlaid with low
                         alpha (open faces black, cohesive ones lighter orange), equal aspect.
  cdfs.png               empirical CDFs of peak load, dissipated energy and crack length over the
                         complete runs, a step curve per (mesh, level), with the Kolmogorov-Smirnov
                         distance to the previous level when summary.json has it.
  energy.png             the finest level's first complete run: external work W and its parts
                         against displacement, and |W - sum of the parts| / W (log, right axis).
A figure without inputs is left out (one line on stderr); the exit code is always 0.
Only the Python standard library, numpy and matplotlib (Agg) are used.
"""
import json
import math
import os
import sys

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.lines import Line2D

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import (  # noqa: E402
    columns, light_grid, number, outdir_arguments, plt, read_table, save_atomically)
from study_plots import level_colours  # noqa: E402
import statistics_plots  # noqa: E402

METRICS = (("peak_load", "peak load (N)"), ("dissipated_energy", "dissipated energy (J)"),
           ("crack_length", "crack length (m)"))
PARTS = ("elastic", "coupling", "cohesive", "dissipated", "switched")  # <part>_energy columns


TAIL_FRACTION = 0.02  # load curves are drawn until the load falls below this fraction of the peak


def skip(what, why):
    print(f"fracture_plots: {what} left out: {why}", file=sys.stderr)


def plural(n, noun):
    return f"{n} {noun}" + ("" if n == 1 else "s")


def read_groups(outdir):
    """The rows of results.csv by (mesh, level), each list in realization order."""
    table = read_table(os.path.join(outdir, "results.csv")) or {}
    groups = {}
    for r in (dict(zip(table, vals)) for vals in zip(*table.values())):
        level = number(r.get("level"))
        r["level"] = int(level) if math.isfinite(level) else -1
        r["complete"] = str(r.get("complete", "")).strip() == "1"
        for k in ("realization", "h_avg") + tuple(m for m, _ in METRICS):
            r[k] = number(r.get(k))
        if r.get("id"):
            groups.setdefault((r.get("mesh", ""), r["level"]), []).append(r)
    return {k: sorted(groups[k], key=lambda r: r["realization"]) for k in sorted(groups)}


def read_levels(outdir):
    """{(mesh, level): level object} from summary.json ({} when missing or malformed)."""
    try:
        with open(os.path.join(outdir, "summary.json")) as f:
            return {(lv["mesh"], int(lv["level"])): lv for lv in json.load(f).get("levels", [])}
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return {}


def h_of(key, runs, levels):
    h = levels.get(key, {}).get("h_avg")
    return h if isinstance(h, (int, float)) else float(np.nanmean([r["h_avg"] for r in runs]))


def group_label(key, runs, levels):
    done = sum(r["complete"] for r in runs)
    count = plural(done, "run") if done == len(runs) else f"{done} of {len(runs)} complete"
    return f"level {key[1]}, h_avg {h_of(key, runs, levels):.3g} m ({count})"


def panel_grid(n, width=5.5, height=4.2, max_cols=3):
    cols = min(n, max_cols)
    fig, axes = plt.subplots(math.ceil(n / cols), cols, squeeze=False, layout="constrained",
                             figsize=(width * cols, height * math.ceil(n / cols)))
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    return fig, list(axes.flat)


def plot_load(outdir, groups, levels, xcol, xlabel, stem, dpi):
    curves = {r["id"]: read_table(os.path.join(outdir, "curves", r["id"] + ".csv"))
              for runs in groups.values() for r in runs}
    meshes = list(dict.fromkeys(m for (m, _), runs in groups.items()
                                if any(curves[r["id"]] for r in runs)))
    if not meshes:
        return skip(stem + ".png", "no load curves")
    fig, axes = panel_grid(len(meshes))
    colour = level_colours({lv for _, lv in groups})
    for ax, mesh in zip(axes, meshes):
        mine = {k: runs for k, runs in groups.items() if k[0] == mesh}
        x_end = 0.0  # where the last curve's load falls below TAIL_FRACTION of its peak
        for key, runs in mine.items():
            for r in (r for r in runs if curves[r["id"]]):
                x, load = columns(curves[r["id"]], xcol, "load")
                carrying = np.nonzero(load >= TAIL_FRACTION * max(load.max(), 0.0))[0]
                if len(carrying):
                    x_end = max(x_end, x[min(carrying[-1] + 1, len(x) - 1)])
                ax.plot(x * 1e3, load, color=colour[key[1]], linewidth=1.0, alpha=0.85,
                        linestyle="-" if r["complete"] else "--",
                        marker="o" if len(x) < 2 else None)  # a lone point shows as a dot
        handles = [Line2D([], [], color=colour[k[1]], label=group_label(k, runs, levels))
                   for k, runs in mine.items()]
        if not all(r["complete"] for runs in mine.values() for r in runs):
            handles.append(Line2D([], [], color="0.4", linestyle="--", label="incomplete run"))
        ax.set(xlabel=xlabel, ylabel="load (N)", title=f"mesh {mesh}")
        # A long tail (the last ligament opening at nearly no load) would squeeze the peak into
        # the left edge: show the curves until they carry almost nothing.
        ax.set_xlim(left=0, right=1.1 * x_end * 1e3 if x_end > 0 else None)
        light_grid(ax)
        ax.legend(handles=handles, fontsize=8)
    save_atomically(fig, os.path.join(outdir, stem + ".png"), dpi)


def plot_cracks(outdir, groups, levels, dpi):
    cracks = {key: [read_table(os.path.join(outdir, "cracks", r["id"] + ".csv")) for r in runs]
              for key, runs in groups.items()}
    keys = [k for k, tables in cracks.items() if any(tables)]
    if not keys:
        return skip("crack_paths.png", "no crack faces")
    fig, axes = panel_grid(len(keys), width=4.5, height=4.5, max_cols=4)
    for ax, key in zip(axes, keys):
        tables = [t for t in cracks[key] if t]
        alpha = min(0.8, max(0.15, 2.0 / len(tables)))
        for t in tables:
            x0, y0, x1, y1 = columns(t, "x0", "y0", "x1", "y1")
            segs = np.stack([np.column_stack([x0, y0]), np.column_stack([x1, y1])], axis=1)
            is_open = np.array([s.strip() == "open" for s in t.get("state", [""] * len(x0))])
            for sel, colour, width, a in ((is_open, "black", 1.6, alpha),
                                          (~is_open, "tab:orange", 1.2, 0.7 * alpha)):
                ax.add_collection(LineCollection(segs[sel], colors=colour, linewidths=width,
                                                 alpha=a))
        ax.margins(0.15)
        ax.autoscale()
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(f"{key[0]}: level {key[1]}, h_avg {h_of(key, groups[key], levels):.3g} m, "
                     + plural(len(tables), "run"), fontsize=10)
        ax.set(xlabel="x (m)", ylabel="y (m)")
        light_grid(ax)
    states = (("black", "open"), ("tab:orange", "cohesive"))
    axes[0].legend(handles=[Line2D([], [], color=c, label=s) for c, s in states], fontsize=8)
    save_atomically(fig, os.path.join(outdir, "crack_paths.png"), dpi)


def ks_text(level, metric):
    ks = level.get("ks_to_previous")
    ks = ks.get(metric) if isinstance(ks, dict) else None
    d, p = (ks.get("distance"), ks.get("p_value")) if isinstance(ks, dict) else (None, None)
    real = (int, float)
    return (f"; KS to prev. {d:.2f}" + (f" (p {p:.2g})" if isinstance(p, real) else "")
            if isinstance(d, real) else "")


def complete_runs(groups):
    done = {k: [r for r in runs if r["complete"]] for k, runs in groups.items()}
    return {k: runs for k, runs in done.items() if runs}


def plot_cdfs(outdir, groups, levels, dpi):
    done = complete_runs(groups)
    if not done:
        return skip("cdfs.png", "no complete runs")
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8), layout="constrained")
    colour = level_colours({lv for _, lv in done})
    styles = dict(zip(dict.fromkeys(m for m, _ in done), ["-", "--", "-.", ":"] * 9))
    for ax, (metric, label) in zip(axes, METRICS):
        for key, runs in done.items():
            v = np.sort([r[metric] for r in runs if math.isfinite(r[metric])])
            if len(v):
                ax.step(np.concatenate([[v[0]], v]), np.arange(len(v) + 1) / len(v),
                        where="post", color=colour[key[1]], linestyle=styles[key[0]],
                        linewidth=1.4, label=f"{key[0]} L{key[1]} (n={len(v)})"
                        + ks_text(levels.get(key, {}), metric))
        ax.set(xlabel=label, ylabel="fraction of runs", ylim=(-0.02, 1.02), title=label)
        light_grid(ax)
        ax.legend(fontsize=7.5, loc="lower right")
    save_atomically(fig, os.path.join(outdir, "cdfs.png"), dpi)


def plot_energy(outdir, groups, levels, dpi):
    done = complete_runs(groups)
    keys = sorted(done, key=lambda k: (h_of(k, groups[k], levels), -k[1]))
    run = done[keys[0]][0] if keys else None  # the finest level's first complete run
    table = run and read_table(os.path.join(outdir, "curves", run["id"] + ".csv"))
    if not table:
        return skip("energy.png", "no complete run with a curve")
    d, w = columns(table, "displacement", "external_work")
    fig, ax = plt.subplots(figsize=(9, 5.5), layout="constrained")
    ax.plot(d * 1e3, w, color="black", linewidth=2.0, label="external work W")
    total = np.zeros_like(w)
    for name, c in zip(PARTS, plt.get_cmap("tab10").colors):
        (part,) = columns(table, name + "_energy")
        if not np.all(np.isnan(part)):  # older curve files lack switched_energy
            total += np.nan_to_num(part)
            ax.plot(d * 1e3, part, color=c, linewidth=1.2, label=name)
    ax.set(xlabel="displacement (mm)", ylabel="energy (J)")
    light_grid(ax)
    err = np.abs(w - total) / np.where(w > 0, w, np.nan)
    err[~(err > 0)] = np.nan  # no work yet, or exactly zero: not on a log axis
    ax2 = ax.twinx()
    ax2.set_ylabel("balance error |W - sum| / W")
    handles = ax.get_legend_handles_labels()
    if np.any(np.isfinite(err)):
        ax2.plot(d * 1e3, err, color="0.45", linestyle=":", linewidth=1.3, label="|W - sum| / W")
        ax2.set_yscale("log")
        handles = [a + b for a, b in zip(handles, ax2.get_legend_handles_labels())]
    ax.legend(*handles, fontsize=8.5, loc="center right")
    worst = np.nanmax(err) if np.any(np.isfinite(err)) else 0.0
    ax.set_title(f"energy of {run['id']} (finest level, h_avg {run['h_avg']:.3g} m); worst "
                 f"balance error {worst:.2e} (results.csv: "
                 f"{number(run.get('energy_balance_error')):.2e})", fontsize=10)
    save_atomically(fig, os.path.join(outdir, "energy.png"), dpi)


def plot_statistics(outdir, _groups, _levels, dpi):
    """The statistical report's figures (statistics_plots.py), where the scene asked for one."""
    statistics_plots.draw_all(outdir, dpi)


def main(argv):
    args = outdir_arguments(__doc__, argv)
    groups = read_groups(args.outdir)
    if not groups:
        skip("every figure", f"no runs in {os.path.join(args.outdir, 'results.csv')}")
        return 0
    levels = read_levels(args.outdir)
    plots = ((plot_load, "displacement", "displacement (mm)", "load_displacement"),
             (plot_load, "cmod", "CMOD (mm)", "load_cmod"),
             (plot_cracks,), (plot_cdfs,), (plot_energy,), (plot_statistics,))
    for plot, *extra in plots:
        try:
            plot(args.outdir, groups, levels, *extra, dpi=args.dpi)
        except Exception as e:  # one bad figure must not cost the others
            plt.close("all")
            skip(f"a figure of {plot.__name__}", f"{type(e).__name__}: {e}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
