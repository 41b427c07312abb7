// projectile-impact: the report's beam struck on its top side by a rigid flat-nosed projectile
// of infinite mass moving down at constant speed: the vertical velocity of the top vertices
// under its nose is prescribed from t = 0 (bonded in the normal direction, free to slide).
#include <cmath>

#include "core/mesh/PolygonMesh.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

class ProjectileImpact : public DynamicsProblem {
 public:
  std::string name() const override { return "projectile-impact"; }
  std::vector<SceneKey> keys() const override {
    return {
        bounded("projectile.speed", "number", "20", "0 < speed <= 1e4",
                "projectile-impact: the rigid projectile's constant downward speed, m/s", 0.0, true,
                1e4),
        bounded("projectile.width", "number", "0.1", "0 < width <= 1e6",
                "projectile-impact: the width of its flat nose, m (the top vertices under it "
                "move down at its speed from t = 0, free to slide)",
                0.0, true, 1e6),
        bounded("projectile.position", "number", "the middle of the top side",
                "nose within the top", "projectile-impact: x of the nose's centre, m", -1e6, false,
                1e6),
    };
  }
  Rectangle default_domain() const override { return Rectangle(0, 0, 4.0, 0.3); }
  bool prescribes_velocity() const override { return true; }

  void read(SceneKeyReader& r, ExplicitParameters& s) override {
    const Rectangle& beam = s.bodies[0].domain;
    SceneObject o = r.object("projectile");
    speed_ = r.number(o, "projectile.speed");
    width_ = r.number(o, "projectile.width");
    position_ = r.number(o, "projectile.position", 0.5 * (beam.x0() + beam.x1()));
    if (position_ - 0.5 * width_ < beam.x0() || position_ + 0.5 * width_ > beam.x1())
      o.fail_value("position", "the nose [" + exact_text(position_ - 0.5 * width_) + ", " +
                                   exact_text(position_ + 0.5 * width_) +
                                   "] leaves the top side [" + exact_text(beam.x0()) + ", " +
                                   exact_text(beam.x1()) + "]: expected it within");
    o.finish();
  }

  void default_length(ExplicitParameters& s) const override { s.end = 3e-3; }
  std::string default_length_doc() const override { return "3e-3"; }

  /// The top vertices under the nose move down at the projectile's speed.
  void add_boundaries(const PolygonMesh& mesh, CentralDifference& run) const override {
    std::vector<int> under;
    for (int v : mesh.side_vertices(Side::top))
      if (std::abs(mesh.vertex(v).x() - position_) <= 0.5 * width_) under.push_back(v);
    if (under.empty())
      throw InputError("projectile: no vertex of the top side within its nose [" +
                       fmt(position_ - 0.5 * width_) + ", " + fmt(position_ + 0.5 * width_) +
                       "]: expected a nose wider than the cells");
    const double speed = speed_;
    run.add_velocity_boundary({under, 1, [speed](double) { return -speed; }});
  }

 private:
  double speed_ = 0.0;     // m/s, downwards
  double width_ = 0.0;     // of the nose, m
  double position_ = 0.0;  // x of the nose's centre, m
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_projectile_impact() {
  return std::make_unique<ProjectileImpact>();
}

}  // namespace vorodg
