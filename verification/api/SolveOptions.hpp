#pragma once
// A solve's settings as the user gave them, by option: numbers set as they are parsed, choices
// kept as text until the schema's one validation, whose messages name the option as written
// ("--kp 0: expected k_p > 0 ..."). The `solve` command (cli/SettingOptions registers the
// options) and the Python module's keywords fill the same struct and get the same checks.
#include <map>
#include <string>

#include "verification/solve/SolveRun.hpp"

namespace vorodg {

struct SettingOptions {
  SolveSettings settings;
  std::map<std::string, std::string> choice_texts;  // choice settings given, by key, unchecked
};

/// The settings the options describe; throws InputError naming the first bad option.
SolveSettings checked_settings(const SettingOptions& options);
/// The values, by flag, of the settings whose default depends on others (the penalty scaling
/// and k_p depend on the formulation): what an echoed command line must state to be reproduced.
std::map<std::string, std::string> resolved_defaults(const SolveSettings& settings);

/// The threads of one solve by default: every core of the machine.
int default_solve_threads();

}  // namespace vorodg
