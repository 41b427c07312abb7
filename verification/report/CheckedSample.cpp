#include "verification/report/CheckedSample.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

void check_sample(std::string_view what, const std::vector<double>& values) {
  if (values.empty()) throw InputError(std::string(what) + ": a sample is empty");
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw InputError(std::string(what) + ": value " + std::to_string(i) +
                       " of a sample is not finite (expected a finite number from every run)");
}

std::vector<double> sorted_sample(std::string_view what, std::vector<double> values) {
  check_sample(what, values);
  std::sort(values.begin(), values.end());
  return values;
}

}  // namespace vorodg
