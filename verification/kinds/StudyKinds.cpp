// The registry of study kinds: one line per kind. A kind lives in its own folder under
// verification/kinds/ and provides a function returning its StudyKind (harness/StudyKind.hpp).
#include "verification/harness/StudyKind.hpp"

namespace vorodg {

StudyKind convergence_kind();    // kinds/convergence
StudyKind penalty_sweep_kind();  // kinds/convergence
StudyKind patch_suite_kind();    // kinds/convergence
StudyKind tradeoff_kind();       // kinds/tradeoff
StudyKind extremes_kind();       // kinds/extremes
StudyKind fracture_kind();       // kinds/fracture (FractureStudy.cpp)
StudyKind dynamics_kind();       // kinds/dynamics (DynamicsStudy.cpp)
StudyKind fragmentation_kind();  // kinds/dynamics (DynamicsStudy.cpp)

const std::vector<StudyKind>& study_kinds() {
  static const std::vector<StudyKind> kinds = {
      convergence_kind(), penalty_sweep_kind(), patch_suite_kind(), tradeoff_kind(),
      extremes_kind(),    fracture_kind(),      dynamics_kind(),    fragmentation_kind()};
  return kinds;
}

}  // namespace vorodg
