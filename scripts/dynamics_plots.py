#!/usr/bin/python3
"""Draws the energy plots of one dynamics study from OUTDIR (written by `vorodg run` on a dynamics
scene).

Usage:
  dynamics_plots.py OUTDIR [--dpi N]

Reads results.csv and history/<id>.csv in OUTDIR and writes, each atomically (temporary file
beside it, then renamed), printing its path:
  plots/<id>_energy.png  per run, two panels against time (ms):
                         top: kinetic and elastic energy, external work (loads and prescribed
                         velocities), contact work, damping, cohesive work (fragmentation), and
                         kinetic + elastic;
                         bottom: the energy balance error |balance - balance(0)| / input (log)
                         and, when contacts occur, the number of contacts (right axis).
  plots/<id>_fragments.png  per fragmentation run (fragments/<id>.csv): the fragments' x
                         velocity against their centre's x, and their mass-fraction CDF.
  plots/<id>_snapshots.png  per run with snapshots (snapshots/<id>.csv, outputs.snapshots): the
                         deformed mesh at each snapshot time, the cells of each fragment of two
                         or more cells in a colour of their own, single-cell fragments grey, and
                         the rigid plane (wall.point, wall.normal of summary.json) shaded
                         (cracks show as gaps where nodes split); reads .vtu with meshio.
  plots/crack_timeline.png  for a fragmentation study: each run's cracked edges against time,
                         a dashed line at its rear strike (column-impact; timeline_plots.py).
  plots/fragment_cdf_<mesh>_L<level>.png  per mesh and level of a fragmentation study (the
                         report's Figures 15, 17-19): the first twelve realizations' fragment
                         mass-fraction CDFs, the mean CDF over all complete realizations with a
                         95 % simultaneous bootstrap band, the 5-95 % envelope of single runs,
                         and an arrow at the mean largest fragment (fragment_level_plots.py).
  plots/largest_fragment_vs_h.png  for a fragmentation study over two or more mesh levels
                         (Figure 20): the largest fragment's mass fraction of every complete run
                         against h_avg with each level's mean and its interval (left), and each
                         level's mean fragment CDF with its band (right).
  plots/fragments_by_variant.png  for the folder of a fragmentation study with variants (one
                         subfolder each): the fragment count (mean, standard deviation and every
                         run) and the largest fragment's mass fraction against the one scene key
                         the variants vary (log axes over a decade or more).
  plots/perturbation_hamming.png  for the folder of a `perturb` study (perturbation.csv): each
                         variant's Hamming distance to perturb-0 against the step, log axis
                         (zero distances are not drawn; the report lists them).
  plots/perturbation_fragment_cdf.png  for the same folder: the fragment mass-fraction CDF of
                         every perturbed run in one plot, perturb-0's in black, and the mean
                         of the variations' CDFs with its simultaneous band (Figure 16).
A run without a history is left out (one line on stderr); the exit code is always 0.
Only the Python standard library, numpy, matplotlib (Agg) and, for snapshots, meshio are used.
"""
import csv
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import (  # noqa: E402
    columns, light_grid, number, outdir_arguments, plt, read_table, save_atomically)
from snapshot_plots import plot_snapshots  # noqa: E402
from timeline_plots import plot_crack_timeline  # noqa: E402
import statistics_plots  # noqa: E402
import fragment_level_plots  # noqa: E402

# (history column, legend label, colour): the energies of the top panel.
ENERGIES = (("kinetic_energy", "kinetic", "tab:blue"),
            ("elastic_energy", "elastic", "tab:orange"),
            ("external_work", "external work", "tab:green"),
            ("contact_work", "contact work", "tab:red"),
            ("dissipated_energy", "dissipated", "tab:purple"),
            ("cohesive_work", "cohesive work", "tab:brown"),
            ("bulk_viscosity_dissipation", "bulk viscosity", "tab:pink"))


def skip(what, why):
    print(f"dynamics_plots: {what} left out: {why}", file=sys.stderr)


def read_runs(outdir):
    """The rows of results.csv, as dicts, in file order."""
    table = read_table(os.path.join(outdir, "results.csv")) or {}
    return [dict(zip(table, values)) for values in zip(*table.values())]


