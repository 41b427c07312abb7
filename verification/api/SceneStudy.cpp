#include "verification/api/SceneStudy.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/StudyKind.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

/// "K/N" of --shard.
Shard parse_shard(const std::string& text) {
  Shard shard;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> shard.index >> slash >> shard.count) || slash != '/' || !in.eof())
    throw InputError("--shard '" + text + "': expected K/N, e.g. 3/16");
  return shard;
}

/// Names the scene in the output folder (for `vorodg merge`), once its runs are done: bad input
/// leaves nothing behind. Rank 0 of an MPI job, or each shard, writes it.
void record_scene(const fs::path& out, const fs::path& scene) {
  if (!Ensemble::coordinator()) return;
  write_file_atomically(out / kRunInfoFile,
                        nlohmann::json{{"scene", fs::absolute(scene).string()}}.dump(1) + "\n");
}

}  // namespace

fs::path shipped_scenes_dir() {
  return fs::path(VORODG_DATA_DIR) / "scenes";
}

fs::path resolve_scene(const std::string& name) {
  if (fs::exists(name)) return name;
  const fs::path shipped = shipped_scenes_dir() / (name + ".json");
  if (fs::exists(shipped)) return shipped;
  throw InputError("scene '" + name +
                   "': no such file, and no shipped scene of that name (see vorodg run --list)");
}

int run_scene_study(const SceneStudyOptions& o) {
  if (!o.shard.empty()) Ensemble::set_shard(parse_shard(o.shard));
  StudyCall call;
  call.scene = fs::absolute(resolve_scene(o.scene));
  call.out = o.out;
  call.threads = o.threads;
  call.progress = !o.quiet;
  call.no_plots = o.no_plots;
  call.force = o.force;
  const int code = scene_kind(read_file(call.scene), call.scene.string()).run(call);
  record_scene(o.out, call.scene);
  return code;
}

}  // namespace vorodg
