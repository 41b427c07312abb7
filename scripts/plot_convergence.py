#!/usr/bin/python3
"""Draws a log-log convergence plot (error against h_avg) and prints convergence tables.

Usage:
  plot_convergence.py CSV OUT.png [--title TEXT] [--ylabel TEXT] [--dpi N]

CSV has a header with (at least) the columns label,h_avg,dofs,l2_error,energy_error, one row per
run; rows with the same label form one refinement sequence (say one mesh family). The plot has
one line per label and norm (L2 solid with circles, energy dashed with squares, one colour per
label); the legend gives the least-squares slope of log(error) against log(h_avg) of each line.
The PNG is written atomically (temporary file beside OUT.png, then renamed); its path is printed.

For each label a table in the manner of deal.II's ConvergenceTable goes to stdout: the rows
sorted from coarse to fine, h_avg, dofs, each error and its rate between consecutive rows,
rate = log(e1/e2) / log(h1/h2), and the fitted slope under each rate column. A missing, zero or
negative error has no rate and is left out of the plot and the fit.

Exit codes: 0 success, 2 bad input (one line on stderr), 1 anything else.
Only the Python standard library, numpy and matplotlib (Agg) are used.
"""
import argparse
import csv
import math
import os
import sys
import tempfile

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from plotting_common import save_atomically  # noqa: E402
import matplotlib.ticker  # noqa: E402

COLUMNS = ("label", "h_avg", "dofs", "l2_error", "energy_error")
# (column, name in tables and legends, line style, marker)
NORMS = (("l2_error", "L2", "-", "o"), ("energy_error", "energy", "--", "s"))


class InputError(Exception):
    pass


# --------------------------------------------------------------------------------------------
# Input


def number(text, path, line, column):
    """A float from a CSV cell; empty, 'nan' or '-' is NaN (a run without that value)."""
    text = (text or "").strip()
    if text in ("", "-", "nan", "NaN"):
        return math.nan
    try:
        return float(text)
    except ValueError:
        raise InputError(f"{path}:{line}: column {column}: expected a number, found {text!r}") from None


