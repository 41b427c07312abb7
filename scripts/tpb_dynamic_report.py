#!/usr/bin/python3
"""The dynamic three-point bend against the quasi-static solver on the same meshes.

    tpb_dynamic_report.py DYNAMIC_DIR STATIC_DIR [-o OUT]

DYNAMIC_DIR is a `vorodg run` of a fragmentation scene of problem three-point-bend whose variant
labels begin with the name of their case (e.g. case2-dg-v0.005: case2); STATIC_DIR a `vorodg run`
of the fracture scene with variants labelled <case> on the same meshes (same family, size, seed
and realizations: the run ids match). What each variant ran with (interfaces, rate.speed,
rate.rise, damping) is read from the settings in its summary.json, never from the label. For every dynamic run
the load-CMOD curve is set against the quasi-static one of the same case and mesh, and tabulated:

  peak, peak_qs      the largest load (N) of each curve; peak_error = peak / peak_qs - 1
  deviation          after the quasi-static peak, the largest |P(cmod) - P_qs(cmod)| over the
                     quasi-static curve's CMOD range, as a fraction of peak_qs
  oscillation        half the range of P - P_qs over the same span, as a fraction of peak_qs:
                     the amplitude of the vibration about the quasi-static curve
  kinetic_at_peak    kinetic energy over the work put in, at the dynamic peak
  dissipated         the law's dissipated energy at the end over the work put in
  balance            the run's worst balance with the law's energies (results.csv)
  seconds            the run's wall time

Writes OUT/tpb-dynamic.csv, OUT/tpb-dynamic.md (medians over realizations) and one PNG per case,
speed, rise and damping with every realization's curves over the quasi-static ones.
"""
import argparse
import csv
import json
import os
import sys

import numpy as np


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}


def results(path):
    with open(path) as f:
        return {r["id"]: r for r in csv.DictReader(f)}


def settings(folder):
    """What a variant ran with: (interfaces, speed, rise, damping) from its summary.json."""
    with open(os.path.join(folder, "summary.json")) as f:
        s = json.load(f)["settings"]
    return dict(approach=s["interfaces"], speed=float(s["rate.speed"]),
                rise=float(s["rate.rise"]), damping=float(s["damping"]))


