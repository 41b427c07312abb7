"""Helpers shared by the plotting scripts (Debian's numpy and matplotlib only)."""
import argparse
import csv
import math
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402


class InputError(Exception):
    """A missing or malformed input file: one line on stderr, no traceback."""


def replace_atomically(path, write, suffix=".tmp"):
    """Calls write(binary file) on a temporary file beside `path`, then renames it into place
    (readable as a file created normally would be; nothing half-written is ever at `path`)."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".", suffix=suffix)
    try:
        with os.fdopen(fd, "wb") as f:
            write(f)
            f.flush()
            os.fsync(f.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes it private
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_text_atomically(path, text):
    """Writes `text` (UTF-8) to `path` atomically."""
    replace_atomically(path, lambda f: f.write(text.encode("utf-8")))


def save_atomically(fig, path, dpi):
    """Writes the figure to a temporary file beside `path`, then renames it into place."""
    try:
        replace_atomically(path, lambda f: fig.savefig(f, format="png", dpi=dpi), ".tmp.png")
    finally:
        plt.close(fig)
    print(path)


def light_grid(ax):
    """Major and minor grid lines, faint enough not to compete with the data."""
    ax.grid(which="major", alpha=0.35)
    ax.grid(which="minor", alpha=0.12)


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


def outdir_arguments(doc, argv):
    """The command line every study plotter takes: OUTDIR and --dpi (positive, default 150).
    `doc` is the script's docstring: its first line is the description, the rest the epilog."""
    ap = argparse.ArgumentParser(description=doc.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n".join(doc.split("\n")[1:]))
    ap.add_argument("outdir", metavar="OUTDIR")
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args(argv)
    if args.dpi <= 0:
        ap.error(f"--dpi must be positive, got {args.dpi}")
    return args


def number(text):
    """A CSV field as a float; NaN for an empty or missing field."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def read_table(path):
    """A CSV file as {column: list of strings}, or None when it is missing or has no data rows."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError:
        return None
    return {k: [r[k] for r in rows] for k in rows[0]} if rows else None


def columns(table, *names):
    """The named numeric columns as arrays (NaN where a column is absent)."""
    n = len(next(iter(table.values())))
    return [np.array([number(v) for v in table[c]]) if c in table else np.full(n, np.nan)
            for c in names]
