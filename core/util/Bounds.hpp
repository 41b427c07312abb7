#pragma once
// The numbers a schema entry accepts (a scene key, a solve setting): finite, and within an
// optional lower and upper bound, each open or closed. The one check every schema makes.
#include <cmath>
#include <optional>

namespace vorodg {

struct Bounds {
  std::optional<double> lower, upper;
  bool lower_open = false, upper_open = false;

  /// Finite and within the bounds.
  bool admits(double x) const {
    if (!std::isfinite(x)) return false;
    if (lower && (lower_open ? !(x > *lower) : !(x >= *lower))) return false;
    return !upper || (upper_open ? x < *upper : x <= *upper);
  }
};

}  // namespace vorodg
