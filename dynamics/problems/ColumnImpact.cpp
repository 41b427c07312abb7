// column-impact: the report's column falling under gravity onto an inclined rigid plane
// (docs/impact.md): the plane passes through the column's bottom-left corner, tilted by the
// obliquity. Measured: when the column's rear half first strikes the plane (the report: at
// about 200 ms, after the column has rotated about its struck corner).
#include <cmath>
#include <numbers>

#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Format.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

/// Standard gravity, m/s^2: the column falls under it.
constexpr double kGravity = 9.81;

/// The first time the plane pushes a vertex of the rear half: the (cell, vertex) pairs farther
/// from the struck corner than half the column's length, in the reference configuration.
class RearStrikeProbe : public ProblemProbe {
 public:
  RearStrikeProbe(const ExplicitParameters& physics, const BodiesMesh& bodies,
                  const CentralDifference& run)
      : run_(run) {
    const Rectangle& column = physics.bodies[0].domain;
    const double half = 0.5 * std::max(column.width(), column.height());
    const PolygonMesh& mesh = bodies.mesh;
    const std::vector<int>& loops = mesh.cell_vertex_list();
    rear_.assign(loops.size(), 0);
    for (std::size_t p = 0; p < loops.size(); ++p)
      rear_[p] = (mesh.vertex(loops[p]) - physics.wall->point).norm() > half;
  }

  /// Only the pairs contact pushed can carry a plane force: a scan of every rear pair each step
  /// was 1.4 % of a column run.
  void observe(DynamicsMeasures& m) override {
    if (!std::isnan(m.rear_strike_time) || !run_.contact()) return;
    const auto force = run_.contact()->plane_pair_forces();
    for (int p : run_.contact()->pushed_pairs())
      if (rear_[p] && force[p] != Point::Zero()) {
        m.rear_strike_time = run_.time();
        return;
      }
  }

 private:
  const CentralDifference& run_;
  std::vector<char> rear_;  // per (cell, vertex) pair: in the rear half
};

class ColumnImpact : public DynamicsProblem {
 public:
  std::string name() const override { return "column-impact"; }
  std::vector<SceneKey> keys() const override {
    return {bounded("obliquity", "number", "45", "0 <= obliquity < 90",
                    "column-impact: the tilt of the plane the column falls on, degrees (the plane "
                    "passes through the column's bottom-left corner, its normal [sin, cos] of the "
                    "tilt)",
                    0.0, false, 90.0, true)};
  }
  Rectangle default_domain() const override { return Rectangle(0, 0, 0.3, 1.83); }
  Eigen::Vector2d default_velocity() const override { return {0.0, -7.6}; }
  Eigen::Vector2d default_gravity() const override { return {0.0, -kGravity}; }
  bool hits_wall() const override { return true; }

  void read(SceneKeyReader& r, ExplicitParameters&) override {
    obliquity_ = r.number(r.top(), "obliquity");
  }

  /// The plane through the column's bottom-left corner, its normal [sin, cos] of the tilt.
  DynamicsWall default_wall(const ExplicitParameters& s) const override {
    const double theta = obliquity_ * std::numbers::pi / 180.0;
    return {s.bodies[0].domain.lo(), Point(std::sin(theta), std::cos(theta))};
  }

  std::unique_ptr<ProblemProbe> probe(const ExplicitParameters& physics, const BodiesMesh& bodies,
                                      const CentralDifference& run, int,
                                      DynamicsMeasures&) const override {
    return std::make_unique<RearStrikeProbe>(physics, bodies, run);
  }

  std::vector<ReportColumn> report_columns() const override {
    std::vector<ReportColumn> columns = DynamicsProblem::report_columns();
    columns.push_back({"rear strike [s]", [](const DynamicsMeasures& m) {
                         return std::isnan(m.rear_strike_time) ? std::string("none")
                                                               : fmt(m.rear_strike_time, 3);
                       }});
    return columns;
  }

  /// The report's contact (section 4): the plastic velocity penalty, and a displacement penalty
  /// that holds the resting column within a tenth of a cell. Coulomb friction 0.75 between
  /// fragments and on the plane: the report gives none, and every surface here is the concrete's
  /// own, whose internal friction it gives as 0.75. Bulk viscosity as explicit codes apply it by
  /// default (Abaqus/Explicit, LS-DYNA, the report's own code family). docs/impact.md measures
  /// each against its absence.
  ContactDefaults default_contact() const override { return {true, 0.1, 0.75, 0.75, 0.06, 1.2}; }

  void default_length(ExplicitParameters& s) const override { s.end = 0.3; }
  std::string default_length_doc() const override { return "0.3"; }

 private:
  double obliquity_ = 0.0;  // degrees
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_column_impact() {
  return std::make_unique<ColumnImpact>();
}

}  // namespace vorodg
