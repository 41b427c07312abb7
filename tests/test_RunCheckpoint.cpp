// Checkpoint and restart of explicit runs (ExplicitSimulation::archive, verification's
// RunCheckpoints, docs/checkpoints.md):
//   - a simulation loaded from another's state after n steps continues bit for bit as the one
//     that never stopped: displacements, velocities, the record with every energy account, the
//     crack pattern and the DOF map, on the column (fragmentation, exact contact, bulk
//     viscosity, cracks released to surface contact), on it with the report's penalty laws, with
//     interfaces coupled from the start (dg) and on the notched three-point bend (cohesive line,
//     load-CMOD probe), each stopped at several steps;
//   - a run asked to stop writes its checkpoint and throws Interrupted naming the run and the step;
//     rerun, it resumes there; after several stops its history, records and every other file are
//     byte for byte those of the run that never stopped (its times aside), and the checkpoints
//     are gone once it finishes;
//   - a refused checkpoint (corrupt) falls back to the one before; with none left, the run starts
//     from t = 0 and still ends the same;
//   - the quasi-static path of tpb-case1 (cmod control, coarsest mesh, a short path) stopped
//     after three of its steps and resumed each time ends with the record, curve, crack faces
//     and frames of the path that never stopped.
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "core/io/AtomicFile.hpp"
#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"
#include "core/util/StopRequest.hpp"
#include "dynamics/ExplicitSimulation.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"
#include "verification/kinds/fracture/FractureRun.hpp"
#include "verification/kinds/fracture/FractureScene.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

const std::string kColumn = R"({"study": "fragmentation", "problem": "column-impact",
  "material": {"E": 2.83e10, "nu": 0.2, "plane": "strain", "density": 2250},
  "cohesive": {"law": "linear", "strength": 3.7e6, "fracture_energy": 57},
  "criterion": {"cohesion": 3.7e6, "friction": 0.75, "tensile_cutoff": 3.7e6},
  "time": {"end": 0.004, "output_every": 200, "history_every": 10},
  "outputs": {"vtu": true, "snapshots": [0.001, 0.003]},
  "meshes": [{"family": "rcp", "sizes": [0.08], "seed": 2008}])";

const std::string kPenaltyLaws =
    R"(, "wall": {"law": "penalty-plane"}, "contact": {"law": "penalty-cell-pairs"})";
const std::string kCoupled = R"(, "kinematics": "small", "interfaces": "dg")";

const std::string kBend = R"({"study": "fragmentation", "problem": "three-point-bend",
  "domain": [0, 0, 2.0, 0.2], "notch_depth": 0.1,
  "material": {"E": 30e9, "nu": 0.2, "plane": "stress", "thickness": 0.05, "density": 2400},
  "cohesive": {"law": "linear", "strength": 3.33e6, "fracture_energy": 124},
  "criterion": {"friction": 0.75}, "cracking": {"mode": "pre-inserted"},
  "rate": {"speed": 0.5, "rise": 0.001, "max_displacement": 2e-4}, "kinematics": "small",
  "contact": {"enabled": false}, "time": {"output_every": 100}, "outputs": {"vtu": false},
  "meshes": [{"family": "rcp", "symmetric": true, "sizes": [0.04], "seed": 2008}]})";

DynamicsScene scene_of(const std::string& text) {
  return parse_dynamics_scene(text, "test");
}

/// Whether two simulations are in the same state, bit for bit.
void expect_same_state(const ExplicitSimulation& a, const ExplicitSimulation& b) {
  const CentralDifference &ra = *a.run, &rb = *b.run;
  ASSERT_EQ(ra.step_count(), rb.step_count());
  ASSERT_EQ(ra.dofs().num_nodes(), rb.dofs().num_nodes());
  EXPECT_TRUE(std::equal(ra.dofs().pair_nodes().begin(), ra.dofs().pair_nodes().end(),
                         rb.dofs().pair_nodes().begin()));
  EXPECT_EQ(std::memcmp(ra.displacement().data(), rb.displacement().data(),
                        ra.displacement().size() * sizeof(double)),
            0);
  EXPECT_EQ(std::memcmp(ra.velocity().data(), rb.velocity().data(),
                        ra.velocity().size() * sizeof(double)),
            0);
  EXPECT_EQ(std::memcmp(&ra.record(), &rb.record(), sizeof(StepRecord)), 0);
  if (a.cracks) {
    EXPECT_EQ(a.cracks->fracture().cracked(), b.cracks->fracture().cracked());
  }
}

