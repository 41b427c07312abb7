#include "verification/report/StatisticalConvergence.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/report/CheckedSample.hpp"
#include "verification/report/Distributions.hpp"
#include "verification/report/EmpiricalCdf.hpp"
#include "verification/report/RateFit.hpp"
#include "verification/report/SamplePlanner.hpp"
#include "verification/report/SampleStatistics.hpp"
#include "verification/report/Wasserstein.hpp"

namespace vorodg {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::converges: return "converges";
    case Verdict::converging: return "converging";
    case Verdict::does_not_converge: return "does not converge";
    case Verdict::undecided: return "undecided";
    case Verdict::not_applicable: return "not applicable";
  }
  return "?";
}

namespace {

double std_dev(const std::vector<double>& v) {
  return *sample_statistics(v).std_dev;
}

/// mean(a) - mean(b) with Welch's interval (the two levels' spreads need not agree).
Interval welch_interval(const std::vector<double>& a, const std::vector<double>& b,
                        double confidence) {
  const SampleStatistics sa = sample_statistics(a), sb = sample_statistics(b);
  const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
  const double va = *sa.std_dev * *sa.std_dev / na, vb = *sb.std_dev * *sb.std_dev / nb;
  const double change = sa.mean - sb.mean, se = std::sqrt(va + vb);
  if (se == 0.0) return {change, change, change};
  const double dof = (va + vb) * (va + vb) / (va * va / (na - 1) + vb * vb / (nb - 1));
  const double half = student_t_quantile(0.5 * (1.0 + confidence), dof) * se;
  return {change, change - half, change + half};
}

/// The values of the realizations both levels hold, in the same order.
std::pair<std::vector<double>, std::vector<double>> pairs_of(const LevelSample& coarse,
                                                             const LevelSample& fine) {
  std::map<int, double> by_realization;
  for (std::size_t i = 0; i < fine.value.size(); ++i)
    by_realization[fine.realization[i]] = fine.value[i];
  std::vector<double> a, b;
  for (std::size_t i = 0; i < coarse.value.size(); ++i)
    if (const auto it = by_realization.find(coarse.realization[i]); it != by_realization.end()) {
      a.push_back(coarse.value[i]);
      b.push_back(it->second);
    }
  return {a, b};
}

/// The realizations of a level's complete runs, measured or not.
std::set<int> complete_runs(const LevelSample& l) {
  const std::vector<int>& all = l.complete.empty() ? l.realization : l.complete;
  return {all.begin(), all.end()};
}

/// The share of complete runs that measured the quantity, the smaller of the two levels.
double measured_share(const LevelSample& coarse, const LevelSample& fine) {
  const auto share = [](const LevelSample& l) {
    return static_cast<double>(l.value.size()) / static_cast<double>(complete_runs(l).size());
  };
  return std::min(share(coarse), share(fine));
}

/// Pairs per realization complete at both levels.
double paired_share(const LevelSample& coarse, const LevelSample& fine, std::size_t pairs) {
  const std::set<int> a = complete_runs(coarse), b = complete_runs(fine);
  std::vector<int> both;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  return both.empty() ? 1.0 : static_cast<double>(pairs) / static_cast<double>(both.size());
}

LevelStep compare(const LevelSample& coarse, const LevelSample& fine, double epsilon,
                  const StatisticalOptions& o) {
  LevelStep s;
  s.measured_share = measured_share(coarse, fine);
  s.ks = ks_two_sample(coarse.value, fine.value);
  const double n = static_cast<double>(coarse.value.size()),
               m = static_cast<double>(fine.value.size());
  s.ks_critical = ks_critical_distance(n * m / (n + m), o.confidence);
  s.wasserstein = bootstrap_independent(coarse.value, fine.value, wasserstein1, o.bootstrap);
  s.mean_change = welch_interval(coarse.value, fine.value, o.confidence);
  s.change_std_dev = std::hypot(std_dev(coarse.value), std_dev(fine.value));
  if (!o.coupled) return s;
  const auto [a, b] = pairs_of(coarse, fine);
  if (a.size() < 2) return s;
  s.coupled = coupled_differences(a, b, epsilon, o.confidence);
  s.paired_share = paired_share(coarse, fine, a.size());
  s.mean_change = s.coupled->mean_difference;
  s.change_std_dev = s.coupled->difference_std_dev;
  return s;
}

}  // namespace

QuantityConvergence statistical_convergence(std::string name, std::vector<LevelSample> levels,
                                            const StatisticalOptions& o) {
  if (levels.size() < 2)
    throw InputError("statistical convergence of " + name + ": " + std::to_string(levels.size()) +
                     " level(s): expected at least 2");
  std::sort(levels.begin(), levels.end(),
            [](const LevelSample& a, const LevelSample& b) { return a.h_avg > b.h_avg; });
  QuantityConvergence q;
  q.name = std::move(name);
  for (const LevelSample& l : levels) {
    check_sample("statistical convergence of " + q.name, l.value);
    if (l.value.size() < 2 || l.realization.size() != l.value.size())
      throw InputError("statistical convergence of " + q.name + ": a level at h = " + fmt(l.h_avg) +
                       " has " + std::to_string(l.value.size()) +
                       " value(s): expected at least 2, each with its realization");
    const std::set<int> measured(l.realization.begin(), l.realization.end()),
        all = complete_runs(l);
    if (!std::includes(all.begin(), all.end(), measured.begin(), measured.end()))
      throw InputError("statistical convergence of " + q.name + ": a level at h = " + fmt(l.h_avg) +
                       " measured realizations that are not among its complete runs");
    q.mean.push_back(mean_interval(l.value, o.confidence));
    q.dkw.push_back(dkw_half_width(l.value.size(), o.confidence));
  }
  const LevelSample& finest = levels.back();
  q.scale = std::max(std::abs(q.mean.back().estimate), std_dev(finest.value));
  if (q.scale == 0.0) q.scale = 1.0;  // every value 0: an absolute tolerance
  q.epsilon = o.tolerance * q.scale;
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    q.steps.push_back(compare(levels[k], levels[k + 1], q.epsilon, o));
  }
  const bool one_sign = std::all_of(q.mean.begin(), q.mean.end(), [&](const Interval& m) {
    return m.estimate * q.mean.front().estimate > 0.0;
  });
  if (one_sign) {
    std::vector<double> h, m;
    for (std::size_t k = 0; k < levels.size(); ++k)
      h.push_back(levels[k].h_avg), m.push_back(std::abs(q.mean[k].estimate));
    q.trend = fit_rate(h, m).rate;
  }
  q.levels = std::move(levels);
  judge_convergence(q, o);
  return q;
}

}  // namespace vorodg
