// The keys of the report's impact problems (docs/fragmentation.md, "The impact problems"): the
// column's plane tilt, the projectile, and gravity (any problem).
#include <cmath>
#include <numbers>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"
#include "verification/model/SettingsSchema.hpp"

namespace vorodg {

/// Standard gravity, m/s^2: the column falls under it.
constexpr double kGravity = 9.81;

void DynamicsSceneReader::read_impact() {
  const bool column = s_.problem == DynamicsProblem::column_impact;
  const bool projectile = s_.problem == DynamicsProblem::projectile_impact;
  s_.gravity = point(top_, "gravity", column ? Point(0, -kGravity) : Point(0, 0));
  refuse_unless(column, "obliquity");
  if (column) s_.obliquity = number(top_, "obliquity");
  refuse_unless(projectile, "projectile");
  if (!projectile) return;
  const Rectangle& beam = s_.bodies[0].domain;
  SceneObject o = object("projectile");
  DynamicsProjectile p;
  p.speed = number(o, "projectile.speed");
  p.width = number(o, "projectile.width");
  p.position = number(o, "projectile.position", 0.5 * (beam.x0() + beam.x1()));
  if (p.position - 0.5 * p.width < beam.x0() || p.position + 0.5 * p.width > beam.x1())
    o.fail_value("position", "the nose [" + exact_text(p.position - 0.5 * p.width) + ", " +
                                 exact_text(p.position + 0.5 * p.width) +
                                 "] leaves the top side [" + exact_text(beam.x0()) + ", " +
                                 exact_text(beam.x1()) + "]: expected it within");
  o.finish();
  s_.projectile = p;
}

DynamicsWall DynamicsSceneReader::column_wall() const {
  const double theta = s_.obliquity * std::numbers::pi / 180.0;
  return {s_.bodies[0].domain.lo(), Point(std::sin(theta), std::cos(theta))};
}

}  // namespace vorodg
