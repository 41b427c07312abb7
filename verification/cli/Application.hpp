#pragma once
// The `vorodg` program: subcommands, the one-line error policy and the exit codes
// (0 ok, 2 bad input, 3 numerical breakdown).
namespace vorodg {

int run_application(int argc, char** argv);

}  // namespace vorodg
