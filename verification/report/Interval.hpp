#pragma once
// An estimate with its confidence interval, as the statistical estimators of the report give it.

namespace vorodg {

struct Interval {
  double estimate = 0.0;
  double low = 0.0;   // the interval's lower end
  double high = 0.0;  // and its upper end, at the confidence asked
  [[nodiscard]] bool contains(double x) const { return low <= x && x <= high; }
};

}  // namespace vorodg
