#pragma once
// A run's checkpoint file: what it is, whose it is, and its state.
//
//   "vorodg-checkpoint\n"            the format's name (18 bytes)
//   u32 version                      kCheckpointVersion
//   u64 header bytes, header         a StateArchive: scene, mesh and build digests, the run's id,
//                                    the step and the time it was taken at, the payload's size
//   payload                          the run's StateArchive
//   u32 CRC-32 of everything above
//
// Written atomically beside the last one, which is kept as <file>.prev until the new one is in
// place, so a stop at any moment (SIGKILL during a write included) leaves at least one whole
// checkpoint. Reading refuses, each with one line naming the file and why: another format or
// version, a truncated or corrupt file, or one written for another scene, mesh, run or build.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace vorodg {

inline constexpr std::uint32_t kCheckpointVersion = 1;

/// What a checkpoint must belong to.
struct CheckpointOwner {
  std::uint64_t scene = 0;  // Digest of the settings that define the run
  std::uint64_t mesh = 0;   // Digest of its mesh
  std::uint64_t build = 0;  // build_digest()
  std::string run;          // the run's id
};

struct CheckpointData {
  long step = 0;
  double time = 0.0;
  std::string payload;
};

/// Writes `data` for `owner` to `file` atomically, keeping the one there as <file>.prev.
void write_checkpoint(const std::filesystem::path& file, const CheckpointOwner& owner,
                      const CheckpointData& data);

/// The checkpoint in `file` if it is whole and belongs to `owner`; otherwise throws
/// CheckpointError with one line naming the file and the reason.
CheckpointData read_checkpoint(const std::filesystem::path& file, const CheckpointOwner& owner);

/// The files to try, newest first: <file>, then <file>.prev (those that exist).
std::vector<std::filesystem::path> checkpoint_candidates(const std::filesystem::path& file);

/// Removes <file> and <file>.prev, either set aside as .refused, and the temporary files of
/// writes a kill cut short (a run that finished needs none of them).
void remove_checkpoints(const std::filesystem::path& file);

}  // namespace vorodg
