#include "verification/cli/Application.hpp"

int main(int argc, char** argv) {
  return vorodg::run_application(argc, argv);
}
