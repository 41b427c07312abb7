#!/usr/bin/python3
"""Draws the plots of one study from OUTDIR/summary.json (written by the study runner).

Usage:
  plot_study.py OUTDIR [--dpi N]

Writes into OUTDIR, each atomically (temporary file beside it, then renamed), printing its path:
  convergence_l2.png      mean relative L2 displacement error against mean h_avg, one series per
                          group (mesh and variant), drawn when some group has two mesh sizes;
                          bars from the smallest to the largest error over the realizations; the
                          runner's least-squares line (from summary.json) through them; legend:
                          that rate with its 95% interval, and the published rate if there is one.
  convergence_energy.png  the same for the energy-norm error, when any level has one.
  penalty.png             when the groups span two or more k_p: mean L2 error against k_p, one
                          line per formulation and level (the CG groups of the same study as dotted
                          horizontal lines); mean iterations against k_p; and, when the groups
                          have fitted rates, the L2 rate against k_p.
  cdf_l2.png              empirical CDF of the L2 error over realizations, one small panel per
                          group (at most 12) and one line per level, each error divided by the
                          mean of its level (so levels decades apart share one axis); left out
                          when no level has more than one realization.
  tradeoff.png            error against wall time, from tradeoff.json (trade-off studies).
  extremes.png            from extremes.csv instead of summary.json (extremes studies).
The format of summary.json is described in study_summary.py. A group without a rate in it is
drawn without a fitted line (the plots never fit).

Exit codes: 0 success, 2 missing or malformed summary.json (one line on stderr), 1 anything else.
Only the Python standard library, numpy and matplotlib (Agg) are used.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import (  # noqa: E402
    InputError, label_minor_ticks, light_grid, outdir_arguments, plt, save_atomically)
from penalty_edges_plot import plot_penalty_edges  # noqa: E402
from study_plots import MARKERS, log_limits, plot_cdf, plot_penalty, title  # noqa: E402
from study_summary import has_mean, is_number, read_summary, usable  # noqa: E402
from tradeoff_extremes_plots import plot_extremes, plot_tradeoff  # noqa: E402

# (key in a level, key of the group's rate, file stem, axis label, slope of the reference line)
NORMS = (("l2", "rate_l2", "convergence_l2", "relative L2 displacement error", 2.0),
         ("energy", "rate_energy", "convergence_energy", "relative energy-norm error", 1.0))


def rate_text(rate):
    if rate is None:
        return "no rate"
    text = f"rate {rate['value']:.2f}"
    if math.isfinite(rate["ci95"]):
        text += f" \u00b1 {rate['ci95']:.2f}"
    return text


def failed_text(group):
    runs = sum(lv["runs"] for lv in group["levels"] if math.isfinite(lv["runs"]))
    failed = sum(lv["failed"] for lv in group["levels"] if math.isfinite(lv["failed"]))
    return f"; {failed:g} of {runs:g} runs failed" if failed > 0 else ""


def colours(n):
    cmap = plt.get_cmap("tab10" if n <= 10 else "tab20")
    return [cmap(i % cmap.N) for i in range(n)]


def legend_label(g, norm, rate):
    label = f"{g['name']}: {rate_text(rate)}"
    pub = g["published"].get("l2_rate" if norm == "l2" else "energy_rate")
    if is_number(pub):
        label += f"; published {pub:.2f}"
    return label + failed_text(g)


def draw_group(ax, g, norm, rate_key, style, offset):
    """The group's level means with their spread, and the runner's fitted line where summary.json
    has its intercept (without one, the means joined by a thin line). Returns the legend handle,
    whether a fit was drawn, the h drawn, the errors drawn and the smallest error per level."""
    lvs = [lv for lv in g["levels"] if has_mean(lv, norm)]
    h = np.array([lv["h_avg"] for lv in lvs])
    st = [lv[norm] for lv in lvs]
    mean = np.array([s["mean"] for s in st])
    lo = np.minimum([s["min"] if usable(s["min"]) else s["mean"] for s in st], mean)
    hi = np.maximum([s["max"] if math.isfinite(s["max"]) else s["mean"] for s in st], mean)
    rate = g[rate_key]
    fitted = rate is not None and math.isfinite(rate["intercept"]) and len(h) > 1
    colour, marker = style
    handle = ax.errorbar(h * offset, mean, yerr=[mean - lo, hi - mean] if np.any(hi > lo) else None,
                         fmt=marker, linestyle="none" if fitted else "-", color=colour,
                         markersize=5, linewidth=0.8, elinewidth=1.1, capsize=3)
    errors = list(lo) + list(hi)
    if fitted:
        ends = np.array([h.min(), h.max()])
        line = np.exp(rate["intercept"]) * ends ** rate["value"]
        handle = (handle, ax.plot(ends * offset, line, color=colour, linewidth=1.4)[0])
        errors += list(line)
    return handle, fitted, list(h * offset), errors, lo


def plot_convergence(summary, norm, rate_key, stem, ylabel, theory, outdir, dpi):
    groups = [g for g in summary["groups"] if any(has_mean(lv, norm) for lv in g["levels"])]
    if not any(len({lv["h_avg"] for lv in g["levels"] if has_mean(lv, norm)}) > 1 for g in groups):
        return False  # no group has two mesh sizes: nothing converges (a patch suite, say)
    n = len(groups)
    legend_rows = math.ceil(n / (2 if n > 7 else 1)) + 1
    # The legend sits below the axes: the figure grows with it so that the axes keep their size.
    fig, ax = plt.subplots(figsize=(8.5, max(6.8, 5.0 + 0.22 * legend_rows)), layout="constrained")
    cols = colours(n)
    all_h, all_e, floor, handles, labels = [], [], [], [], []
    h_min = min(lv["h_avg"] for g in groups for lv in g["levels"] if has_mean(lv, norm))
    # Groups on the same meshes share h_avg exactly; a small sideways offset keeps their error
    # bars apart (at most ±3% in h, which does not move a line's slope).
    many_runs = any(len(lv[norm]["values"]) > 1 for g in groups for lv in g["levels"] if lv[norm])
    dodge = n > 1 and many_runs
    any_fit = False
    for i, g in enumerate(groups):
        offset = math.exp(0.06 * ((i - (n - 1) / 2) / (n - 1))) if dodge else 1.0
        style = (cols[i], MARKERS[i % len(MARKERS)])
        handle, fitted, hs, es, lo = draw_group(ax, g, norm, rate_key, style, offset)
        handles.append(handle)
        labels.append(legend_label(g, norm, g[rate_key]))
        any_fit |= fitted
        all_h += hs
        all_e += es
        floor += [e / (h / offset / h_min) ** theory for e, h in zip(lo, hs)]
    # Reference slope under all the data.
    hs = np.array([min(all_h), max(all_h)])
    c = 0.5 * min(f for f in floor if usable(f))
    handles += ax.plot(hs, c * (hs / h_min) ** theory, color="0.45", linestyle="--", linewidth=1.0)
    labels.append(f"slope {theory:g} (theory for linear-complete elements)")
    all_e += list(c * (hs / h_min) ** theory)
    ax.set_xscale("log")
    ax.set_yscale("log")
    log_limits(ax, "x", all_h, 1.15)
    log_limits(ax, "y", all_e, 1.4)
    label_minor_ticks(ax.xaxis, min(all_h), max(all_h))
    ax.set_xlabel("h_avg (mean cell size)")
    ax.set_ylabel(ylabel)
    light_grid(ax)
    sub = ("markers: mean over the realizations; bars: smallest to largest error"
           if many_runs else "markers: one realization per level")
    if any_fit:
        sub += "; solid lines: the least-squares fits"
    if dodge:
        sub += ("\n(series shifted sideways by up to \u00b13% in h so that their bars do not"
                " overlap)")
    ax.set_title(title(summary, ylabel.replace("relative ", "") + " against h_avg") + "\n" + sub,
                 fontsize=10.5)
    ax.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, -0.11), fontsize=8.5,
              ncol=2 if n > 7 else 1, frameon=False, title_fontsize=8.5,
              title="mesh, variant: least-squares rate \u00b1 95% interval")
    save_atomically(fig, os.path.join(outdir, stem + ".png"), dpi)
    return True


def main(argv):
    args = outdir_arguments(__doc__, argv)
    if plot_extremes(args.outdir, args.dpi):
        return 0
    try:
        summary = read_summary(os.path.join(args.outdir, "summary.json"))
    except InputError as e:
        print(f"plot_study: {e}", file=sys.stderr)
        return 2
    drawn = [plot_convergence(summary, *norm, args.outdir, args.dpi) for norm in NORMS]
    drawn.append(plot_penalty(summary, args.outdir, args.dpi))
    drawn.append(plot_penalty_edges(args.outdir, args.dpi))
    drawn.append(plot_cdf(summary, args.outdir, args.dpi))
    drawn.append(plot_tradeoff(args.outdir, args.dpi))
    if not any(drawn):
        print(f"plot_study: nothing to plot for {summary['name']}: no group has two mesh sizes "
              "or two k_p, and no level has two realizations", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
