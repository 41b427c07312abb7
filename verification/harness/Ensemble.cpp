#include "verification/harness/Ensemble.hpp"

#include <cstdlib>
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/MpiRuntime.hpp"

#ifdef VORODG_HAVE_MPI
#include <mpi.h>
#endif

namespace vorodg {
namespace {

int g_rank = 0, g_size = 1;
bool g_joined = false;
Shard g_shard;
bool g_report_only = false;
constexpr const char* kShardPrefix = "results.shard-";

/// The number of processes an MPI launcher asked for, from its environment (Open MPI, MPICH and
/// Slurm's PMI), or 1.
int launcher_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return 1;
}

}  // namespace

bool Ensemble::built_with_mpi() {
  return mpi_runtime::built_with_mpi();
}

void Ensemble::start(int& argc, char**& argv) {
#ifdef VORODG_HAVE_MPI
  if (launcher_size() <= 1 && !std::getenv("OMPI_COMM_WORLD_RANK")) return;  // not under mpirun
  // Only each process's main thread calls MPI for the pool (TaskPool funnels its workers'
  // traffic); hypre's solves on MPI_COMM_SELF in the workers need the threads level anyway.
  mpi_runtime::initialize(&argc, &argv);
  g_joined = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
#else
  (void)argc, (void)argv;
  const int asked = launcher_size();
  if (asked > 1)
    throw InputError("started as one of " + std::to_string(asked) +
                     " MPI processes, but this vorodg was built without MPI "
                     "(-DVORODG_MPI=OFF): rebuild with MPI, or run one process (--threads)");
#endif
}

void Ensemble::stop() {
  mpi_runtime::finalize();  // also ends a singleton session started by an AMG solve
  g_joined = false;
}

void Ensemble::abort(int code) {
#ifdef VORODG_HAVE_MPI
  if (g_joined && g_size > 1) MPI_Abort(MPI_COMM_WORLD, code);
#else
  (void)code;
#endif
}

void Ensemble::set_shard(Shard shard) {
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count)
    throw InputError("--shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                     ": expected K/N with 0 <= K < N");
  if (g_size > 1 && shard.count > 1)
    throw InputError("--shard under mpirun: use either MPI ranks or shards, not both");
  g_shard = shard;
}

const Shard& Ensemble::shard() {
  return g_shard;
}
void Ensemble::set_report_only(bool on) {
  g_report_only = on;
}
bool Ensemble::report_only() {
  return g_report_only;
}

std::filesystem::path Ensemble::own_results(const std::filesystem::path& jsonl) {
  if (g_shard.count == 1) return jsonl;
  return jsonl.parent_path() / (kShardPrefix + std::to_string(g_shard.index) + "-of-" +
                                std::to_string(g_shard.count) + ".jsonl");
}

bool Ensemble::is_shard_results(const std::string& name) {
  return name.starts_with(kShardPrefix) && name.ends_with(".jsonl");
}

int Ensemble::rank() {
  return g_rank;
}
int Ensemble::size() {
  return g_size;
}

}  // namespace vorodg
