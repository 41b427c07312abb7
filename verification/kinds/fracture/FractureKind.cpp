// The fracture study: cohesive crack growth along a quasi-static load path, each variant of the
// scene into its own subfolder (FractureStudy). A run whose path could not be followed to its
// end keeps its converged points; the study then exits 3.
#include "verification/fracture/FractureKeys.hpp"
#include "verification/fracture/FractureStudy.hpp"
#include "verification/harness/StudyParts.hpp"

namespace vorodg {
namespace {

int run_fracture_scene(const StudyCall& call) {
  return run_study_parts<FractureScene>(
      read_fracture_scene(call.scene), call, "fracture", "fracture_plots.py",
      [&](const FractureScene& part, const std::filesystem::path& out) {
        const FractureStudyResult r = run_fracture_study(part, out, call.threads, call.progress);
        return PartCounts{r.records.size(), r.incomplete};
      });
}

}  // namespace

StudyKind fracture_kind() {
  return {"fracture",
          "cohesive crack growth along a load path: curves, cracks, distributions per level",
          [](const std::string& text, const std::string& source) {
            return parse_fracture_scene(text, source).description;
          },
          run_fracture_scene, [] { return fracture_scene_keys().keys; }};
}

}  // namespace vorodg
