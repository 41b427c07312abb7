// wall-impact: a block thrown at a fixed rigid wall. Measured against the 1D elastic bar: the
// rebound speed (equal to the impact speed) and the contact time 2 L / c_bar, L the block's
// extent along the wall's normal.
#include <algorithm>

#include "core/schema/SceneKeyReader.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

class WallImpact : public DynamicsProblem {
 public:
  std::string name() const override { return "wall-impact"; }
  Rectangle default_domain() const override { return Rectangle(0, 0, 0.4, 0.1); }
  Eigen::Vector2d default_velocity() const override { return {1.0, 0.0}; }
  void read(SceneKeyReader&, ExplicitParameters&) override {}
  bool hits_wall() const override { return true; }

  void default_length(ExplicitParameters& s) const override {
    const Rectangle& body = s.bodies[0].domain;
    const Point n = s.wall->normal;
    double gap = 1e300;  // from the leading corner to the wall, at the approach speed
    for (const Point& c : corners(body)) gap = std::min(gap, (c - s.wall->point).dot(n));
    s.end = gap / -s.bodies[0].velocity.dot(n) + 3.0 * 2.0 * extent(body, n) / s.bar_speed();
  }
  std::string default_length_doc() const override {
    return "the flight to contact plus 3 x 2 L / c_bar (L: the extent along the wall's normal)";
  }
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_wall_impact() {
  return std::make_unique<WallImpact>();
}

}  // namespace vorodg
