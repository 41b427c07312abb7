// The fragmentation study kind (a dynamics scene with cracks; verification/kinds/dynamics,
// docs/fragmentation.md):
//   - the reader refuses fragmentation keys in a dynamics study, strip-expansion outside a
//     fragmentation study, the Lanczos step estimate with interfaces coupled from the start
//     (valid for the uncracked map only; without them it is accepted), a
//     negative fracture energy, and a K0 too small for the law's peak to come before delta_c,
//     each with an InputError;
//   - one run of the stretched strip (2 mm x 10 um, 200 quads, alumina, rate 1e5 /s, the default
//     K0 = 10 E / h): fragments = broken edges + 1, the discrete energy balance to 1e-10 of the
//     input, the balance with the law's closed forms within 1 % (measured 1.1e-3: the step's
//     error at the law's kinks, docs/fragmentation.md), fragments/<id>.csv masses summing to
//     rho x area to 1e-12, and cracks/<id>.csv with one row per cracked edge; the mass in
//     single-cell fragments is what fragments/<id>.csv gives for the one-cell rows;
//   - a body too strong to crack, spun at 10 rad/s for 50 ms with corotational kinematics: one
//     fragment, no sand, and the main body's turn is 0.5 rad to 1e-3 (its elastic wobble).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

const std::string kStrip = R"("problem": "strip-expansion", "strain_rate": 1e5,
  "material": {"E": 275e9, "nu": 0.0, "density": 2750},
  "contact": {"enabled": false}, "outputs": {"vtu": false},
  "meshes": [{"family": "quad", "sizes": [1e-05]}])";

std::string scene(const std::string& extra, const std::string& study = "fragmentation") {
  return "{\"study\": \"" + study + "\", " + kStrip + (extra.empty() ? "" : ", " + extra) + "}";
}

TEST(FragmentationStudy, RefusesWhatItCannotRun) {
  EXPECT_NO_THROW(parse_dynamics_scene(scene(""), "test"));
  const std::string wall = R"({"study": "dynamics", "problem": "wall-impact",
    "cohesive": {"strength": 1e6}, "meshes": [{"family": "quad", "sizes": [0.05]}]})";
  EXPECT_THROW(parse_dynamics_scene(wall, "test"), InputError);
  EXPECT_THROW(parse_dynamics_scene(scene("", "dynamics"), "test"), InputError);
  EXPECT_EQ(parse_dynamics_scene(scene(""), "test").estimate, StepEstimate::cells);
  EXPECT_EQ(parse_dynamics_scene(scene(R"("time": {"estimate": "lanczos"})"), "test").estimate,
            StepEstimate::lanczos);
  EXPECT_NO_THROW(
      parse_dynamics_scene(scene(R"("interfaces": "dg", "kinematics": "small")"), "test"));
  EXPECT_THROW(
      parse_dynamics_scene(
          scene(R"("interfaces": "dg", "kinematics": "small", "time": {"estimate": "lanczos"})"),
          "test"),
      InputError);
  EXPECT_THROW(parse_dynamics_scene(scene(R"("cohesive": {"fracture_energy": -1})"), "test"),
               InputError);
  const DynamicsScene soft =
      parse_dynamics_scene(scene(R"("cohesive": {"initial_stiffness": 1e-6})"), "test");
  const fs::path out = fs::temp_directory_path() / ("vorodg_frag_soft_" + std::to_string(getpid()));
  EXPECT_THROW(run_dynamics(soft, ensemble_runs(soft.meshes).front(), out), InputError);
  fs::remove_all(out);
}

TEST(FragmentationStudy, StretchedStripRun) {
  const DynamicsScene s = parse_dynamics_scene(scene(""), "test");
  const fs::path out =
      fs::temp_directory_path() / ("vorodg_frag_strip_" + std::to_string(getpid()));
  fs::remove_all(out);
  const EnsembleRunId id = ensemble_runs(s.meshes).front();
  const DynamicsRecord r = run_dynamics(s, id, out);
  const DynamicsMeasures& m = r.measures;
  std::printf(
      "strip run: %ld steps, %g cracked, %g broken, %g fragments, largest %.3f of the mass, "
      "dissipated %.4e J/m; balance %.1e, with the law's closed forms %.2e\n",
      r.steps, m.cracked_edges, m.broken_edges, m.fragments, m.max_fragment_mass_fraction,
      m.dissipated_energy, m.max_energy_balance_error, m.law_balance_error);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_GT(m.broken_edges, 1);
  EXPECT_EQ(m.fragments, m.broken_edges + 1);
  EXPECT_LT(m.max_energy_balance_error, 1e-10);
  EXPECT_LT(m.law_balance_error, 0.01);
  std::ifstream fragments(out / "fragments" / (id.id() + ".csv"));
  std::string line;
  std::getline(fragments, line);
  EXPECT_EQ(line, "fragment,mass,cells,x,y,vx,vy");
  double mass = 0.0, sand = 0.0;
  int rows = 0;
  while (std::getline(fragments, line)) {
    std::istringstream row(line);
    std::string id_text, mass_text, cells_text;
    std::getline(row, id_text, ','), std::getline(row, mass_text, ','),
        std::getline(row, cells_text, ',');
    mass += std::stod(mass_text);
    if (std::stoi(cells_text) == 1) sand += std::stod(mass_text);
    ++rows;
  }
  EXPECT_EQ(rows, m.fragments);
  EXPECT_NEAR(m.single_cell_mass_fraction, sand / mass, 1e-12);
  EXPECT_NEAR(mass, 2750.0 * 0.002 * 1e-5, 1e-12 * 2750.0 * 0.002 * 1e-5);
  std::ifstream cracks(out / "cracks" / (id.id() + ".csv"));
  std::getline(cracks, line);
  EXPECT_EQ(line, "step,edge");
  rows = 0;
  while (std::getline(cracks, line)) ++rows;
  EXPECT_EQ(rows, m.cracked_edges);
  fs::remove_all(out);
}

TEST(FragmentationStudy, TheMainBodysTurnOfASpinningBody) {
  const DynamicsScene s = parse_dynamics_scene(R"({"study": "fragmentation", "problem": "free-body",
    "initial_velocity": [0, 0], "angular_velocity": 10, "kinematics": "corotational",
    "material": {"E": 2e11, "nu": 0.3, "density": 7800}, "cohesive": {"strength": 1e9, "fracture_energy": 1e7},
    "contact": {"enabled": false}, "outputs": {"vtu": false}, "time": {"end": 0.05},
    "meshes": [{"family": "quad", "sizes": [0.25]}]})",
                                               "test");
  const fs::path out = fs::temp_directory_path() / ("vorodg_frag_spin_" + std::to_string(getpid()));
  fs::remove_all(out);
  const DynamicsRecord r = run_dynamics(s, ensemble_runs(s.meshes).front(), out);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_EQ(r.measures.fragments, 1);
  EXPECT_EQ(r.measures.single_cell_mass_fraction, 0.0);
  EXPECT_NEAR(r.measures.main_body_rotation, 10.0 * r.end_time, 1e-3);
  fs::remove_all(out);
}

}  // namespace
}  // namespace vorodg
