#pragma once
// The two kinds of failure a user must be told about, with the exit codes the command line maps
// them to: bad input (2) and a numerical breakdown (3). Messages are one line: what, where,
// expected against found.
#include <stdexcept>
#include <string>

namespace vorodg {

/// Invalid input: a file, a key, a command-line value or a mesh that cannot be used. Exit code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The numerics broke down (singular system, diverging iteration, degenerate geometry met during
/// a computation). Exit code 3.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Refuses a parameter outside its range: "<name> = <value>: expected <range>" (the caller
/// prefixes where the name lives, e.g. the scene key's object).
void require_parameter(bool ok, const std::string& name, double value, const std::string& range);

inline constexpr int kExitInputError = 2;
inline constexpr int kExitNumericalError = 3;

}  // namespace vorodg