/// Steps a simulation of `text` to `stop`, saves it, loads that into a second one built afresh,
/// and steps both to `stop + more`: the two must agree bit for bit after every stretch.
void expect_restart_continues(const std::string& text, long stop, long more) {
  const DynamicsScene scene = scene_of(text);
  const EnsembleRunId id = ensemble_runs(scene.meshes).front();
  ExplicitSimulation a = dynamics_simulation(scene, id);
  for (long s = 0; s < stop; ++s) a.step();
  StateArchive saved;
  a.archive(saved);
  ExplicitSimulation b = dynamics_simulation(scene, id);
  StateArchive loaded(saved.bytes());
  b.archive(loaded);
  loaded.finish();
  expect_same_state(a, b);
  for (long s = 0; s < more; ++s) a.step(), b.step();
  expect_same_state(a, b);
  if (a.cracks)
    std::printf("stop at %ld: %zu cracked edges after %ld more steps\n", stop,
                a.cracks->fracture().events().size(), more);
}

TEST(RunCheckpoint, ColumnContinuesBitForBit) {
  for (long stop : {1L, 57L, 240L, 611L}) expect_restart_continues(kColumn + "}", stop, 400);
}

TEST(RunCheckpoint, ColumnWithTheReportsPenaltiesContinuesBitForBit) {
  for (long stop : {3L, 333L}) expect_restart_continues(kColumn + kPenaltyLaws + "}", stop, 400);
}

TEST(RunCheckpoint, CoupledInterfacesContinueBitForBit) {
  for (long stop : {5L, 300L}) expect_restart_continues(kColumn + kCoupled + "}", stop, 300);
}

TEST(RunCheckpoint, NotchedBendContinuesBitForBit) {
  for (long stop : {10L, 700L}) expect_restart_continues(kBend, stop, 700);
}

class RunStops : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("vorodg_test_RunCheckpoint_" + std::string(info->name()) + std::to_string(getpid()));
    fs::remove_all(dir_);
    clear_stop_request();
  }
  void TearDown() override {
    clear_stop_request();
    fs::remove_all(dir_);
  }

  /// Every file under `root` (checkpoints/ aside) by relative path, with its bytes.
  static std::map<std::string, std::string> files(const fs::path& root) {
    std::map<std::string, std::string> all;
    for (const auto& entry : fs::recursive_directory_iterator(root))
      if (entry.is_regular_file()) {
        const std::string name = fs::relative(entry.path(), root).generic_string();
        if (!name.starts_with("checkpoints/")) all[name] = read_file(entry.path());
      }
    return all;
  }
  /// A record's line with its times taken out.
  static nlohmann::json untimed(const DynamicsScene& scene, const DynamicsRecord& r) {
    nlohmann::json j = dynamics_record_json(scene, r);
    for (const char* t : {"seconds", "loop_seconds", "check_seconds", "rebuild_seconds",
                          "coupling_seconds", "checkpoint_seconds"})
      j.erase(t);
    return j;
  }

  fs::path dir_;
};

TEST_F(RunStops, AStoppedRunResumesWhereItStoppedAndEndsTheSame) {
  const DynamicsScene scene = scene_of(kColumn + R"(, "checkpoint": {"steps": 150}})");
  const EnsembleRunId id = ensemble_runs(scene.meshes).front();
  const DynamicsRecord reference = run_dynamics(scene, id, dir_ / "reference");
  ASSERT_TRUE(reference.complete) << reference.failure;
  EXPECT_GT(reference.checkpoints, 0);
  EXPECT_TRUE(fs::is_empty(dir_ / "reference" / "checkpoints"));
  // Stopped at once three times (steps 1, 2, 3), then run to the end.
  const fs::path out = dir_ / "stopped";
  for (int stop = 1; stop <= 3; ++stop) {
    request_stop(SIGTERM);
    try {
      run_dynamics(scene, id, out);
      FAIL() << "a stop was asked for: the run must not finish";
    } catch (const Interrupted& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(id.id() + " stopped at step " + std::to_string(stop)), std::string::npos)
          << what;
    }
    clear_stop_request();
  }
  const DynamicsRecord resumed = run_dynamics(scene, id, out);
  EXPECT_EQ(untimed(scene, resumed), untimed(scene, reference));
  EXPECT_EQ(files(out), files(dir_ / "reference"));
  EXPECT_TRUE(fs::is_empty(out / "checkpoints"));
}

