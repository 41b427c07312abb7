"""vorodg.run: a scene run from Python writes what `vorodg run` writes (the same summary.json),
takes a dict as well as a file, and refuses bad scenes with the program's message."""
import json

import pytest

from conftest import ROOT, program_error, vorodg

SCENE = {
    "name": "py-convergence",
    "description": "beam convergence, two levels, CG and DG",
    "study": "convergence",
    "problems": ["beam"],
    "domain": [0, -0.5, 4, 0.5],
    "material": {"E": 1.0, "nu": 0.3, "plane": "stress"},
    "meshes": [{"family": "rcp", "sizes": [0.4, 0.2], "realizations": 2, "seed": 2008}],
    "formulations": [{"name": "cg"}, {"name": "dg-sipg"}],
}


def without_times(value):
    """The JSON with every wall time and memory figure taken out (they differ run to run)."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items()
                if "seconds" not in k and "rss" not in k and k != "time"}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def test_a_scene_file_gives_the_programs_summary(tmp_path, program):
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps(SCENE))
    program("run", scene, "-o", tmp_path / "cli", "--quiet", "--no-plots")
    r = vorodg.run(str(scene), str(tmp_path / "py"), progress=False, plots=False)
    cli = json.loads((tmp_path / "cli" / "summary.json").read_text())
    py = json.loads((tmp_path / "py" / "summary.json").read_text())
    assert without_times(py) == without_times(cli)
    assert r["summary"] == py and r["exit_code"] == 0
    assert len(r["records"]) == 2 * 2 * 2  # levels x realizations x formulations
    assert {rec["formulation"] for rec in r["records"]} == {"cg", "dg-sipg"}


def test_a_dict_scene_runs_and_resumes(tmp_path, capsys):
    out = tmp_path / "out"
    first = vorodg.run(SCENE, str(out), progress=True, plots=False)
    assert (out / "scene.json").exists() and first["exit_code"] == 0
    second = vorodg.run(SCENE, str(out), progress=False, plots=False)  # nothing left to run
    assert second["records"] == first["records"]
    assert "py-convergence" in capsys.readouterr().out  # the echo and progress reach Python


def test_variants_come_back_by_label(tmp_path):
    scene = json.loads((ROOT / "data" / "scenes" / "tpb-dynamic-static.json").read_text())
    scene["meshes"][0].update(sizes=[0.04], realizations=1)
    scene["loading"] = {"control": "cmod", "max_cmod": 2e-4, "steps": 10}
    r = vorodg.run(scene, str(tmp_path), progress=False, plots=False)
    assert set(r["variants"]) == {"case1", "case2"} and r["exit_code"] == 0
    modes = {label: part["summary"]["mode"] for label, part in r["variants"].items()}
    assert modes == {"case1": "pre-inserted", "case2": "restricted"}
    assert all(len(part["records"]) == 1 for part in r["variants"].values())


def test_bad_scenes_are_refused_with_the_programs_message(tmp_path):
    bad = dict(SCENE, meshes=[dict(SCENE["meshes"][0], sizes=[0.2, 0.4])])  # coarse to fine
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(bad))
    expected = program_error("run", path, "-o", tmp_path / "cli", "--quiet")
    with pytest.raises(ValueError) as e:
        vorodg.run(str(path), str(tmp_path / "py"), progress=False)
    assert str(e.value) == expected
    with pytest.raises(ValueError, match="no such file, and no shipped scene"):
        vorodg.run("no-such-scene", str(tmp_path / "x"))
    with pytest.raises(ValueError, match="expected a file, a shipped scene's name or a dict"):
        vorodg.run(42, str(tmp_path / "y"))