def plot_energy(outdir, run, dpi):
    table = read_table(os.path.join(outdir, "history", run["id"] + ".csv"))
    if not table:
        return skip(f"the energy plot of {run['id']}", "no history")
    t = columns(table, "time")[0] * 1e3
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True, layout="constrained",
                                      gridspec_kw={"height_ratios": (3, 2)})
    for name, label, colour in ENERGIES:
        y = columns(table, name)[0]
        if np.any(np.abs(np.nan_to_num(y)) > 0):  # a term that never acts stays off the plot
            top.plot(t, y, color=colour, linewidth=1.3, label=label)
    total = columns(table, "kinetic_energy")[0] + columns(table, "elastic_energy")[0]
    top.plot(t, total, color="black", linewidth=1.0, linestyle="--", label="kinetic + elastic")
    top.set(ylabel="energy per unit thickness (J/m)")
    light_grid(top)
    top.legend(fontsize=8.5, loc="best")
    error = columns(table, "balance_error")[0]
    error[~(error > 0)] = np.nan  # exactly zero (step 0): not on a log axis
    if np.any(np.isfinite(error)):
        bottom.plot(t, error, color="0.3", linewidth=1.0, label="|balance - balance(0)| / input")
        bottom.set_yscale("log")
    bottom.set(xlabel="time (ms)", ylabel="energy balance error")
    light_grid(bottom)
    handles, labels = bottom.get_legend_handles_labels()
    contacts = columns(table, "contacts")[0]
    if np.nansum(contacts) > 0:
        right = bottom.twinx()
        right.plot(t, contacts, color="tab:red", linewidth=0.9, alpha=0.6, label="contacts")
        right.set_ylabel("contacts")
        h, lab = right.get_legend_handles_labels()
        handles, labels = handles + h, labels + lab
    if handles:
        bottom.legend(handles, labels, fontsize=8.5, loc="upper left")
    top.set_title(f"{run['id']}: {run.get('problem', '')}, {run.get('cells', '?')} cells, "
                  f"dt {number(run.get('dt')):.3g} s, final balance error "
                  f"{number(run.get('energy_balance_error')):.2e}", fontsize=10)
    os.makedirs(os.path.join(outdir, "plots"), exist_ok=True)
    save_atomically(fig, os.path.join(outdir, "plots", run["id"] + "_energy.png"), dpi)


def read_fragments(outdir, run):
    table = read_table(os.path.join(outdir, "fragments", run["id"] + ".csv"))
    return table if table and len(table.get("mass", [])) else None


def mass_cdf(table):
    """The fragment mass fractions, ascending, and (i + 1) / n."""
    m = np.sort(np.asarray(table["mass"], dtype=float))
    return m / m.sum(), np.arange(1, m.size + 1) / m.size


def plot_fragments(outdir, run, table, dpi):
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    x, vx = (np.asarray(table[k], dtype=float) for k in ("x", "vx"))
    left.plot(x * 1e3, vx, "o", markersize=3.5, color="tab:blue")
    left.set(xlabel="fragment centre x (mm)", ylabel="fragment velocity x (m/s)")
    light_grid(left)
    fraction, cdf = mass_cdf(table)
    right.step(fraction, cdf, where="post", color="tab:blue")
    right.set(xscale="log", xlabel="fragment mass / total mass", ylabel="cumulative fraction")
    light_grid(right)
    fig.suptitle(f"{run['id']}: {len(x)} fragments, largest {fraction.max():.3f} of the mass",
                 fontsize=10)
    save_atomically(fig, os.path.join(outdir, "plots", run["id"] + "_fragments.png"), dpi)


def level_groups(outdir, runs):
    """The complete runs with a fragment table, by (mesh, level): lists of (run, mass fractions)."""
    groups = {}
    for run in runs:
        table = read_fragments(outdir, run)
        if table and run.get("complete") == "1":
            groups.setdefault((run.get("mesh", "?"), run.get("level", "?")), []).append(
                (run, mass_cdf(table)[0]))
    return groups


def plot_level_cdfs(outdir, runs, dpi):
    """Figures 15, 17-19: per level, the mean fragment CDF with its band (fragment_level_plots)."""
    for (mesh, level), members in level_groups(outdir, runs).items():
        fragment_level_plots.plot_level(outdir, mesh, level, members, dpi)


