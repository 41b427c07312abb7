#pragma once
// Direct solves of a symmetric sparse matrix whose entries change, from one factorization to
// the next, only among a few unknowns (the "varying" ones: the crack faces' end DOFs of a
// quasi-static fracture path, whose bulk is linear). The rest is factored once (sparse
// Cholesky of the constant block A_II); each factorization then only forms and factors the
// small dense Schur complement
//   S = K_GG - K_GI A_II^-1 K_IG,
// of which the second term is constant too. A solve is two sparse back-solves and one dense one.
//
// Whether the constant part really stayed constant is checked at every factorization, entry by
// entry against the first matrix (to kConstantTolerance of the matrix's largest entry): a
// matrix that changed elsewhere is refused (factorize returns false) and the caller factors
// it whole. S may be indefinite (a softening law's tangent): it is factored by LU with partial
// pivoting.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "core/solve/SparseCholesky.hpp"

namespace vorodg {

class CondensedCholesky {
 public:
  /// `varying`: the unknowns (0 .. n-1 of the matrices to come) whose rows and columns may
  /// change between factorizations.
  explicit CondensedCholesky(std::vector<int> varying);

  /// Entries outside the varying block may differ from the first matrix's by this much,
  /// relative to its largest entry (round-off of an unchanged sum), and no more.
  static constexpr double kConstantTolerance = 1e-12;

  /// Factors the matrix whose lower triangle is given (the same pattern at every call). The
  /// first call factors the constant block and precomputes its part of the Schur complement.
  /// Returns false, factoring nothing, if an entry outside the varying block changed.
  /// Throws NumericalError if the constant block is not positive definite or S is singular.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  /// Solves with the last factorization. Throws NumericalError on a non-finite result.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  /// The same for several right-hand sides at once (one column each).
  Eigen::MatrixXd solve_many(const Eigen::MatrixXd& rhs) const;

  int num_varying() const { return static_cast<int>(varying_.size()); }
  /// Seconds the first call took (the constant block's factorization and the Schur part).
  double setup_seconds() const { return setup_seconds_; }

 private:
  void set_up(const Eigen::SparseMatrix<double>& lower);
  bool constant_part_unchanged(const Eigen::SparseMatrix<double>& lower) const;

  std::vector<int> varying_;   // sorted, unique
  std::vector<int> constant_;  // the others, ascending
  std::vector<int> place_;     // per unknown: its index in varying_ or constant_
  std::vector<char> is_varying_;
  SparseCholesky inner_;              // A_II
  Eigen::SparseMatrix<double> K_IG_;  // n_I x n_G, constant
  Eigen::MatrixXd correction_;        // K_GI A_II^-1 K_IG, constant
  std::vector<double> first_values_;  // the first matrix's entries, for the check
  double scale_ = 0.0;                // its largest entry's magnitude
  Eigen::MatrixXd schur_;             // S of the last factorization
  std::optional<Eigen::PartialPivLU<Eigen::MatrixXd>> schur_lu_;
  double setup_seconds_ = 0.0;
};

}  // namespace vorodg
