#pragma once
// The penalty eps_F of every interface and the weights of the interface average {.}_w, in one
// object (docs/dg.md "Penalty"). Four scalings:
//   h-avg:    eps = k_p E / h_avg                        (the report's f(h) = 1/h, the default of
//   local-h:  eps = k_p E / h_F, h_F = (|K_1| + |K_2|) / (2 |F|)     the penalty-type schemes)
//   fixed-h:  eps = k_p E / H, H the domain's shorter side: a penalty that is not refined
//   coercive: eps = k_p eta_F from the cells' trace constants (TraceConstants), with
//             k_s = N_s C_{s,F} (N_s the interfaces of cell s) and
//               plain average:    w = (1/2, 1/2),               eta_F = k_1 + k_2
//               weighted average: w_s = k_other / (k_1 + k_2),  eta_F = 4 k_1 k_2 / (k_1 + k_2)
//             so that k_p > 1/2 makes the symmetric interior-penalty form coercive and k_p = 1
//             (the default) gives it the coercivity constant 1/2 in the DG energy norm.
#include <Eigen/Core>
#include <vector>

#include "interfaces/TraceConstants.hpp"

namespace vorodg {

enum class PenaltyScaling { h_avg, local_h, fixed_h, coercive };

class InterfacePenalty {
 public:
  /// `kind` says which traction the coercive constants bound; unused for the other scalings.
  /// `stiffness` holds every cell's matrix (the coercive scaling's constants need them).
  InterfacePenalty(const InterfaceOperators& ops, const ElasticityIntegrator& integrator,
                   const ElasticityIntegrator::CellMatrices& stiffness, PenaltyScaling scaling,
                   double kp, bool weighted_average, TractionKind kind, int threads);

  /// eps on interface i (the index into DgSpace::interfaces()).
  double eps(int i) const { return eps_[i]; }
  /// The weights (w_1, w_2) of the two cells' stresses in the interface average.
  const Eigen::Vector2d& weights(int i) const { return weights_[i]; }
  /// eps_F relative to E / h_avg, per interface: what the penalty study plots.
  std::vector<double> relative_to_h_avg() const;

 private:
  void set_coercive(const TraceConstants& constants, double kp, bool weighted_average);

  const ElasticityIntegrator& integrator_;
  const DgSpace& space_;
  std::vector<double> eps_;
  std::vector<Eigen::Vector2d> weights_;
};

}  // namespace vorodg
