#pragma once
// The quantiles the report's intervals and sample-size planner need, from Boost.Math (a
// well-kept implementation, not a series of our own). Each refuses a probability outside (0, 1).
#include <cstddef>

namespace vorodg {

/// z with Pr(Z <= z) = p for a standard normal Z.
double normal_quantile(double p);

/// t with Pr(T <= t) = p for Student's t with `degrees_of_freedom` > 0.
double student_t_quantile(double p, double degrees_of_freedom);

/// The two-sided critical value of a Student-t interval at `confidence` from n values: the
/// t_{n-1} quantile at (1 + confidence) / 2. Needs n >= 2.
double student_t_critical(double confidence, std::size_t n);

}  // namespace vorodg
