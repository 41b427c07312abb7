// The report's impact problems and the keys that come with them (verification/kinds/dynamics/
// problems/ColumnImpact and ProjectileImpact, docs/fragmentation.md "The impact problems"):
//   - column-impact's defaults: the 0.3 x 1.83 m column falling at 7.6 m/s under gravity onto a
//     plane through its bottom-left corner with normal [sin, cos] of the obliquity (45 degrees),
//     300 ms; another obliquity turns the normal;
//   - projectile-impact's defaults (the 4 x 0.3 m beam at rest, a 0.1 m nose at mid-span, 20 m/s,
//     3 ms), and one clear InputError for a nose off the beam, an obliquity at 90 degrees or in
//     another problem, projectile keys in another problem, and snapshot times out of order;
//   - a short projectile run: the projectile's work is its speed times the momentum it gave (so
//     every node it pushes moves at its speed), the energy balance closes to 1e-10 of the input
//     (the work the projectile does), momentum is not held to anything, and the snapshot frames are
//     written and listed;
//   - the quiescent displacement penalty: a column run records k_d = M g cos 45 / (x h_avg), M
//     the lumped mass (rho times the area to round-off), to 1e-12; without a wall, or without
//     gravity towards it, the key is refused;
//   - gravity on a free body: the momentum after n steps is M g t to 1e-12, and the balance
//     (gravity's work booked as external work) closes to 1e-10.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/util/Errors.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

std::string scene(const std::string& problem, const std::string& extra) {
  return R"({"study": "dynamics", "problem": ")" + problem +
         R"(", "material": {"E": 2.83e10, "nu": 0.2, "plane": "strain", "density": 2250},
    "outputs": {"vtu": false}, "meshes": [{"family": "rcp", "sizes": [0.1], "seed": 3}])" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

struct Scratch {
  fs::path dir;
  explicit Scratch(const std::string& name)
      : dir(fs::temp_directory_path() / ("vorodg_" + name + "_" + std::to_string(getpid()))) {
    fs::remove_all(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
};

/// The first or the last row of a history CSV as {column: value}.
std::map<std::string, double> history_row(const fs::path& file, bool first = false) {
  std::ifstream in(file);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line) && (last = line, !first)) {
  }
  std::map<std::string, double> row;
  std::stringstream h(header), v(last);
  std::string name, value;
  while (std::getline(h, name, ',') && std::getline(v, value, ','))
    row[name] = value.empty() ? NAN : std::stod(value);
  return row;
}

TEST(ImpactProblems, ColumnTakesTheReportsContactUnlessTheSceneSaysOtherwise) {
  const DynamicsScene s = parse_dynamics_scene(scene("column-impact", ""), "test");
  EXPECT_TRUE(s.penalty.plastic);
  EXPECT_EQ(s.quiescent_penetration, 0.1);
  EXPECT_EQ(s.contact_friction, 0.75);
  EXPECT_EQ(s.wall->friction, 0.75);
  EXPECT_EQ(s.bulk_viscosity.linear, 0.06);
  EXPECT_EQ(s.bulk_viscosity.quadratic, 1.2);
  // Damped contact instead of the plastic penalty; no resting weight, no displacement penalty.
  const DynamicsScene damped = parse_dynamics_scene(
      scene("column-impact", R"("contact": {"damping_ratio": 0.1}, "gravity": [0, 0])"), "test");
  EXPECT_FALSE(damped.penalty.plastic);
  EXPECT_EQ(damped.quiescent_penetration, 0.0);
  // Other problems keep the plain defaults.
  const DynamicsScene wall = parse_dynamics_scene(scene("wall-impact", ""), "test");
  EXPECT_FALSE(wall.penalty.plastic);
  EXPECT_EQ(wall.contact_friction, 0.0);
  EXPECT_EQ(wall.bulk_viscosity.linear, 0.0);
}

