// The verdicts of a statistical-convergence analysis (docs/statistics.md, "The verdicts"). Each
// reads the finest pair of levels first: what it cannot resolve is "undecided" with the sample
// size that would decide it; what it resolves as different is "converging" if the difference
// fell from the pair before with an observed order, else "does not converge".
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/util/Format.hpp"
#include "verification/report/RateFit.hpp"
#include "verification/report/SamplePlanner.hpp"
#include "verification/report/StatisticalConvergence.hpp"

namespace vorodg {
namespace {

/// The half-width an interval around `estimate` needs to fall on one side of `bound`: their
/// distance, but at least a tenth of the bound (an estimate on the bound decides nothing).
double clearance(double estimate, double bound) {
  return std::max(std::abs(estimate - bound), 0.1 * bound);
}

/// What a "does not converge" from a single pair of levels must add: it has no trend.
std::string single_pair(const QuantityConvergence& q) {
  return q.steps.size() == 1
             ? "; with two levels there is no trend to tell a slow convergence from none"
             : "";
}

std::string range(const Interval& i) {
  // Appended piece by piece: GCC 12 warns falsely (-Wstringop-overflow) on "[" + std::string&&
  // once this is inlined into a unity batch.
  std::string out = "[";
  out += fmt(i.low, 3);
  out += ", ";
  out += fmt(i.high, 3);
  out += "]";
  return out;
}

/// The order at which a difference d fell from step k - 1 to step k (h of their coarse levels).
double fell_at(const QuantityConvergence& q, std::size_t k, double d_before, double d_now) {
  return pair_rate(q.levels[k - 1].h_avg, std::abs(d_before), q.levels[k].h_avg, std::abs(d_now));
}

/// A falling difference between the last two steps: both intervals given, the later one wholly
/// below the earlier. `value(step)` picks the interval.
template <class Pick>
std::optional<double> falling(const QuantityConvergence& q, Pick value) {
  const std::size_t k = q.steps.size() - 1;
  if (k == 0) return std::nullopt;
  const std::optional<Interval> before = value(q.steps[k - 1]), now = value(q.steps[k]);
  if (!before || !now || !(now->high < before->low)) return std::nullopt;
  return fell_at(q, k, before->estimate, now->estimate);
}

/// The finest two levels' common value when every realization of both has it (a quantity
/// constant by construction, such as a straight crack's tortuosity).
std::optional<double> one_constant(const QuantityConvergence& q) {
  const std::size_t n = q.levels.size();
  const double c = q.levels[n - 1].value.front();
  for (std::size_t k = n - 2; k < n; ++k)
    for (double v : q.levels[k].value)
      if (v != c) return std::nullopt;
  return c;
}

/// Both finest samples all equal to c: a law that puts mass p elsewhere shows only c in n draws
/// with probability (1 - p)^n <= exp(-p n), so at confidence o.confidence, split over the two
/// samples, p <= ln(2 / (1 - confidence)) / n for each (the rule of three, 3 / n, for one sample
/// at 95 %). The two laws then differ by at most the larger p in KS distance.
NotionVerdict constant_in_distribution(const QuantityConvergence& q, double c,
                                       const StatisticalOptions& o) {
  const std::size_t n =
      std::min(q.levels[q.levels.size() - 2].value.size(), q.levels.back().value.size());
  const double tail = std::log(2.0 / (1.0 - o.confidence));
  const double bound = tail / static_cast<double>(n);
  const std::string what = "every realization of the finest two levels is " + fmt(c, 6) +
                           ": their laws differ by at most " + fmt(bound, 2) + " in KS distance";
  if (bound <= o.ks_resolution)
    return {Verdict::converges, what + " (<= " + fmt(o.ks_resolution, 2) + ")"};
  return {Verdict::undecided, what + "; " + fmt(o.ks_resolution, 2) + " asks",
          static_cast<std::size_t>(std::ceil(tail / o.ks_resolution))};
}

NotionVerdict in_distribution(const QuantityConvergence& q, const StatisticalOptions& o) {
  if (const std::optional<double> c = one_constant(q)) return constant_in_distribution(q, *c, o);
  const LevelStep& s = q.steps.back();
  const std::string ks = "KS D = " + fmt(s.ks.distance, 3) + " (p = " + fmt(s.ks.p_value, 2) +
                         ", detectable " + fmt(s.ks_critical, 2) + ")";
  if (s.ks.p_value < 1.0 - o.confidence) {
    const auto order = falling(q, [](const LevelStep& t) { return std::optional(t.wasserstein); });
    if (order)
      return {Verdict::converging, "the finest levels' laws still differ (" + ks +
                                       "), but W1 fell to " + fmt(s.wasserstein.estimate, 3) +
                                       " at observed order " + fmt(*order, 2)};
    return {Verdict::does_not_converge, "the finest levels' laws differ (" + ks + ", W1 " +
                                            range(s.wasserstein) + ")" + single_pair(q)};
  }
  if (s.ks_critical <= o.ks_resolution)
    return {Verdict::converges, "the finest levels' laws agree to the resolution asked (" + ks +
                                    " <= " + fmt(o.ks_resolution, 2) + ")"};
  return {Verdict::undecided,
          "no difference seen, but only a distance above " + fmt(s.ks_critical, 2) + " could be (" +
              ks + "); " + fmt(o.ks_resolution, 2) + " asks",
          realizations_for_ks(o.ks_resolution, o.confidence)};
}

NotionVerdict of_mean(const QuantityConvergence& q, const StatisticalOptions& o) {
  const Interval& c = q.steps.back().mean_change;
  const std::string change = "the mean changes by " + fmt(c.estimate, 3) + " " + range(c) +
                             " between the finest levels (tolerance " + fmt(q.epsilon, 3) + ")";
  if (c.low >= -q.epsilon && c.high <= q.epsilon) return {Verdict::converges, change};
  if (c.contains(0.0)) {  // to decide: an interval inside +-eps, or one clear of 0
    const double size = std::abs(c.estimate);
    const double half = size > q.epsilon ? size : clearance(size, q.epsilon);
    return {Verdict::undecided, change,
            realizations_for_mean(q.steps.back().change_std_dev, half, o.confidence)};
  }
  const auto order = falling(q, [](const LevelStep& t) {
    Interval a = t.mean_change;  // its size: the interval of |change| when it excludes 0
    if (a.low < 0.0 && a.high > 0.0) return std::optional<Interval>();
    if (a.high < 0.0) a = {-a.estimate, -a.high, -a.low};
    return std::optional(a);
  });
  if (order)
    return {Verdict::converging,
            change + ", after a larger change, at observed order " + fmt(*order, 2)};
  std::string trend = q.trend ? "; the mean goes as h^" + fmt(*q.trend, 2) : "";
  return {Verdict::does_not_converge, change + trend + single_pair(q)};
}

NotionVerdict coupled_notion(const QuantityConvergence& q, const StatisticalOptions& o,
                             bool probability) {
  if (!o.coupled)
    return {Verdict::not_applicable,
            "the levels do not share their random field: no pairs to difference"};
  const LevelStep& s = q.steps.back();
  if (!s.coupled)
    return {Verdict::not_applicable, "fewer than two realizations ran at both finest levels"};
  const Interval v = probability ? s.coupled->exceedance : s.coupled->mean_absolute;
  const double bound = probability ? o.probability : q.epsilon;
  const std::string what =
      (probability ? "Pr(|D| > " + fmt(q.epsilon, 3) + ") = " : std::string("E|D| = ")) +
      fmt(v.estimate, 3) + " " + range(v) + " against " + fmt(bound, 3);
  if (v.high <= bound) return {Verdict::converges, what};
  if (v.low > bound) {
    const auto order = falling(q, [&](const LevelStep& t) {
      if (!t.coupled) return std::optional<Interval>();
      return std::optional(probability ? t.coupled->exceedance : t.coupled->mean_absolute);
    });
    if (order) return {Verdict::converging, what + ", falling at observed order " + fmt(*order, 2)};
    return {Verdict::does_not_converge, what + single_pair(q)};
  }
  // To decide: an interval wholly on the estimate's side of the bound, if the estimate stays.
  std::size_t n = 0;
  if (!probability)
    n = realizations_for_mean(s.coupled->absolute_std_dev, clearance(v.estimate, bound),
                              o.confidence);
  else if (v.estimate != bound)
    n = realizations_to_clear(v.estimate, bound, o.confidence);
  else
    n = realizations_for_probability(bound, clearance(v.estimate, bound), o.confidence);
  return {Verdict::undecided, what, n};
}

/// The planner counts values (or pairs); a quantity only some runs measure (a column that never
/// struck has no rear-strike time) needs that many divided by the share of runs that give one.
NotionVerdict in_runs(NotionVerdict v, double share, const char* unit) {
  if (v.realizations == 0 || share >= 1.0) return v;
  const std::size_t values = v.realizations;
  v.realizations = static_cast<std::size_t>(std::ceil(static_cast<double>(values) / share));
  v.reason += "; that is " + std::to_string(values) + " " + unit + ", and " +
              fmt(100.0 * share, 2) + " % of the runs give one";
  return v;
}

}  // namespace

void judge_convergence(QuantityConvergence& q, const StatisticalOptions& o) {
  const LevelStep& finest = q.steps.back();
  q.in_distribution = in_runs(in_distribution(q, o), finest.measured_share, "values");
  q.of_mean = finest.coupled ? in_runs(of_mean(q, o), finest.paired_share, "pairs")
                             : in_runs(of_mean(q, o), finest.measured_share, "values");
  q.in_mean = in_runs(coupled_notion(q, o, false), finest.paired_share, "pairs");
  q.in_probability = in_runs(coupled_notion(q, o, true), finest.paired_share, "pairs");
}

}  // namespace vorodg
