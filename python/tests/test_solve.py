"""vorodg.solve: the program's solve to the bit (displacements, errors, record), its settings
with the schema's names, defaults and ranges, its messages for bad input, and its own exception
type for a breakdown."""
import json

import meshio
import numpy as np
import pytest

from conftest import program_error, vorodg

def untimed(record):
    """A record without its wall times and the process's peak memory: nothing else may differ."""
    return {k: v for k, v in record.items() if "seconds" not in k and "memory" not in k}


@pytest.mark.parametrize("formulation, extra", [("cg", []), ("dg-nitsche", ["--kp", "100"])])
def test_beam_solve_is_the_programs_to_the_bit(tmp_path, program, formulation, extra):
    args = ["--family", "rcp", "--d", "0.2", "--seed", "5", "--formulation", formulation,
            "--threads", "2", *extra]
    program("solve", *args, "--metrics", tmp_path / "m.json", "-o", tmp_path / "r.vtu")
    cli = json.loads((tmp_path / "m.json").read_text())

    mesh = vorodg.generate_mesh(family="rcp", domain=(0, -0.5, 4, 0.5), d=0.2, seed=5)
    kwargs = {"kp": 100.0} if extra else {}
    r = vorodg.solve(mesh, formulation=formulation, threads=2, **kwargs)

    assert untimed(r["record"]) == untimed(cli)
    assert r["l2_error"] == cli["l2_error"] and r["energy_error"] == cli["energy_error"]
    result = meshio.read(tmp_path / "r.vtu")
    u = result.point_data["displacement"][:, :2]
    if formulation == "cg":
        assert np.array_equal(r["displacement"], u)
    else:  # one point per (cell, vertex): every cell's own copy, cell by cell
        assert np.array_equal(r["cell_displacements"].reshape(-1, 2), u)
    # meshio splits the polygons into blocks by their number of sides: put them back in order.
    ids = np.concatenate(result.cell_data["cell_id"]).ravel().astype(int)
    stress = np.empty_like(r["cell_stress"])
    stress[ids] = np.concatenate(result.cell_data["mean_stress"])[:, :3]
    assert np.array_equal(r["cell_stress"], stress)
    assert set(r["seconds"]) >= {"element", "factorization", "solve"}


def test_settings_are_the_schemas():
    names = {s["name"]: s for s in vorodg.settings()}
    assert {"problem", "formulation", "E", "nu", "kp", "penalty", "max_iter", "no_errors",
            "threads"} <= set(names)
    assert names["max_iter"]["option"] == "--max-iter"
    assert names["nu"]["default"] == "0.3" and names["nu"]["range"] == "-1 < nu < 0.5"
    assert names["formulation"]["kind"] == "choice"


def test_no_errors_skips_them():
    mesh = vorodg.generate_mesh(family="quad", domain=(0, -0.5, 4, 0.5), h=0.25)
    r = vorodg.solve(mesh, no_errors=True)
    assert r["l2_error"] is None and r["energy_error"] is None
    assert "l2_error" not in r["record"]


def test_bad_settings_give_the_programs_message():
    mesh = vorodg.generate_mesh(family="quad", domain=(0, -0.5, 4, 0.5), h=0.5)
    for option, value, kwargs in [("--nu", "0.7", dict(nu=0.7)), ("--kp", "0", dict(kp=0.0)),
                                  ("--rule", "2", dict(rule=2)),
                                  ("--formulation", "dg", dict(formulation="dg")),
                                  ("--max-iter", "0", dict(max_iter=0))]:
        expected = program_error("solve", "--family", "quad", "--h", "0.5", option, value)
        with pytest.raises(ValueError) as e:
            vorodg.solve(mesh, **kwargs)
        assert str(e.value) == expected


def test_a_misspelt_or_mistyped_setting_is_named():
    mesh = vorodg.generate_mesh(family="quad", domain=(0, -0.5, 4, 0.5), h=0.5)
    with pytest.raises(ValueError, match=r"^setting 'kpp': unknown; expected one of .*\bkp\b"):
        vorodg.solve(mesh, kpp=10)
    with pytest.raises(ValueError, match=r"^--kp 'big': expected a finite number"):
        vorodg.solve(mesh, kp="big")
    with pytest.raises(ValueError, match=r"^--E nan: expected a finite number"):
        vorodg.solve(mesh, E=float("nan"))
    with pytest.raises(ValueError, match=r"^--rule 3.0: expected an integer"):
        vorodg.solve(mesh, rule=3.0)
    with pytest.raises(ValueError, match=r"^--no-errors 1: expected True or False"):
        vorodg.solve(mesh, no_errors=1)


def test_a_breakdown_is_a_numerical_error():
    mesh = vorodg.generate_mesh(family="quad", domain=(0, -0.5, 4, 0.5), h=0.25)
    with pytest.raises(vorodg.NumericalError, match="did not converge"):
        vorodg.solve(mesh, formulation="dg-al", max_iter=2)
    assert issubclass(vorodg.NumericalError, ArithmeticError)
