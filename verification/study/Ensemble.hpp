#pragma once
// The processes that share one study: this process alone, or the ranks of an MPI job started by
// mpirun (or srun). Rank 0 is the coordinator: it hands out the tasks (TaskPool), is the only
// writer of results.jsonl, and writes the reports; the other ranks run tasks and report back.
//
// A build without MPI (-DVORODG_MPI=OFF) refuses to start under an MPI launcher that asks for
// more than one process, rather than running the whole study once per process.
namespace vorodg {

class Ensemble {
 public:
  /// Joins the MPI job when there is one (before anything else in main). Throws InputError if
  /// this build lacks MPI and the launcher asked for more than one process.
  static void start(int& argc, char**& argv);
  /// Leaves the MPI job (at the end of main; a no-op without one).
  static void stop();
  /// Ends every process of the job with `code` (an error on one rank must not leave the
  /// others waiting for it); returns without MPI.
  static void abort(int code);

  static int rank();
  static int size();
  static bool coordinator() { return rank() == 0; }
  static bool built_with_mpi();
};

}  // namespace vorodg
