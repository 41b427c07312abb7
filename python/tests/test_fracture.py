"""Fracture and fragmentation from Python: the quasi-static path's curve and interface states
(the run's own record and files), a fragmentation run's fragments (momentum and mass add up),
and the crack-state measures on a cut mesh."""
import csv
import json

import numpy as np
import pytest

from conftest import ROOT, vorodg

SCENES = ROOT / "data" / "scenes"


def shipped(name):
    return json.loads((SCENES / f"{name}.json").read_text())


@pytest.fixture(scope="module")
def path_run(tmp_path_factory):
    scene = shipped("tpb-dynamic-static")
    scene["meshes"][0].update(sizes=[0.04], realizations=1)
    scene["loading"] = {"control": "cmod", "max_cmod": 3e-4, "steps": 30}
    out = tmp_path_factory.mktemp("tpb")
    return vorodg.fracture_path(scene, str(out), variant="case1"), out


def test_the_curve_is_the_runs(path_run):
    r, out = path_run
    curve, record = r["curve"], r["record"]
    assert record["complete"] and record["id"] == "rcp-L0-R0"
    assert len(curve["load"]) == record["points"] and curve["step"][0] == 0  # from rest
    assert curve["load"].max() == record["peak_load"]
    with open(out / "curves" / "rcp-L0-R0.csv") as f:
        rows = list(csv.DictReader(f))
    assert np.allclose([float(x["load"]) for x in rows], curve["load"], rtol=1e-11, atol=0)


def test_the_interfaces_say_where_it_cracked(path_run):
    r, _ = path_run
    faces, mesh = r["interfaces"], r["mesh"]
    assert faces["state"].shape == faces["max_opening"].shape == (len(faces["edge"]), 2)
    assert set(np.unique(faces["state"])) <= {0, 1, 2}
    # Case 1: the line is cohesive from the start; what opened is on the line x = 1.
    opened = faces["edge"][(faces["max_opening"] > 0).any(axis=1)]
    assert len(opened) > 0
    ends = mesh.vertices[mesh.edges[opened]]
    assert np.allclose(ends[:, :, 0], 1.0, atol=1e-12)


def test_fragments_and_hamming_of_a_cut_mesh():
    mesh = vorodg.generate_mesh(family="quad", domain=(0, 0, 2, 1), h=0.25)
    mid = mesh.vertices[mesh.edges]  # (edges, 2 ends, xy)
    cut = np.all(np.isclose(mid[:, :, 0], 1.0), axis=1) & (mesh.edge_cells[:, 1] >= 0)
    f = vorodg.fragments(mesh, cut, density=2.0)
    assert len(f["mass"]) == 2 and np.allclose(f["mass"], 2.0)  # density x area 1
    assert np.allclose(sorted(f["centre"][:, 0]), [0.5, 1.5])
    assert f["cells"].sum() == mesh.num_cells
    assert vorodg.hamming(mesh, cut, np.zeros_like(cut)) == np.count_nonzero(cut)
    assert vorodg.hamming(mesh, cut, cut) == 0
    with pytest.raises(ValueError, match="expected one per mesh edge"):
        vorodg.fragments(mesh, cut[:-1])


def test_a_fragmentation_run_gives_its_fragments(tmp_path):
    scene = shipped("strip-fragmentation-quick")
    r = vorodg.fragmentation_run(scene, str(tmp_path), variant=None if "variants" not in scene
                                 else scene["variants"][0]["label"])
    f, record = r["fragments"], r["record"]
    assert record["complete"]
    k = len(f["mass"])
    assert k == record["fragments"] and f["centre"].shape == f["velocity"].shape == (k, 2)
    assert f["cells"].sum() == r["mesh"].num_cells
    assert len(r["broken"]) == r["mesh"].num_edges
    assert np.count_nonzero(r["broken"]) == record["broken_edges"]


def test_bad_choices_are_named(tmp_path):
    scene = shipped("tpb-dynamic-static")
    with pytest.raises(ValueError, match="the scene has variants: give variant= one of case1, case2"):
        vorodg.fracture_path(scene, str(tmp_path))
    with pytest.raises(ValueError, match=r"run 7: expected 0 <= run < 3"):
        vorodg.fracture_path(scene, str(tmp_path), variant="case1", run=7)
    with pytest.raises(ValueError, match=r"run 'rcp-L0-R9': no such run \(rcp-L0-R0, rcp-L0-R1, rcp-L0-R2\)"):
        vorodg.fracture_path(scene, str(tmp_path), variant="case1", run="rcp-L0-R9")


def test_the_load_at_twice_the_peak_displacement_is_the_curves(tmp_path):
    """load_at_twice_peak, kept point by point as the path runs, against the finished curve read
    independently: the first crossing of twice the peak's displacement after the peak,
    interpolated linearly between the two points around it."""
    vorodg.run("demo-fracture", str(tmp_path), threads=2, progress=False, plots=False)
    with open(tmp_path / "results.csv") as f:
        runs = list(csv.DictReader(f))
    assert runs
    for run in runs:
        with open(tmp_path / "curves" / f"{run['id']}.csv") as f:
            curve = list(csv.DictReader(f))
        stroke = np.array([float(p["displacement"]) for p in curve])
        load = np.array([float(p["load"]) for p in curve])
        peak = int(np.argmax(load))
        target = 2.0 * stroke[peak]
        assert stroke[-1] >= target, "the demo's paths run past twice the peak"
        after = peak + int(np.argmax(stroke[peak:] >= target))
        t = (target - stroke[after - 1]) / (stroke[after] - stroke[after - 1])
        expected = load[after - 1] + t * (load[after] - load[after - 1])
        assert float(run["load_at_twice_peak"]) == pytest.approx(expected, rel=1e-9)


def test_the_crack_tortuosity_is_the_crack_files(tmp_path):
    """crack_tortuosity against cracks/<run>.csv: the faces' total length over their extent along
    y (on demo-fracture's mirrored meshes the crack is the straight mid-line: 1)."""
    vorodg.run("demo-fracture", str(tmp_path), threads=2, progress=False, plots=False)
    with open(tmp_path / "results.csv") as f:
        runs = list(csv.DictReader(f))
    for run in runs:
        with open(tmp_path / "cracks" / f"{run['id']}.csv") as f:
            faces = list(csv.DictReader(f))
        assert faces
        length = sum(np.hypot(float(p["x1"]) - float(p["x0"]), float(p["y1"]) - float(p["y0"]))
                     for p in faces)
        ys = [float(p[k]) for p in faces for k in ("y0", "y1")]
        assert float(run["crack_tortuosity"]) == pytest.approx(length / (max(ys) - min(ys)),
                                                               rel=1e-9)
