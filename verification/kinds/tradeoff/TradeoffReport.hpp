#pragma once
// The trade-off study's report (TradeoffAnalysis): which configurations converge and why the
// others are excluded, what accuracy costs (error-cost slopes, seconds per DOF, the spread of
// the timings), the Pareto front of the admitted ones, the recommendation for three target
// errors and the check of the smallest (TradeoffVerification). Wall times are not
// deterministic, so all of this goes to tradeoff.json and report.md, never to summary.json.
#include <filesystem>
#include <sstream>
#include <vector>

#include "verification/solve/RunRecord.hpp"
#include "verification/static/StudySummary.hpp"

namespace vorodg {

void write_tradeoff(const Scene& scene, const StudySummary& summary,
                    const std::vector<RunRecord>& records, const std::filesystem::path& out,
                    std::ostringstream& md);

}  // namespace vorodg
