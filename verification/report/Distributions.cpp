#include "verification/report/Distributions.hpp"

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cstddef>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

void check_probability(const char* what, double p) {
  if (!(p > 0.0 && p < 1.0))
    throw InputError(std::string(what) + ": probability " + std::to_string(p) +
                     ": expected a value in (0, 1)");
}

}  // namespace

double normal_quantile(double p) {
  check_probability("normal quantile", p);
  return boost::math::quantile(boost::math::normal_distribution<double>(), p);
}

double student_t_quantile(double p, double degrees_of_freedom) {
  check_probability("Student t quantile", p);
  if (!(degrees_of_freedom > 0.0))
    throw InputError("Student t quantile: degrees of freedom " +
                     std::to_string(degrees_of_freedom) + ": expected > 0");
  return boost::math::quantile(boost::math::students_t_distribution<double>(degrees_of_freedom), p);
}

double student_t_critical(double confidence, std::size_t n) {
  if (n < 2)
    throw InputError("a Student t interval needs at least 2 values, found " + std::to_string(n));
  return student_t_quantile(0.5 * (1.0 + confidence), static_cast<double>(n - 1));
}

}  // namespace vorodg
