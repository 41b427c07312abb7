#!/usr/bin/env python3
"""Mean fragment size of strip studies against the three 1D fragmentation theories.

Usage: fragment_theory.py OUT [OUT ...] [--png FILE]

Each OUT is the output folder of a `fragmentation` study of the strip-expansion problem with
variants (the shipped strip-fragmentation and strip-fragmentation-theory). For every variant,
from its summary.json (strain rate, E, density, strength, fracture energy, domain) and levels.csv
(mean fragment count, h_avg): the mean fragment length s = L / N and, in the units of Levy and
Molinari (2010), L0 = E G / sigma_c^2, t0 = L0 / c, rate0 = sigma_c / (E t0), the normalized
rate and size. Beside them the three laws, s/L0 against rate/rate0:
  Grady (1982):                 (24 / r^2)^(1/3)
  Glenn and Chudnovsky (1986):  (4 / r) sinh(asinh(1.5 r) / 3)
  Zhou, Molinari, Ramesh (2005): 4.5 / (1 + 4.5 r^(2/3))
A point is "resolved" where h_avg <= s_ZMR / 8 (cohesive fragment counts converge only with cells
several times smaller than the fragments). Prints a table; draws the figure when asked.
"""
import argparse
import csv
import json
import math
import os
import sys


def grady(r):
    return (24.0 / r ** 2) ** (1.0 / 3.0)


def glenn_chudnovsky(r):
    return 4.0 / r * math.sinh(math.asinh(1.5 * r) / 3.0)


def zmr(r):
    return 4.5 / (1.0 + 4.5 * r ** (2.0 / 3.0))


def number(settings, key):
    return float(settings[key])


def points(out):
    rows = []
    for v in sorted(os.listdir(out)):
        folder = os.path.join(out, v)
        if not os.path.exists(os.path.join(folder, "levels.csv")):
            continue
        with open(os.path.join(folder, "summary.json")) as f:
            s = json.load(f)["settings"]
        with open(os.path.join(folder, "levels.csv")) as f:
            level = list(csv.DictReader(f))[-1]
        E, rho = number(s, "material.E"), number(s, "material.density")
        strength, G = number(s, "cohesive.strength"), number(s, "cohesive.fracture_energy")
        domain = json.loads(s["domain"])
        length = domain[2] - domain[0]
        L0 = E * G / strength ** 2
        rate0 = strength / (E * L0 / math.sqrt(E / rho))
        r = number(s, "strain_rate") / rate0
        size = length / float(level["fragments_mean"])
        h = float(level["h_avg"])
        rows.append({"study": os.path.basename(os.path.normpath(out)), "variant": v, "rate": r,
                     "size": size / L0, "zmr": zmr(r), "h_over_zmr": h / (zmr(r) * L0),
                     "resolved": h <= zmr(r) * L0 / 8.0})
    return rows


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out", nargs="+")
    p.add_argument("--png")
    a = p.parse_args(argv)
    rows = [row for out in a.out for row in points(out)]
    print("| study / variant | rate / rate0 | s / L0 | ZMR | ours / ZMR | h_avg / s_ZMR | resolved |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['study']} / {r['variant']} | {r['rate']:.3g} | {r['size']:.3g} | "
              f"{r['zmr']:.3g} | {r['size'] / r['zmr']:.2f} | {r['h_over_zmr']:.3f} | "
              f"{'yes' if r['resolved'] else 'no'} |")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
        r = np.logspace(-1, 2, 200)
        fig, ax = plt.subplots(figsize=(6.5, 4.5), layout="constrained")
        ax.loglog(r, [grady(x) for x in r], label="Grady")
        ax.loglog(r, [glenn_chudnovsky(x) for x in r], label="Glenn-Chudnovsky")
        ax.loglog(r, [zmr(x) for x in r], label="Zhou-Molinari-Ramesh")
        for resolved, marker in ((True, "o"), (False, "x")):
            pick = [x for x in rows if x["resolved"] == resolved]
            if pick:
                ax.loglog([x["rate"] for x in pick], [x["size"] for x in pick], marker,
                          color="k", label="strip, " + ("resolved" if resolved else
                                                         "h_avg > s_ZMR / 8"))
        ax.set(xlabel="normalized strain rate", ylabel="mean fragment size / L0",
               title="alumina strip against the 1D theories")
        ax.legend(fontsize=8)
        fig.savefig(a.png + ".tmp.png", dpi=110)
        os.replace(a.png + ".tmp.png", a.png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
