#!/usr/bin/python3
"""Draws the plots of one study from OUTDIR/summary.json (written by the study runner).

Usage:
  plot_study.py OUTDIR [--dpi N]

Writes into OUTDIR, each atomically (temporary file beside it, then renamed), printing its path:
  convergence_l2.png      mean relative L2 displacement error against mean h_avg, one line per
                          group (variant), drawn when some group has two mesh sizes; bars from the smallest to the largest error over the
                          realizations; legend: least-squares rate with its 95% interval, and
                          the published rate when the group has one.
  convergence_energy.png  the same for the energy-norm error, when any level has one.
  penalty.png             when groups carry "kp": mean L2 error against k_p, one line per
                          formulation and level (the CG groups of the same study as dotted
                          horizontal lines); mean iterations against k_p; and, when the groups
                          have fitted rates, the L2 rate against k_p.
  cdf_l2.png              empirical CDF of the L2 error over realizations, one small panel per
                          group (at most 12) and one line per level, each error divided by the
                          mean of its level (so levels decades apart share one axis); left out
                          when no level has more than one realization.

summary.json:
  {"scene": {"name": ..., "study": ..., ...},
   "groups": [{"variant": ..., "formulation": ..., "kp": ... (optional),
               "levels": [{"level": ..., "h_avg": ..., "dofs": ..., "runs": ..., "failed": ...,
                           "l2": {"mean", "std", "min", "max", "values": [...]},
                           "energy": {...} (optional), "iterations": {"mean"}, "seconds": {"mean"}}],
               "rate_l2": {"value", "ci95", ...} (optional), "rate_energy": {...} (optional),
               "published": {"l2_rate", "source"} (optional)}]}
A level whose errors are missing, null, zero or negative is left out of the plots (a failed
level). A group with no "rate_l2" gets a least-squares fit here (marked "fit here").

Exit codes: 0 success, 2 missing or malformed summary.json (one line on stderr), 1 anything else.
Only the Python standard library, numpy and matplotlib (Agg) are used.
"""
import argparse
import json
import math
import os
import sys
import textwrap

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import plt, save_atomically  # noqa: E402
from plot_convergence import label_minor_ticks  # noqa: E402

MAX_CDF_PANELS = 12
# (key in a level, key of the group's rate, file stem, axis label, slope of the reference line)
NORMS = (("l2", "rate_l2", "convergence_l2", "relative L2 displacement error", 2.0),
         ("energy", "rate_energy", "convergence_energy", "relative energy-norm error", 1.0))
MARKERS = "osD^v<>phX*"


class InputError(Exception):
    pass


# --------------------------------------------------------------------------------------------
# Input


def is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def num(x):
    """A float, or NaN for a missing/null/non-numeric value."""
    return float(x) if is_number(x) else math.nan


def usable(e):
    return math.isfinite(e) and e > 0


def read_stats(raw, where):
    """A level's error statistics {mean, min, max, values} (NaN where absent); None when the
    entry is missing or null (a level whose runs all failed)."""
    if raw is None:
        return None
    if not isinstance(raw, dict):
        raise InputError(f"{where}: expected an object with mean/min/max/values")
    values = raw.get("values")
    if values is None:
        values = []
    if not isinstance(values, list):
        raise InputError(f"{where}.values: expected a list")
    vals = np.array([num(v) for v in values], dtype=float)
    vals = vals[np.isfinite(vals)]
    pos = vals[vals > 0]
    mean, lo, hi = num(raw.get("mean")), num(raw.get("min")), num(raw.get("max"))
    if not math.isfinite(mean) and len(vals):
        mean = float(vals.mean())
    if not math.isfinite(lo) and len(vals):
        lo = float(vals.min())
    if not math.isfinite(hi) and len(vals):
        hi = float(vals.max())
    return {"mean": mean, "min": lo, "max": hi, "values": vals, "positive": pos}


def mean_of(raw):
    return num(raw.get("mean")) if isinstance(raw, dict) else math.nan


def read_rate(raw):
    if isinstance(raw, dict) and is_number(raw.get("value")) and math.isfinite(raw["value"]):
        return {"value": float(raw["value"]), "ci95": num(raw.get("ci95"))}
    return None


