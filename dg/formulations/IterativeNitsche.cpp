// dg-nitsche: the report's iterative Nitsche (Eqs. 27-29),
//   a(u, v) + eps int [u].[v] = l(v) + int {sigma(u^i)} n . [v],
// the average stress of the last iterate on the right side, so the matrix is the penalty
// scheme's, factored once. The consistency operator int {sigma(u)} n . [v] is built once as a
// sparse matrix on all DOFs and applied per iteration.
#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "dg/DgFormulation.hpp"

namespace vorodg {

namespace {

constexpr int kConsistencyChunk = 1024;  // interfaces per parallel work item

class IterativeNitsche final : public DgFormulation {
 public:
  bool iterative() const override { return true; }

  /// int {sigma(u)} n.[v] as a matrix on all DOFs. Only the rows of the edge's end vertices are
  /// non-zero in a block ([v] lives there), so exact zeros are left out: a product with the
  /// matrix adds the same terms in the same order either way.
  void prepare(const DgTermContext& context) override {
    const auto& faces = context.space.interfaces();
    const int n = static_cast<int>(faces.size());
    std::vector<std::vector<Eigen::Triplet<double>>> parts((n + kConsistencyChunk - 1) /
                                                           kConsistencyChunk);
#pragma omp parallel for schedule(dynamic, 1) num_threads(context.threads)
    for (int part = 0; part < static_cast<int>(parts.size()); ++part)
      for (int i = part * kConsistencyChunk; i < std::min(n, (part + 1) * kConsistencyChunk); ++i) {
        const std::vector<int> dofs = context.ops.dofs(faces[i]);
        const Eigen::MatrixXd local = context.consistency_block(i);
        for (std::size_t j = 0; j < dofs.size(); ++j)
          for (std::size_t r = 0; r < dofs.size(); ++r)
            if (local(r, j) != 0.0) parts[part].emplace_back(dofs[r], dofs[j], local(r, j));
      }
    std::vector<Eigen::Triplet<double>> triplets;  // in interface order, as the sums must run
    for (const auto& part : parts) triplets.insert(triplets.end(), part.begin(), part.end());
    consistency_.resize(context.num_dofs(), context.num_dofs());
    consistency_.setFromTriplets(triplets.begin(), triplets.end());
  }

  /// +int {sigma(u)} n.[v] at the last iterate.
  Eigen::VectorXd interface_load(const DgTermContext&, const Eigen::VectorXd& u) const override {
    return consistency_ * u;
  }

 private:
  Eigen::SparseMatrix<double> consistency_;
};

}  // namespace

std::unique_ptr<DgFormulation> make_iterative_nitsche(const DgOptions&) {
  return std::make_unique<IterativeNitsche>();
}

}  // namespace vorodg
