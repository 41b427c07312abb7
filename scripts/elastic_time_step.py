#!/usr/bin/env python3
"""The elastic column against the step: what a time-refinement study of it measured.

Usage: elastic_time_step.py OUT [--json FILE]

OUT is the output folder of a `dynamics` study of the column-impact problem with
time.refinement (the shipped scene `column-impact-elastic-time-step`: fracture off, its first
5 ms, one folder <variant>/dt-<fraction>/ per contact law and step). For every run of every part:
  - the plane's impulse over the first 2 ms along its normal, from the history's momenta: the
    change of the bodies' normal momentum less gravity's impulse M (g . n) t (nothing else acts);
  - the most compressive principal cell stress over the frames (the refinement writes them at
    the same times at every step);
  - the cells past the report's Mohr-Coulomb criterion at the frames nearest 1, 2 and 5 ms
    (elastic_diagnostic.py's test).
Then per variant and run, the spread across the steps against the issue's bounds: the impulse
within 1 % across the three steps, the peak compression within 3 % and the cells past the
criterion within 5 % between the two smallest steps. Prints a table; writes JSON when asked.
Only numpy (through elastic_diagnostic) is used.
"""
import argparse
import csv
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from elastic_diagnostic import failing_cells, most_compressive, stresses  # noqa: E402

IMPULSE_WINDOW, CRITERION_TIMES = 0.002, (0.001, 0.002, 0.005)


def parts(out):
    """(variant, fraction, folder) of every refined part, the fraction read from summary.json."""
    found = []
    for root, _, files in os.walk(out):
        if "summary.json" not in files:
            continue
        with open(os.path.join(root, "summary.json")) as f:
            settings = json.load(f)["settings"]
        variant = os.path.relpath(os.path.dirname(root), out)
        found.append((variant, settings, root))
    return found


def vector(text):
    return [float(x) for x in text.strip("[]").split(",")]


def impulse(history, settings):
    """The plane's normal impulse over [0, IMPULSE_WINDOW], from the momenta in the history."""
    normal, gravity = vector(settings["wall.normal"]), vector(settings["gravity"])
    velocity = vector(settings["initial_velocity"])
    n = math.hypot(*normal)
    normal = [normal[0] / n, normal[1] / n]
    with open(history) as f:
        rows = [(float(r["time"]), float(r["momentum_x"]), float(r["momentum_y"]))
                for r in csv.DictReader(f)]
    t0, px0, py0 = rows[0]
    mass = math.hypot(px0, py0) / math.hypot(*velocity)
    for (ta, xa, ya), (tb, xb, yb) in zip(rows, rows[1:]):
        if ta <= IMPULSE_WINDOW <= tb:
            w = (IMPULSE_WINDOW - ta) / (tb - ta)
            px, py = xa + w * (xb - xa), ya + w * (yb - ya)
            change = (px - px0) * normal[0] + (py - py0) * normal[1]
            return change - mass * (gravity[0] * normal[0] + gravity[1] * normal[1]) * IMPULSE_WINDOW
    raise SystemExit(f"elastic_time_step: {history} ends before {IMPULSE_WINDOW} s")


def frames(pvd):
    root = ET.parse(pvd).getroot()
    base = os.path.dirname(pvd)
    return [(float(d.get("timestep")), os.path.join(base, d.get("file"))) for d in root.iter("DataSet")]


def measure(folder, settings, run):
    rows = frames(os.path.join(folder, "vtu", run + ".pvd"))
    peak, at = 0.0, {}
    for t, path in rows:
        s = stresses(path)
        peak = min(peak, most_compressive(s))
        for target in CRITERION_TIMES:
            best = at.get(target)
            if best is None or abs(t - target) < abs(best[0] - target):
                at[target] = (t, failing_cells(s))
    return {"impulse_2ms": impulse(os.path.join(folder, "history", run + ".csv"), settings),
            "peak_compression": peak,
            "failing": {str(k): v[1] for k, v in at.items()}}


def spread(values):
    lo, hi = min(values), max(values)
    return (hi - lo) / max(abs(hi), abs(lo), 1e-300)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--json")
    a = p.parse_args(argv)
    data = {}
    for variant, settings, folder in parts(a.out):
        fraction = float(settings["time.safety"])
        runs = sorted(f[:-4] for f in os.listdir(os.path.join(folder, "vtu")) if f.endswith(".pvd"))
        for run in runs:
            data.setdefault(variant, {}).setdefault(run, []).append(
                {"safety": fraction, **measure(folder, settings, run)})
    verdicts = True
    for variant, by_run in sorted(data.items()):
        for run, steps in sorted(by_run.items()):
            steps.sort(key=lambda r: -r["safety"])
            print(f"{variant} {run}:")
            for r in steps:
                cells = ", ".join(f"{r['failing'][str(t)]}" for t in CRITERION_TIMES)
                print(f"  safety {r['safety']:.4g}: impulse over 2 ms {r['impulse_2ms']:.1f} N s/m, "
                      f"peak compression {r['peak_compression'] / 1e6:.2f} MPa, "
                      f"cells past the criterion at 1, 2, 5 ms: {cells}")
            fine = steps[-2:]
            checks = {
                "impulse within 1 % over the steps": spread([r["impulse_2ms"] for r in steps]) <= 0.01,
                "peak compression within 3 % (two smallest steps)":
                    spread([r["peak_compression"] for r in fine]) <= 0.03,
            }
            for t in CRITERION_TIMES:
                values = [r["failing"][str(t)] for r in fine]
                checks[f"cells past the criterion at {t * 1e3:g} ms within 5 %"] = (
                    max(values) == 0 or spread(values) <= 0.05)
            for name, ok in checks.items():
                print(f"  {'holds' if ok else 'FAILS'}: {name}")
                verdicts = verdicts and ok
    if a.json:
        with open(a.json + ".tmp", "w") as f:
            json.dump(data, f, indent=1)
        os.replace(a.json + ".tmp", a.json)
    return 0 if verdicts else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