def compare(dyn, qs):
    """The measures of one dynamic curve against its quasi-static one."""
    peak_qs = qs["load"].max()
    after = qs["cmod"] >= qs["cmod"][qs["load"].argmax()]
    lo, hi = qs["cmod"][after].min(), qs["cmod"][after].max()
    span = (dyn["cmod"] >= lo) & (dyn["cmod"] <= hi)
    residual = dyn["load"][span] - np.interp(dyn["cmod"][span], qs["cmod"], qs["load"])
    if residual.size == 0:
        return dict(peak_qs=peak_qs, deviation=np.nan, oscillation=np.nan)
    return dict(peak_qs=peak_qs, deviation=np.abs(residual).max() / peak_qs,
                oscillation=0.5 * (residual.max() - residual.min()) / peak_qs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dynamic")
    parser.add_argument("static")
    parser.add_argument("-o", "--out", default=None)
    a = parser.parse_args()
    out = a.out or a.dynamic
    os.makedirs(out, exist_ok=True)
    rows = []
    for variant in sorted(os.listdir(a.dynamic)):
        folder = os.path.join(a.dynamic, variant)
        if not os.path.exists(os.path.join(folder, "results.csv")):
            continue
        case = variant.split("-")[0]
        static = os.path.join(a.static, case)
        if not os.path.isdir(static):
            sys.exit(f"{static}: no quasi-static runs for case {case}")
        ran = settings(folder)
        for run_id, r in results(os.path.join(folder, "results.csv")).items():
            dyn = read_csv(os.path.join(folder, "curves", run_id + ".csv"))
            qs = read_csv(os.path.join(static, "curves", run_id + ".csv"))
            row = dict(case=case, run=run_id, **ran)
            row.update(compare(dyn, qs))
            work = dyn["external_work"] + dyn["reaction_work"]
            at = dyn["load"].argmax()
            row.update(peak=dyn["load"].max(), kinetic_at_peak=dyn["kinetic"][at] / work[at],
                       dissipated=dyn["cohesive_dissipated"][-1] / work[-1],
                       balance=float(r["law_balance_error"]), seconds=float(r["seconds"]),
                       steps=int(float(r["steps"])))
            row["peak_error"] = row["peak"] / row["peak_qs"] - 1.0
            row["_curves"] = (dyn, qs)
            rows.append(row)
    if not rows:
        sys.exit(f"{a.dynamic}: no variants with results.csv")
    columns = ["case", "approach", "speed", "rise", "damping", "run", "peak", "peak_qs", "peak_error", "deviation",
               "oscillation", "kinetic_at_peak", "dissipated", "balance", "steps", "seconds"]
    tmp = os.path.join(out, "tpb-dynamic.csv.tmp")
    with open(tmp, "w") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for r in rows:
            w.writerow([r[c] if not isinstance(r[c], float) else f"{r[c]:.6g}" for c in columns])
    os.replace(tmp, os.path.join(out, "tpb-dynamic.csv"))
    write_table(rows, out)
    plot(rows, out)


def write_table(rows, out):
    key = lambda r: (r["case"], r["speed"], r["rise"], r["damping"], r["approach"])
    lines = ["| case | speed (m/s) | rise (s) | damping (1/s) | approach | runs | peak (N) | "
             "QS peak (N) | peak error | deviation | oscillation | kinetic at peak | "
             "dissipated / work | worst balance | steps | seconds |", "|" + "---|" * 16]
    for k in sorted({key(r) for r in rows}):
        g = [r for r in rows if key(r) == k]
        case, speed, rise, damping, approach = k
        med = lambda k: float(np.median([r[k] for r in g]))
        lines.append(f"| {case} | {speed:g} | {rise:g} | {damping:g} | {approach} | {len(g)} | "
                     f"{med('peak'):.1f} | "
                     f"{med('peak_qs'):.1f} | {med('peak_error'):+.3f} | {med('deviation'):.3f} | "
                     f"{med('oscillation'):.3f} | {med('kinetic_at_peak'):.4f} | "
                     f"{med('dissipated'):.3f} | {max(r['balance'] for r in g):.1e} | "
                     f"{med('steps'):.0f} | {med('seconds'):.1f} |")
    text = "Medians over realizations (worst balance: the largest).\n\n" + "\n".join(lines) + "\n"
    tmp = os.path.join(out, "tpb-dynamic.md.tmp")
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, os.path.join(out, "tpb-dynamic.md"))
    print(text)


def plot(rows, out):
    """One PNG per case and speed: every realization's curves over the quasi-static ones, the
    whole range on the left and the quasi-static curve's range on the right (dg drawn last)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    colours = {"insertion": "tab:red", "dg": "tab:blue"}
    order = {"insertion": 0, "dg": 1}
    key = lambda r: (r["case"], r["speed"], r["rise"], r["damping"])
    for case, speed, rise, damping in sorted({key(r) for r in rows}):
        group = sorted((r for r in rows if key(r) == (case, speed, rise, damping)),
                       key=lambda r: order.get(r["approach"], 2))
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
        for ax in axes:
            drawn = set()
            for r in group:
                dyn, qs = r["_curves"]
                ax.plot(1e3 * dyn["cmod"], dyn["load"], color=colours.get(r["approach"], "k"),
                        lw=0.8, alpha=0.8,
                        label=r["approach"] if r["approach"] not in drawn else None)
                drawn.add(r["approach"])
                ax.plot(1e3 * qs["cmod"], qs["load"], "k--", lw=1.2,
                        label="quasi-static" if "qs" not in drawn else None)
                drawn.add("qs")
            ax.set_xlabel("CMOD (mm)")
            ax.set_ylabel("load (N)")
            ax.set_xlim(0, 1.0)
            ax.legend()
        peak = max(r["peak_qs"] for r in group)
        axes[1].set_ylim(-0.25 * peak, 1.5 * peak)
        axes[0].set_title(f"{case}, load point at {speed:g} m/s, rise {1e3 * rise:g} ms"
                          + (f", damping {damping:g} /s" if damping > 0 else ""))
        axes[1].set_title("the quasi-static curve's range")
        fig.tight_layout()
        name = f"tpb-dynamic-{case}-v{speed:g}-rise{1e3 * rise:g}ms"
        path = os.path.join(out, name + (f"-damping{damping:g}" if damping > 0 else "") + ".png")
        fig.savefig(path + ".tmp.png", dpi=110)
        os.replace(path + ".tmp.png", path)
        plt.close(fig)


if __name__ == "__main__":
    main()
