#include "verification/study/TradeoffSettings.hpp"

#include <algorithm>

#include "verification/harness/SceneObject.hpp"

namespace vorodg {

TradeoffSettings read_tradeoff_settings(SceneObject& block) {
  TradeoffSettings s;
  s.rate_tolerance = block.number("rate_tolerance", s.rate_tolerance);
  if (!(s.rate_tolerance > 0 && s.rate_tolerance < 1))
    block.fail_value("rate_tolerance", "expected 0 < rate_tolerance < 1");
  s.min_seconds = block.number("min_seconds", s.min_seconds);
  if (!(s.min_seconds >= 0)) block.fail_value("min_seconds", "expected >= 0");
  s.targets = block.numbers("targets", {});
  for (double e : s.targets)
    if (!(e > 0)) block.fail_value("targets", "expected errors > 0");
  std::sort(s.targets.rbegin(), s.targets.rend());  // largest first, as the report reads them
  s.verify = block.flag("verify", s.verify);
  s.verification_realizations =
      block.integer("verification_realizations", s.verification_realizations);
  if (s.verification_realizations < 1)
    block.fail_value("verification_realizations", "expected >= 1");
  block.finish();
  return s;
}

}  // namespace vorodg
