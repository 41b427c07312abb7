#!/usr/bin/python3
"""Draws a study's statistical convergence over its mesh levels (statistical-levels.csv,
statistical-convergence.csv and results.csv in OUTDIR, written by a scene with `statistics`).

One figure per mesh block and quantity, OUTDIR/plots/statistics-<mesh>-<quantity>.png: left, each
level's empirical CDF of the quantity over its complete runs with its Dvoretzky-Kiefer-Wolfowitz
band (the half-width the report computed); right, each level's mean with its interval against
h_avg, and for levels that share a random field E|q_h - q_h/2| with its interval at the coarser
level's h. Nothing is recomputed but the CDF's steps.
"""
import os
import sys

import numpy as np

from plotting_common import (InputError, columns, light_grid, outdir_arguments, plt, read_table,
                             save_atomically)


def rows_of(table, mesh, quantity):
    """The indices of a statistics table's rows for one (mesh, quantity)."""
    return [i for i, (m, q) in enumerate(zip(table["mesh"], table["quantity"]))
            if m == mesh and q == quantity]


def level_values(results, mesh, quantity, levels):
    """The quantity over the complete runs of `mesh` at each of `levels` (level indices), sorted."""
    if quantity not in results:
        raise InputError(f"results.csv: no column {quantity}")
    level, value, complete = columns(results, "level", quantity, "complete")
    mine = np.array([m == mesh for m in results["mesh"]]) & (complete == 1) & np.isfinite(value)
    return [np.sort(value[mine & (level == lv)]) for lv in levels]


def draw(outdir, results, levels, steps, mesh, quantity, dpi):
    rows = rows_of(levels, mesh, quantity)
    index, h, mean, low, high, band = (c[rows] for c in columns(
        levels, "level", "h_avg", "mean", "mean low", "mean high", "CDF band +-"))
    samples = level_values(results, mesh, quantity, index)
    fig, (cdf, trend) = plt.subplots(1, 2, figsize=(10, 4))
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, len(h)))
    for values, hk, eps, colour in zip(samples, h, band, colours):
        f = np.arange(1, len(values) + 1) / len(values)
        cdf.step(values, f, where="post", color=colour, label=f"h = {hk:.3g} ({len(values)} runs)")
        cdf.fill_between(values, np.clip(f - eps, 0, 1), np.clip(f + eps, 0, 1), step="post",
                         color=colour, alpha=0.15, linewidth=0)
    cdf.set_xlabel(quantity)
    cdf.set_ylabel("empirical CDF (95 % DKW band)")
    cdf.legend(fontsize=8)
    light_grid(cdf)
    trend.errorbar(h, mean, yerr=[mean - low, high - mean], marker="o", capsize=3, label="mean")
    srows = rows_of(steps, mesh, quantity)
    if srows and "E|D|" in steps:
        hs, d, dlo, dhi = (c[srows] for c in columns(steps, "h", "E|D|", "E|D| low", "E|D| high"))
        if np.isfinite(d).any():
            trend.errorbar(hs, d, yerr=[d - dlo, dhi - d], marker="s", capsize=3,
                           label="E|q_h - q_h/2| (at h)")
    trend.set_xscale("log")
    trend.set_xlabel("h_avg")
    trend.set_ylabel(quantity)
    trend.legend(fontsize=8)
    light_grid(trend)
    fig.suptitle(f"{mesh}: {quantity}", fontsize=10)
    fig.tight_layout()
    name = "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in f"{mesh}-{quantity}")
    save_atomically(fig, os.path.join(outdir, "plots", f"statistics-{name}.png"), dpi)


def draw_all(outdir, dpi):
    """Every figure of OUTDIR's statistical report; nothing when the study wrote none."""
    levels = read_table(os.path.join(outdir, "statistical-levels.csv"))
    if levels is None:
        return
    steps = read_table(os.path.join(outdir, "statistical-convergence.csv"))
    results = read_table(os.path.join(outdir, "results.csv"))
    if steps is None or results is None:
        raise InputError(f"{outdir}: expected statistical-convergence.csv and results.csv beside "
                         "statistical-levels.csv")
    os.makedirs(os.path.join(outdir, "plots"), exist_ok=True)
    for mesh, quantity in dict.fromkeys(zip(levels["mesh"], levels["quantity"])):
        draw(outdir, results, levels, steps, mesh, quantity, dpi)


def main(argv):
    args = outdir_arguments(__doc__, argv)
    if read_table(os.path.join(args.outdir, "statistical-levels.csv")) is None:
        raise InputError(f"{args.outdir}: no statistical-levels.csv (a scene without statistics)")
    draw_all(args.outdir, args.dpi)


if __name__ == "__main__":
    try:
        main(sys.argv[1:])
    except InputError as e:
        print(f"statistics_plots.py: {e}", file=sys.stderr)
        sys.exit(2)
