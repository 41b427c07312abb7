#!/usr/bin/python3
"""A bounded Voronoi mesh made "elsewhere", the way a new user would with Qhull.

Seeds: dart throwing with minimum distance d in the rectangle (fixed seed), then N Lloyd steps.
Cells: scipy.spatial.Voronoi (Qhull) of the seeds and their mirror images about the four sides,
so that each seed's cell is bounded and clipped exactly by the sides. Vertices within 1e-12 x
domain size are merged (neighbours share indices), side vertices are snapped onto the sides,
cells are counter-clockwise. Short edges are kept on purpose: Qhull meshes have them.
Written with meshio as a .vtu of "polygon" blocks (meshio >= 4.4 groups polygons by vertex
count under the one type name; older meshio called them "polygon5", "polygon6", ...).

Usage: qhull_voronoi_mesh.py -o FILE [--domain x0,y0,x1,y1] [--d D] [--seed S] [--lloyd N]
"""
import argparse

import meshio
import numpy as np
from scipy.spatial import Voronoi, cKDTree


def dart_throwing(box, d, rng, misses=5000):
    """Random points at least d apart; stops after `misses` rejected darts in a row."""
    x0, y0, x1, y1 = box
    pts, fails = [], 0
    grid = {}  # background grid of cell size d/sqrt(2): at most one point per grid cell
    s = d / np.sqrt(2)
    while fails < misses:
        p = rng.uniform((x0, y0), (x1, y1))
        i, j = int((p[0] - x0) / s), int((p[1] - y0) / s)
        near = (grid.get((a, b)) for a in range(i - 2, i + 3) for b in range(j - 2, j + 3))
        if any(q is not None and np.hypot(*(p - q)) < d for q in near):
            fails += 1
            continue
        grid[(i, j)], fails = p, 0
        pts.append(p)
    return np.array(pts)


def clipped_cells(seeds, box):
    """Bounded Voronoi cells of the seeds: (vertices, list of counter-clockwise index lists)."""
    x0, y0, x1, y1 = box
    n = len(seeds)
    mirrors = [seeds.copy() for _ in range(4)]
    mirrors[0][:, 0] = 2 * x0 - seeds[:, 0]
    mirrors[1][:, 0] = 2 * x1 - seeds[:, 0]
    mirrors[2][:, 1] = 2 * y0 - seeds[:, 1]
    mirrors[3][:, 1] = 2 * y1 - seeds[:, 1]
    vor = Voronoi(np.vstack([seeds, *mirrors]))
    v = vor.vertices.copy()
    tol = 1e-12 * max(x1 - x0, y1 - y0)
    for k, side in ((0, x0), (0, x1), (1, y0), (1, y1)):  # exactly on the sides
        v[np.abs(v[:, k] - side) <= tol, k] = side
    # Merge vertices closer than tol (union-find over close pairs): one index per location.
    parent = np.arange(len(v))
    def root(a):
        while parent[a] != a:
            a = parent[a]
        return a
    for a, b in cKDTree(v).query_pairs(tol):
        ra, rb = root(a), root(b)
        parent[max(ra, rb)] = min(ra, rb)
    rep = np.array([root(a) for a in range(len(v))])
    cells, used = [], set()
    for i in range(n):
        region = vor.regions[vor.point_region[i]]
        assert region and -1 not in region, "unbounded cell of an original seed"
        idx = np.unique(rep[region])
        ang = np.arctan2(v[idx, 1] - seeds[i, 1], v[idx, 0] - seeds[i, 0])
        cells.append(list(idx[np.argsort(ang)]))  # convex cell around its seed: CCW by angle
        used.update(cells[-1])
    # Keep only the vertices the cells use, renumbered 0..m-1.
    used = np.array(sorted(used))
    new = {old: k for k, old in enumerate(used)}
    return v[used], [[new[a] for a in c] for c in cells]


def polygon_area_centroid(p):
    x, y = p[:, 0], p[:, 1]
    xn, yn = np.roll(x, -1), np.roll(y, -1)
    cross = x * yn - xn * y
    a = cross.sum() / 2
    return a, np.array([((x + xn) * cross).sum(), ((y + yn) * cross).sum()]) / (6 * a)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-o", required=True, help="output .vtu")
    ap.add_argument("--domain", default="0,-0.5,4,0.5", help="rectangle x0,y0,x1,y1")
    ap.add_argument("--d", type=float, default=0.1, help="minimum distance between seeds")
    ap.add_argument("--seed", type=int, default=1, help="random seed")
    ap.add_argument("--lloyd", type=int, default=1, help="Lloyd steps")
    args = ap.parse_args()
    box = [float(s) for s in args.domain.split(",")]
    seeds = dart_throwing(box, args.d, np.random.default_rng(args.seed))
    for _ in range(args.lloyd):  # move each seed to the centroid of its clipped cell
        v, cells = clipped_cells(seeds, box)
        seeds = np.array([polygon_area_centroid(v[c])[1] for c in cells])
    v, cells = clipped_cells(seeds, box)

    areas = [polygon_area_centroid(v[c])[0] for c in cells]
    assert min(areas) > 0, "a cell is not counter-clockwise"
    edges = {tuple(sorted((c[k], c[(k + 1) % len(c)]))) for c in cells for k in range(len(c))}
    shortest = min(np.hypot(*(v[a] - v[b])) for a, b in edges)
    sizes = sorted({len(c) for c in cells})
    blocks = [("polygon", np.array([c for c in cells if len(c) == k])) for k in sizes]
    points = np.column_stack([v, np.zeros(len(v))])
    meshio.write(args.o, meshio.Mesh(points, blocks), file_format="vtu")

    back = meshio.read(args.o)  # read back: same points and cell count
    assert np.array_equal(back.points, points)
    assert sum(len(b.data) for b in back.cells) == len(cells)
    print(f"{args.o}: {len(cells)} cells, {len(v)} vertices, {len(edges)} edges, "
          f"shortest edge / d {shortest / args.d:.6g}, "
          f"h_avg {np.sqrt(sum(areas) / len(cells)):.6g}, area {sum(areas):.15g}")


if __name__ == "__main__":
    main()
