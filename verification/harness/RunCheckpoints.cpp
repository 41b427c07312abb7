#include "verification/harness/RunCheckpoints.hpp"

#include <iostream>

#include "core/io/StateArchive.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Digest.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/StopRequest.hpp"

namespace fs = std::filesystem;

namespace vorodg {

RunCheckpoints::RunCheckpoints(const fs::path& out, CheckpointOwner owner, CheckpointPolicy policy)
    : file_(out / "checkpoints" / (owner.run + ".ckpt")),
      owner_(std::move(owner)),
      policy_(policy) {}

bool RunCheckpoints::due(long step) const {
  if (policy_.steps > 0 && step - last_step_ >= policy_.steps) return true;
  return policy_.wall_seconds > 0.0 && since_.seconds() >= policy_.wall_seconds;
}

void RunCheckpoints::write(long step, double time, const std::function<void(StateArchive&)>& save) {
  const Stopwatch clock;
  StateArchive state;
  save(state);
  fs::create_directories(file_.parent_path());
  write_checkpoint(file_, owner_, {step, time, state.bytes()});
  last_step_ = step;
  ++written_;
  seconds_ += clock.seconds();
  since_.restart();
}

std::optional<long> RunCheckpoints::resume(const Loader& load,
                                           const std::function<void()>& rebuild) {
  bool tried = false;
  const std::vector<fs::path> candidates = checkpoint_candidates(file_);
  for (const fs::path& file : candidates) {
    try {
      CheckpointData data = read_checkpoint(file, owner_);
      if (tried) rebuild();
      tried = true;
      StateArchive state(std::move(data.payload));
      load(state);
      state.finish();
      std::cerr << "vorodg: run " << owner_.run << ": resumed at step " << data.step << " ("
                << clock_text(data.time) << ") from " << file.string() << "\n";
      last_step_ = data.step;
      return data.step;
    } catch (const CheckpointError& e) {
      // Set aside (not rotated into .prev over a good one by the next write), kept to inspect.
      std::error_code ec;
      fs::rename(file, file.string() + ".refused", ec);
      std::cerr << "vorodg: " << e.what() << " (set aside as .refused)\n";
    }
  }
  if (tried) rebuild();
  if (!candidates.empty())
    std::cerr << "vorodg: run " << owner_.run
              << ": no usable checkpoint, it starts again from the beginning\n";
  return std::nullopt;
}

std::string RunCheckpoints::clock_text(double value) const {
  return clock_ + " = " + fmt(value) + " " + unit_;
}

void RunCheckpoints::finished() const {
  remove_checkpoints(file_);
}

CheckpointOwner checkpoint_owner(const std::vector<std::pair<std::string, std::string>>& settings,
                                 const std::string& part, const PolygonMesh& mesh,
                                 const std::string& run) {
  Digest scene;
  for (const auto& [key, value] : settings)
    if (!key.starts_with("checkpoint.")) scene.add(key).add(value);
  scene.add(part);
  Digest cells;
  cells.add(mesh.vertices()).add(mesh.offsets()).add(mesh.cell_vertex_list());
  return {scene.value(), cells.value(), build_digest(), run};
}

CheckpointPolicy read_checkpoint_policy(SceneKeyReader& reader) {
  SceneObject c = reader.object("checkpoint");
  CheckpointPolicy policy;
  policy.wall_seconds = reader.number(c, "checkpoint.wall_seconds");
  policy.steps = reader.integer(c, "checkpoint.steps");
  c.finish();
  return policy;
}

void stop_if_requested(RunCheckpoints& checkpoints, long step, double time,
                       const std::function<void(StateArchive&)>& save) {
  if (!stop_requested()) return;
  checkpoints.write(step, time, save);
  throw Interrupted("run " + checkpoints.file().stem().string() + " stopped at step " +
                    std::to_string(step) + " (" + checkpoints.clock_text(time) + "), checkpoint " +
                    checkpoints.file().string());
}

}  // namespace vorodg
