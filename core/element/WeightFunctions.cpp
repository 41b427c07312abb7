#include "core/element/WeightFunctions.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <string>

#include "core/element/LatticeBasis.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// Stiffness and load of one sub-triangle of fan triangle (C, A, B): every sub-triangle of the
/// lattice, up or down, has the same matrices in its local node order (the down triangles are
/// the up ones turned by 180 degrees).
struct SubTriangleMatrices {
  Eigen::Matrix<double, 6, 6> K;
  Eigen::Matrix<double, 6, 1> f;
};

/// Reference integrals R_ab(i, j) = int d_a phi_i d_b phi_j over the reference triangle, for the
/// (xi, eta) derivatives a, b, and int phi_i: a sub-triangle's matrices are a combination of
/// them with its metric, so no quadrature runs per sub-triangle.
struct ReferenceIntegrals {
  Eigen::Matrix<double, 6, 6> R[2][2];
  Eigen::Matrix<double, 6, 1> mass;
};

ReferenceIntegrals make_reference(int degree) {
  ReferenceIntegrals ref;
  for (auto& row : ref.R)
    for (auto& m : row) m.setZero();
  ref.mass.setZero();
  const int n = degree == 1 ? 3 : 6;
  const TriangleRule& rule = triangle_rule(3);  // exact: the integrands are quadratic at most
  for (int q = 0; q < rule.size(); ++q) {
    double phi[6], dphi[6][2];
    lattice_basis(degree, rule.bary[q][1], rule.bary[q][2], phi, dphi);
    const double w = 0.5 * rule.weights[q];  // the reference triangle's area is 1/2
    for (int i = 0; i < n; ++i) {
      ref.mass[i] += w * phi[i];
      for (int j = 0; j < n; ++j)
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) ref.R[a][b](i, j) += w * dphi[i][a] * dphi[j][b];
    }
  }
  return ref;
}

const ReferenceIntegrals& reference_integrals(int degree) {
  static const ReferenceIntegrals p1 = make_reference(1), p2 = make_reference(2);
  return degree == 1 ? p1 : p2;
}

SubTriangleMatrices sub_triangle_matrices(const Point& C, const Point& A, const Point& B, int m,
                                          int degree) {
  const Eigen::Matrix2d J = sub_triangle_jacobian(C, A, B, m, true);
  const double det = std::abs(J.determinant());
  const Eigen::Matrix2d Jinv = J.inverse();
  const Eigen::Matrix2d metric = det * Jinv * Jinv.transpose();  // |J| J^-1 J^-T
  const ReferenceIntegrals& ref = reference_integrals(degree);
  SubTriangleMatrices out;
  out.K = metric(0, 0) * ref.R[0][0] + metric(0, 1) * (ref.R[0][1] + ref.R[1][0]) +
          metric(1, 1) * ref.R[1][1];
  out.f = det * ref.mass;
  return out;
}

/// Unknown numbering of one patch: per patch cell, the unknown of each cell-local node, or -1
/// where the weight function is held at zero (every node on an edge not incident to the patch
/// vertex, including the other vertices).
struct PatchNumbering {
  struct CellDofs {
    int cell;
    int k;  // position of the patch vertex in the cell's loop
    std::vector<int> dof;
  };
  std::vector<CellDofs> cells;
  int unknowns = 0;
};

/// Numbers the patch of `vertex` into `patch` (reusing its storage: this runs once per vertex).
void number_patch(const PolygonMesh& mesh, int vertex, int N, PatchNumbering& patch) {
  patch.unknowns = 0;
  const auto patch_cells = mesh.vertex_cells(vertex);
  patch.cells.resize(patch_cells.size());
  const int vertex_dof = patch.unknowns++;
  std::array<std::pair<int, int>, 64> shared_edges;  // mesh edge -> first unknown of its nodes
  int n_shared = 0;
  for (std::size_t pc = 0; pc < patch_cells.size(); ++pc) {
    const int c = patch_cells[pc];
    const auto loop = mesh.cell_vertices(c);
    const int n = static_cast<int>(loop.size());
    const FanLattice lattice(n, N);
    PatchNumbering::CellDofs& cd = patch.cells[pc];
    cd.cell = c;
    cd.k = static_cast<int>(std::find(loop.begin(), loop.end(), vertex) - loop.begin());
    cd.dof.assign(lattice.node_count(), -1);
    cd.dof[0] = patch.unknowns++;
    cd.dof[1 + cd.k] = vertex_dof;
    for (int s = 0; s < n; ++s)
      for (int t = 1; t < N; ++t) cd.dof[lattice.spoke_node(s, t)] = patch.unknowns++;
    for (int node = lattice.first_interior(); node < lattice.node_count(); ++node)
      cd.dof[node] = patch.unknowns++;                // fan interiors
    for (int e_local : {cd.k, (cd.k + n - 1) % n}) {  // the two edges at the patch vertex
      const int e = mesh.cell_edges(c)[e_local];
      auto it = std::find_if(shared_edges.begin(), shared_edges.begin() + n_shared,
                             [&](const auto& p) { return p.first == e; });
      if (it == shared_edges.begin() + n_shared) {
        if (n_shared == static_cast<int>(shared_edges.size()))
          throw InputError("vertex " + std::to_string(vertex) + " has more than 32 cells");
        *it = {e, patch.unknowns};
        ++n_shared;
        patch.unknowns += N - 1;
      }
      const bool same_direction = mesh.edge(e).v0 == loop[e_local];
      for (int t = 1; t < N; ++t)
        cd.dof[lattice.edge_node(e_local, t)] = it->second + (same_direction ? t : N - t) - 1;
    }
  }
}

}  // namespace

