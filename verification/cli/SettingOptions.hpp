#pragma once
// The command-line adapter of the settings schema: one option per schema setting that has a
// flag, with the schema's doc and default, filling SettingOptions (api/SolveOptions), whose
// checked_settings is the schema's one validation.
#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "verification/api/SolveOptions.hpp"

namespace vorodg {

/// Registers the schema's options on `command`, writing into `options`.
void add_setting_options(CLI::App& command, SettingOptions& options);

}  // namespace vorodg
