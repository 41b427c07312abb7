"""The band of the mean fragment CDF in scripts/fragment_level_plots.py (the report's Figures
15-20 redrawn): a run's CDF on a grid against its closed form, the simultaneous band's coverage of
a known expected CDF, and the figures written from a small study folder."""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

import fragment_level_plots as flp  # noqa: E402


def test_a_runs_cdf_counts_the_fragments_at_or_below_each_point():
    grid = np.array([0.05, 0.1, 0.25, 0.3, 1.0])
    assert np.array_equal(flp.cdf_on_grid([0.3, 0.1, 0.6], grid),
                          np.array([0.0, 1.0, 1.0, 2.0, 3.0]) / 3.0)


def uniform_runs(rng, realizations, fragments):
    """Runs whose fractions are independent uniforms: every run's expected CDF is x on [0, 1]."""
    return [rng.uniform(size=fragments) for _ in range(realizations)]


def test_the_band_holds_the_whole_expected_cdf_in_about_95_percent_of_samples():
    rng = np.random.default_rng(7)
    grid = np.linspace(0.0025, 1.0, 400)
    trials, covered = 300, 0
    for trial in range(trials):
        _, mean, band = flp.mean_cdf_band(uniform_runs(rng, 100, 3), grid, resamples=400,
                                          seed=trial)
        covered += np.all(np.abs(mean - grid) <= band)
    share = covered / trials
    # 95 % within three standard errors (0.013). At 40 runs the bootstrap falls short (0.91 in
    # 300 trials), at 100 to 400 runs it measured 0.95 to 0.958 in 600 trials each.
    assert 0.91 <= share <= 0.99, share


def test_the_band_narrows_like_one_over_root_n():
    rng = np.random.default_rng(11)
    grid = np.linspace(0.0025, 1.0, 200)
    widths = [np.median([flp.mean_cdf_band(uniform_runs(rng, n, 5), grid, resamples=300,
                                           seed=s)[2] for s in range(20)]) for n in (25, 100)]
    assert 1.7 <= widths[0] / widths[1] <= 2.3, widths


def test_one_realization_has_no_band():
    _, mean, band = flp.mean_cdf_band([np.array([0.2, 0.8])], np.array([0.5, 1.0]))
    assert np.array_equal(mean, [0.5, 1.0]) and np.isnan(band)


def write_study(folder, rng):
    """A study folder of two levels, six complete runs each, with their fragment tables."""
    (folder / "fragments").mkdir(parents=True)
    (folder / "plots").mkdir()
    rows = ["id,mesh,level,realization,complete,h_avg,max_fragment_mass_fraction"]
    for level, h in ((0, 0.05), (1, 0.025)):
        for r in range(6):
            run = f"rcp-L{level}-R{r}"
            mass = rng.exponential(size=20 * (level + 1))
            (folder / "fragments" / f"{run}.csv").write_text(
                "fragment,mass\n" + "".join(f"{i},{m}\n" for i, m in enumerate(mass)))
            rows.append(f"{run},rcp,{level},{r},1,{h},{mass.max() / mass.sum()}")
    (folder / "results.csv").write_text("\n".join(rows) + "\n")


def test_the_figures_are_written_for_every_level(tmp_path):
    import dynamics_plots
    write_study(tmp_path, np.random.default_rng(3))
    runs = dynamics_plots.read_runs(str(tmp_path))
    dynamics_plots.plot_level_cdfs(str(tmp_path), runs, 60)
    dynamics_plots.plot_levels(str(tmp_path), runs, 60)
    written = sorted(p.name for p in (tmp_path / "plots").iterdir())
    assert written == ["fragment_cdf_rcp_L0.png", "fragment_cdf_rcp_L1.png",
                       "largest_fragment_vs_h.png"]
