#include "core/util/MpiRuntime.hpp"

#include <cstdlib>
#include <mutex>
#include <string>

#include "core/util/Errors.hpp"

#ifdef VORODG_HAVE_MPI
#include <mpi.h>
#endif

namespace vorodg::mpi_runtime {

bool built_with_mpi() {
#ifdef VORODG_HAVE_MPI
  return true;
#else
  return false;
#endif
}

#ifdef VORODG_HAVE_MPI
namespace {
std::mutex g_mutex;  // initialization may be asked for by several worker threads at once
}  // namespace

void initialize(int* argc, char*** argv) {
  const std::lock_guard lock(g_mutex);
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &provided);
  std::atexit(finalize);  // a singleton started by a solve deep in a study ends with the program
  if (provided < MPI_THREAD_MULTIPLE)
    throw NumericalError("MPI provides thread level " + std::to_string(provided) +
                         ": expected MPI_THREAD_MULTIPLE (" + std::to_string(MPI_THREAD_MULTIPLE) +
                         "), which studies with the amg-cg solver need");
}

bool active() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

void finalize() {
  const std::lock_guard lock(g_mutex);
  if (active()) MPI_Finalize();
}
#else
void initialize(int*, char***) {
  throw InputError(
      "MPI is needed (ranks or the amg-cg solver), but this vorodg was built "
      "without it (-DVORODG_MPI=OFF)");
}
bool active() {
  return false;
}
void finalize() {}
#endif

}  // namespace vorodg::mpi_runtime
