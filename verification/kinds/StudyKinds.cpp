// The registry of study kinds, in the order messages and docs list them. A kind lives in its own
// folder under verification/kinds/ and provides <name>_kind() returning its StudyKind
// (harness/StudyKind.hpp); adding one is its folder and one line here, or one call of
// register_study_kind from any file (a test's toy kind).
#include "core/util/NamedRegistry.hpp"
#include "verification/harness/StudyKind.hpp"

#define VORODG_STUDY_KINDS(KIND)              \
  KIND(convergence)   /* kinds/convergence */ \
  KIND(penalty_sweep) /* kinds/convergence */ \
  KIND(patch_suite)   /* kinds/convergence */ \
  KIND(tradeoff)      /* kinds/tradeoff */    \
  KIND(extremes)      /* kinds/extremes */    \
  KIND(fracture)      /* kinds/fracture */    \
  KIND(dynamics)      /* kinds/dynamics */    \
  KIND(fragmentation) /* kinds/dynamics */

namespace vorodg {

#define VORODG_DECLARE_KIND(name) StudyKind name##_kind();
VORODG_STUDY_KINDS(VORODG_DECLARE_KIND)

namespace {

NamedRegistry<StudyKind>& registry() {
#define VORODG_LIST_KIND(name) name##_kind(),
  static NamedRegistry<StudyKind> kinds("study kind", {VORODG_STUDY_KINDS(VORODG_LIST_KIND)});
  return kinds;
}

}  // namespace

const std::vector<StudyKind>& study_kinds() {
  return registry().entries();
}

bool register_study_kind(StudyKind kind) {
  return registry().add(std::move(kind));
}

}  // namespace vorodg