def plot_levels(outdir, runs, dpi):
    """Figure 20 and the levels' mean CDFs, for two or more levels."""
    groups = level_groups(outdir, runs)
    if len(groups) >= 2:
        fragment_level_plots.plot_levels(outdir, groups, dpi)


def plot_perturbation(outdir, dpi):
    """Figure 22: the crack-state distance of each perturbed run to the reference run."""
    curves = {}
    with open(os.path.join(outdir, "perturbation.csv"), newline="") as f:
        for row in csv.DictReader(f):
            key = (row["variant"], row["value"], row["run"])
            curves.setdefault(key, []).append((int(row["step"]), int(row["distance"])))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    drawn = 0
    for (variant, value, run), points in sorted(curves.items()):
        steps = np.array([p[0] for p in points])
        distance = np.array([p[1] for p in points], dtype=float)
        shown = distance > 0
        if shown.any():
            ax.step(steps[shown], distance[shown], where="post", label=f"{value} ({run})")
            drawn += 1
    ax.set_yscale("log")
    ax.set_xlabel("step")
    ax.set_ylabel("Hamming distance to perturb-0")
    ax.set_title(f"{drawn} of {len(curves)} runs differ from the reference")
    light_grid(ax)
    if drawn:
        ax.legend(fontsize=7)
    os.makedirs(os.path.join(outdir, "plots"), exist_ok=True)
    save_atomically(fig, os.path.join(outdir, "plots", "perturbation_hamming.png"), dpi)


def plot_perturbation_cdfs(outdir, dpi):
    """Figure 16: the fragment mass-fraction CDF of every variant's runs in one plot (grey), the
    reference (perturb-0) in black, and the mean of the variants' CDFs with its 95 % simultaneous
    band (fragment_level_plots): is the reference a typical member of its variations?"""
    fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
    variants, reference = [], []
    for name in sorted(os.listdir(outdir), key=lambda n: (len(n), n)):
        if not name.startswith("perturb-"):
            continue
        for run in read_runs(os.path.join(outdir, name)):
            table = read_fragments(os.path.join(outdir, name), run)
            if not table:
                continue
            fraction, cdf = mass_cdf(table)
            if name == "perturb-0":
                reference.append(fraction)
                ax.step(fraction, cdf, where="post", color="black", linewidth=2.0, zorder=3,
                        label=f"{name}, the reference ({run['id']})")
            else:
                ax.step(fraction, cdf, where="post", color="0.45", linewidth=0.8, alpha=0.6,
                        label=None if variants else "a variation (each grey curve)")
                variants.append(fraction)
    if not variants and not reference:
        plt.close(fig)
        return
    if len(variants) >= 2:
        grid = fragment_level_plots.log_grid(variants + reference)
        _, mean, band = fragment_level_plots.mean_cdf_band(variants, grid)
        fragment_level_plots.draw_band(
            ax, grid, mean, band, "tab:blue",
            f"mean of the {len(variants)} variations, 95 % simultaneous band (+-{band:.3f})")
    ax.set(xscale="log", xlabel="fragment mass / total mass", ylabel="cumulative fraction",
           ylim=(0, 1.02), title=f"fragment mass CDFs of {len(variants) + len(reference)} runs "
           "(perturb-0 in black)")
    light_grid(ax)
    ax.legend(fontsize=7, loc="upper left")
    save_atomically(fig, os.path.join(outdir, "plots", "perturbation_fragment_cdf.png"), dpi)


def read_variants(outdir):
    """[(label, settings, rows of results.csv)] of the fragmentation subfolders of outdir."""
    variants = []
    for name in sorted(os.listdir(outdir)):
        summary = os.path.join(outdir, name, "summary.json")
        if not os.path.isfile(summary):
            continue
        with open(summary) as f:
            s = json.load(f)
        if s.get("study") == "fragmentation":
            variants.append((name, s.get("settings", {}), read_runs(os.path.join(outdir, name))))
    return variants


