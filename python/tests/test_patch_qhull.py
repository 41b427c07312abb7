"""A mesh a user made: scipy's Qhull Voronoi diagram of random seeds, clipped to the unit
square by mirroring the seeds across its sides (examples/voronoi_patch_test.py), solves the
patch tests to round-off."""
import sys

import pytest

from conftest import ROOT, vorodg

sys.path.insert(0, str(ROOT / "examples"))
from voronoi_patch_test import voronoi_in_unit_square  # noqa: E402


@pytest.fixture(scope="module")
def mesh():
    return vorodg.Mesh(*voronoi_in_unit_square(60, seed=11), domain=(0, 0, 1, 1))


def test_the_mesh_is_a_voronoi_tessellation(mesh):
    assert mesh.num_cells == 60
    assert mesh.cell_areas().sum() == pytest.approx(1.0, rel=1e-12)
    assert mesh.statistics()["min_interior_angle_deg"] > 0


@pytest.mark.parametrize("problem", ["patch", "patch-mixed"])
@pytest.mark.parametrize("formulation", ["cg", "dg-sipg"])
def test_patch_tests_pass_to_round_off(mesh, problem, formulation):
    r = vorodg.solve(mesh, problem=problem, formulation=formulation)
    assert r["l2_error"] < 1e-10, r["l2_error"]
    assert r["energy_error"] < 1e-10, r["energy_error"]
