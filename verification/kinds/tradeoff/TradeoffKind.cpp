// The trade-off study: error against wall time over the knobs, the Pareto front and a
// recommendation, which is checked by running it once more before the report
// (TradeoffVerification; docs/tradeoff.md).
#include "verification/kinds/tradeoff/TradeoffReport.hpp"
#include "verification/kinds/tradeoff/TradeoffVerification.hpp"
#include "verification/static/StaticStudy.hpp"

namespace vorodg {
namespace {

constexpr StaticSceneForm kTradeoffForm{false, true};  // with its tradeoff block

/// The convergence tables, then the trade-off: the Pareto front and the recommendation.
int tradeoff_sections(const ReportInput& in, std::ostringstream& md) {
  convergence_sections(in, md);
  write_tradeoff(in.scene, in.summary, in.records, in.out, md);
  return 0;
}

}  // namespace

StudyKind tradeoff_kind() {
  return {"trade-off", "error against wall time over the knobs; Pareto front",
          static_scene_reader(kTradeoffForm),
          [](const StudyCall& call) {
            const Scene scene = read_scene(call.scene, kTradeoffForm);
            return run_static_study(
                scene, call, tradeoff_sections,
                [&](const std::vector<RunRecord>& results, const StudyOptions& options) {
                  run_tradeoff_check(scene, results, options);
                });
          },
          static_scene_keys};
}

}  // namespace vorodg