def read_summary(path):
    try:
        with open(path) as f:
            data = json.load(f)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: not valid JSON: {e}") from None
    if not isinstance(data, dict):
        raise InputError(f"{path}: expected a JSON object at the top")
    scene = data.get("scene")
    if not isinstance(scene, dict):
        raise InputError(f"{path}: \"scene\" must be an object")
    raw_groups = data.get("groups")
    if not isinstance(raw_groups, list) or not raw_groups:
        raise InputError(f"{path}: \"groups\" must be a non-empty list")
    groups = []
    for gi, g in enumerate(raw_groups):
        where = f"{path}: groups[{gi}]"
        if not isinstance(g, dict):
            raise InputError(f"{where}: expected an object")
        variant = g.get("variant")
        if not isinstance(variant, str) or not variant:
            raise InputError(f"{where}: \"variant\" must be a non-empty string")
        formulation = g.get("formulation")
        formulation = formulation if isinstance(formulation, str) and formulation else variant
        kp = g.get("kp")
        if kp is not None and not (is_number(kp) and kp >= 0 and math.isfinite(kp)):
            raise InputError(f"{where} ({variant}): \"kp\" must be a number >= 0, found {kp!r}")
        if kp == 0:
            kp = None  # no penalty: on the k_p plots like CG, a reference line
        raw_levels = g.get("levels")
        if not isinstance(raw_levels, list):
            raise InputError(f"{where} ({variant}): \"levels\" must be a list")
        levels = []
        for li, lv in enumerate(raw_levels):
            lwhere = f"{where}.levels[{li}]"
            if not isinstance(lv, dict):
                raise InputError(f"{lwhere}: expected an object")
            h = lv.get("h_avg")
            if not (is_number(h) and h > 0 and math.isfinite(h)):
                if lv.get("l2") is None:
                    continue  # every run of the level failed: no mesh size, no error
                raise InputError(f"{lwhere}: \"h_avg\" must be a positive number, found {h!r}")
            level = lv.get("level", li)
            if not is_number(level):
                raise InputError(f"{lwhere}: \"level\" must be a number, found {level!r}")
            levels.append({
                "level": int(level), "h_avg": float(h), "dofs": num(lv.get("dofs")),
                "runs": num(lv.get("runs")), "failed": num(lv.get("failed")),
                "l2": read_stats(lv.get("l2"), f"{lwhere}.l2"),
                "energy": read_stats(lv.get("energy"), f"{lwhere}.energy"),
                "iterations": mean_of(lv.get("iterations")),
                "seconds": mean_of(lv.get("seconds")),
            })
        levels.sort(key=lambda r: -r["h_avg"])
        published = g.get("published") if isinstance(g.get("published"), dict) else {}
        groups.append({
            "variant": variant, "formulation": formulation,
            "kp": float(kp) if kp is not None else None, "levels": levels,
            "rate_l2": read_rate(g.get("rate_l2")), "rate_energy": read_rate(g.get("rate_energy")),
            "published": published,
        })
    if not any(has_mean(lv, "l2") for g in groups for lv in g["levels"]):
        raise InputError(f"{path}: no level has a positive L2 error")
    name = scene.get("name") if isinstance(scene.get("name"), str) else "unnamed scene"
    study = scene.get("study") if isinstance(scene.get("study"), str) else "study"
    return {"name": name, "study": study, "scene": scene, "groups": groups}


def has_mean(lv, norm):
    return lv[norm] is not None and usable(lv[norm]["mean"])


# --------------------------------------------------------------------------------------------
# Fits and labels

# Two-sided 95% quantiles of Student's t for 1..30 degrees of freedom.
T95 = (12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179,
       2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
       2.060, 2.056, 2.052, 2.048, 2.045, 2.042)


