#pragma once
// Which BLAS the sparse direct solver will call: Debian's reference BLAS is 3-4x slower than
// OpenBLAS for CHOLMOD's supernodal factorization, so every run reports it.
#include <string>

namespace vorodg {

/// A one-line description, e.g. "OpenBLAS 0.3.21 (pthread) [/usr/lib/.../libblas.so.3]".
std::string blas_description();

/// Sets the BLAS's own thread count and returns the previous one (OpenBLAS; with a BLAS that has
/// no threads nothing happens and 1 is returned). Studies that run one solve per core set it to
/// 1: OpenBLAS's spinning threads on top of parallel runs made fig26 1.5x slower.
int set_blas_threads(int threads);

/// The BLAS's thread count set for a scope and restored after it. A single solve asked for N
/// threads takes N in the factorization's BLAS too: otherwise OpenBLAS starts one per core
/// whatever --threads says (measured: a "one-thread" solve at 1e5 cells factored on both
/// cores, its idle threads spinning in sched_yield).
class ScopedBlasThreads {
 public:
  explicit ScopedBlasThreads(int threads) : previous_(set_blas_threads(threads)) {}
  ~ScopedBlasThreads() { set_blas_threads(previous_); }
  ScopedBlasThreads(const ScopedBlasThreads&) = delete;
  ScopedBlasThreads& operator=(const ScopedBlasThreads&) = delete;

 private:
  int previous_;
};

/// No OpenMP teams for the libraries the calling thread calls within a scope (OpenMP's
/// settings are per thread, so other threads and our own regions elsewhere are untouched).
/// CHOLMOD's supernodal factorization opens teams of a fixed 4 threads around its scatter
/// loops, whatever omp_set_num_threads says; measured at 1e5 cells on this 2-core machine, they
/// made the factorization 2.6x slower with one thread (2.91 s against 1.13 s, its time spent
/// waking and parking workers) and 1.5x slower with two. Its parallel speed comes from the
/// BLAS, whose threads are set apart (ScopedBlasThreads).
class ScopedSerialOpenMp {
 public:
  ScopedSerialOpenMp();
  ~ScopedSerialOpenMp();
  ScopedSerialOpenMp(const ScopedSerialOpenMp&) = delete;
  ScopedSerialOpenMp& operator=(const ScopedSerialOpenMp&) = delete;

 private:
  int previous_levels_;
};

}  // namespace vorodg
