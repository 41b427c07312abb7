// dg-al: the augmented Lagrangian of the report (Eqs. 24-26),
//   a(u, v) + int lambda.[v] + eps int [u].[v] = l(v),   lambda <- lambda + eps [u],
// with one multiplier per interface quadrature point (two-point Gauss, exact for the linear
// jumps). The multiplier term is lagged: it moves to the right side, so the matrix is that of
// the penalty scheme, factored once. With `al_update_kp` the update step is the report's k_p E
// (no 1 / h) instead of each interface's eps.
#include <vector>

#include "core/quadrature/TriangleRule.hpp"
#include "dg/DgElasticity.hpp"
#include "dg/DgFormulation.hpp"

namespace vorodg {

namespace {

class AugmentedLagrangian final : public DgFormulation {
 public:
  bool iterative() const override { return true; }

  void prepare(const DgTermContext& context) override {
    lambda_.assign(2 * context.space.interfaces().size(), Eigen::Vector2d::Zero());
  }

  /// lambda <- lambda + step [u] at each interface quadrature point.
  void update(const DgTermContext& context, const Eigen::VectorXd& u) override {
    const SegmentRule& rule = gauss2_segment();
    const auto& faces = context.space.interfaces();
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const std::vector<int> dofs = context.ops.dofs(faces[i]);
      Eigen::VectorXd uf(dofs.size());
      for (std::size_t k = 0; k < dofs.size(); ++k) uf[k] = u[dofs[k]];
      const double step = context.options.al_update_kp ? penalty_multiplier(context.options) *
                                                             context.integrator.material().E()
                                                       : context.penalty.eps(static_cast<int>(i));
      for (int q = 0; q < 2; ++q)
        lambda_[2 * i + q] += step * (context.ops.jump(faces[i], rule.t[q]) * uf);
    }
  }

  /// -int lambda.[v], on the interfaces' DOFs.
  Eigen::VectorXd interface_load(const DgTermContext& context,
                                 const Eigen::VectorXd&) const override {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(context.num_dofs());
    const SegmentRule& rule = gauss2_segment();
    const auto& faces = context.space.interfaces();
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const Interface& f = faces[i];
      const std::vector<int> dofs = context.ops.dofs(f);
      Eigen::VectorXd local = Eigen::VectorXd::Zero(dofs.size());
      for (int q = 0; q < 2; ++q)
        local -= rule.weights[q] * f.length * context.ops.jump(f, rule.t[q]).transpose() *
                 lambda_[2 * i + q];
      for (std::size_t k = 0; k < dofs.size(); ++k) g[dofs[k]] += local[k];
    }
    return g;
  }

 private:
  std::vector<Eigen::Vector2d> lambda_;  // per interface quadrature point
};

}  // namespace

std::unique_ptr<DgFormulation> make_augmented_lagrangian(const DgOptions&) {
  return std::make_unique<AugmentedLagrangian>();
}

}  // namespace vorodg
