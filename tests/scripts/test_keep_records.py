"""scripts/keep_records: what a campaign keeps of its output folder (results lines, run.json,
fragments, cracks, in the folder's layout) and what it leaves (histories, checkpoints,
pictures); a second copy over the first takes the newer lines; bad arguments exit non-zero."""
import subprocess
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "keep_records"


def make_output(root):
    files = {
        "run.json": "{}",
        "exact/dt-1/results.shard-0-of-2.jsonl": '{"id": "rcp-L0-R0"}\n',
        "exact/dt-1/fragments/rcp-L0-R0.csv": "fragment,mass\n0,1.0\n",
        "exact/dt-1/cracks/rcp-L0-R0.csv": "edge,time\n",
        "exact/dt-1/history/rcp-L0-R0.csv": "step,time\n",
        "exact/dt-1/checkpoints/rcp-L0-R1.ckpt": "binary",
        "exact/dt-1/plots/time.png": "png",
    }
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def kept(root):
    return sorted(str(p.relative_to(root)) for p in root.rglob("*") if p.is_file())


def test_keeps_the_records_and_leaves_the_rest(tmp_path):
    out, dest = tmp_path / "out", tmp_path / "kept"
    make_output(out)
    subprocess.run([str(SCRIPT), str(out), str(dest)], check=True)
    assert kept(dest) == ["exact/dt-1/cracks/rcp-L0-R0.csv",
                          "exact/dt-1/fragments/rcp-L0-R0.csv",
                          "exact/dt-1/results.shard-0-of-2.jsonl", "run.json"]
    # The shard goes on: the next copy takes its new line.
    results = out / "exact/dt-1/results.shard-0-of-2.jsonl"
    results.write_text(results.read_text() + '{"id": "rcp-L0-R1"}\n')
    subprocess.run([str(SCRIPT), str(out), str(dest)], check=True)
    assert (dest / "exact/dt-1/results.shard-0-of-2.jsonl").read_text().count("\n") == 2


def test_bad_arguments_exit_non_zero(tmp_path):
    for args in ([], [str(tmp_path / "missing"), str(tmp_path / "dest")]):
        r = subprocess.run([str(SCRIPT), *args], capture_output=True, text=True)
        assert r.returncode != 0 and "keep_records" in r.stderr
