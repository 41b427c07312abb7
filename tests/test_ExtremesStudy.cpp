// The extremes study: scenes with sweeps (each sweep is the top-level keys with its own keys
// JSON-merge-patched over them), the verdict of a run (ok / degraded / broken) against each kind
// of baseline, the axis value of a run, and `vorodg run` on a tiny extremes scene end to end
// (the files written, the verdicts physics predicts, a rerun resuming to the same bytes).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "support/ExtremesRows.hpp"
#include "support/RunVorodg.hpp"
#include "verification/kinds/extremes/ExtremesReport.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;
using nlohmann::json;
namespace fs = std::filesystem;

const fs::path kExe = VORODG_EXE;
const fs::path kRepo = fs::path(VORODG_TEST_DATA).parent_path().parent_path();

// ---------------------------------------------------------------------------------------------
// Parsing

const char* kTwoSweeps = R"({
  "name": "two-sweeps",
  "description": "parsing test",
  "study": "extremes",
  "problems": ["beam"],
  "domain": [0, -0.5, 4, 0.5],
  "material": {"E": 2.0, "nu": 0.25, "plane": "strain", "load": 3.0},
  "meshes": [{"family": "rcp", "sizes": [0.5, 0.25], "realizations": 2, "seed": 11}],
  "formulations": [{"name": "cg"}, {"name": "dg-nitsche", "kp": [100]}],
  "sweeps": [
    {"name": "first", "axis": "nu", "baseline": "first-nu", "expected_rate": 1.5,
     "degraded_factor": 4, "broken_factor": 40,
     "material": {"nu": [0.3, 0.49]},
     "domain": [0, -0.5, 10, 0.5],
     "meshes": [{"family": "quad", "sizes": [0.5]}]},
    {"name": "second", "axis": "kp"}
  ]
})";

TEST(ExtremesScene, SweepsInheritTheTopLevelKeysAndTheirOverridesWin) {
  const Scene scene = parse_scene(kTwoSweeps, "two.json", {.sweeps = true});
  EXPECT_EQ(scene.study, "extremes");
  EXPECT_EQ(scene.name, "two-sweeps");
  EXPECT_EQ(scene.description, "parsing test");
  ASSERT_EQ(scene.sweeps.size(), 2u);

  const Scene& a = *scene.sweeps[0];
  EXPECT_EQ(a.name, "first");
  EXPECT_EQ(a.axis, "nu");
  EXPECT_EQ(a.baseline, "first-nu");
  EXPECT_DOUBLE_EQ(a.expected_rate, 1.5);
  EXPECT_DOUBLE_EQ(a.degraded_factor, 4.0);
  EXPECT_DOUBLE_EQ(a.broken_factor, 40.0);
  // The material object is merged deeply: nu overridden, E, plane and load inherited.
  EXPECT_EQ(a.nu, (std::vector<double>{0.3, 0.49}));
  EXPECT_EQ(a.plane, PlaneModel::strain);
  EXPECT_DOUBLE_EQ(a.E, 2.0);
  EXPECT_DOUBLE_EQ(a.load, 3.0);
  // The domain override applies.
  EXPECT_DOUBLE_EQ(a.domain.x1(), 10.0);
  EXPECT_DOUBLE_EQ(a.domain.width(), 10.0);
  EXPECT_DOUBLE_EQ(a.domain.height(), 1.0);
  // Arrays are replaced, not merged: one quad mesh with its own defaults.
  ASSERT_EQ(a.meshes.size(), 1u);
  EXPECT_EQ(a.meshes[0].family, MeshFamily::quad);
  EXPECT_EQ(a.meshes[0].label, "quad");
  EXPECT_EQ(a.meshes[0].sizes, (std::vector<double>{0.5}));
  EXPECT_EQ(a.meshes[0].realizations, 1);
  EXPECT_EQ(a.meshes[0].seed, 1u);
  // Not overridden: the top-level formulations and problems.
  ASSERT_EQ(a.formulations.size(), 2u);
  EXPECT_EQ(a.formulations[0].settings.formulation, "cg");
  EXPECT_EQ(a.formulations[1].settings.formulation, "dg-nitsche");
  EXPECT_EQ(a.formulations[1].kp, (std::vector<double>{100.0}));
  EXPECT_EQ(a.problems, (std::vector<std::string>{"beam"}));
  EXPECT_EQ(a.study, "convergence");  // each sweep runs as a convergence study

  const Scene& b = *scene.sweeps[1];
  EXPECT_EQ(b.name, "second");
  EXPECT_EQ(b.axis, "kp");
  // Defaults.
  EXPECT_EQ(b.baseline, "none");
  EXPECT_DOUBLE_EQ(b.expected_rate, 2.0);
  EXPECT_DOUBLE_EQ(b.degraded_factor, 3.0);
  EXPECT_DOUBLE_EQ(b.broken_factor, 30.0);
  // Everything from the top level.
  EXPECT_EQ(b.nu, (std::vector<double>{0.25}));
  EXPECT_EQ(b.plane, PlaneModel::strain);
  EXPECT_DOUBLE_EQ(b.E, 2.0);
  EXPECT_DOUBLE_EQ(b.load, 3.0);
  EXPECT_DOUBLE_EQ(b.domain.x0(), 0.0);
  EXPECT_DOUBLE_EQ(b.domain.y0(), -0.5);
  EXPECT_DOUBLE_EQ(b.domain.x1(), 4.0);
  EXPECT_DOUBLE_EQ(b.domain.y1(), 0.5);
  ASSERT_EQ(b.meshes.size(), 1u);
  EXPECT_EQ(b.meshes[0].family, MeshFamily::rcp);
  EXPECT_EQ(b.meshes[0].sizes, (std::vector<double>{0.5, 0.25}));
  EXPECT_EQ(b.meshes[0].realizations, 2);
  EXPECT_EQ(b.meshes[0].seed, 11u);
  ASSERT_EQ(b.formulations.size(), 2u);
}

