#include "dynamics/BulkViscosity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

BulkViscosity::BulkViscosity(const PolygonMesh& mesh, const BulkViscosityParameters& parameters,
                             double density, std::vector<double> wave_speeds)
    : gradient_(mesh),
      parameters_(parameters),
      density_(density),
      speed_(std::move(wave_speeds)),
      length_(mesh.num_cells()),
      offsets_(mesh.offsets()),
      pair_force_(2 * std::size_t(offsets_.back()), 0.0),
      rate_(mesh.num_cells(), 0.0),
      xi_(mesh.num_cells(), 0.0),
      cofactor_(4 * std::size_t(mesh.num_cells()), 0.0) {
  require_parameter(parameters.linear >= 0.0, "bulk viscosity linear", parameters.linear, ">= 0");
  require_parameter(parameters.quadratic >= 0.0, "bulk viscosity quadratic", parameters.quadratic,
                    ">= 0");
  require_parameter(density > 0.0, "bulk viscosity density", density, "> 0");
  if (static_cast<int>(speed_.size()) != mesh.num_cells())
    throw InputError("bulk viscosity: " + std::to_string(speed_.size()) + " wave speeds for " +
                     std::to_string(mesh.num_cells()) + " cells");
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!(speed_[c] > 0.0) || !std::isfinite(speed_[c]))
      throw InputError("bulk viscosity: cell " + std::to_string(c) + ": wave speed " +
                       fmt(speed_[c]) + ", expected > 0");
    length_[c] = std::sqrt(gradient_.area(c));
  }
}

double BulkViscosity::step_factor(double xi) {
  return std::sqrt(1.0 + xi * xi) - xi;
}

double BulkViscosity::allowed_damping_ratio(double ratio) {
  if (ratio >= 1.0) return std::numeric_limits<double>::infinity();
  return (1.0 - ratio * ratio) / (2.0 * ratio);
}

void BulkViscosity::set_step_ratio(double ratio) {
  require_parameter(ratio > 0.0, "bulk viscosity step ratio", ratio, "> 0");
  step_ratio_ = ratio;
  allowed_xi_ = allowed_damping_ratio(ratio);
}

double BulkViscosity::damping_ratio(int c, double rate) const {
  const double b2 = parameters_.quadratic;
  return parameters_.linear - b2 * b2 * (length_[c] / speed_[c]) * std::min(0.0, rate);
}

double BulkViscosity::pressure(int c, double rate) const {
  return pressure(c, rate, damping_ratio(c, rate));
}

void BulkViscosity::cell_rate(int c, const int* node, const double* v, const double* u) {
  // Velocities (and displacements) relative to vertex 0 (sum_k b_k = 0, so the same gradient): a
  // translating cell has exactly zero rate, whatever its speed. Read straight from the node
  // arrays: the gathered copies in per-thread buffers were most of this term's cost.
  const Eigen::Matrix2d gv = gradient_.gradient_at_nodes(c, node, v);
  // The cofactor of F maps b_k to the current configuration's weights (the identity at rest).
  Eigen::Map<Eigen::Matrix2d> cofactor(cofactor_.data() + 4 * std::size_t(c));
  cofactor.setIdentity();
  double rate = gv(0, 0) + gv(1, 1);
  if (u) {
    const Eigen::Matrix2d F = Eigen::Matrix2d::Identity() + gradient_.gradient_at_nodes(c, node, u);
    cofactor << F(1, 1), -F(1, 0), -F(0, 1), F(0, 0);
    rate = cofactor.cwiseProduct(gv).sum() / F.determinant();
  }
  rate_[c] = rate;
}