TEST(ImpactProblems, ColumnDefaults) {
  const DynamicsScene s = parse_dynamics_scene(scene("column-impact", ""), "test");
  const Rectangle& d = s.bodies[0].domain;
  EXPECT_EQ(d.x1(), 0.3);
  EXPECT_EQ(d.y1(), 1.83);
  EXPECT_EQ(s.bodies[0].velocity, Point(0, -7.6));
  EXPECT_EQ(s.gravity, Point(0, -9.81));
  ASSERT_TRUE(s.wall);
  EXPECT_EQ(s.wall->point, Point(0, 0));
  EXPECT_NEAR(s.wall->normal.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(s.wall->normal.y(), std::sqrt(0.5), 1e-15);
  EXPECT_EQ(s.end, 0.3);
  const DynamicsScene tilted =
      parse_dynamics_scene(scene("column-impact", R"("obliquity": 30)"), "test");
  EXPECT_NEAR(tilted.wall->normal.x(), 0.5, 1e-15);
  EXPECT_NEAR(tilted.wall->normal.y(), std::sqrt(3.0) / 2, 1e-15);
}

TEST(ImpactProblems, ProjectileDefaultsAndRefusals) {
  const DynamicsScene s = parse_dynamics_scene(scene("projectile-impact", ""), "test");
  EXPECT_EQ(s.problem->name(), "projectile-impact");
  EXPECT_EQ(s.setting("projectile.speed"), "20");
  EXPECT_EQ(s.setting("projectile.width"), "0.1");
  EXPECT_EQ(s.setting("projectile.position"), "2");
  EXPECT_EQ(s.bodies[0].velocity, Point(0, 0));
  EXPECT_EQ(s.end, 3e-3);
  EXPECT_FALSE(s.wall);
  for (const std::string& bad : {scene("projectile-impact", R"("projectile": {"position": 3.98})"),
                                 scene("projectile-impact", R"("projectile": {"speed": 0})"),
                                 scene("projectile-impact", R"("obliquity": 10)"),
                                 scene("column-impact", R"("obliquity": 90)"),
                                 scene("column-impact", R"("projectile": {"speed": 20})"),
                                 scene("column-impact", R"("outputs": {"snapshots": [0.2, 0.1]})")})
    EXPECT_THROW(parse_dynamics_scene(bad, "test"), InputError) << bad;
}

TEST(ImpactProblems, ProjectileDrivesTheNodesUnderItsNose) {
  const DynamicsScene s = parse_dynamics_scene(
      scene("projectile-impact",
            R"("domain": [0, 0, 1, 0.3], "projectile": {"width": 0.25, "speed": 5},
               "time": {"end": 2e-4}, "outputs": {"vtu": false, "snapshots": [0, 1e-4]})"),
      "test");
  const Scratch out("projectile");
  const EnsembleRunId id = ensemble_runs(s.meshes).front();
  const DynamicsRecord r = run_dynamics(s, id, out.dir);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_LT(r.measures.max_energy_balance_error, 1e-10);
  EXPECT_TRUE(std::isnan(r.measures.momentum_drift));
  const fs::path history = out.dir / "history" / (id.id() + ".csv");
  const auto start = history_row(history, true), row = history_row(history);
  // Only the projectile pushes the beam, with its nodes at -speed from t = 0: its work is -speed
  // times the momentum it gave since, and positive.
  const double given = row.at("momentum_y") - start.at("momentum_y");
  EXPECT_GT(row.at("reaction_work"), 0.0);
  EXPECT_NEAR(row.at("reaction_work"), -5.0 * given, 1e-9 * row.at("reaction_work"));
  std::ifstream list(out.dir / "snapshots" / (id.id() + ".csv"));
  std::string line;
  int rows = 0;
  std::getline(list, line);
  EXPECT_EQ(line, "snapshot,requested_time,time,step,file");
  while (std::getline(list, line)) {
    EXPECT_TRUE(fs::exists(out.dir / "vtu" / line.substr(line.rfind(',') + 1))) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 2);
}

TEST(ImpactProblems, GravityChangesMomentumByMgt) {
  const DynamicsScene s = parse_dynamics_scene(
      scene("free-body", R"("gravity": [0, -10], "angular_velocity": 0, "initial_velocity": [0, 0],
                           "time": {"steps": 50})"),
      "test");
  const Scratch out("gravity");
  const EnsembleRunId id = ensemble_runs(s.meshes).front();
  const DynamicsRecord r = run_dynamics(s, id, out.dir);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_LT(r.measures.max_energy_balance_error, 1e-10);
  const auto row = history_row(out.dir / "history" / (id.id() + ".csv"));
  const double mass = 2250.0 * 1.0 * 1.0;         // free-body's default domain, unit thickness
  const double scale = mass * 10.0 * r.end_time;  // the history holds 12 significant digits
  EXPECT_NEAR(row.at("momentum_y"), -mass * 10.0 * row.at("time"), 1e-10 * scale);
  EXPECT_NEAR(row.at("momentum_x"), 0.0, 1e-10 * scale);
  EXPECT_GT(row.at("external_work"), 0.0);
}

TEST(ImpactProblems, QuiescentPenaltyFollowsTheRestingWeight) {
  const DynamicsScene s = parse_dynamics_scene(
      scene("column-impact",
            R"("contact": {"quiescent_penetration": 0.1, "plastic": true}, "time": {"steps": 2})"),
      "test");
  Scratch out("quiescent");
  const DynamicsRecord r = run_dynamics(s, ensemble_runs(s.meshes).front(), out.dir);
  const double weight = 2250.0 * 0.3 * 1.83 * 9.81 * std::cos(std::numbers::pi / 4);
  EXPECT_NEAR(r.contact_stiffness, weight / (0.1 * r.h_avg), 1e-12 * weight / (0.1 * r.h_avg));
  const DynamicsScene plain = parse_dynamics_scene(
      scene("column-impact", R"("contact": {"quiescent_penetration": 0}, "time": {"steps": 2})"),
      "test");
  EXPECT_TRUE(std::isnan(
      run_dynamics(plain, ensemble_runs(plain.meshes).front(), out.dir).contact_stiffness));
  for (const std::string& bad :
       {scene("wall-impact", R"("contact": {"quiescent_penetration": 0.1})"),
        scene("column-impact", R"("contact": {"damping_ratio": 0.1, "plastic": true})"),
        scene("column-impact", R"("gravity": [0, 0], "contact": {"quiescent_penetration": 0.1})"),
        scene("column-impact", R"("contact": {"quiescent_penetration": -0.1})")})
    EXPECT_THROW(parse_dynamics_scene(bad, "test"), InputError) << bad;
}

TEST(ImpactProblems, AColumnRestingOnThePlaneSinksNoMoreThanTheTolerance) {
  // Set down on a level plane (at 1 cm/s) and left to rest under gravity for 0.3 s (1.5 periods
  // of the column on the displacement penalty at 0.1 h_avg, 4.8 at 0.01) with the
  // report's contact (the plastic velocity penalty and the quiescent displacement penalty).
  for (const double tolerance : {0.1, 0.01}) {
    const DynamicsScene s = parse_dynamics_scene(
        scene("column-impact",
              R"("obliquity": 0, "initial_velocity": [0, -0.01], "time": {"end": 0.3},
                 "bulk_viscosity": {"linear": 0, "quadratic": 0},
                 "contact": {"plastic": true, "quiescent_penetration": )" +
                  std::to_string(tolerance) + "}"),
        "test");
    Scratch out("resting");
    const DynamicsRecord r = run_dynamics(s, ensemble_runs(s.meshes).front(), out.dir);
    std::printf("resting column, tolerance %.2f h_avg: sank %.4f h_avg at most\n", tolerance,
                r.measures.max_penetration_over_h);
    EXPECT_TRUE(r.complete);
    EXPECT_GT(r.measures.max_penetration_over_h, 0.0);
    EXPECT_LE(r.measures.max_penetration_over_h, tolerance);
  }
}

}  // namespace
}  // namespace vorodg
