#!/usr/bin/python3
"""meshio round trips of .vtu files, run by ctest as meshio_roundtrip.

(a) Meshes written by meshio in each of its modes (default zlib binary, zlib with UInt64
    headers, uncompressed binary, ASCII) and by this script as appended raw and base64 data are
    read by `vorodg mesh --check` and solved with the patch test, whose errors must be at
    round-off; meshio's LZMA mode must be refused with a message naming the compressor.
(b) Files written by vorodg (a mesh, a CG and a DG result) are read by meshio and compared, array
    by array, with the same data written as exact ASCII text by vtu_reencode (vorodg's reader and
    its ASCII writer) and by `vorodg ... --ascii` (where the command has that flag).

Usage: meshio_roundtrip.py VORODG VTU_REENCODE. Prints one line per check and a closing
'N passed, M failed'; exits 1 if any check failed.
"""
import base64
import json
import subprocess
import sys
import tempfile
import zlib
from pathlib import Path

try:
    import meshio
    import numpy as np
except ImportError as e:
    print(f"meshio_roundtrip: {e}: install python3-meshio (scripts/bootstrap)")
    sys.exit(1)

DOMAIN = "0,0,2,1"
PATCH_TOL = 1e-9  # patch-test errors: round-off of a few hundred unknowns
results = []


def check(name, ok, detail=""):
    results.append(bool(ok))
    print(("ok   " if ok else "FAIL ") + name + ("" if ok or not detail else ": " + detail))
    return ok


def run(args):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=300)


def run_ok(name, args):
    p = run(args)
    check(name, p.returncode == 0, f"exit {p.returncode}: {p.stderr.strip()[:300]}")
    return p.returncode == 0


def cell_arrays(mesh):
    """Connectivity, per-cell vertex counts and types, over all cell blocks."""
    conn = np.concatenate([c.data.ravel() for c in mesh.cells])
    sizes = np.concatenate([np.full(len(c.data), c.data.shape[1]) for c in mesh.cells])
    types = [c.type for c in mesh.cells for _ in range(len(c.data))]
    return conn, sizes, types


def grid_mesh():
    """Quads and triangles on [0,2] x [0,1], counter-clockwise: meshio's quad and triangle types."""
    xs, ys = np.linspace(0, 2, 5), np.linspace(0, 1, 3)
    pts = np.array([[x, y, 0.0] for y in ys for x in xs])
    quads, tris = [], []
    for j in range(2):
        for i in range(4):
            a, b, c, d = j * 5 + i, j * 5 + i + 1, (j + 1) * 5 + i + 1, (j + 1) * 5 + i
            if (i + j) % 2:
                quads.append([a, b, c, d])
            else:
                tris += [[a, b, c], [a, c, d]]
    return meshio.Mesh(pts, [("quad", np.array(quads)), ("triangle", np.array(tris))])


