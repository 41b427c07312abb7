#pragma once
// Error against wall time over a scene's knobs: per (variant, level) the mean L2 error and the
// median total seconds over the realizations; the Pareto front (no other configuration is both
// cheaper and more accurate); per knob, its cost and accuracy against the first formulation at
// the same level. Wall times are not deterministic, so all of this goes to tradeoff.json and
// report.md, never to summary.json.
#include <filesystem>
#include <sstream>
#include <vector>

#include "verification/model/RunRecord.hpp"

namespace vorodg {

void write_tradeoff(const std::vector<RunRecord>& records, const std::filesystem::path& out,
                    std::ostringstream& md);

}  // namespace vorodg
