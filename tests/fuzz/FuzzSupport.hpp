#pragma once
// Shared by the fuzz targets: what counts as a finding besides a crash or a sanitizer report.
// The readers' only correct response to bad input is one of our error types (InputError,
// NumericalError), which the targets catch; any other exception escapes LLVMFuzzerTestOneInput
// and terminates the program, which libFuzzer (and the corpus replay test) reports as a crash.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace vorodg::fuzz {

/// An input was accepted that breaks a promise of the reader or validator: report and abort.
[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "FUZZ FINDING: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void require(bool ok, const std::string& what) {
  if (!ok) finding(what);
}

}  // namespace vorodg::fuzz
