#pragma once
// How many realizations a level needs before a statistical conclusion can be drawn at the asked
// resolution. Each answer is the smallest n at which the interval (or the test's critical value)
// at `confidence` is no wider than delta: a true difference of delta is then declared about half
// the time, and a larger one more often. The report prints them beside every conclusion it draws,
// so that "undecided" comes with how many runs would decide.
#include <cstddef>

namespace vorodg {

/// The two-sample KS distance the test declares at `confidence` for the effective size
/// n_e = n m / (n + m): lambda / (sqrt(n_e) + 0.12 + 0.11 / sqrt(n_e)), Q_KS(lambda) = 1 - c.
double ks_critical_distance(double effective_size, double confidence = 0.95);

/// Per level (two levels of equal size): the two-sample Kolmogorov-Smirnov test's critical
/// distance (asymptotic, Stephens' correction) at most delta, 0 < delta < 1.
std::size_t realizations_for_ks(double delta, double confidence = 0.95);

/// The DKW band's half-width at most delta: n = ln(2 / (1 - confidence)) / (2 delta^2).
std::size_t realizations_for_cdf_band(double delta, double confidence = 0.95);

/// A mean (or E|D|^r) to within +-delta given the values' standard deviation: the smallest
/// n >= 2 with t_{n-1} std_dev / sqrt(n) <= delta.
std::size_t realizations_for_mean(double std_dev, double delta, double confidence = 0.95);

/// A probability near p to within +-delta (normal approximation: z^2 p (1 - p) / delta^2); p = 0.5
/// when nothing is known of it, the most demanding.
std::size_t realizations_for_probability(double p, double delta, double confidence = 0.95);

/// The share of a sample beyond a bound: the smallest n at which the Wilson interval of the
/// share `share` (round(share n) of n) lies wholly on its side of `bound`, 0 < bound < 1 and
/// share != bound. What decides "is Pr below the bound?" if the share stays what it is.
std::size_t realizations_to_clear(double share, double bound, double confidence = 0.95);

}  // namespace vorodg
