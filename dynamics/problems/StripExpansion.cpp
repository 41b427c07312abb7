// strip-expansion (fragmentation only): a thin strip stretched about its middle at a uniform
// strain rate, which cracks open into fragments (docs/fragmentation.md): the count and the sizes
// against the 1D theories.
#include "core/schema/SceneKeyReader.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

class StripExpansion : public DynamicsProblem {
 public:
  std::string name() const override { return "strip-expansion"; }
  std::vector<SceneKey> keys() const override {
    return {bounded("strain_rate", "number", "1e5", "0 < strain_rate <= 1e9",
                    "strip-expansion: the initial velocity is strain_rate (x - x_mid) along x, 1/s",
                    0.0, true, 1e9)};
  }
  bool needs_fragmentation() const override { return true; }
  Rectangle default_domain() const override { return Rectangle(0, 0, 0.002, 1e-5); }

  void read(SceneKeyReader& r, ExplicitParameters&) override {
    strain_rate_ = r.number(r.top(), "strain_rate");
  }

  void default_length(ExplicitParameters& s) const override {
    s.end = 20.0 * s.criterion.tensile_cutoff / (s.E * strain_rate_);
  }
  std::string default_length_doc() const override {
    return "20 x the time to reach the cutoff, sigma_o / (E strain_rate)";
  }

  /// Stretched about the middle: strain_rate (x - x_mid) along x.
  void add_initial_velocity(const DynamicsBody& b, const Eigen::Vector2d& x,
                            Eigen::Ref<Eigen::Vector2d> v) const override {
    v[0] += strain_rate_ * (x.x() - 0.5 * (b.domain.x0() + b.domain.x1()));
  }

 private:
  double strain_rate_ = 0.0;
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_strip_expansion() {
  return std::make_unique<StripExpansion>();
}

}  // namespace vorodg
