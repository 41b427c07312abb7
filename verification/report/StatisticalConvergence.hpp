#pragma once
// The statistical-convergence analysis of one quantity of interest over mesh levels (the report's
// section 5; docs/statistics.md "The verdicts"): per level, the mean with its interval and the
// empirical CDF's DKW half-width; between each level and the next finer one, the three notions
// (in distribution: KS and W1; of the mean: the change of the mean; for levels that share their
// random field, in r-th mean and in probability: E|D|^r and Pr(|D| > eps)); the trend of the mean
// in h; and for each notion a plain verdict with the sample size that would decide it.
#include <optional>
#include <string>
#include <vector>

#include "verification/report/Bootstrap.hpp"
#include "verification/report/CoupledDifferences.hpp"
#include "verification/report/Interval.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"

namespace vorodg {

/// One level's sample: a value per complete realization, and which realization it came from
/// (levels that share their random field pair up by realization).
struct LevelSample {
  double h_avg = 0.0;
  std::vector<int> realization;
  std::vector<double> value;
  /// The realizations of every complete run of the level, measured or not (a column that never
  /// struck has no rear-strike time); empty: those of `value`. What a run-count answer scales by.
  std::vector<int> complete;
  double core_seconds = 0.0;  // what its complete runs took, summed (the cost of the level)
  int level = 0;  // its index in the scene's mesh block (for the files that name runs by it)
};

struct StatisticalOptions {
  double confidence = 0.95;
  /// Realization i of every level shares its random field (and seed): the coupled notions apply.
  bool coupled = false;
  /// The resolution a verdict asks for, relative to the quantity's scale (the finest level's
  /// |mean|, or its standard deviation where that is larger): the epsilon of Pr(|D| > eps), the
  /// tolerance of E|D| and of the change of the mean.
  double tolerance = 0.05;
  /// The KS distance below which two levels' laws count as the same (the planner sizes for it).
  double ks_resolution = 0.1;
  /// Pr(|D| > eps) below this counts as converged in probability.
  double probability = 0.1;
  BootstrapOptions bootstrap;
};

/// Level k against level k + 1 (the finer).
struct LevelStep {
  KsResult ks;
  double ks_critical = 0.0;     // the distance the test can declare at these sizes and confidence
  Interval wasserstein;         // W1, percentile bootstrap (each level resampled on its own)
  Interval mean_change;         // mean_k - mean_{k+1}: Welch t, or paired t when coupled
  double change_std_dev = 0.0;  // sqrt(s_k^2 + s_{k+1}^2), or sd(D) when coupled: for the planner
  std::optional<CoupledDifferences> coupled;  // on the realizations both levels hold
  /// The share of complete runs that measured the quantity (the smaller of the two levels), and
  /// of realizations complete at both levels that give a pair: 1 for a quantity every run has.
  double measured_share = 1.0, paired_share = 1.0;
};

enum class Verdict { converges, converging, does_not_converge, undecided, not_applicable };
const char* verdict_name(Verdict v);

struct NotionVerdict {
  Verdict verdict = Verdict::not_applicable;
  std::string reason;            // one plain sentence with the numbers behind it
  std::size_t realizations = 0;  // runs per level, to decide an undecided verdict (0: not needed)
};

struct QuantityConvergence {
  std::string name;
  std::string mesh;                 // the mesh block it belongs to (empty: one block)
  std::vector<LevelSample> levels;  // coarse to fine
  std::vector<Interval> mean;       // per level (Student t; a point for one realization)
  std::vector<double> dkw;          // per level, the DKW half-width
  std::vector<LevelStep> steps;     // levels.size() - 1
  double scale = 0.0, epsilon = 0.0;
  std::optional<double> trend;  // d log|mean| / d log h over the levels (same sign, >= 2)
  NotionVerdict in_distribution, of_mean, in_mean, in_probability;
};

/// Sets the four verdicts of q from its numbers (docs/statistics.md, "The verdicts").
void judge_convergence(QuantityConvergence& q, const StatisticalOptions& options);

/// The analysis of one quantity. Levels are sorted coarse to fine by h_avg; each needs a
/// non-empty finite sample. Throws InputError for fewer than two levels.
QuantityConvergence statistical_convergence(std::string name, std::vector<LevelSample> levels,
                                            const StatisticalOptions& options = {});

}  // namespace vorodg
