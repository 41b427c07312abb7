// The harness's registry of study kinds and its record tables: every kind named in messages
// and --list, every shipped scene read by its kind's reader, a misspelt study answered with the
// whole list, records whose numbers are not finite written in a form they read back, and a run
// whose result overflows ending with exit 3 and a message naming the quantity, never an abort.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "support/RunVorodg.hpp"
#include "support/TestDir.hpp"
#include "verification/harness/RecordFields.hpp"
#include "verification/harness/StudyKind.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::run_program;
using testing::slurp;

const fs::path kScenes = fs::path(VORODG_TEST_DATA) / ".." / ".." / "data" / "scenes";
const char* const kEveryKind[] = {"convergence", "penalty-sweep", "patch-suite", "trade-off",
                                  "extremes",    "fracture",      "dynamics",    "fragmentation"};

TEST(StudyKinds, TheRegistryIsTheListOfStudyChoices) {
  ASSERT_EQ(study_kinds().size(), std::size(kEveryKind));
  for (const char* name : kEveryKind) {
    EXPECT_EQ(study_kind(name, "").name, name);
    EXPECT_TRUE(is_choice(study_choices(), name)) << name;
  }
}

TEST(StudyKinds, AMisspeltStudyListsEveryKind) {
  try {
    read_study_scene(R"({"study": "fragmentaton"})", "s.json");
    FAIL() << "a misspelt study was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("scene s.json: key 'study': 'fragmentaton': expected"), std::string::npos)
        << what;
    for (const char* name : kEveryKind) EXPECT_NE(what.find(name), std::string::npos) << name;
  }
}

TEST(StudyKinds, EveryShippedSceneReadsThroughItsKind) {
  int scenes = 0;
  for (const auto& e : fs::directory_iterator(kScenes)) {
    if (e.path().extension() != ".json") continue;
    const std::string text = read_file(e.path());
    EXPECT_NO_THROW(read_study_scene(text, e.path().string())) << e.path();
    ++scenes;
  }
  EXPECT_GT(scenes, 30);
}

TEST(StudyKinds, ListSeparatesEveryNameFromItsKind) {
  const fs::path dir = testing::fresh_test_dir("study_kinds_list");
  const testing::RunResult r = run_program(VORODG_EXE, {"run", "--list"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  const std::regex row(R"(^(\S+) +(\S+): .+$)");
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;  // the echoed options
    std::smatch m;
    ASSERT_TRUE(std::regex_match(line, m, row)) << line;
    EXPECT_TRUE(fs::exists(kScenes / (m[1].str() + ".json"))) << line;
    EXPECT_TRUE(is_choice(study_choices(), m[2].str())) << line;
    ++rows;
  }
  EXPECT_GT(rows, 30);
  fs::remove_all(dir);
}

/// The rows of docs/scenes.md that start with "| `name` |" (each kind has its own table).
std::vector<std::string> doc_rows(const std::string& doc, const std::string& name) {
  std::vector<std::string> rows;
  for (auto at = doc.find("| `" + name + "` |"); at != std::string::npos;
       at = doc.find("| `" + name + "` |", at + 1))
    rows.push_back(doc.substr(at, doc.find('\n', at) - at));
  return rows;
}

TEST(StudyKinds, EveryKeyOfEveryKindIsInTheScenesDoc) {
  const std::string doc = slurp(kScenes / ".." / ".." / "docs" / "scenes.md");
  ASSERT_FALSE(doc.empty());
  for (const StudyKind& kind : study_kinds())
    for (const SceneKey& k : kind.keys()) {
      const std::vector<std::string> rows = doc_rows(doc, k.name);
      ASSERT_FALSE(rows.empty()) << kind.name << ": " << k.name << " is not in docs/scenes.md";
      bool with_default = false;
      for (const std::string& row : rows)
        with_default |= row.find("| " + k.fallback + " |") != std::string::npos ||
                        row.find("| `" + k.fallback + "` |") != std::string::npos;
      EXPECT_TRUE(with_default) << kind.name << ": " << k.name << ": default " << k.fallback
                                << " in no row of docs/scenes.md";
    }
  // The rows are the tables', word for word.
  for (const StudyKind& kind : study_kinds()) {
    std::istringstream rows(key_table_markdown(kind));
    for (std::string row; std::getline(rows, row);)
      EXPECT_NE(doc.find(row + "\n"), std::string::npos) << kind.name << ": not in docs: " << row;
  }
}

TEST(StudyKinds, EveryNumberHasAFiniteRange) {
  for (const StudyKind& kind : study_kinds())
    for (const SceneKey& k : kind.keys()) {
      const bool numeric = k.is_number() || (k.type.front() == '[' && k.name != "domain" &&
                                             k.name != "second_block.domain");
      if (!numeric) continue;
      const Bounds& b = k.bounds;
      ASSERT_TRUE(b.lower && b.upper) << kind.name << ": " << k.name << " has no finite range";
      EXPECT_TRUE(std::isfinite(*b.lower) && std::isfinite(*b.upper)) << k.name;
      EXPECT_LT(*b.lower, *b.upper) << k.name;
      // The range holds its default wherever the default is a number.
      try {
        EXPECT_FALSE(check_key(k, key_default(k))) << kind.name << ": " << k.name;
      } catch (const std::logic_error&) {  // a default in words
      }
    }
}

TEST(StudyKinds, AValueThatWouldOverflowIsRefusedNamingTheKey) {
  const fs::path dir = testing::fresh_test_dir("study_kinds_huge");
  json scene = json::parse(read_file(kScenes / "tpb-case4.json"));
  scene["material"]["thickness"] = 1e308;
  std::ofstream(dir / "huge.json") << scene.dump(1);
  const testing::RunResult r = run_program(
      VORODG_EXE, {"run", (dir / "huge.json").string(), "-o", (dir / "out").string(), "--quiet"},
      dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("thickness"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1e+308"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "results.jsonl"));
  fs::remove_all(dir);
}

TEST(StudyKinds, AnOldSpellingIsRefusedNamingTheNewOne) {
  json scene = json::parse(read_file(kScenes / "demo-fracture.json"));
  scene["cohesive"]["friction"] = 0.5;
  try {
    read_study_scene(scene.dump(), "old.json");
    FAIL() << "cohesive.friction was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cohesive.friction: this key is now spelled "
                                         "criterion.friction"),
              std::string::npos)
        << e.what();
  }
}

struct Sample {
  double x = 0.0, y = 0.0;
  int n = 0;
  std::string text;
};

std::vector<RecordField<Sample>> sample_fields() {
  return {field("x", &Sample::x), field("y", &Sample::y, {true, 6, true}, true),
          field("n", &Sample::n), field("text", &Sample::text, kNotInCsv)};
}

TEST(RecordFields, NonFiniteNumbersReadBack) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double x : {inf, -inf, std::nan(""), 1.5, -0.0}) {
    Sample s{x, 2.0, 3, "t"};
    const json line = json::parse(record_json(sample_fields(), s).dump());  // as in a file
    Sample back;
    read_record(sample_fields(), line, back);
    if (std::isnan(x))
      EXPECT_TRUE(std::isnan(back.x));
    else
      EXPECT_EQ(back.x, x);
    EXPECT_EQ(back.n, 3);
  }
  EXPECT_TRUE(std::isnan(read_number(json(nullptr))));  // what older records held
  EXPECT_THROW(read_number(json("infinity")), json::type_error);
}

