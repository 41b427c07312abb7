#!/usr/bin/env python3
"""The column's elastic diagnostic: how hard the contact hits the cells, before any crack.

Usage: elastic_diagnostic.py OUT [--png FILE] [--json FILE]

OUT is the output folder of a `dynamics` study of the column-impact problem with variants (the
shipped scene `column-impact-elastic`: fracture off, one variant per contact setting). For every
variant and every .vtu frame of its first run, from the cells' mean stresses (Voigt xx, yy, xy):
  - the most compressive principal stress over the cells (MPa, negative);
  - the number of cells whose stress fails the report's Mohr-Coulomb criterion on some plane
    (c = sigma_o = 3.7 MPa, mu = 0.75; 72 plane orientations): the cells a crack would start at.
Beside them, rho c v_n, the stress of a 1D elastic impact at the normal speed (c the dilatational
speed in plane strain, v_n = 7.6 m/s x cos 45 degrees). Prints a table per variant; draws the
peak compression against time (PNG); writes the numbers (JSON) when asked.
Only numpy and matplotlib (Agg) are used (meshio for ASCII frames).
"""
import argparse
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

COHESION, TENSILE_CUTOFF, FRICTION = 3.7e6, 3.7e6, 0.75
E, NU, RHO, SPEED, OBLIQUITY = 28.3e9, 0.2, 2250.0, 7.6, 45.0


def rho_c_vn():
    c = math.sqrt(E * (1 - NU) / (RHO * (1 + NU) * (1 - 2 * NU)))
    return RHO * c * SPEED * math.cos(math.radians(OBLIQUITY))


def frames(variant_dir):
    """(time, file) of every frame of the variant's first run."""
    vtu = os.path.join(variant_dir, "vtu")
    pvd = sorted(f for f in os.listdir(vtu) if f.endswith(".pvd"))[0]
    root = ET.parse(os.path.join(vtu, pvd)).getroot()
    return [(float(d.get("timestep")), os.path.join(vtu, d.get("file")))
            for d in root.iter("DataSet")]


def stresses(path):
    """The cells' mean stresses (xx, yy, xy) of a frame vorodg wrote.

    Read here rather than with meshio: meshio 1.x re-encodes raw appended zlib data in base64
    array by array and misreads some arrays whose lengths fall badly (2 of 813 frames of the
    column, 'mean_stress'). The layout is VTK's: after the '_' of <AppendedData>, each array at its
    offset is a header of UInt64 words [blocks, block size, last block size, compressed sizes]
    and the zlib blocks."""
    import zlib
    with open(path, "rb") as f:
        raw = f.read()
    if b"<AppendedData" not in raw:  # an ASCII frame: meshio reads those right
        import meshio
        return np.concatenate([np.asarray(b) for b in meshio.read(path).cell_data["mean_stress"]])
    start = raw.index(b"_", raw.index(b"<AppendedData")) + 1
    header = raw[:raw.index(b"<AppendedData")].decode()
    tag = header[header.index('Name="mean_stress"'):]
    offset = int(tag[tag.index('offset="') + 8:].split('"', 1)[0])
    words = np.frombuffer(raw, dtype="<u8", count=1, offset=start + offset)
    blocks = int(words[0])
    sizes = np.frombuffer(raw, dtype="<u8", count=3 + blocks, offset=start + offset)[3:]
    at = start + offset + 8 * (3 + blocks)
    data = b""
    for size in sizes:
        data += zlib.decompress(raw[at:at + int(size)])
        at += int(size)
    return np.frombuffer(data, dtype="<f8").reshape(-1, 3)


def failing_cells(s):
    """Cells whose stress fails the Mohr-Coulomb criterion on one of 72 planes."""
    theta = np.linspace(0.0, math.pi, 72, endpoint=False)
    n = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    sx, sy, sxy = s[:, 0:1], s[:, 1:2], s[:, 2:3]
    tx = sx * n[:, 0] + sxy * n[:, 1]
    ty = sxy * n[:, 0] + sy * n[:, 1]
    normal = tx * n[:, 0] + ty * n[:, 1]
    shear = -tx * n[:, 1] + ty * n[:, 0]
    room = COHESION - FRICTION * normal
    fails = (normal >= TENSILE_CUTOFF) | (room <= 0) | (np.abs(shear) >= room)
    return int(np.count_nonzero(fails.any(axis=1)))


def most_compressive(s):
    centre = 0.5 * (s[:, 0] + s[:, 1])
    radius = np.hypot(0.5 * (s[:, 0] - s[:, 1]), s[:, 2])
    return float(np.min(centre - radius))


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--png")
    p.add_argument("--json")
    a = p.parse_args(argv)
    variants = sorted(d for d in os.listdir(a.out) if os.path.isdir(os.path.join(a.out, d)))
    data = {}
    for v in variants:
        rows = []
        for t, f in frames(os.path.join(a.out, v)):
            s = stresses(f)
            rows.append({"time": t, "peak_compression": most_compressive(s),
                         "failing_cells": failing_cells(s), "cells": int(len(s))})
        data[v] = rows
    reference = rho_c_vn()
    print(f"rho c v_n = {reference / 1e6:.1f} MPa")
    for v, rows in data.items():
        peak = min(r["peak_compression"] for r in rows)
        worst = max(r["failing_cells"] for r in rows)
        print(f"{v}: peak compression {peak / 1e6:.1f} MPa ({peak / -reference:.2f} x rho c v_n), "
              f"at most {worst} of {rows[0]['cells']} cells past the criterion")
    if a.json:
        with open(a.json + ".tmp", "w") as f:
            json.dump({"rho_c_vn": reference, "variants": data}, f, indent=1)
        os.replace(a.json + ".tmp", a.json)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(11, 4), layout="constrained")
        for v, rows in data.items():
            t = [1e3 * r["time"] for r in rows]
            axes[0].plot(t, [r["peak_compression"] / 1e6 for r in rows], label=v)
            axes[1].plot(t, [r["failing_cells"] for r in rows], label=v)
        axes[0].axhline(-reference / 1e6, color="k", linestyle="--", label="-rho c v_n")
        axes[0].set(xlabel="t [ms]", ylabel="most compressive cell stress [MPa]")
        axes[1].set(xlabel="t [ms]", ylabel="cells past Mohr-Coulomb")
        axes[0].legend(fontsize=8)
        fig.suptitle("column-impact, fracture off: what the contact does to the cells")
        fig.savefig(a.png + ".tmp.png", dpi=110)
        os.replace(a.png + ".tmp.png", a.png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