def fit_here(group, norm):
    """Least-squares slope of log(error) against log(h_avg) over every realization (or over the
    level means where there are no values) with its 95% half-interval; None if undefined."""
    xs, ys = [], []
    for lv in group["levels"]:
        st = lv[norm]
        if st is None:
            continue
        vals = st["positive"] if len(st["positive"]) else ([st["mean"]] if usable(st["mean"]) else [])
        xs += [math.log(lv["h_avg"])] * len(vals)
        ys += [math.log(v) for v in vals]
    if len(set(xs)) < 2:
        return None
    x, y = np.array(xs), np.array(ys)
    slope, intercept = np.polyfit(x, y, 1)
    n = len(x)
    ci = math.nan
    if n > 2:
        resid = y - (slope * x + intercept)
        se = math.sqrt(float(resid @ resid) / (n - 2) / float((x - x.mean()) @ (x - x.mean())))
        ci = (T95[n - 3] if n - 2 <= len(T95) else 1.96) * se
    return {"value": float(slope), "ci95": ci}


def rate_text(rate, here):
    if rate is None:
        return "no rate"
    text = f"rate {rate['value']:.2f}"
    if math.isfinite(rate["ci95"]):
        text += f" \u00b1 {rate['ci95']:.2f}"
    return text + (", fit here" if here else "")


def failed_text(group):
    runs = sum(lv["runs"] for lv in group["levels"] if math.isfinite(lv["runs"]))
    failed = sum(lv["failed"] for lv in group["levels"] if math.isfinite(lv["failed"]))
    return f"; {failed:g} of {runs:g} runs failed" if failed > 0 else ""


def colours(n):
    cmap = plt.get_cmap("tab10" if n <= 10 else "tab20")
    return [cmap(i % cmap.N) for i in range(n)]


def level_colours(levels):
    """A colour per level index, coarse (dark) to fine (light) along viridis."""
    levels = sorted(levels)
    cmap = plt.get_cmap("viridis")
    span = max(len(levels) - 1, 1)
    return {lv: cmap(0.9 * i / span) for i, lv in enumerate(levels)}


def title(summary, what):
    return textwrap.fill(f"{summary['name']} ({summary['study']}): {what}", 100)


def log_limits(ax, axis, values, pad=1.25):
    values = [v for v in values if usable(v)]
    if values:
        lo, hi = min(values), max(values)
        (ax.set_xlim if axis == "x" else ax.set_ylim)(lo / pad, hi * pad)


# --------------------------------------------------------------------------------------------
# Plots


