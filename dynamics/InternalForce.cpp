#include "dynamics/InternalForce.hpp"

#include <algorithm>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// The last vertex's force becomes minus the sum of the others' (x and y).
inline void equilibrate(int n, double* f) {
  double sx = 0.0, sy = 0.0;
  for (int k = 0; k < n - 1; ++k) sx += f[2 * k], sy += f[2 * k + 1];
  f[2 * n - 2] = -sx;
  f[2 * n - 1] = -sy;
}

/// f_c = K_c u_c for a cell of N vertices, u_c gathered through the pairs' nodes; returns
/// 1/2 u_c.f_c. Fixed sizes let Eigen unroll and vectorize the 2N x 2N mat-vec.
/// Round-off must not create momentum. K_c annihilates translations, so u_c is taken relative
/// to its first vertex: the same force, but with round-off that scales with the cell's
/// deformation, not with how far it has moved (a body in uniform motion feels exactly zero
/// force). And the cell's force must be self-equilibrated: its last vertex takes minus the sum
/// of the others, so what round-off is left (from the rounding of u itself, which grows with a
/// spin) moves no momentum.
template <int N>
double cell_force(const double* K, const int* node, const double* u, double* f) {
  Eigen::Matrix<double, 2 * N, 1> uc;
  const double rx = u[2 * node[0]], ry = u[2 * node[0] + 1];
  for (int k = 0; k < N; ++k) {
    uc[2 * k] = u[2 * node[k]] - rx;
    uc[2 * k + 1] = u[2 * node[k] + 1] - ry;
  }
  Eigen::Map<Eigen::Matrix<double, 2 * N, 1>> fc(f);
  // Coefficient-based, as in corotational_force below: Eigen's general gemv kernel, which `*`
  // picks at this size, made BM_PlainStep 3 % slower at 1e4 and 1e5 cells.
  fc.noalias() = Eigen::Map<const Eigen::Matrix<double, 2 * N, 2 * N>>(K).lazyProduct(uc);
  equilibrate(N, f);
  return 0.5 * uc.dot(fc);
}

/// The same for a cell size without a fixed-size instance.
double cell_force_any(int n, const double* K, const int* node, const double* u, double* f) {
  Eigen::VectorXd uc(2 * n);
  const double rx = u[2 * node[0]], ry = u[2 * node[0] + 1];
  for (int k = 0; k < n; ++k) {
    uc[2 * k] = u[2 * node[k]] - rx;
    uc[2 * k + 1] = u[2 * node[k] + 1] - ry;
  }
  Eigen::Map<Eigen::VectorXd> fc(f, 2 * n);
  fc.noalias() = Eigen::Map<const Eigen::MatrixXd>(K, 2 * n, 2 * n) * uc;
  equilibrate(n, f);
  return 0.5 * uc.dot(fc);
}

/// The corotational force of cell c (CorotationalFrames): the local force K u^ of the
/// displacements in the cell's turning frame, turned back and completed by the turn's own
/// derivative; returns 1/2 u^.K u^. Both forces are self-equilibrated as above.
template <int N>
double corotational_force(const CorotationalFrames& frames, int c, const double* K, const int* node,
                          const double* u, double* f, double* local_out) {
  constexpr int M = N > 0 ? 2 * N : Eigen::Dynamic;
  const int n = N > 0 ? N : frames.cell_size(c);
  Eigen::Matrix<double, M, 1> w(2 * n), f_local(2 * n);
  Eigen::Map<Eigen::Matrix<double, M, 1>> local(local_out, 2 * n);
  const double rx = u[2 * node[0]], ry = u[2 * node[0] + 1];
  for (int k = 0; k < n; ++k) {
    w[2 * k] = u[2 * node[k]] - rx;
    w[2 * k + 1] = u[2 * node[k] + 1] - ry;
  }
  const CorotationalFrames::Turn turn = frames.local_displacements(c, n, w.data(), local.data());
  // Coefficient-based (lazyProduct): Eigen sends a product of this size to its general gemv
  // kernel, whose setup per call made the corotational force 15 % slower (BM_CorotationalForce).
  f_local.noalias() =
      Eigen::Map<const Eigen::Matrix<double, M, M>>(K, 2 * n, 2 * n).lazyProduct(local);
  equilibrate(n, f_local.data());
  frames.global_force(c, n, turn, local.data(), f_local.data(), f);
  equilibrate(n, f);
  return 0.5 * local.dot(f_local);
}

}  // namespace

