#include "interfaces/InterfacePenalty.hpp"

#include <algorithm>

#include "core/util/Errors.hpp"

namespace vorodg {

InterfacePenalty::InterfacePenalty(const InterfaceOperators& ops,
                                   const ElasticityIntegrator& integrator,
                                   const ElasticityIntegrator::CellMatrices& stiffness,
                                   PenaltyScaling scaling, double kp, bool weighted_average,
                                   TractionKind kind, int threads)
    : integrator_(integrator), space_(ops.space()) {
  const auto& faces = space_.interfaces();
  weights_.assign(faces.size(), InterfaceOperators::kPlainAverage);
  if (weighted_average && scaling != PenaltyScaling::coercive)
    throw InputError("weighted interface averages need the coercive penalty (penalty auto)");
  if (scaling == PenaltyScaling::coercive) {
    set_coercive(TraceConstants(ops, stiffness, kind, threads), kp, weighted_average);
    return;
  }
  const PolygonMesh& mesh = space_.mesh();
  const double E = integrator.material().E();
  const double fixed = std::min(mesh.domain().width(), mesh.domain().height());
  eps_.resize(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const double h = scaling == PenaltyScaling::local_h   ? faces[i].h_local
                     : scaling == PenaltyScaling::fixed_h ? fixed
                                                          : mesh.h_avg();
    eps_[i] = kp * E / h;  // eps = k_p E f(h), f(h) = 1/h
  }
}

void InterfacePenalty::set_coercive(const TraceConstants& constants, double kp,
                                    bool weighted_average) {
  const auto& faces = space_.interfaces();
  eps_.resize(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Interface& f = faces[i];
    double k[2];
    for (int s = 0; s < 2; ++s)
      k[s] = space_.interface_count(f.cell[s]) * constants.constant(f.cell[s], f.local_edge[s]);
    const double sum = k[0] + k[1];
    if (!(sum > 0.0))
      throw NumericalError("interface on edge " + std::to_string(f.edge) +
                           ": both cells' trace constants are zero");
    if (weighted_average) {
      // Weights that minimise sum_s w_s^2 k_s: the cell with the larger constant counts less.
      weights_[i] = Eigen::Vector2d(k[1] / sum, k[0] / sum);
      eps_[i] = kp * 4.0 * k[0] * k[1] / sum;
    } else {
      eps_[i] = kp * sum;
    }
  }
}

std::vector<double> InterfacePenalty::relative_to_h_avg() const {
  const double scale = integrator_.material().E() / space_.mesh().h_avg();
  std::vector<double> out(eps_.size());
  for (std::size_t i = 0; i < eps_.size(); ++i) out[i] = eps_[i] / scale;
  return out;
}

}  // namespace vorodg
