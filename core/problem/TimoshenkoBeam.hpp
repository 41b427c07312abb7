#pragma once
// Timoshenko's cantilever (the report's beam-bending verification problem): domain
// [0, L] x [-D/2, D/2], end load P, I = D^3/12. The exact displacement is prescribed on x = 0,
// the exact (parabolic shear) traction on x = L; top and bottom are traction-free. In plane
// strain E and nu are replaced by E/(1-nu^2) and nu/(1-nu).
#include "core/problem/ExactSolution.hpp"

namespace vorodg {

class TimoshenkoBeam : public ExactSolution {
 public:
  TimoshenkoBeam(const IsotropicElasticity& material, double length, double depth, double load);

  std::string name() const override { return "beam"; }
  Eigen::Vector2d displacement(const Point& x) const override;
  Eigen::Matrix2d gradient(const Point& x) const override;
  std::array<Eigen::Matrix2d, 2> hessian(const Point& x) const override;
  /// The beam is in equilibrium without body force (exactly; -div sigma evaluates to ~1e-15).
  Eigen::Vector2d body_force(const Point&) const override { return Eigen::Vector2d::Zero(); }
  bool has_body_force() const override { return false; }

  /// The beam's domain, [0, L] x [-D/2, D/2].
  Rectangle domain() const { return {0.0, -depth_ / 2, length_, depth_ / 2}; }

 private:
  double length_, depth_, load_, inertia_;
  double E_, nu_;  // effective plane-stress constants
};

}  // namespace vorodg
