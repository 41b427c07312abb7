#pragma once
// The command-line adapter of the settings schema: one option per schema setting that has a
// flag, with the schema's doc and default; after parsing, the schema's one validation, its
// messages naming the option as the user wrote it ("--kp 0: expected k_p > 0 ...").
#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "verification/solve/SolveRun.hpp"

namespace vorodg {

struct SettingOptions {
  SolveSettings settings;
  std::map<std::string, std::string> choice_texts;  // choice settings given, by key, unchecked
};

/// Registers the schema's options on `command`, writing into `options`.
void add_setting_options(CLI::App& command, SettingOptions& options);
/// The settings the options describe; throws InputError naming the first bad option.
SolveSettings checked_settings(const SettingOptions& options);
/// The values, by flag, of the settings whose default depends on others (the penalty scaling
/// and k_p depend on the formulation): what an echoed command line must state to be reproduced.
std::map<std::string, std::string> resolved_defaults(const SolveSettings& settings);

}  // namespace vorodg
