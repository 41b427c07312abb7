// Time-refinement studies (`time.refinement`; verification/kinds/dynamics/TimeRefinement*,
// docs/dynamics.md "Time refinement"):
//   - step_trend against closed forms: means and standard errors of known samples; a measure
//     exactly linear in the step has that slope (to 1e-12); q = 2 + 3 f^2 at f = 1, 1/2, 1/4 has
//     the observed order 2 and the limit 2 (to 1e-6: Extrapolation's golden-section search); a
//     trend that grows as 1 / f (monotone, differences growing) gets neither; non-finite values
//     are left out;
//   - the reader turns time.refinement into one part per fraction with the safety scaled, the
//     history and frames every 1 / f as many steps (at the same times) and nothing else changed
//     (labels dt-<f>, <variant>/dt-<f> with variants), and refuses a single
//     fraction, an ascending list, a fraction past 1 and refinement beside perturb;
//   - `vorodg run` on a wall impact with three fractions writes each part's results, the report
//     and its picture, and the wall impulse agrees across the steps within 0.1 % (the exact
//     plane).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "support/RunVorodg.hpp"
#include "verification/kinds/dynamics/TimeRefinementReport.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;
using namespace vorodg::testing;

TEST(TimeRefinement, TheTrendOfKnownSamples) {
  const std::vector<double> f = {1.0, 0.5, 0.25};
  // Means 2, 4, 6 with standard errors 1 / sqrt(3) (samples m - 1, m, m + 1): a line of slope
  // -16 / 3 in f, as the weighted fit of equal weights gives.
  const StepTrend line = step_trend(f, {{1, 2, 3}, {3, 4, 5}, {5, 6, 7}});
  EXPECT_DOUBLE_EQ(line.mean[1], 4.0);
  EXPECT_NEAR(line.std_error[0], 1.0 / std::sqrt(3.0), 1e-15);
  const double xm = (1.0 + 0.5 + 0.25) / 3.0, ym = 4.0;
  double sxy = 0.0, sxx = 0.0;
  for (int i = 0; i < 3; ++i) {
    sxy += (f[i] - xm) * (2.0 + 2.0 * i - ym);
    sxx += (f[i] - xm) * (f[i] - xm);
  }
  EXPECT_NEAR(line.slope, sxy / sxx, 1e-12);
  EXPECT_NEAR(line.slope_error, 1.0 / std::sqrt(3.0) / std::sqrt(sxx), 1e-12);
  EXPECT_TRUE(std::isnan(line.order)) << "a linear trend's differences do not shrink here";

  auto q = [](double x) { return 2.0 + 3.0 * x * x; };
  const StepTrend quadratic = step_trend(f, {{q(1.0)}, {q(0.5)}, {q(0.25)}});
  EXPECT_NEAR(quadratic.order, 2.0, 1e-6);
  EXPECT_NEAR(quadratic.extrapolated, 2.0, 1e-6);
  EXPECT_TRUE(std::isnan(quadratic.std_error[0]));  // one run: no error

  const StepTrend growing = step_trend(f, {{1.0}, {2.0}, {4.0}});
  EXPECT_TRUE(std::isnan(growing.order));
  EXPECT_TRUE(std::isnan(growing.extrapolated));

  const StepTrend gaps = step_trend(f, {{1.0, NAN}, {NAN}, {3.0}});
  EXPECT_EQ(gaps.runs[0], 1);
  EXPECT_EQ(gaps.runs[1], 0);
  EXPECT_TRUE(std::isnan(gaps.mean[1]));
}

std::string wall(const std::string& extra) {
  return std::string(R"({"study": "dynamics", "name": "steps", "problem": "wall-impact",
    "domain": [0, 0, 0.4, 0.1], "initial_velocity": [1, 0],
    "material": {"E": 2e11, "nu": 0.3, "plane": "stress", "density": 7800},
    "outputs": {"vtu": false},
    "meshes": [{"family": "rcp", "sizes": [0.02], "realizations": 2, "seed": 2008}], )") +
         extra + "}";
}

TEST(TimeRefinement, EachFractionIsAPartWithItsSafetyScaled) {
  const DynamicsScene s = parse_dynamics_scene(
      wall(R"("time": {"safety": 0.8, "refinement": [1, 0.5, 0.25]})"), "test scene");
  ASSERT_EQ(s.variants.size(), 3u);
  const double expected[] = {0.8, 0.4, 0.2};
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(s.variants[i].safety, expected[i]);
    EXPECT_EQ(s.variants[i].setting("time.safety"), exact_text(expected[i]));
    EXPECT_EQ(s.variants[i].meshes.size(), s.meshes.size());
  }
  EXPECT_EQ(s.variants[1].label, "dt-0.5");
  EXPECT_EQ(s.variants[2].output_every, 4 * s.output_every);  // frames at the same times
  EXPECT_EQ(s.variants[2].history_every, 4 * s.history_every);
  EXPECT_EQ(s.variants[2].setting("time.output_every"), std::to_string(4 * s.output_every));
  EXPECT_DOUBLE_EQ(s.variants[2].step_fraction, 0.25);

  const DynamicsScene v = parse_dynamics_scene(wall(R"("time": {"refinement": [1, 0.5]},
              "variants": [{"label": "a"}, {"label": "b", "contact": {"law": "penalty-cell-pairs"}}])"),
                                               "test scene");
  ASSERT_EQ(v.variants.size(), 4u);
  EXPECT_EQ(v.variants[3].label, "b/dt-0.5");
  EXPECT_EQ(v.variants[3].refinement_base, "b");
  EXPECT_EQ(v.variants[3].contact_law, "penalty-cell-pairs");
}

TEST(TimeRefinement, RefusesWhatIsNotARefinement) {
  for (const char* bad :
       {R"("time": {"refinement": [1]})", R"("time": {"refinement": [0.5, 1]})",
        R"("time": {"refinement": [1.5, 1]})", R"("time": {"refinement": [1, 0]})"})
    EXPECT_THROW(parse_dynamics_scene(wall(bad), "test scene"), InputError) << bad;
}

TEST(TimeRefinement, RunWritesEveryStepAndTheReport) {
  const fs::path dir = fs::temp_directory_path() / ("vorodg_refine_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = dir / "steps.json", out = dir / "out";
  std::ofstream(scene) << wall(R"("time": {"refinement": [1, 0.5, 0.25]})");
  const RunResult r =
      run_program(VORODG_EXE, {"run", scene.string(), "-o", out.string(), "--quiet"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"dt-1", "dt-0.5", "dt-0.25"})
    EXPECT_TRUE(fs::exists(out / part / "results.csv")) << part;
  const std::string md = slurp(out / "time-refinement.md"),
                    csv = slurp(out / "time-refinement.csv");
  EXPECT_NE(md.find("| wall_impulse |"), std::string::npos) << md;
  EXPECT_TRUE(fs::exists(out / "plots" / "time_refinement.png")) << r.err;
  // The wall's impulse per step, from the CSV's rows "steps",0,0,"wall_impulse",<f>,<runs>,<mean>
  std::vector<double> impulse;
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);)
    if (line.find("\"wall_impulse\"") != std::string::npos) {
      std::vector<std::string> cells;
      std::istringstream row(line);
      for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
      impulse.push_back(std::stod(cells.at(6)));
    }
  ASSERT_EQ(impulse.size(), 3u) << csv;
  for (double i : impulse) EXPECT_NEAR(i / impulse[0], 1.0, 1e-3);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vorodg
