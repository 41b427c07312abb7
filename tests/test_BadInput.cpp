// Bad input, table-driven: every row of tests/data/bad/cases.json runs the built
// program on one bad input (a .vtu mesh, a scene, a command-line value, an unwritable output) and
// checks that it is refused cleanly:
// - the expected exit code (2 bad input, 3 numerical breakdown), no signal, no abort;
// - exactly one line on stderr, "vorodg: error: ..." or "vorodg: numerical breakdown: ...",
//   containing the row's text (the key, option, cell or vertex it is about);
// - nothing written in the output folder (no partial, no temporary file), nor in the current
//   folder, nor a temporary file beside the test data;
// - no "nan" or "inf" on stdout.
// The inputs live in tests/data/bad/ (scenes/ and meshes/ hold the ones made for this test).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "support/RunVorodg.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;
namespace fs = std::filesystem;

const fs::path kExe = VORODG_EXE;
const fs::path kData = VORODG_TEST_DATA;
const fs::path kCases = kData / "bad" / "cases.json";

struct BadCase {
  std::string name;
  std::vector<std::string> args;  // with {data} and {out} placeholders
  int exit_code = 0;
  std::string mention;
};

// gtest prints the parameter when a test fails: the command line.
void PrintTo(const BadCase& c, std::ostream* os) {
  *os << "vorodg";
  for (const auto& a : c.args) *os << " " << a;
}

/// The table; empty if it cannot be read (TableIsWellFormed then says why).
std::vector<BadCase> load_cases() {
  std::vector<BadCase> cases;
  try {
    const auto table = nlohmann::json::parse(slurp(kCases));
    for (const auto& row : table.at("cases")) {
      BadCase c;
      c.name = row.at("name").get<std::string>();
      c.args = row.at("args").get<std::vector<std::string>>();
      c.exit_code = row.at("exit").get<int>();
      c.mention = row.at("stderr").get<std::string>();
      cases.push_back(c);
    }
  } catch (const std::exception&) {
    cases.clear();
  }
  return cases;
}

std::string substitute(std::string arg, const fs::path& out) {
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"{data}", kData.string()}, {"{out}", out.string()}})
    for (std::size_t at; (at = arg.find(key)) != std::string::npos;)
      arg.replace(at, key.size(), value);
  return arg;
}

std::vector<std::string> files_under(const fs::path& folder) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(folder)) found.push_back(e.path().string());
  return found;
}

/// Runs in a folder of its own, restored afterwards: a stray file written relative to the
/// current folder would land in `folder` and be seen.
class WorkingFolder {
 public:
  explicit WorkingFolder(const fs::path& folder) : saved_(fs::current_path()) {
    fs::current_path(folder);
  }
  ~WorkingFolder() { fs::current_path(saved_); }

 private:
  fs::path saved_;
};

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, IsRefusedCleanly) {
  const BadCase& c = GetParam();
  const fs::path scratch = fs::temp_directory_path() /
                           ("vorodg_test_BadInput_" + c.name + "_" + std::to_string(::getpid()));
  const fs::path io = scratch / "io", out = scratch / "out", cwd = scratch / "cwd";
  fs::remove_all(scratch);
  for (const auto& f : {io, out, cwd}) fs::create_directories(f);

  std::vector<std::string> args;
  for (const auto& a : c.args) args.push_back(substitute(a, out));
  RunResult r;
  {
    const WorkingFolder here(cwd);
    r = run_program(kExe, args, io);
  }
  std::string command = "vorodg";
  for (const auto& a : args) command += " " + quote(a);
  SCOPED_TRACE(command + "\n  exit " + std::to_string(r.exit_code) + ", signal " +
               std::to_string(r.signal) + "\n  stderr: " + r.err +
               "  stdout: " + r.out.substr(0, 600));

  EXPECT_EQ(r.signal, 0) << "killed by a signal";
  EXPECT_EQ(r.exit_code, c.exit_code);
  EXPECT_EQ(r.err_lines(), 1) << "expected exactly one line on stderr";
  const std::string prefix = c.exit_code == 3 ? "vorodg: numerical breakdown: " : "vorodg: error: ";
  EXPECT_TRUE(r.err.starts_with(prefix)) << "expected the line to start with '" << prefix << "'";
  EXPECT_NE(r.err.find(c.mention), std::string::npos)
      << "expected stderr to mention '" << c.mention << "'";
  EXPECT_EQ(r.err.find("terminate called"), std::string::npos);

  for (const auto& folder : {out, cwd})
    for (const auto& f : files_under(folder)) ADD_FAILURE() << "left behind: " << f;
  for (const auto& f : files_under(kData / "bad"))
    EXPECT_EQ(f.find(".tmp."), std::string::npos) << "temporary file left beside the data: " << f;

  static const std::regex not_finite(R"((^|[^A-Za-z])(nan|inf|infinity)([^A-Za-z]|$))",
                                     std::regex::icase);
  EXPECT_FALSE(std::regex_search(r.out, not_finite)) << "stdout holds a nan or inf";

  fs::remove_all(scratch);
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, ::testing::ValuesIn(load_cases()),
                         [](const ::testing::TestParamInfo<BadCase>& info) {
                           return info.param.name;
                         });

// The table itself: readable, names usable as test names and unique, exit codes 2 or 3, every
// placeholder known, and every input made for it (bad/scenes, bad/meshes) used by some row.
TEST(BadInputTable, IsWellFormedAndCoversEveryFile) {
  ASSERT_TRUE(fs::exists(kCases)) << kCases;
  ASSERT_NO_THROW({ const auto table = nlohmann::json::parse(slurp(kCases)); }) << kCases;
  const std::vector<BadCase> cases = load_cases();
  ASSERT_GE(cases.size(), 100u) << "the table could not be read or lost rows";
  std::set<std::string> names;
  std::string all_args;
  for (const BadCase& c : cases) {
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
    EXPECT_FALSE(c.name.empty());
    EXPECT_TRUE(std::all_of(c.name.begin(), c.name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
    })) << c.name;
    EXPECT_TRUE(c.exit_code == 2 || c.exit_code == 3) << c.name;
    EXPECT_FALSE(c.mention.empty()) << c.name;
    for (const auto& a : c.args) {
      const std::string s = substitute(a, "/out");
      EXPECT_EQ(s.find('{'), std::string::npos) << c.name << ": unknown placeholder in " << a;
      all_args += s + "\n";
    }
  }
  for (const char* folder : {"scenes", "meshes"})
    for (const auto& e : fs::directory_iterator(kData / "bad" / folder))
      EXPECT_NE(all_args.find(e.path().string() + "\n"), std::string::npos)
          << e.path() << " is used by no case";
}

}  // namespace
}  // namespace vorodg