def appended_vtu(path, mesh, encoding, compress):
    """The mesh as VTK writes appended data: raw bytes or base64, zlib blocks or not, UInt64."""
    conn, sizes, _ = cell_arrays(mesh)
    vtk_type = {"triangle": 5, "quad": 9, "polygon": 7}
    types = np.array([vtk_type[c.type] for c in mesh.cells for _ in range(len(c.data))], "<u1")
    arrays = [("Points", "Float64", 3, mesh.points.astype("<f8")),
              ("connectivity", "Int64", 0, conn.astype("<i8")),
              ("offsets", "Int64", 0, np.cumsum(sizes).astype("<i8")), ("types", "UInt8", 0, types)]
    blob, tags = b"", {}
    for name, typ, comps, values in arrays:
        raw = values.tobytes()
        if compress:
            blocks = [zlib.compress(raw[i:i + 32768]) for i in range(0, len(raw), 32768)]
            words = [len(blocks), 32768, len(raw) % 32768] + [len(b) for b in blocks]
            parts = (np.array(words, "<u8").tobytes(), b"".join(blocks))
        else:
            parts = (np.array([len(raw)], "<u8").tobytes(), raw)
        data = b"".join(parts) if encoding == "raw" else b"".join(base64.b64encode(p) for p in parts)
        nc = f' NumberOfComponents="{comps}"' if comps else ""
        tags[name] = (f'<DataArray type="{typ}" Name="{name}"{nc} format="appended" '
                      f'offset="{len(blob)}"/>')
        blob += data
    compressor = ' compressor="vtkZLibDataCompressor"' if compress else ""
    head = (f'<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
            f'byte_order="LittleEndian" header_type="UInt64"{compressor}>\n<UnstructuredGrid>\n'
            f'<Piece NumberOfPoints="{len(mesh.points)}" NumberOfCells="{len(types)}">\n'
            f'<Points>{tags["Points"]}</Points>\n<Cells>{tags["connectivity"]}{tags["offsets"]}'
            f'{tags["types"]}</Cells>\n</Piece>\n</UnstructuredGrid>\n'
            f'<AppendedData encoding="{encoding}">\n_')
    Path(path).write_bytes(head.encode() + blob + b"\n</AppendedData>\n</VTKFile>\n")


def files_written_by_meshio(tmp, vorodg):
    """(name, path) of every meshio mode and appended layout, for a polygon and a grid mesh."""
    if not run_ok("vorodg writes the source mesh", [vorodg, "mesh", "--family", "rcp", "--d", "0.12",
                                                    "--domain", DOMAIN, "--seed", "3", "-o", tmp / "src.vtu"]):
        return []
    out = []
    for mesh_name, mesh in (("rcp", meshio.read(tmp / "src.vtu")), ("grid", grid_mesh())):
        modes = {"default": {}, "zlib-uint64": {"header_type": "UInt64"},
                 "uncompressed": {"compression": None}, "ascii": {"binary": False}}
        for mode, kwargs in modes.items():
            path = tmp / f"meshio_{mesh_name}_{mode}.vtu"
            meshio.write(path, mesh, file_format="vtu", **kwargs)
            out.append((f"{mesh_name} meshio {mode}", path))
        for encoding, compress in (("raw", True), ("raw", False), ("base64", True), ("base64", False)):
            path = tmp / f"appended_{mesh_name}_{encoding}_{'zlib' if compress else 'plain'}.vtu"
            appended_vtu(path, mesh, encoding, compress)
            back = meshio.read(path)  # the layout is VTK's: meshio reads it too
            check(f"meshio reads {path.name}", np.array_equal(back.points, mesh.points))
            out.append((f"{mesh_name} appended {encoding} {'zlib' if compress else 'plain'}", path))
    return out


def part_a(tmp, vorodg):
    for name, path in files_written_by_meshio(tmp, vorodg):
        run_ok(f"mesh --check, {name}", [vorodg, "mesh", "--check", path, "--domain", DOMAIN])
        metrics = tmp / "metrics.json"
        if run_ok(f"solve patch, {name}", [vorodg, "solve", "--mesh", path, "--problem", "patch",
                                           "--domain", DOMAIN, "-o", tmp / "patch.vtu", "--metrics", metrics]):
            m = json.loads(metrics.read_text())
            err = max(m["l2_error"], m["energy_error"])
            check(f"patch test at round-off, {name}", err < PATCH_TOL, f"error {err:.3g}")
    lzma_file = tmp / "meshio_lzma.vtu"
    meshio.write(lzma_file, grid_mesh(), file_format="vtu", compression="lzma")
    p = run([vorodg, "mesh", "--check", lzma_file])
    check("meshio lzma file refused naming the compressor",
          p.returncode == 2 and 'compressor="vtkLZMADataCompressor" is not supported' in p.stderr,
          f"exit {p.returncode}: {p.stderr.strip()}")


