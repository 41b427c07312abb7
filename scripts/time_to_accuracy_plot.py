#!/usr/bin/python3
"""Time to accuracy on Timoshenko's cantilever: deal.II Q1 on 4n x n squares against vorodg's CG
on random (rcp) meshes, from the raw runs of `side_by_side_dealii.py --rcp`.

Summarizes the runs (deal.II: median time per n; vorodg: median time and mean L2 error and h_avg
over the seeds of each d), interpolates each code's time at a target L2 error linearly in
log(time) against log(L2) between the two bracketing points (extrapolating from the nearest two,
flagged, when the target is not bracketed), and draws L2 error against time, log-log.

side_by_side_dealii.py imports it; run alone, it redraws from a raw file it wrote:
    time_to_accuracy_plot.py RAW.json [--target L2] [--plot FILE.png]
(the markdown goes to stdout; the plot is drawn only when --plot is given).
"""
import argparse
import math
import sys
from pathlib import Path

import numpy as np


class InputError(Exception):
    """A one-line reason to stop with a non-zero exit."""


def _median(xs):
    return float(np.median(xs))


def summarize(raw):
    """Per-size points of both codes: {"dealii": [...], "vorodg": [...]}, coarse to fine."""
    dealii = []
    for n in sorted({r["n"] for r in raw["dealii_runs"]}):
        runs = [r for r in raw["dealii_runs"] if r["n"] == n]
        dealii.append({"n": n, "dofs": runs[0]["dofs"], "h": 1.0 / n, "runs": len(runs),
                       "l2_error": _median([r["l2_error"] for r in runs]),
                       "time": _median([r["seconds"]["total"] for r in runs]),
                       "wall": _median([r["wall"] for r in runs])})
    vorodg = []
    for d in sorted({r["d"] for r in raw["vorodg_runs"]}, reverse=True):
        runs = [r for r in raw["vorodg_runs"] if r["d"] == d]
        l2 = [r["l2_error"] for r in runs]
        vorodg.append({"d": d, "seeds": sorted(r["seed"] for r in runs),
                       "dofs": float(np.mean([r["dofs"] for r in runs])),
                       "h": float(np.mean([r["h_avg"] for r in runs])),
                       "l2_error": float(np.mean(l2)), "l2_min": min(l2), "l2_max": max(l2),
                       "time": _median([r["wall"] for r in runs]),
                       "stage_sum": _median([r["stage_sum"] for r in runs])})
    return {"dealii": dealii, "vorodg": vorodg}


def interpolate(points, target, key="time", label="n"):
    """The time at L2 error `target`: linear in log(time) against log(L2) between the two points
    that bracket it, else extrapolated from the nearest two. A dict with "time" (None with fewer
    than two points), "extrapolated" and "between" (the two points' labels)."""
    pts = sorted((p["l2_error"], p[key], p[label]) for p in points
                 if p["l2_error"] > 0 and p[key] > 0)
    if len(pts) < 2:
        return {"time": None, "extrapolated": True, "between": [p[2] for p in pts]}
    pair = next(((a, b) for a, b in zip(pts, pts[1:]) if a[0] <= target <= b[0]), None)
    extrapolated = pair is None
    if extrapolated:  # the finest two below the range, the coarsest two above it
        pair = (pts[0], pts[1]) if target < pts[0][0] else (pts[-2], pts[-1])
    (e1, t1, l1), (e2, t2, l2) = pair
    if e1 == e2:
        lt = 0.5 * (math.log(t1) + math.log(t2))
    else:
        lt = math.log(t1) + (math.log(target) - math.log(e1)) * \
            (math.log(t2) - math.log(t1)) / (math.log(e2) - math.log(e1))
    return {"time": math.exp(lt), "extrapolated": extrapolated, "between": [l1, l2]}


