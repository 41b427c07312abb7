#include <iostream>

#include "core/util/Errors.hpp"
#include "verification/cli/Application.hpp"
#include "verification/harness/Ensemble.hpp"

int main(int argc, char** argv) {
  using namespace vorodg;
  try {
    Ensemble::start(argc, argv);
  } catch (const InputError& e) {
    std::cerr << "vorodg: error: " << e.what() << "\n";
    return kExitInputError;
  }
  // Under MPI the coordinator speaks for the job; the other ranks' errors still reach stderr.
  if (!Ensemble::coordinator()) std::cout.rdbuf(nullptr);
  const int code = run_application(argc, argv);
  Ensemble::stop();
  return code;
}
