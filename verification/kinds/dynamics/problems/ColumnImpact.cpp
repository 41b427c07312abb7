// column-impact: the report's column falling under gravity onto an inclined rigid plane
// (docs/impact.md): the plane passes through the column's bottom-left corner, tilted by the
// obliquity.
#include <cmath>
#include <numbers>

#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"
#include "verification/kinds/dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

/// Standard gravity, m/s^2: the column falls under it.
constexpr double kGravity = 9.81;

class ColumnImpact : public DynamicsProblem {
 public:
  std::string name() const override { return "column-impact"; }
  std::vector<std::string> own_keys() const override { return {"obliquity"}; }
  Rectangle default_domain() const override { return Rectangle(0, 0, 0.3, 1.83); }
  Eigen::Vector2d default_velocity() const override { return {0.0, -7.6}; }
  Eigen::Vector2d default_gravity() const override { return {0.0, -kGravity}; }
  bool hits_wall() const override { return true; }

  void read(DynamicsSceneReader& r, DynamicsScene&) override {
    obliquity_ = r.number(r.top(), "obliquity");
  }

  /// The plane through the column's bottom-left corner, its normal [sin, cos] of the tilt.
  DynamicsWall default_wall(const DynamicsScene& s) const override {
    const double theta = obliquity_ * std::numbers::pi / 180.0;
    return {s.bodies[0].domain.lo(), Point(std::sin(theta), std::cos(theta))};
  }

  void default_length(DynamicsScene& s) const override { s.end = 0.3; }
  std::string default_length_doc() const override { return "0.3"; }

 private:
  double obliquity_ = 0.0;  // degrees
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_column_impact() {
  return std::make_unique<ColumnImpact>();
}

}  // namespace vorodg
