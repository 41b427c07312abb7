#include "core/element/WeightFunctions.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/element/CellCondensation.hpp"
#include "core/element/LatticeBasis.hpp"
#include "core/element/LatticeStiffness.hpp"
#include "core/element/SmallCholesky.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

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

/// A congruent cell's slice of `data` (cell c at offsets[c]) is its representative's; called by
/// every thread of a parallel region (an orphaned worksharing loop).
void copy_from_representatives(std::span<const int> representative,
                               const std::vector<std::size_t>& offsets, std::vector<double>& data) {
  const int nc = static_cast<int>(representative.size());
#pragma omp for schedule(static)
  for (int c = 0; c < nc; ++c) {
    const int r = representative[c];
    if (r == c) continue;
    std::copy(data.begin() + offsets[r], data.begin() + offsets[r + 1], data.begin() + offsets[c]);
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
                                 int threads, std::span<const int> representative)
    : mesh_(mesh), options_(options) {
  if (!representative.empty() && static_cast<int>(representative.size()) != mesh.num_cells())
    throw InputError("weight functions: " + std::to_string(representative.size()) +
                     " representatives for " + std::to_string(mesh.num_cells()) + " cells");
  check_weight_options(options);
  centroids_.resize(mesh.num_cells());
  offsets_.resize(mesh.num_cells() + 1, 0);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    centroids_[c] = mesh.cell_centroid(c);
    offsets_[c + 1] =
        offsets_[c] + static_cast<std::size_t>(mesh.cell_size(c)) * lattice(c).node_count();
  }
  values_.assign(offsets_.back(), 0.0);
  int largest = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) largest = std::max(largest, lattice(c).node_count());
  if (options.condense && largest <= kMaxCondensedNodes) {
    solve_by_condensation(threads, representative);
    return;
  }
#pragma omp parallel num_threads(std::max(threads, 1))
  {
#pragma omp for schedule(dynamic, 64)
    for (int v = 0; v < mesh.num_vertices(); ++v) solve_patch(v);
  }
}

/// The patch problems with every cell's inner nodes eliminated: (1) per cell, the Schur
/// complement on each vertex's boundary nodes; (2) per vertex, the patch problem on its own node
/// and the nodes of the edges at it; (3) per cell, the inner values of each of its vertices'
/// weight functions from those boundary values. The same solution as one solve per patch, to
/// round-off, with each cell's matrix assembled and factored twice instead of once per vertex.
void WeightFunctions::solve_by_condensation(int threads, std::span<const int> representative) {
  const int N = divisions(), m = lattice_size(), degree = options_.degree, nb = 2 * N - 1;
  const int nc = mesh_.num_cells();
  const int per_vertex = nb * nb + nb;
  std::vector<std::size_t> block_offsets(nc + 1, 0);
  for (int c = 0; c < nc; ++c)
    block_offsets[c + 1] =
        block_offsets[c] + static_cast<std::size_t>(mesh_.cell_size(c)) * per_vertex;
  std::vector<double> blocks(block_offsets.back());
#pragma omp parallel num_threads(std::max(threads, 1))
  {
    CellCondensation cc;
#pragma omp for schedule(dynamic, 256)
    for (int c = 0; c < nc; ++c) {
      if (!computes(representative, c)) continue;
      condense_cell(mesh_, centroids_[c], c, N, m, degree, cc);
      vertex_blocks(cc, blocks.data() + block_offsets[c]);
    }
    copy_from_representatives(representative, block_offsets, blocks);
    std::vector<double> A, rhs;
    std::vector<int> local;  // per patch cell, its block's nodes as patch unknowns
    std::vector<int> edges;  // the patch's edges at the vertex
#pragma omp for schedule(dynamic, 256)
    for (int v = 0; v < mesh_.num_vertices(); ++v) {
      const auto cells = mesh_.vertex_cells(v);
      if (std::none_of(cells.begin(), cells.end(),
                       [&](int c) { return computes(representative, c); }))
        continue;  // every cell of the patch takes its values from its representative
      // Patch unknowns: the vertex, then N - 1 per edge at it, by distance from the vertex.
      edges.clear();
      const auto slot = [&](int e) {
        const auto it = std::find(edges.begin(), edges.end(), e);
        if (it != edges.end()) return static_cast<int>(it - edges.begin());
        edges.push_back(e);
        return static_cast<int>(edges.size()) - 1;
      };
      local.resize(cells.size() * nb);
      for (std::size_t pc = 0; pc < cells.size(); ++pc) {
        const int c = cells[pc], n = mesh_.cell_size(c), k = vertex_position(c, v);
        const int after = slot(mesh_.cell_edges(c)[k]);
        const int before = slot(mesh_.cell_edges(c)[(k + n - 1) % n]);
        int* idx = local.data() + pc * nb;
        idx[0] = 0;
        for (int s = 1; s < N; ++s) {
          idx[s] = 1 + after * (N - 1) + s - 1;
          idx[N - 1 + s] = 1 + before * (N - 1) + s - 1;
        }
      }
      const int p = 1 + static_cast<int>(edges.size()) * (N - 1);
      A.assign(static_cast<std::size_t>(p) * p, 0.0);
      rhs.assign(p, 0.0);
      for (std::size_t pc = 0; pc < cells.size(); ++pc) {
        const int c = cells[pc];
        const double* block = blocks.data() + block_offsets[c] +
                              static_cast<std::size_t>(vertex_position(c, v)) * per_vertex;
        const int* idx = local.data() + pc * nb;
        for (int a = 0; a < nb; ++a) {
          rhs[idx[a]] += block[nb * nb + a];
          for (int b = 0; b < nb; ++b) A[idx[a] * p + idx[b]] += block[a * nb + b];
        }
      }
      // A sum of Schur complements of positive definite cell matrices: positive definite.
      cholesky_in_place(A.data(), p);
      forward_solve(A.data(), p, rhs.data());
      backward_solve(A.data(), p, rhs.data());
      for (std::size_t pc = 0; pc < cells.size(); ++pc) {
        const int c = cells[pc], n = mesh_.cell_size(c), k = vertex_position(c, v);
        const FanLattice lat(n, N);
        double* out = values_.data() + offsets_[c] + static_cast<std::size_t>(k) * lat.node_count();
        int bn[2 * kMaxCondensedNodes];
        CellCondensation::boundary_nodes(lat, n, N, k, bn);
        const int* idx = local.data() + pc * nb;
        for (int a = 0; a < nb; ++a) out[bn[a]] = rhs[idx[a]];
      }
    }
#pragma omp for schedule(dynamic, 256)
    for (int c = 0; c < nc; ++c) {
      if (!computes(representative, c)) continue;
      condense_cell(mesh_, centroids_[c], c, N, m, degree, cc);
      recover_inner_values(cc, N, values_.data() + offsets_[c]);
    }
    copy_from_representatives(representative, offsets_, values_);
  }
}

