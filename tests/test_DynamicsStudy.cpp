// The dynamics study kind (verification/kinds/dynamics), run by run and end to end:
//   - a block thrown at a rigid wall at normal incidence, default penalty (alpha 0.1): no
//     penetration deeper than 1% of h_avg; the rebound speed and the contact time are printed
//     beside the 1D elastic-bar estimates (rebound = impact speed, contact time = 2 L / c_bar) and
//     held to loose bounds (rebound within 5% below, contact time 1 to 1.4 times the estimate);
//   - two blocks thrown at each other: total linear momentum to 1e-10 of sum m|v|;
//   - a free body with contact on and nothing to touch: momentum to 1e-12, no contact;
//   - a wave bar: the measured speed within 1% of the bar speed;
//   - the scene reader: every key of the table is in docs/dynamics.md, --force lets safety >= 1
//     through, the defaults are echoed;
//   - `vorodg run` end to end: the history columns exactly as named, one row per step, the
//     reports, the .pvd series (its frames listed relative to it with -o relative to the working
//     folder), the energy plot, and a rerun that resumes without running again.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/util/Errors.hpp"
#include "support/RunVorodg.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;
namespace fs = std::filesystem;

const fs::path kExe = VORODG_EXE;
const fs::path kData = VORODG_TEST_DATA;

/// A fresh scratch folder per test, removed at the end.
class DynamicsStudy : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    scratch_ =
        fs::temp_directory_path() / ("vorodg_test_DynamicsStudy_" + std::string(info->name()) +
                                     "_" + std::to_string(::getpid()));
    fs::remove_all(scratch_);
    fs::create_directories(scratch_);
  }
  void TearDown() override { fs::remove_all(scratch_); }

  /// Runs the first run of a scene given as JSON text.
  DynamicsRecord run_first(const std::string& text) {
    const DynamicsScene scene = parse_dynamics_scene(text, "test scene");
    return run_dynamics(scene, ensemble_runs(scene.meshes).front(), scratch_ / "run");
  }

  fs::path scratch_;
};

const char* kNoVtu = R"("outputs": {"vtu": false})";

TEST_F(DynamicsStudy, WallImpactAtNormalIncidence) {
  const DynamicsRecord r = run_first(std::string(R"({"study": "dynamics", "problem": "wall-impact",
    "domain": [0, 0, 0.4, 0.1], "initial_velocity": [1, 0],
    "meshes": [{"family": "rcp", "sizes": [0.01], "seed": 2008}], )") +
                                     kNoVtu + "}");
  const DynamicsMeasures& m = r.measures;
  std::printf(
      "wall impact, rcp, %d cells, %ld steps: max penetration / h_avg %.2e; rebound %.4f m/s "
      "(1D bar: %.4f); contact time %.4e s (1D bar 2L/c_bar: %.4e, ratio %.3f); energy balance "
      "%.1e\n",
      r.cells, r.steps, m.max_penetration_over_h, m.rebound_velocity, m.rebound_estimate,
      m.contact_time, m.contact_time_estimate, m.contact_time / m.contact_time_estimate,
      m.energy_balance_error);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_TRUE(m.contact_ended);
  // The exact plane (the default): no vertex behind it beyond round-off, the contact as long as
  // the bar's round trip within 2 %, and a rebound that the mesh's dispersion keeps below the
  // impact speed (0.921 here at h = L / 40; it tends to 1 as h does: test_ExactPlane).
  EXPECT_LT(m.max_penetration_over_h, 1e-12);
  EXPECT_DOUBLE_EQ(m.impact_velocity, 1.0);
  EXPECT_DOUBLE_EQ(m.rebound_estimate, 1.0);
  EXPECT_GT(m.rebound_velocity, 0.9);
  EXPECT_LE(m.rebound_velocity, 1.0 + 1e-6);
  EXPECT_NEAR(m.contact_time / m.contact_time_estimate, 1.0, 0.02);
  EXPECT_LT(m.energy_balance_error, 1e-10);
  // The wall's impulse is the change of the block's normal momentum, M (rebound + impact) with
  // M = rho x area (steel's 7800 kg/m^3 on 0.4 x 0.1), to round-off: nothing else acts on it.
  const double mass = 7800.0 * 0.4 * 0.1;
  std::printf("wall impulse %.6f N s/m, momentum change %.6f, 2 M v %.6f\n", m.wall_impulse,
              mass * (m.rebound_velocity + m.impact_velocity), 2.0 * mass * m.impact_velocity);
  EXPECT_NEAR(m.wall_impulse, mass * (m.rebound_velocity + m.impact_velocity),
              1e-9 * mass * m.impact_velocity);
}

TEST_F(DynamicsStudy, TwoBlocksKeepTheirTotalMomentum) {
  const DynamicsRecord r = run_first(std::string(R"({"study": "dynamics", "problem": "two-blocks",
    "domain": [0, 0, 0.3, 0.1], "initial_velocity": [2, 0],
    "second_block": {"domain": [0.301, 0.03, 0.501, 0.18], "initial_velocity": [-1, 0.2],
                     "angular_velocity": 3},
    "meshes": [{"family": "rcp", "sizes": [0.01], "seed": 7}], )") +
                                     kNoVtu + "}");
  const DynamicsMeasures& m = r.measures;
  std::printf(
      "two blocks, %d cells, %ld steps, %d in contact: momentum drift %.2e, max penetration / "
      "h_avg %.2e, energy balance %.1e\n",
      r.cells, r.steps, m.contact_steps, m.momentum_drift, m.max_penetration_over_h,
      m.energy_balance_error);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_GT(m.contact_steps, 10);
  EXPECT_LT(m.momentum_drift, 1e-10);
  EXPECT_LT(m.max_penetration_over_h, 0.01);
  EXPECT_LT(m.energy_balance_error, 1e-10);
}