TEST(ExtremesScene, TheShippedSceneCoversEveryAxisAndItsExtremes) {
  const fs::path file = kRepo / "data" / "scenes" / "extremes.json";
  ASSERT_TRUE(fs::exists(file)) << file;
  const Scene scene = read_scene(file, {.sweeps = true});
  EXPECT_EQ(scene.study, "extremes");
  ASSERT_FALSE(scene.sweeps.empty());

  std::set<std::string> axes;
  for (const auto& s : scene.sweeps) axes.insert(s->axis);
  EXPECT_EQ(axes,
            (std::set<std::string>{"nu", "kp", "aspect", "perturbation", "regularization", "h"}));

  // nu up to 0.4999999 in plane strain, with cg both with and without mean dilation.
  bool nu_extreme = false;
  for (const auto& s : scene.sweeps) {
    if (s->axis != "nu") continue;
    const bool reaches = std::find(s->nu.begin(), s->nu.end(), 0.4999999) != s->nu.end();
    bool with = false, without = false;
    for (const SceneFormulation& f : s->formulations) {
      if (f.settings.formulation != "cg") continue;
      (f.settings.mean_dilation ? with : without) = true;
    }
    if (reaches && s->plane == PlaneModel::strain && with && without) nu_extreme = true;
  }
  EXPECT_TRUE(nu_extreme)
      << "no nu sweep reaches 0.4999999 in plane strain with cg +- mean_dilation";

  // k_p from 1e-3 to 1e12 for every DG formulation.
  for (const char* dg : {"dg-penalty", "dg-al", "dg-nitsche", "dg-sipg"}) {
    bool covered = false;
    for (const auto& s : scene.sweeps) {
      if (s->axis != "kp") continue;
      for (const SceneFormulation& f : s->formulations) {
        if (f.settings.formulation != dg || f.kp.empty()) continue;
        const auto [lo, hi] = std::minmax_element(f.kp.begin(), f.kp.end());
        if (*lo <= 1e-3 && *hi >= 1e12) covered = true;
      }
    }
    EXPECT_TRUE(covered) << dg << ": no kp sweep covers 1e-3 .. 1e12";
  }

  // Perturbation up to 0.49, and an rcp mesh without regularization.
  double max_perturbation = 0;
  bool unregularized = false;
  for (const auto& s : scene.sweeps) {
    for (const SceneMesh& m : s->meshes) {
      if (s->axis == "perturbation") max_perturbation = std::max(max_perturbation, m.perturbation);
      if (s->axis == "regularization" && m.regularization == 0.0) unregularized = true;
    }
  }
  EXPECT_GE(max_perturbation, 0.49);
  EXPECT_TRUE(unregularized);
}

