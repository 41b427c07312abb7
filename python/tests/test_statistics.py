"""vorodg.statistics against scipy and numpy on random samples (fixed seeds): the estimators the
statistical-convergence report uses, each computed by the C++ library and by an independent
implementation. scipy's Student-t quantiles are 4e-12 to 4e-10 off at small degrees of freedom
(tests/test_StatisticalEstimators.cpp has mpmath's values), so t-based intervals compare at 1e-9."""
import numpy as np
import pytest
from scipy import stats

from vorodg import statistics as vs


@pytest.fixture
def rng():
    return np.random.default_rng(2008)


@pytest.mark.parametrize("n,m", [(12, 12), (40, 25), (300, 500)])
def test_distances_match_scipy(rng, n, m):
    a, b = rng.normal(0.0, 1.0, n), rng.gamma(2.0, 0.6, m)
    b[: m // 3] = np.round(b[: m // 3], 1)  # ties within b
    ks = vs.ks_two_sample(a, b)
    assert ks["distance"] == pytest.approx(stats.ks_2samp(a, b).statistic, abs=1e-14)
    assert vs.wasserstein1(a, b) == pytest.approx(stats.wasserstein_distance(a, b), rel=1e-12)


def test_empirical_cdf_and_quantiles_match_numpy(rng):
    x = rng.weibull(1.5, 101)
    f = vs.EmpiricalCdf(x)
    probes = np.concatenate([x[:10], rng.uniform(-0.5, 3.0, 50)])
    expected = np.searchsorted(np.sort(x), probes, side="right") / x.size
    assert [f(p) for p in probes] == pytest.approx(expected, abs=1e-15)
    ps = np.linspace(0.0, 1.0, 17)
    assert [f.quantile(p) for p in ps] == pytest.approx(np.quantile(x, ps), rel=1e-14)
    assert f.dkw_half_width(0.9) == pytest.approx(np.sqrt(np.log(2 / 0.1) / (2 * 101)), rel=1e-14)


def test_intervals_match_scipy(rng):
    x = rng.normal(3.0, 0.7, 9)
    low, high = stats.t.interval(0.9, x.size - 1, loc=x.mean(), scale=stats.sem(x))
    t = vs.mean_interval(x, 0.9)
    assert (t.low, t.high) == pytest.approx((low, high), rel=1e-9)
    for hits, trials in [(0, 7), (3, 12), (40, 41), (250, 1000)]:
        ci = stats.binomtest(hits, trials).proportion_ci(0.95, "wilson")
        w = vs.wilson_interval(hits, trials)
        assert (w.low, w.high) == pytest.approx((ci.low, ci.high), abs=1e-12)
    assert vs.normal_quantile(0.995) == pytest.approx(stats.norm.ppf(0.995), rel=1e-14)
    assert vs.student_t_quantile(0.9, 4.0) == pytest.approx(stats.t.ppf(0.9, 4.0), rel=1e-9)


def test_coupled_differences_match_their_definitions(rng):
    coarse = rng.normal(100.0, 10.0, 30)
    fine = coarse + rng.normal(1.0, 2.0, 30)
    r = vs.coupled_differences(coarse, fine, epsilon=2.5, confidence=0.95)
    d = coarse - fine
    for key, values in [("mean_difference", d), ("mean_absolute", abs(d)), ("mean_square", d**2)]:
        low, high = stats.t.interval(0.95, d.size - 1, loc=values.mean(), scale=stats.sem(values))
        assert r[key].estimate == pytest.approx(values.mean(), rel=1e-13)
        assert (r[key].low, r[key].high) == pytest.approx((max(low, 0.0) if key != "mean_difference" else low, high), rel=1e-9)
    hits = int(np.sum(abs(d) > 2.5))
    ci = stats.binomtest(hits, d.size).proportion_ci(0.95, "wilson")
    assert (r["exceedance"].low, r["exceedance"].high) == pytest.approx((ci.low, ci.high), abs=1e-12)


def test_bootstrap_agrees_with_scipys_within_resampling_error(rng):
    """Both percentile intervals of W1 between two samples; different generators, so they agree to
    the resampling error of a 2.5 % quantile from 4000 draws (a few per cent of the width)."""
    a, b = rng.normal(0.0, 1.0, 60), rng.normal(0.3, 1.2, 80)
    ours = vs.bootstrap_interval(a, b, vs.wasserstein1, resamples=4000)
    theirs = stats.bootstrap((a, b), stats.wasserstein_distance, method="percentile",
                             n_resamples=4000, vectorized=False, random_state=1).confidence_interval
    width = theirs.high - theirs.low
    assert ours.estimate == pytest.approx(stats.wasserstein_distance(a, b), rel=1e-12)
    assert ours.low == pytest.approx(theirs.low, abs=0.1 * width)
    assert ours.high == pytest.approx(theirs.high, abs=0.1 * width)
    paired = vs.bootstrap_interval(a, a + 0.01, lambda x, y: float(np.mean(x) - np.mean(y)),
                                   paired=True, resamples=200)
    assert paired.low == pytest.approx(-0.01, abs=1e-12) and paired.high == pytest.approx(-0.01, abs=1e-12)


def test_planner_resolves_what_it_promises(rng):
    n = vs.realizations_for_ks(0.2)
    lam = stats.kstwobign.isf(0.05)
    crit = lambda k: lam / (np.sqrt(k / 2) + 0.12 + 0.11 / np.sqrt(k / 2))  # noqa: E731
    assert crit(n) <= 0.2 < crit(n - 1)
    assert vs.realizations_for_cdf_band(0.1) == int(np.ceil(np.log(40) / (2 * 0.01)))
    m = vs.realizations_for_mean(3.0, 1.0)
    half = lambda k: stats.t.ppf(0.975, k - 1) * 3.0 / np.sqrt(k)  # noqa: E731
    assert half(m) <= 1.0 + 1e-9 and half(m - 1) > 1.0


def test_bad_samples_are_refused_in_one_line():
    with pytest.raises(ValueError, match="not finite"):
        vs.wasserstein1([1.0, float("nan")], [1.0])
    with pytest.raises(ValueError, match="empty"):
        vs.ks_two_sample([], [1.0])
    with pytest.raises(ValueError, match="one pair per realization"):
        vs.coupled_differences([1.0, 2.0], [1.0], epsilon=0.1)


def _strip_scene(field):
    """The shipped quick campaign made smaller: the strip at the normalized rate 10, two levels,
    six realizations; with or without its random material field."""
    import json
    from conftest import ROOT
    scene = json.loads((ROOT / "data" / "scenes" / "strip-statistical-convergence-quick.json").read_text())
    scene["meshes"][0]["realizations"] = 6
    if not field:
        for key in [k for k in scene["material"] if k.startswith("field")]:
            del scene["material"][key]
    return scene


def _report_rows(folder):
    import csv
    with open(folder / "rate-10" / "statistical-convergence.csv") as f:
        return list(csv.DictReader(f))


def test_a_scene_with_a_field_gets_the_coupled_report(tmp_path):
    import vorodg
    vorodg.run(_strip_scene(True), str(tmp_path / "field"), threads=2, progress=False, plots=False)
    rows = _report_rows(tmp_path / "field")
    assert [(r["mesh"], r["quantity"]) for r in rows] == [
        ("rcp", "fragments"), ("rcp", "max_fragment_mass_fraction"), ("rcp", "dissipated_energy")]
    verdicts = {"converges", "converging", "does not converge", "undecided"}
    for r in rows:
        assert int(r["pairs"]) == 6
        # Jensen: E|D| >= |E D|, and E|D|^2 >= (E|D|)^2, realization by realization pairs.
        assert float(r["E|D|"]) >= abs(float(r["mean change"])) - 1e-12 * abs(float(r["E|D|"]))
        assert float(r["E|D|^2"]) >= float(r["E|D|"]) ** 2 * (1 - 1e-12)
        assert {r["in distribution"], r["of the mean"], r["in mean"], r["in probability"]} <= verdicts
    md = (tmp_path / "field" / "rate-10" / "statistical-convergence.md").read_text()
    assert "levels coupled" in md
    import csv
    with open(tmp_path / "field" / "rate-10" / "statistical-levels.csv") as f:
        levels = list(csv.DictReader(f))
    assert len(levels) == 3 * 2 and all(int(l["runs"]) == 6 for l in levels)
    for l in levels:  # the DKW half-width for 6 runs at 95 %
        assert float(l["CDF band +-"]) == pytest.approx((np.log(40) / 12) ** 0.5, rel=1e-12)
        assert float(l["mean low"]) <= float(l["mean"]) <= float(l["mean high"])
        assert float(l["core-hours"]) > 0


def test_without_a_field_the_coupled_notions_do_not_apply(tmp_path):
    import vorodg
    vorodg.run(_strip_scene(False), str(tmp_path / "plain"), threads=2, progress=False, plots=False)
    for r in _report_rows(tmp_path / "plain"):
        assert r["in mean"] == "not applicable" and r["in probability"] == "not applicable"
        assert "pairs" not in r or r["pairs"] == ""
