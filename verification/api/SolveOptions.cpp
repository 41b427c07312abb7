#include "verification/api/SolveOptions.hpp"

#include <algorithm>
#include <thread>

#include "core/util/Errors.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace vorodg {

SolveSettings checked_settings(const SettingOptions& o) {
  SolveSettings settings = o.settings;
  for (const auto& [key, text] : o.choice_texts) {
    const SettingSpec& spec = setting_spec(key);
    if (const auto message = check_text(spec, text)) throw InputError(spec.flag + " " + *message);
    spec.set_text(settings, text);
  }
  if (const auto error = check_settings(settings))
    throw InputError(error->spec->flag + " " + error->message);
  return settings;
}

std::map<std::string, std::string> resolved_defaults(const SolveSettings& settings) {
  std::map<std::string, std::string> out;
  for (const SettingSpec& spec : setting_specs())
    if (spec.default_depends && !spec.flag.empty()) out[spec.flag] = value_text(spec, settings);
  return out;
}

int default_solve_threads() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace vorodg
