#include "core/io/Checkpoint.hpp"

#include <cstring>

#include "core/io/AtomicFile.hpp"
#include "core/io/StateArchive.hpp"
#include "core/util/Digest.hpp"
#include "core/util/Errors.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

constexpr std::string_view kMagic = "vorodg-checkpoint\n";

/// The header's fields, saved or loaded.
struct Header {
  CheckpointOwner owner;
  long step = 0;
  double time = 0.0;
  std::uint64_t payload = 0;

  void archive(StateArchive& a) {
    a.value("scene", owner.scene);
    a.value("mesh", owner.mesh);
    a.value("build", owner.build);
    a.text("run", owner.run);
    a.value("step", step);
    a.value("time", time);
    a.value("payload", payload);
  }
};

fs::path previous(const fs::path& file) {
  return file.string() + ".prev";
}

/// The first field of `found` that differs from `expected`, as "what: expected .., found ..".
std::string mismatch(const CheckpointOwner& expected, const CheckpointOwner& found) {
  const auto hex = hex_digest;
  if (found.run != expected.run)
    return "written for run '" + found.run + "', expected '" + expected.run + "'";
  if (found.scene != expected.scene)
    return "written for other settings (scene digest " + hex(found.scene) + ", expected " +
           hex(expected.scene) + ")";
  if (found.mesh != expected.mesh)
    return "written for another mesh (digest " + hex(found.mesh) + ", expected " +
           hex(expected.mesh) + ")";
  if (found.build != expected.build)
    return "written by another build of vorodg (digest " + hex(found.build) + ", expected " +
           hex(expected.build) + ")";
  return "";
}

}  // namespace

void write_checkpoint(const fs::path& file, const CheckpointOwner& owner,
                      const CheckpointData& data) {
  Header header{owner, data.step, data.time, data.payload.size()};
  StateArchive fields;
  header.archive(fields);
  std::string bytes(kMagic);
  append_bytes(bytes, kCheckpointVersion);
  append_bytes(bytes, static_cast<std::uint64_t>(fields.bytes().size()));
  bytes += fields.bytes();
  bytes += data.payload;
  append_bytes(bytes, crc32_of(bytes));
  std::error_code ec;
  if (fs::exists(file, ec)) fs::rename(file, previous(file), ec);
  write_file_atomically(file, bytes);
}

CheckpointData read_checkpoint(const fs::path& file, const CheckpointOwner& owner) {
  auto refuse = [&](const std::string& why) {
    return CheckpointError("checkpoint '" + file.string() + "': " + why);
  };
  std::string bytes;
  try {
    bytes = read_file(file);
  } catch (const InputError& e) {
    throw CheckpointError(e.what());
  }
  const std::size_t fixed = kMagic.size() + sizeof(std::uint32_t) + sizeof(std::uint64_t);
  if (bytes.size() < fixed + sizeof(std::uint32_t) || bytes.compare(0, kMagic.size(), kMagic) != 0)
    throw refuse("not a vorodg checkpoint (no format line)");
  std::uint32_t version = 0, crc = 0;
  std::memcpy(&version, bytes.data() + kMagic.size(), sizeof version);
  if (version != kCheckpointVersion)
    throw refuse("format version " + std::to_string(version) + ", expected " +
                 std::to_string(kCheckpointVersion));
  std::memcpy(&crc, bytes.data() + bytes.size() - sizeof crc, sizeof crc);
  const std::string_view body(bytes.data(), bytes.size() - sizeof crc);
  std::uint64_t header_bytes = 0;
  std::memcpy(&header_bytes, bytes.data() + kMagic.size() + sizeof version, sizeof header_bytes);
  if (header_bytes > body.size() - fixed)
    throw refuse("truncated (" + std::to_string(bytes.size()) + " bytes, header cut short)");
  Header header;
  try {
    StateArchive fields(std::string(body.substr(fixed, header_bytes)));
    header.archive(fields);
    fields.finish();
  } catch (const CheckpointError& e) {
    throw refuse(std::string("unreadable header: ") + e.what());
  }
  const std::size_t expected_size = fixed + header_bytes + header.payload + sizeof crc;
  if (bytes.size() != expected_size)
    throw refuse("truncated (" + std::to_string(bytes.size()) + " bytes, expected " +
                 std::to_string(expected_size) + ")");
  if (crc32_of(body) != crc) throw refuse("corrupt (its CRC-32 does not match its contents)");
  if (const std::string why = mismatch(owner, header.owner); !why.empty()) throw refuse(why);
  return {header.step, header.time, std::string(body.substr(fixed + header_bytes))};
}

std::vector<fs::path> checkpoint_candidates(const fs::path& file) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::path& f : {file, previous(file)})
    if (fs::exists(f, ec)) found.push_back(f);
  return found;
}

void remove_checkpoints(const fs::path& file) {
  std::error_code ec;
  for (const fs::path& f : {file, previous(file), fs::path(file.string() + ".refused"),
                            fs::path(previous(file).string() + ".refused")})
    fs::remove(f, ec);
  // A write cut short by a kill leaves its temporary file (<file>.tmp.<pid>) behind.
  const std::string stem = file.filename().string() + ".tmp.";
  for (const auto& entry : fs::directory_iterator(file.parent_path(), ec))
    if (entry.path().filename().string().starts_with(stem)) fs::remove(entry.path(), ec);
}

}  // namespace vorodg
