// The checkpoint's two layers (core/io/StateArchive, core/io/Checkpoint):
//   - an archive saves and loads values, vectors, Eigen vectors, texts, hash maps and sets and
//     vectors of structs through one function, and a load gives back what was saved, bit for
//     bit (NaN and -0 included);
//   - a load that meets another name, another size or the payload's end, or leaves bytes over,
//     throws CheckpointError naming the entry;
//   - a checkpoint file round-trips its step, time and payload; the one before is kept as .prev;
//   - a truncated file (at every length), a flipped bit (in every byte), another format version
//     and a file of another scene, mesh, build or run are each refused with one line that names
//     the file and the reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/io/Checkpoint.hpp"
#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

// No padding, so that its bytes are its members' (a padded struct's padding is copied as it is,
// whatever it holds: PaddedRoundTrips).
struct Plain {
  std::int64_t a = 0;
  double b = 0.0;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
};

/// Everything an archive carries, through one function.
struct Sample {
  double x = 0.0;
  long n = 0;
  std::vector<int> ints;
  std::vector<Plain> plains;
  Eigen::VectorXd u;
  std::string text;
  std::unordered_map<std::uint64_t, double> map;
  std::unordered_set<int> set;
  std::vector<std::pair<int, std::string>> pairs;

  void archive(StateArchive& a) {
    a.value("x", x);
    a.value("n", n);
    a.vector("ints", ints);
    a.vector("plains", plains);
    a.vector("u", u);
    a.text("text", text);
    a.map("map", map);
    a.set("set", set);
    a.each("pairs", pairs, [](StateArchive& item, std::pair<int, std::string>& p) {
      item.value("first", p.first);
      item.text("second", p.second);
    });
  }
};

Sample filled() {
  Sample s;
  s.x = -0.0;
  s.n = -7;
  s.ints = {3, 1, 4};
  s.plains = {{1, 2.5, {3, 4}}, {-1, NAN, {0, -0.0}}};
  s.u = Eigen::VectorXd::LinSpaced(5, -1.0, 1.0);
  s.u[2] = std::nextafter(0.0, 1.0);
  s.text = std::string("a\0b", 3);
  s.map = {{9, 1.5}, {2, -3.0}, {40, 0.25}};
  s.set = {5, -2, 11};
  s.pairs = {{1, "one"}, {2, ""}};
  return s;
}

std::string saved(Sample s) {
  StateArchive a;
  s.archive(a);
  return a.bytes();
}

TEST(StateArchive, LoadGivesBackWhatWasSavedBitForBit) {
  const std::string bytes = saved(filled());
  Sample back;
  StateArchive a(bytes);
  back.archive(a);
  a.finish();
  // Saving what was loaded gives the same bytes: every member, every bit (NaN, -0, denormals).
  EXPECT_EQ(saved(back), bytes);
  EXPECT_TRUE(std::signbit(back.x));
  EXPECT_EQ(back.map, filled().map);
  EXPECT_EQ(back.set, filled().set);
  EXPECT_EQ(back.pairs, filled().pairs);
  // One state, one payload: hash containers are saved in key order.
  Sample other = filled();
  other.map.rehash(1000);
  EXPECT_EQ(saved(other), bytes);
}

TEST(StateArchive, PaddedStructsRoundTripMemberByMember) {
  struct Padded {
    int a;
    double b;
    bool c;
  };
  std::vector<Padded> items{{1, 2.5, true}, {-3, NAN, false}};
  StateArchive out;
  out.vector("padded", items);
  std::vector<Padded> back;
  StateArchive in(out.bytes());
  in.vector("padded", back);
  in.finish();
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].a, 1);
  EXPECT_EQ(back[0].b, 2.5);
  EXPECT_TRUE(back[0].c);
  EXPECT_EQ(back[1].a, -3);
  EXPECT_TRUE(std::isnan(back[1].b));
  EXPECT_FALSE(back[1].c);
}

TEST(StateArchive, ATextBeingWrittenGoesOnWhereItStopped) {
  std::ostringstream rows;
  rows << "t,f\n0,1\n";
  StateArchive out;
  out.text("rows", rows);
  std::ostringstream back;
  back << "stale";
  StateArchive in(out.bytes());
  in.text("rows", back);
  in.finish();
  back << "1,2\n";
  EXPECT_EQ(back.str(), "t,f\n0,1\n1,2\n");
}

