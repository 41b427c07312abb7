#pragma once
// How two runs' crack states drift apart over time (report section 7, its Figure 22): cracks
// never heal, so a run's crack state after step s is the set of edges whose crack event came at or
// before s, and the Hamming distance of two runs on the same mesh after step s is the size of the
// symmetric difference of those sets. This works on the event lists alone (cracks/<run id>.csv),
// so runs can be compared after they finished, without their meshes.
#include <vector>

namespace vorodg {

/// A crack formed: edge `edge` cracked after step `step`.
struct CrackEvent {
  long step;
  int edge;
};

struct DistanceAtStep {
  long step;
  int distance;
};

/// The Hamming distance between the crack states of runs `a` and `b` after every step at which
/// either gained a crack, in step order (one entry per such step; empty if neither cracked).
/// Events need not be sorted. An edge listed twice in one run is refused with an InputError.
std::vector<DistanceAtStep> hamming_history(const std::vector<CrackEvent>& a,
                                            const std::vector<CrackEvent>& b);

}  // namespace vorodg