def time_to_target(summary, target):
    """Interpolated times (primary and secondary measures) and their ratios."""
    dealii, vorodg = summary["dealii"], summary["vorodg"]
    t = {"dealii_total": interpolate(dealii, target, "time", "n"),
         "dealii_wall": interpolate(dealii, target, "wall", "n"),
         "vorodg_wall": interpolate(vorodg, target, "time", "d"),
         "vorodg_stage_sum": interpolate(vorodg, target, "stage_sum", "d")}

    def ratio(a, b):
        if t[a]["time"] is None or t[b]["time"] is None:
            return None
        return {"value": t[a]["time"] / t[b]["time"],
                "extrapolated": t[a]["extrapolated"] or t[b]["extrapolated"]}
    return {"target": target, "times": t,
            "ratio": ratio("vorodg_wall", "dealii_total"),
            "ratio_stage_sum": ratio("vorodg_stage_sum", "dealii_total"),
            "ratio_walls": ratio("vorodg_wall", "dealii_wall")}


def _interp_text(i, what, sym):
    if i["time"] is None:
        return f"{what}: not enough points"
    lo, hi = i["between"]
    how = "extrapolated from" if i["extrapolated"] else "between"
    return f"{what} {i['time']:.3f} s ({how} {sym} = {hi:g} and {lo:g})"


def _ratio_text(r):
    if r is None:
        return "n/a"
    return f"{r['value']:.2f}" + (" (extrapolated)" if r["extrapolated"] else "")


def report(raw, summary, tt):
    """The markdown: the header stored in the raw file, one table per code, the times at the
    target and their ratios."""
    out = list(raw.get("header", []))
    out += ["deal.II Q1, 4n x n squares (UMFPACK; median of "
            f"{raw['repeats']} run(s) per n):", "",
            "| n | DOFs | h = 1/n | L2 error | total [s] | process wall [s] |",
            "|---:|---:|---:|---:|---:|---:|"]
    for p in summary["dealii"]:
        out.append(f"| {p['n']} | {p['dofs']} | {p['h']:.5f} | {p['l2_error']:.4e} | "
                   f"{p['time']:.3f} | {p['wall']:.3f} |")
    out += ["", f"vorodg CG on rcp meshes ({raw['realizations']} seed(s) per d: mean DOFs, h_avg "
            "and L2 error, median times):", "",
            "| d | DOFs | h_avg | L2 error | L2 min .. max | total wall [s] | stage sum [s] |",
            "|---:|---:|---:|---:|---:|---:|---:|"]
    for p in summary["vorodg"]:
        out.append(f"| {p['d']:g} | {p['dofs']:.0f} | {p['h']:.5f} | {p['l2_error']:.4e} | "
                   f"{p['l2_min']:.3e} .. {p['l2_max']:.3e} | {p['time']:.3f} | "
                   f"{p['stage_sum']:.3f} |")
    t, target = tt["times"], tt["target"]
    notes = [f"{code}: target not bracketed by its L2 errors, extrapolated"
             for code, k in (("deal.II", "dealii_total"), ("vorodg", "vorodg_wall"))
             if t[k]["time"] is not None and t[k]["extrapolated"]]
    out += ["", f"Time to L2 error {target:.3g} (log-log interpolation): "
            + _interp_text(t["dealii_total"], "deal.II total", "n") + "; "
            + _interp_text(t["vorodg_wall"], "vorodg wall", "d") + "; "
            + f"ratio vorodg / deal.II = {_ratio_text(tt['ratio'])}"
            + (f" [{'; '.join(notes)}]" if notes else "") + ".",
            "", f"Also: vorodg stage sum / deal.II total = {_ratio_text(tt['ratio_stage_sum'])} "
            f"(both in-program times); vorodg wall / deal.II process wall = "
            f"{_ratio_text(tt['ratio_walls'])} (both whole processes).", ""]
    return "\n".join(out)