def varied_key(variants):
    """The one numeric setting whose value differs between the variants (None otherwise). The
    time.* settings are left out: when a scene does not set them they follow from the others."""
    keys = [k for k in variants[0][1]
            if not k.startswith("time.") and len({str(v[1].get(k)) for v in variants}) > 1]
    numeric = [k for k in keys if all(np.isfinite(number(str(v[1].get(k)))) for v in variants)]
    return numeric[0] if len(numeric) == 1 else None


def plot_variants(outdir, variants, dpi):
    """Fragment count and largest fragment against the key the variants vary."""
    key = varied_key(variants)
    variants.sort(key=lambda v: number(str(v[1].get(key))) if key else v[0])
    x = np.array([number(str(v[1].get(key))) if key else i for i, v in enumerate(variants)])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, column, label in ((axes[0], "fragments", "fragments"),
                              (axes[1], "max_fragment_mass_fraction", "largest fragment / mass")):
        values = [np.array([number(r[column]) for r in v[2]]) for v in variants]
        for xi, v in zip(x, values):
            ax.plot(np.full(v.size, xi), v, ".", color="0.7")
        means = np.array([v.mean() for v in values])
        spread = np.array([v.std(ddof=1) if v.size > 1 else 0.0 for v in values])
        ax.errorbar(x, means, yerr=spread, fmt="o-", capsize=3, label="mean and sd")
        if key and x.min() > 0 and x.max() >= 10 * x.min():
            ax.set_xscale("log")
            ax.set_yscale("log")
        ax.set_xlabel(key or "variant")
        if not key:
            ax.set_xticks(x, [v[0] for v in variants])
        ax.set_ylabel(label)
        light_grid(ax)
    axes[0].legend(fontsize=8)
    runs = sum(len(v[2]) for v in variants)
    fig.suptitle(f"{len(variants)} variants, {runs} runs")
    fig.tight_layout()
    os.makedirs(os.path.join(outdir, "plots"), exist_ok=True)
    save_atomically(fig, os.path.join(outdir, "plots", "fragments_by_variant.png"), dpi)


def plot_statistics(outdir, _runs, dpi):
    """The statistical report's figures (statistics_plots.py), where the scene asked for one."""
    statistics_plots.draw_all(outdir, dpi)


def main(argv):
    args = outdir_arguments(__doc__, argv)
    variants = read_variants(args.outdir)
    if len(variants) >= 2:
        try:
            plot_variants(args.outdir, variants, args.dpi)
        except Exception as e:
            plt.close("all")
            skip("the plot across variants", f"{type(e).__name__}: {e}")
    if os.path.exists(os.path.join(args.outdir, "perturbation.csv")):
        for what, plot in (("the perturbation plot", plot_perturbation),
                           ("the CDFs across the perturbed runs", plot_perturbation_cdfs)):
            try:
                plot(args.outdir, args.dpi)
            except Exception as e:
                plt.close("all")
                skip(what, f"{type(e).__name__}: {e}")
        return 0
    runs = [r for r in read_runs(args.outdir) if r.get("id")]
    if not runs:
        if not variants:
            skip("every figure", f"no runs in {os.path.join(args.outdir, 'results.csv')}")
        return 0
    for run in runs:
        try:
            plot_energy(args.outdir, run, args.dpi)
        except Exception as e:  # one bad figure must not cost the others
            plt.close("all")
            skip(f"the energy plot of {run['id']}", f"{type(e).__name__}: {e}")
        try:
            plot_snapshots(args.outdir, run, args.dpi)
        except Exception as e:
            plt.close("all")
            skip(f"the snapshots of {run['id']}", f"{type(e).__name__}: {e}")
        table = read_fragments(args.outdir, run)
        if table:
            try:
                plot_fragments(args.outdir, run, table, args.dpi)
            except Exception as e:
                plt.close("all")
                skip(f"the fragment plot of {run['id']}", f"{type(e).__name__}: {e}")
    for what, plot in (("the crack time line", plot_crack_timeline),
                       ("the fragment CDFs", plot_level_cdfs),
                       ("the plot over the levels", plot_levels),
                       ("the statistical convergence", plot_statistics)):
        try:
            plot(args.outdir, runs, args.dpi)
        except Exception as e:
            plt.close("all")
            skip(what, f"{type(e).__name__}: {e}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
