#include "fracture/Fragments.hpp"

#include <algorithm>
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/UnionFind.hpp"

namespace vorodg {

Fragments::Fragments(const CrackState& cracks, const std::vector<double>& pair_masses)
    : mesh_(&cracks.mesh()), lumped_(&pair_masses) {
  if (static_cast<int>(pair_masses.size()) != mesh_->offsets().back())
    throw InputError("fragments: lumped masses of " + std::to_string(pair_masses.size()) +
                     " pairs for a mesh of " + std::to_string(mesh_->offsets().back()));
  label_cells(cracks);
  accumulate_lumped();
}

Fragments::Fragments(const CrackState& cracks, double density) : mesh_(&cracks.mesh()) {
  require_parameter(density > 0.0, "fragments: density", density, "> 0");
  label_cells(cracks);
  accumulate_areas(density);
}

void Fragments::label_cells(const CrackState& cracks) {
  UnionFind cells(mesh_->num_cells());
  for (int e = 0; e < mesh_->num_edges(); ++e) {
    const MeshEdge& edge = mesh_->edge(e);
    if (!edge.on_boundary() && !cracks.cracked(e)) cells.join(edge.cell0, edge.cell1);
  }
  fragment_ = cells.labels(&num_fragments_);
  cells_.assign(num_fragments_, 0);
  for (int f : fragment_) ++cells_[f];
  mass_ = Eigen::VectorXd::Zero(num_fragments_);
  centre_ = Eigen::Matrix2Xd::Zero(2, num_fragments_);
}

double Fragments::pair_mass(int c, int k) const {
  return (*lumped_)[mesh_->offsets()[c] + k];
}

void Fragments::accumulate_lumped() {
  // One pass in pair order: every fragment's sums, and the total, in the order the lumped
  // masses' own total is summed.
  for (int c = 0; c < mesh_->num_cells(); ++c) {
    const auto loop = mesh_->cell_vertices(c);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const double m = pair_mass(c, static_cast<int>(k));
      mass_[fragment_[c]] += m;
      centre_.col(fragment_[c]) += m * mesh_->vertex(loop[k]);
      total_ += m;
    }
  }
  for (int f = 0; f < num_fragments_; ++f) centre_.col(f) /= mass_[f];
}

void Fragments::accumulate_areas(double density) {
  for (int c = 0; c < mesh_->num_cells(); ++c) {
    const double m = density * mesh_->cell_area(c);
    mass_[fragment_[c]] += m;
    centre_.col(fragment_[c]) += m * mesh_->cell_centroid(c);
    total_ += m;
  }
  for (int f = 0; f < num_fragments_; ++f) centre_.col(f) /= mass_[f];
}

Eigen::Matrix2Xd Fragments::velocities(const SplitDofMap& dofs, const Eigen::VectorXd& v) const {
  if (!lumped_) throw InputError("fragments: velocities need lumped masses, not density x area");
  if (v.size() != dofs.num_dofs())
    throw InputError("fragments: " + std::to_string(v.size()) + " velocity entries for a map of " +
                     std::to_string(dofs.num_dofs()) + " DOFs");
  Eigen::Matrix2Xd momentum = Eigen::Matrix2Xd::Zero(2, num_fragments_);
  for (int c = 0; c < mesh_->num_cells(); ++c)
    for (int k = 0; k < mesh_->cell_size(c); ++k)
      momentum.col(fragment_[c]) += pair_mass(c, k) * v.segment<2>(2 * dofs.node(c, k));
  for (int f = 0; f < num_fragments_; ++f) momentum.col(f) /= mass_[f];
  return momentum;
}

Eigen::VectorXd Fragments::sorted_mass_fractions() const {
  Eigen::VectorXd fractions = mass_ / total_;
  std::sort(fractions.data(), fractions.data() + fractions.size());
  return fractions;
}

double Fragments::largest_mass_fraction() const {
  return mass_.maxCoeff() / total_;
}

Fragments::Cdf Fragments::mass_fraction_cdf() const {
  Cdf cdf{sorted_mass_fractions(), Eigen::VectorXd(num_fragments_)};
  for (int i = 0; i < num_fragments_; ++i) cdf.cumulative[i] = double(i + 1) / num_fragments_;
  return cdf;
}

}  // namespace vorodg
