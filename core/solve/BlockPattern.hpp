#pragma once
// A fixed sparsity pattern built from dense blocks (a cell's DOFs, an interface's DOFs), with the
// position of every block entry in the compressed-column value array. A matrix whose pattern
// never changes but whose values do (a Newton tangent) is then re-assembled in place: copy a base
// of values, scatter the blocks that changed; no triplets, no sort, no reallocation.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <span>
#include <vector>

namespace vorodg {

class BlockPattern {
 public:
  /// Full (both triangles) n x n pattern of the union of the blocks; each block lists its DOFs.
  BlockPattern(int n, const std::vector<std::vector<int>>& blocks);

  /// A matrix with the pattern and zero values.
  Eigen::SparseMatrix<double> zero_matrix() const;
  int num_blocks() const { return static_cast<int>(block_start_.size()) - 1; }
  /// Value positions of block b's entries, column-major (entry (i, j) at i + m j).
  std::span<const int> positions(int b) const {
    return {positions_.data() + block_start_[b],
            static_cast<std::size_t>(block_start_[b + 1] - block_start_[b])};
  }
  /// Adds the dense block Kb (m x m) into the values of `matrix` (which has this pattern).
  void add(int b, const Eigen::Ref<const Eigen::MatrixXd>& Kb,
           Eigen::SparseMatrix<double>& matrix) const;

 private:
  Eigen::SparseMatrix<double> pattern_;
  std::vector<int> block_start_, positions_;
};

/// The lower triangle of a pattern restricted to a subset of its rows and columns (the free
/// DOFs), with a map from the full matrix's value positions to the restricted ones, so that a
/// tangent is restricted in place every iteration.
class RestrictedLower {
 public:
  /// `index[i]`: the restricted index of DOF i, or -1 if it is left out.
  RestrictedLower(const Eigen::SparseMatrix<double>& full, const std::vector<int>& index, int n);
  /// Overwrites the values of matrix() with those of `full` (same pattern as at construction).
  const Eigen::SparseMatrix<double>& restrict(const Eigen::SparseMatrix<double>& full);
  const Eigen::SparseMatrix<double>& matrix() const { return lower_; }

 private:
  Eigen::SparseMatrix<double> lower_;
  std::vector<int> target_;  // per full value position: the restricted position or -1
};

}  // namespace vorodg
