// The settings schema (verification/solve/SettingsSchema): one name, default, range and doc per
// setting; the one validation; and the documents that must agree with it (docs/scenes.md and
// `vorodg solve --help`).
#include "verification/solve/SettingsSchema.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "support/RunVorodg.hpp"

namespace vorodg {
namespace {

const std::filesystem::path kRepo =
    std::filesystem::path(VORODG_TEST_DATA).parent_path().parent_path();

TEST(SettingsSchema, KeysAndFlagsAreUnique) {
  std::set<std::string> keys, flags;
  for (const SettingSpec& spec : setting_specs()) {
    EXPECT_TRUE(keys.insert(spec.name).second) << spec.name;
    if (!spec.flag.empty()) {
      EXPECT_TRUE(flags.insert(spec.flag).second) << spec.flag;
    }
    EXPECT_FALSE(spec.doc.empty()) << spec.name;
  }
}

/// A setting is a scene key's row: the generic key check (core/schema) and the settings' own
/// check agree on every numeric setting's default and just beyond its bounds.
TEST(SettingsSchema, EverySettingIsASceneKeyRowThatChecksAsTheSchemaDoes) {
  const SolveSettings defaults;
  for (const SettingSpec& spec : setting_specs()) {
    if (!spec.is_number()) continue;
    const SceneKey& row = spec;
    EXPECT_EQ(row.type, spec.kind == SettingKind::number ? "number" : "integer") << spec.name;
    if (!spec.default_depends) {
      EXPECT_FALSE(check_key(row, spec.get(defaults)).has_value()) << spec.name;
      EXPECT_FALSE(check_value(spec, spec.get(defaults)).has_value()) << spec.name;
    }
    for (const std::optional<double>& bound : {spec.bounds.lower, spec.bounds.upper}) {
      if (!bound) continue;
      const double beyond =
          *bound + (bound == spec.bounds.upper ? 1.0 : -1.0) * std::max(1.0, std::abs(*bound));
      EXPECT_TRUE(check_key(row, beyond).has_value()) << spec.name << " " << beyond;
      EXPECT_TRUE(check_value(spec, beyond).has_value()) << spec.name << " " << beyond;
    }
  }
}

TEST(SettingsSchema, DefaultsAreTheDefaultSettingsAndValid) {
  EXPECT_FALSE(check_settings(SolveSettings{}).has_value());
  EXPECT_EQ(setting_spec("nu").fallback, "0.3");
  EXPECT_EQ(setting_spec("kp").fallback, "1 with penalty auto, else 1000");
  SolveSettings sipg, nitsche;
  sipg.formulation = "dg-sipg";
  nitsche.formulation = "dg-nitsche";
  EXPECT_EQ(value_text(setting_spec("kp"), sipg), "1");
  EXPECT_EQ(value_text(setting_spec("penalty"), sipg), "auto");
  EXPECT_EQ(value_text(setting_spec("traction"), sipg), "fan");
  EXPECT_EQ(value_text(setting_spec("kp"), nitsche), "1000");
  EXPECT_EQ(value_text(setting_spec("penalty"), nitsche), "h-avg");
  EXPECT_EQ(value_text(setting_spec("traction"), nitsche), "mean");
  EXPECT_EQ(setting_spec("correction").fallback, "true");
  EXPECT_EQ(setting_spec("name").fallback, "cg");
  EXPECT_EQ(setting_spec("plane").fallback, "stress");
}

TEST(SettingsSchema, EachRangeNamesWhatItExpects) {
  EXPECT_EQ(setting_spec("nu").range, "-1 < nu < 0.5");
  EXPECT_EQ(setting_spec("kp").range, "0 < k_p <= 1e+16");
  EXPECT_EQ(setting_spec("rule").range, "1, 3 or 6");
  EXPECT_EQ(setting_spec("max_iterations").range, "1 <= max_iterations <= 1e+07");
  EXPECT_EQ(setting_spec("refinement").range, "0 <= refinement <= 4");
  EXPECT_EQ(setting_spec("plane").range, "stress or strain");
}

TEST(SettingsSchema, TheFirstBadSettingIsNamedWithItsValue) {
  SolveSettings s;
  s.nu = 0.5;
  auto error = check_settings(s);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->spec->name, "nu");
  EXPECT_EQ(error->message.rfind("0.5: expected -1 < nu < 0.5", 0), 0u) << error->message;
  s = SolveSettings{};
  s.element.rule_points = 2;
  error = check_settings(s);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->spec->flag, "--rule");
  s = SolveSettings{};
  s.problem = "plate";
  error = check_settings(s);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->message, "'plate': expected beam, patch, patch-mixed, patch-traction or mms");
  for (double bad : {0.0, -1.0, std::nan("")})
    EXPECT_TRUE(check_value(setting_spec("kp"), bad)) << bad;
}

TEST(SettingsSchema, ScenesDocListsEveryKeyWithItsDefault) {
  const std::string doc = testing::slurp(kRepo / "docs" / "scenes.md");
  const std::map<SettingScope, std::string> prefix = {
      {SettingScope::material, "material."},
      {SettingScope::formulation, "formulations[]."},
      {SettingScope::outputs, "outputs."}};
  for (const SettingSpec& spec : setting_specs()) {
    if (!prefix.count(spec.scope)) continue;
    const std::string key = "`" + prefix.at(spec.scope) + spec.name + "`";
    const auto at = doc.find("| " + key + " |");
    ASSERT_NE(at, std::string::npos) << key << " is not a row of docs/scenes.md";
    const std::string row = doc.substr(at, doc.find('\n', at) - at);
    const std::string d = spec.fallback;
    EXPECT_TRUE(row.find("| " + d + " |") != std::string::npos ||
                row.find("| `" + d + "` |") != std::string::npos)
        << key << ": default " << d << " not in the row: " << row;
    // The range cell is the schema's requirement, which names every choice.
    const std::string range = spec.range;
    EXPECT_NE(row.find("| " + range + " |"), std::string::npos)
        << key << ": range " << range << " not in the row: " << row;
    if (spec.choices) {
      for (const NamedChoice& c : *spec.choices)
        EXPECT_NE(range.find(c.name), std::string::npos) << key << ": " << c.name;
    }
  }
}

TEST(SettingsSchema, SolveHelpListsEveryFlagWithItsDoc) {
  const auto scratch =
      std::filesystem::temp_directory_path() / ("schema_help_" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  const auto r = testing::run_program(VORODG_EXE, {"solve", "--help"}, scratch);
  std::filesystem::remove_all(scratch);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const SettingSpec& spec : setting_specs()) {
    if (spec.flag.empty()) continue;
    EXPECT_NE(r.out.find(spec.flag), std::string::npos) << spec.flag;
    EXPECT_NE(r.out.find(spec.doc.substr(0, 20)), std::string::npos) << spec.doc;
  }
}

}  // namespace
}  // namespace vorodg
