#!/usr/bin/python3
"""Draws a time-refinement study (time.refinement) from OUTDIR/time-refinement.csv.

Usage:
  time_refinement_plot.py OUTDIR [--dpi N]

Writes OUTDIR/plots/time_refinement.png: one panel per headline measure that the study
recorded (fragments, largest fragment, mass in single cells, broken edges near the impact, rear
strike, the wall's impulse, its force over a cell's transit time, rebound, contact time), each
against the step as a fraction of the default one, with the standard error of the mean over the
realizations, one line per refined part and mesh level. A measure converged in the step is flat
towards the left of each panel.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import (  # noqa: E402
    InputError, columns, light_grid, outdir_arguments, plt, read_table, save_atomically)

HEADLINES = [("fragments", "fragments", 1.0), ("max_fragment_mass_fraction", "largest fragment [%]", 100.0),
             ("single_cell_mass_fraction", "mass in single cells [%]", 100.0),
             ("broken_near_impact", "broken edges near the impact [%]", 100.0),
             ("rear_strike_time", "rear strike [ms]", 1e3), ("wall_impulse", "wall impulse [N s/m]", 1.0),
             ("peak_wall_force_window", "wall force over h/c [MN/m]", 1e-6),
             ("rebound_velocity", "rebound speed [m/s]", 1.0), ("contact_time", "contact time [ms]", 1e3)]


def series(table):
    """{measure: {(group, mesh, level): [(fraction, mean, error)]}} from the CSV's rows."""
    out = {}
    # Columns without a value in any row (std_error with one realization) are not written.
    fraction, mean, error = columns(table, "fraction", "mean", "std_error")
    for i, measure in enumerate(table["measure"]):
        key = (table["group"][i], table["mesh"][i], table["level"][i])
        point = (fraction[i], mean[i], error[i])
        out.setdefault(measure, {}).setdefault(key, []).append(point)
    return out


def main(argv):
    args = outdir_arguments(__doc__, argv)
    table = read_table(os.path.join(args.outdir, "time-refinement.csv"))
    if table is None:
        raise InputError(f"{args.outdir}/time-refinement.csv: missing or empty")
    data = series(table)
    shown = [h for h in HEADLINES if h[0] in data]
    if not shown:
        raise InputError(f"{args.outdir}/time-refinement.csv: none of the headline measures")
    cols = min(3, len(shown))
    rows = math.ceil(len(shown) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.3 * rows), squeeze=False)
    for ax, (measure, title, scale) in zip(axes.flat, shown):
        for (group, mesh, level), points in sorted(data[measure].items()):
            points.sort()
            f = [p[0] for p in points]
            m = [scale * p[1] for p in points]
            e = [scale * p[2] if math.isfinite(p[2]) else 0.0 for p in points]
            ax.errorbar(f, m, yerr=e, marker="o", capsize=3, label=f"{group} L{level}")
        ax.set_xscale("log", base=2)
        ax.set_xlabel("step / default step")
        ax.set_title(title, fontsize=10)
        light_grid(ax)
    for ax in list(axes.flat)[len(shown):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=7)
    fig.suptitle(os.path.basename(os.path.normpath(args.outdir)) + ": time refinement", fontsize=11)
    fig.tight_layout()
    os.makedirs(os.path.join(args.outdir, "plots"), exist_ok=True)
    save_atomically(fig, os.path.join(args.outdir, "plots", "time_refinement.png"), args.dpi)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except InputError as e:
        sys.exit(f"time_refinement_plot: {e}")