def read_csv(path):
    """{label: rows sorted by h_avg descending}, labels in order of first appearance.
    Each row is a dict with h_avg, dofs and the error columns as floats."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            header = [c.strip() for c in (reader.fieldnames or [])]
            missing = [c for c in COLUMNS if c not in header]
            if missing:
                raise InputError(f"{path}: missing column{'s' if len(missing) > 1 else ''} "
                                 f"{', '.join(missing)}; expected {','.join(COLUMNS)}, "
                                 f"found {','.join(header) or 'no header'}")
            reader.fieldnames = header
            groups = {}
            for row in reader:
                line = reader.line_num
                if all(not (v or "").strip() for k, v in row.items() if k is not None):
                    continue  # blank line
                label = (row["label"] or "").strip()
                if not label:
                    raise InputError(f"{path}:{line}: empty label")
                h = number(row["h_avg"], path, line, "h_avg")
                if not (h > 0 and math.isfinite(h)):
                    raise InputError(f"{path}:{line}: h_avg must be positive and finite, found {row['h_avg']!r}")
                dofs = number(row["dofs"], path, line, "dofs")
                rec = {"h_avg": h, "dofs": dofs}
                for column, _, _, _ in NORMS:
                    rec[column] = number(row[column], path, line, column)
                groups.setdefault(label, []).append(rec)
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}") from None
    except csv.Error as e:
        raise InputError(f"{path}: not a CSV file: {e}") from None
    if not groups:
        raise InputError(f"{path}: no data rows")
    for label, rows in groups.items():
        rows.sort(key=lambda r: -r["h_avg"])
    return groups


# --------------------------------------------------------------------------------------------
# Rates


def usable(e):
    return math.isfinite(e) and e > 0


def rate(h1, e1, h2, e2):
    """log(e1/e2) / log(h1/h2), or None when undefined."""
    if not (usable(e1) and usable(e2)) or h1 == h2:
        return None
    return math.log(e1 / e2) / math.log(h1 / h2)


def fitted_slope(rows, column):
    """Least-squares slope of log(error) against log(h_avg), or None with fewer than two points
    (or all at one h)."""
    pts = [(r["h_avg"], r[column]) for r in rows if usable(r[column])]
    if len(pts) < 2 or len({h for h, _ in pts}) < 2:
        return None
    x = np.log([h for h, _ in pts])
    y = np.log([e for _, e in pts])
    return float(np.polyfit(x, y, 1)[0])


def fmt_rate(r):
    return "-" if r is None else f"{r:.2f}"


def fmt_err(e):
    return "-" if not math.isfinite(e) else f"{e:.3e}"


def fmt_dofs(d):
    return "-" if not math.isfinite(d) else (f"{int(d)}" if d == int(d) else f"{d:g}")


def print_tables(groups, out=sys.stdout):
    for i, (label, rows) in enumerate(groups.items()):
        header = ["h_avg", "dofs"]
        for _, name, _, _ in NORMS:
            header += [name, "rate"]
        body = []
        for k, r in enumerate(rows):
            line = [f"{r['h_avg']:.4e}", fmt_dofs(r["dofs"])]
            for column, _, _, _ in NORMS:
                prev = rows[k - 1] if k else None
                rt = rate(prev["h_avg"], prev[column], r["h_avg"], r[column]) if prev else None
                line += [fmt_err(r[column]), fmt_rate(rt)]
            body.append(line)
        fit = ["fit", ""]
        for column, _, _, _ in NORMS:
            fit += ["", fmt_rate(fitted_slope(rows, column))]
        widths = [max(len(x[j]) for x in [header] + body + [fit]) for j in range(len(header))]
        if i:
            print(file=out)
        print(f"{label}:", file=out)

        def emit(cells):
            # Left-aligned first column like deal.II's key column, numbers right-aligned.
            parts = [cells[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(cells[1:], widths[1:])]
            print("  ".join(parts).rstrip(), file=out)

        emit(header)
        for line in body:
            emit(line)
        emit(fit)
    print("(rate = log(e1/e2) / log(h1/h2) between consecutive rows; fit: least-squares slope "
          "of log(error) against log(h_avg))", file=out)


# --------------------------------------------------------------------------------------------
# Plot




def label_minor_ticks(axis, lo, hi):
    """Plain numbers on the ticks of a log axis spanning [lo, hi]: on the powers of ten and, for
    a span of a decade or two (a refinement study), on the 2x, 3x and 5x minor ticks too."""
    span = math.log10(hi / lo) if lo > 0 and hi > lo else 0.0
    mantissas = (2, 3, 5) if span <= 1.5 else (2, 5) if span <= 3.0 else ()

    def minor(x, _pos):
        mantissa = x / 10.0 ** math.floor(math.log10(x) + 1e-9)
        m = round(mantissa)
        return f"{x:g}" if m in mantissas and abs(mantissa - m) < 1e-6 else ""

    axis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda x, _pos: f"{x:g}"))
    axis.set_minor_formatter(matplotlib.ticker.FuncFormatter(minor))
    axis.set_tick_params(which="both", labelsize=9)


def plot(groups, out, title, ylabel, dpi):
    fig, ax = plt.subplots(figsize=(7.5, 5.5), layout="constrained")
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    drawn = 0
    for i, (label, rows) in enumerate(groups.items()):
        colour = colours[i % len(colours)]
        for column, name, style, marker in NORMS:
            pts = [(r["h_avg"], r[column]) for r in rows if usable(r[column])]
            if not pts:
                continue
            slope = fitted_slope(rows, column)
            text = f"{label}, {name}: slope {fmt_rate(slope)}" if slope is not None else f"{label}, {name}"
            ax.plot([h for h, _ in pts], [e for _, e in pts], linestyle=style, marker=marker,
                    color=colour, markersize=5, linewidth=1.4, label=text)
            drawn += 1
    if not drawn:
        plt.close(fig)
        raise InputError("no positive error to plot")
    ax.set_xscale("log")
    ax.set_yscale("log")
    hs = [r["h_avg"] for rows in groups.values() for r in rows]
    label_minor_ticks(ax.xaxis, min(hs), max(hs))
    ax.set_xlabel("h_avg (mean cell size)")
    ax.set_ylabel(ylabel)
    ax.grid(which="major", alpha=0.35)
    ax.grid(which="minor", alpha=0.12)
    ax.set_title(title, fontsize=11)
    ax.legend(fontsize=9, frameon=True, framealpha=0.9, loc="best")
    save_atomically(fig, out, dpi)


# --------------------------------------------------------------------------------------------


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n".join(__doc__.split("\n")[1:]))
    ap.add_argument("csv")
    ap.add_argument("out", metavar="OUT.png")
    ap.add_argument("--title", default="convergence: error against h_avg "
                                       "(legend: least-squares slope)")
    ap.add_argument("--ylabel", default="error")
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args(argv)
    if args.dpi <= 0:
        ap.error(f"--dpi must be positive, got {args.dpi}")
    try:
        groups = read_csv(args.csv)
        folder = os.path.dirname(os.path.abspath(args.out))
        if not os.path.isdir(folder):
            raise InputError(f"{args.out}: folder {folder} does not exist")
        print_tables(groups)
        print()
        plot(groups, args.out, args.title, args.ylabel, args.dpi)
    except InputError as e:
        print(f"plot_convergence: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
