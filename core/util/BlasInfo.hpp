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

}  // namespace vorodg
