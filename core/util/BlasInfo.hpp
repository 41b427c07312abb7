#pragma once
// Which BLAS the sparse direct solver will call: Debian's reference BLAS is 3-4x slower than
// OpenBLAS for CHOLMOD's supernodal factorization, so every run reports it.
#include <string>

namespace vorodg {

/// A one-line description, e.g. "OpenBLAS 0.3.21 (pthread) [/usr/lib/.../libblas.so.3]".
std::string blas_description();

}  // namespace vorodg
