#include "verification/static/TradeoffSettings.hpp"

#include <algorithm>

#include "core/schema/SceneKeyReader.hpp"
#include "core/schema/SceneObject.hpp"
#include "verification/static/StaticSceneKeys.hpp"

namespace vorodg {

TradeoffSettings read_tradeoff_settings(SceneObject& block) {
  TradeoffSettings s;
  const auto number = [&](const std::string& name, double fallback) {
    return checked_number(block, name, static_key("tradeoff." + name), fallback);
  };
  s.rate_tolerance = number("rate_tolerance", s.rate_tolerance);
  s.min_seconds = number("min_seconds", s.min_seconds);
  s.targets = block.numbers("targets", {});
  for (double e : s.targets)
    if (const auto bad = check_key(static_key("tradeoff.targets"), e))
      block.fail_value("targets", *bad);
  std::sort(s.targets.rbegin(), s.targets.rend());  // largest first, as the report reads them
  s.verify = block.flag("verify", s.verify);
  s.verification_realizations =
      block.integer("verification_realizations", s.verification_realizations);
  if (const auto bad =
          check_key(static_key("tradeoff.verification_realizations"), s.verification_realizations))
    block.fail_value("verification_realizations", *bad);
  block.finish();
  return s;
}

}  // namespace vorodg
