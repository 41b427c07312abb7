#include "verification/cli/SettingOptions.hpp"

#include "core/util/Errors.hpp"
#include "verification/cli/CliSupport.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace vorodg {

void add_setting_options(CLI::App& cmd, SettingOptions& o) {
  for (const SettingSpec& spec : setting_specs()) {
    if (spec.flag.empty()) continue;
    const SettingSpec* p = &spec;  // the schema is static: its address outlives the command
    switch (spec.kind) {
      case SettingKind::flag:
        cmd.add_flag_callback(
            spec.flag, [p, &o] { p->set(o.settings, p->flag_negates ? 0.0 : 1.0); }, spec.doc);
        break;
      case SettingKind::number:
        cmd.add_option_function<double>(
               spec.flag, [p, &o](const double& v) { p->set(o.settings, v); }, spec.doc)
            ->default_str(spec.fallback)
            ->check(finite_number());
        break;
      case SettingKind::integer:
        cmd.add_option_function<int>(
               spec.flag, [p, &o](const int& v) { p->set(o.settings, v); },
               spec.doc + " (" + spec.range + ")")
            ->default_str(spec.fallback);
        break;
      case SettingKind::choice:
        cmd.add_option_function<std::string>(
               spec.flag, [p, &o](const std::string& v) { o.choice_texts[p->name] = v; },
               spec.doc + ": " + choice_alternatives(*spec.choices))
            ->default_str(spec.fallback);
        break;
    }
  }
}

}  // namespace vorodg