// ---------------------------------------------------------------------------------------------
// Verdicts

// Exactly representable errors, so that ratios at the factors are exact.
constexpr double kBase = 1.0 / 1024;

TEST(ExtremesVerdict, AFailedRunIsBrokenWithItsError) {
  const Scene s = hand_sweep("none");
  const json r = failed_row("dg-sipg", "the matrix is not positive definite at k_p = 0.001 E");
  const RunVerdict v = judge(s, r, {r});
  EXPECT_EQ(v.level, "broken");
  EXPECT_NE(v.reason.find("the matrix is not positive definite at k_p = 0.001 E"),
            std::string::npos)
      << v.reason;
}

TEST(ExtremesVerdict, ANonConvergedDgIterationIsBroken) {
  const Scene s = hand_sweep("none");
  for (const char* stop : {"max-iterations", "diverged"}) {
    json r = row("dg-al", 0.01);
    r["stop_reason"] = stop;
    r["iterations"] = 100;
    const RunVerdict v = judge(s, r, {r});
    EXPECT_EQ(v.level, "broken") << stop;
    EXPECT_NE(v.reason.find(stop), std::string::npos) << v.reason;
  }
  // Converged in few steps, or a direct solve: ok.
  const json converged = row("dg-al", 0.01);
  EXPECT_EQ(judge(s, converged, {converged}).level, "ok");
  const json direct = row("cg", 0.01);
  EXPECT_EQ(judge(s, direct, {direct}).level, "ok");
}

TEST(ExtremesVerdict, ARelativeErrorOfOneOrMoreIsBroken) {
  const Scene s = hand_sweep("none");
  for (double e : {1.0, 740.0}) {
    const json r = row("cg", e);
    const RunVerdict v = judge(s, r, {r});
    EXPECT_EQ(v.level, "broken") << e;
    EXPECT_NE(v.reason.find(">= 1"), std::string::npos) << v.reason;
  }
  const json r = row("cg", 0.999);
  EXPECT_EQ(judge(s, r, {r}).level, "ok");
}

