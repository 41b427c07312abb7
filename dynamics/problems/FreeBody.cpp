// free-body: a block thrown and spun with nothing acting on it. Measured: the drift of its
// momentum and of its angular momentum, which the central-difference map keeps to round-off.
#include "core/schema/SceneKeyReader.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

class FreeBody : public DynamicsProblem {
 public:
  std::string name() const override { return "free-body"; }
  Rectangle default_domain() const override { return Rectangle(0, 0, 1, 1); }
  Eigen::Vector2d default_velocity() const override { return {1.0, 0.5}; }
  double default_angular_velocity() const override { return 1.0; }
  void read(SceneKeyReader&, ExplicitParameters&) override {}
  void default_length(ExplicitParameters& s) const override { s.steps = 1000; }
  std::string default_length_doc() const override { return "1000 steps"; }
  bool measures_angular_momentum() const override { return true; }

  std::vector<ReportColumn> report_columns() const override {
    return {{"angular momentum drift",
             [](const DynamicsMeasures& m) { return measure_text(m.angular_momentum_drift, 2); }}};
  }
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_free_body() {
  return std::make_unique<FreeBody>();
}

}  // namespace vorodg
