#pragma once
// The two-sample Kolmogorov-Smirnov test: D = sup |F_1 - F_2| over the two empirical CDFs, and the
// asymptotic p-value Q_KS((sqrt(n_e) + 0.12 + 0.11 / sqrt(n_e)) D), n_e = n m / (n + m), with
// Q_KS(x) = 2 sum_k (-1)^(k-1) exp(-2 k^2 x^2) (Stephens' small-sample correction). How the
// fracture studies measure convergence in distribution between successive levels.
#include <vector>

namespace vorodg {

struct KsResult {
  double distance = 0.0;  // D in [0, 1]
  double p_value = 1.0;   // the chance of a D this large if both samples came from one law
};

/// Q_KS(x) = Pr(sqrt(n_e) D > x) in the limit of large samples, the p-value's series.
double kolmogorov_survival(double x);

/// Throws InputError if either sample is empty or holds a non-finite value.
KsResult ks_two_sample(std::vector<double> a, std::vector<double> b);

}  // namespace vorodg
