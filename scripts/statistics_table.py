#!/usr/bin/python3
"""One markdown table of a study's statistical convergence, a row per quantity, for the docs.

Usage: statistics_table.py OUTDIR [--mesh LABEL]

Reads statistical-levels.csv and statistical-convergence.csv (written by a scene with
`statistics`) and prints, per quantity of one mesh block: the means over the levels (coarse to
fine), the runs per level, the KS distance and p-value of the finest pair, W1 of each pair, and
for coupled levels E|D| of each pair and Pr(|D| > eps) of the finest; then the four verdicts as
the report gave them. Nothing is computed but formatting; every number is the report's.
"""
import argparse
import csv
import os
import sys


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text, digits=3):
    """A report number in `digits` significant figures; '-' where the report left it empty."""
    if text in ("", None):
        return "-"
    return f"{float(text):.{digits}g}"


def table(outdir, mesh):
    levels = [r for r in read(os.path.join(outdir, "statistical-levels.csv"))
              if mesh in (None, r["mesh"])]
    pairs = [r for r in read(os.path.join(outdir, "statistical-convergence.csv"))
             if mesh in (None, r["mesh"])]
    quantities = list(dict.fromkeys(r["quantity"] for r in levels))
    coupled = any(r.get("E|D|") for r in pairs)
    head = ["quantity", "runs per level", "means over the levels", "KS D (p), finest pair",
            "W1, the pairs"]
    if coupled:
        head += ["E\\|D\\|, the pairs", "Pr(\\|D\\| > eps), finest"]
    head += ["distribution", "of the mean", "in mean", "in probability"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for q in quantities:
        mine = sorted((r for r in levels if r["quantity"] == q), key=lambda r: -float(r["h_avg"]))
        steps = sorted((r for r in pairs if r["quantity"] == q), key=lambda r: -float(r["h"]))
        if not steps:
            continue
        finest = steps[-1]
        row = [q, ", ".join(r["runs"] for r in mine), ", ".join(number(r["mean"]) for r in mine),
               f"{number(finest['KS D'], 2)} ({number(finest['p'], 2)})",
               ", ".join(number(r["W1"]) for r in steps)]
        if coupled:
            row += [", ".join(number(r.get("E|D|")) for r in steps),
                    number(finest.get("Pr(|D| > eps)"), 2)]
        row += [finest[k] or "-" for k in ("in distribution", "of the mean", "in mean",
                                             "in probability")]
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("outdir")
    p.add_argument("--mesh", help="the mesh block's label (default: all)")
    a = p.parse_args(argv)
    try:
        print(table(a.outdir, a.mesh))
    except (OSError, KeyError, ValueError) as e:
        print(f"statistics_table.py: {a.outdir}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
