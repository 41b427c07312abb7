#!/usr/bin/python3
"""The ablation table of a fragmentation study with variants (column-impact-ablation): one
Markdown table per mesh block, one row per variant, in the scene's order.

Usage:
  ablation_table.py OUTDIR SCENE.json

Per variant and block, over its complete runs: the fragments and the largest fragment's share of
the mass (mean, and min to max), the mass in single-cell fragments, where the broken edges are
(near the impact / mid-length / elsewhere, results.csv's broken_* fractions), the largest
fragment's turn |main_body_rotation|, the rear strike (mean time of the runs whose rear half
touched the plane, and how many did), the peak force of the plane, and where the energy went, as
shares of the input (the initial kinetic energy plus gravity's work, history/<id>.csv): the
cohesive law's dissipation, friction on the faces and on contact, contact's velocity penalty
(what contact's work took beyond its friction and its springs' energy at the end), bulk
viscosity; the worst balance with the closed forms; the median run time.
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting_common import number, read_table  # noqa: E402


def rows_of(path):
    table = read_table(path) or {}
    return [dict(zip(table, values)) for values in zip(*table.values())]


def energy_shares(outdir, run):
    """Shares of the input energy of a run, from the first and last rows of its history."""
    history = rows_of(os.path.join(outdir, "history", run["id"] + ".csv"))
    if not history:
        return {}
    first, last = history[0], history[-1]
    put_in = number(first["kinetic_energy"]) + number(first["elastic_energy"]) + \
        number(last["external_work"])
    friction = number(run.get("contact_friction_dissipated"))
    velocity = -number(last["contact_work"]) - number(last["contact_potential"]) - \
        (friction if np.isfinite(friction) else 0.0)
    bulk = number(last.get("bulk_viscosity_dissipation", "nan"))
    return {"law": number(run["dissipated_energy"]) / put_in,
            "faces": number(run.get("face_friction_dissipated")) / put_in,
            "contact friction": friction / put_in, "velocity penalty": velocity / put_in,
            "bulk": bulk / put_in}


def spread(values, scale=1.0, digits=3):
    v = np.asarray([x for x in values if np.isfinite(x)]) * scale
    if v.size == 0:
        return "-"
    if v.size == 1 or np.ptp(v) == 0:
        return f"{v.mean():.{digits}g}"
    return f"{v.mean():.{digits}g} ({v.min():.{digits}g} to {v.max():.{digits}g})"


def mean(values, scale=1.0, digits=2):
    v = np.asarray([x for x in values if np.isfinite(x)]) * scale
    return f"{v.mean():.{digits}g}" if v.size else "-"


def row(label, outdir, runs):
    col = lambda name: [number(r.get(name)) for r in runs]  # noqa: E731
    shares = [energy_shares(outdir, r) for r in runs]
    share = lambda key: mean([s.get(key, np.nan) for s in shares], 100)  # noqa: E731
    strikes = [t for t in col("rear_strike_time") if np.isfinite(t)]
    strike = f"{np.mean(strikes) * 1e3:.0f} ms ({len(strikes)}/{len(runs)})" if strikes \
        else f"none (0/{len(runs)})"
    where = " / ".join(mean(col(k), 100) for k in
                       ("broken_near_impact", "broken_mid_length", "broken_elsewhere"))
    cells = [label, str(len(runs)), spread(col("fragments")),
             spread(col("max_fragment_mass_fraction"), 100, 2),
             mean(col("single_cell_mass_fraction"), 100), where,
             mean([abs(x) for x in col("main_body_rotation")]), strike,
             mean(col("peak_wall_force"), 1e-6), share("law"), share("faces"),
             share("contact friction"), share("velocity penalty"), share("bulk"),
             f"{np.nanmax(col('law_balance_error')):.1e}", f"{np.median(col('seconds')):.0f}"]
    return "| " + " | ".join(cells) + " |"


HEADER = ("| variant | runs | fragments | largest fragment [%] | mass in single cells [%] | "
          "broken near impact / mid-length / elsewhere [%] | main body's turn [rad] | "
          "rear strike | peak plane force [MN/m] | law [%] | face friction [%] | "
          "contact friction [%] | velocity penalty [%] | bulk viscosity [%] | law balance | "
          "run [s] |\n" + "|---" * 16 + "|")


def main(argv):
    outdir, scene_path = argv[0], argv[1]
    scene = json.load(open(scene_path))
    labels = [v["label"] for v in scene["variants"]]
    blocks = [m.get("label", m.get("family", "rcp")) for m in scene["meshes"]]
    for block, mesh in zip(blocks, scene["meshes"]):
        print(f"\n{block}, h = {mesh['sizes'][0] * 1e3:.1f} mm:\n\n{HEADER}")
        for label in labels:
            runs = [r for r in rows_of(os.path.join(outdir, label, "results.csv"))
                    if r.get("mesh") == block and r.get("complete") in ("1", "true")]
            if runs:
                print(row(label, os.path.join(outdir, label), runs))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