def same_arrays(name, a, b):
    """meshio's reading of the binary file `a` against its reading of the ASCII file `b`."""
    ok = check(f"{name}: points", np.array_equal(a.points, b.points))
    ca, cb = cell_arrays(a), cell_arrays(b)
    ok &= check(f"{name}: cells", np.array_equal(ca[0], cb[0]) and np.array_equal(ca[1], cb[1])
                and ca[2] == cb[2])
    ok &= check(f"{name}: array names", sorted(a.point_data) == sorted(b.point_data)
                and sorted(a.cell_data) == sorted(b.cell_data), f"{list(a.point_data)} {list(a.cell_data)}")
    for key in sorted(set(a.point_data) & set(b.point_data)):
        ok &= check(f"{name}: point data '{key}'", np.array_equal(a.point_data[key], b.point_data[key]))
    for key in sorted(set(a.cell_data) & set(b.cell_data)):
        x, y = np.concatenate(a.cell_data[key]), np.concatenate(b.cell_data[key])
        ok &= check(f"{name}: cell data '{key}'", np.array_equal(x, y))
    check(f"{name}: field data 'domain'", np.array_equal(a.field_data.get("domain"), [0, 0, 2, 1]))
    return ok


def part_b(tmp, vorodg, reencode):
    runs = {
        "mesh": ["mesh", "--family", "rcp", "--d", "0.1", "--domain", DOMAIN, "--seed", "7"],
        "cg": ["solve", "--family", "rcp", "--d", "0.15", "--domain", DOMAIN, "--problem", "patch"],
        "dg": ["solve", "--family", "rcp", "--d", "0.15", "--domain", DOMAIN, "--problem", "patch",
               "--formulation", "dg-nitsche"],
    }
    for name, args in runs.items():
        binary, ascii_ref, metrics = tmp / f"{name}.vtu", tmp / f"{name}_ascii.vtu", tmp / f"{name}.json"
        extra = ["--metrics", metrics] if args[0] == "solve" else []
        if not run_ok(f"vorodg {name} writes {binary.name}", [vorodg, *args, "-o", binary, *extra]):
            continue
        text = binary.read_bytes()
        xml = text.split(b"<AppendedData")[0]
        check(f"{name}: written as zlib appended raw data", b'compressor="vtkZLibDataCompressor"' in xml
              and b'<AppendedData encoding="raw">' in text
              and b'format="ascii"' not in xml.split(b"</FieldData>")[1])
        a = meshio.read(binary)
        reencoded = tmp / f"{name}_reencoded.vtu"
        if run_ok(f"vtu_reencode {name} to ASCII", [reencode, binary, reencoded, "ascii"]):
            same_arrays(f"{name} vs vtu_reencode ASCII", a, meshio.read(reencoded))
        if "--ascii" in run([vorodg, args[0], "--help"]).stdout:
            if run_ok(f"vorodg {name} --ascii", [vorodg, *args, "--ascii", "-o", ascii_ref, *extra]):
                same_arrays(f"{name} vs --ascii", a, meshio.read(ascii_ref))
        n_cells = sum(len(c.data) for c in a.cells)
        if name == "mesh":
            ids = np.concatenate(a.cell_data["cell_id"]).ravel()  # (n, 1): one component
            check("mesh: cell_id is 0..n-1", np.array_equal(ids, np.arange(n_cells)))
            continue
        m = json.loads(metrics.read_text())
        check(f"{name}: cell count as reported", m["cells"] == n_cells, f"{m['cells']} vs {n_cells}")
        gap = np.abs(a.point_data["displacement"] - a.point_data["exact_displacement"]).max()
        check(f"{name}: displacement is the exact patch field", gap < PATCH_TOL, f"gap {gap:.3g}")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    vorodg, reencode = Path(sys.argv[1]), Path(sys.argv[2])
    with tempfile.TemporaryDirectory(prefix="vorodg_meshio_") as tmp:
        part_a(Path(tmp), vorodg)
        part_b(Path(tmp), vorodg, reencode)
    failed = results.count(False)
    print(f"{len(results) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