TEST(ExtremesVerdict, ANonFiniteErrorIsBroken) {
  const Scene s = hand_sweep("none");
  const json nan_row = row("dg-al", std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(judge(s, nan_row, {nan_row}).level, "broken");
  // A NaN or an infinity is written to results.jsonl as null (JSON has neither): a resumed study
  // reads it back that way and must give the same verdict, not throw.
  const json reread = json::parse(nan_row.dump());
  ASSERT_TRUE(reread["l2_error"].is_null());
  RunVerdict v;
  EXPECT_NO_THROW(v = judge(s, reread, {reread}));
  EXPECT_EQ(v.level, "broken");
  EXPECT_NE(v.reason.find("non-finite"), std::string::npos) << v.reason;
}

/// The verdicts of a run with error `factor` times the baseline's, given the baseline row.
void expect_factors(const Scene& s, json run, const json& base, double base_error) {
  struct Case {
    double factor;
    const char* level;
  };
  // Exactly at a factor is not above it.
  for (const Case& c : {Case{1.0, "ok"}, Case{2.5, "ok"}, Case{3.0, "ok"}, Case{3.5, "degraded"},
                        Case{30.0, "degraded"}, Case{31.0, "broken"}, Case{200.0, "broken"}}) {
    run["l2_error"] = c.factor * base_error;
    const RunVerdict v = judge(s, run, {base, run});
    EXPECT_EQ(v.level, c.level) << s.baseline << " x" << c.factor << ": " << v.reason;
    if (std::string(c.level) != "ok") {
      EXPECT_NE(v.reason.find("baseline (" + s.baseline + ")"), std::string::npos) << v.reason;
    }
  }
}

TEST(ExtremesVerdict, FirstNuBaseline) {
  const Scene s = hand_sweep("first-nu");
  const json base = row("dg-al", kBase, "first", 0, 0.3);
  expect_factors(s, row("dg-al", 0.0, "first", 0, 0.49), base, kBase);
  // The baseline is the same variant at the first nu: a cg run at the first nu is no baseline.
  const json cg = row("cg", kBase, "first", 0, 0.3);
  const json run = row("dg-al", 100 * kBase, "first", 0, 0.49);
  EXPECT_EQ(judge(s, run, {cg, run}).level, "ok");
}

TEST(ExtremesVerdict, CgBaseline) {
  const Scene s = hand_sweep("cg");
  const json base = row("cg", kBase);
  expect_factors(s, row("dg-al", 0.0), base, kBase);
  // The cg run at the same place: realization 1's cg, not realization 0's.
  const json cg0 = row("cg", kBase, "first", 0, 0.3, 0);
  const json cg1 = row("cg", 16 * kBase, "first", 0, 0.3, 1);
  const json dg1 = row("dg-al", 32 * kBase, "first", 0, 0.3, 1);
  EXPECT_EQ(judge(s, dg1, {cg0, cg1, dg1}).level, "ok");
  // And at the same nu.
  const json cg_other_nu = row("cg", kBase, "first", 0, 0.49);
  const json cg_same_nu = row("cg", 16 * kBase, "first", 0, 0.3);
  EXPECT_EQ(judge(s, dg1, {cg_other_nu, dg1}).level, "ok");  // no baseline at all
  const json dg0 = row("dg-al", 32 * kBase);
  EXPECT_EQ(judge(s, dg0, {cg_other_nu, cg_same_nu, dg0}).level, "ok");
}

TEST(ExtremesVerdict, FirstMeshBaseline) {
  const Scene s = hand_sweep("first-mesh");
  const json base = row("dg-al", kBase, "first");
  expect_factors(s, row("dg-al", 0.0, "second"), base, kBase);
  // The same variant on the first mesh: cg there is no baseline for dg-al.
  const json cg = row("cg", kBase, "first");
  const json run = row("dg-al", 100 * kBase, "second");
  EXPECT_EQ(judge(s, run, {cg, run}).level, "ok");
}

TEST(ExtremesVerdict, CoarsestLevelBaselineScalesWithTheExpectedRate) {
  Scene s = hand_sweep("coarsest-level");
  const json base = row("cg", 1.0 / 64, "first", 0, 0.3, 0, 0.5);
  // Level 1 at half the h: expected error (1/2)^2 of the coarsest one.
  const double expected = (1.0 / 64) * 0.25;
  expect_factors(s, row("cg", 0.0, "first", 1, 0.3, 0, 0.25), base, expected);
  // An error that did not fall at all is 4x the expected one at rate 2: degraded ...
  const json flat = row("cg", 1.0 / 64, "first", 1, 0.3, 0, 0.25);
  EXPECT_EQ(judge(s, flat, {base, flat}).level, "degraded");
  // ... but only 2x at rate 1: ok.
  s.expected_rate = 1.0;
  EXPECT_EQ(judge(s, flat, {base, flat}).level, "ok");
  // The coarsest level is its own baseline.
  EXPECT_EQ(judge(s, base, {base, flat}).level, "ok");
}

TEST(ExtremesVerdict, FactorsComeFromTheSweep) {
  Scene s = hand_sweep("cg");
  s.degraded_factor = 10;
  s.broken_factor = 100;
  const json base = row("cg", kBase);
  json run = row("dg-al", 8 * kBase);
  EXPECT_EQ(judge(s, run, {base, run}).level, "ok");
  run["l2_error"] = 10 * kBase;
  EXPECT_EQ(judge(s, run, {base, run}).level, "ok");
  run["l2_error"] = 12 * kBase;
  EXPECT_EQ(judge(s, run, {base, run}).level, "degraded");
  run["l2_error"] = 100 * kBase;
  EXPECT_EQ(judge(s, run, {base, run}).level, "degraded");
  run["l2_error"] = 128 * kBase;
  EXPECT_EQ(judge(s, run, {base, run}).level, "broken");
}

TEST(ExtremesVerdict, ANearSingularFactorIsDegraded) {
  const Scene s = hand_sweep("none");
  json r = row("dg-al", 0.01);
  r["rcond"] = 1e-14;
  RunVerdict v = judge(s, r, {r});
  EXPECT_EQ(v.level, "degraded");
  EXPECT_NE(v.reason.find("rcond"), std::string::npos) << v.reason;
  r["rcond"] = 1e-12;  // at the threshold: not below it
  EXPECT_EQ(judge(s, r, {r}).level, "ok");
  r["rcond"] = 1e-6;
  EXPECT_EQ(judge(s, r, {r}).level, "ok");
  // A slow DG iteration (more than half of the formulation's 100 steps): degraded.
  r["iterations"] = 51;
  v = judge(s, r, {r});
  EXPECT_EQ(v.level, "degraded");
  EXPECT_NE(v.reason.find("slow"), std::string::npos) << v.reason;
  r["iterations"] = 50;
  EXPECT_EQ(judge(s, r, {r}).level, "ok");
}

TEST(ExtremesVerdict, AMissingOrFailedBaselineLeavesTheAbsoluteChecks) {
  for (const char* baseline : {"cg", "first-nu", "first-mesh", "coarsest-level", "none"}) {
    const Scene s = hand_sweep(baseline);
    // The run would be 512x its baseline, if there were one.
    const json run = row("dg-al", 0.5, "second", 1, 0.49, 0, 0.25);
    EXPECT_EQ(judge(s, run, {run}).level, "ok") << baseline;
    // A failed baseline run of each kind: no comparison either.
    json failed = failed_row(std::string(baseline) == "cg" ? "cg" : "dg-al", "singular");
    failed["nu"] = std::string(baseline) == "first-nu" ? 0.3 : 0.49;
    failed["mesh"] = std::string(baseline) == "first-mesh" ? "first" : "second";
    failed["level"] = std::string(baseline) == "coarsest-level" ? 0 : 1;
    EXPECT_EQ(judge(s, run, {failed, run}).level, "ok") << baseline;
    // The absolute checks still apply.
    json bad = run;
    bad["l2_error"] = 2.0;
    EXPECT_EQ(judge(s, bad, {failed, bad}).level, "broken") << baseline;
    bad = run;
    bad["rcond"] = 1e-13;
    EXPECT_EQ(judge(s, bad, {failed, bad}).level, "degraded") << baseline;
  }
}

// ---------------------------------------------------------------------------------------------
// Axis values

TEST(ExtremesAxis, EachAxisGivesItsValue) {
  Scene s = hand_sweep("none");
  s.domain = Rectangle(0, -0.5, 10, 0.5);
  s.meshes[0].regularization = 0.0;
  s.meshes[1].regularization = 0.01;
  json r = row("dg-al", 0.01, "second", 1, 0.49, 0, 0.27);
  r["kp"] = 1e6;

  s.axis = "nu";
  EXPECT_DOUBLE_EQ(axis(s, r), 0.49);
  s.axis = "kp";
  EXPECT_DOUBLE_EQ(axis(s, r), 1e6);
  s.axis = "aspect";
  EXPECT_DOUBLE_EQ(axis(s, r), 10.0);
  s.axis = "perturbation";
  EXPECT_DOUBLE_EQ(axis(s, r), 0.4);
  EXPECT_DOUBLE_EQ(axis(s, row("cg", 0.01, "first")), 0.1);
  s.axis = "regularization";
  EXPECT_DOUBLE_EQ(axis(s, r), 0.01);
  EXPECT_DOUBLE_EQ(axis(s, row("cg", 0.01, "first")), 0.0);
  s.axis = "h";
  EXPECT_DOUBLE_EQ(axis(s, r), 0.27);  // the measured h_avg
  // A failed run has no h_avg: the level's nominal size.
  json failed = failed_row("dg-al", "singular", "second");
  failed["level"] = 1;
  EXPECT_DOUBLE_EQ(axis(s, failed), 0.25);
  // A mesh the sweep does not know: no value.
  s.axis = "perturbation";
  EXPECT_TRUE(std::isnan(axis(s, row("cg", 0.01, "elsewhere"))));
}

// ---------------------------------------------------------------------------------------------
// End to end

const char* kTinyExtremes = R"({
  "name": "tiny-extremes",
  "description": "two small sweeps",
  "study": "extremes",
  "problems": ["beam"],
  "domain": [0, -0.5, 4, 0.5],
  "material": {"E": 1.0, "nu": 0.3, "plane": "stress"},
  "meshes": [{"family": "rcp", "sizes": [0.5], "seed": 7}],
  "formulations": [{"name": "cg"}],
  "sweeps": [
    {"name": "kp", "axis": "kp", "baseline": "cg",
     "formulations": [{"name": "cg"}, {"name": "dg-sipg", "kp": [1e-3, 1e6]}]},
    {"name": "nu", "axis": "nu", "baseline": "first-nu",
     "material": {"nu": [0.3, 0.4999999], "plane": "strain"},
     "formulations": [{"name": "cg"}, {"name": "cg", "mean_dilation": true}]}
  ]
})";

class ExtremesRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vorodg_test_extremes_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "tiny.json") << kTinyExtremes;
  }
  void TearDown() override { fs::remove_all(dir_); }
  RunResult run(const std::vector<std::string>& args) const {
    return run_program(kExe, args, dir_);
  }
  fs::path dir_;
};

int count_lines(const fs::path& file) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty();
  return n;
}

TEST_F(ExtremesRun, VerdictsFollowThePhysicsAndARerunResumes) {
  const fs::path out = dir_ / "out";
  const std::vector<std::string> args = {
      "run", (dir_ / "tiny.json").string(), "-o", out.string(), "--quiet", "--no-plots"};
  const RunResult r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;  // broken runs are findings, not a failure
  for (const char* f : {"report.md", "extremes.csv", "extremes.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  for (const char* sweep : {"kp", "nu"}) {
    EXPECT_TRUE(fs::exists(out / sweep / "results.jsonl")) << sweep;
    EXPECT_TRUE(fs::exists(out / sweep / "report.md")) << sweep;
  }
  EXPECT_EQ(count_lines(out / "kp" / "results.jsonl"), 3);  // cg, sipg at two k_p
  EXPECT_EQ(count_lines(out / "nu" / "results.jsonl"), 4);  // 2 nu x 2 cg variants
  EXPECT_EQ(count_lines(out / "extremes.csv"), 1 + 7);
  EXPECT_NE(slurp(out / "report.md").find("| axis | formulation |"), std::string::npos);

  const json summary = json::parse(slurp(out / "extremes.json"));
  EXPECT_EQ(summary["scene"], "tiny-extremes");
  ASSERT_EQ(summary["cases"].size(), 7u);
  auto verdict = [&](const std::string& sweep, const std::string& id_suffix) -> json {
    for (const json& c : summary["cases"]) {
      const std::string id = c["id"];
      if (c["sweep"] == sweep && id.size() >= id_suffix.size() &&
          id.compare(id.size() - id_suffix.size(), id_suffix.size(), id_suffix) == 0)
        return c;
    }
    ADD_FAILURE() << "no case " << sweep << " ..." << id_suffix;
    return json{{"verdict", ""}, {"reason", ""}, {"value", -1.0}};
  };
  // k_p sweep: cg is its own baseline; SIPG below its coercivity threshold breaks down, at
  // 1e6 E it matches cg.
  const json cg = verdict("kp", "nu=0.3/cg");
  EXPECT_EQ(cg["verdict"], "ok") << cg["reason"];
  const json sipg_low = verdict("kp", "dg-sipg kp=0.001");
  EXPECT_EQ(sipg_low["verdict"], "broken");
  EXPECT_NE(sipg_low["reason"].get<std::string>().find("not positive definite"), std::string::npos)
      << sipg_low["reason"];
  EXPECT_DOUBLE_EQ(sipg_low["value"].get<double>(), 1e-3);
  const json sipg_high = verdict("kp", "dg-sipg kp=1e+06");
  EXPECT_EQ(sipg_high["verdict"], "ok") << sipg_high["reason"];
  EXPECT_DOUBLE_EQ(sipg_high["value"].get<double>(), 1e6);
  EXPECT_NEAR(sipg_high["l2_error"].get<double>(), cg["l2_error"].get<double>(),
              1e-3 * cg["l2_error"].get<double>());
  // nu sweep in plane strain: standard cg locks at 0.4999999, mean dilation does not.
  EXPECT_EQ(verdict("nu", "nu=0.3/cg")["verdict"], "ok");
  EXPECT_EQ(verdict("nu", "nu=0.3/cg mean-dilation")["verdict"], "ok");
  const json locked = verdict("nu", "nu=0.4999999/cg");
  EXPECT_TRUE(locked["verdict"] == "degraded" || locked["verdict"] == "broken") << locked.dump();
  EXPECT_NE(locked["reason"].get<std::string>().find("first-nu"), std::string::npos)
      << locked["reason"];
  EXPECT_DOUBLE_EQ(locked["value"].get<double>(), 0.4999999);
  const json md = verdict("nu", "nu=0.4999999/cg mean-dilation");
  EXPECT_EQ(md["verdict"], "ok") << md["reason"];
  EXPECT_LT(md["l2_error"].get<double>(), 0.5 * locked["l2_error"].get<double>());

  // The trust table: mean dilation trusted up to 0.4999999, sipg nowhere trusted below 1e-3.
  bool md_trusted = false;
  for (const json& t : summary["trust"])
    if (t["axis"] == "nu" && t["formulation"] == "cg mean-dilation")
      md_trusted = t["trusted"] == json::array({0.3, 0.4999999});
  EXPECT_TRUE(md_trusted) << summary["trust"].dump();

  // A second run resumes: nothing is run again and the verdicts are the same bytes.
  const std::string first = slurp(out / "extremes.json");
  const std::string kp_lines = slurp(out / "kp" / "results.jsonl");
  const std::string nu_lines = slurp(out / "nu" / "results.jsonl");
  const RunResult again = run(args);
  ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
  EXPECT_EQ(slurp(out / "kp" / "results.jsonl"), kp_lines);
  EXPECT_EQ(slurp(out / "nu" / "results.jsonl"), nu_lines);
  EXPECT_EQ(slurp(out / "extremes.json"), first);
}

}  // namespace
}  // namespace vorodg

namespace vorodg {
namespace {

TEST(SceneLabels, NameThePenaltyAndTractionThatDifferFromTheDefaults) {
  // Two dg-sipg blocks that differ only in penalty scaling or traction must not share a label
  // (run ids are built from it); the formulation's own defaults add nothing.
  const Scene scene = parse_scene(R"({"problems": ["patch"], "meshes": [{"sizes": [0.5]}],
      "formulations": [{"name": "dg-sipg"}, {"name": "dg-sipg", "penalty": "h-avg"},
                       {"name": "dg-sipg", "traction": "point", "weighted_average": true},
                       {"name": "dg-nitsche", "penalty": "auto"}]})",
                                  "labels");
  std::vector<std::string> labels;
  for (const SceneFormulation& f : scene.formulations) labels.push_back(f.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"dg-sipg", "dg-sipg h-avg",
                                              "dg-sipg point-stress weighted", "dg-nitsche auto"}));
  EXPECT_EQ(scene.formulations[0].kp, (std::vector<double>{1.0}));
  EXPECT_EQ(scene.formulations[1].kp, (std::vector<double>{1000.0}));
}

}  // namespace
}  // namespace vorodg
