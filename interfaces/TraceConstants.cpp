#include "interfaces/TraceConstants.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <thread>

#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// Orthonormal basis of the rigid motions (two translations, one rotation about the vertices'
/// mean, which makes it orthogonal to both) at the cell's vertex DOFs: the shape functions are
/// nodal and reproduce linear fields.
Eigen::MatrixXd rigid_modes(const PolygonMesh& mesh, int c) {
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (int v : loop) centre += mesh.vertex(v) / n;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(2 * n, 3);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d x = mesh.vertex(loop[k]) - centre;
    R(2 * k, 0) = R(2 * k + 1, 1) = 1.0 / std::sqrt(n);
    R(2 * k, 2) = -x.y();
    R(2 * k + 1, 2) = x.x();
  }
  R.col(2).normalize();
  return R;
}

double largest_eigenvalue(const Eigen::MatrixXd& S) {
  if (S.rows() == 2) {  // closed form for the constant-along-the-edge tractions
    const double half = 0.5 * (S(0, 0) - S(1, 1));
    return 0.5 * (S(0, 0) + S(1, 1)) + std::sqrt(half * half + S(0, 1) * S(1, 0));
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

/// Rows of a stress constant along edge k: ||S n||^2_F = length |N S v|^2.
Eigen::MatrixXd fan_rows(const InterfaceOperators& ops, int c, int k, const StressOperator& S) {
  const PolygonMesh& mesh = ops.space().mesh();
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  const double length = (mesh.vertex(loop[(k + 1) % n]) - mesh.vertex(loop[k])).norm();
  return std::sqrt(length) * InterfaceOperators::traction_map(ops.edge_normal(c, k)) * S;
}

}  // namespace

Eigen::MatrixXd TraceConstants::traction_rows(const InterfaceOperators& ops, TractionKind kind,
                                              int c, int k) {
  if (kind != TractionKind::point) return fan_rows(ops, c, k, ops.edge_stress(c, k, 0.5, kind));
  const PolygonMesh& mesh = ops.space().mesh();
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  const double length = (mesh.vertex(loop[(k + 1) % n]) - mesh.vertex(loop[k])).norm();
  const auto N = InterfaceOperators::traction_map(ops.edge_normal(c, k));
  const SegmentRule& rule = gauss2_segment();
  Eigen::MatrixXd G(4, 2 * n);
  for (int g = 0; g < 2; ++g)
    G.middleRows(2 * g, 2) =
        std::sqrt(rule.weights[g] * length) * N * ops.edge_stress(c, k, rule.t[g], kind);
  return G;
}

TraceConstants::TraceConstants(const InterfaceOperators& ops,
                               const ElasticityIntegrator::CellMatrices& stiffness,
                               TractionKind kind, int threads)
    : kind_(kind) {
  const PolygonMesh& mesh = ops.space().mesh();
  const int cells = mesh.num_cells();
  offsets_.assign(cells + 1, 0);
  for (int c = 0; c < cells; ++c) offsets_[c + 1] = offsets_[c] + mesh.cell_size(c);
  constants_.assign(offsets_.back(), 0.0);
  const int workers = std::clamp(threads, 1, std::max(cells, 1));
  std::vector<std::thread> pool;
  std::vector<std::string> failures(workers);
  for (int t = 0; t < workers; ++t)
    pool.emplace_back([&, t] {
      try {
        for (int c = t; c < cells; c += workers)
          compute_cell(ops, stiffness.block(c, 2 * mesh.cell_size(c)), c);
      } catch (const NumericalError& e) {
        failures[t] = e.what();
      }
    });
  for (auto& worker : pool) worker.join();
  for (const std::string& failure : failures)
    if (!failure.empty()) throw NumericalError(failure);
}

void TraceConstants::compute_cell(const InterfaceOperators& ops,
                                  const Eigen::Ref<const Eigen::MatrixXd>& K, int c) {
  const PolygonMesh& mesh = ops.space().mesh();
  const int n = mesh.cell_size(c);
  // K + s R R^T: positive definite when the only zero-energy modes are rigid, and its inverse
  // equals the pseudo-inverse of K on every traction row (rows annihilate rigid modes).
  const Eigen::MatrixXd R = rigid_modes(mesh, c);
  const double shift = K.trace() / (2 * n);
  thread_local Eigen::MatrixXd shifted;  // one buffer per thread: no allocation per cell
  shifted = K;
  shifted.noalias() += shift * R * R.transpose();
  const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(shifted);  // factors in place
  if (llt.info() != Eigen::Success)
    throw NumericalError("cell " + std::to_string(c) +
                         ": the stiffness matrix has a zero-energy mode that is not a rigid "
                         "motion; no trace constant exists");
  // Every edge's rows stacked, one triangular solve for all of them: Y = L^{-1} G^T.
  std::vector<StressOperator> fans;
  if (kind_ == TractionKind::fan) fans = ops.fan_stresses(c);
  const int rows = kind_ == TractionKind::point ? 4 : 2;
  thread_local Eigen::MatrixXd G, Y;
  G.resize(rows * n, 2 * n);
  for (int k = 0; k < n; ++k)
    G.middleRows(rows * k, rows) =
        kind_ == TractionKind::fan ? fan_rows(ops, c, k, fans[k]) : traction_rows(ops, kind_, c, k);
  Y = G.transpose();
  llt.matrixL().solveInPlace(Y);
  for (int k = 0; k < n; ++k) {
    const auto Yk = Y.middleCols(rows * k, rows);
    constants_[offsets_[c] + k] = largest_eigenvalue(Yk.transpose() * Yk);
  }
}

std::vector<double> TraceConstants::brute_force(const InterfaceOperators& ops,
                                                const ElasticityIntegrator& integrator,
                                                TractionKind kind, int c) {
  Eigen::MatrixXd K;
  integrator.cell_matrix(c, K);
  // The range of K from its eigenvectors; the quotient restricted to it is an ordinary
  // symmetric eigenproblem in the coordinates K^{1/2} v.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
  const double top = eig.eigenvalues().maxCoeff();
  std::vector<int> range;
  for (int i = 0; i < K.rows(); ++i)
    if (eig.eigenvalues()[i] > 1e-10 * top) range.push_back(i);
  Eigen::MatrixXd W(K.rows(), range.size());  // columns: v_i / sqrt(lambda_i)
  for (std::size_t j = 0; j < range.size(); ++j)
    W.col(j) = eig.eigenvectors().col(range[j]) / std::sqrt(eig.eigenvalues()[range[j]]);
  std::vector<double> out;
  for (int k = 0; k < ops.space().mesh().cell_size(c); ++k) {
    const Eigen::MatrixXd G = traction_rows(ops, kind, c, k) * W;
    out.push_back(largest_eigenvalue(G.transpose() * G));
  }
  return out;
}

}  // namespace vorodg
