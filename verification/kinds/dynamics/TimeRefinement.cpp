// `time.refinement` in a dynamics or fragmentation scene (docs/dynamics.md, "Time refinement"):
// every part at each fraction of its step. The step is safety x (the chosen critical estimate) x
// (the laws' step factors), so scaling the safety scales the step and changes nothing else: the
// same meshes, seeds and physics at dt0, dt0 f_1, dt0 f_2, ... The history rows and the frames
// are written every `history_every / f` and `output_every / f` steps (rounded), so at the same
// times in every part (exactly where 1 / f is a whole number).
#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"

namespace vorodg {
namespace {

/// `part` at the fraction f of its step, labelled `label`.
DynamicsScene at_fraction(const DynamicsScene& part, double f, const std::string& label) {
  DynamicsScene q = part;
  q.variants.clear();
  q.safety = part.safety * f;
  q.step_fraction = f;
  q.refinement_base = part.label;
  q.label = label;
  // The history and the frames at the same times as the first part's.
  q.output_every = std::max(1, static_cast<int>(std::lround(part.output_every / f)));
  q.history_every = std::max(1, static_cast<int>(std::lround(part.history_every / f)));
  for (auto& [key, value] : q.settings) {
    if (key == "time.safety") value = exact_text(q.safety);
    if (key == "time.output_every") value = std::to_string(q.output_every);
    if (key == "time.history_every") value = std::to_string(q.history_every);
  }
  return q;
}

}  // namespace

DynamicsScene refined_scene(DynamicsScene top, const std::string& source) {
  if (!top.perturb_key.empty())
    throw InputError("scene " + source +
                     ": time.refinement beside perturb: expected one or the "
                     "other");
  std::vector<DynamicsScene> parts = top.variants;
  if (parts.empty()) parts.push_back(top);
  std::vector<DynamicsScene> refined;
  for (const DynamicsScene& part : parts) {
    if (part.refinement.empty()) {
      refined.push_back(part);
      continue;
    }
    const std::string prefix = part.label.empty() ? "" : part.label + "/";
    for (double f : part.refinement)
      refined.push_back(at_fraction(part, f, prefix + "dt-" + exact_text(f)));
    refined.back().name = top.name;
  }
  for (DynamicsScene& r : refined) r.name = top.name;
  top.variants = std::move(refined);
  return top;
}

}  // namespace vorodg
