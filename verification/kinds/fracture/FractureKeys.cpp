// Every key of a fracture scene: the one table its reader (FractureScene.cpp) takes defaults and
// bounds from, and docs/scenes.md lists ("Fracture studies"; a test checks every row). The
// upper bounds are generous physical limits (no solid is stiffer than 1e13 Pa, no thickness of
// a plane model beyond 1 km): what they refuse is a value that would overflow the run.
#include "verification/kinds/fracture/FractureKeys.hpp"

#include "core/material/MaterialKeys.hpp"
#include "fracture/CohesiveKeys.hpp"
#include "fracture/FractureProblem.hpp"
#include "verification/harness/CommonKeys.hpp"
#include "verification/harness/StatisticalReport.hpp"
#include "verification/model/ElementKeys.hpp"
#include "verification/model/MaterialFieldKeys.hpp"

namespace vorodg {
namespace {

/// The study, the problem and its geometry.
std::vector<SceneKey> fracture_problem_keys() {
  return {
      key("study", "string", "fracture", "fracture", "the study kind"),
      key("label", "string", "\"\"", "any", "a variant's name and subfolder (variants[] only)"),
      key("problem", "string", "three-point-bend", fracture_problem_list(),
          "the bar pulled apart across a crack line, or Petersson's notched beam"),
      key("domain", "[x0, y0, x1, y1]", "[0, 0, 2, 0.2]", kRectangleRange,
          "the bar or the beam, m"),
      bounded("notch_depth", "number", "0", "0 <= notch_depth <= 1e6, below the height",
              "three-point bend: a traction-free slit at the crack line from the bottom, m", 0.0,
              false, 1e6),
  };
}

/// Where faces crack.
std::vector<SceneKey> cracking_keys() {
  return {
      key("cracking.mode", "string", "restricted",
          "pre-inserted, restricted, contiguous or arbitrary",
          "where faces crack: pre-inserted on the crack line, inserted on it, next to the notch "
          "or a crack, or anywhere (docs/fracture.md)"),
      bounded("cracking.line", "number", "mid-span", "-1e6 <= line <= 1e6, within the domain",
              "x of the crack line (the notch and the load point are on it), m", -1e6, false, 1e6),
      key("cracking.split_all", "bool", "false", "true or false",
          "split every interior edge (full DG) whatever the mode"),
  };
}

/// The load path: its control, its main stage and an optional tail.
std::vector<SceneKey> loading_keys() {
  return {
      key("loading.control", "string", "displacement", "displacement, cmod or arc-length",
          "the path's control: the load point's displacement, the crack mouth opening, or the "
          "energy released per step (follows snap-back)"),
      bounded("loading.max_displacement", "number", "0", "0 <= max_displacement <= 1000",
              "displacement control: the end of the main stage, m", 0.0, false, 1e3),
      bounded("loading.max_cmod", "number", "0", "0 <= max_cmod <= 1000",
              "cmod control: the end of the main stage, m", 0.0, false, 1e3),
      bounded("loading.steps", "integer", "100", "1 <= steps <= 1e7",
              "equal steps to that end (halved where Newton or the energy balance asks)", 1.0,
              false, 1e7),
      bounded("loading.tail.max_displacement", "number", "none",
              "beyond the main stage's end, <= 1000",
              "displacement control: the end of a second stage of equal steps, m", 0.0, true, 1e3),
      bounded("loading.tail.max_cmod", "number", "none", "beyond the main stage's end, <= 1000",
              "cmod control: the end of a second stage of equal steps, m", 0.0, true, 1e3),
      bounded("loading.tail.steps", "integer", "10", "1 <= steps <= 1e7",
              "the second stage's number of steps", 1.0, false, 1e7),
  };
}

/// The outputs and the variants.
std::vector<SceneKey> fracture_study_keys() {
  return {
      bounded("outputs.vtu_every", "integer", "10", "0 <= vtu_every <= 1e9",
              "write the deformed mesh every this many points (0: never)", 0.0, false, 1e9),
      variants_key(),
  };
}

std::vector<SceneKey> make_fracture_keys() {
  std::vector<SceneKey> keys = naming_keys();
  append_keys(keys, fracture_problem_keys());
  append_keys(keys, element_keys());
  append_keys(keys, elastic_keys("3e10", "0.2"));
  append_keys(keys, {bounded("material.thickness", "number", "1", "0 < thickness <= 1000",
                             "out of plane, m: loads in newtons and energies in joules include it",
                             0.0, true, 1e3)});
  append_keys(keys, material_field_keys());
  append_keys(keys, cohesive_keys({"3.33e6", "124", "1000", "0.75", "pre-inserted faces", ""}));
  append_keys(keys, cracking_keys());
  append_keys(keys, loading_keys());
  append_keys(keys, mesh_keys());
  append_keys(keys, fracture_study_keys());
  append_keys(keys, checkpoint_keys());
  append_keys(keys, statistics_keys());
  return keys;
}

}  // namespace

const KeyTable& fracture_scene_keys() {
  static const KeyTable table{"fracture",
                              make_fracture_keys(),
                              {{"cohesive.cohesion", "criterion.cohesion"},
                               {"cohesive.friction", "criterion.friction"},
                               {"cohesive.tensile_cutoff", "criterion.tensile_cutoff"}}};
  return table;
}

}  // namespace vorodg
