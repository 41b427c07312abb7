"""The time-to-accuracy interpolation of scripts/time_to_accuracy_plot.py (the deal.II
comparison) on closed forms, and the scripts' atomic text writer."""
import math
import os
import stat
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

import time_to_accuracy_plot as tta  # noqa: E402
from plotting_common import write_text_atomically  # noqa: E402


def power_law(labels, c=2.0, p=1.5):
    """Points on time = c * L2^(-p): a straight line in log-log, which the interpolation must
    reproduce exactly inside the range and beyond it."""
    return [{"l2_error": 10.0 ** -k, "time": c * (10.0 ** -k) ** -p, "n": n}
            for k, n in zip((3, 4, 5), labels)]


def test_a_power_law_is_interpolated_exactly():
    r = tta.interpolate(power_law((32, 64, 128)), 3e-5)
    assert not r["extrapolated"]
    assert r["between"] == [128, 64]
    assert math.isclose(r["time"], 2.0 * 3e-5 ** -1.5, rel_tol=1e-12)


def test_outside_the_range_it_extrapolates_and_says_so():
    finer = tta.interpolate(power_law((32, 64, 128)), 1e-6)
    coarser = tta.interpolate(power_law((32, 64, 128)), 1e-2)
    assert finer["extrapolated"] and coarser["extrapolated"]
    assert finer["between"] == [128, 64] and coarser["between"] == [64, 32]
    assert math.isclose(finer["time"], 2.0 * 1e-6 ** -1.5, rel_tol=1e-12)
    assert math.isclose(coarser["time"], 2.0 * 1e-2 ** -1.5, rel_tol=1e-12)


def test_too_few_points_give_no_time_and_equal_errors_their_mean():
    assert tta.interpolate(power_law((32,))[:1], 1e-3)["time"] is None
    flat = [{"l2_error": 1e-4, "time": 1.0, "n": 1}, {"l2_error": 1e-4, "time": 4.0, "n": 2}]
    assert math.isclose(tta.interpolate(flat, 1e-4)["time"], 2.0, rel_tol=1e-12)


def test_the_writer_leaves_a_whole_readable_file_and_no_temporary(tmp_path):
    target = tmp_path / "table.md"
    write_text_atomically(target, "| a |\n")
    write_text_atomically(target, "| b |\n")
    assert target.read_text() == "| b |\n"
    assert [p.name for p in tmp_path.iterdir()] == ["table.md"]
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(target.stat().st_mode) == 0o666 & ~umask
