#include "core/solve/BlockPattern.hpp"

#include <algorithm>

#include "core/util/Errors.hpp"

namespace vorodg {

BlockPattern::BlockPattern(int n, const std::vector<std::vector<int>>& blocks) {
  std::vector<Eigen::Triplet<double>> entries;
  std::size_t total = 0;
  for (const auto& dofs : blocks) total += dofs.size() * dofs.size();
  entries.reserve(total);
  for (const auto& dofs : blocks)
    for (int j : dofs)
      for (int i : dofs) entries.emplace_back(i, j, 0.0);
  pattern_.resize(n, n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();
  block_start_.assign(1, 0);
  positions_.reserve(total);
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (const auto& dofs : blocks) {
    for (int j : dofs)
      for (int i : dofs) {
        const int* it = std::lower_bound(inner + outer[j], inner + outer[j + 1], i);
        positions_.push_back(static_cast<int>(it - inner));
      }
    block_start_.push_back(static_cast<int>(positions_.size()));
  }
}

Eigen::SparseMatrix<double> BlockPattern::zero_matrix() const {
  return pattern_;
}

void BlockPattern::add(int b, const Eigen::Ref<const Eigen::MatrixXd>& Kb,
                       Eigen::SparseMatrix<double>& matrix) const {
  const std::span<const int> pos = positions(b);
  if (static_cast<Eigen::Index>(pos.size()) != Kb.size())
    throw NumericalError("internal: block size does not match its pattern");
  double* values = matrix.valuePtr();
  const double* k = Kb.data();  // column-major, as the positions
  for (std::size_t e = 0; e < pos.size(); ++e) values[pos[e]] += k[e];
}

RestrictedLower::RestrictedLower(const Eigen::SparseMatrix<double>& full,
                                 const std::vector<int>& index, int n) {
  if (!full.isCompressed()) throw NumericalError("internal: restrict needs a compressed matrix");
  const int* full_outer = full.outerIndexPtr();
  const int* full_inner = full.innerIndexPtr();
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < full.outerSize(); ++j)
    for (int k = full_outer[j]; k < full_outer[j + 1]; ++k)
      if (index[j] >= 0 && index[full_inner[k]] >= index[j])
        entries.emplace_back(index[full_inner[k]], index[j], 0.0);
  lower_.resize(n, n);
  lower_.setFromTriplets(entries.begin(), entries.end());
  lower_.makeCompressed();
  target_.assign(full.nonZeros(), -1);
  const int* outer = lower_.outerIndexPtr();
  const int* inner = lower_.innerIndexPtr();
  for (int j = 0; j < full.outerSize(); ++j)
    for (int k = full_outer[j]; k < full_outer[j + 1]; ++k) {
      const int fj = index[j], fi = index[full_inner[k]];
      if (fj < 0 || fi < fj) continue;
      target_[k] =
          static_cast<int>(std::lower_bound(inner + outer[fj], inner + outer[fj + 1], fi) - inner);
    }
}

const Eigen::SparseMatrix<double>& RestrictedLower::restrict(
    const Eigen::SparseMatrix<double>& full) {
  if (full.nonZeros() != static_cast<Eigen::Index>(target_.size()))
    throw NumericalError("internal: the matrix to restrict changed its pattern");
  double* out = lower_.valuePtr();
  std::fill(out, out + lower_.nonZeros(), 0.0);
  const double* in = full.valuePtr();
  for (std::size_t k = 0; k < target_.size(); ++k)
    if (target_[k] >= 0) out[target_[k]] += in[k];
  return lower_;
}

}  // namespace vorodg
