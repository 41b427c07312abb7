"""The per-edge coercive penalty of a penalty study (penalty_edges.csv, written by
`vorodg run`): eps h_avg / E against the edge length / h_avg, one panel per traction, coloured by
mesh level. Shows where a penalty that scales with 1/h alone is wrong."""
import csv
import os

from plotting_common import light_grid, plt, save_atomically


def plot_penalty_edges(outdir, dpi):
    path = os.path.join(outdir, "penalty_edges.csv")
    if not os.path.exists(path):
        return False
    rows = {}
    with open(path, newline="") as f:
        records = list(csv.DictReader(f))
    several = len({r["element"] for r in records}) > 1  # name the element only if it varies
    for r in records:
        element = f" {r['element']}" if several else ""
        key = (r["traction"], f"{r['mesh']}{element} level {r['level']}")
        rows.setdefault(key, []).append((float(r["edge_length_over_h_avg"]),
                                         float(r["eps_over_E_per_h_avg"])))
    tractions = sorted({t for t, _ in rows})
    fig, axes = plt.subplots(1, len(tractions), figsize=(5.5 * len(tractions), 4.6),
                             squeeze=False, sharex=True)
    for ax, traction in zip(axes[0], tractions):
        for (t, level), pts in sorted(rows.items()):
            if t != traction:
                continue
            xs, ys = zip(*pts)
            ax.loglog(xs, ys, ".", ms=3, alpha=0.6, label=level)
        ax.set_title(f"traction: {traction}")
        ax.set_xlabel("edge length / h_avg")
        ax.set_ylabel("coercive penalty eps h_avg / E (k_p = 1)")
        light_grid(ax)
        ax.legend(fontsize=8, markerscale=3)
    fig.suptitle("Per-interface coercive penalty against edge length", fontsize=11.5)
    fig.tight_layout()
    save_atomically(fig, os.path.join(outdir, "penalty_edges.png"), dpi)
    return True