TEST(RecordFields, OptionalFieldsAreLeftOutWhenNotMeasured) {
  const Sample s{1.0, NAN, 2, "t"};
  const json j = record_json(sample_fields(), s);
  EXPECT_FALSE(j.contains("y"));
  Sample back{0.0, 7.0, 0, ""};
  read_record(sample_fields(), j, back);
  EXPECT_TRUE(std::isnan(back.y));
  EXPECT_THROW(read_record(sample_fields(), json{{"y", 1.0}}, back), json::exception);
}

TEST(RecordFields, CsvRowsFollowTheTable) {
  const Sample s{0.1, NAN, 4, "not listed"};
  EXPECT_EQ(csv_header(sample_fields()), "x,y,n\n");
  EXPECT_EQ(csv_row(sample_fields(), s), "0.1,,4\n");
  EXPECT_EQ(non_finite_field(sample_fields(), s), "");  // y is optional: not measured
  EXPECT_EQ(non_finite_field(sample_fields(), Sample{INFINITY, 0.0, 0, ""}), "x");
}

TEST(StudyKinds, ARecordThatOverflowedMakesTheStudyExit3NamingTheQuantity) {
  // No scene within the keys' ranges overflows, so the record is one an older version wrote: a
  // complete run whose peak load is infinite. Resuming reads it back and refuses it.
  const fs::path dir = testing::fresh_test_dir("study_kinds_overflow");
  json scene = json::parse(read_file(kScenes / "demo-fracture.json"));
  scene["meshes"][0]["sizes"] = json::array({0.04});
  scene["meshes"][0]["realizations"] = 1;
  std::ofstream(dir / "s.json") << scene.dump(1);
  fs::create_directories(dir / "out");
  json record = {{"id", "rcp-L0-R0"},
                 {"cells", 10},
                 {"dofs", 40},
                 {"full_dg_dofs", 80},
                 {"h_avg", 0.04},
                 {"peak_load", "inf"},
                 {"displacement_at_peak", 0.0},
                 {"dissipated_energy", 0.0},
                 {"crack_length", 0.0},
                 {"energy_balance_error", 0.0},
                 {"points", 3},
                 {"newton_iterations", 3},
                 {"factorizations", 3},
                 {"complete", true},
                 {"failure", ""},
                 {"ended", ""},
                 {"seconds", 1.0}};
  std::ofstream(dir / "out" / "results.jsonl") << record.dump() << "\n";
  const testing::RunResult r = run_program(
      VORODG_EXE,
      {"run", (dir / "s.json").string(), "-o", (dir / "out").string(), "--quiet", "--no-plots"},
      dir);
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  const std::string report = slurp(dir / "out" / "report.md");
  EXPECT_NE(report.find("peak_load is not finite"), std::string::npos) << report;
  EXPECT_NE(slurp(dir / "out" / "results.csv").find(",inf,"), std::string::npos);
  fs::remove_all(dir);
}

TEST(StudyKinds, ARecordThisVersionCannotReadIsOneLineNotAnAbort) {
  const fs::path dir = testing::fresh_test_dir("study_kinds_old_record");
  json scene = json::parse(read_file(kScenes / "demo-fracture.json"));
  scene["meshes"][0]["sizes"] = json::array({0.04});
  scene["meshes"][0]["realizations"] = 1;
  std::ofstream(dir / "s.json") << scene.dump(1);
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "results.jsonl") << R"({"id": "rcp-L0-R0", "cells": 10})"
                                               << "\n";
  const testing::RunResult r = run_program(
      VORODG_EXE,
      {"run", (dir / "s.json").string(), "-o", (dir / "out").string(), "--quiet", "--no-plots"},
      dir);
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("rcp-L0-R0 is not one this version reads"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vorodg
