#pragma once
// The process's one MPI session, shared by MPI's two users here: a study spread over the ranks
// of a job (verification/harness/Ensemble) and hypre's algebraic multigrid, whose objects live on
// MPI_COMM_SELF even in a single process. Whichever comes first initializes MPI; a process
// started without a launcher becomes a singleton job of one rank. MPI_THREAD_MULTIPLE is asked
// for because a study's worker threads call hypre while the main thread serves the other ranks.
namespace vorodg::mpi_runtime {

/// Whether this vorodg was built with MPI (-DVORODG_MPI).
bool built_with_mpi();

/// Initializes MPI once per process, with the program's arguments when given; later calls do
/// nothing. Registers finalize() to run at exit. Throws NumericalError if MPI cannot run threads
/// concurrently, InputError if this vorodg was built without MPI.
void initialize(int* argc = nullptr, char*** argv = nullptr);

/// Whether MPI is initialized and not yet finalized.
bool active();

/// Finalizes MPI if it is active (a second call does nothing). Call it from the main thread.
void finalize();

}  // namespace vorodg::mpi_runtime