int WeightFunctions::vertex_position(int cell, int vertex) const {
  const auto loop = mesh_.cell_vertices(cell);
  return static_cast<int>(std::find(loop.begin(), loop.end(), vertex) - loop.begin());
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
  for (const auto& cd : patch.cells)
    for_each_sub_triangle(mesh_, centroids_[cd.cell], cd.cell, N, m, degree,
                          [&](const SubTriangleNodes& nodes, const SubTriangleMatrices& local) {
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
                          });
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
  evaluate_fan(cell, fan, {&bary, 1}, w, grad);
}

void WeightFunctions::evaluate_fan(int cell, int fan, std::span<const Eigen::Vector3d> points,
                                   double* w, Eigen::Vector2d* grad) const {
  const auto loop = mesh_.cell_vertices(cell);
  const int n = static_cast<int>(loop.size());
  const int m = lattice_size(), degree = options_.degree;
  const FanLattice lat = lattice(cell);
  // Every sub-triangle of the fan triangle is the same affine map up to a sign (the "down"
  // ones are point-reflected): one inverse serves all the points.
  const Eigen::Matrix2d Jinv_t = sub_triangle_jacobian(centroids_[cell], mesh_.vertex(loop[fan]),
                                                       mesh_.vertex(loop[(fan + 1) % n]), m, true)
                                     .inverse()
                                     .transpose();
  const double* vals = values_.data() + offsets_[cell];
  const std::size_t stride = static_cast<std::size_t>(lat.node_count());
  for (std::size_t p = 0; p < points.size(); ++p, w += n, grad += n) {
    const LatticeLocation loc = locate_in_lattice(points[p], m);
    const auto nodes = sub_triangle_nodes(lat, fan, loc.a, loc.b, loc.up, degree);
    double phi[6], dphi[6][2];
    lattice_basis(degree, loc.xi, loc.eta, phi, dphi);
    const double sign = loc.up ? 1.0 : -1.0;
    for (int j = 0; j < n; ++j) {
      const double* nodal = vals + j * stride;
      double value = 0.0;
      Eigen::Vector2d d = Eigen::Vector2d::Zero();
      for (int i = 0; i < nodes.count; ++i) {
        const double v = nodal[nodes.node[i]];
        value += phi[i] * v;
        d += v * Eigen::Vector2d(dphi[i][0], dphi[i][1]);
      }
      w[j] = value;
      grad[j] = sign * (Jinv_t * d);
    }
  }
}

}  // namespace vorodg