def plot_convergence(summary, norm, rate_key, stem, ylabel, theory, outdir, dpi):
    groups = [g for g in summary["groups"] if any(has_mean(lv, norm) for lv in g["levels"])]
    if not any(len({lv["h_avg"] for lv in g["levels"] if has_mean(lv, norm)}) > 1 for g in groups):
        return False  # no group has two mesh sizes: nothing converges (a patch suite, say)
    fig, ax = plt.subplots(figsize=(8.5, 6.8), layout="constrained")
    cols = colours(len(groups))
    all_h, all_e, floor = [], [], []
    h_min = min(lv["h_avg"] for g in groups for lv in g["levels"] if has_mean(lv, norm))
    # Groups on the same meshes share h_avg exactly; a small sideways offset keeps their error
    # bars apart (at most ±3% in h, which does not move a line's slope).
    n = len(groups)
    many_runs = any(len(lv[norm]["values"]) > 1 for g in groups for lv in g["levels"] if lv[norm])
    dodge = n > 1 and many_runs
    offsets = [math.exp(0.06 * ((i - (n - 1) / 2) / (n - 1))) if dodge else 1.0 for i in range(n)]
    for i, g in enumerate(groups):
        lvs = [lv for lv in g["levels"] if has_mean(lv, norm)]
        h = np.array([lv["h_avg"] for lv in lvs])
        mean = np.array([lv[norm]["mean"] for lv in lvs])
        lo = np.array([lv[norm]["min"] if usable(lv[norm]["min"]) else lv[norm]["mean"] for lv in lvs])
        hi = np.array([lv[norm]["max"] if math.isfinite(lv[norm]["max"]) else lv[norm]["mean"] for lv in lvs])
        lo, hi = np.minimum(lo, mean), np.maximum(hi, mean)
        rate, here = g[rate_key], False
        if rate is None:
            rate, here = fit_here(g, norm), True
        label = f"{g['variant']}: {rate_text(rate, here)}"
        pub = g["published"].get("l2_rate" if norm == "l2" else "energy_rate")
        if is_number(pub):
            label += f"; published {pub:.2f}"
        label += failed_text(g)
        spread = np.any(hi > lo)
        ax.errorbar(h * offsets[i], mean, yerr=[mean - lo, hi - mean] if spread else None,
                    fmt="-" + MARKERS[i % len(MARKERS)], color=cols[i], markersize=5,
                    linewidth=1.4, elinewidth=1.1, capsize=3, label=label)
        all_h += list(h * offsets[i])
        all_e += list(lo) + list(hi)
        floor += list(lo / (h / h_min) ** theory)
    # Reference slope under all the data.
    hs = np.array([min(all_h), max(all_h)])
    c = 0.5 * min(f for f in floor if usable(f))
    ax.plot(hs, c * (hs / h_min) ** theory, color="0.45", linestyle="--", linewidth=1.0,
            label=f"slope {theory:g} (theory for linear-complete elements)")
    all_e += list(c * (hs / h_min) ** theory)
    ax.set_xscale("log")
    ax.set_yscale("log")
    log_limits(ax, "x", all_h, 1.15)
    log_limits(ax, "y", all_e, 1.4)
    label_minor_ticks(ax.xaxis, min(all_h), max(all_h))
    ax.set_xlabel("h_avg (mean cell size)")
    ax.set_ylabel(ylabel)
    ax.grid(which="major", alpha=0.35)
    ax.grid(which="minor", alpha=0.12)
    sub = ("markers: mean over the realizations; bars: smallest to largest error"
           if many_runs else "one realization per level")
    if dodge:
        sub += "\n(lines shifted sideways by up to \u00b13% in h so that their bars do not overlap)"
    ax.set_title(title(summary, ylabel.replace("relative ", "") + " against h_avg") + "\n" + sub,
                 fontsize=10.5)
    handles, labels = ax.get_legend_handles_labels()
    order = sorted(range(len(labels)), key=lambda k: labels[k].startswith("slope "))
    ax.legend([handles[k] for k in order], [labels[k] for k in order], loc="upper center",
              bbox_to_anchor=(0.5, -0.11), fontsize=8.5, ncol=2 if n > 7 else 1, frameon=False,
              title="least-squares rate \u00b1 95% interval",
              title_fontsize=8.5)
    save_atomically(fig, os.path.join(outdir, stem + ".png"), dpi)
    return True


