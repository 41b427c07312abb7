#include "verification/cli/SolveCommand.hpp"

#include <iostream>
#include <thread>

#include "core/io/JsonOutput.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/cli/ResultFile.hpp"
#include "verification/model/Choices.hpp"
#include "verification/solve/RunRecord.hpp"

namespace vorodg {
namespace {

void print_summary(const SolveSettings& settings, const MeshSpec& spec, const RunMetrics& m) {
  std::cout << settings.problem << " on " << family_name(spec.family) << ": " << m.cells
            << " cells, " << m.dofs << " dofs, h_avg " << m.h_avg;
  if (m.errors_measured)
    std::cout << ", L2 error " << m.l2_error << ", energy error " << m.energy_error << "\n";
  else
    std::cout << ", errors not measured (--no-errors)\n";
  if (m.solver == "amg-cg")
    std::cout << "solver amg-cg: " << m.solver_iterations << " iterations, relative residual "
              << m.solver_residual << "\n";
  else
    std::cout << "solver cholmod: " << m.factor_nonzeros << " factor entries, rcond " << m.rcond
              << "\n";
  if (m.dg)
    std::cout << settings.formulation << ": penalty "
              << penalty_name(penalty_scaling(dg_options(settings))) << ", k_p "
              << penalty_multiplier(dg_options(settings)) << ", " << m.dg->iterations
              << " iterations, " << m.dg->stop_reason << ", relative gap " << m.dg->relative_gap
              << ", " << m.dg->seconds_per_iteration << " s per iteration\n";
  std::cout << "seconds:";
  for (const auto& [stage, s] : m.seconds) std::cout << " " << stage << " " << s;
  std::cout << "\nblas: " << blas_description() << "\n";
}

}  // namespace

CLI::App* add_solve_command(CLI::App& app, SolveCommandOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("solve", "Solve one problem on one mesh and measure its error");
  add_mesh_source_options(*cmd, o.mesh);
  o.mesh.domain = "0,-0.5,4,0.5";  // the beam's default: [0, L] x [-D/2, D/2], L/D = 4
  cmd->get_option("--domain")->default_str(o.mesh.domain);
  cmd->add_option("--mesh", o.mesh.file, "Read the mesh from this .vtu instead of generating one");
  add_setting_options(*cmd, o.settings);
  o.settings.settings.element.threads = default_solve_threads();
  cmd->get_option("--threads")->default_str(std::to_string(o.settings.settings.element.threads));
  add_vtu_output_options(*cmd, o.output, "Result file");
  cmd->add_option("--metrics", o.metrics, "Metrics file to write (.json)");
  return cmd;
}

int run_solve_command(const SolveCommandOptions& o, const CLI::App& command) {
  // Every value is checked, naming its option, before anything is echoed, meshed or solved.
  const SolveSettings settings = checked_settings(o.settings);
  check_output_folder(o.output.path, "--output");
  check_output_folder(o.metrics, "--metrics");
  Stopwatch clock;
  MeshSpec spec = mesh_spec(o.mesh, command.count("--domain") > 0);
  spec.threads = settings.element.threads;
  echo_options("vorodg solve", command, resolved_defaults(settings));
  const GeneratedMesh generated = generate_mesh(spec);
  const PolygonMesh& mesh = generated.mesh;
  require_valid_mesh(
      mesh, "mesh " + (spec.path.empty() ? std::string(family_name(spec.family)) : spec.path));
  const double mesh_seconds = clock.seconds();

  SolveResult r;
  {
    const ScopedBlasThreads blas(settings.element.threads);
    r = run_solve(mesh, settings);
  }
  r.seconds["mesh"] = mesh_seconds;
  require_converged(r, settings);
  const auto exact = make_problem(settings, mesh.domain());
  const RunMetrics metrics = run_metrics(mesh, r);

  if (!o.metrics.empty()) write_json(o.metrics, solve_record(metrics, settings, spec.family));
  if (!o.output.path.empty())
    write_result(o.output.path, mesh, r, *exact, settings.formulation != "cg", o.output.encoding());
  print_summary(settings, spec, metrics);
  return 0;
}

}  // namespace vorodg
