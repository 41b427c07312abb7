// projectile-impact: the report's beam struck on its top side by a rigid flat-nosed projectile
// of infinite mass moving down at constant speed: the vertical velocity of the top vertices
// under its nose is prescribed from t = 0 (bonded in the normal direction, free to slide).
#include <cmath>

#include "core/mesh/PolygonMesh.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"
#include "verification/kinds/dynamics/problems/DynamicsProblem.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace vorodg {
namespace {

class ProjectileImpact : public DynamicsProblem {
 public:
  std::string name() const override { return "projectile-impact"; }
  std::vector<std::string> own_keys() const override { return {"projectile"}; }
  Rectangle default_domain() const override { return Rectangle(0, 0, 4.0, 0.3); }
  bool prescribes_velocity() const override { return true; }

  void read(DynamicsSceneReader& r, DynamicsScene& s) override {
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

  void default_length(DynamicsScene& s) const override { s.end = 3e-3; }
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
