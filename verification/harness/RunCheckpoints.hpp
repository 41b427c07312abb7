#pragma once
// A run's checkpoints: when to write them, where, and how a rerun picks the newest usable one.
// The state itself is the run's to save and load (one archive function for both); this class
// owns the policy: every `wall_seconds` of wall time and/or every `steps` steps, at once on a
// stop request, the newest file first on resume and the one before it if the newest is refused
// (each refusal one line on stderr naming the file and the reason; the file is set aside as
// <file>.refused), and the files removed once the run has finished.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/io/Checkpoint.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

class PolygonMesh;
class SceneKeyReader;
class StateArchive;

/// How often a run checkpoints.
struct CheckpointPolicy {
  double wall_seconds = 60.0;  // 0: not by time
  long steps = 0;              // 0: not by steps
};

class RunCheckpoints {
 public:
  /// The checkpoints of run `owner.run` under `out`/checkpoints/.
  RunCheckpoints(const std::filesystem::path& out, CheckpointOwner owner, CheckpointPolicy policy);

  /// After step `step`: whether a checkpoint is due by the policy.
  bool due(long step) const;
  /// Writes the state `save` produces as the checkpoint of `step` at `time` (atomically; the
  /// one before kept), and restarts the wall clock.
  void write(long step, double time, const std::function<void(StateArchive&)>& save);

  using Loader = std::function<void(StateArchive&)>;
  /// Continues from the newest usable checkpoint: for each file, newest first, `load` reads it
  /// into a run built afresh by `rebuild` (called before every attempt after the first, since a
  /// refused load may have changed the run). Returns the step resumed from, or nothing (no
  /// usable checkpoint: the run starts from t = 0, rebuilt if an attempt was made).
  std::optional<long> resume(const Loader& load, const std::function<void()>& rebuild);

  /// The run finished: its checkpoints are removed.
  void finished() const;

  /// What the run's clock is called in messages, with its unit: "t" in "s" by default (a
  /// quasi-static path's is its stroke, in m).
  void set_clock(std::string name, std::string unit) {
    clock_ = std::move(name), unit_ = std::move(unit);
  }
  /// "<clock> = <value> <unit>".
  std::string clock_text(double value) const;

  const std::filesystem::path& file() const { return file_; }
  /// Checkpoints written, and the wall seconds spent writing them (the cost of checkpointing).
  int written() const { return written_; }
  double seconds() const { return seconds_; }

 private:
  std::filesystem::path file_;
  CheckpointOwner owner_;
  CheckpointPolicy policy_;
  std::string clock_ = "t", unit_ = "s";
  Stopwatch since_;
  long last_step_ = 0;
  int written_ = 0;
  double seconds_ = 0.0;
};

/// What a checkpoint of run `run` must belong to: the scene's `settings` (every echoed key but
/// checkpoint.*, which a rerun may change) with `part` (what tells a study's parts apart beyond
/// them), the mesh (its vertices and cells) and the running build.
CheckpointOwner checkpoint_owner(const std::vector<std::pair<std::string, std::string>>& settings,
                                 const std::string& part, const PolygonMesh& mesh,
                                 const std::string& run);

/// The scene's checkpoint object (checkpoint_keys()), read with `reader`.
CheckpointPolicy read_checkpoint_policy(SceneKeyReader& reader);

/// Stops the run after `step` if a stop was asked for: writes its checkpoint with `save`, then
/// throws Interrupted naming the run, the step and the time.
void stop_if_requested(RunCheckpoints& checkpoints, long step, double time,
                       const std::function<void(StateArchive&)>& save);

}  // namespace vorodg
