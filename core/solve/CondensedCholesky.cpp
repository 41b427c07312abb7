#include "core/solve/CondensedCholesky.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

CondensedCholesky::CondensedCholesky(std::vector<int> varying) : varying_(std::move(varying)) {
  std::sort(varying_.begin(), varying_.end());
  varying_.erase(std::unique(varying_.begin(), varying_.end()), varying_.end());
}

void CondensedCholesky::set_up(const Eigen::SparseMatrix<double>& lower) {
  const int n = static_cast<int>(lower.cols());
  if (!varying_.empty() && (varying_.front() < 0 || varying_.back() >= n))
    throw InputError("CondensedCholesky: a varying unknown lies outside the matrix (" +
                     std::to_string(n) + " unknowns)");
  is_varying_.assign(n, 0);
  for (int g : varying_) is_varying_[g] = 1;
  place_.assign(n, -1);
  constant_.clear();
  for (int i = 0; i < n; ++i)
    if (!is_varying_[i]) place_[i] = static_cast<int>(constant_.size()), constant_.push_back(i);
  for (std::size_t k = 0; k < varying_.size(); ++k) place_[varying_[k]] = static_cast<int>(k);

  // Split the constant entries: A_II (its lower triangle) and K_IG.
  const int nI = static_cast<int>(constant_.size()), nG = num_varying();
  std::vector<Eigen::Triplet<double>> a_ii, k_ig;
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (i < j) continue;  // the lower triangle only
      if (!is_varying_[i] && !is_varying_[j])
        a_ii.emplace_back(place_[i], place_[j], it.value());
      else if (!is_varying_[i])
        k_ig.emplace_back(place_[i], place_[j], it.value());
      else if (!is_varying_[j])
        k_ig.emplace_back(place_[j], place_[i], it.value());
    }
  Eigen::SparseMatrix<double> A_II(nI, nI);
  A_II.setFromTriplets(a_ii.begin(), a_ii.end());
  K_IG_.resize(nI, nG);
  K_IG_.setFromTriplets(k_ig.begin(), k_ig.end());
  FactorizationOptions options;
  options.ordering = FillOrdering::amd;  // the constant set need not keep a node's DOFs in pairs
  options.block_size = 1;
  options.min_rcond = 0.0;
  inner_.factorize(A_II, options);

  // Its part of every Schur complement, K_GI A_II^-1 K_IG, kBlock columns at a time.
  constexpr int kBlock = 32;
  correction_.resize(nG, nG);
  for (int g = 0; g < nG; g += kBlock) {
    const int columns = std::min(kBlock, nG - g);
    const Eigen::MatrixXd x = inner_.solve_many(Eigen::MatrixXd(K_IG_.middleCols(g, columns)));
    correction_.middleCols(g, columns) = K_IG_.transpose() * x;
  }
  first_values_.assign(lower.valuePtr(), lower.valuePtr() + lower.nonZeros());
  scale_ = 0.0;
  for (double v : first_values_) scale_ = std::max(scale_, std::abs(v));
}

bool CondensedCholesky::constant_part_unchanged(const Eigen::SparseMatrix<double>& lower) const {
  if (static_cast<std::size_t>(lower.nonZeros()) != first_values_.size()) return false;
  const double tolerance = kConstantTolerance * scale_;
  const double* value = lower.valuePtr();
  for (int j = 0; j < lower.cols(); ++j)
    for (int q = lower.outerIndexPtr()[j]; q < lower.outerIndexPtr()[j + 1]; ++q) {
      const int i = lower.innerIndexPtr()[q];
      if (is_varying_[i] && is_varying_[j]) continue;
      if (!(std::abs(value[q] - first_values_[q]) <= tolerance)) return false;
    }
  return true;
}

bool CondensedCholesky::factorize(const Eigen::SparseMatrix<double>& lower) {
  if (place_.empty()) {
    Stopwatch clock;
    set_up(lower);
    setup_seconds_ = clock.seconds();
  } else if (static_cast<int>(place_.size()) != lower.cols() || !constant_part_unchanged(lower)) {
    return false;
  }
  const int nG = num_varying();
  schur_ = -correction_;
  for (int g = 0; g < nG; ++g) {
    const int j = varying_[g];
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (i < j || !is_varying_[i]) continue;
      const int r = place_[i];
      schur_(r, g) += it.value();
      if (r != g) schur_(g, r) += it.value();
    }
  }
  {
    // Small and dense: Eigen's OpenMP teams for its blocks would only wait on each other.
    const ScopedSerialOpenMp serial;
    schur_lu_.emplace(schur_);
  }
  if (nG > 0 && !(std::isfinite(schur_lu_->rcond()) && schur_lu_->rcond() > 0.0))
    throw NumericalError("the Schur complement on the " + std::to_string(nG) +
                         " varying unknowns is singular");
  return true;
}

Eigen::VectorXd CondensedCholesky::solve(const Eigen::VectorXd& rhs) const {
  return solve_many(Eigen::MatrixXd(rhs)).col(0);
}

Eigen::MatrixXd CondensedCholesky::solve_many(const Eigen::MatrixXd& rhs) const {
  if (!schur_lu_) throw NumericalError("internal: CondensedCholesky::solve before factorize");
  const int nI = static_cast<int>(constant_.size()), nG = num_varying();
  const Eigen::Index m = rhs.cols();
  Eigen::MatrixXd r_I(nI, m), r_G(nG, m);
  for (int k = 0; k < nI; ++k) r_I.row(k) = rhs.row(constant_[k]);
  for (int k = 0; k < nG; ++k) r_G.row(k) = rhs.row(varying_[k]);
  const Eigen::MatrixXd y = inner_.solve_many(r_I);
  const Eigen::MatrixXd x_G = schur_lu_->solve(r_G - K_IG_.transpose() * y);
  const Eigen::MatrixXd x_I = inner_.solve_many(r_I - K_IG_ * x_G);
  Eigen::MatrixXd x(rhs.rows(), m);
  for (int k = 0; k < nI; ++k) x.row(constant_[k]) = x_I.row(k);
  for (int k = 0; k < nG; ++k) x.row(varying_[k]) = x_G.row(k);
  if (!x.allFinite()) throw NumericalError("the condensed solve gave a non-finite result");
  return x;
}

}  // namespace vorodg
