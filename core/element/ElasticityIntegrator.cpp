#include "core/element/ElasticityIntegrator.hpp"

#include <algorithm>
#include <vector>

#include "core/element/VirtualElement.hpp"

namespace vorodg {

ElasticityIntegrator::ElasticityIntegrator(const ElementTable& table,
                                           const IsotropicElasticity& material, bool mean_dilation)
    : table_(table), material_(material), mean_dilation_(mean_dilation) {}

void ElasticityIntegrator::strain_operator(int c, int q, StrainOperator& B) const {
  strain_operator_of(c, &table_.grad(c, q, 0), B);  // the gradients of (c, q) are contiguous
}

void ElasticityIntegrator::strain_operator_of(int c, const Eigen::Vector2d* gradients,
                                              StrainOperator& B) const {
  const int n = table_.num_nodes(c);
  vorodg::strain_operator(gradients, n, B);
  if (!mean_dilation_) return;
  // B-bar: the in-plane dilatation eps_xx + eps_yy (all of the volumetric strain in plane
  // strain, where eps_zz = 0) is replaced by its cell mean: each of the two normal strains takes
  // half of the difference. (The 3D split with 1/3 would need an eps_zz row; without it the
  // pointwise dilatation stays in and the element still locks.)
  const double share = 0.5;
  double area = 0.0;
  for (int j = 0; j < table_.num_points(c); ++j) area += table_.weight(c, j);
  for (int k = 0; k < n; ++k) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (int j = 0; j < table_.num_points(c); ++j)
      mean += table_.weight(c, j) * table_.grad(c, j, k);
    const Eigen::Vector2d shift = share * (mean / area - gradients[k]);
    for (int d = 0; d < 2; ++d) {
      B(0, 2 * k + d) += shift[d];
      B(1, 2 * k + d) += shift[d];
    }
  }
}

void ElasticityIntegrator::cell_matrix(int c, Eigen::MatrixXd& K) const {
  if (mean_dilation_)
    strain_operator_stiffness(c, K);
  else  // the standard B: the same sum from products of the gradients
    standard_strain_stiffness(table_.weights(c), &table_.grad(c, 0, 0), table_.num_nodes(c),
                              material_.D(), K);
  if (table_.options().family == ElementFamily::vem) add_vem_stabilization(c, K);
}

void ElasticityIntegrator::strain_operator_stiffness(int c, Eigen::MatrixXd& K) const {
  const int n = table_.num_nodes(c);
  K.setZero(2 * n, 2 * n);
  StrainOperator B;
  const Eigen::Matrix3d& D = material_.D();
  for (int q = 0; q < table_.num_points(c); ++q) {
    strain_operator(c, q, B);
    K.noalias() += table_.weight(c, q) * (B.transpose() * D * B);
  }
}

/// The virtual element's stabilization, tau trace(K) / (2n) (I - P)^T (I - P) on each
/// displacement component: the usual dofi-dofi form, scaled by the consistency part so that it
/// has the stiffness's units and size whatever the material and the cell.
void ElasticityIntegrator::add_vem_stabilization(int c, Eigen::MatrixXd& K) const {
  const PolygonMesh& mesh = table_.mesh();
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  Eigen::Vector2d nodes[64];
  for (int k = 0; k < n; ++k) nodes[k] = mesh.vertex(loop[k]);
  const Eigen::MatrixXd pattern =
      vem_stabilization_pattern({nodes, static_cast<std::size_t>(n)}, mesh.cell_area(c));
  const double scale = table_.options().vem_stabilization * K.trace() / (2.0 * n);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 2; ++d) K(2 * j + d, 2 * k + d) += scale * pattern(j, k);
}

ElasticityIntegrator::CellMatrices ElasticityIntegrator::cell_matrices(int first, int last,
                                                                       int threads) const {
  const PolygonMesh& mesh = table_.mesh();
  const int count = last - first;
  CellMatrices out;
  out.first = first;
  out.offset.assign(count + 1, 0);
  for (int i = 0; i < count; ++i)
    out.offset[i + 1] =
        out.offset[i] + 4 * std::size_t(mesh.cell_size(first + i)) * mesh.cell_size(first + i);
  out.data.resize(out.offset.back());
#pragma omp parallel num_threads(std::max(threads, 1))
  {
    Eigen::MatrixXd K;
#pragma omp for schedule(dynamic, 256)
    for (int i = 0; i < count; ++i) {
      cell_matrix(first + i, K);
      std::copy(K.data(), K.data() + K.size(), out.data.begin() + out.offset[i]);
    }
  }
  return out;
}

Eigen::Vector3d ElasticityIntegrator::mean_stress(int c, const Eigen::VectorXd& u) const {
  return material_.D() * (mean_strain_operator(c) * u);
}

StrainOperator ElasticityIntegrator::mean_strain_operator(int c) const {
  // B is linear in the gradients, so its mean is B of the mean gradients; and the B-bar shift
  // (the cell-mean dilatation minus the pointwise one) vanishes there, so both operators agree.
  const int n = table_.num_nodes(c);
  thread_local std::vector<Eigen::Vector2d> mean;
  mean.assign(n, Eigen::Vector2d::Zero());
  double area = 0.0;
  for (int q = 0; q < table_.num_points(c); ++q) {
    const double w = table_.weight(c, q);
    area += w;
    for (int k = 0; k < n; ++k) mean[k] += w * table_.grad(c, q, k);
  }
  for (Eigen::Vector2d& g : mean) g /= area;
  StrainOperator B;
  vorodg::strain_operator(mean.data(), n, B);
  return B;
}

ElasticityIntegrator::MeanStrainOperators ElasticityIntegrator::all_mean_strain_operators(
    int threads) const {
  const int nc = table_.mesh().num_cells();
  MeanStrainOperators out;
  out.offset.assign(nc + 1, 0);
  for (int c = 0; c < nc; ++c)
    out.offset[c + 1] = out.offset[c] + 6 * std::size_t(table_.num_nodes(c));
  out.data.resize(out.offset.back());
#pragma omp parallel for schedule(dynamic, 256) num_threads(std::max(threads, 1))
  for (int c = 0; c < nc; ++c) {
    const StrainOperator op = mean_strain_operator(c);
    std::copy(op.data(), op.data() + op.size(), out.data.begin() + out.offset[c]);
  }
  return out;
}

}  // namespace vorodg
