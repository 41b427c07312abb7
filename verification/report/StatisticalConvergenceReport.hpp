#pragma once
// The statistical-convergence report's writers: for each quantity, the levels (mean with its
// interval, the CDF band), the pairs of successive levels (KS, W1, the change of the mean and,
// for coupled levels, E|D|, E|D|^2 and Pr(|D| > eps), each with its interval), the trend of the
// mean in h, and the four verdicts with the sample sizes that would decide the undecided ones.
// Markdown for people and CSV for programs, filled from one table.
#include <string>
#include <vector>

#include "verification/report/StatisticalConvergence.hpp"

namespace vorodg {

/// statistical-convergence.md: a section per quantity.
std::string statistical_convergence_md(const std::vector<QuantityConvergence>& quantities,
                                       const StatisticalOptions& options);

/// statistical-convergence.csv: one row per quantity and pair of successive levels, every
/// number in full (intervals as low and high columns), the verdicts of the finest pair on its
/// row.
std::string statistical_convergence_csv(const std::vector<QuantityConvergence>& quantities);

/// statistical-levels.csv: one row per quantity and level (h_avg, runs, the mean with its
/// interval, the DKW half-width, core-hours): what the plots draw the bands from.
std::string statistical_levels_csv(const std::vector<QuantityConvergence>& quantities);

}  // namespace vorodg
