#pragma once
// Peak resident memory of this process so far, for run metrics (Linux: getrusage reports KiB).
#include <sys/resource.h>

namespace vorodg {

inline double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace vorodg
