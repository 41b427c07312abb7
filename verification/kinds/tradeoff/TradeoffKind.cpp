// The trade-off study: error against wall time over the knobs, the Pareto front and a
// recommendation, which is checked by running it once more before the report
// (TradeoffVerification; docs/tradeoff.md).
#include "verification/study/StaticStudy.hpp"
#include "verification/study/TradeoffVerification.hpp"

namespace vorodg {

StudyKind tradeoff_kind() {
  return {"trade-off", "error against wall time over the knobs; Pareto front", read_static_scene,
          [](const StudyCall& call) {
            const Scene scene = read_scene(call.scene);
            return run_static_study(
                scene, call,
                [&](const std::vector<RunRecord>& results, const StudyOptions& options) {
                  run_tradeoff_check(scene, results, options);
                });
          },
          static_scene_keys};
}

}  // namespace vorodg
