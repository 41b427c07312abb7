#!/usr/bin/python3
"""DG against CG on the beam over RCP realizations (the trend of the report's Figure 26).

Runs `vorodg solve` for every (level, realization, formulation, k_p) on 2 processes, collects the
metrics into a CSV, prints per level the mean and standard deviation of the L2 error over the
realizations and the least-squares rate over all (log h_avg, log error) points, and draws the
error against h_avg. A stopgap until the study harness (issue 6) runs scenes.

Usage: dg_beam_study.py OUTDIR [--realizations 10] [--kp 1e1,1e2,1e3,1e4] [--d 0.2,...]
"""
import argparse
import concurrent.futures as futures
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import plt, save_atomically  # noqa: E402

VORODG = os.environ.get("VORODG", "build/bin/vorodg")


def run(job):
    label, formulation, kp, d, seed, out = job
    metrics = os.path.join(out, f"{label}-d{d}-s{seed}.json")
    if not os.path.exists(metrics):  # finished runs are kept: a rerun resumes
        cmd = [VORODG, "solve", "--family", "rcp", "--d", str(d), "--seed", str(seed),
               "--domain", "0,-0.5,4,0.5", "--problem", "beam", "--formulation", formulation,
               "--max-iter", "5000", "--metrics", metrics]
        if formulation != "cg":
            cmd += ["--kp", str(kp)]
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            return dict(label=label, d=d, seed=seed, failed=done.stderr.strip())
    with open(metrics) as f:
        m = json.load(f)
    return dict(label=label, d=d, seed=seed, h_avg=m["h_avg"], dofs=m["dofs"], l2=m["l2_error"],
                energy=m["energy_error"], iterations=m.get("iterations", 1),
                stop=m.get("stop_reason", "direct"), seconds=sum(m["seconds"].values()))


def fit(hs, es):
    x, y = np.log(hs), np.log(es)
    slope, intercept = np.polyfit(x, y, 1)
    resid = y - (slope * x + intercept)
    n = len(x)
    se = math.sqrt(resid @ resid / (n - 2) / ((x - x.mean()) @ (x - x.mean()))) if n > 2 else float("nan")
    return slope, se


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--realizations", type=int, default=10)
    p.add_argument("--kp", default="1e1,1e2,1e3,1e4")
    p.add_argument("--formulation", default="dg-nitsche")
    p.add_argument("--no-cg", action="store_true")
    p.add_argument("--d", default="0.2,0.1,0.05,0.025,0.0125")
    a = p.parse_args()
    os.makedirs(os.path.join(a.out, "runs"), exist_ok=True)
    levels = [float(x) for x in a.d.split(",")]
    configs = ([] if a.no_cg else [("cg", "cg", None)]) + [
        (f"{a.formulation} kp={k}", a.formulation, k) for k in a.kp.split(",")]
    jobs = [(label.replace(" ", "_"), f, k, d, 1000 + i, os.path.join(a.out, "runs"))
            for (label, f, k) in configs for d in levels for i in range(a.realizations)]
    with futures.ProcessPoolExecutor(max_workers=2) as pool:
        rows = list(pool.map(run, jobs))
    failed = [r for r in rows if "failed" in r]
    for r in failed:
        print(f"failed: {r['label']} d={r['d']} seed={r['seed']}: {r['failed']}", file=sys.stderr)
    rows = [r for r in rows if "failed" not in r]
    with open(os.path.join(a.out, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    fig, ax = plt.subplots(figsize=(8, 6))
    print(f"beam, L/D = 4, plane stress, nu = 0.3, rcp, {a.realizations} realizations per level")
    for (label, _, _) in configs:
        key = label.replace(" ", "_")
        mine = [r for r in rows if r["label"] == key]
        if not mine:
            continue
        print(f"\n{label}")
        print(f"{'d':>8} {'h_avg':>9} {'dofs':>8} {'mean L2':>10} {'std':>9} {'iter':>6} {'stops':>16}")
        hs, es = [], []
        for d in levels:
            at = [r for r in mine if r["d"] == d]
            if not at:
                continue
            l2 = np.array([r["l2"] for r in at])
            stops = sorted({r["stop"] for r in at})
            print(f"{d:8.4f} {np.mean([r['h_avg'] for r in at]):9.5f} {int(np.mean([r['dofs'] for r in at])):8d} "
                  f"{l2.mean():10.3e} {l2.std(ddof=1) if len(l2) > 1 else 0:9.2e} "
                  f"{np.mean([r['iterations'] for r in at]):6.1f} {','.join(stops):>16}")
            hs += [r["h_avg"] for r in at]
            es += [r["l2"] for r in at]
        slope, se = fit(np.array(hs), np.array(es))
        print(f"least-squares L2 rate {slope:.3f} (95% interval +-{1.96 * se:.3f})")
        ax.loglog(hs, es, "o", ms=3, alpha=0.5, label=f"{label}: rate {slope:.2f}")
    ax.set_xlabel("h_avg")
    ax.set_ylabel("relative L2 displacement error")
    ax.set_title(f"Beam on RCP meshes: {a.formulation} against k_p")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save_atomically(fig, os.path.join(a.out, "dg_vs_cg.png"), 120)


if __name__ == "__main__":
    main()
