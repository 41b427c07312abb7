#pragma once
// The one check every estimator of the report makes on a sample of realizations: it is not empty
// and every value is finite. A NaN in a sample is a broken run, never a value to average over.
#include <string_view>
#include <vector>

namespace vorodg {

/// Throws InputError "<what>: ..." if the sample is empty or holds a non-finite value (saying at
/// which position).
void check_sample(std::string_view what, const std::vector<double>& values);

/// The sample, checked as above, sorted ascending.
std::vector<double> sorted_sample(std::string_view what, std::vector<double> values);

}  // namespace vorodg
