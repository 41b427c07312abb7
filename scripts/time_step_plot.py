#!/usr/bin/python3
"""The column's fragments against the time step (column-impact-time-step): one PNG.

Usage:
  time_step_plot.py OUTDIR SCENE.json [-o PNG] [--dpi N]

Per variant of the scene (OUTDIR/<label>/results.csv), over its complete runs: the mean time
step dt and the mean number of fragments with its standard error (left), and the peak force of
the plane (right), each against dt. Variants whose runs did not break (one fragment each) are
listed in the title instead. A weighted straight line through the fragments shows the order of
the dependence. Default output: OUTDIR/time-step.png.
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import columns, light_grid, plt, read_table, save_atomically  # noqa: E402


def variant_points(outdir, label):
    """(mean dt [us], mean fragments, their standard error, mean peak plane force [MN/m], runs)."""
    table = read_table(os.path.join(outdir, label, "results.csv"))
    if table is None:
        return None
    dt, fragments, force, complete = columns(table, "dt", "fragments", "peak_wall_force",
                                             "complete")
    keep = complete > 0
    if not keep.any():
        return None
    dt, fragments, force = dt[keep], fragments[keep], force[keep]
    error = fragments.std(ddof=1) / np.sqrt(fragments.size) if fragments.size > 1 else 0.0
    return dt.mean() * 1e6, fragments.mean(), error, force.mean() / 1e6, fragments.size


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("scene")
    ap.add_argument("-o", "--output")
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args(argv)
    scene = json.load(open(args.scene))
    points, unbroken = [], []
    for variant in scene["variants"]:
        p = variant_points(args.outdir, variant["label"])
        if p is None:
            continue
        (unbroken if p[1] <= 1.0 else points).append((variant["label"], p))
    if not points:
        sys.exit(f"time_step_plot: no complete runs with fragments under {args.outdir}")
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for label, (dt, frag, err, force, runs) in points:
        left.errorbar(dt, frag, yerr=err, fmt="o", capsize=3, label=f"{label} ({runs} runs)")
        right.plot(dt, force, "o")
    dts = np.array([p[1][0] for p in points])
    if len(points) >= 2:
        frags = np.array([p[1][1] for p in points])
        weights = 1.0 / np.maximum([p[1][2] for p in points], 1e-9) ** 2
        slope, intercept = np.polyfit(dts, frags, 1, w=np.sqrt(weights))
        x = np.linspace(0.0, dts.max() * 1.05, 50)
        left.plot(x, intercept + slope * x, "k--", lw=1,
                  label=f"fit: {intercept:.1f} {slope:+.1f} dt/us")
    left.set_xlabel("time step dt [us]")
    left.set_ylabel("fragments (mean, standard error)")
    left.set_xlim(0.0, dts.max() * 1.1)
    left.legend(fontsize=8)
    right.set_xlabel("time step dt [us]")
    right.set_ylabel("peak force of the plane [MN/m]")
    right.set_xlim(0.0, dts.max() * 1.1)
    for ax in (left, right):
        light_grid(ax)
    title = scene["name"]
    if unbroken:
        title += ": unbroken in every run: " + ", ".join(label for label, _ in unbroken)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    save_atomically(fig, args.output or os.path.join(args.outdir, "time-step.png"), args.dpi)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
