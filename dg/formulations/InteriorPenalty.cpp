// dg-sipg: symmetric (s = -1, SIPG) or non-symmetric (s = +1, NIPG) interior penalty, one solve,
// as MFEM's ex17:
//   a(u, v) - int {sigma(u)} n.[v] + s int {sigma(v)} n.[u] + eps int [u].[v] = l(v).
// Symmetric interior penalty is coercive only above a mesh-dependent penalty, so its defaults
// are the coercive scaling (k_p = 1 is the proven bound) and each cell's fan stress, whose trace
// constant stays bounded at short edges.
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "dg/DgElasticity.hpp"
#include "dg/DgFormulation.hpp"

namespace vorodg {

namespace {

class InteriorPenalty final : public DgFormulation {
 public:
  explicit InteriorPenalty(int sign) : sign_(sign) {}

  PenaltyScaling default_scaling() const override { return PenaltyScaling::coercive; }
  TractionKind default_traction() const override { return TractionKind::fan; }
  bool symmetric() const override { return sign_ < 0; }
  void check_options(const DgOptions& options) const override {
    if (options.sipg_sign != -1 && options.sipg_sign != 1)
      throw InputError("dg-sipg sign " + std::to_string(options.sipg_sign) +
                       ": expected -1 (symmetric) or +1 (non-symmetric)");
  }

  /// -int {sigma(u)}n.[v] + s int {sigma(v)}n.[u], beside the penalty block.
  void add_interface_block(const DgTermContext& context, std::size_t i,
                           Eigen::MatrixXd& local) const override {
    const Eigen::MatrixXd JT = context.consistency_block(i);
    local += -JT + sign_ * JT.transpose();
  }

  // The large one-sided gradients of RK shape functions at short edges push the coercivity
  // threshold up, so a penalty that suits the other schemes may fall below it.
  std::optional<std::string> not_definite_hint(const DgOptions& options) const override {
    return "dg-sipg: the matrix is not positive definite at k_p = " +
           fmt(penalty_multiplier(options)) +
           ": the penalty is below the coercivity threshold of the interface terms on this mesh "
           "(use --penalty auto with --kp 1 or more, or raise --kp)";
  }

 private:
  int sign_;
};

}  // namespace

std::unique_ptr<DgFormulation> make_interior_penalty(const DgOptions& options) {
  return std::make_unique<InteriorPenalty>(options.sipg_sign);
}

}  // namespace vorodg