def plot(raw, summary, tt, path, dpi=150):
    """L2 error against time, log-log, both codes, the target as a horizontal line; written to
    a temporary file beside `path`, then renamed into place."""
    import matplotlib.pyplot as plt

    from plotting_common import save_atomically

    fig, ax = plt.subplots(figsize=(7.0, 6.0), layout="constrained")
    target = tt["target"]
    curves = [("dealii", "dealii_total", "n", "o-", "C0",
               f"deal.II Q1, 4n x n squares (its total, median of {raw['repeats']})"),
              ("vorodg", "vorodg_wall", "d", "s-", "C3",
               f"vorodg CG, rcp meshes (process wall, median over {raw['realizations']} "
               "seed(s); mean L2)")]
    for code, key, label, style, color, name in curves:
        pts = summary[code]
        x = [p["time"] for p in pts]
        y = [p["l2_error"] for p in pts]
        ax.loglog(x, y, style, color=color, label=name)
        for p in pts:
            ax.annotate(f"{label}={p[label]:g}", (p["time"], p["l2_error"]), fontsize=7,
                        xytext=(4, 3), textcoords="offset points", color=color)
        i = tt["times"][key]
        if i["time"] is None:
            continue
        ax.plot([i["time"]], [target], "+" if i["extrapolated"] else "x", color=color,
                markersize=10, mew=2)
        if i["extrapolated"]:  # dotted from the nearer end of the curve
            near = min(pts, key=lambda p: abs(math.log(p["l2_error"] / target)))
            ax.plot([near["time"], i["time"]], [near["l2_error"], target], ":", color=color)
    ax.axhline(target, color="0.4", ls="--", lw=1,
               label=f"target L2 = {target:.3g} (x: interpolated, +: extrapolated)")
    ax.set_xlabel("time to solution [s] (one thread: mesh, assembly, solve, error)")
    ax.set_ylabel("relative L2 displacement error ||u_h - u|| / ||u|| [-]")
    ax.set_title("Timoshenko cantilever: L2 error against time, one thread, medians",
                 fontsize=11)
    ax.grid(which="major", alpha=0.35)
    ax.grid(which="minor", alpha=0.12)
    ax.margins(0.08)
    ax.legend(fontsize=8, title_fontsize=9, loc="upper center", bbox_to_anchor=(0.5, -0.12),
              title=f"time at target: vorodg / deal.II = {_ratio_text(tt['ratio'])}")

    save_atomically(fig, path, dpi)


def check_target(target):
    if not (math.isfinite(target) and 0 < target < 1):
        raise InputError(f"--target {target}: expected a relative L2 error in (0, 1)")


def check_plot_path(p):
    if Path(p).suffix.lower() != ".png":
        raise InputError(f"--plot {p}: expected a .png file")
    if not Path(p).resolve().parent.is_dir():
        raise InputError(f"--plot {p}: its folder does not exist")


def main(argv):
    import json

    class Parser(argparse.ArgumentParser):
        def error(self, message):
            raise InputError(f"bad arguments: {message} (see --help)")
    p = Parser(description=__doc__.split("\n\n")[0])
    p.add_argument("raw", metavar="RAW.json", help="raw file of side_by_side_dealii.py --rcp")
    p.add_argument("--target", type=float, help="L2 error (default: the one the runs used)")
    p.add_argument("--plot", help="PNG to draw")
    a = p.parse_args(argv)
    try:
        raw = json.loads(Path(a.raw).read_text())
    except (OSError, ValueError) as e:
        raise InputError(f"{a.raw}: cannot read it as JSON ({e})")
    if raw.get("mode") != "rcp" or not raw.get("dealii_runs") or not raw.get("vorodg_runs"):
        raise InputError(f"{a.raw}: not a raw file of side_by_side_dealii.py --rcp")
    target = raw["target"] if a.target is None else a.target
    check_target(target)
    if a.plot:
        check_plot_path(a.plot)
    summary = summarize(raw)
    tt = time_to_target(summary, target)
    sys.stdout.write(report(raw, summary, tt))
    if a.plot:
        plot(raw, summary, tt, a.plot)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except InputError as e:
        print(f"time_to_accuracy_plot: {e}", file=sys.stderr)
        sys.exit(1)
