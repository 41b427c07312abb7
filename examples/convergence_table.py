"""The demo study's CG convergence table, from Python: run the shipped scene, then build the
table from its records in a dozen lines, and check it against the one the study wrote.

Per level: the mean h_avg and DOFs of its realizations, the mean and sample standard deviation
of each error, and the rate between consecutive levels, log(e1 / e0) / log(h1 / h0), from the
means (docs/design.md: on random meshes, rates against h_avg).

    PYTHONPATH=build /usr/bin/python3 examples/convergence_table.py [OUTPUT]
"""
import pathlib
import sys

import numpy as np

import vorodg


def table(records):
    """The markdown rows of the study's table for these records (one formulation)."""
    rows, previous = [], None
    for level in sorted({r["level"] for r in records}):
        runs = [r for r in records if r["level"] == level]
        h, dofs, iterations = (np.mean([r[k] for r in runs]) for k in ("h_avg", "dofs", "iterations"))
        l2, energy = (np.array([r[k] for r in runs]) for k in ("l2_error", "energy_error"))
        rates = ["-", "-"] if previous is None else [
            f"{np.log(e.mean() / e0) / np.log(h / previous[0]):.3g}"
            for e, e0 in ((l2, previous[1]), (energy, previous[2]))]
        rows.append(f"| {level} | {h:.4g} | {dofs:.6g} | {len(runs)} "
                    f"| {l2.mean():.3e} ± {l2.std(ddof=1):.1e} | {rates[0]} "
                    f"| {energy.mean():.3e} ± {energy.std(ddof=1):.1e} | {rates[1]} | {iterations:.3g} |")
        previous = (h, l2.mean(), energy.mean())
    return rows


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python-demo")
    result = vorodg.run("demo", str(out), progress=False, plots=False)
    rows = table([r for r in result["records"] if r["formulation"] == "cg"])
    print("\n".join(rows))
    report = (out / "report.md").read_text()
    section = report.split("## rcp | beam | cg")[1].split("##")[0]
    assert all(row in section for row in rows), "the table differs from the study's report.md"
    print(f"identical to the CG table of {out / 'report.md'}")


if __name__ == "__main__":
    main()
