// ParaView collections (.pvd): the text, the file rewritten atomically after every entry (a
// stopped run keeps the finished steps), relative paths, escaping and refused values.
#include "core/io/PvdCollection.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / ("vorodg_test_Pvd_" + std::string(info->name()) +
                                                    "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

constexpr const char* kHead =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    "  <Collection>\n";
constexpr const char* kTail = "  </Collection>\n</VTKFile>\n";

TEST(PvdCollection, WritesNothingUntilTheFirstEntry) {
  const fs::path dir = temp_dir();
  const PvdCollection pvd(dir / "run.pvd");
  EXPECT_FALSE(fs::exists(dir / "run.pvd"));
  EXPECT_EQ(pvd.text(), std::string(kHead) + kTail);
  fs::remove_all(dir);
}

TEST(PvdCollection, RewritesTheFileAfterEveryEntry) {
  const fs::path dir = temp_dir();
  PvdCollection pvd(dir / "run.pvd");
  pvd.add(0, "steps/step_0.vtu");
  const std::string one =
      std::string(kHead) +
      "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"steps/step_0.vtu\"/>\n" + kTail;
  EXPECT_EQ(read_file(dir / "run.pvd"), one);
  pvd.add(0.1, "steps/step_1.vtu");
  pvd.add(2.5e-7, "steps/step_2.vtu");
  const std::string three =
      std::string(kHead) +
      "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"steps/step_0.vtu\"/>\n"
      "    <DataSet timestep=\"0.1\" group=\"\" part=\"0\" file=\"steps/step_1.vtu\"/>\n"
      "    <DataSet timestep=\"2.5e-07\" group=\"\" part=\"0\" file=\"steps/step_2.vtu\"/>\n" +
      kTail;
  EXPECT_EQ(read_file(dir / "run.pvd"), three);
  EXPECT_EQ(pvd.entries().size(), 3u);
  // Only the collection is in the folder: no temporary file was left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  fs::remove_all(dir);
}

TEST(PvdCollection, StoresPathsRelativeToItsFolderAndEscapesThem) {
  const fs::path dir = temp_dir();
  PvdCollection pvd(dir / "out" / "series.pvd");
  fs::create_directories(dir / "out");
  pvd.add(1, dir / "out" / "a&b" / "r<1>.vtu");
  pvd.add(2, dir / "elsewhere" / "r.vtu");
  ASSERT_EQ(pvd.entries().size(), 2u);
  EXPECT_EQ(pvd.entries()[0].file, "a&b/r<1>.vtu");
  EXPECT_EQ(pvd.entries()[1].file, "../elsewhere/r.vtu");
  const std::string text = read_file(dir / "out" / "series.pvd");
  EXPECT_NE(text.find("file=\"a&amp;b/r&lt;1&gt;.vtu\""), std::string::npos) << text;
  EXPECT_NE(text.find("file=\"../elsewhere/r.vtu\""), std::string::npos) << text;
  fs::remove_all(dir);
}

TEST(PvdCollection, RefusesNonFiniteValuesAndUnwritableFolders) {
  const fs::path dir = temp_dir();
  PvdCollection pvd(dir / "run.pvd");
  pvd.add(1, "a.vtu");
  const std::string before = read_file(dir / "run.pvd");
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    try {
      pvd.add(bad, "b.vtu");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("run.pvd"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("b.vtu"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(read_file(dir / "run.pvd"), before);
  EXPECT_EQ(pvd.entries().size(), 1u);
  PvdCollection nowhere(dir / "no" / "such" / "folder.pvd");
  EXPECT_THROW(nowhere.add(0, "a.vtu"), InputError);
  EXPECT_TRUE(nowhere.entries().empty());  // the entry that could not be written is not kept
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vorodg
