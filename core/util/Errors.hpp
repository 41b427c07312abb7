#pragma once
// The failures a user must be told about, with the exit codes the command line maps them to: bad
// input (2), a numerical breakdown (3) and a stop on request (75). Messages are one line: what,
// where, expected against found.
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

/// A checkpoint that cannot be used (truncated, corrupt, from another scene, mesh or build). Never
/// an exit: the run falls back to an older checkpoint or to its start, and says why in one line.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run stopped on request (SIGTERM, SIGINT) after writing its checkpoint: resumable. Exit code
/// kExitInterrupted.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Refuses a parameter outside its range: "<name> = <value>: expected <range>" (the caller
/// prefixes where the name lives, e.g. the scene key's object).
void require_parameter(bool ok, const std::string& name, double value, const std::string& range);

inline constexpr int kExitInputError = 2;
inline constexpr int kExitNumericalError = 3;
/// Stopped by a signal with every unfinished run checkpointed: run the same command again to
/// resume (75 is sysexits' EX_TEMPFAIL, "try again later").
inline constexpr int kExitInterrupted = 75;

}  // namespace vorodg