TEST_F(DynamicsStudy, FreeBodyWithContactOnKeepsMomentum) {
  const DynamicsRecord r = run_first(std::string(R"({"study": "dynamics", "problem": "free-body",
    "contact": {"enabled": true}, "time": {"steps": 3000},
    "meshes": [{"family": "rcp", "sizes": [0.05], "seed": 3}], )") +
                                     kNoVtu + "}");
  std::printf("free body with contact on, %d cells, %ld steps: momentum drift %.2e, angular %.2e\n",
              r.cells, r.steps, r.measures.momentum_drift, r.measures.angular_momentum_drift);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_EQ(r.steps, 3000);
  EXPECT_EQ(r.measures.contact_steps, 0);
  EXPECT_LT(r.measures.momentum_drift, 1e-12);
}

TEST_F(DynamicsStudy, WaveBarArrivesAtTheBarSpeed) {
  const DynamicsRecord r = run_first(std::string(R"({"study": "dynamics", "problem": "wave-bar",
    "meshes": [{"family": "hex", "sizes": [0.0125]}], )") +
                                     kNoVtu + "}");
  std::printf("wave bar, hex, %d cells: arrival %.5e s (L/c %.5e), speed error %+.3f%%\n", r.cells,
              r.measures.arrival_time, r.measures.arrival_theory,
              100 * r.measures.wave_speed_error);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_LT(std::abs(r.measures.wave_speed_error), 0.01);
}

TEST_F(DynamicsStudy, EveryKeyIsDocumentedAndForceLetsSafetyThrough) {
  std::ifstream in(kData / ".." / ".." / "docs" / "scenes.md");
  const std::string docs((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(docs.empty());
  for (const SceneKey& k : dynamics_scene_keys().keys)
    EXPECT_NE(docs.find("`" + k.name + "`"), std::string::npos) << k.name << " is not documented";
  const std::string text = R"({"study": "dynamics", "problem": "free-body",
    "time": {"safety": 1.2}, "meshes": [{"family": "rcp", "sizes": [0.1]}]})";
  EXPECT_THROW(parse_dynamics_scene(text, "test"), InputError);
  const DynamicsScene forced = parse_dynamics_scene(text, "test", true);
  EXPECT_EQ(forced.safety, 1.2);
  // Every key the problem uses is echoed with the value used, defaults included.
  bool echoed_estimate = false;
  for (const auto& [key, value] : forced.settings)
    echoed_estimate |= key == "time.estimate" && value == "lanczos";
  EXPECT_TRUE(echoed_estimate);
}

TEST_F(DynamicsStudy, RunWritesHistoryReportsSeriesAndPlots) {
  const fs::path scene = scratch_ / "impact.json", out = scratch_ / "out";
  std::ofstream(scene) << R"({"study": "dynamics", "problem": "wall-impact",
    "description": "end to end", "time": {"output_every": 50},
    "meshes": [{"family": "quad", "sizes": [0.02]}]})";
  // -o relative to the working folder: the series must still list its frames relative to itself.
  const fs::path here = fs::current_path();
  fs::current_path(scratch_);
  const RunResult r = run_program(kExe, {"run", scene.string(), "-o", "out", "--quiet"}, scratch_);
  fs::current_path(here);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("#   contact.alpha = 0.1"), std::string::npos) << r.out;
  const std::string history = slurp(out / "history" / "quad-L0-R0.csv");
  const std::string header = history.substr(0, history.find('\n'));
  EXPECT_EQ(header.substr(0, header.find(",angular_momentum")),
            "step,time,kinetic_energy,elastic_energy,external_work,contact_work,"
            "dissipated_energy,momentum_x,momentum_y");
  const auto summary = nlohmann::json::parse(slurp(out / "summary.json"));
  const long steps = summary.at("records").at(0).at("steps").get<long>();
  EXPECT_EQ(std::count(history.begin(), history.end(), '\n'), steps + 2);  // header, step 0
  EXPECT_EQ(summary.at("study"), "dynamics");
  EXPECT_TRUE(summary.at("records").at(0).contains("rebound_velocity"));
  const std::string results = slurp(out / "results.csv");
  for (const char* column : {"dt_critical_lanczos", "dt_critical_cells", "max_penetration_over_h",
                             "rebound_estimate", "contact_time_estimate", "momentum_drift"})
    EXPECT_NE(results.find(column), std::string::npos) << column;
  EXPECT_TRUE(fs::exists(out / "report.md"));
  EXPECT_TRUE(fs::exists(out / "vtu" / "quad-L0-R0.pvd"));
  EXPECT_TRUE(fs::exists(out / "vtu" / "quad-L0-R0" / "step_0.vtu"));
  EXPECT_NE(slurp(out / "vtu" / "quad-L0-R0.pvd").find(R"(file="quad-L0-R0/step_0.vtu")"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(out / "plots" / "quad-L0-R0_energy.png")) << r.err;
  // A rerun finds the run done and only rewrites the reports.
  const RunResult again = run_program(
      kExe, {"run", scene.string(), "-o", out.string(), "--quiet", "--no-plots"}, scratch_);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const std::string jsonl = slurp(out / "results.jsonl");
  EXPECT_EQ(std::count(jsonl.begin(), jsonl.end(), '\n'), 1);
}

}  // namespace
}  // namespace vorodg