InternalForce::InternalForce(const PolygonMesh& mesh, CellMatrices matrices, bool corotational)
    : offsets_(mesh.offsets()), K_(std::move(matrices)) {
  if (corotational) {
    frames_.emplace(mesh);
    local_.assign(2 * std::size_t(offsets_.back()), 0.0);
  }
  const int nc = mesh.num_cells();
  const bool whole = K_.first == 0 && static_cast<int>(K_.offset.size()) == nc + 1;
  if (!whole)
    throw InputError("internal force: cell matrices of cells [" + std::to_string(K_.first) + ", " +
                     std::to_string(K_.first + int(K_.offset.size()) - 1) + "), expected all " +
                     std::to_string(nc) + " cells");
  for (int c = 0; c < nc; ++c)
    if (K_.offset[c + 1] - K_.offset[c] != 4 * std::size_t(cell_size(c)) * cell_size(c))
      throw InputError("internal force: the matrix of cell " + std::to_string(c) +
                       " does not match its " + std::to_string(cell_size(c)) + " vertices");
  pair_force_.assign(2 * std::size_t(offsets_.back()), 0.0);
  cell_energy_.assign(nc, 0.0);
}

double InternalForce::compute(const SplitDofMap& dofs, const Eigen::VectorXd& u, Eigen::VectorXd& f,
                              int threads) {
  if (dofs.pair_nodes().size() != pair_force_.size() / 2)
    throw InputError("internal force: a DOF map of " + std::to_string(dofs.pair_nodes().size()) +
                     " pairs for a mesh of " + std::to_string(pair_force_.size() / 2));
  if (u.size() != dofs.num_dofs())
    throw InputError("internal force: " + std::to_string(u.size()) + " displacements for " +
                     std::to_string(dofs.num_nodes()) + " nodes");
  cell_forces(dofs.pair_nodes().data(), u.data(), threads);
  return reassemble(dofs, f, threads);
}

double InternalForce::reassemble(const SplitDofMap& dofs, Eigen::VectorXd& f, int threads) {
  const int nodes = dofs.num_nodes();
  f.resize(2 * nodes);
#pragma omp parallel for schedule(static, 1024) num_threads(std::max(threads, 1))
  for (int i = 0; i < nodes; ++i) gather_node(dofs, i, f.data());
  const auto energy = energy_sum_.sum<1>(num_cells(), threads,
                                         [&](int c, double* acc) { acc[0] += cell_energy_[c]; });
  return energy[0];
}

void InternalForce::reassemble_nodes(const SplitDofMap& dofs, std::span<const int> nodes,
                                     Eigen::VectorXd& f) const {
  for (int i : nodes) gather_node(dofs, i, f.data());
}

void InternalForce::cell_forces(const int* pair_node, const double* u, int threads) {
  const int nc = num_cells();
#pragma omp parallel for schedule(static, 512) num_threads(std::max(threads, 1))
  for (int c = 0; c < nc; ++c) {
    const double* K = K_.data.data() + K_.offset[c];
    const int* node = pair_node + offsets_[c];
    double* f = pair_force_.data() + 2 * std::size_t(offsets_[c]);
    double& e = cell_energy_[c];
    if (frames_) {
      double* local = local_.data() + 2 * std::size_t(offsets_[c]);
      switch (cell_size(c)) {
        // The sizes of the plain force's: the dynamic-size path allocates its three vectors
        // per cell and step (malloc and free were a third of the frames' time on rcp).
        case 3: e = corotational_force<3>(*frames_, c, K, node, u, f, local); break;
        case 4: e = corotational_force<4>(*frames_, c, K, node, u, f, local); break;
        case 5: e = corotational_force<5>(*frames_, c, K, node, u, f, local); break;
        case 6: e = corotational_force<6>(*frames_, c, K, node, u, f, local); break;
        case 7: e = corotational_force<7>(*frames_, c, K, node, u, f, local); break;
        case 8: e = corotational_force<8>(*frames_, c, K, node, u, f, local); break;
        case 9: e = corotational_force<9>(*frames_, c, K, node, u, f, local); break;
        case 10: e = corotational_force<10>(*frames_, c, K, node, u, f, local); break;
        default: e = corotational_force<0>(*frames_, c, K, node, u, f, local);
      }
      continue;
    }
    switch (cell_size(c)) {
      case 3: e = cell_force<3>(K, node, u, f); break;
      case 4: e = cell_force<4>(K, node, u, f); break;
      case 5: e = cell_force<5>(K, node, u, f); break;
      case 6: e = cell_force<6>(K, node, u, f); break;
      case 7: e = cell_force<7>(K, node, u, f); break;
      case 8: e = cell_force<8>(K, node, u, f); break;
      case 9: e = cell_force<9>(K, node, u, f); break;
      case 10: e = cell_force<10>(K, node, u, f); break;
      default: e = cell_force_any(cell_size(c), K, node, u, f);
    }
  }
}

void InternalForce::gather_node(const SplitDofMap& dofs, int i, double* f) const {
  double fx = 0.0, fy = 0.0;
  for (int p : dofs.node_pairs(i)) {
    fx += pair_force_[2 * std::size_t(p)];
    fy += pair_force_[2 * std::size_t(p) + 1];
  }
  f[2 * i] = fx;
  f[2 * i + 1] = fy;
}

void InternalForce::archive(StateArchive& a) {
  a.vector("force.pair_force", pair_force_);
  a.vector("force.cell_energy", cell_energy_);
  a.vector("force.local", local_);
}

}  // namespace vorodg
