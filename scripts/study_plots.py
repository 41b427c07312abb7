"""The plots of a study's summary.json beyond the convergence lines: the penalty sweep (error,
iterations and rate against k_p) and the spread of the error over mesh realizations (CDFs)."""
import math
import os
import textwrap

import numpy as np
from matplotlib.lines import Line2D

from plotting_common import light_grid, plt, save_atomically
from study_summary import has_mean, usable

MAX_CDF_PANELS = 12
MARKERS = "osD^v<>phX*"


def title(summary, what):
    return textwrap.fill(f"{summary['name']} ({summary['study']}): {what}", 100)


def log_limits(ax, axis, values, pad=1.25):
    values = [v for v in values if usable(v)]
    if values:
        lo, hi = min(values), max(values)
        (ax.set_xlim if axis == "x" else ax.set_ylim)(lo / pad, hi * pad)


def level_colours(levels):
    """A colour per level index, coarse (dark) to fine (light) along viridis."""
    levels = sorted(levels)
    cmap = plt.get_cmap("viridis")
    span = max(len(levels) - 1, 1)
    return {lv: cmap(0.9 * i / span) for i, lv in enumerate(levels)}


def level_sizes(groups):
    """h_avg of each level index, as the first group that has the level measured it."""
    sizes = {}
    for g in groups:
        for lv in g["levels"]:
            sizes.setdefault(lv["level"], lv["h_avg"])
    return sizes