def plot_penalty(summary, outdir, dpi):
    kp_groups = [g for g in summary["groups"] if g["kp"] is not None]
    if not kp_groups:
        return False
    cg_groups = [g for g in summary["groups"] if g["kp"] is None]
    formulations = list(dict.fromkeys(g["formulation"] for g in kp_groups))
    styles = ["-", "--", "-.", ":"]
    fstyle = {f: (styles[i % len(styles)], MARKERS[i % len(MARKERS)]) for i, f in enumerate(formulations)}
    levels = sorted({lv["level"] for g in summary["groups"] for lv in g["levels"]})
    lcol = level_colours(levels)
    level_h = {}
    for g in summary["groups"]:
        for lv in g["levels"]:
            level_h.setdefault(lv["level"], lv["h_avg"])
    rated = [g for g in kp_groups if g["rate_l2"] is not None]
    ncols = 3 if rated else 2
    fig, axes = plt.subplots(1, ncols, figsize=(5.2 * ncols + 2.6, 5.4), layout="constrained")
    ax_err, ax_it = axes[0], axes[1]
    kps = sorted({g["kp"] for g in kp_groups})

    def series(f, level, key):
        pts = []
        for g in kp_groups:
            if g["formulation"] != f:
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
    ax_err.set_xlabel("penalty stiffness k_p")
    ax_err.set_ylabel("mean relative L2 displacement error")
    ax_err.set_title("L2 error against k_p", fontsize=10.5)
    ax_err.grid(which="major", alpha=0.35)
    ax_err.grid(which="minor", alpha=0.12)
    ax_it.set_xscale("log")
    ax_it.set_xlabel("penalty stiffness k_p")
    ax_it.set_ylabel("mean iterations")
    ax_it.set_title("iterations against k_p", fontsize=10.5)
    ax_it.grid(which="major", alpha=0.35)
    ax_it.grid(which="minor", alpha=0.12)
    if any_iter:
        ax_it.set_ylim(bottom=0)
        ax_it.yaxis.set_major_locator(plt.MaxNLocator(integer=True))
    else:
        ax_it.text(0.5, 0.5, "no iteration counts in summary.json", transform=ax_it.transAxes,
                   ha="center", va="center", color="0.4")
    for ax in (ax_err, ax_it):
        if len(kps) > 1:
            ax.set_xlim(kps[0] / 2, kps[-1] * 2)

    last = ax_it
    if rated:
        ax_rate = axes[2]
        for f in formulations:
            ls, mk = fstyle[f]
            gs = sorted((g for g in rated if g["formulation"] == f), key=lambda g: g["kp"])
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
                ax_rate.annotate(f"{g['variant']}: {g['rate_l2']['value']:.2f}",
                                 xy=(0.02, g["rate_l2"]["value"]),
                                 xycoords=("axes fraction", "data"), xytext=(0, 3),
                                 textcoords="offset points", fontsize=8, color="tab:red")
        ax_rate.set_xscale("log")
        ax_rate.set_xlabel("penalty stiffness k_p")
        ax_rate.set_ylabel("least-squares L2 rate (bars: 95% interval)")
        ax_rate.set_title("L2 rate against k_p", fontsize=10.5)
        ax_rate.grid(which="major", alpha=0.35)
        ax_rate.grid(which="minor", alpha=0.12)
        if len(kps) > 1:
            ax_rate.set_xlim(kps[0] / 2, kps[-1] * 2)
        last = ax_rate

    # Two legends beside the last panel: colour = level, line style = formulation.
    from matplotlib.lines import Line2D
    level_handles = [Line2D([], [], color=lcol[lvl], linewidth=2.5,
                            label=f"level {lvl}  (h_avg {level_h[lvl]:.3g})") for lvl in levels]
    form_handles = [Line2D([], [], color="black", linestyle=fstyle[f][0], marker=fstyle[f][1],
                           markersize=5, label=f) for f in formulations]
    if cg_groups:
        form_handles.append(Line2D([], [], color="0.3", linestyle=":", linewidth=1.2,
                                   label="cg (no k_p; error at that level)"))
    leg1 = last.legend(handles=level_handles, title="colour: level", loc="upper left",
                       bbox_to_anchor=(1.03, 1.0), fontsize=8.5, title_fontsize=9, frameon=False)
    last.add_artist(leg1)
    last.legend(handles=form_handles, title="line: formulation", loc="lower left",
                bbox_to_anchor=(1.03, 0.0), fontsize=8.5, title_fontsize=9, frameon=False)
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
    level_h = {}
    for g in groups:
        for lv in g["levels"]:
            level_h.setdefault(lv["level"], lv["h_avg"])
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
        ax.set_title(g["variant"], fontsize=9)
        ax.grid(which="major", alpha=0.35)
        ax.grid(which="minor", alpha=0.12)
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
    from matplotlib.lines import Line2D
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


# --------------------------------------------------------------------------------------------