void BulkViscosity::cell_force(int c, bool current) {
  const int n = gradient_.cell_size(c);
  const double* b = gradient_.weights(c);
  const Eigen::Map<const Eigen::Matrix2d> cofactor(cofactor_.data() + 4 * std::size_t(c));
  xi_[c] = damping_ratio(c, rate_[c]);  // kept: check() no longer computes it again
  const double qa = pressure(c, rate_[c], xi_[c]) * gradient_.area(c);
  double* f = pair_force_.data() + 2 * std::size_t(offsets_[c]);
  // f_k = -q A cof(F) b_k; the last vertex takes minus the sum of the others, so that round-off
  // moves no momentum (as InternalForce does).
  double sx = 0.0, sy = 0.0;
  for (int k = 0; k < n - 1; ++k) {
    const Eigen::Vector2d bk =
        current ? Eigen::Vector2d(cofactor * Eigen::Vector2d(b[2 * k], b[2 * k + 1]))
                : Eigen::Vector2d(b[2 * k], b[2 * k + 1]);
    f[2 * k] = -qa * bk.x(), f[2 * k + 1] = -qa * bk.y();
    sx += f[2 * k], sy += f[2 * k + 1];
  }
  f[2 * n - 2] = -sx, f[2 * n - 1] = -sy;
}

void BulkViscosity::compute(const SplitDofMap& dofs, const Eigen::VectorXd& v, Eigen::VectorXd& f,
                            int threads, const Eigen::VectorXd* u) {
  if (current_ && (!u || u->size() != v.size()))
    throw InputError("bulk viscosity: the current configuration needs the node displacements");
  if (dofs.pair_nodes().size() != pair_force_.size() / 2 || v.size() != dofs.num_dofs())
    throw InputError("bulk viscosity: a DOF map of " + std::to_string(dofs.pair_nodes().size()) +
                     " pairs and " + std::to_string(v.size()) + " velocities for a mesh of " +
                     std::to_string(pair_force_.size() / 2) + " pairs");
  const int nc = gradient_.num_cells(), nodes = dofs.num_nodes();
  const int* pair_node = dofs.pair_nodes().data();
  // Rates first, then forces: two short loops let the processor overlap neighbouring cells'
  // long chains of dependent arithmetic (the gradients' sums, the division, the pressure), which
  // one loop doing both serialized.
#pragma omp parallel for schedule(static, 512) num_threads(std::max(threads, 1))
  for (int c = 0; c < nc; ++c)
    cell_rate(c, pair_node + offsets_[c], v.data(), current_ ? u->data() : nullptr);
#pragma omp parallel for schedule(static, 512) num_threads(std::max(threads, 1))
  for (int c = 0; c < nc; ++c) cell_force(c, current_);
  f.resize(2 * nodes);
#pragma omp parallel for schedule(static, 1024) num_threads(std::max(threads, 1))
  for (int i = 0; i < nodes; ++i) {
    double fx = 0.0, fy = 0.0;
    for (int p : dofs.node_pairs(i)) {
      fx += pair_force_[2 * std::size_t(p)];
      fy += pair_force_[2 * std::size_t(p) + 1];
    }
    f[2 * i] = fx, f[2 * i + 1] = fy;
  }
  check();
}

void BulkViscosity::check() {
  // The first cell with the largest xi: the same cell for any thread count.
  int worst = 0;
  max_xi_ = 0.0;
  for (int c = 0; c < gradient_.num_cells(); ++c)
    if (xi_[c] > max_xi_) max_xi_ = xi_[c], worst = c;
  if (step_ratio_ > 0.0 && max_xi_ > allowed_xi_)
    throw NumericalError(
        "bulk viscosity: cell " + std::to_string(worst) + " changes volume at the rate " +
        fmt(rate_[worst], 4) + " 1/s: its damping ratio xi = " + fmt(max_xi_, 4) + " (linear " +
        fmt(parameters_.linear, 4) + ") is above " + fmt(allowed_xi_, 4) +
        ", the most that dt = " + fmt(step_ratio_, 4) +
        " x the critical step allows (dt <= 2 / omega (sqrt(1 + xi^2) - xi)); lower "
        "bulk_viscosity.quadratic or time.safety");
}

void BulkViscosity::archive(StateArchive& a) {
  a.vector("bulk.pair_force", pair_force_);
  a.vector("bulk.rate", rate_);
  a.vector("bulk.xi", xi_);
  a.vector("bulk.cofactor", cofactor_);
  a.value("bulk.max_xi", max_xi_);
}

}  // namespace vorodg
