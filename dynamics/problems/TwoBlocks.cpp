// two-blocks: two blocks thrown at each other (by default head on at equal and opposite speeds).
// Measured: the contact time against 2 L / c_bar of the shorter block along their relative
// velocity, and the momentum, which contact between the bodies keeps.
#include <algorithm>
#include <cmath>

#include "core/schema/SceneKeyReader.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

class TwoBlocks : public DynamicsProblem {
 public:
  std::string name() const override { return "two-blocks"; }
  std::vector<SceneKey> keys() const override {
    return {
        key("second_block.domain", "[x0, y0, x1, y1]", "domain moved right by 1.05 times its width",
            "x0 < x1, y0 < y1, apart from domain",
            "two-blocks: the second body (family file: the same size as domain)"),
        bounded("second_block.initial_velocity", "[vx, vy]", "minus initial_velocity",
                "each |component| <= 1e4", "two-blocks: the second body's velocity, m/s", -1e4,
                false, 1e4),
        bounded("second_block.angular_velocity", "number", "0", "|omega| <= 1e6",
                "two-blocks: the second body's spin, rad/s", -1e6, false, 1e6),
    };
  }
  Rectangle default_domain() const override { return Rectangle(0, 0, 0.2, 0.1); }
  Eigen::Vector2d default_velocity() const override { return {1.0, 0.0}; }

  /// The second block: by default the first moved right by 1.05 of its width, thrown back.
  void read(SceneKeyReader& r, ExplicitParameters& s) override {
    const DynamicsBody& a = s.bodies[0];
    SceneObject o = r.object("second_block");
    const double shift = 1.05 * a.domain.width();
    DynamicsBody b;
    b.domain = r.rectangle(
        o, "second_block.domain",
        Rectangle(a.domain.x0() + shift, a.domain.y0(), a.domain.x1() + shift, a.domain.y1()));
    b.velocity = r.point(o, "second_block.initial_velocity", -a.velocity);
    b.angular_velocity = r.number(o, "second_block.angular_velocity");
    const bool apart = b.domain.x0() >= a.domain.x1() || a.domain.x0() >= b.domain.x1() ||
                       b.domain.y0() >= a.domain.y1() || a.domain.y0() >= b.domain.y1();
    if (!apart)
      o.fail_value("domain", rect_text(b.domain) + " overlaps domain " + rect_text(a.domain) +
                                 ": expected the blocks apart (touching at most)");
    o.finish();
    s.bodies.push_back(b);
  }

  void default_length(ExplicitParameters& s) const override {
    const DynamicsBody &a = s.bodies[0], &b = s.bodies[1];
    const Rectangle &d = a.domain, &e = b.domain;
    const double gap = std::hypot(std::max({0.0, e.x0() - d.x1(), d.x0() - e.x1()}),
                                  std::max({0.0, e.y0() - d.y1(), d.y0() - e.y1()}));
    const double speed = (a.velocity - b.velocity).norm();
    s.end =
        (speed > 0.0 ? gap / speed : 0.0) + 6.0 * std::max(d.scale(), e.scale()) / s.bar_speed();
  }
  std::string default_length_doc() const override {
    return "the flight to contact plus 3 x 2 L / c_bar (L: the longer side of either block)";
  }

  std::unique_ptr<ProblemProbe> probe(const ExplicitParameters& s, const BodiesMesh&,
                                      const CentralDifference&, int,
                                      DynamicsMeasures& m) const override {
    if (s.wall) return nullptr;  // a wall's estimate stands
    const Point relative = s.bodies[0].velocity - s.bodies[1].velocity;
    const Point d = relative.norm() > 0.0 ? Point(relative.normalized()) : Point(1.0, 0.0);
    const double shorter = std::min(extent(s.bodies[0].domain, d), extent(s.bodies[1].domain, d));
    m.contact_time_estimate = 2.0 * shorter / s.bar_speed();
    return nullptr;
  }
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_two_blocks() {
  return std::make_unique<TwoBlocks>();
}

}  // namespace vorodg
