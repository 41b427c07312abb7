// Every element family in the dynamics and fragmentation study kinds (`element`,
// `vem_stabilization`; docs/element.md):
//   - the reader takes each family's name, echoes it, and refuses an unknown name or a
//     non-positive stabilization scale with an InputError;
//   - a wave bar on a hexagon mesh (convex cells, so Wachspress too): the measured speed within
//     1% of the bar speed and the energy balance to 1e-10 of the input, for each element;
//   - the elements differ where they should: the cells' stable step of VEM is not RK's (the same
//     mesh gives a different stiffness), so the run really used the element it names;
//   - the stretched strip cracks with each element: fragments = broken edges + 1 and the energy
//     balance to 1e-10, as with the default element.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

const char* kWaveBar = R"({"study": "dynamics", "problem": "wave-bar",
  "meshes": [{"family": "hex", "sizes": [0.0125]}], "outputs": {"vtu": false}, )";

const char* kStrip = R"({"study": "fragmentation", "problem": "strip-expansion",
  "strain_rate": 1e5, "material": {"E": 275e9, "nu": 0.0, "density": 2750},
  "contact": {"enabled": false}, "outputs": {"vtu": false},
  "meshes": [{"family": "quad", "sizes": [1e-05]}], )";

std::string element_key(const std::string& name) {
  return "\"element\": \"" + name + "\"}";
}

DynamicsRecord run_first(const std::string& text, const std::string& tag) {
  const DynamicsScene scene = parse_dynamics_scene(text, "test scene");
  const fs::path out = fs::temp_directory_path() /
                       ("vorodg_test_DynamicsElements_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(out);
  DynamicsRecord r = run_dynamics(scene, ensemble_runs(scene.meshes).front(), out);
  fs::remove_all(out);
  return r;
}

TEST(DynamicsElements, TheReaderTakesEveryFamilyAndRefusesOthers) {
  for (const NamedChoice& family : element_choices()) {
    const DynamicsScene s = parse_dynamics_scene(kWaveBar + element_key(family.name), "test");
    EXPECT_EQ(element_name(s.element.family), family.name);
    bool echoed = false;
    for (const auto& [key, value] : s.settings) echoed |= key == "element" && value == family.name;
    EXPECT_TRUE(echoed) << family.name;
  }
  EXPECT_EQ(
      parse_dynamics_scene(std::string(kWaveBar) + "\"sides\": \"free\"}", "test").element.family,
      ElementFamily::rk);
  EXPECT_THROW(parse_dynamics_scene(kWaveBar + element_key("q4"), "test"), InputError);
  EXPECT_THROW(parse_dynamics_scene(std::string(kWaveBar) + "\"vem_stabilization\": 0}", "test"),
               InputError);
}

TEST(DynamicsElements, EveryElementCarriesTheWaveAtTheBarSpeed) {
  double rk_step = 0.0, vem_step = 0.0;
  for (const NamedChoice& family : element_choices()) {
    const DynamicsRecord r = run_first(kWaveBar + element_key(family.name), family.name);
    std::printf(
        "wave bar, hex, %-10s %d cells: speed error %+.3f%%, cells' step %.4e s, energy "
        "balance %.1e\n",
        family.name.c_str(), r.cells, 100 * r.measures.wave_speed_error, r.dt_cells,
        r.measures.max_energy_balance_error);
    ASSERT_TRUE(r.complete) << family.name << ": " << r.failure;
    EXPECT_LT(std::abs(r.measures.wave_speed_error), 0.01) << family.name;
    EXPECT_LT(r.measures.max_energy_balance_error, 1e-10) << family.name;
    if (family.name == "rk") rk_step = r.dt_cells;
    if (family.name == "vem") vem_step = r.dt_cells;
  }
  EXPECT_GT(std::abs(vem_step / rk_step - 1.0), 1e-6);
}

TEST(DynamicsElements, TheStripCracksWithEveryElement) {
  for (const NamedChoice& family : element_choices()) {
    const DynamicsRecord r = run_first(kStrip + element_key(family.name), "strip_" + family.name);
    const DynamicsMeasures& m = r.measures;
    std::printf("strip, %-10s %ld steps: %g broken, %g fragments, balance %.1e\n",
                family.name.c_str(), r.steps, m.broken_edges, m.fragments,
                m.max_energy_balance_error);
    ASSERT_TRUE(r.complete) << family.name << ": " << r.failure;
    EXPECT_GT(m.broken_edges, 1) << family.name;
    EXPECT_EQ(m.fragments, m.broken_edges + 1) << family.name;
    EXPECT_LT(m.max_energy_balance_error, 1e-10) << family.name;
  }
}

}  // namespace
}  // namespace vorodg
