#pragma once
// The L2 rate against k_p of every DG reading of a study, beside CG's on the same meshes: the
// trend the report's Figure 26 shows (rates rising with k_p), stated from our numbers. A rise
// counts only where it exceeds the two 95% intervals; a reading "reaches CG" where its rate at
// its largest k_p is within the two intervals of CG's.
#include <sstream>

#include "verification/static/StudySummary.hpp"

namespace vorodg {

void write_kp_trend(const StudySummary& summary, std::ostringstream& md);

}  // namespace vorodg
