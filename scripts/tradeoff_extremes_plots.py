"""The plots of the studies that write their own tables instead of (or beside) summary.json:
error against wall time (trade-off studies) and the verdicts of the extremes studies."""
import csv
import json
import math
import os

from plotting_common import plt, save_atomically
from study_summary import usable


def plot_tradeoff(outdir, dpi):
    """Error against median wall time per run (tradeoff.json, written for trade-off studies): one
    marker per configuration and level with the range of the realizations' times as a horizontal
    bar; excluded configurations hollow and grey, levels too short to time faint; each admitted
    configuration's fitted error-cost line over its timed levels; the Pareto front; the
    recommendation's predictions (stars) and the check run (a filled diamond with its range)."""
    path = os.path.join(outdir, "tradeoff.json")
    if not os.path.exists(path):
        return False
    with open(path) as f:
        data = json.load(f)
    points = data.get("points", [])
    if not points:
        return False
    configs = {c["variant"]: c for c in data.get("configs", [])}
    fig, ax = plt.subplots(figsize=(10, 6.5))
    variants = list(dict.fromkeys(p["variant"] for p in points))
    markers = "os^vD<>ph*XP"
    # Grey is for the excluded: the admitted take the other colours of tab10, then tab20b.
    palette = [c for k, c in enumerate(plt.cm.tab10.colors) if k != 7] + list(plt.cm.tab20b.colors)
    for i, v in enumerate(variants):
        mine = sorted((p for p in points if p["variant"] == v), key=lambda p: p["level"])
        admitted = configs.get(v, {}).get("admitted", True)
        style = dict(marker=markers[i % len(markers)], linestyle=":", color=palette[i % len(palette)])
        if not admitted:
            style.update(color="0.55", markerfacecolor="none")
        label = v if admitted else f"{v} (excluded)"
        line = None
        for timed in (True, False):
            sel = [p for p in mine if p.get("timed", True) == timed]
            if not sel:
                continue
            xs = [p["seconds"] for p in sel]
            err = [[p["seconds"] - p.get("seconds_min", p["seconds"]) for p in sel],
                   [p.get("seconds_max", p["seconds"]) - p["seconds"] for p in sel]]
            line = ax.errorbar(xs, [p["l2_error"] for p in sel], xerr=err, capsize=2,
                               alpha=1.0 if timed else 0.3,
                               label=label if timed or line is None else None, **style)
        fit = configs.get(v, {}).get("cost_line")
        timed_pts = [p for p in mine if p.get("timed")]
        if admitted and fit and timed_pts:
            t = [min(p["seconds"] for p in timed_pts), max(p["seconds"] for p in timed_pts)]
            ax.loglog(t, [math.exp(fit["intercept"]) * x ** -fit["slope"] for x in t], "-",
                      color=style["color"], lw=1, alpha=0.6)
    front = data.get("pareto", [])
    if front:
        ax.loglog([p["seconds"] for p in front], [p["l2_error"] for p in front], "k-", lw=2.5,
                  alpha=0.3, label="Pareto front (admitted, timed)")
    targets = [t for t in data.get("targets", []) if "seconds" in t]
    if targets:
        ax.loglog([t["seconds"] for t in targets], [t["error"] for t in targets], "k*", ms=12,
                  mfc="gold", label="recommendation: predicted time to error")
    check = data.get("check", {})
    if "seconds" in check:
        ax.errorbar([check["seconds"]], [check["l2_error"]],
                    xerr=[[check["seconds"] - check["seconds_min"]],
                          [check["seconds_max"] - check["seconds"]]],
                    fmt="D", color="crimson", ms=8, capsize=3,
                    label=f"check run ({check['variant']})")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per run (s): median, bar = range of the realizations")
    ax.set_ylabel("mean relative L2 displacement error")
    ax.set_title("error against wall time (faint: levels too short to time)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save_atomically(fig, os.path.join(outdir, "tradeoff.png"), dpi)
    return True


def plot_extremes(outdir, dpi):
    """extremes.csv (extremes studies): one panel per axis, the error of every run against the
    axis value, one marker per formulation, coloured by verdict (ok / degraded / broken)."""
    path = os.path.join(outdir, "extremes.csv")
    if not os.path.exists(path):
        return False
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