def plot_penalty(summary, outdir, dpi):
    kp_groups = [g for g in summary["groups"] if g["kp"] is not None]
    kps = sorted({g["kp"] for g in kp_groups})
    if len(kps) < 2:
        return False  # one k_p (a patch suite, say) is no sweep
    cg_groups = [g for g in summary["groups"] if g["kp"] is None]
    formulations = list(dict.fromkeys(g["series"] for g in kp_groups))
    styles = ["-", "--", "-.", ":"]
    fstyle = {f: (styles[i % len(styles)], MARKERS[i % len(MARKERS)]) for i, f in enumerate(formulations)}
    levels = sorted({lv["level"] for g in summary["groups"] for lv in g["levels"]})
    lcol = level_colours(levels)
    level_h = level_sizes(summary["groups"])
    rated = [g for g in kp_groups if g["rate_l2"] is not None]
    ncols = 3 if rated else 2
    # Many formulations: their legend goes in a row block under the panels, not beside them.
    legend_rows = math.ceil((len(formulations) + bool(cg_groups)) / 4) if len(formulations) > 7 else 0
    fig = plt.figure(figsize=(5.2 * ncols + 2.6, 5.4 + 0.25 * legend_rows), layout="constrained")
    grid = fig.add_gridspec(2 if legend_rows else 1, ncols,
                            height_ratios=[5.4, 0.25 * legend_rows + 0.3] if legend_rows else None)
    axes = [fig.add_subplot(grid[0, i]) for i in range(ncols)]
    ax_err, ax_it = axes[0], axes[1]

    def series(f, level, key):
        pts = []
        for g in kp_groups:
            if g["series"] != f:
                continue
            for lv in g["levels"]:
                if lv["level"] == level:
                    y = lv["l2"]["mean"] if key == "l2" and lv["l2"] else lv.get(key, math.nan)
                    if math.isfinite(y):
                        pts.append((g["kp"], y))
        pts.sort()
        return np.array([p[0] for p in pts]), np.array([p[1] for p in pts])

    any_iter = False
    for f in formulations:
        ls, mk = fstyle[f]
        for level in levels:
            x, y = series(f, level, "l2")
            keep = y > 0
            if keep.any():
                ax_err.plot(x[keep], y[keep], linestyle=ls, marker=mk, color=lcol[level],
                            markersize=5, linewidth=1.4)
            x, y = series(f, level, "iterations")
            if len(x):
                any_iter = True
                ax_it.plot(x, y, linestyle=ls, marker=mk, color=lcol[level], markersize=5,
                           linewidth=1.4)
    # CG on the same levels: no k_p, so a horizontal line at its error.
    for g in cg_groups:
        for lv in g["levels"]:
            if has_mean(lv, "l2"):
                ax_err.axhline(lv["l2"]["mean"], color=lcol[lv["level"]], linestyle=":",
                               linewidth=1.2, alpha=0.9)
    ax_err.set_xscale("log")
    ax_err.set_yscale("log")
    ax_err.set_xlabel("penalty multiplier k_p (of E/h_avg; of the coercive bound for auto)")
    ax_err.set_ylabel("mean relative L2 displacement error")
    ax_err.set_title("L2 error against k_p", fontsize=10.5)
    light_grid(ax_err)
    ax_it.set_xscale("log")
    ax_it.set_xlabel("penalty multiplier k_p")
    ax_it.set_ylabel("mean iterations")
    ax_it.set_title("iterations against k_p", fontsize=10.5)
    light_grid(ax_it)
    if any_iter:
        ax_it.set_ylim(bottom=0)
        ax_it.yaxis.set_major_locator(plt.MaxNLocator(integer=True))
    else:
        ax_it.text(0.5, 0.5, "no iteration counts in summary.json", transform=ax_it.transAxes,
                   ha="center", va="center", color="0.4")
    for ax in (ax_err, ax_it):
        ax.set_xlim(kps[0] / 2, kps[-1] * 2)

    last = ax_it
    if rated:
        ax_rate = axes[2]
        for f in formulations:
            ls, mk = fstyle[f]
            gs = sorted((g for g in rated if g["series"] == f), key=lambda g: g["kp"])
            if not gs:
                continue
            x = np.array([g["kp"] for g in gs])
            y = np.array([g["rate_l2"]["value"] for g in gs])
            e = np.array([g["rate_l2"]["ci95"] for g in gs])
            ax_rate.errorbar(x, y, yerr=np.where(np.isfinite(e), e, 0), linestyle=ls, marker=mk,
                             color="black", markersize=5, linewidth=1.4, capsize=3)
        for i, g in enumerate(cg_groups):
            if g["rate_l2"] is not None:
                ax_rate.axhline(g["rate_l2"]["value"], color="tab:red", linestyle=":",
                                linewidth=1.3)
                ax_rate.annotate(f"{g['name']}: {g['rate_l2']['value']:.2f}",
                                 xy=(0.02, g["rate_l2"]["value"]),
                                 xycoords=("axes fraction", "data"), xytext=(0, 3),
                                 textcoords="offset points", fontsize=8, color="tab:red")
        ax_rate.set_xscale("log")
        ax_rate.set_xlabel("penalty multiplier k_p")
        ax_rate.set_ylabel("least-squares L2 rate (bars: 95% interval)")
        ax_rate.set_title("L2 rate against k_p", fontsize=10.5)
        light_grid(ax_rate)
        ax_rate.set_xlim(kps[0] / 2, kps[-1] * 2)
        last = ax_rate

    # Two legends beside the last panel: colour = level, line style = formulation.
    level_handles = [Line2D([], [], color=lcol[lvl], linewidth=2.5,
                            label=f"level {lvl}  (h_avg {level_h[lvl]:.3g})") for lvl in levels]
    form_handles = [Line2D([], [], color="black", linestyle=fstyle[f][0], marker=fstyle[f][1],
                           markersize=5, label=f) for f in formulations]
    if cg_groups:
        form_handles.append(Line2D([], [], color="0.3", linestyle=":", linewidth=1.2,
                                   label="cg (no k_p; error at that level)"))
    leg1 = last.legend(handles=level_handles, title="colour: level", loc="upper left",
                       bbox_to_anchor=(1.03, 1.0), fontsize=8.5, title_fontsize=9, frameon=False)
    if not legend_rows:
        last.add_artist(leg1)  # the formulation legend below replaces the axes' legend
        last.legend(handles=form_handles, title="line: formulation", loc="lower left",
                    bbox_to_anchor=(1.03, 0.0), fontsize=8.5, title_fontsize=9, frameon=False)
    else:
        ax_legend = fig.add_subplot(grid[1, :])
        ax_legend.axis("off")
        ax_legend.legend(handles=form_handles, title="line: formulation", loc="center", ncol=4,
                         fontsize=8.5, title_fontsize=9, frameon=False)
    fig.suptitle(title(summary, "penalty stiffness k_p"), fontsize=11.5)
    save_atomically(fig, os.path.join(outdir, "penalty.png"), dpi)
    return True