def plot_tradeoff(outdir, dpi):
    """Error against median wall time per run (tradeoff.json, written for trade-off studies),
    one marker per configuration and level, the Pareto front as a line."""
    path = os.path.join(outdir, "tradeoff.json")
    if not os.path.exists(path):
        return False
    with open(path) as f:
        data = json.load(f)
    points = data.get("points", [])
    if not points:
        return False
    fig, ax = plt.subplots(figsize=(9, 6))
    variants = list(dict.fromkeys(p["variant"] for p in points))
    markers = "os^vD<>ph*XP"
    for i, v in enumerate(variants):
        mine = sorted((p for p in points if p["variant"] == v), key=lambda p: p["level"])
        ax.loglog([p["seconds"] for p in mine], [p["l2_error"] for p in mine], marker=markers[i % len(markers)],
                  linestyle=":", label=v)
    front = data.get("pareto", [])
    ax.loglog([p["seconds"] for p in front], [p["l2_error"] for p in front], "k-", lw=2, alpha=0.4,
              label="Pareto front")
    ax.set_xlabel("median wall time per run (s)")
    ax.set_ylabel("mean relative L2 displacement error")
    ax.set_title("error against wall time (markers: levels, coarse to fine along each line)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save_atomically(fig, os.path.join(outdir, "tradeoff.png"), dpi)
    return True


def plot_extremes(outdir, dpi):
    """extremes.csv (extremes studies): one panel per axis, the error of every run against the
    axis value, one marker per formulation, coloured by verdict (ok / degraded / broken)."""
    path = os.path.join(outdir, "extremes.csv")
    if not os.path.exists(path):
        return False
    import csv
    with open(path) as f:
        rows = list(csv.DictReader(f))
    axes = list(dict.fromkeys(r["axis"] for r in rows))
    colour = {"ok": "tab:green", "degraded": "tab:orange", "broken": "tab:red"}
    markers = "os^vD<>ph*XP"
    cols = min(3, len(axes))
    nrows = (len(axes) + cols - 1) // cols
    fig, grid = plt.subplots(nrows, cols, figsize=(5.2 * cols, 4.2 * nrows), squeeze=False)
    def as_float(text):
        try:
            return float(text)
        except ValueError:
            return math.nan

    for panel, axis in zip(grid.flat, axes):
        mine = [r for r in rows if r["axis"] == axis]
        # nu is drawn against -log10(0.5 - nu), the number of nines; other wide axes on log scale.
        def x_of(r):
            v = as_float(r["value"])
            return -math.log10(0.5 - v) if axis == "nu" else v
        xs = [x_of(r) for r in mine if math.isfinite(x_of(r)) and x_of(r) > 0]
        logx = axis != "nu" and bool(xs) and max(xs) / min(xs) > 20
        forms = list(dict.fromkeys(r["formulation"] for r in mine))
        for i, form in enumerate(forms):
            for verdict, c in colour.items():
                pts = [(x_of(r), as_float(r["l2_error"])) for r in mine
                       if r["formulation"] == form and r["verdict"] == verdict]
                pts = [(x, y if usable(y) else 1.0) for x, y in pts
                       if math.isfinite(x) and (x > 0 or not logx)]
                if pts:
                    panel.scatter([p[0] for p in pts], [p[1] for p in pts], color=c,
                                  marker=markers[i % len(markers)], s=28, alpha=0.8,
                                  label=form if verdict == "ok" else None)
        if logx:
            panel.set_xscale("log")
        panel.set_xlabel("-log10(0.5 - nu)" if axis == "nu" else axis)
        panel.set_yscale("log")
        panel.set_ylabel("relative L2 error (failed runs at 1)")
        panel.set_title(f"{axis}: green ok, orange degraded, red broken", fontsize=9)
        panel.grid(True, which="both", alpha=0.3)
        panel.legend(fontsize=7)
    for panel in list(grid.flat)[len(axes):]:
        panel.set_visible(False)
    fig.tight_layout()
    save_atomically(fig, os.path.join(outdir, "extremes.png"), dpi)
    return True


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n".join(__doc__.split("\n")[1:]))
    ap.add_argument("outdir", metavar="OUTDIR")
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args(argv)
    if args.dpi <= 0:
        ap.error(f"--dpi must be positive, got {args.dpi}")
    if plot_extremes(args.outdir, args.dpi):
        return 0
    try:
        summary = read_summary(os.path.join(args.outdir, "summary.json"))
    except InputError as e:
        print(f"plot_study: {e}", file=sys.stderr)
        return 2
    drawn = [plot_convergence(summary, *norm, args.outdir, args.dpi) for norm in NORMS]
    drawn.append(plot_penalty(summary, args.outdir, args.dpi))
    drawn.append(plot_cdf(summary, args.outdir, args.dpi))
    drawn.append(plot_tradeoff(args.outdir, args.dpi))
    if not any(drawn):
        print(f"plot_study: nothing to plot for {summary['name']}: no group has two mesh sizes "
              "or a k_p, and no level has two realizations", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