TEST(StateArchive, RefusesAnotherLayoutNamingTheEntry) {
  const std::string bytes = saved(filled());
  auto message = [](const std::function<void(StateArchive&)>& load, const std::string& bytes) {
    try {
      StateArchive a(bytes);
      load(a);
      a.finish();
    } catch (const CheckpointError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  // Another name first.
  EXPECT_NE(message(
                [](StateArchive& a) {
                  double y;
                  a.value("y", y);
                },
                bytes)
                .find("expected 'y', found 'x'"),
            std::string::npos);
  // Another size: a long where a double of the same name was saved is fine (8 bytes), an int
  // is not.
  EXPECT_NE(message(
                [](StateArchive& a) {
                  int x;
                  a.value("x", x);
                },
                bytes)
                .find("expected 4 bytes, found 8"),
            std::string::npos);
  // The payload cut short, and bytes left over.
  EXPECT_NE(message(
                [](StateArchive& a) {
                  Sample s;
                  s.archive(a);
                },
                bytes.substr(0, 40))
                .find("ends early"),
            std::string::npos);
  EXPECT_NE(message(
                [](StateArchive& a) {
                  double x;
                  a.value("x", x);
                },
                bytes)
                .find("left"),
            std::string::npos);
}

class CheckpointFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vorodg_test_Checkpoint_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// The one-line refusal of `file` for `owner`, or "accepted".
  static std::string refusal(const fs::path& file, const CheckpointOwner& owner) {
    try {
      read_checkpoint(file, owner);
    } catch (const CheckpointError& e) {
      return e.what();
    }
    return "accepted";
  }

  fs::path dir_;
  const CheckpointOwner owner_{11, 22, 33, "rcp-L0-R1"};
  const CheckpointData data_{1234, 0.5, std::string("payload\0with bytes", 18)};
};

TEST_F(CheckpointFile, RoundTripsAndKeepsThePreviousOne) {
  const fs::path file = dir_ / "run.ckpt";
  write_checkpoint(file, owner_, data_);
  const CheckpointData back = read_checkpoint(file, owner_);
  EXPECT_EQ(back.step, 1234);
  EXPECT_EQ(back.time, 0.5);
  EXPECT_EQ(back.payload, data_.payload);
  write_checkpoint(file, owner_, {1300, 0.6, "newer"});
  EXPECT_EQ(read_checkpoint(file, owner_).step, 1300);
  const std::vector<fs::path> candidates = checkpoint_candidates(file);
  ASSERT_EQ(candidates.size(), 2u);
  EXPECT_EQ(candidates[0], file);
  EXPECT_EQ(read_checkpoint(candidates[1], owner_).step, 1234);
  remove_checkpoints(file);
  EXPECT_TRUE(checkpoint_candidates(file).empty());
}

TEST_F(CheckpointFile, RefusesTruncatedCorruptAndForeignFilesInOneLine) {
  const fs::path file = dir_ / "run.ckpt", bad = dir_ / "bad.ckpt";
  write_checkpoint(file, owner_, data_);
  const std::string bytes = read_file(file);
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    write_file_atomically(bad, bytes.substr(0, n));
    const std::string why = refusal(bad, owner_);
    EXPECT_NE(why, "accepted") << "cut at " << n;
    EXPECT_EQ(why.find('\n'), std::string::npos);
    EXPECT_NE(why.find(bad.string()), std::string::npos) << why;
  }
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::string flipped = bytes;
    flipped[i] = static_cast<char>(flipped[i] ^ (1 << (i % 8)));
    write_file_atomically(bad, flipped);
    EXPECT_NE(refusal(bad, owner_), "accepted") << "bit flipped in byte " << i;
  }
  write_file_atomically(bad, bytes.substr(0, bytes.size() - 9));
  EXPECT_NE(refusal(bad, owner_).find("truncated"), std::string::npos) << refusal(bad, owner_);
  std::string flipped = bytes;
  flipped[bytes.size() - 10] ^= 4;  // inside the payload
  write_file_atomically(bad, flipped);
  EXPECT_NE(refusal(bad, owner_).find("corrupt"), std::string::npos) << refusal(bad, owner_);
  std::string version = bytes;
  version[18] = 9;
  write_file_atomically(bad, version);
  EXPECT_NE(refusal(bad, owner_).find("format version 9"), std::string::npos);
  // Another scene, mesh, build or run: each says which.
  const std::pair<CheckpointOwner, std::string> foreign[] = {
      {{12, 22, 33, owner_.run}, "other settings"},
      {{11, 23, 33, owner_.run}, "another mesh"},
      {{11, 22, 34, owner_.run}, "another build"},
      {{11, 22, 33, "rcp-L0-R2"}, "run 'rcp-L0-R1'"}};
  for (const auto& [other, why] : foreign)
    EXPECT_NE(refusal(file, other).find(why), std::string::npos) << refusal(file, other);
  EXPECT_NE(refusal(dir_ / "absent.ckpt", owner_), "accepted");
}

}  // namespace
}  // namespace vorodg
