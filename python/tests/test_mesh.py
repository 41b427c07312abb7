"""vorodg.Mesh: generated with `vorodg mesh`'s parameters (the same mesh as the program's, to the
bit), written and read as .vtu, built from arrays, and refused with the program's messages."""
import numpy as np
import pytest

from conftest import program_error, vorodg


def unit_square_quads(n):
    """An n x n grid of unit-square quads on [0, 1]^2 as arrays (counter-clockwise cells)."""
    x = np.linspace(0.0, 1.0, n + 1)
    vertices = np.array([(xi, yj) for yj in x for xi in x])
    cells = []
    for j in range(n):
        for i in range(n):
            v = j * (n + 1) + i
            cells.append([v, v + 1, v + n + 2, v + n + 1])
    offsets = np.arange(0, 4 * len(cells) + 1, 4)
    return vertices, offsets, np.concatenate(cells)


def test_generated_mesh_is_the_programs(tmp_path, program):
    mesh = vorodg.generate_mesh(family="rcp", domain=(0, 0, 2, 1), d=0.1, seed=7)
    program("mesh", "--family", "rcp", "--domain", "0,0,2,1", "--d", 0.1, "--seed", 7,
            "-o", tmp_path / "m.vtu")
    read = vorodg.read_mesh(str(tmp_path / "m.vtu"))
    assert mesh.family == "rcp" and read.family == "file"
    assert np.array_equal(mesh.vertices, read.vertices)  # binary .vtu: exact doubles
    assert np.array_equal(mesh.offsets, read.offsets)
    assert np.array_equal(mesh.connectivity, read.connectivity)
    assert mesh.domain == (0.0, 0.0, 2.0, 1.0)


def test_arrays_describe_the_mesh():
    mesh = vorodg.generate_mesh(family="hex", domain=(0, 0, 1, 1), h=0.2)
    v, off, conn = mesh.vertices, mesh.offsets, mesh.connectivity
    assert v.shape == (mesh.num_vertices, 2) and v.dtype == np.float64
    assert off.shape == (mesh.num_cells + 1,) and off[0] == 0 and off[-1] == len(conn)
    assert mesh.edges.shape == mesh.edge_cells.shape == (mesh.num_edges, 2)
    # Every interior edge has two cells, every boundary edge one, and each cell lists its edges'
    # vertices: the sum of the cells' sides counts interior edges twice.
    interior = np.count_nonzero(mesh.edge_cells[:, 1] >= 0)
    assert 2 * interior + (mesh.num_edges - interior) == len(conn)
    assert mesh.cell_areas().sum() == pytest.approx(1.0, rel=1e-12)
    stats = mesh.statistics()
    assert stats["cells"] == mesh.num_cells and stats["h_avg"] == mesh.h_avg
    assert mesh.cell_centroids().shape == (mesh.num_cells, 2)


def test_write_and_read_back(tmp_path):
    mesh = vorodg.generate_mesh(family="perturbed-hex", domain=(0, 0, 1, 1), h=0.1, seed=3)
    for ascii_ in (False, True):
        path = tmp_path / f"m{int(ascii_)}.vtu"
        mesh.write(str(path), ascii=ascii_)
        back = vorodg.read_mesh(str(path))
        assert np.array_equal(back.connectivity, mesh.connectivity)
        assert np.allclose(back.vertices, mesh.vertices, rtol=0, atol=1e-15)


def test_mesh_from_arrays():
    mesh = vorodg.Mesh(*unit_square_quads(3))
    assert mesh.num_cells == 9 and mesh.num_vertices == 16 and mesh.family == "file"
    assert mesh.domain == (0.0, 0.0, 1.0, 1.0)  # the bounding box
    assert mesh.h_avg == pytest.approx(1.0 / 3.0)


def test_a_cell_that_does_not_close_is_refused():
    vertices, offsets, conn = unit_square_quads(2)
    # The last cell loses a vertex: a triangle that leaves a hole and overlaps nothing.
    offsets = offsets.copy()
    conn = conn[:-1]
    offsets[-1] -= 1
    with pytest.raises(ValueError, match=r"^mesh from arrays is invalid: .*defects; see vorodg mesh --check"):
        vorodg.Mesh(vertices, offsets, conn)
    # A cell of two vertices.
    with pytest.raises(ValueError, match=r"^mesh: cell 1 has 2 vertices, expected at least 3$"):
        vorodg.Mesh(vertices, np.array([0, 4, 6]), np.array([0, 1, 4, 3, 1, 2]))


def test_bad_arrays_are_refused_not_crashed():
    vertices, offsets, conn = unit_square_quads(2)
    bad = conn.copy()
    bad[0] = 99
    with pytest.raises(ValueError, match="99"):
        vorodg.Mesh(vertices, offsets, bad)
    with pytest.raises(ValueError, match=r"expected shape \(n, 2\)"):
        vorodg.Mesh(vertices.ravel(), offsets, conn)
    with pytest.raises(ValueError):
        vorodg.Mesh(vertices, offsets[::-1].copy(), conn)


def test_bad_parameters_give_the_programs_message():
    for args, kwargs in [(("--d", 0), dict(d=0.0)),
                         (("--family", "hexx", "--d", 0.2), dict(family="hexx", d=0.2)),
                         (("--family", "quad", "--d", 0.2), dict(family="quad", d=0.2))]:
        expected = program_error("mesh", *args)
        with pytest.raises(ValueError) as e:
            vorodg.generate_mesh(**kwargs)
        assert str(e.value) == expected
