#pragma once
// The empirical CDF of a sample of realizations, F_n(x) = #{x_i <= x} / n, with its
// Dvoretzky-Kiefer-Wolfowitz band: Pr(sup_x |F_n(x) - F(x)| > eps) <= 2 exp(-2 n eps^2) for
// every n and every F (Massart's constant), so F_n +- eps holds the true CDF everywhere at once
// with probability at least `confidence`. No assumption on F: the band a fragment-mass CDF of a
// few runs is drawn with.
#include <string_view>
#include <utility>
#include <vector>

namespace vorodg {

class EmpiricalCdf {
 public:
  /// Throws InputError (with `what` in front) for an empty sample or a non-finite value.
  explicit EmpiricalCdf(std::vector<double> sample, std::string_view what = "empirical CDF");

  [[nodiscard]] std::size_t size() const { return sorted_.size(); }
  [[nodiscard]] const std::vector<double>& sorted() const { return sorted_; }

  /// F_n(x): the share of the sample at or below x.
  [[nodiscard]] double operator()(double x) const;

  /// The p-quantile, interpolated linearly between order statistics at positions (n - 1) p (the
  /// default of numpy and R, "type 7"); p in [0, 1].
  [[nodiscard]] double quantile(double p) const;

  /// eps = sqrt(ln(2 / (1 - confidence)) / (2 n)), confidence in (0, 1).
  [[nodiscard]] double dkw_half_width(double confidence = 0.95) const;

  /// The band's lower and upper bound at x: F_n(x) -+ eps, clipped to [0, 1].
  [[nodiscard]] std::pair<double, double> dkw_band(double x, double confidence = 0.95) const;

 private:
  std::vector<double> sorted_;
};

/// The DKW half-width for n values at `confidence` (what EmpiricalCdf::dkw_half_width returns).
double dkw_half_width(std::size_t n, double confidence = 0.95);

}  // namespace vorodg
