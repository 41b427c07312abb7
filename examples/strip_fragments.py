"""Fragments of a stretched strip, from Python: one run of the shipped quick strip scene at its
slowest strain rate, and what its fragments do.

The strip is stretched by v = rate (x - x_mid), free at both ends, and breaks into fragments
that fly apart at about the velocity of their centre in that field (neighbours may still knock
into each other). What must hold exactly: their masses add up to the strip's, and their momenta
to the initial one, zero.

    PYTHONPATH=build /usr/bin/python3 examples/strip_fragments.py [OUTPUT]
"""
import json
import pathlib
import sys

import numpy as np

import vorodg

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python-strip")
    scene = json.loads((ROOT / "data" / "scenes" / "strip-fragmentation-quick.json").read_text())
    label = scene["variants"][0]["label"]
    r = vorodg.fragmentation_run(scene, str(out), variant=label)
    f, record = r["fragments"], r["record"]
    order = np.argsort(f["centre"][:, 0])
    print(f"{label}: {len(f['mass'])} fragments, {record['broken_edges']:.0f} broken edges, "
          f"energy balance {record['max_energy_balance_error']:.1e}")
    print("   x centre (mm)   mass fraction   vx (m/s)")
    for k in order:
        print(f"   {1e3 * f['centre'][k, 0]:12.3f}   {f['mass'][k] / f['mass'].sum():13.4f}"
              f"   {f['velocity'][k, 0]:8.3f}")
    density = scene["material"]["density"]
    assert np.isclose(f["mass"].sum(), density * r["mesh"].cell_areas().sum(), rtol=1e-12)
    momentum = f["mass"] @ f["velocity"]
    assert np.all(np.abs(momentum) <= 1e-9 * f["mass"] @ np.abs(f["velocity"][:, 0])), momentum
    print(f"total momentum {momentum} kg m/s per unit thickness")


if __name__ == "__main__":
    main()