void check_weight_options(const WeightFunctionOptions& o) {
  if (std::find(kWeightDegrees.begin(), kWeightDegrees.end(), o.degree) == kWeightDegrees.end())
    throw InputError("weight function degree " + std::to_string(o.degree) + ": expected 1 or 2");
  if (o.refinement < 0 || o.refinement > kMaxWeightRefinement)
    throw InputError("weight function refinement " + std::to_string(o.refinement) +
                     ": expected 0..4");
}

WeightFunctions::WeightFunctions(const PolygonMesh& mesh, const WeightFunctionOptions& options,
                                 int threads)
    : mesh_(mesh), options_(options) {
  check_weight_options(options);
  centroids_.resize(mesh.num_cells());
  offsets_.resize(mesh.num_cells() + 1, 0);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    centroids_[c] = mesh.cell_centroid(c);
    offsets_[c + 1] =
        offsets_[c] + static_cast<std::size_t>(mesh.cell_size(c)) * lattice(c).node_count();
  }
  values_.assign(offsets_.back(), 0.0);
#pragma omp parallel num_threads(std::max(threads, 1))
  {
#pragma omp for schedule(dynamic, 64)
    for (int v = 0; v < mesh.num_vertices(); ++v) solve_patch(v);
  }
}

void WeightFunctions::solve_patch(int vertex) {
  const int N = divisions(), m = lattice_size(), degree = options_.degree;
  // Per-thread scratch: a patch is small and solved once per vertex, so allocation would
  // dominate.
  thread_local PatchNumbering patch;
  thread_local std::vector<double> dense_storage;
  thread_local std::vector<Eigen::Triplet<double>> triplets;
  number_patch(mesh_, vertex, N, patch);
  const int n_u = patch.unknowns;
  const bool dense = n_u <= 64;  // beyond that the sparse factorization is cheaper
  triplets.clear();
  if (dense) dense_storage.assign(static_cast<std::size_t>(n_u) * n_u, 0.0);
  Eigen::Map<Eigen::MatrixXd> K_dense(dense ? dense_storage.data() : nullptr, dense ? n_u : 0,
                                      dense ? n_u : 0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_u);

  // -lap w = 1: stiffness and load of every sub-triangle, scattered to the unknowns.
  for (const auto& cd : patch.cells) {
    const auto loop = mesh_.cell_vertices(cd.cell);
    const int n = static_cast<int>(loop.size());
    const FanLattice lattice(n, N);
    for (int k = 0; k < n; ++k) {
      const auto local = sub_triangle_matrices(centroids_[cd.cell], mesh_.vertex(loop[k]),
                                               mesh_.vertex(loop[(k + 1) % n]), m, degree);
      for (int a = 0; a < m; ++a)
        for (int b = 0; a + b < m; ++b)
          for (bool up : {true, false}) {
            if (!up && a + b > m - 2) continue;
            const auto nodes = sub_triangle_nodes(lattice, k, a, b, up, degree);
            int dofs[6];
            for (int i = 0; i < nodes.count; ++i) dofs[i] = cd.dof[nodes.node[i]];
            // Lower triangle only: both factorizations read nothing else.
            for (int i = 0; i < nodes.count; ++i) {
              const int di = dofs[i];
              if (di < 0) continue;
              f[di] += local.f[i];
              for (int j = 0; j < nodes.count; ++j) {
                const int dj = dofs[j];
                if (dj < 0 || dj > di) continue;
                if (dense)
                  K_dense(di, dj) += local.K(i, j);
                else
                  triplets.emplace_back(di, dj, local.K(i, j));
              }
            }
          }
    }
  }
  Eigen::VectorXd w;
  if (dense) {
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(K_dense);  // factorizes in place
    w = llt.solve(f);
  } else {
    Eigen::SparseMatrix<double> K(n_u, n_u);
    K.setFromTriplets(triplets.begin(), triplets.end());
    w = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>(K).solve(f);
  }
  for (const auto& cd : patch.cells) {
    const int n_nodes = static_cast<int>(cd.dof.size());
    double* out = values_.data() + offsets_[cd.cell] + static_cast<std::size_t>(cd.k) * n_nodes;
    for (int node = 0; node < n_nodes; ++node)
      out[node] = cd.dof[node] >= 0 ? w[cd.dof[node]] : 0.0;
  }
}

void WeightFunctions::evaluate(int cell, int fan, const Eigen::Vector3d& bary, double* w,
                               Eigen::Vector2d* grad) const {
  const auto loop = mesh_.cell_vertices(cell);
  const int n = static_cast<int>(loop.size());
  const int m = lattice_size(), degree = options_.degree;
  const FanLattice lat = lattice(cell);
  const LatticeLocation loc = locate_in_lattice(bary, m);
  const auto nodes = sub_triangle_nodes(lat, fan, loc.a, loc.b, loc.up, degree);
  double phi[6], dphi[6][2];
  lattice_basis(degree, loc.xi, loc.eta, phi, dphi);
  const Eigen::Matrix2d Jinv_t = sub_triangle_jacobian(centroids_[cell], mesh_.vertex(loop[fan]),
                                                       mesh_.vertex(loop[(fan + 1) % n]), m, loc.up)
                                     .inverse()
                                     .transpose();
  for (int j = 0; j < n; ++j) {
    const auto vals = values(cell, j);
    double value = 0.0;
    Eigen::Vector2d d = Eigen::Vector2d::Zero();
    for (int i = 0; i < nodes.count; ++i) {
      const double nodal = vals[nodes.node[i]];
      value += phi[i] * nodal;
      d += nodal * Eigen::Vector2d(dphi[i][0], dphi[i][1]);
    }
    w[j] = value;
    grad[j] = Jinv_t * d;
  }
}

}  // namespace vorodg
