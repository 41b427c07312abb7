#include "verification/cli/Application.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "verification/cli/MergeCommand.hpp"
#include "verification/cli/MeshCommand.hpp"
#include "verification/cli/RunCommand.hpp"
#include "verification/cli/SolveCommand.hpp"
#include "verification/harness/Ensemble.hpp"

namespace vorodg {
namespace {

int print_info() {
  std::cout << "vorodg " << VORODG_VERSION << "\n"
            << "blas: " << blas_description() << "\n"
            << "mpi: " << (Ensemble::built_with_mpi() ? "yes" : "no (built with -DVORODG_MPI=OFF)")
            << "\n";
  return 0;
}

/// An error on one rank of an MPI job must not leave the others waiting for it: it ends them
/// all (Ensemble::abort). Alone, the code is returned.
int stop_job(int code) {
  Ensemble::abort(code);
  return code;
}

}  // namespace

int run_application(int argc, char** argv) {
  CLI::App app{
      "vorodg: RK polygon elements (CG and DG) for 2D elasticity on random Voronoi "
      "meshes, with a verification harness"};
  app.require_subcommand(1);
  app.set_version_flag("--version", VORODG_VERSION);
  MeshCommandOptions mesh_options;
  CLI::App* mesh = add_mesh_command(app, mesh_options);
  SolveCommandOptions solve_options;
  CLI::App* solve = add_solve_command(app, solve_options);
  RunCommandOptions run_options;
  CLI::App* run = add_run_command(app, run_options);
  MergeCommandOptions merge_options;
  CLI::App* merge = add_merge_command(app, merge_options);
  CLI::App* info =
      app.add_subcommand("info", "Print the version, the BLAS in use and whether MPI is built in");
  // CLI11 would only say "A subcommand is required": name what was found.
  if (argc > 1) {
    const std::string first = argv[1];
    const bool option = first.starts_with('-');
    if (option ? first != "-h" && first != "--help" && first != "--help-all" && first != "--version"
               : first != "mesh" && first != "solve" && first != "run" && first != "merge" &&
                     first != "info") {
      std::cerr << "vorodg: error: unknown " << (option ? "option" : "command") << " '" << first
                << "': expected a command, mesh, solve, run, merge or info (see --help)\n";
      return kExitInputError;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "vorodg: error: " << e.what() << " (see --help)\n";
    return kExitInputError;
  }
  try {
    if (mesh->parsed()) return run_mesh_command(mesh_options, *mesh);
    if (solve->parsed()) return run_solve_command(solve_options, *solve);
    if (run->parsed()) return run_run_command(run_options, *run);
    if (merge->parsed()) return run_merge_command(merge_options, *merge);
    if (info->parsed()) return print_info();
  } catch (const InputError& e) {
    std::cerr << "vorodg: error: " << e.what() << "\n";
    return stop_job(kExitInputError);
  } catch (const NumericalError& e) {
    std::cerr << "vorodg: numerical breakdown: " << e.what() << "\n";
    return stop_job(kExitNumericalError);
  } catch (const Interrupted& e) {
    std::cerr << "vorodg: stopped: " << e.what()
              << "; every unfinished run is checkpointed: run the same command to resume\n";
    return stop_job(kExitInterrupted);
  } catch (const std::bad_alloc&) {
    std::cerr << "vorodg: error: out of memory\n";
    return stop_job(kExitNumericalError);
  }
  return 0;
}

}  // namespace vorodg
