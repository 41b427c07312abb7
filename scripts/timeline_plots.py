"""The crack time line of a fragmentation study (dynamics_plots.py draws it): every run's number
of cracked edges against time, from cracks/<id>.csv (the step each edge cracked) and the run's dt
in results.csv, with a dashed line at the run's rear strike (rear_strike_time: when the rear
half of a falling column first touches the plane), so that the bursts of cracking can be read
against the impacts that cause them.
"""
import os

import numpy as np

from plotting_common import light_grid, number, plt, read_table, save_atomically


def plot_crack_timeline(outdir, runs, dpi):
    """plots/crack_timeline.png; nothing when no run has a crack log."""
    drawn = 0
    fig, ax = plt.subplots(figsize=(9, 4.5), layout="constrained")
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, run in enumerate(runs):
        table = read_table(os.path.join(outdir, "cracks", run["id"] + ".csv"))
        dt = number(run.get("dt"))
        if not table or not np.isfinite(dt):
            continue
        t = np.sort(np.asarray(table.get("step", []), dtype=float)) * dt * 1e3
        colour = colours[i % len(colours)]
        ax.step(np.concatenate(([0.0], t)), np.arange(t.size + 1), where="post", color=colour,
                linewidth=1.2, label=run["id"])
        strike = number(run.get("rear_strike_time"))
        if np.isfinite(strike):
            ax.axvline(strike * 1e3, color=colour, linestyle="--", linewidth=0.9)
        drawn += 1
    if not drawn:
        plt.close(fig)
        return
    ax.set(xlabel="time (ms)", ylabel="cracked edges",
           title="cracks against time; dashed: the rear half first touches the plane")
    light_grid(ax)
    ax.legend(fontsize=8, loc="lower right")
    os.makedirs(os.path.join(outdir, "plots"), exist_ok=True)
    save_atomically(fig, os.path.join(outdir, "plots", "crack_timeline.png"), dpi)
