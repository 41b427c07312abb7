#pragma once
// Bulk (artificial) viscosity, linear and quadratic in the volumetric strain rate, as explicit
// codes use it (Abaqus/Explicit, LS-DYNA; their defaults b1 = 0.06, b2 = 1.2) to damp the
// ringing of the highest frequencies behind a steep front. Per cell c, with L = sqrt(A_c), the
// dilatational speed c_d and the volumetric strain rate eps = tr of the mean velocity gradient
// (MeanGradient, the same operator CorotationalFrames turns cells with):
//     xi = b1 - b2^2 (L / c_d) min(0, eps)        (the fraction of critical damping of the
//                                                  cell's highest, dilatational mode)
//     q  = xi rho c_d L eps = b1 rho c_d L eps - rho (b2 L)^2 eps min(0, eps)
// a pressure-like stress q I added to the cell's stress: linear in eps always, quadratic only in
// compression, and of the sign of eps, so that it always resists the change of volume. (The
// quadratic term is written with a minus: rho (b2 L)^2 eps min(0, eps) is eps^2 > 0 in
// compression, a tension that would help the compression along.)
//
// Its nodal force is the exact virtual work of q I on the cell's mean velocity gradient:
// f_k = -q A b_k, so that v.f = -q A eps <= 0 (it only ever takes energy out, at the rate
// xi rho c_d L A eps^2). Only cells carry it: cohesive faces and contact have their own laws
// (and damping), and a crack opening is no change of volume of the material.
//
// Stability: with the force taken from the half-step velocities (CentralDifference), a damping
// ratio xi of the highest mode lowers the critical step to (2 / omega_max)(sqrt(1 + xi^2) - xi)
// (the Abaqus/Explicit manual's formula). The linear term's share is known at setup (xi = b1:
// the caller takes step_factor(b1) off the step); the quadratic term's grows with the
// compression rate, so compute() checks every step that no cell's xi passes what the chosen
// step allows and throws NumericalError if one does (docs/dynamics.md, "Bulk viscosity").
//
// Finite rotations (set_current_configuration, for corotational kinematics): the rate is then
// that of the current volume, eps = dJ/dt / J with J = det F, F = I + G(u) the cell's mean
// deformation gradient, and the force the virtual work of q on the current area A J:
// f_k = -q A cof(F) b_k (cof(F) = J F^-T), so that v.f = -q A dJ/dt. A spinning cell keeps its
// volume, and so reads no rate however far it has turned; with F = I it is the above.
//
// Determinism: each cell writes its force into its own (cell, vertex) pair slots and its rate
// into its own cell slot; each node adds its pairs in pair order (InternalForce's pattern).
#include <Eigen/Core>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/MeanGradient.hpp"

namespace vorodg {

class StateArchive;

struct BulkViscosityParameters {
  double linear = 0.0;     // b1
  double quadratic = 0.0;  // b2
  bool active() const { return linear > 0.0 || quadratic > 0.0; }
};

class BulkViscosity {
 public:
  /// `wave_speeds`: the dilatational speed c_d of each cell of `mesh`. Throws InputError unless
  /// b1, b2 >= 0, density > 0 and every speed > 0.
  BulkViscosity(const PolygonMesh& mesh, const BulkViscosityParameters& parameters, double density,
                std::vector<double> wave_speeds);

  /// sqrt(1 + xi^2) - xi: what a damping ratio xi of the highest mode leaves of the critical
  /// step.
  static double step_factor(double xi);
  /// The largest xi that a step of `ratio` times the undamped critical step stays stable with
  /// (step_factor's inverse, (1 - r^2) / (2 r)); infinite for ratio >= 1 (--force: no check).
  static double allowed_damping_ratio(double ratio);
  /// dt over the undamped critical step: compute() then throws once a cell's xi passes
  /// allowed_damping_ratio(ratio). Without it nothing is checked.
  void set_step_ratio(double ratio);

  /// xi and q of cell c at volumetric strain rate `rate`.
  double damping_ratio(int c, double rate) const;
  double pressure(int c, double rate) const;

  /// The rate of the current volume (the cell's mean deformation gradient from the node
  /// displacements given to compute), for cells that may turn far (corotational kinematics).
  void set_current_configuration(bool on) { current_ = on; }
  bool current_configuration() const { return current_; }

  /// The nodal forces at node velocities v of `dofs` (f resized); keeps each cell's rate. With
  /// the current configuration, `u` holds the node displacements (ignored otherwise).
  /// Throws NumericalError naming the cell if its xi passes what the step ratio allows.
  void compute(const SplitDofMap& dofs, const Eigen::VectorXd& v, Eigen::VectorXd& f, int threads,
               const Eigen::VectorXd* u = nullptr);

  const BulkViscosityParameters& parameters() const { return parameters_; }
  const MeanGradient& gradient() const { return gradient_; }
  /// From the last compute: cell c's volumetric strain rate, and the largest xi of any cell.
  double cell_rate(int c) const { return rate_[c]; }
  double max_damping_ratio() const { return max_xi_; }

  /// Saves or loads what a step leaves for the next (a checkpoint).
  void archive(StateArchive& a);

 private:
  /// Cell c's volumetric rate and cofactor of F (the identity without `u`), kept.
  void cell_rate(int c, const int* node, const double* v, const double* u);
  /// Cell c's pair forces from its kept rate and cofactor; keeps its xi for check().
  void cell_force(int c, bool current);
  /// q of cell c at `rate` whose damping ratio is xi (pressure's formula, xi computed once).
  double pressure(int c, double rate, double xi) const {
    return xi * density_ * speed_[c] * length_[c] * rate;
  }
  /// The largest xi of the last compute; throws if it passes the allowed one.
  void check();

  MeanGradient gradient_;
  bool current_ = false;
  BulkViscosityParameters parameters_;
  double density_;
  std::vector<double> speed_, length_;  // per cell: c_d and L = sqrt(A)
  std::vector<int> offsets_;
  std::vector<double> pair_force_, rate_;
  std::vector<double> xi_;        // per cell: its damping ratio at the last compute
  std::vector<double> cofactor_;  // per cell: cof(F), 2 x 2 column-major
  double step_ratio_ = 0.0, allowed_xi_ = 0.0, max_xi_ = 0.0;
};

}  // namespace vorodg
