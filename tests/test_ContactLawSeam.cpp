// A contact law added from outside the library, in this file alone, with one registration line:
// a rigid plane that pushes each vertex behind it with a linear spring k d, k = alpha m / dt^2,
// and nothing else (no damping, no friction): what the shipped "penalty-plane" does at its
// defaults, written again without PenaltyContact. A scene chooses it by `wall.law`, and it must
// run end to end as the shipped law does:
//   1. the registry knows it after the shipped laws, as an obstacle, and the dynamics scene reader
//      takes it as a wall's law (and refuses an unknown name with one line naming the key);
//   2. a block thrown at the wall with it rebounds as with "penalty-plane" at the same alpha: the
//      rebound speed, the contact time and the peak wall force agree to 1e-12 relative, and the
//      energy balance closes to 1e-10 of the input energy.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/util/Errors.hpp"
#include "dynamics/contact/ContactLaws.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

class SpringPlane final : public ContactLaw {
 public:
  SpringPlane(const Point& point, const Point& normal, double alpha)
      : point_(point), normal_(normal.normalized()), alpha_(alpha) {}

  bool external() const override { return true; }
  std::span<const int> touched() const override { return touched_; }
  /// How often any SpringPlane was evaluated: the run did use it.
  static inline long evaluations = 0;

  ContactReport add_forces(const SurfaceCells& surface, const PairState& state,
                           std::span<Point> force, std::span<Point>) override {
    ++evaluations;
    const PolygonMesh& mesh = surface.mesh();
    ContactReport report;
    touched_.clear();
    std::unordered_set<int> taken;  // each node once, on its first pair
    for (int c : surface.cells()) {
      ++report.candidates;
      for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p) {
        const double depth = -(state.position[p] - point_).dot(normal_);
        if (depth <= 0.0 || !taken.insert(state.node_of(p)).second) continue;
        const double k = alpha_ * state.mass[p] / (state.dt * state.dt);
        force[p] += (k * depth) * normal_;
        touched_.push_back(p);
        ++report.contacts;
        report.potential += 0.5 * k * depth * depth;
        report.max_depth = std::max(report.max_depth, depth);
      }
    }
    return report;
  }

 private:
  Point point_, normal_;
  double alpha_;
  std::vector<int> touched_;
};

// The one registration line.
const bool kRegistered = register_contact_law(
    {"spring-plane", "a rigid plane with a linear spring per vertex (a test's toy)", true,
     [](const ContactLawSettings& s) {
       return std::make_unique<SpringPlane>(s.point, s.normal, s.penalty.parameters().alpha);
     }});

std::string wall_impact(const std::string& law) {
  return R"({"study": "dynamics", "problem": "wall-impact", "domain": [0, 0, 0.4, 0.1],
    "initial_velocity": [1, 0], "wall": {"law": ")" +
         law + R"("}, "meshes": [{"family": "rcp", "sizes": [0.02], "seed": 2008}],
    "outputs": {"vtu": false}})";
}

class ContactLawSeam : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = fs::temp_directory_path() /
               ("vorodg_test_ContactLawSeam_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
    fs::remove_all(scratch_);
    fs::create_directories(scratch_);
  }
  void TearDown() override { fs::remove_all(scratch_); }

  DynamicsRecord run(const std::string& law) {
    const DynamicsScene scene = parse_dynamics_scene(wall_impact(law), "test scene");
    return run_dynamics(scene, ensemble_runs(scene.meshes).front(), scratch_ / law);
  }

  fs::path scratch_;
};

TEST_F(ContactLawSeam, ARegisteredLawIsKnownAndChosenByTheWallsLawKey) {
  ASSERT_TRUE(kRegistered);
  EXPECT_EQ(contact_laws().back().name, "spring-plane");
  EXPECT_TRUE(contact_laws().back().obstacle);
  const DynamicsScene scene = parse_dynamics_scene(wall_impact("spring-plane"), "test scene");
  ASSERT_TRUE(scene.wall.has_value());
  EXPECT_EQ(scene.wall->law, "spring-plane");
  EXPECT_EQ(scene.setting("wall.law"), "spring-plane");
  try {
    parse_dynamics_scene(wall_impact("no-such-law"), "test scene");
    FAIL() << "an unknown law was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wall.law"), std::string::npos) << e.what();
  }
}

TEST_F(ContactLawSeam, AToyLawRunsAWallImpactAsTheShippedPlaneDoes) {
  SpringPlane::evaluations = 0;
  const DynamicsRecord toy = run("spring-plane");
  EXPECT_EQ(SpringPlane::evaluations, toy.steps + 1);  // once per force evaluation
  const long toy_evaluations = SpringPlane::evaluations;
  const DynamicsRecord shipped = run("penalty-plane");
  EXPECT_EQ(SpringPlane::evaluations, toy_evaluations);  // the shipped run did not call it
  ASSERT_TRUE(toy.complete) << toy.failure;
  ASSERT_TRUE(shipped.complete) << shipped.failure;
  const DynamicsMeasures &a = toy.measures, &b = shipped.measures;
  std::printf(
      "wall impact, %d cells: rebound %.12f (rigid-plane %.12f), contact time %.6e "
      "(%.6e), peak force %.6e (%.6e), balance %.1e (%.1e), evaluations %ld\n",
      toy.cells, a.rebound_velocity, b.rebound_velocity, a.contact_time, b.contact_time,
      a.peak_wall_force, b.peak_wall_force, a.energy_balance_error, b.energy_balance_error,
      toy_evaluations);
  EXPECT_TRUE(a.contact_ended);
  EXPECT_NEAR(a.rebound_velocity, b.rebound_velocity, 1e-12 * b.rebound_velocity);
  EXPECT_NEAR(a.contact_time, b.contact_time, 1e-12 * b.contact_time);
  EXPECT_NEAR(a.peak_wall_force, b.peak_wall_force, 1e-12 * b.peak_wall_force);
  EXPECT_LT(std::abs(a.energy_balance_error), 1e-10);
}

}  // namespace
}  // namespace vorodg
