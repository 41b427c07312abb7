"""The patch tests on a mesh you made yourself: scipy's Voronoi diagram (Qhull) of random seeds
in the unit square, handed to vorodg as arrays, solved by every formulation.

The seeds are mirrored across the square's four sides, so that every original seed's Voronoi
region is a closed polygon inside the square; its corners are renumbered and put in
counter-clockwise order. vorodg validates the mesh (ValueError naming the first defect if it is
not a tessellation of the square) and solves the patch tests, whose exact solution is
linear (the all-traction one has no Dirichlet side and is refused as singular). The consistent
formulations reproduce it to round-off: CG, and DG with the consistency terms (augmented
Lagrangian, iterative Nitsche, SIPG, their iterations to 1e-10). The pure penalty is not
consistent: its error is of the penalty's size, 1e-4 to 1e-3 at k_p = 1000 (docs/dg.md).

    PYTHONPATH=build /usr/bin/python3 examples/voronoi_patch_test.py
"""
import numpy as np
from scipy.spatial import Voronoi

import vorodg


def voronoi_in_unit_square(n, seed):
    """(vertices, offsets, connectivity) of the Voronoi tessellation of n random seeds."""
    rng = np.random.default_rng(seed)
    points = rng.uniform(0.05, 0.95, size=(n, 2))
    x, y = points[:, 0], points[:, 1]
    mirrored = np.vstack([points, np.column_stack([-x, y]), np.column_stack([2 - x, y]),
                          np.column_stack([x, -y]), np.column_stack([x, 2 - y])])
    vor = Voronoi(mirrored)
    renumbered, cells = {}, []
    for i in range(n):
        region = vor.regions[vor.point_region[i]]
        assert -1 not in region, "a seed's region is unbounded"
        corners = vor.vertices[region]
        centre = corners.mean(axis=0)
        order = np.argsort(np.arctan2(corners[:, 1] - centre[1], corners[:, 0] - centre[0]))
        cells.append([renumbered.setdefault(region[k], len(renumbered)) for k in order])
    vertices = np.empty((len(renumbered), 2))
    for old, new in renumbered.items():
        vertices[new] = vor.vertices[old]
    vertices = np.clip(vertices, 0.0, 1.0)  # Qhull leaves the sides' vertices 1e-16 off them
    offsets = np.concatenate([[0], np.cumsum([len(c) for c in cells])])
    return vertices, offsets, np.concatenate(cells)


def main():
    mesh = vorodg.Mesh(*voronoi_in_unit_square(60, seed=11), domain=(0, 0, 1, 1))
    print(mesh)
    print("problem          formulation   L2 error   energy error")
    for problem in ("patch", "patch-mixed"):  # patch-traction is singular, and refused
        for formulation in ("cg", "dg-penalty", "dg-al", "dg-nitsche", "dg-sipg"):
            r = vorodg.solve(mesh, problem=problem, formulation=formulation)
            print(f"{problem:16s} {formulation:12s} {r['l2_error']:9.1e}  {r['energy_error']:9.1e}")
            if formulation != "dg-penalty":
                assert r["l2_error"] < 1e-10 and r["energy_error"] < 1e-10


if __name__ == "__main__":
    main()
