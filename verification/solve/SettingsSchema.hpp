#pragma once
// One schema of every setting of a solve. A setting is a scene key's row (core/schema's SceneKey:
// the key within its scope's object, type, default, range, doc and numeric bounds: the one schema
// type of every key of every kind) bound to SolveSettings and to a `vorodg solve` option.
// Defaults are read from a default-constructed SolveSettings (the one place they are written);
// ranges are stated here once. The command line (verification/cli) and the scene reader
// (verification/study) are thin adapters over it, check_settings() is the one validation, and
// `--help` and docs/scenes.md are generated from or tested against it.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/schema/SceneKeys.hpp"
#include "core/util/Bounds.hpp"
#include "core/util/Format.hpp"
#include "verification/model/Choices.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {

enum class SettingKind { number, integer, flag, choice };
/// Where a setting lives in a scene: the top level, `material`, `formulations[i]`, `outputs`;
/// `command_line` settings exist only as `vorodg solve` options.
enum class SettingScope { top, material, formulation, outputs, command_line };

/// A setting: its row (name: the key within its scope's object; type; fallback: the default as
/// text, or in words where it depends on the formulation; range: what is accepted, in words;
/// doc; bounds: of a number or integer, those of `allowed` where it lists values) and its binding.
struct SettingSpec : SceneKey {
  std::string flag;    // `vorodg solve` option; empty: none
  std::string symbol;  // the quantity's name in messages ("k_p", "nu")
  SettingKind kind = SettingKind::number;
  SettingScope scope = SettingScope::formulation;
  std::vector<int> allowed;          // integers: the only values allowed (empty: any in bounds)
  const Choices* choices = nullptr;  // choice settings
  bool flag_negates = false;         // the flag sets the value to false (--no-correction)
  bool default_depends = false;      // the default depends on the formulation (fallback says how)
  // Numbers, integers and flags (0 or 1) travel as double; choices as their name.
  std::function<double(const SolveSettings&)> get;
  std::function<void(SolveSettings&, double)> set;
  std::function<std::string(const SolveSettings&)> get_text;
  std::function<void(SolveSettings&, const std::string&)> set_text;
};

/// Every setting, in the order `--help` and docs/scenes.md list them.
const std::vector<SettingSpec>& setting_specs();
/// The spec of a scene key; throws std::out_of_range for an unknown one.
const SettingSpec& setting_spec(const std::string& key);

/// The setting's value in `settings` as text: numbers exact, flags true/false, choices by name.
std::string value_text(const SettingSpec& spec, const SolveSettings& settings);

/// A value outside its range: "0.5: expected -1 < nu < 0.5"; none if it is valid.
std::optional<std::string> check_value(const SettingSpec& spec, double value);
std::optional<std::string> check_text(const SettingSpec& spec, const std::string& text);

struct SettingError {
  const SettingSpec* spec;
  std::string message;  // without the setting's name: adapters add the flag or the scene key
};
/// The one validation of a solve's settings: the first setting out of its range, if any.
std::optional<SettingError> check_settings(const SolveSettings& settings);

}  // namespace vorodg