def plot_cdf(summary, outdir, dpi):
    groups = [g for g in summary["groups"]
              if any(lv["l2"] is not None and len(lv["l2"]["positive"]) > 1 for lv in g["levels"])]
    if not groups:
        return False
    total = len(groups)
    groups = groups[:MAX_CDF_PANELS]
    n = len(groups)
    ncols = min(n, 4)
    nrows = math.ceil(n / ncols)
    levels = sorted({lv["level"] for g in groups for lv in g["levels"]})
    lcol = level_colours(levels)
    level_h = level_sizes(groups)
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.5 * ncols + 2.2, 2.9 * nrows + 0.9),
                             layout="constrained", sharex=True, sharey=True, squeeze=False)
    xs = []
    drawn = set()
    for k, g in enumerate(groups):
        ax = axes[k // ncols][k % ncols]
        for lv in g["levels"]:
            if lv["l2"] is None or len(lv["l2"]["positive"]) < 2:
                continue
            # Divided by the level's mean: the spread shrinks with h, and on one error axis the
            # CDFs of all levels would be near-vertical steps decades apart.
            v = np.sort(lv["l2"]["positive"]) / lv["l2"]["positive"].mean()
            m = len(v)
            # Step from 0 to 1: the fraction of realizations with error <= x.
            x = np.concatenate(([v[0]], v, [v[-1]]))
            y = np.concatenate(([0.0], np.arange(1, m + 1) / m, [1.0]))
            ax.step(x, y, where="post", color=lcol[lv["level"]], linewidth=1.5)
            ax.plot(v, np.arange(1, m + 1) / m, "o", color=lcol[lv["level"]], markersize=2.5)
            xs += list(v)
            drawn.add(lv["level"])
        ax.axvline(1.0, color="0.5", linewidth=0.8, zorder=0)
        ax.set_title(g["name"], fontsize=9)
        light_grid(ax)
        ax.set_ylim(-0.03, 1.03)
        if k % ncols == 0:
            ax.set_ylabel("fraction of realizations")
        if k // ncols == nrows - 1 or k + ncols >= n:
            ax.set_xlabel("L2 error / mean L2 error of the level")
            ax.xaxis.set_tick_params(labelbottom=True)
    for k in range(n, nrows * ncols):
        axes[k // ncols][k % ncols].set_visible(False)
    if xs:
        pad = 0.05 * max(max(xs) - min(xs), 0.02)
        axes[0][0].set_xlim(min(xs) - pad, max(xs) + pad)
    handles = [Line2D([], [], color=lcol[lvl], linewidth=2.5,
                      label=f"level {lvl}\nh_avg {level_h[lvl]:.3g}") for lvl in levels if lvl in drawn]
    axes[0][ncols - 1].legend(handles=handles, title="level", loc="upper left",
                              bbox_to_anchor=(1.04, 1.0), fontsize=8.5, title_fontsize=9,
                              frameon=False)
    more = f" (first {n} of {total} groups)" if total > n else ""
    fig.suptitle(title(summary, "empirical CDF of the L2 error over the realizations of each "
                       "level" + more) + "\n(each error divided by the mean of its level; "
                 "the spread is the relative scatter over mesh realizations)", fontsize=11)
    save_atomically(fig, os.path.join(outdir, "cdf_l2.png"), dpi)
    return True
