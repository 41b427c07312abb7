// Sensitivity studies (`perturb` in a fragmentation scene; verification/kinds/dynamics/
// PerturbationReport, docs/fragmentation.md):
//   - the reader turns perturb {key, values} into one variant per value, labelled perturb-<i>,
//     with the key set by name or JSON pointer and nothing else changed; perturb {variation,
//     seeds} into the uniform material and one variant per seed with the variation set; it refuses
//     perturb beside variants, fewer than two values, a key that is not a string, and a dynamics
//     study;
//   - on the stretched strip (200 quads, rate 1e5 /s), a repeated reference value gives distance 0
//     after every step (identical inputs, identical crack states), and a rate 2 % higher gives a
//     crack state that differs at some step; perturbation.csv has one row per step at which
//     either run cracked;
//   - `vorodg run` on such a scene writes the report and both plots (the Hamming distance, and
//     the fragment count against the varied key).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "core/util/Errors.hpp"
#include "support/RunVorodg.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"
#include "verification/kinds/dynamics/PerturbationReport.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;
using namespace vorodg::testing;

std::string strip(const std::string& extra, const std::string& study = "fragmentation") {
  return "{\"study\": \"" + study + R"(", "name": "sensitivity", "problem": "strip-expansion",
  "strain_rate": 1e5, "material": {"E": 275e9, "nu": 0.0, "density": 2750},
  "cohesive": {"strength": 3e8, "fracture_energy": 100},
  "contact": {"enabled": false}, "outputs": {"vtu": false},
  "meshes": [{"family": "quad", "sizes": [1e-05]}], )" +
         extra + "}";
}

TEST(PerturbationStudy, PerturbBecomesOneVariantPerValue) {
  const DynamicsScene s = parse_dynamics_scene(
      strip(R"("perturb": {"key": "strain_rate", "values": [1e5, 2e5]})"), "test");
  ASSERT_EQ(s.variants.size(), 2u);
  EXPECT_EQ(s.variants[0].label, "perturb-0");
  EXPECT_EQ(s.variants[1].label, "perturb-1");
  EXPECT_EQ(std::stod(s.variants[0].setting("strain_rate")), 1e5);
  EXPECT_EQ(std::stod(s.variants[1].setting("strain_rate")), 2e5);
  EXPECT_EQ(s.variants[1].cohesive.strength, 3e8);  // nothing else changed
  EXPECT_EQ(s.perturb_key, "strain_rate");
  const DynamicsScene p = parse_dynamics_scene(
      strip(R"("perturb": {"key": "/cohesive/strength", "values": [3e8, 3.3e8]})"), "test");
  EXPECT_EQ(p.variants[1].cohesive.strength, 3.3e8);
  EXPECT_EQ(p.variants[1].cohesive.fracture_energy, 100.0);
  EXPECT_EQ(std::stod(p.variants[1].setting("strain_rate")), 1e5);
}

TEST(PerturbationStudy, MaterialVariationBesideTheUniformMaterial) {
  const DynamicsScene s =
      parse_dynamics_scene(strip(R"("perturb": {"variation": 0.05, "seeds": [4, 9]})"), "test");
  ASSERT_EQ(s.variants.size(), 3u);
  EXPECT_EQ(s.variants[0].variation, 0.0);  // the reference: the uniform material
  EXPECT_EQ(s.variants[1].variation, 0.05);
  EXPECT_EQ(s.variants[1].variation_seed, 4u);
  EXPECT_EQ(s.variants[2].variation_seed, 9u);
  EXPECT_EQ(s.perturb_key, "/material/variation_seed");
  EXPECT_EQ(s.perturb_values.front(), "\"uniform\"");
  EXPECT_THROW(parse_dynamics_scene(strip(R"("perturb": {"variation": 0.05})"), "t"), InputError);
  EXPECT_THROW(parse_dynamics_scene(strip(R"("perturb": {"variation": 1.5, "seeds": [1]})"), "t"),
               InputError);
}

TEST(PerturbationStudy, RefusesWhatItCannotCompare) {
  const std::string good = R"("perturb": {"key": "strain_rate", "values": [1e5, 2e5]})";
  EXPECT_THROW(parse_dynamics_scene(strip(good + R"(, "variants": [{"label": "a"}])"), "test"),
               InputError);
  EXPECT_THROW(
      parse_dynamics_scene(strip(R"("perturb": {"key": "strain_rate", "values": [1e5]})"), "t"),
      InputError);
  EXPECT_THROW(parse_dynamics_scene(strip(R"("perturb": {"key": 3, "values": [1, 2]})"), "t"),
               InputError);
  EXPECT_THROW(parse_dynamics_scene(strip(good, "dynamics"), "test"), InputError);
}

TEST(PerturbationStudy, IdenticalInputsGiveIdenticalCracks) {
  const DynamicsScene s = parse_dynamics_scene(
      strip(R"("perturb": {"key": "strain_rate", "values": [1e5, 1e5, 1.02e5]})"), "test");
  const fs::path out = fs::temp_directory_path() / ("vorodg_perturb_" + std::to_string(getpid()));
  fs::remove_all(out);
  for (const DynamicsScene& v : s.variants) {
    const DynamicsRecord r = run_dynamics(v, ensemble_runs(v.meshes).front(), out / v.label);
    ASSERT_TRUE(r.complete) << r.failure;
  }
  write_perturbation_report(s, out);
  std::ifstream csv(out / "perturbation.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "variant,value,run,step,distance");
  std::map<std::string, int> rows, largest;
  while (std::getline(csv, line)) {
    const std::string variant = line.substr(0, line.find(','));
    const int distance = std::stoi(line.substr(line.rfind(',') + 1));
    ++rows[variant];
    largest[variant] = std::max(largest[variant], distance);
  }
  EXPECT_GT(rows["perturb-1"], 0);
  EXPECT_EQ(largest["perturb-1"], 0);
  EXPECT_GT(largest["perturb-2"], 0);
  EXPECT_TRUE(fs::exists(out / "perturbation.md"));
  fs::remove_all(out);
}

TEST(PerturbationStudy, RunWritesTheReportAndPlots) {
  const fs::path dir =
      fs::temp_directory_path() / ("vorodg_perturb_cli_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = dir / "sensitivity.json", out = dir / "out";
  std::ofstream(scene) << strip(R"("perturb": {"key": "strain_rate", "values": [1e5, 1.02e5]})");
  const RunResult r =
      run_program(VORODG_EXE, {"run", scene.string(), "-o", out.string(), "--quiet"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "perturb-1" / "results.csv"));
  EXPECT_TRUE(fs::exists(out / "perturbation.csv"));
  EXPECT_TRUE(fs::exists(out / "perturbation.md"));
  EXPECT_TRUE(fs::exists(out / "plots" / "perturbation_hamming.png")) << r.err;
  EXPECT_TRUE(fs::exists(out / "plots" / "fragments_by_variant.png")) << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vorodg
