#include "verification/report/EmpiricalCdf.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/report/CheckedSample.hpp"

namespace vorodg {

EmpiricalCdf::EmpiricalCdf(std::vector<double> sample, std::string_view what)
    : sorted_(sorted_sample(what, std::move(sample))) {}

double EmpiricalCdf::operator()(double x) const {
  const auto at_or_below = std::upper_bound(sorted_.begin(), sorted_.end(), x) - sorted_.begin();
  return static_cast<double>(at_or_below) / static_cast<double>(sorted_.size());
}

double EmpiricalCdf::quantile(double p) const {
  if (!(p >= 0.0 && p <= 1.0))
    throw InputError("empirical quantile: p = " + std::to_string(p) + ": expected in [0, 1]");
  const double position = p * static_cast<double>(sorted_.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  if (below + 1 >= sorted_.size()) return sorted_.back();
  const double t = position - static_cast<double>(below);
  return sorted_[below] + t * (sorted_[below + 1] - sorted_[below]);
}

double EmpiricalCdf::dkw_half_width(double confidence) const {
  return vorodg::dkw_half_width(sorted_.size(), confidence);
}

std::pair<double, double> EmpiricalCdf::dkw_band(double x, double confidence) const {
  const double f = (*this)(x), eps = dkw_half_width(confidence);
  return {std::max(0.0, f - eps), std::min(1.0, f + eps)};
}

double dkw_half_width(std::size_t n, double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0))
    throw InputError("DKW band: confidence " + std::to_string(confidence) + ": expected in (0, 1)");
  if (n == 0) throw InputError("DKW band: a sample is empty");
  return std::sqrt(std::log(2.0 / (1.0 - confidence)) / (2.0 * static_cast<double>(n)));
}

}  // namespace vorodg
