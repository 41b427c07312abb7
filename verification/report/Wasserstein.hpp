#pragma once
// The Wasserstein-1 (earth mover's) distance between two samples' empirical distributions,
// W1 = integral |F_a(x) - F_b(x)| dx: in the quantity's own units, where the Kolmogorov-Smirnov
// distance is a share. Where D says whether two levels' CDFs differ, W1 says by how much of the
// quantity (fragments, joules) the mass has to move.
#include <vector>

namespace vorodg {

/// Throws InputError for an empty sample or a non-finite value.
double wasserstein1(std::vector<double> a, std::vector<double> b);

}  // namespace vorodg