TEST_F(RunStops, ARefusedCheckpointFallsBackToThePreviousOneOrToTheStart) {
  const DynamicsScene scene = scene_of(kColumn + R"(, "checkpoint": {"steps": 100}})");
  const EnsembleRunId id = ensemble_runs(scene.meshes).front();
  const DynamicsRecord reference = run_dynamics(scene, id, dir_ / "reference");
  const fs::path out = dir_ / "stopped", file = out / "checkpoints" / (id.id() + ".ckpt");
  const fs::path previous = file.string() + ".prev";
  // Two stops leave two checkpoints (steps 1 and 2); corrupt the newest: the run resumes from
  // the one before.
  for (int stop = 0; stop < 2; ++stop) {
    request_stop(SIGTERM);
    EXPECT_THROW(run_dynamics(scene, id, out), Interrupted);
    clear_stop_request();
  }
  ASSERT_TRUE(fs::exists(previous));
  std::string bytes = read_file(file);
  bytes[bytes.size() / 2] ^= 1;
  write_file_atomically(file, bytes);
  testing::internal::CaptureStderr();
  request_stop(SIGTERM);
  EXPECT_THROW(run_dynamics(scene, id, out), Interrupted);  // resumed at 1, stopped at 2
  clear_stop_request();
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("corrupt"), std::string::npos) << said;
  EXPECT_NE(said.find("resumed at step 1"), std::string::npos) << said;
  // Both files cut short: the run says so and starts again from t = 0.
  for (const fs::path& f : {file, previous}) {
    const std::string whole = read_file(f);
    write_file_atomically(f, whole.substr(0, whole.size() / 3));
  }
  testing::internal::CaptureStderr();
  const DynamicsRecord resumed = run_dynamics(scene, id, out);
  const std::string restarted = testing::internal::GetCapturedStderr();
  EXPECT_NE(restarted.find("truncated"), std::string::npos) << restarted;
  EXPECT_NE(restarted.find("starts again from the beginning"), std::string::npos) << restarted;
  EXPECT_EQ(untimed(scene, resumed), untimed(scene, reference));
  EXPECT_EQ(files(out), files(dir_ / "reference"));
}

TEST_F(RunStops, AStoppedQuasiStaticPathResumesAndEndsTheSame) {
  const FractureScene scene = parse_fracture_scene(
      R"({"study": "fracture", "problem": "three-point-bend", "domain": [0, 0, 2.0, 0.2],
      "notch_depth": 0.1, "material": {"E": 30e9, "nu": 0.2, "plane": "stress", "thickness": 0.05},
      "cohesive": {"law": "linear", "strength": 3.33e6, "fracture_energy": 124},
      "cracking": {"mode": "pre-inserted"},
      "loading": {"control": "cmod", "max_cmod": 3e-4, "steps": 30},
      "outputs": {"vtu_every": 5}, "checkpoint": {"steps": 4},
      "meshes": [{"family": "rcp", "symmetric": true, "sizes": [0.04], "seed": 2008}]})",
      "test");
  const EnsembleRunId id = ensemble_runs(scene.meshes).front();
  auto untimed_path = [](const FractureRecord& r) {
    nlohmann::json j = fracture_record_json(r);
    for (const char* t : {"seconds", "path_seconds"}) j.erase(t);
    return j;
  };
  const FractureRecord reference = run_fracture(scene, id, dir_ / "reference");
  ASSERT_TRUE(reference.complete) << reference.failure;
  const fs::path out = dir_ / "stopped";
  for (int stop = 1; stop <= 3; ++stop) {
    request_stop(SIGTERM);
    try {
      run_fracture(scene, id, out);
      FAIL() << "a stop was asked for: the path must not finish";
    } catch (const Interrupted& e) {
      EXPECT_NE(std::string(e.what()).find("stopped at step " + std::to_string(stop)),
                std::string::npos)
          << e.what();
    }
    clear_stop_request();
  }
  const FractureRecord resumed = run_fracture(scene, id, out);
  EXPECT_EQ(untimed_path(resumed), untimed_path(reference));
  EXPECT_EQ(files(out), files(dir_ / "reference"));
}

}  // namespace
}  // namespace vorodg
