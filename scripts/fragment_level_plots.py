"""The report's fragment-mass figures over mesh levels, with the sample's uncertainty drawn.

The report's Figures 15 and 17-19 show, per mesh level, the fragment mass-fraction CDF of each of
twelve realizations, and its Figure 20 the largest fragment of each run per level. With hundreds
of realizations per level, single curves say little: what the question of convergence in
distribution asks about is the expected CDF, F(x) = E[F_i(x)], the mean over realizations of a
run's CDF (a run's fragments are not independent draws, so pooling them and using a DKW band
would claim far too much).

The band of F is simultaneous: the 95 % quantile c of sup_x |mean* - mean| over bootstrap
resamples of the realizations (each realization's CDF is one draw of a random function), so that
[mean - c, mean + c] holds the whole expected CDF at about 95 %. It is evaluated on a log grid of
x (GRID points from the smallest fraction to 1), which can only miss a little of the sup between
grid points. Beside it, the 5-95 % envelope of single realizations says how far one run strays.
The arrow of Figures 15-19 (the mean of the largest fragment) is drawn with its interval from
statistical-levels.csv when the report computed one.
"""
import os

import numpy as np

from plotting_common import columns, light_grid, number, plt, read_table, save_atomically

GRID = 400
RESAMPLES = 1000
SHOWN_REALIZATIONS = 12  # as many single curves as the report drew
SEED = 2008  # the bootstrap's generator: the same figure on every redraw


def cdf_on_grid(fractions, grid):
    """One run's CDF of its fragment mass fractions at the grid points: share of fragments <= x."""
    f = np.sort(np.asarray(fractions, dtype=float))
    return np.searchsorted(f, grid, side="right") / f.size


def mean_cdf_band(runs, grid, confidence=0.95, resamples=RESAMPLES, seed=SEED):
    """The mean of the runs' CDFs on the grid and the half-width of its simultaneous band (the
    bootstrap quantile of the largest deviation over the grid). runs: one array of fractions per
    realization."""
    cdfs = np.array([cdf_on_grid(r, grid) for r in runs])
    mean = cdfs.mean(axis=0)
    if len(runs) < 2:
        return cdfs, mean, np.nan
    rng = np.random.default_rng(seed)
    counts = rng.multinomial(len(runs), np.full(len(runs), 1.0 / len(runs)), size=resamples)
    deviation = np.abs(counts @ cdfs / len(runs) - mean).max(axis=1)
    return cdfs, mean, float(np.quantile(deviation, confidence))


def log_grid(runs):
    smallest = min(np.min(r) for r in runs)
    return np.geomspace(smallest, 1.0, GRID)


def largest_interval(outdir, mesh, level):
    """(mean, low, high) of the largest fragment at one level from statistical-levels.csv, or
    None where the scene had no statistics for it."""
    table = read_table(os.path.join(outdir, "statistical-levels.csv"))
    if not table or "quantity" not in table:
        return None
    lv, mean, low, high = columns(table, "level", "mean", "mean low", "mean high")
    for i, (m, q) in enumerate(zip(table["mesh"], table["quantity"])):
        if m == mesh and q == "max_fragment_mass_fraction" and lv[i] == number(level):
            return mean[i], low[i], high[i]
    return None


def draw_band(ax, grid, mean, band, colour, label):
    ax.plot(grid, mean, color=colour, linewidth=2.0, label=label)
    if np.isfinite(band):
        ax.fill_between(grid, np.clip(mean - band, 0, 1), np.clip(mean + band, 0, 1),
                        color=colour, alpha=0.25, linewidth=0)


def plot_level(outdir, mesh, level, members, dpi):
    """Figures 15, 17-19 for one level: members are (run, fractions) of its complete runs."""
    runs = [fractions for _, fractions in members]
    grid = log_grid(runs)
    cdfs, mean, band = mean_cdf_band(runs, grid)
    fig, ax = plt.subplots(figsize=(6.5, 4.5), layout="constrained")
    shown = sorted(members, key=lambda m: number(m[0].get("realization", 0)))[:SHOWN_REALIZATIONS]
    for run, fractions in shown:
        f = np.sort(fractions)
        ax.step(f, np.arange(1, f.size + 1) / f.size, where="post", linewidth=0.7, alpha=0.55,
                color="0.45")
    if len(runs) >= 20:
        low, high = np.quantile(cdfs, [0.05, 0.95], axis=0)
        ax.fill_between(grid, low, high, color="tab:orange", alpha=0.15, linewidth=0,
                        label="5-95 % of single runs")
    draw_band(ax, grid, mean, band, "tab:blue",
              f"mean CDF of {len(runs)} runs, 95 % simultaneous band (+-{band:.3f})")
    largest = largest_interval(outdir, mesh, level)
    if largest is None:
        m = np.mean([np.max(r) for r in runs])
        largest = (m, m, m)
    ax.annotate("", xy=(largest[0], 0.0), xytext=(largest[0], 0.25),
                arrowprops=dict(arrowstyle="->", color="tab:red"))
    ax.plot([largest[1], largest[2]], [0.02, 0.02], color="tab:red", linewidth=3,
            label=f"mean largest fragment {largest[0]:.3f} [{largest[1]:.3f}, {largest[2]:.3f}]")
    ax.set(xscale="log", xlabel="fragment mass / total mass", ylabel="cumulative fraction",
           ylim=(0, 1.02), title=f"{mesh}, level {level}: {len(runs)} realizations "
           f"({len(shown)} drawn grey)")
    light_grid(ax)
    ax.legend(fontsize=7, loc="upper left")
    save_atomically(fig, os.path.join(outdir, "plots", f"fragment_cdf_{mesh}_L{level}.png"), dpi)


def plot_levels(outdir, levels, dpi):
    """Figure 20 and the levels' mean CDFs: levels maps (mesh, level) to its members."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    ordered = sorted(levels.items(), key=lambda kv: -np.mean([number(r["h_avg"]) for r, _ in
                                                              kv[1]]))
    for (mesh, level), members in ordered:
        h = np.array([number(r["h_avg"]) for r, _ in members])
        largest = np.array([number(r["max_fragment_mass_fraction"]) for r, _ in members])
        dots = left.plot(h, largest, "o", alpha=0.25, markersize=3)[0]
        interval = largest_interval(outdir, mesh, level)
        if interval is not None:
            left.errorbar(h.mean(), interval[0], yerr=[[interval[0] - interval[1]],
                                                       [interval[2] - interval[0]]],
                          fmt="s", color="k", capsize=4)
        else:
            left.plot(h.mean(), largest.mean(), "s", color="k")
        runs = [fractions for _, fractions in members]
        grid = log_grid(runs)
        _, mean, band = mean_cdf_band(runs, grid)
        draw_band(right, grid, mean, band, dots.get_color(),
                  f"{mesh} L{level}, h_avg {h.mean():.3g} ({len(runs)} runs, +-{band:.3f})")
    left.set(xscale="log", xlabel="h_avg (m)", ylabel="largest fragment / total mass",
             title="every run; the level's mean with its 95 % interval")
    right.set(xscale="log", xlabel="fragment mass / total mass", ylabel="mean cumulative fraction",
              title="mean CDF per level, 95 % simultaneous bands")
    for ax in (left, right):
        light_grid(ax)
    right.legend(fontsize=7, loc="upper left")
    save_atomically(fig, os.path.join(outdir, "plots", "largest_fragment_vs_h.png"), dpi)
